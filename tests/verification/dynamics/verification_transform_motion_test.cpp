// Prescribed velocities and accelerations at *TRANSFORM nodes (docs/theory/dynamics.md §11, "Base
// motion"): the condition acts on the node's local DOF through its constraint row, whose
// right-hand side is the rate integrated exactly over each increment from the committed state
// (as at a global DOF: u_n + int v, or u_n + v_n dt + the double integral of a), and whose own
// rates (v, a of the right-hand side) enter the impact projection and the accelerations.
//
// The local system turns x by 30 degrees about z: local 1 = (cos 30, sin 30, 0). Output U, V, A at
// a transformed node are in its local system (docs/results.md), so the checks below read local
// components.
// 1. A wall (node 3) driven at -V along local 1 hits a resting point mass m (node 2) through a
//    GAPUNI along the same axis, clearance d: fully plastic, the mass takes the wall's velocity
//    (V local 1 = -V from the impact on, local 2 = 0) and with the trapezoidal rule the energies
//    split exactly as for a wall along x (verification_moving_stop_test.cpp): the wall's work
//    ALLWK = m V^2 (the row's reaction is the support's: ALLWK, not ALLIE), ALLKE = ALLKL =
//    m V^2 / 2, ALLIE = 0; to 1e-12 of m V^2.
// 2. A mass driven by a constant acceleration A along local 1 from rest: u = A t^2 / 2, v = A t,
//    a = A along local 1 at every increment (1e-12), nothing along local 2.
// 3. A velocity at a transformed node in a static step: u = V t along local 1 (a STEP variation,
//    Abaqus's default for velocities in static steps), exactly.
// 4. An acceleration at a transformed node in a static step: one error naming the step.
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>

namespace gapfem {
namespace {

constexpr double kM = 2.0, kV = 0.5, kD = 0.01, kC = 0.86602540378443865, kS = 0.5;

const Vec3& V(const JobResult& r, const Frame& f, Label node) {
  return f.nodes.V.at(r.model->mesh.find_node(node));
}
const Vec3& A(const JobResult& r, const Frame& f, Label node) {
  return f.nodes.A.at(r.model->mesh.find_node(node));
}

std::string skewed_nodes(double wall_distance) {
  return fmt::format(R"(*NODE
2, 0., 0., 0.
3, {}, {}, 0.
*NSET, NSET=BOTH
2, 3
*TRANSFORM, NSET=BOTH
{}, {}, 0., {}, {}, 0.
*ELEMENT, TYPE=MASS, ELSET=PM
5, 2
*MASS, ELSET=PM
{}
*AMPLITUDE, NAME=CONST
0., 1., 10., 1.
)",
                     wall_distance * kC, wall_distance * kS, kC, kS, -kS, kC, kM);
}

TEST(VerificationTransformMotion, AWallDrivenAlongASkewedAxisHitsAMass) {
  const JobResult r = test::run_deck("*HEADING\nskewed wall\n" + skewed_nodes(0.5 * kD) +
                                     fmt::format(R"(*ELEMENT, TYPE=GAPUNI, ELSET=G
10, 2, 3
*GAP, ELSET=G
{}, {}, {}, 0., 1.
*BOUNDARY
BOTH, 2, 3
*STEP, INC=1000
*DYNAMIC, DIRECT, ALPHA=0.
0.003, 0.06
*BOUNDARY, TYPE=VELOCITY, AMPLITUDE=CONST
3, 1, 1, {}
*NODE PRINT, FREQUENCY=1
U, V
*END STEP
)",
                                                 kD, kC, kS, -kV));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const double scale = kM * kV * kV, t_c = kD / kV; // the clearance is the GAPUNI's d
  int after = 0;
  for (const Frame& f : r.frames) {
    if (f.increment == 0 || !f.energies) continue;
    EXPECT_NEAR(V(r, f, 3)[0], -kV, 1e-12);
    EXPECT_NEAR(V(r, f, 3)[1], 0.0, 1e-9); // the rows hold u to the solver's tolerance
    if (f.step_time < t_c - 1e-12) {
      EXPECT_NEAR(V(r, f, 2)[0], 0.0, 1e-12) << f.step_time;
      continue;
    }
    ++after;
    EXPECT_NEAR(V(r, f, 2)[0], -kV, 1e-10) << f.step_time;
    EXPECT_NEAR(V(r, f, 2)[1], 0.0, 1e-12) << f.step_time;
    const Energies& e = *f.energies;
    EXPECT_NEAR(e.allwk, scale, 1e-12 * scale);
    EXPECT_NEAR(e.allke, 0.5 * scale, 1e-12 * scale);
    EXPECT_NEAR(e.allkl, 0.5 * scale, 1e-12 * scale);
    EXPECT_NEAR(e.allie, 0.0, 1e-12 * scale);
  }
  EXPECT_GE(after, 10);
}

TEST(VerificationTransformMotion, AConstantAccelerationAlongASkewedAxis) {
  constexpr double kA = 3.0, kDt = 0.01;
  const JobResult r = test::run_deck("*HEADING\nskewed acceleration\n" + skewed_nodes(1.0) +
                                     fmt::format(R"(*BOUNDARY
2, 2, 3
3, 1, 3
*STEP, INC=1000
*DYNAMIC, DIRECT, APPLICATION=MODERATE DISSIPATION
{}, 0.1
*BOUNDARY, TYPE=ACCELERATION, AMPLITUDE=CONST
2, 1, 1, {}
*NODE PRINT, FREQUENCY=1
U, V, A
*END STEP
)",
                                                 kDt, kA));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  int n = 0;
  for (const Frame& f : r.frames) {
    if (f.increment == 0) continue;
    const double t = f.step_time;
    EXPECT_NEAR(test::U(r, f, 2)[0], 0.5 * kA * t * t, 1e-12) << t;
    EXPECT_NEAR(test::U(r, f, 2)[1], 0.0, 1e-12) << t;
    EXPECT_NEAR(V(r, f, 2)[0], kA * t, 1e-10) << t;
    EXPECT_NEAR(A(r, f, 2)[0], kA, 1e-8) << t;
    ++n;
  }
  EXPECT_EQ(n, 10);
}

TEST(VerificationTransformMotion, AVelocityInAStaticStepIsIntegrated) {
  const JobResult r =
      test::run_deck("*HEADING\nskewed velocity, static\n" + skewed_nodes(1.0) + R"(*BOUNDARY
2, 2, 3
3, 1, 3
*STEP
*STATIC
0.25, 1.
*BOUNDARY, TYPE=VELOCITY
2, 1, 1, 0.2
*NODE PRINT
U
*END STEP
)");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  int n = 0;
  for (const Frame& f : r.frames) {
    if (f.increment == 0) continue;
    EXPECT_NEAR(test::U(r, f, 2)[0], 0.2 * f.step_time, 1e-12) << f.step_time;
    ++n;
  }
  EXPECT_EQ(n, 4);
}

TEST(VerificationTransformMotion, AnAccelerationInAStaticStepIsOneError) {
  const JobResult r =
      test::run_deck("*HEADING\nskewed acceleration, static\n" + skewed_nodes(1.0) + R"(*BOUNDARY
2, 2, 3
3, 1, 3
*STEP
*STATIC
*BOUNDARY, TYPE=ACCELERATION
2, 1, 1, 0.2
*END STEP
)");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.error.find("needs a *DYNAMIC step"), std::string::npos) << r.error;
}

} // namespace
} // namespace gapfem
