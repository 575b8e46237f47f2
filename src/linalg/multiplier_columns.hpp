#pragma once
/// @file multiplier_columns.hpp
/// The multiplier system of a kept Cholesky factor as a dense matrix. With M = L L^T (in the
/// factor's ordering P), constraint rows c_i and force columns d_i (d_i = c_i^T unless a row
/// carries its own column), the multiplier (Schur) matrix C M^-1 D is Z_C^T Z_D with the columns
/// z = L^-1 P c^T. They are sparse (the elimination-tree paths from a row's DOFs to the root),
/// made by sparse forward solves when first needed, and kept with their inner products while the
/// factor lives: a Newton step is then one forward solve, a dense solve of the multipliers and one
/// backward solve (docs/theory/gap_elements.md, "Solving the constrained system").
///
/// A kept column ("unit") is either a whole row's (found again by its multiplier and
/// coefficients) or an equation's, z_j = L^-1 P e_j. A row whose coefficients change from one
/// iteration to the next over the same few equations (a slipping gap's row across its slip
/// direction, a rotating gap's row, a friction column that follows the normal force) is a
/// combination of its equations' columns, which never change while the factor lives; a row that
/// stays the same is one column of its own, whatever its length.
#include "linalg/constraint_block.hpp"
#include "linalg/linear_solver.hpp"

#include <Eigen/Dense>
#include <span>
#include <unordered_map>
#include <vector>

namespace gapfem {

class MultiplierColumns {
 public:
  /// Rows as combinations of kept columns (CSR: row r is sum_k coef[k] z_{unit[k]}).
  struct Combination {
    std::vector<int> ptr{0};
    std::vector<int> unit;
    std::vector<double> coef;
    int rows() const { return static_cast<int>(ptr.size()) - 1; }
  };
  /// Rows with more coefficients than this are never split into equation columns.
  static constexpr int kMaxEquations = 12;

  /// Forget every column (a new factor of size n).
  void reset(LocalIndex n);
  int size() const { return static_cast<int>(_units.size()); }
  /// Append rows `rows` of B (their coefficients, or their columns D when `columns`) to `out` as
  /// combinations of kept columns, making the missing ones with the solver's sparse forward
  /// solves (`made` counts them). False (nothing appended) when the solver declines or the
  /// columns would not leave room in memory for the rest of the run.
  bool express(LinearSolver& solver, const ConstraintBlock& B, std::span<const int> rows,
               bool columns, Combination& out, int& made);
  /// S = A Z^T Z B^T (A.rows() x B.rows()).
  Eigen::MatrixXd product(const Combination& A, const Combination& B) const;
  /// out = A Z^T t (t in the factor's ordering).
  void dot(const Combination& A, std::span<const double> t, std::span<double> out) const;
  /// t -= Z B^T w.
  void subtract(const Combination& B, std::span<const double> w, std::span<double> t) const;
  /// Keep only the columns A and B use (renumbering them in A and B) once the others are many
  /// (a gap that opens often closes again in a later increment).
  void prune(Combination& A, Combination& B);
  std::size_t bytes() const;

 private:
  struct Unit {
    std::int64_t multiplier = -1;  ///< a row's multiplier (-1: an equation's column)
    LocalIndex equation = -1;      ///< the equation of an equation's column
    std::vector<LocalIndex> c_col; ///< a row's equations and coefficients (its identity)
    std::vector<double> c_val;
    std::vector<LocalIndex> z_row; ///< z = L^-1 P c^T, rows ascending in the factor's ordering
    std::vector<double> z_val;
  };
  /// The row unit of these coefficients for this multiplier, or -1.
  int find_row(std::int64_t multiplier, std::span<const LocalIndex> col,
               std::span<const double> val) const;
  /// The units A and B use, in order of first use; local[u] is u's place among them (-1: unused).
  std::vector<int> used_units(const Combination& A, const Combination& B,
                              std::vector<int>& local) const;
  /// Add units (their c_col/c_val set) with one batch of sparse forward solves.
  bool make(LinearSolver& solver, std::vector<Unit>& fresh);
  void index_unit(int u);

  LocalIndex _n = 0;
  std::vector<Unit> _units;
  std::unordered_multimap<std::int64_t, int> _of_row; ///< multiplier -> row units
  std::unordered_map<LocalIndex, int> _of_equation;   ///< equation -> its unit
  Eigen::MatrixXd _G;                                 ///< z_i^T z_j
  std::vector<int> _pos;                              ///< scratch for fill_gram
};

} // namespace gapfem
