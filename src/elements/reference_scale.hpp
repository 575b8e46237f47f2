#pragma once
/// @file reference_scale.hpp
/// Geometric checks that hold at any scale. A length, area or volume computed from coordinates of
/// 1e200 overflows (and from coordinates of 1e-120 underflows) long before the element is
/// degenerate; a check that squares or multiplies coordinates then reports "coincide" or
/// "inverted" for a sound element. The checks therefore look at the nodes scaled by a power of two
/// (exact) that brings the element's extent near 1, and lengths are taken with std::hypot.
#include "common/types.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

namespace gapfem {

/// The power of two f for which the nodes X * f span about 1: their largest coordinate
/// difference (the element's extent) times f lies in [0.5, 1). 1 when the nodes coincide or are
/// not finite (the check then sees them as they are).
inline double unit_scale(std::span<const Vec3> X) {
  double extent = 0.0;
  for (const Vec3& x : X)
    for (int i = 0; i < 3; ++i) extent = std::max(extent, std::abs(x[i] - X[0][i]));
  if (!(extent > 0.0) || !std::isfinite(extent)) {
    // (a difference can overflow where the coordinates do not: halve them first)
    for (const Vec3& x : X)
      for (int i = 0; i < 3; ++i) extent = std::max(extent, std::abs(0.5 * x[i] - 0.5 * X[0][i]));
    if (!(extent > 0.0) || !std::isfinite(extent)) return 1.0;
    return std::ldexp(0.5, -std::ilogb(extent));
  }
  return std::ldexp(1.0, -std::ilogb(extent) - 1);
}

/// The nodes X scaled by unit_scale(X) into `out` (which holds at least X.size() nodes): what
/// a check of the reference geometry looks at.
template <std::size_t N>
std::span<const Vec3> scaled_nodes(std::span<const Vec3> X, std::array<Vec3, N>& out) {
  const double f = unit_scale(X);
  const std::size_t n = std::min(X.size(), N);
  for (std::size_t a = 0; a < n; ++a)
    for (int i = 0; i < 3; ++i) out[a][i] = f * X[a][i];
  return {out.data(), n};
}

/// |a - b| without overflow or underflow of the squares.
inline double point_distance(const Vec3& a, const Vec3& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

} // namespace gapfem
