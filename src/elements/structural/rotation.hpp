#pragma once
/// @file rotation.hpp
/// Finite rotations for the geometrically exact beams, templated on the scalar (double or Jet<N>):
/// unit quaternions, the exponential map of a rotation vector, its logarithm, and the right
/// Jacobian of the exponential map. Every function is smooth through the zero rotation: the
/// functions of theta^2 that the closed forms divide by theta are evaluated by their Taylor series
/// below a small angle, so the derivatives a Jet carries are exact there too.
/// Conventions: q = (w, x, y, z) = (cos(theta/2), sin(theta/2) n); R(q) a = q a q*.
#include "common/jet.hpp"

#include <array>
#include <cmath>
#include <initializer_list>
#include <type_traits>

namespace gapfem::rotation {

template <class T>
using V3 = std::array<T, 3>;

template <class T>
struct Quat {
  T w = T(1.0), x = T(0.0), y = T(0.0), z = T(0.0);
};

template <class A, class B>
auto dot3(const V3<A>& a, const V3<B>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class A, class B>
auto cross3(const V3<A>& a, const V3<B>& b) {
  using R = decltype(a[0] * b[0]);
  return V3<R>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// Polynomial c0 + c1 x + c2 x^2 + … by Horner's rule.
template <class T>
T horner(const T& x, std::initializer_list<double> c) {
  const double* p = c.end();
  T r(*--p);
  while (p != c.begin()) r = r * x + *--p;
  return r;
}

/// Below this theta^2 the trigonometric functions of theta^2 use their series (error < 1e-20).
inline constexpr double kSeriesLimit = 0.04;

/// cos(theta / 2) as a function of x = theta^2.
template <class T>
T cos_half(const T& x) {
  using std::cos, std::sqrt;
  if (value(x) < kSeriesLimit)
    return horner(x, {1.0, -1.0 / 8, 1.0 / 384, -1.0 / 46080, 1.0 / 10321920, -1.0 / 3715891200.0});
  return cos(0.5 * sqrt(x));
}
/// sin(theta / 2) / theta as a function of x = theta^2.
template <class T>
T sinc_half(const T& x) {
  using std::sin, std::sqrt;
  if (value(x) < kSeriesLimit)
    return 0.5 * horner(x, {1.0, -1.0 / 24, 1.0 / 1920, -1.0 / 322560, 1.0 / 92897280.0,
                            -1.0 / 40874803200.0});
  const T t = sqrt(x);
  return sin(0.5 * t) / t;
}
/// (1 - cos theta) / theta^2 as a function of x = theta^2.
template <class T>
T one_minus_cos_over(const T& x) {
  using std::cos, std::sqrt;
  if (value(x) < kSeriesLimit)
    return horner(x,
                  {0.5, -1.0 / 24, 1.0 / 720, -1.0 / 40320, 1.0 / 3628800.0, -1.0 / 479001600.0});
  return (1.0 - cos(sqrt(x))) / x;
}
/// (theta - sin theta) / theta^3 as a function of x = theta^2.
template <class T>
T theta_minus_sin_over(const T& x) {
  using std::sin, std::sqrt;
  if (value(x) < kSeriesLimit)
    return horner(
        x, {1.0 / 6, -1.0 / 120, 1.0 / 5040, -1.0 / 362880, 1.0 / 39916800.0, -1.0 / 6227020800.0});
  const T t = sqrt(x);
  return (t - sin(t)) / (x * t);
}
/// asin(sqrt(s)) / sqrt(s) for 0 <= s < 1.
template <class T>
T asin_ratio(const T& s) {
  using std::asin, std::sqrt;
  if (value(s) < 0.01)
    return horner(s, {1.0, 1.0 / 6, 3.0 / 40, 5.0 / 112, 35.0 / 1152, 63.0 / 2816, 231.0 / 13312,
                      143.0 / 10240});
  const T r = sqrt(s);
  return asin(r) / r;
}

/// Quaternion of the rotation vector v (the exponential map).
template <class T>
Quat<T> quat_exp(const V3<T>& v) {
  const T x = dot3(v, v);
  if constexpr (std::is_same_v<T, double>) {
    // theta^2 overflows before theta does (rotations of a linear analysis under loads near the
    // double range): the angle from a scaled norm keeps the quaternion finite
    if (!std::isfinite(x)) {
      const double t = std::hypot(v[0], v[1], v[2]);
      if (std::isfinite(t) && t > 0.0) {
        const double s = std::sin(0.5 * t) / t;
        return {std::cos(0.5 * t), s * v[0], s * v[1], s * v[2]};
      }
    }
  }
  const T s = sinc_half(x);
  return {cos_half(x), s * v[0], s * v[1], s * v[2]};
}

/// Rotation vector of q (the logarithm), |result| < pi; q and -q give the same vector.
template <class T>
V3<T> quat_log(Quat<T> q) {
  if (value(q.w) < 0.0) q = {-q.w, -q.x, -q.y, -q.z};
  const T s = q.x * q.x + q.y * q.y + q.z * q.z; // sin^2(theta / 2)
  const T f = 2.0 * asin_ratio(s);
  return {f * q.x, f * q.y, f * q.z};
}

template <class A, class B>
auto quat_mul(const Quat<A>& a, const Quat<B>& b) {
  using R = decltype(a.w * b.w);
  return Quat<R>{
      a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
      a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
template <class T>
Quat<T> conj(const Quat<T>& q) {
  return {q.w, -q.x, -q.y, -q.z};
}

/// R(q) a: a + 2 w (v x a) + 2 v x (v x a) for q = (w, v).
template <class T, class A>
auto rotate(const Quat<T>& q, const V3<A>& a) {
  const V3<T> v{q.x, q.y, q.z};
  const auto c = cross3(v, a);
  const auto cc = cross3(v, c);
  using R = decltype(c[0] * q.w);
  V3<R> r;
  for (int i = 0; i < 3; ++i) r[i] = a[i] + 2.0 * (q.w * c[i] + cc[i]);
  return r;
}

/// Writes q normalised to a unit quaternion (w, x, y, z) into out[0..3]: the nodal-rotation history
/// of the beams and shells.
inline void store_unit(const Quat<double>& q, double* out) {
  const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  out[0] = q.w / n;
  out[1] = q.x / n;
  out[2] = q.y / n;
  out[3] = q.z / n;
}

/// Normalised midpoint of two rotations on the shortest arc: exp(log(a* b) / 2) applied to a.
template <class T>
Quat<T> quat_mid(const Quat<T>& a, Quat<T> b) {
  using std::sqrt;
  if (value(a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z) < 0.0) b = {-b.w, -b.x, -b.y, -b.z};
  const T w = a.w + b.w, x = a.x + b.x, y = a.y + b.y, z = a.z + b.z;
  const T r = 1.0 / sqrt(w * w + x * x + y * y + z * z);
  return {w * r, x * r, y * r, z * r};
}

/// The right Jacobian of the exponential map applied to a: exp(phi)^T d exp(phi) = [J_r dphi]x,
/// J_r = I - (1 - cos)/theta^2 [phi]x + (theta - sin)/theta^3 [phi]x^2.
template <class T>
V3<T> right_jacobian(const V3<T>& phi, const V3<T>& a) {
  const T x = dot3(phi, phi);
  const T b = one_minus_cos_over(x), c = theta_minus_sin_over(x);
  const V3<T> pa = cross3(phi, a);
  const V3<T> ppa = cross3(phi, pa);
  return {a[0] - b * pa[0] + c * ppa[0], a[1] - b * pa[1] + c * ppa[1],
          a[2] - b * pa[2] + c * ppa[2]};
}

} // namespace gapfem::rotation
