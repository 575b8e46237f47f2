// Jet<N> (second-order forward differentiation) and the finite-rotation helpers built on it:
// gradients and Hessians against central differences of the plain-double evaluation, the series
// branches against the closed forms at their switch-over, and the rotation identities.
#include "common/jet.hpp"
#include "elements/structural/rotation.hpp"

#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <random>

namespace gapfem {
namespace {

using namespace rotation;

/// f(x) for N inputs, evaluated with any scalar.
template <int N>
using Fn = std::function<Jet<N>(const std::array<Jet<N>, N>&)>;

/// Checks the gradient and Hessian of a Jet function against central differences of its value.
template <int N>
void expect_matches_fd(const std::function<Jet<N>(const std::array<Jet<N>, N>&)>& f,
                       std::array<double, N> x, double tol) {
  std::array<Jet<N>, N> xv;
  for (int i = 0; i < N; ++i) xv[i] = Jet<N>::variable(x[i], i);
  const Jet<N> y = f(xv);
  auto val = [&](std::array<double, N> p) {
    std::array<Jet<N>, N> pj;
    for (int i = 0; i < N; ++i) pj[i] = Jet<N>::variable(p[i], i);
    return f(pj);
  };
  const double h = 1e-5;
  for (int i = 0; i < N; ++i) {
    auto xp = x, xm = x;
    xp[i] += h;
    xm[i] -= h;
    const Jet<N> yp = val(xp), ym = val(xm);
    EXPECT_NEAR(y.g[i], (yp.v - ym.v) / (2 * h), tol) << "g" << i;
    for (int j = 0; j < N; ++j)
      EXPECT_NEAR(y.hess(i, j), (yp.g[j] - ym.g[j]) / (2 * h), tol) << "H" << i << j;
  }
}

TEST(Jet, ArithmeticAndFunctionsMatchCentralDifferences) {
  expect_matches_fd<3>(
      [](const std::array<Jet<3>, 3>& x) {
        return sin(x[0] * x[1]) / (2.0 + cos(x[2])) + sqrt(1.0 + x[0] * x[0]) * atan(x[1] - x[2]) -
               3.0 * x[2] * x[2] * x[0] + asin(0.3 * x[1]);
      },
      {0.7, -0.4, 1.3}, 1e-7);
  expect_matches_fd<2>([](const std::array<Jet<2>, 2>& x) { return atan2_any(x[0], x[1]); },
                       {-0.3, -0.8}, 1e-7);
  expect_matches_fd<2>([](const std::array<Jet<2>, 2>& x) { return atan2_any(x[0], x[1]); },
                       {0.9, 0.2}, 1e-7);
}

TEST(Jet, SeriesBranchesAgreeWithTheClosedFormsAtTheSwitch) {
  // just below and above the switch, value and the first two derivatives must agree
  for (double x : {kSeriesLimit * (1 - 1e-9), kSeriesLimit * (1 + 1e-9)}) {
    const Jet<1> v = Jet<1>::variable(x, 0);
    const double t = std::sqrt(x);
    EXPECT_NEAR(cos_half(v).v, std::cos(t / 2), 1e-15);
    EXPECT_NEAR(sinc_half(v).v, std::sin(t / 2) / t, 1e-15);
    EXPECT_NEAR(one_minus_cos_over(v).v, (1 - std::cos(t)) / x, 1e-13);
    EXPECT_NEAR(theta_minus_sin_over(v).v, (t - std::sin(t)) / (x * t), 1e-11);
  }
  const double lo = kSeriesLimit * (1 - 1e-7), hi = kSeriesLimit * (1 + 1e-7);
  auto both = [&](auto f) {
    const Jet<1> a = f(Jet<1>::variable(lo, 0)), b = f(Jet<1>::variable(hi, 0));
    EXPECT_NEAR(a.g[0], b.g[0], 1e-8);
    EXPECT_NEAR(a.h[0], b.h[0], 1e-6);
  };
  both([](const Jet<1>& x) { return cos_half(x); });
  both([](const Jet<1>& x) { return sinc_half(x); });
  both([](const Jet<1>& x) { return one_minus_cos_over(x); });
  both([](const Jet<1>& x) { return theta_minus_sin_over(x); });
  const Jet<1> a = asin_ratio(Jet<1>::variable(0.01 * (1 - 1e-9), 0));
  const Jet<1> b = asin_ratio(Jet<1>::variable(0.01 * (1 + 1e-9), 0));
  EXPECT_NEAR(a.v, b.v, 1e-11); // the inputs differ by 2e-11, the slope is 0.17
  EXPECT_NEAR(a.g[0], b.g[0], 1e-8);
}

TEST(Rotation, ExpLogRoundTripAndRotationMatchRodrigues) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int k = 0; k < 50; ++k) {
    const double scale = k < 10 ? 1e-4 : 1.8; // small (series) and large angles, |v| < pi
    const V3<double> v{scale * U(rng), scale * U(rng), scale * U(rng)};
    const V3<double> back = quat_log(quat_exp(v));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(back[i], v[i], 1e-12);
    // Rodrigues: R a = a cos + (n x a) sin + n (n.a)(1 - cos)
    const V3<double> a{U(rng), U(rng), U(rng)};
    const double th = std::sqrt(dot3(v, v));
    const V3<double> n{v[0] / th, v[1] / th, v[2] / th};
    const V3<double> na = cross3(n, a);
    const V3<double> r = rotate(quat_exp(v), a);
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(
          r[i], a[i] * std::cos(th) + na[i] * std::sin(th) + n[i] * dot3(n, a) * (1 - std::cos(th)),
          1e-12);
  }
}

TEST(Rotation, RightJacobianIsTheDerivativeOfTheExponentialMap) {
  // exp(phi)^T d/ds exp(phi + s d) at s = 0 is the skew matrix of J_r(phi) d: check on a vector
  for (const V3<double> phi : {V3<double>{0.3, -1.1, 0.7}, V3<double>{1e-3, 2e-3, -1e-3}}) {
    const V3<double> d{0.2, 0.5, -0.4}, a{1.0, -2.0, 0.5};
    const double h = 1e-6;
    V3<double> pp, pm;
    for (int i = 0; i < 3; ++i) pp[i] = phi[i] + h * d[i], pm[i] = phi[i] - h * d[i];
    const V3<double> rp = rotate(quat_exp(pp), a), rm = rotate(quat_exp(pm), a);
    V3<double> dr;
    for (int i = 0; i < 3; ++i) dr[i] = (rp[i] - rm[i]) / (2 * h);
    const V3<double> w = right_jacobian(phi, d);
    // d(R a) = R (w x a)
    const V3<double> expect = rotate(quat_exp(phi), cross3(w, a));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(dr[i], expect[i], 1e-8);
  }
}

TEST(Rotation, MidpointIsHalfwayOnTheShortestArc) {
  const Quat<double> a = quat_exp(V3<double>{0.2, 0.1, -0.3});
  const Quat<double> b = quat_exp(V3<double>{-0.5, 0.9, 0.4});
  Quat<double> nb{-b.w, -b.x, -b.y, -b.z}; // the same rotation
  for (const Quat<double>& bb : {b, nb}) {
    const Quat<double> m = quat_mid(a, bb);
    const V3<double> h1 = quat_log(quat_mul(conj(a), m));
    const V3<double> h2 = quat_log(quat_mul(conj(m), bb));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(h1[i], h2[i], 1e-12);
  }
}

} // namespace
} // namespace gapfem
