#pragma once
/// @file discretization.hpp
/// The runtime view of a Model: element blocks (one kernel per element type and property), the
/// DOF map, per-element gather lists, and the model-owned flat history and multiplier storage with
/// a committed and a trial copy (style.md §3-4). Built once per analysis.
#include "elements/element_kernel.hpp"
#include "fem/constraint_set.hpp"
#include "fem/dof_map.hpp"
#include "fem/matrix_terms.hpp"

#include <memory>
#include <vector>

namespace gapfem {

struct Model;

struct ElementBlock {
  ElementType type{};
  std::int32_t variant = -1; ///< USER / SUBSTRUCTURE: the deck's type (Mesh::elem_variant)
  PropertyRef property;
  std::unique_ptr<ElementKernel> kernel;
  std::vector<ElemId> elements;
  int n_nodes = 0, n_dofs = 0, n_state = 0, n_mult = 0;
  bool uses_temperature = false;
  std::vector<LocalIndex> slots;                    ///< elements.size() x n_dofs
  std::vector<LocalIndex> eqs;                      ///< per step: slot → equation
  std::vector<double> state_committed, state_trial; ///< elements.size() x n_state
  std::vector<double> mult_committed, mult_trial;   ///< elements.size() x n_mult
  std::int64_t mult_offset = 0;                     ///< first global multiplier index of the block
  std::vector<double> interference;   ///< per element, current allowance v(t) (gap blocks)
  std::vector<double> stiffness_hint; ///< per element (gap blocks), see ElementInput

  std::size_t size() const { return elements.size(); }
  std::span<const LocalIndex> element_slots(std::size_t i) const {
    return {slots.data() + i * n_dofs, static_cast<std::size_t>(n_dofs)};
  }
  std::span<const LocalIndex> element_eqs(std::size_t i) const {
    return {eqs.data() + i * n_dofs, static_cast<std::size_t>(n_dofs)};
  }
};

class Discretization {
 public:
  /// Builds kernels, the DOF map and the storage; validates every element (InputError).
  explicit Discretization(const Model& model, const KernelOptions& options = {});

  const Model& model() const { return _model; }
  const DofMap& dofs() const { return _dofs; }
  std::vector<ElementBlock>& blocks() { return _blocks; }
  const std::vector<ElementBlock>& blocks() const { return _blocks; }
  /// (block, index in block) of an element.
  std::pair<int, LocalIndex> locate(ElemId e) const { return {_elem_block[e], _elem_index[e]}; }
  /// All multipliers: the elements' (block by block), then one per constraint row.
  std::int64_t n_multipliers() const { return _n_mult + _constraints.n_rows(); }
  /// Index of the first constraint-row multiplier.
  std::int64_t constraint_multiplier_offset() const { return _n_mult; }
  ConstraintSet& constraints() { return _constraints; }
  const ConstraintSet& constraints() const { return _constraints; }
  /// *MATRIX ASSEMBLE stiffness terms (empty when the model has none).
  const MatrixTerms& matrix_terms() const { return _matrix_terms; }
  bool has_gaps() const { return _has_gaps; }
  bool has_temperature_field() const { return _uses_temperature_field; }

  /// Set per-step equation numbers in every block and in the constraint rows.
  /// `local_bcs`: the (node, DOF) boundary conditions of the step in local systems (*TRANSFORM).
  void set_equations(const EquationMap& eqmap,
                     std::span<const std::pair<NodeId, int>> local_bcs = {});
  /// Trial := committed (start of an increment attempt).
  void reset_trial();
  /// Committed := trial (increment accepted).
  void commit();
  /// Copy of every trial history and multiplier, so that an evaluation can be repeated with the
  /// history it saw (StepProblem::assemble_tangent).
  void save_trial(std::vector<double>& out) const;
  void restore_trial(std::span<const double> saved);
  /// Multiplier value by global index (trial).
  double& multiplier_trial(std::int64_t index);
  /// Multiplier value by global index (committed: an impact's new contact forces).
  double& multiplier_committed(std::int64_t index);
  /// Whether the multiplier is a gap's normal force (a unilateral row: compressive >= 0), not a
  /// friction row's or a linear constraint's (either sign).
  bool is_contact_normal(std::int64_t index) const;
  /// The normal multiplier of the gap whose multiplier `index` is (its normal force or one of its
  /// friction rows); -1 when it is no gap's.
  std::int64_t contact_normal_of(std::int64_t index) const;

 private:
  double& multiplier(std::int64_t index, bool trial);
  const Model& _model;
  DofMap _dofs;
  ConstraintSet _constraints;
  MatrixTerms _matrix_terms;
  std::vector<ElementBlock> _blocks;
  std::vector<int> _elem_block;
  std::vector<LocalIndex> _elem_index;
  std::vector<std::pair<int, std::int64_t>> _mult_blocks; ///< (block, offset) sorted by offset
  std::int64_t _n_mult = 0;
  bool _has_gaps = false;
  bool _uses_temperature_field = false;
};

} // namespace gapfem
