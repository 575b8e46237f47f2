#pragma once
/// @file constraint_set.hpp
/// All linear multi-point constraints of a model in one object (style.md: "all linear constraints
/// live in one object"). Each row  sum_k c_k u[slot_k] = value  is enforced exactly with its own
/// Lagrange multiplier: the assembler adds the constraint forces C^T lambda to the internal forces
/// and appends the rows to the Newton system's ConstraintBlock, where KktSolver treats them like
/// closed hard-contact gaps. The rows never change within a step, so a factor that holds them is
/// reused like any other (docs/architecture.md, "Linear constraints").
#include "common/types.hpp"
#include "linalg/constraint_block.hpp"

#include <array>
#include <map>
#include <span>
#include <vector>

namespace gapfem {

struct Model;
class DofMap;
struct EquationMap;

class ConstraintSet {
 public:
  ConstraintSet() = default;
  /// Rows of model.constraints over the slots of `dofs`. A term on a DOF the node does not carry
  /// is an InputError naming the constraint.
  ConstraintSet(const Model& model, const DofMap& dofs);

  int n_rows() const { return static_cast<int>(_value.size()); }
  bool empty() const { return _value.empty(); }
  /// Model constraint a row came from (index into Model::constraints; -1: a boundary condition in a
  /// local system).
  int source(int r) const { return _source[r]; }
  std::span<const LocalIndex> row_slots(int r) const {
    return {_slot.data() + _ptr[r], static_cast<std::size_t>(_ptr[r + 1] - _ptr[r])};
  }
  std::span<const double> row_coeffs(int r) const {
    return {_coeff.data() + _ptr[r], static_cast<std::size_t>(_ptr[r + 1] - _ptr[r])};
  }

  /// Per step: equation numbers of the terms and the rows that apply (a row that yields to a
  /// boundary condition on its dependent DOF does not; the rows of boundary conditions in local
  /// systems apply where `local_bcs` (node, DOF 1-6) lists them). Throws InputError for a
  /// prescribed dependent DOF of a row that does not yield.
  void set_equations(const Model& model, const EquationMap& eqmap,
                     std::span<const std::pair<NodeId, int>> local_bcs = {});
  /// The row of a boundary condition on DOF `dof` (1-6) of a node with a *TRANSFORM, or -1.
  int bc_row(NodeId node, int dof) const;
  /// Right-hand side of row r (a boundary condition's value in its local system).
  void set_value(int r, double v) { _value[r] = v; }
  /// The rates of row r's right-hand side (a boundary condition in a local system given as a
  /// velocity or acceleration): in dynamic steps the row holds C v = rate_v, C a = rate_a.
  void clear_rates() { _rate.clear(); }
  void set_rates(int r, double rate_v, double rate_a) {
    if (_rate.size() != 2 * _value.size()) _rate.assign(2 * _value.size(), 0.0);
    _rate[2 * static_cast<std::size_t>(r)] = rate_v;
    _rate[2 * static_cast<std::size_t>(r) + 1] = rate_a;
  }
  bool active(int r) const { return _active[r] != 0; }
  /// Equations of row r in the current step (-1: prescribed), for the sparsity pattern.
  std::span<const LocalIndex> row_eqs(int r) const {
    return {_eq.data() + _ptr[r], static_cast<std::size_t>(_ptr[r + 1] - _ptr[r])};
  }

  /// f_int += C^T lambda (trial multipliers) per slot, and the active rows appended to C (if
  /// given) with g = C u - value and multiplier index first_multiplier + r. flux_sum/flux_count
  /// receive the constraint forces per field.
  void assemble(std::span<const double> u, std::span<double> f_int, ConstraintBlock* C,
                std::int64_t first_multiplier, const DofMap& dofs,
                std::array<double, kNumFields>& flux_sum, std::array<long, kNumFields>& flux_count,
                const ConstraintBlock::GivenFields& given = {}) const;

  std::vector<double> mult_committed, mult_trial; ///< per row

 private:
  std::vector<LocalIndex> _ptr{0};
  std::vector<LocalIndex> _slot, _eq;
  std::vector<double> _coeff;
  std::vector<double> _value;
  std::vector<double> _rate; ///< 2 per row (set_rates), empty when none is set
  std::vector<int> _source;
  std::vector<std::uint8_t> _active;
  std::map<std::pair<NodeId, int>, int> _bc_row;
};

} // namespace gapfem
