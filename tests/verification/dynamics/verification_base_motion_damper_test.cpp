// A dashpot on a moving support (*BOUNDARY, TYPE=VELOCITY; docs/theory/dynamics.md, "Base
// motion"): the elements see the support's prescribed velocity, not the integrator's map of its
// displacement increment; and a consistent mass coupled to an accelerated base (last test).
//
// Node 1 the support, driven along x with v_g(t) = V0 + V sin(W t) (a PERIODIC amplitude); node 2
// a point mass m joined to it by a DASHPOT2 c on DOF 1. The mass obeys
//   m a + c (v - v_g) = 0,   v(0) = 0,  so a(0) = c V0 / m (INITIAL=YES: the equation at t = 0).
// HHT (ALPHA = alpha, GAMMA = 1/2 - alpha, BETA = (1 - alpha)^2 / 4) writes it at t_n+1 as
//   m a_n+1 + (1 + alpha) c (v_n+1 - v_g(t_n+1)) - alpha c (v_n - v_g(t_n)) = 0,
//   v_n+1 = v_n + dt ((1 - gamma) a_n + gamma a_n+1),
// a scalar recursion the test runs itself (the method's exact discrete solution): gapfem's V and
// A of the mass equal it to 1e-10 of max |v| (rounding only). Two faults this catches (both seen
// before the fix: V of the mass 5.8e-3 off after the first increment, v ~ 0.013): R(0) without
// the dashpot's force from the support's velocity (a(0) = 0 instead of c V0 / m), and elements
// seeing the support's velocity as the integrator's map of its exact displacement increment
// instead of v_g(t_n+1).
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>

namespace gapfem {
namespace {

constexpr double kM = 0.5, kC = 3.0, kV0 = 0.2, kV = 1.0, kW = 5.0;

std::string damper_deck(double alpha, double dt, double period) {
  return fmt::format(R"(*HEADING
A point mass dragged by a dashpot from a moving support
*NODE
1, 0., 0., 0.
2, 1., 0., 0.
*ELEMENT, TYPE=MASS, ELSET=M
1, 2
*MASS, ELSET=M
{}
*ELEMENT, TYPE=DASHPOT2, ELSET=D
2, 1, 2
*DASHPOT, ELSET=D
1, 1
{}
*AMPLITUDE, NAME=VEL, DEFINITION=PERIODIC
1, {}, 0., {}
0., {}
*BOUNDARY
1, 2, 3
2, 2, 3
*STEP, INC=100000
*DYNAMIC, DIRECT, ALPHA={}, INITIAL=YES
{}, {}
*BOUNDARY, TYPE=VELOCITY, AMPLITUDE=VEL
1, 1, 1, 1.
*NODE PRINT, FREQUENCY=1
V, A
*END STEP
)",
                     kM, kC, kW, kV0, kV, alpha, dt, period);
}

double v_g(double t) {
  return kV0 + kV * std::sin(kW * t);
}

void expect_hht_recursion(double alpha) {
  const double dt = 0.01, period = 2.0, gamma = 0.5 - alpha;
  const JobResult r = test::run_deck(damper_deck(alpha, dt, period));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const LocalIndex n1 = r.model->mesh.find_node(1), n2 = r.model->mesh.find_node(2);
  double v = 0.0, a = kC * kV0 / kM, t = 0.0; // the recursion's state at t_n
  int checked = 0;
  for (const Frame& f : r.frames) {
    if (f.increment == 0) continue;
    const double t1 = t + dt;
    // m a1 + (1+alpha) c (v + dt (1-gamma) a + dt gamma a1 - v_g(t1)) - alpha c (v - v_g(t)) = 0
    const double a1 =
        (-(1.0 + alpha) * kC * (v + dt * (1.0 - gamma) * a - v_g(t1)) + alpha * kC * (v - v_g(t))) /
        (kM + (1.0 + alpha) * kC * gamma * dt);
    v += dt * ((1.0 - gamma) * a + gamma * a1);
    a = a1;
    t = t1;
    ASSERT_NEAR(f.step_time, t, 1e-12);
    EXPECT_NEAR(f.nodes.V.at(n2)[0], v, 1e-10 * (kV0 + kV)) << "t = " << t;
    EXPECT_NEAR(f.nodes.A.at(n2)[0], a, 1e-10 * kC * (kV0 + kV) / kM) << "t = " << t;
    EXPECT_NEAR(f.nodes.V.at(n1)[0], v_g(t), 1e-12) << "t = " << t; // the prescribed velocity
    ++checked;
  }
  EXPECT_EQ(checked, 200);
}

TEST(VerificationBaseMotionDamper, TrapezoidalRuleSeesThePrescribedVelocity) {
  expect_hht_recursion(0.0);
}

TEST(VerificationBaseMotionDamper, HhtSeesThePrescribedVelocity) {
  expect_hht_recursion(-0.05);
}

// A consistent mass couples free DOFs to driven ones. One C3D8 unit cube, density rho, nearly no
// stiffness (E = 1e-12), its four nodes at z = 0 driven along x with a constant acceleration A
// from t = 0 (TYPE=ACCELERATION, a constant amplitude), the four at z = 1 free. Its consistent
// mass M_ab = rho V (1/3)^(3-d) (1/6)^d, d the number of coordinates in which nodes a and b
// differ (per direction, int N_a N_b = h/3 alike, h/6 apart). A top node's row sums to rho V / 12
// over the top nodes and rho V / 24 over the bottom ones, so with no force M_ff a_f + M_fp A = 0
// gives every top node a_f = -A / 2 at every time, t = 0 included (INITIAL=YES), and v_f = -A t / 2
// (HHT integrates a constant acceleration exactly): the velocities start right only if the
// initial accelerations have the coupling M_fp a_p (without it, a(0) = 0 and v_f lags by
// (1 - gamma) dt A / 2 for ever).
TEST(VerificationBaseMotionDamper, ConsistentMassCouplingToAnAcceleratedBase) {
  constexpr double kA = 3.0;
  const JobResult r = test::run_deck(fmt::format(R"(*NODE
1, 0., 0., 0.
2, 1., 0., 0.
3, 1., 1., 0.
4, 0., 1., 0.
5, 0., 0., 1.
6, 1., 0., 1.
7, 1., 1., 1.
8, 0., 1., 1.
*NSET, NSET=BASE
1, 2, 3, 4
*NSET, NSET=TOP
5, 6, 7, 8
*ELEMENT, TYPE=C3D8, ELSET=CUBE
1, 1, 2, 3, 4, 5, 6, 7, 8
*MATERIAL, NAME=SOFT
*ELASTIC
1e-12, 0.
*DENSITY
2.
*SOLID SECTION, ELSET=CUBE, MATERIAL=SOFT
*BOUNDARY
BASE, 2, 3
TOP, 2, 3
*AMPLITUDE, NAME=CONST
0., 1., 10., 1.
*STEP, INC=1000
*DYNAMIC, DIRECT, APPLICATION=TRANSIENT FIDELITY, INITIAL=YES
0.01, 0.2
*BOUNDARY, TYPE=ACCELERATION, AMPLITUDE=CONST
BASE, 1, 1, {}
*NODE PRINT, FREQUENCY=1
V, A
*END STEP
)",
                                                 kA));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  int checked = 0;
  for (const Frame& f : r.frames) {
    if (f.increment == 0) continue;
    for (Label n = 5; n <= 8; ++n) {
      const LocalIndex i = r.model->mesh.find_node(n);
      EXPECT_NEAR(f.nodes.A.at(i)[0], -0.5 * kA, 1e-9 * kA) << "node " << n << " t " << f.step_time;
      // HHT integrates a constant acceleration exactly from a consistent a(0)
      EXPECT_NEAR(f.nodes.V.at(i)[0], -0.5 * kA * f.step_time, 1e-9 * kA)
          << "node " << n << " t " << f.step_time;
    }
    EXPECT_NEAR(f.nodes.A.at(r.model->mesh.find_node(1))[0], kA, 1e-12);
    ++checked;
  }
  EXPECT_EQ(checked, 20);
}

} // namespace
} // namespace gapfem
