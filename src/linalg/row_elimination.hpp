#pragma once
/// @file row_elimination.hpp
/// Exact elimination of the constraint rows an iterative solver need not iterate on.
///
/// The Newton system of the seam (constrained_solver.hpp)
///
///     [ K  D ] [du]   [ b ]
///     [ C -E ] [dl] = [-g ]
///
/// has two kinds of rows that can be removed exactly, leaving a smaller bordered system (often
/// none at all: K alone, which CG with an algebraic multigrid solves well):
///
/// * **Pinned rows**: an exact row (E = 0) with a single coefficient c on equation j, whose
///   column has its single entry d there too, and no other row touching j: a gap to a fixed node
///   along an axis, a stick row of such a gap. It fixes du_j = -g / c. Equation j's row and column
///   of K are replaced by its diagonal (the right-hand side of the other equations takes
///   K_ij du_j), and the row's multiplier follows afterwards from equation j itself:
///   dl = (b_j - sum_k K_jk du_k) / d.
/// * **Compliant rows** (E > 0, a penalty gap): the multiplier dl = (C du + g) / E is substituted,
///   K + D E^-1 C with right-hand side b - D E^-1 g: the penalty stiffness, exactly.
///
/// Neither changes the solution; K's pattern is kept (eliminated equations keep their entries as
/// zeros), so a preconditioner built for one system can serve the next. K is modified in place
/// and restore() gives it back bit for bit.
#include "linalg/constraint_block.hpp"
#include "linalg/csr_matrix.hpp"

#include <span>
#include <utility>
#include <vector>

namespace gapfem {

class RowElimination {
 public:
  /// Eliminates what it can from (K, b, C): K is modified in place, reduced_b() and
  /// reduced_rows() give the remaining system. With `pin` false only compliant rows are folded.
  void reduce(CsrMatrix& K, std::span<const double> b, const ConstraintBlock& C, bool pin = true);
  /// The right-hand side and the rows of the remaining system.
  std::span<const double> reduced_b() const { return _b; }
  const ConstraintBlock& reduced_rows() const { return _rows; }
  /// Equations fixed by pinned rows (their reduced equation is K_jj du_j = K_jj du_j*).
  std::size_t pinned_count() const { return _pin_eq.size(); }
  std::span<const LocalIndex> pinned_equations() const { return _pin_eq; }
  /// The rows of C (given to reduce()) that are not pinned: those left in the bordered system and
  /// the compliant rows folded into K, each a spring in the reduced K.
  ConstraintBlock unpinned_rows(const ConstraintBlock& C) const;
  /// Rows removed from the bordered system.
  int eliminated_rows() const { return _n_rows - _rows.n_rows(); }
  /// Complete the solution: du at the pinned equations set exactly, dl of every original row from
  /// dl_reduced (the remaining rows' multipliers) and the eliminated equations. K must still be the
  /// reduced matrix; b and C the originals given to reduce().
  void recover(std::span<const double> b, const ConstraintBlock& C, std::span<double> du,
               std::span<const double> dl_reduced, std::span<double> dl) const;
  /// Give K its original values back.
  void restore(CsrMatrix& K) const;

 private:
  int _n_rows = 0;
  std::vector<double> _b;
  ConstraintBlock _rows;
  std::vector<int> _kept; ///< original index of each remaining row
  // pinned rows: row, equation, value du_j, column entry d
  std::vector<int> _pin_row;
  std::vector<LocalIndex> _pin_eq;
  std::vector<double> _pin_du, _pin_d;
  std::vector<LocalIndex> _pin_row_start; ///< into _pin_cols/_pin_vals: equation j's row of K
  std::vector<LocalIndex> _pin_cols;
  std::vector<double> _pin_vals;
  std::vector<int> _folded;                          ///< compliant rows substituted into K
  std::vector<std::pair<LocalIndex, double>> _saved; ///< (position, original value) in K
};

} // namespace gapfem
