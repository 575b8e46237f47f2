// The second-order integrators of *DYNAMIC (solver/time_integrator.hpp) on a single degree of
// freedom m a + c v + k u = f, advanced exactly as the step problem does it: the residual
//   inertia_weight() m a + R(t + dt) + history_weight() R(t),   R = k u + c v - f,
// with v, a from the integrator's affine maps and the tangent from its weights; one linear solve
// per increment. Checked against the closed forms of the methods (Hilber, Hughes and Taylor 1977;
// Hughes, "The Finite Element Method", §9.3):
//   - trapezoidal rule (alpha = 0): no amplitude decay, period T' = 2 pi / w' with
//     w' dt = 2 atan(w dt / 2);
//   - HHT with alpha: spectral radius (1 + alpha) / (1 - alpha) as w dt -> infinity; second-order
//     accurate (the period error of a fine step falls 4x when dt halves);
//   - backward Euler: its amplification 1 / (1 + (w dt)^2)^(1/2) per step for a free oscillator;
//   - a constant force gives the static answer f / k after the transient decays (alpha < 0).
#include "solver/time_integrator.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace gapfem {
namespace {

struct Sdof {
  double m = 1.0, c = 0.0, k = 1.0, f = 0.0;
  double u = 1.0, v = 0.0, a = 0.0, R = 0.0;

  /// The starting acceleration and residual from equilibrium: m a + R = 0.
  void start() {
    R = k * u + c * v - f;
    a = -R / m;
  }
  void step(TimeIntegrator& ti, double dt) {
    ti.begin_increment(dt);
    const RateCoefficients rc = ti.coefficients();
    const OperatorWeights w = ti.weights();
    auto residual = [&](double du, double& vn, double& an) {
      vn = rc.velocity(du, v, a);
      an = rc.acceleration(du, v, a);
      return w.inertia * m * an + (k * (u + du) + c * vn - f) + ti.history_weight() * R;
    };
    double vn = 0.0, an = 0.0;
    const double r0 = residual(0.0, vn, an);
    const double du = -r0 / (w.m * m + w.c * c + w.k * k);
    EXPECT_NEAR(residual(du, vn, an), 0.0,
                1e-12 * (std::abs(r0) + k * std::abs(u) + 1.0)); // linear: one solve
    u += du;
    v = vn;
    a = an;
    R = k * u + c * v - f;
  }
};

/// Amplitude sqrt(u^2 + (v / w)^2) of a free undamped oscillator.
double amplitude(const Sdof& s) {
  const double w = std::sqrt(s.k / s.m);
  return std::hypot(s.u, s.v / w);
}

TEST(Hht, ParametersFromAlphaAndAbaqusApplications) {
  const auto tf = HilberHughesTaylor::with_alpha(-0.05);
  EXPECT_DOUBLE_EQ(tf.beta(), 0.275625);
  EXPECT_DOUBLE_EQ(tf.gamma(), 0.55);
  const auto md = HilberHughesTaylor::with_alpha(1.0 - std::sqrt(2.0));
  EXPECT_NEAR(md.beta(), 0.5, 1e-15);
  EXPECT_NEAR(md.gamma(), 0.91421356, 1e-8);
  HilberHughesTaylor h = tf;
  h.begin_increment(0.1);
  EXPECT_TRUE(h.needs_rate_history());
  const OperatorWeights w = h.weights();
  EXPECT_DOUBLE_EQ(w.inertia, 1.0 / 0.95);
  EXPECT_DOUBLE_EQ(w.m, 1.0 / (0.95 * 0.275625 * 0.01));
  EXPECT_DOUBLE_EQ(w.c, 0.55 / (0.275625 * 0.1));
  EXPECT_DOUBLE_EQ(h.history_weight(), 0.05 / 0.95);
}

TEST(Hht, TrapezoidalRuleKeepsTheAmplitudeAndElongatesThePeriodAsItsClosedForm) {
  auto ti = HilberHughesTaylor::with_alpha(0.0);
  const double w = 3.0, dt = 0.2;
  Sdof s;
  s.k = w * w;
  s.start();
  // count the time to the 20th upward zero crossing of v... use the phase instead: after n steps
  // the discrete solution is cos(n w' dt)
  const int n = 37;
  for (int i = 0; i < n; ++i) s.step(ti, dt);
  EXPECT_NEAR(amplitude(s), 1.0, 1e-12);
  const double wd = 2.0 * std::atan(w * dt / 2.0) / dt;
  EXPECT_NEAR(s.u, std::cos(n * wd * dt), 1e-10);
}

// At w dt -> infinity HHT's principal roots coincide (a Jordan block): the amplitude goes as
// (c1 + c2 n) rho^n, so rho is measured with the factor n taken out over many steps.
TEST(Hht, SpectralRadiusAtInfinityIsOnePlusAlphaOverOneMinusAlpha) {
  for (double alpha : {-0.05, -0.1, -1.0 / 3.0}) {
    auto ti = HilberHughesTaylor::with_alpha(alpha);
    Sdof s;
    s.k = 1e12; // w dt = 1e6
    s.start();
    const int n1 = 100, n2 = 200;
    for (int i = 0; i < n1; ++i) s.step(ti, 1.0);
    const double a1 = amplitude(s);
    for (int i = n1; i < n2; ++i) s.step(ti, 1.0);
    const double rho = std::pow(amplitude(s) / a1 * n1 / n2, 1.0 / (n2 - n1));
    EXPECT_NEAR(rho, (1.0 + alpha) / (1.0 - alpha), 2e-4) << "alpha " << alpha;
  }
}

TEST(Hht, SecondOrderAccuracy) {
  auto err = [](double dt) {
    auto ti = HilberHughesTaylor::with_alpha(-0.05);
    Sdof s;
    s.k = 4.0;
    s.c = 0.1;
    s.start();
    const int n = static_cast<int>(std::lround(2.0 / dt));
    for (int i = 0; i < n; ++i) s.step(ti, dt);
    // exact damped response from u = 1, v = 0
    const double w = 2.0, z = 0.1 / (2.0 * w), wd = w * std::sqrt(1.0 - z * z);
    const double exact =
        std::exp(-z * w * 2.0) * (std::cos(wd * 2.0) + z * w / wd * std::sin(wd * 2.0));
    return std::abs(s.u - exact);
  };
  const double e1 = err(0.01), e2 = err(0.005);
  EXPECT_NEAR(e1 / e2, 4.0, 0.3);
}

TEST(Hht, BackwardEulerDampsAsItsAmplificationFactor) {
  BackwardEulerDynamic be;
  const double w = 2.0, dt = 0.3;
  Sdof s;
  s.k = w * w;
  s.start();
  s.step(be, dt); // the first step starts from a = -u w^2 (not on the method's eigen-solution)
  const double a0 = amplitude(s);
  for (int i = 0; i < 5; ++i) s.step(be, dt);
  // backward Euler on the first-order system: eigenvalues 1 / (1 - i w dt) in (u, v / w)
  EXPECT_NEAR(amplitude(s) / a0, std::pow(1.0 / std::sqrt(1.0 + w * w * dt * dt), 5), 1e-12);
}

TEST(Hht, ConstantForceSettlesOnTheStaticAnswer) {
  auto ti = HilberHughesTaylor::with_alpha(-1.0 / 3.0);
  Sdof s;
  s.k = 100.0;
  s.c = 2.0;
  s.u = 0.0;
  s.f = 5.0;
  s.start();
  for (int i = 0; i < 2000; ++i) s.step(ti, 0.01);
  EXPECT_NEAR(s.u, 0.05, 1e-9);
  EXPECT_NEAR(s.v, 0.0, 1e-8);
}

} // namespace
} // namespace gapfem
