#pragma once
/// @file multiplier_columns.hpp
/// The multiplier system of a kept Cholesky factor as a dense matrix. With M = L L^T (in the
/// factor's ordering P) and constraint rows c_i, the multiplier (Schur) matrix C M^-1 C^T is
/// Z^T Z with the columns z_i = L^-1 P c_i^T. They are sparse (the elimination-tree paths from a
/// row's DOFs to the root), made by sparse forward solves when a row first appears, and kept
/// with their inner products while the factor lives: a Newton step is then one forward solve,
/// a dense solve of the multipliers and one backward solve (docs/theory/gap_elements.md,
/// "Solving the constrained system").
#include "linalg/constraint_block.hpp"
#include "linalg/linear_solver.hpp"

#include <Eigen/Dense>
#include <span>
#include <unordered_map>
#include <vector>

namespace gapfem {

class MultiplierColumns {
 public:
  /// Forget every column (a new factor of size n).
  void reset(LocalIndex n);
  int size() const { return static_cast<int>(_cols.size()); }
  /// The column of row r of B (found by its multiplier and coefficients), or -1.
  int find(const ConstraintBlock& B, int r) const;
  /// Make the columns of rows `rows` of B (none of them present) with the solver's sparse
  /// forward solves; their indices go to `index`. False (nothing added) when the solver declines.
  bool add(LinearSolver& solver, const ConstraintBlock& B, std::span<const int> rows,
           std::vector<int>& index);
  /// Keep only the columns listed (in that order): keep[i] is the old index of new column i.
  void keep(std::span<const int> keep);
  /// Inner products z_i^T z_j.
  const Eigen::MatrixXd& gram() const { return _G; }
  /// out[j] = z_{idx[j]}^T t (t in the factor's ordering).
  void dot(std::span<const int> idx, std::span<const double> t, std::span<double> out) const;
  /// t -= sum_j w[j] z_{idx[j]}.
  void subtract(std::span<const int> idx, std::span<const double> w, std::span<double> t) const;
  std::size_t bytes() const;

 private:
  struct Column {
    std::int64_t multiplier = -1;
    std::vector<LocalIndex> c_col; ///< the row's equations and coefficients (its identity)
    std::vector<double> c_val;
    std::vector<LocalIndex> z_row; ///< z = L^-1 P c^T, rows ascending in the factor's ordering
    std::vector<double> z_val;
  };
  LocalIndex _n = 0;
  std::vector<Column> _cols;
  std::unordered_multimap<std::int64_t, int> _of; ///< multiplier -> columns
  Eigen::MatrixXd _G;
  std::vector<int> _pos; ///< scratch for fill_gram
};

} // namespace gapfem
