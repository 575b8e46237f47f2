#pragma once
/// @file matrix_terms.hpp
/// Stiffness terms added to the model as a whole, not by elements: the matrices of *MATRIX
/// ASSEMBLE (a reduced model from another code). Constant: internal forces K u and tangent K.
#include "fem/dof_map.hpp"
#include "linalg/matrix_inserter.hpp"

#include <array>
#include <span>
#include <vector>

namespace gapfem {

struct Model;

class MatrixTerms {
 public:
  MatrixTerms() = default;
  /// The terms of Model::matrix_terms over the DOF map's slots (their DOFs must be carried).
  MatrixTerms(const Model& model, const DofMap& dofs);
  bool empty() const { return _value.empty(); }
  /// Equation numbers of a step (terms on prescribed DOFs still give forces, not stiffness).
  void set_equations(const EquationMap& eqmap);
  /// f_int += K u (per slot) with its flux, K(eq, eq) += the terms on free equations
  /// (lane 0 of the inserter).
  void assemble(std::span<const double> u, std::span<double> f_int, MatrixInserter* K,
                const DofMap& dofs, std::array<double, kNumFields>& flux_sum,
                std::array<long, kNumFields>& flux_count) const;
  /// |diagonal terms| added per slot.
  void add_diagonal(std::span<double> diag) const;
  /// The (row, column) equation pairs, for the sparsity pattern (set_equations first).
  std::span<const std::array<LocalIndex, 2>> equation_pairs() const { return _eqs; }

 private:
  std::vector<LocalIndex> _row, _col; ///< slots
  std::vector<double> _value;
  std::vector<std::array<LocalIndex, 2>> _eqs;
};

} // namespace gapfem
