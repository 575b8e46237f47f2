// Point inertias (elements/structural/point_inertia.hpp) with closed forms:
// - a MASS element (m = 0.5, *MASS) on a SPRING1 (k = 500) under a force suddenly applied: the
//   trapezoidal rule's discrete solution u_n = F/k (1 - cos(n theta)), theta = 2 atan(w dt / 2),
//   w = sqrt(k/m), to 1e-9 (the same oscillator as the bar of verification_dynamic_sdof_test);
// - a ROTARYI element (I33 = 0.02, *ROTARY INERTIA) on a rotational SPRING1 (k = 8 on DOF 6)
//   under a moment M = 0.4: phi_n = M/k (1 - cos(n theta)) with w = sqrt(k / I33);
// - GRAV on the MASS element in a static step: u = m g / k;
// - input errors: each keyword on the other element type, a negative mass, a missing data line,
//   a negative ALPHA (ALPHA itself: verification_dashpot_test.cpp).
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <numbers>

namespace gapfem {
namespace {

using test::run_deck;

/// The node's other DOFs of the same kind (translations or rotations) held.
std::string held_but(int dof) {
  std::string b = "*BOUNDARY\n";
  const int first = dof <= 3 ? 1 : 4;
  for (int d = first; d < first + 3; ++d)
    if (d != dof) b += fmt::format("1, {}, {}\n", d, d);
  return b;
}

std::string deck(const std::string& inertia, int dof, double k, const std::string& step) {
  return fmt::format(R"(*HEADING
a point inertia on a spring to ground
*NODE
1, 0., 0., 0.
*ELEMENT, TYPE=SPRING1, ELSET=SPR
1, 1
*SPRING, ELSET=SPR
{}
{}
{}{}{})",
                     dof, k, inertia, held_but(dof), step);
}

std::string dynamic_step(double dt, double period, int dof, double load) {
  return fmt::format(R"(*AMPLITUDE, NAME=CONST
0., 1., 1000., 1.
*STEP, INC=100000
*DYNAMIC, DIRECT, ALPHA=0.
{}, {}
*CLOAD, AMPLITUDE=CONST
1, {}, {}
*NODE PRINT, FREQUENCY=1
U, UR
*END STEP
)",
                     dt, period, dof, load);
}

/// The DOF's value at the end of every increment.
std::vector<double> history(const JobResult& r, int dof) {
  std::vector<double> h;
  for (const Frame& f : r.frames) {
    if (f.increment <= 0) continue;
    const NodeId n = r.model->mesh.find_node(1);
    h.push_back(dof <= 3 ? f.nodes.U.at(n)[dof - 1] : f.nodes.UR.at(n)[dof - 4]);
  }
  return h;
}

void expect_trapezoidal_step_response(const JobResult& r, int dof, double k, double inertia,
                                      double load, double dt) {
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto h = history(r, dof);
  ASSERT_EQ(h.size(), 40u);
  const double theta = 2.0 * std::atan(std::sqrt(k / inertia) * dt / 2.0);
  for (std::size_t n = 0; n < h.size(); ++n)
    EXPECT_NEAR(h[n], load / k * (1.0 - std::cos((n + 1) * theta)), 1e-9 * load / k) << n + 1;
}

constexpr const char* kMass = "*ELEMENT, TYPE=MASS, ELSET=M\n2, 1\n*MASS, ELSET=M\n0.5\n";
constexpr const char* kRotary =
    "*ELEMENT, TYPE=ROTARYI, ELSET=R\n2, 1\n*ROTARY INERTIA, ELSET=R\n0.01, 0.01, 0.02\n";

TEST(VerificationPointInertia, MassOnASpringOscillatesAsItsClosedForm) {
  const double T = 2.0 * std::numbers::pi / std::sqrt(1000.0), dt = T / 20.0;
  const JobResult r = run_deck(deck(kMass, 1, 500.0, dynamic_step(dt, 2.0 * T, 1, 5.0)));
  expect_trapezoidal_step_response(r, 1, 500.0, 0.5, 5.0, dt);
}

TEST(VerificationPointInertia, RotaryInertiaOnARotationalSpringOscillatesAsItsClosedForm) {
  const double T = 2.0 * std::numbers::pi / std::sqrt(8.0 / 0.02), dt = T / 20.0;
  const JobResult r = run_deck(deck(kRotary, 6, 8.0, dynamic_step(dt, 2.0 * T, 6, 0.4)));
  expect_trapezoidal_step_response(r, 6, 8.0, 0.02, 0.4, dt);
}

TEST(VerificationPointInertia, GravityLoadsAPointMass) {
  const JobResult r = run_deck(deck(kMass, 2, 500.0, R"(*STEP
*STATIC
*DLOAD
M, GRAV, 9.81, 0., -1., 0.
*NODE PRINT
U
*END STEP
)"));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  EXPECT_NEAR(test::U(r, test::last_frame(r), 1)[1], -0.5 * 9.81 / 500.0, 1e-12);
}

TEST(VerificationPointInertia, InputErrors) {
  const std::string step = dynamic_step(0.01, 0.1, 1, 1.0);
  auto error = [&](const std::string& inertia) {
    const JobResult r = run_deck(deck(inertia, 1, 500.0, step));
    EXPECT_NE(r.exit_code, 0);
    return r.error;
  };
  EXPECT_NE(error("*ELEMENT, TYPE=MASS, ELSET=M\n2, 1\n*ROTARY INERTIA, ELSET=M\n1., 1., 1.\n")
                .find("MASS elements take *MASS, not *ROTARY INERTIA"),
            std::string::npos);
  EXPECT_NE(error("*ELEMENT, TYPE=MASS, ELSET=M\n2, 1\n*MASS, ELSET=M\n-0.5\n")
                .find("must not be negative"),
            std::string::npos);
  EXPECT_NE(error("*ELEMENT, TYPE=MASS, ELSET=M\n2, 1\n*MASS, ELSET=M\n").find("data line"),
            std::string::npos);
  EXPECT_NE(error("*ELEMENT, TYPE=MASS, ELSET=M\n2, 1\n*MASS, ELSET=M, ALPHA=-0.1\n0.5\n")
                .find("ALPHA must not be negative"),
            std::string::npos);
  EXPECT_NE(error("*ELEMENT, TYPE=MASS, ELSET=M\n2, 1\n").find("*MASS"), std::string::npos);
}

} // namespace
} // namespace gapfem
