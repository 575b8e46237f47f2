#pragma once
/// @file user_kernel_common.hpp
/// What the kernels of the deck's own element types share (user elements, substructures): their
/// DOFs per node from Abaqus DOF numbers, and the element nodal forces NFORC.
#include "elements/element_kernel.hpp"

#include <string_view>
#include <vector>

namespace gapfem {

/// The DOFs of an element type whose nodes carry different DOF lists.
class NodeDofTable {
 public:
  NodeDofTable() = default;
  /// `abaqus`: per node, Abaqus DOF numbers (checked by the reader: 1-6, 11-25).
  explicit NodeDofTable(const std::vector<std::vector<int>>& abaqus);
  int n_nodes() const { return static_cast<int>(_offset.size()) - 1; }
  int n_dofs() const { return static_cast<int>(_dofs.size()); }
  std::span<const DofType> node(int a) const {
    return {_dofs.data() + _offset[a], static_cast<std::size_t>(_offset[a + 1] - _offset[a])};
  }
  /// NFORC component names: one per DOF number any node carries, ascending ("NFORC1", "NFORC11").
  std::span<const std::string_view> nforc_names() const { return _nforc; }
  /// Column of DOF d in the NFORC rows.
  int nforc_column(DofType d) const;

 private:
  std::vector<DofType> _dofs;
  std::vector<int> _offset{0};
  std::span<const std::string_view> _nforc; ///< interned: valid for the life of the program
  std::vector<DofType> _nforc_dofs;
};

/// Adds the NFORC block: per node, the components of the element's internal force vector `f`
/// (element order), 0 for DOFs the node does not carry.
void add_nodal_forces(const NodeDofTable& dofs, std::span<const double> f, ElementRecovery& out);

} // namespace gapfem
