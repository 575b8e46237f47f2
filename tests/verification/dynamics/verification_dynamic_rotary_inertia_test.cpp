// The beams' rotary inertia in a dynamic step (elements/structural/beam_mass.hpp,
// docs/theory/dynamics.md §8): one PIPE31 (L = 1000, r_o = 50, t = 5, E = 2e5, nu = 0.3,
// rho = 7.85e-9) clamped at node 1, every DOF of node 2 but the twist UR1 held, a torque T = 1e5
// suddenly applied there. The twist is a single-DOF oscillator: the torsional stiffness
// k = G J / L (a circular tube's St. Venant J equals its polar moment I_p = pi/2 (r_o^4 - r_i^4))
// and the lumped polar inertia of the two-node element's end, I = rho I_p L / 2 (Abaqus lumps the
// mass of two-node beams). The trapezoidal rule (ALPHA=0.) gives phi_n = T/k (1 - cos(n theta)),
// theta = 2 atan(w dt / 2), w = sqrt(k / I), exactly: checked to 1e-9 of T/k (round-off of a
// linear recurrence over 40 steps). Without rotary inertia the twist would have no mass and jump
// to T/k at once; with the consistent inertia (rho I_p L / 3 at the end) the period would be
// sqrt(2/3) as long: both differ by far more than the tolerance.
#include "test_util.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace gapfem {
namespace {

TEST(DynamicRotaryInertia, PipeTwistIsTheLumpedPolarInertiaOscillator) {
  const char* deck = R"(*HEADING
a pipe twisted by a suddenly applied torque
*NODE
1, 0., 0., 0.
2, 1000., 0., 0.
*ELEMENT, TYPE=PIPE31, ELSET=P
1, 1, 2
*BEAM SECTION, ELSET=P, MATERIAL=STEEL, SECTION=PIPE
50., 5.
0., 0., 1.
*MATERIAL, NAME=STEEL
*ELASTIC
200000., 0.3
*DENSITY
7.85e-9
*BOUNDARY
1, 1, 6
2, 1, 3
2, 5, 6
*AMPLITUDE, NAME=CONST
0., 1., 1., 1.
*STEP, INC=1000
*DYNAMIC, DIRECT, ALPHA=0.
3.5e-5, 1.4e-3
*CLOAD, AMPLITUDE=CONST
2, 4, 1e5
*NODE PRINT, FREQUENCY=1
UR
*END STEP
)";
  const JobResult r = test::run_deck_exact(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const double ro = 50.0, ri = 45.0, L = 1000.0;
  const double Ip = std::numbers::pi / 2.0 * (std::pow(ro, 4) - std::pow(ri, 4));
  const double G = 200000.0 / (2.0 * 1.3), k = G * Ip / L, I = 7.85e-9 * Ip * L / 2.0;
  const double T = 1e5, dt = 3.5e-5, theta = 2.0 * std::atan(std::sqrt(k / I) * dt / 2.0);
  std::vector<double> phi;
  for (const Frame& f : r.frames)
    if (f.increment > 0) phi.push_back(f.nodes.UR.at(r.model->mesh.find_node(2))[0]);
  ASSERT_EQ(phi.size(), 40u);
  for (std::size_t n = 0; n < phi.size(); ++n)
    EXPECT_NEAR(phi[n], T / k * (1.0 - std::cos((n + 1) * theta)), 1e-9 * T / k) << n + 1;
}

} // namespace
} // namespace gapfem
