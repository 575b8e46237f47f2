#pragma once
/// @file norms.hpp
/// Vector norms the solvers share.
#include <algorithm>
#include <cmath>
#include <span>

namespace gapfem {

/// max |v_i| (0 for an empty vector).
inline double norm_inf(std::span<const double> v) {
  double s = 0.0;
  for (double x : v) s = std::max(s, std::abs(x));
  return s;
}

} // namespace gapfem
