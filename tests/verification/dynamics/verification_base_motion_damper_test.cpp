// A dashpot on a moving support (*BOUNDARY, TYPE=VELOCITY; docs/theory/dynamics.md, "Base
// motion"): the elements see the support's prescribed velocity, not the integrator's map of its
// displacement increment.
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

} // namespace
} // namespace gapfem
