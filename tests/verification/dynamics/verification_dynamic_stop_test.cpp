// Masses given initial velocities against gap stops in *DYNAMIC steps (docs/theory/dynamics.md,
// §5 impacts), each against its closed form, with the trapezoidal rule (ALPHA=0, INITIAL=YES):
// - The bilinear oscillator: a mass m on a spring k1, from u = 0 with v0, closes a GAPUNI of
//   clearance c onto a massless stop held by a spring k2. Free flight u = (v0/w1) sin(w1 t),
//   w1^2 = k1/m, until u = c at t1 = asin(c w1/v0)/w1 with speed vc = v0 cos(w1 t1); in contact
//   the stiffness is k1 + k2 about u_eq = k2 c/(k1 + k2): u - u_eq = A2 sin(w2 tau + phi),
//   A2^2 = (c - u_eq)^2 + (vc/w2)^2, so u_max = u_eq + A2 and the contact lasts
//   (pi - 2 asin((c - u_eq)/A2))/w2; the stop has no mass: no kinetic energy is lost when the
//   mass reaches it (ALLKL 0), and energy is conserved (ALLKE + ALLIE = 1/2 m v0^2).
// - A point mass in a GAPCYL guide (axis x, radial clearance r) moving from the axis with a
//   radial speed 1 and an axial speed 0.5: it reaches the wall at t = r along its radial
//   direction, the fully plastic impact takes the radial kinetic energy (1/2 m x 1), and it
//   slides on along the axis at 0.5 (frictionless), staying at the wall.
// - A point mass in a GAPSPHER socket of radius r moving from the centre with speed 1: it stops
//   on the sphere at r along its direction, all its kinetic energy lost (1/2 m).
// Tolerances: the trapezoidal rule's period error (w dt)^2/12 on the times and amplitudes, and
// the impact found within the increment that closes the gap (its contact work, a fraction of
// one increment's, goes into ALLIE instead of ALLKL).
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <numbers>

namespace gapfem {
namespace {

using test::run_deck;

TEST(VerificationDynamicStop, BilinearOscillatorOnAMasslessSpringSupportedStop) {
  constexpr double m = 0.5, k1 = 500.0, k2 = 1500.0, c = 0.01, v0 = 1.0, dt = 1e-4;
  const JobResult r = run_deck(fmt::format(R"(*HEADING
bilinear oscillator
*NODE
1, 0., 0., 0.
2, 1., 0., 0.
3, 1.01, 0., 0.
4, 2., 0., 0.
*ELEMENT, TYPE=SPRINGA, ELSET=K1
1, 1, 2
*SPRING, ELSET=K1

{}
*ELEMENT, TYPE=SPRINGA, ELSET=K2
2, 3, 4
*SPRING, ELSET=K2

{}
*ELEMENT, TYPE=MASS, ELSET=M
3, 2
*MASS, ELSET=M
{}
*ELEMENT, TYPE=GAPUNI, ELSET=G
10, 2, 3
*GAP, ELSET=G
{}, 1., 0., 0.
*BOUNDARY
1, 1, 3
4, 1, 3
2, 2, 3
3, 2, 3
*INITIAL CONDITIONS, TYPE=VELOCITY
2, 1, {}
*STEP, INC=10000
*DYNAMIC, DIRECT, ALPHA=0., INITIAL=YES
{}, 0.08
*NODE PRINT, FREQUENCY=1
U
*END STEP
)",
                                           k1, k2, m, c, v0, dt));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const double w1 = std::sqrt(k1 / m), w2 = std::sqrt((k1 + k2) / m);
  const double t1 = std::asin(c * w1 / v0) / w1, vc = v0 * std::cos(w1 * t1);
  const double ueq = k2 * c / (k1 + k2), A2 = std::hypot(c - ueq, vc / w2);
  const double duration = (std::numbers::pi - 2.0 * std::asin((c - ueq) / A2)) / w2;
  double umax = 0.0, first = -1.0, last = -1.0;
  for (const Frame& f : r.frames) {
    const double u = test::U(r, f, 2)[0];
    umax = std::max(umax, u);
    if (u > c + 1e-12) {
      if (first < 0.0) first = f.step_time;
      last = f.step_time;
    }
  }
  const double period_error = (w2 * dt) * (w2 * dt) / 12.0; // 1.3e-5
  EXPECT_NEAR(umax, ueq + A2, 10.0 * period_error * A2 + 1e-9);
  EXPECT_NEAR(first, t1, 2.0 * dt);
  EXPECT_NEAR(last - first, duration, 3.0 * dt);
  const Energies& e = *r.increments.back().energies;
  // a massless stop takes no kinetic energy: ALLKL holds only the closing increment's trapezoid
  // of the gap force (it rises from 0 within the increment; docs/theory/dynamics.md §5), an O(dt)
  // share of that increment's closure: measured 5.1e-6 of the initial kinetic energy
  EXPECT_LT(e.allkl, 1e-4 * 0.5 * m * v0 * v0);
  EXPECT_NEAR(e.allke + e.allie, 0.5 * m * v0 * v0, 1e-3 * 0.5 * m * v0 * v0);
}

/// A point mass at node 1 inside a gap element (type, data line) to the fixed node 2, both at
/// the origin, with the initial velocity (vx, vy, vz).
std::string mass_in_gap(const std::string& type, const std::string& gap, double vx, double vy,
                        double vz) {
  return fmt::format(R"(*HEADING
a mass in a {0}
*NODE
1, 0., 0., 0.
2, 0., 0., 0.
*ELEMENT, TYPE=MASS, ELSET=M
1, 1
*MASS, ELSET=M
2.
*ELEMENT, TYPE={0}, ELSET=G
10, 1, 2
*GAP, ELSET=G
{1}
*BOUNDARY
2, 1, 3
*INITIAL CONDITIONS, TYPE=VELOCITY
1, 1, {2}
1, 2, {3}
1, 3, {4}
*STEP, INC=1000
*DYNAMIC, DIRECT, ALPHA=0., INITIAL=YES
0.0005, 0.03
*NODE PRINT, FREQUENCY=1
U
*END STEP
)",
                     type, gap, vx, vy, vz);
}

TEST(VerificationDynamicStop, AMassInAGapcylGuideKeepsItsAxialSpeed) {
  constexpr double r = 0.01, m = 2.0;
  const JobResult res = run_deck(mass_in_gap("GAPCYL", "0.01, 1., 0., 0.", 0.5, 0.6, 0.8));
  ASSERT_EQ(res.exit_code, 0) << res.error;
  const Frame& end = test::last_frame(res);
  const Vec3& u = test::U(res, end, 1);
  EXPECT_NEAR(u[0], 0.5 * 0.03, 1e-9); // the axial motion goes on
  EXPECT_NEAR(u[1], 0.6 * r, 1e-9);    // at the wall, where it hit
  EXPECT_NEAR(u[2], 0.8 * r, 1e-9);
  const Energies& e = *res.increments.back().energies;
  EXPECT_NEAR(e.allke, 0.5 * m * 0.25, 1e-9);
  EXPECT_NEAR(e.allkl, 0.5 * m * 1.0, 0.05 * 0.5 * m);
  EXPECT_NEAR(e.etotal(), 0.5 * m * 1.25, 1e-9);
}

TEST(VerificationDynamicStop, AMassInAGapspherSocketStopsOnItsSphere) {
  constexpr double r = 0.01, m = 2.0;
  const JobResult res = run_deck(mass_in_gap("GAPSPHER", "0.01", 0.48, 0.6, 0.64));
  ASSERT_EQ(res.exit_code, 0) << res.error;
  const Vec3& u = test::U(res, test::last_frame(res), 1);
  EXPECT_NEAR(u[0], 0.48 * r, 1e-9);
  EXPECT_NEAR(u[1], 0.6 * r, 1e-9);
  EXPECT_NEAR(u[2], 0.64 * r, 1e-9);
  const Energies& e = *res.increments.back().energies;
  EXPECT_NEAR(e.allke, 0.0, 1e-12);
  EXPECT_NEAR(e.allkl, 0.5 * m, 0.05 * 0.5 * m);
  EXPECT_NEAR(e.etotal(), 0.5 * m, 1e-9);
}

} // namespace
} // namespace gapfem
