#pragma once
/// @file jet.hpp
/// Second-order forward-mode automatic differentiation: a Jet<N> carries a value, its gradient
/// with respect to N independent variables and its (symmetric) Hessian. An element that writes its
/// energy once as a template over the scalar type gets the residual (the gradient) and the exact
/// consistent tangent (the Hessian) from the same code, with no hand-derived linearisation to get
/// wrong (docs/theory/structural.md, "Geometrically exact beams"). Dual<N> is the first-order
/// counterpart (value and gradient).
///
/// Fixed size, no heap: the Hessian is stored packed (upper triangle, row by row). Each product
/// costs O(N^2), so Jets suit small kernels (beams: N <= 18). Functions that are smooth but whose
/// closed forms lose precision or divide by zero near a point (sin(x)/x at 0) are evaluated through
/// `chain(a, f, f', f'')` with the caller's own series.
#include <array>
#include <cmath>

namespace gapfem {

template <int N>
struct Jet {
  static constexpr int kPacked = N * (N + 1) / 2;
  double v = 0.0;
  std::array<double, N> g{};
  std::array<double, kPacked> h{};

  Jet() = default;
  Jet(double value) : v(value) {} // NOLINT(google-explicit-constructor): constants mix freely

  /// The independent variable number `i` with value `value`.
  static Jet variable(double value, int i) {
    Jet j(value);
    j.g[i] = 1.0;
    return j;
  }
  /// Packed index of Hessian entry (i, j), i <= j.
  static constexpr int index(int i, int j) { return i * N - i * (i - 1) / 2 + (j - i); }
  /// Hessian entry (i, j), any order.
  double hess(int i, int j) const { return i <= j ? h[index(i, j)] : h[index(j, i)]; }

  Jet& operator+=(const Jet& b) {
    v += b.v;
    for (int i = 0; i < N; ++i) g[i] += b.g[i];
    for (int k = 0; k < kPacked; ++k) h[k] += b.h[k];
    return *this;
  }
  Jet& operator-=(const Jet& b) {
    v -= b.v;
    for (int i = 0; i < N; ++i) g[i] -= b.g[i];
    for (int k = 0; k < kPacked; ++k) h[k] -= b.h[k];
    return *this;
  }
  Jet& operator+=(double s) {
    v += s;
    return *this;
  }
  Jet& operator-=(double s) {
    v -= s;
    return *this;
  }
  Jet& operator*=(double s) {
    v *= s;
    for (int i = 0; i < N; ++i) g[i] *= s;
    for (int k = 0; k < kPacked; ++k) h[k] *= s;
    return *this;
  }
  Jet& operator*=(const Jet& b) { return *this = *this * b; }

  friend Jet operator+(Jet a, const Jet& b) { return a += b; }
  friend Jet operator-(Jet a, const Jet& b) { return a -= b; }
  friend Jet operator+(Jet a, double s) { return a += s; }
  friend Jet operator+(double s, Jet a) { return a += s; }
  friend Jet operator-(Jet a, double s) { return a -= s; }
  friend Jet operator-(double s, const Jet& a) { return (-a) += s; }
  friend Jet operator-(Jet a) { return a *= -1.0; }
  friend Jet operator*(Jet a, double s) { return a *= s; }
  friend Jet operator*(double s, Jet a) { return a *= s; }
  friend Jet operator/(Jet a, double s) { return a *= 1.0 / s; }

  /// Product rule: (ab)'' = a b'' + b a'' + a' b'^T + b' a'^T.
  friend Jet operator*(const Jet& a, const Jet& b) {
    Jet c;
    c.v = a.v * b.v;
    for (int i = 0; i < N; ++i) c.g[i] = a.v * b.g[i] + b.v * a.g[i];
    int k = 0;
    for (int i = 0; i < N; ++i)
      for (int j = i; j < N; ++j, ++k)
        c.h[k] = a.v * b.h[k] + b.v * a.h[k] + a.g[i] * b.g[j] + a.g[j] * b.g[i];
    return c;
  }
  friend Jet operator/(const Jet& a, const Jet& b) { return a * reciprocal(b); }
  friend Jet operator/(double s, const Jet& b) { return reciprocal(b) *= s; }

  /// f(a) from f(a.v), f'(a.v), f''(a.v): g = f' a', H = f' a'' + f'' a' a'^T.
  friend Jet chain(const Jet& a, double f0, double f1, double f2) {
    Jet c;
    c.v = f0;
    for (int i = 0; i < N; ++i) c.g[i] = f1 * a.g[i];
    int k = 0;
    for (int i = 0; i < N; ++i)
      for (int j = i; j < N; ++j, ++k) c.h[k] = f1 * a.h[k] + f2 * a.g[i] * a.g[j];
    return c;
  }
  friend Jet reciprocal(const Jet& a) {
    const double r = 1.0 / a.v;
    return chain(a, r, -r * r, 2.0 * r * r * r);
  }
  friend Jet sqrt(const Jet& a) {
    const double s = std::sqrt(a.v);
    return chain(a, s, 0.5 / s, -0.25 / (s * a.v));
  }
  friend Jet sin(const Jet& a) {
    const double s = std::sin(a.v);
    return chain(a, s, std::cos(a.v), -s);
  }
  friend Jet cos(const Jet& a) {
    const double c = std::cos(a.v);
    return chain(a, c, -std::sin(a.v), -c);
  }
  friend Jet atan(const Jet& a) {
    const double d = 1.0 / (1.0 + a.v * a.v);
    return chain(a, std::atan(a.v), d, -2.0 * a.v * d * d);
  }
  friend Jet asin(const Jet& a) {
    const double q = 1.0 / (1.0 - a.v * a.v);
    const double d = std::sqrt(q);
    return chain(a, std::asin(a.v), d, a.v * q * d);
  }
  friend double value(const Jet& a) { return a.v; }
};

/// First-order forward differentiation: value and gradient only, O(N) per operation. For
/// functions that are linear in the variables (small-displacement strains), whose Hessian the
/// caller forms itself (B^T C B).
template <int N>
struct Dual {
  double v = 0.0;
  std::array<double, N> g{};

  Dual() = default;
  Dual(double value) : v(value) {} // NOLINT(google-explicit-constructor)
  static Dual variable(double value, int i) {
    Dual d(value);
    d.g[i] = 1.0;
    return d;
  }
  Dual& operator+=(const Dual& b) {
    v += b.v;
    for (int i = 0; i < N; ++i) g[i] += b.g[i];
    return *this;
  }
  Dual& operator-=(const Dual& b) {
    v -= b.v;
    for (int i = 0; i < N; ++i) g[i] -= b.g[i];
    return *this;
  }
  Dual& operator+=(double s) {
    v += s;
    return *this;
  }
  Dual& operator-=(double s) {
    v -= s;
    return *this;
  }
  Dual& operator*=(double s) {
    v *= s;
    for (int i = 0; i < N; ++i) g[i] *= s;
    return *this;
  }
  friend Dual operator+(Dual a, const Dual& b) { return a += b; }
  friend Dual operator-(Dual a, const Dual& b) { return a -= b; }
  friend Dual operator+(Dual a, double s) { return a += s; }
  friend Dual operator+(double s, Dual a) { return a += s; }
  friend Dual operator-(Dual a, double s) { return a -= s; }
  friend Dual operator-(double s, const Dual& a) { return (-a) += s; }
  friend Dual operator-(Dual a) { return a *= -1.0; }
  friend Dual operator*(Dual a, double s) { return a *= s; }
  friend Dual operator*(double s, Dual a) { return a *= s; }
  friend Dual operator/(Dual a, double s) { return a *= 1.0 / s; }
  friend Dual operator*(const Dual& a, const Dual& b) {
    Dual c;
    c.v = a.v * b.v;
    for (int i = 0; i < N; ++i) c.g[i] = a.v * b.g[i] + b.v * a.g[i];
    return c;
  }
  /// f(a) from f(a.v) and f'(a.v) (f'' is not needed at first order).
  friend Dual chain(const Dual& a, double f0, double f1, double) {
    Dual c;
    c.v = f0;
    for (int i = 0; i < N; ++i) c.g[i] = f1 * a.g[i];
    return c;
  }
  friend Dual reciprocal(const Dual& a) { return chain(a, 1.0 / a.v, -1.0 / (a.v * a.v), 0.0); }
  friend Dual operator/(const Dual& a, const Dual& b) { return a * reciprocal(b); }
  friend Dual operator/(double s, const Dual& b) { return reciprocal(b) *= s; }
  friend Dual sqrt(const Dual& a) {
    const double s = std::sqrt(a.v);
    return chain(a, s, 0.5 / s, 0.0);
  }
  friend Dual sin(const Dual& a) { return chain(a, std::sin(a.v), std::cos(a.v), 0.0); }
  friend Dual cos(const Dual& a) { return chain(a, std::cos(a.v), -std::sin(a.v), 0.0); }
  friend Dual atan(const Dual& a) { return chain(a, std::atan(a.v), 1.0 / (1.0 + a.v * a.v), 0.0); }
  friend Dual asin(const Dual& a) {
    return chain(a, std::asin(a.v), 1.0 / std::sqrt(1.0 - a.v * a.v), 0.0);
  }
  friend double value(const Dual& a) { return a.v; }
};

/// Uniform access to the value of a scalar that may be a plain double.
inline double value(double a) {
  return a;
}
/// chain() for plain doubles, so templated code can call it for either scalar type.
inline double chain(double, double f0, double, double) {
  return f0;
}

/// atan2 for any scalar: the branch is chosen by value, the derivatives are those of atan2.
template <class T>
T atan2_any(const T& y, const T& x) {
  using std::atan;
  const double yv = value(y), xv = value(x);
  constexpr double pi = 3.14159265358979323846;
  if (std::abs(xv) >= std::abs(yv)) {
    if (xv == 0.0) return T(0.0) * y; // both zero: atan2(0, 0) = 0, derivative taken as 0
    const T a = atan(y / x);
    return xv > 0.0 ? a : a + (yv >= 0.0 ? pi : -pi);
  }
  return (yv > 0.0 ? 0.5 * pi : -0.5 * pi) - atan(x / y);
}

} // namespace gapfem
