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
  /// Per row, in dynamic steps (empty otherwise): the row's product with the committed velocities
  /// and accelerations of the prescribed DOFs it touches, which its columns leave out (a gap to a
  /// moving support): an impact makes C v + given_v and C a + given_a vanish
  std::vector<double> given_v, given_a;
  /// Per row, in dynamic steps: C (u - u_start) over all its DOFs, prescribed ones included (how
  /// far the increment moved along the row: the closure of a gap that closed in it)
  std::vector<double> travel;

  int n_rows() const { return static_cast<int>(g.size()); }
  void clear() {
    row_ptr.assign(1, 0);
    col.clear();
    val.clear();
    dval.clear();
    g.clear();
    compliance.clear();
    multiplier.clear();
    given_v.clear();
    given_a.clear();
    travel.clear();
  }
  /// The fields a dynamic step's rows read their prescribed parts from (add_given).
  struct GivenFields {
    std::span<const double> v, a, u, u_start; ///< per slot
  };
  /// After add_row returned true (dynamic steps): the row's given_v, given_a from the committed
  /// rates per slot of the DOFs whose equation number is negative (prescribed), and its travel.
  void add_given(std::span<const LocalIndex> eqs, std::span<const LocalIndex> slots,
                 std::span<const double> coeff, const GivenFields& f) {
    double pv = 0.0, pa = 0.0, du = 0.0;
    for (std::size_t k = 0; k < eqs.size(); ++k) {
      const auto s = static_cast<std::size_t>(slots[k]);
      if (!f.u.empty() && !f.u_start.empty()) du += coeff[k] * (f.u[s] - f.u_start[s]);
      if (eqs[k] >= 0) continue;
      pv += coeff[k] * f.v[s];
      if (!f.a.empty()) pa += coeff[k] * f.a[s];
    }
    given_v.push_back(pv);
    given_a.push_back(pa);
    travel.push_back(du);
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
