#pragma once
/// @file table.hpp
/// Piecewise-linear tables used for temperature-dependent material data and tabulated laws.
#include <span>
#include <vector>

namespace gapfem {

/// Rows of n_values property values plus one independent variable (usually temperature), sorted by
/// that variable. Interpolation is linear, extrapolation constant (Abaqus's rule for material
/// data).
struct PropertyTable {
  int n_values = 0;
  std::vector<double> values; ///< row-major, n_rows × n_values
  std::vector<double> keys;   ///< one per row; empty or size 1 means "not dependent"

  bool empty() const { return values.empty(); }
  int n_rows() const { return n_values == 0 ? 0 : static_cast<int>(values.size()) / n_values; }
  /// Interpolate all values at `key` into out (size n_values); optionally the derivative d/dkey.
  void evaluate(double key, std::span<double> out, std::span<double> dout = {}) const;
  /// Convenience for single-valued tables.
  double value(double key) const;
  double derivative(double key) const;
};

/// y(x) piecewise linear through (x_i, y_i), x ascending. Outside the range: `extrapolate` decides
/// between constant values and continuing the end slopes.
struct Curve {
  std::vector<double> x, y;
  enum class Extrapolation { Constant, Linear } extrapolation = Extrapolation::Constant;
  double value(double at) const;
  double slope(double at) const;
};

} // namespace gapfem
