#pragma once
/// @file constraint_block.hpp
/// The active constraint rows of one Newton iteration (closed hard-contact gaps, Lagrange stick):
/// a sparse matrix C (rows = constraints, columns = equations), the constraint values g(u) and,
/// per row, where its multiplier lives in the model's multiplier storage.
#include "common/types.hpp"

#include <span>
#include <vector>

namespace gapfem {

struct ConstraintBlock {
  std::vector<LocalIndex> row_ptr{0};
  std::vector<LocalIndex> col;
  std::vector<double> val;
  /// Optional: d(residual)/d(lambda) per row in the same layout as val (the column block D of the
  /// system [K D; C 0]); empty when D = C^T for every row.
  std::vector<double> dval;
  std::vector<double> g; ///< g_i(u); the Newton step drives C du - E dl + g to 0
  /// E_ii per row: 0 for an exact constraint; 1/k for a compliant row, whose multiplier is a force
  /// of stiffness k (a penalty gap): the row's equation is C du - dl / k + g = 0
  std::vector<double> compliance;
  std::vector<std::int64_t> multiplier; ///< index of the row's multiplier in the model storage

  int n_rows() const { return static_cast<int>(g.size()); }
  void clear() {
    row_ptr.assign(1, 0);
    col.clear();
    val.clear();
    dval.clear();
    g.clear();
    compliance.clear();
    multiplier.clear();
  }
  /// Append a row: equation numbers (negative = prescribed DOF, skipped) and coefficients.
  /// Returns false (and appends nothing) when no coefficient falls on a free equation.
  bool add_row(std::span<const LocalIndex> eqs, std::span<const double> coeff, double value,
               std::int64_t multiplier_index, std::span<const double> column = {},
               double row_compliance = 0.0);
  bool has_compliance() const;
  bool has_columns() const { return !dval.empty(); }
  /// E_rr (0 when no row carries a compliance).
  double row_compliance(int r) const {
    return static_cast<std::size_t>(r) < compliance.size() ? compliance[r] : 0.0;
  }
  /// Entry k of D (the row's own column when given, else its coefficient).
  double column_value(LocalIndex k) const { return has_columns() ? dval[k] : val[k]; }
  /// y = C x
  void multiply(std::span<const double> x, std::span<double> y) const;
  /// x += alpha * C^T y
  void add_transpose_multiply(std::span<const double> y, double alpha, std::span<double> x) const;
  /// x += alpha * D y (D = C^T when no columns were given)
  void add_column_multiply(std::span<const double> y, double alpha, std::span<double> x) const;
};

} // namespace gapfem
