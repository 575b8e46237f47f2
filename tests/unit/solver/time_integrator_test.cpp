// The time-integrator seam (issue 44, item 2): backward Euler's maps and weights, the coefficients
// kernels see for a transient context, and a linear transient heat problem that still converges
// in one Newton iteration per increment with the capacity integrated through the seam.
#include "solver/time_integrator.hpp"
#include "test_util.hpp"

#include <gtest/gtest.h>

namespace gapfem {
namespace {

TEST(TimeIntegrator, BackwardEulerMapsAndWeights) {
  BackwardEuler be;
  be.begin_increment(0.25);
  const RateCoefficients c = be.coefficients();
  EXPECT_TRUE(c.first_order);
  EXPECT_FALSE(c.second_order);
  EXPECT_EQ(c.v_du, 1.0 / 0.25);
  EXPECT_FALSE(c.velocity_has_history());
  EXPECT_FALSE(be.needs_rate_history());
  const OperatorWeights w = be.weights();
  EXPECT_EQ(w.k, 1.0);
  EXPECT_EQ(w.c, 4.0);
  EXPECT_EQ(w.m, 0.0);
  // a damping operator's weight is formed as c / dt (the stabilization's arithmetic)
  EXPECT_EQ(be.damping_weight(0.3), 0.3 / 0.25);
  const std::vector<double> u{1.0, 2.0, -1.0}, u0{0.5, 2.0, 0.0};
  std::vector<double> v(3), a(3, 7.0);
  be.rates(u, u0, {}, {}, v, a);
  EXPECT_EQ(v, (std::vector<double>{2.0, 0.0, -4.0}));
  EXPECT_EQ(a, (std::vector<double>{7.0, 7.0, 7.0})); // first order: a untouched
  // no increment: no rates, no weights
  be.begin_increment(0.0);
  EXPECT_FALSE(be.coefficients().defined());
  EXPECT_EQ(be.damping_weight(0.3), 0.0);
}

TEST(TimeIntegrator, StepsChooseTheirIntegrator) {
  StepContext ctx;
  EXPECT_EQ(make_time_integrator(ctx), nullptr); // static: quasi-static, none
  ctx.transient = true;
  const auto integrator = make_time_integrator(ctx);
  ASSERT_NE(integrator, nullptr);
  EXPECT_EQ(integrator->name(), "backward Euler");
}

TEST(TimeIntegrator, KernelsSeeTheIntegratorsCoefficients) {
  StepContext ctx;
  EXPECT_FALSE(rate_coefficients(ctx).defined());
  // a context made without an integrator (an element test): backward Euler over dt if transient
  ctx.transient = true;
  ctx.dt = 0.5;
  EXPECT_EQ(rate_coefficients(ctx).v_du, 2.0);
  // the step problem's coefficients win
  ctx.rates.first_order = true;
  ctx.rates.v_du = 3.0;
  EXPECT_EQ(rate_coefficients(ctx).v_du, 3.0);
}

// A bar of DC3D8 bricks with constant conductivity and capacity, one end held at 100, fixed
// increments: a linear problem, so every increment takes exactly one Newton iteration.
TEST(TimeIntegrator, LinearTransientHeatTakesOneIteration) {
  std::string deck = "*HEADING\nlinear transient heat\n*NODE\n";
  for (int i = 0; i <= 4; ++i)
    for (int k = 0; k < 4; ++k) {
      const int id = 4 * i + k + 1;
      deck += std::to_string(id) + ", " + std::to_string(i) + ", " + std::to_string(k % 2) + ", " +
              std::to_string(k / 2) + "\n";
    }
  deck += "*ELEMENT, TYPE=DC3D8, ELSET=BAR\n";
  for (int i = 0; i < 4; ++i) {
    const int a = 4 * i + 1, b = a + 4;
    deck += std::to_string(i + 1) + ", " + std::to_string(a) + ", " + std::to_string(b) + ", " +
            std::to_string(b + 1) + ", " + std::to_string(a + 1) + ", " + std::to_string(a + 2) +
            ", " + std::to_string(b + 2) + ", " + std::to_string(b + 3) + ", " +
            std::to_string(a + 3) + "\n";
  }
  deck += "*NSET, NSET=ALL, GENERATE\n1, 20, 1\n*NSET, NSET=HOT\n1, 2, 3, 4\n"
          "*SOLID SECTION, ELSET=BAR, MATERIAL=M\n\n*MATERIAL, NAME=M\n*CONDUCTIVITY\n45.\n"
          "*DENSITY\n7.8e-9\n*SPECIFIC HEAT\n4.6e8\n"
          "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nALL, 20.\n"
          "*STEP, INC=100\n*HEAT TRANSFER\n0.5, 5.\n*BOUNDARY\nHOT, 11, 11, 100.\n"
          "*END STEP\n";
  const JobResult r = test::run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  ASSERT_GE(r.increments.size(), 2u);
  for (const IncrementInfo& inc : r.increments) EXPECT_EQ(inc.iterations, 1);
}

} // namespace
} // namespace gapfem
