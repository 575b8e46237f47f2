// Amplitude curves (model/amplitude.hpp): every kind's value against values derived by hand from
// the Abaqus definitions, the slope against a central difference of the value, and the first
// and second integrals against numerical quadrature of the value (adaptive Simpson: an oracle
// independent of the closed forms), on fixed and randomized curves.
#include "model/amplitude.hpp"

#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <random>

namespace gapfem {
namespace {

/// Adaptive Simpson on [a, b] to an absolute tolerance (splits until the two halves agree, so
/// kinks and jumps of the integrand are resolved).
double simpson(const std::function<double(double)>& f, double a, double b, double fa, double fm,
               double fb, double whole, double tol, int depth) {
  const double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
  const double flm = f(lm), frm = f(rm);
  const double left = (m - a) / 6 * (fa + 4 * flm + fm), right = (b - m) / 6 * (fm + 4 * frm + fb);
  if (depth <= 0 || std::abs(left + right - whole) <= 15 * tol)
    return left + right + (left + right - whole) / 15;
  return simpson(f, a, m, fa, flm, fm, left, tol / 2, depth - 1) +
         simpson(f, m, b, fm, frm, fb, right, tol / 2, depth - 1);
}
double quad(const std::function<double(double)>& f, double a, double b, double tol = 1e-13) {
  if (a == b) return 0.0;
  // start from 16 panels so that no feature hides between the first samples
  double sum = 0.0;
  const int n = 16;
  for (int i = 0; i < n; ++i) {
    const double x0 = a + (b - a) * i / n, x1 = a + (b - a) * (i + 1) / n;
    const double f0 = f(x0), f1 = f(x1), fm = f(0.5 * (x0 + x1));
    sum += simpson(f, x0, x1, f0, fm, f1, (x1 - x0) / 6 * (f0 + 4 * fm + f1), tol / n, 40);
  }
  return sum;
}

/// Where the curve may have a kink or a jump (its points, or t0), in amplitude time.
std::vector<double> breaks(const Amplitude& a) {
  std::vector<double> raw = a.t;
  if (a.kind != Amplitude::Kind::Tabular && a.kind != Amplitude::Kind::SmoothStep) raw = {a.t0};
  for (double& r : raw) r = a.shift_x + a.scale_x * r;
  return raw;
}

/// Quadrature of f over [x0, x1] split at the curve's breaks (so that every piece is smooth).
double quad_split(const Amplitude& a, const std::function<double(double)>& f, double x0,
                  double x1) {
  double sum = 0.0, from = x0;
  for (double b : breaks(a))
    if (b > from && b < x1) {
      sum += quad(f, from, b);
      from = b;
    }
  return sum + quad(f, from, x1);
}

/// The integral of a over [x0, x1] and the double integral (Cauchy's formula: int_{x0}^{x1}
/// (x1 - s) a(s) ds) by quadrature.
double quad1(const Amplitude& a, double x0, double x1) {
  return quad_split(
      a, [&](double s) { return a.at(s); }, x0, x1);
}
double quad2(const Amplitude& a, double x0, double x1) {
  return quad_split(
      a, [&](double s) { return (x1 - s) * a.at(s); }, x0, x1);
}

/// Checks the integrals over [x0, x1] against quadrature, and the slope at x1 against a central
/// difference (where the curve is smooth around x1).
void check_integrals(const Amplitude& a, double x0, double x1, double tol) {
  const double scale = 1.0 + std::abs(x1 - x0);
  EXPECT_NEAR(a.integral(x0, x1), quad1(a, x0, x1), tol * scale)
      << a.name << " " << x0 << " " << x1;
  EXPECT_NEAR(a.integral2(x0, x1), quad2(a, x0, x1), tol * scale * scale)
      << a.name << " " << x0 << " " << x1;
}

Amplitude table(Amplitude::Kind kind, std::vector<double> t, std::vector<double> v) {
  Amplitude a;
  a.name = kind == Amplitude::Kind::Tabular ? "TABULAR" : "SMOOTH";
  a.kind = kind;
  a.t = std::move(t);
  a.a = std::move(v);
  a.finish();
  return a;
}

TEST(Amplitude, TabularIsLinearBetweenPointsAndConstantOutside) {
  const Amplitude a = table(Amplitude::Kind::Tabular, {0, 1, 3, 4}, {0, 2, 2, -1});
  EXPECT_DOUBLE_EQ(a.at(0.5), 1.0);
  EXPECT_DOUBLE_EQ(a.at(2.0), 2.0);
  EXPECT_DOUBLE_EQ(a.at(3.5), 0.5);
  EXPECT_DOUBLE_EQ(a.at(-1.0), 0.0);
  EXPECT_DOUBLE_EQ(a.at(5.0), -1.0);
  EXPECT_DOUBLE_EQ(a.slope(0.5), 2.0);
  EXPECT_DOUBLE_EQ(a.slope(3.5), -3.0);
  EXPECT_DOUBLE_EQ(a.slope(7.0), 0.0);
  // by hand: the trapezoids 1 + 4 + 0.5; the double integral over [0, 1] of 2 s is 1/3
  EXPECT_NEAR(a.integral(0.0, 4.0), 5.5, 1e-14);
  EXPECT_NEAR(a.integral2(0.0, 1.0), 1.0 / 3.0, 1e-14);
  // after the last point: -1 per unit time; before the first: 0
  EXPECT_NEAR(a.integral(4.0, 6.0), -2.0, 1e-14);
  EXPECT_NEAR(a.integral2(-3.0, -1.0), 0.0, 1e-14);
  for (double x0 : {-1.0, 0.0, 0.3, 2.5})
    for (double x1 : {0.7, 1.0, 3.2, 4.0, 5.5}) check_integrals(a, x0, x1, 1e-11);
}

TEST(Amplitude, EmptyTableIsOne) {
  Amplitude a;
  a.finish();
  EXPECT_EQ(a.value(3.0, 1.0), 1.0);
  EXPECT_NEAR(a.integral(1.0, 3.0), 2.0, 1e-15);
  EXPECT_NEAR(a.integral2(1.0, 3.0), 2.0, 1e-15);
}

TEST(Amplitude, SmoothStepHasZeroSlopeAndCurvatureAtThePoints) {
  const Amplitude a = table(Amplitude::Kind::SmoothStep, {0, 2, 3}, {0, 1, -1});
  // xi = 1/2: xi^3 (10 - 15 xi + 6 xi^2) = 1/8 * 4 = 1/2; slope 30 xi^2 (1 - xi)^2 / h
  EXPECT_DOUBLE_EQ(a.at(1.0), 0.5);
  EXPECT_DOUBLE_EQ(a.slope(1.0), 30.0 / 16.0 / 2.0);
  EXPECT_DOUBLE_EQ(a.at(2.5), 0.0);
  for (double x : {0.0, 2.0, 3.0}) {
    EXPECT_NEAR(a.slope(x), 0.0, 1e-15);
    const double h = 1e-4; // curvature by the second difference: O(h) at a point of zero curvature
    EXPECT_NEAR((a.at(x + h) - 2 * a.at(x) + a.at(x - h)) / (h * h), 0.0, 1e-2) << x;
  }
  // the integral of the step over [0, h]: d h / 2; the double integral: d h^2 / 7
  EXPECT_NEAR(a.integral(0.0, 2.0), 1.0, 1e-14);
  EXPECT_NEAR(a.integral2(0.0, 2.0), 4.0 / 7.0, 1e-14);
  for (double x0 : {-0.5, 0.0, 1.3})
    for (double x1 : {0.4, 2.0, 2.7, 4.0}) check_integrals(a, x0, x1, 1e-11);
}

TEST(Amplitude, PeriodicIsTheFourierSeriesFromT0AndA0Before) {
  Amplitude a;
  a.name = "PERIODIC";
  a.kind = Amplitude::Kind::Periodic;
  a.omega = 3.0;
  a.t0 = 0.5;
  a.a0 = 0.2;
  a.coef = {1.0, -0.5, 0.25, 2.0};
  a.finish();
  auto hand = [](double t) {
    const double tau = t - 0.5;
    return 0.2 + std::cos(3 * tau) - 0.5 * std::sin(3 * tau) + 0.25 * std::cos(6 * tau) +
           2.0 * std::sin(6 * tau);
  };
  EXPECT_DOUBLE_EQ(a.at(0.3), 0.2);
  for (double t : {0.5, 0.9, 2.0, 7.3}) EXPECT_NEAR(a.at(t), hand(t), 1e-14) << t;
  const double h = 1e-5;
  for (double t : {0.9, 2.0}) EXPECT_NEAR(a.slope(t), (hand(t + h) - hand(t - h)) / (2 * h), 1e-7);
  // across t0 the curve jumps (A1 + A2 = 1.25): quadrature resolves it
  for (double x0 : {0.0, 0.5, 1.1})
    for (double x1 : {0.6, 2.0, 5.0}) check_integrals(a, x0, x1, 1e-10);
}

TEST(Amplitude, ModulatedAndDecay) {
  Amplitude m;
  m.name = "MODULATED";
  m.kind = Amplitude::Kind::Modulated;
  m.a0 = 0.5;
  m.amp = 2.0;
  m.t0 = 1.0;
  m.omega = 5.0;
  m.omega2 = 0.5;
  m.finish();
  EXPECT_DOUBLE_EQ(m.at(0.5), 0.5);
  EXPECT_NEAR(m.at(2.0), 0.5 + 2.0 * std::sin(5.0) * std::sin(0.5), 1e-14);
  const double h = 1e-5;
  EXPECT_NEAR(m.slope(2.0), (m.at(2.0 + h) - m.at(2.0 - h)) / (2 * h), 1e-7);
  for (double x0 : {0.0, 1.0, 1.7})
    for (double x1 : {1.2, 3.0, 6.0}) check_integrals(m, x0, x1, 1e-10);
  m.omega2 = 5.0; // equal frequencies: the difference term is constant (the c = 0 limit)
  for (double x1 : {1.2, 3.0}) check_integrals(m, 0.0, x1, 1e-10);

  Amplitude d;
  d.name = "DECAY";
  d.kind = Amplitude::Kind::Decay;
  d.a0 = -1.0;
  d.amp = 3.0;
  d.t0 = 0.25;
  d.td = 0.7;
  d.finish();
  EXPECT_DOUBLE_EQ(d.at(0.0), -1.0);
  EXPECT_NEAR(d.at(1.65), -1.0 + 3.0 * std::exp(-2.0), 1e-14);
  EXPECT_NEAR(d.slope(1.65), -3.0 / 0.7 * std::exp(-2.0), 1e-14);
  for (double x0 : {0.0, 0.25, 0.5})
    for (double x1 : {0.3, 1.0, 4.0}) check_integrals(d, x0, x1, 1e-10);
}

TEST(Amplitude, ScaleAndShiftActOnTimeAndValue) {
  Amplitude a = table(Amplitude::Kind::Tabular, {0, 1}, {0, 1});
  a.scale_x = 2.0;
  a.shift_x = 1.0;
  a.scale_y = 3.0;
  a.shift_y = -0.5;
  // a(x) = 3 r((x - 1) / 2) - 0.5: the ramp now runs from x = 1 to x = 3, up to 2.5
  EXPECT_DOUBLE_EQ(a.at(1.0), -0.5);
  EXPECT_DOUBLE_EQ(a.at(2.0), 1.0);
  EXPECT_DOUBLE_EQ(a.at(5.0), 2.5);
  EXPECT_DOUBLE_EQ(a.slope(2.0), 1.5);
  for (double x0 : {0.0, 1.5})
    for (double x1 : {2.0, 3.0, 4.5}) check_integrals(a, x0, x1, 1e-11);
}

TEST(Amplitude, StepAndTotalTime) {
  Amplitude a = table(Amplitude::Kind::Tabular, {0, 10}, {0, 10});
  EXPECT_DOUBLE_EQ(a.value(2.0, 5.0), 2.0);
  a.time = Amplitude::TimeBase::Total;
  EXPECT_DOUBLE_EQ(a.value(2.0, 5.0), 7.0);
  EXPECT_DOUBLE_EQ(a.time_of(2.0, 5.0), 7.0);
}

TEST(Amplitude, RandomizedTablesIntegrateAsQuadrature) {
  std::mt19937 gen(46);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 1 + static_cast<int>(u(gen) * 9);
    std::vector<double> t, v;
    double x = -2.0 + 4.0 * u(gen);
    for (int i = 0; i < n; ++i) {
      x += 0.05 + u(gen); // at least 0.05 apart
      t.push_back(x);
      v.push_back(-5.0 + 10.0 * u(gen));
    }
    const auto kind = trial % 2 ? Amplitude::Kind::SmoothStep : Amplitude::Kind::Tabular;
    const Amplitude a = table(kind, t, v);
    for (int k = 0; k < 4; ++k) {
      double x0 = t.front() - 1.0 + (t.back() - t.front() + 2.0) * u(gen);
      double x1 = t.front() - 1.0 + (t.back() - t.front() + 2.0) * u(gen);
      if (x1 < x0) std::swap(x0, x1);
      check_integrals(a, x0, x1, 1e-10);
    }
  }
}

} // namespace
} // namespace gapfem
