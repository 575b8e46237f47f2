#pragma once
/// @file dof_map.hpp
/// (node, DOF type) → slot, and per step slot → equation. A slot is an active nodal DOF; an
/// equation is a slot that is not prescribed in the current step. Solution vectors are slot-sized;
/// matrices are equation-sized.
#include "common/types.hpp"

#include <bit>
#include <span>
#include <vector>

namespace gapfem {

class DofMap {
 public:
  DofMap() = default;
  /// masks[n]: bit dof_bit(d) set when node n carries DOF d.
  explicit DofMap(std::vector<DofMask> masks);

  LocalIndex n_slots() const { return static_cast<LocalIndex>(_slot_node.size()); }
  NodeId n_nodes() const { return static_cast<NodeId>(_mask.size()); }
  DofMask mask(NodeId n) const { return _mask[n]; }
  bool has(NodeId n, DofType d) const { return (_mask[n] & dof_bit(d)) != 0; }
  /// Slot of (node, dof), or -1 when the node does not carry that DOF.
  LocalIndex slot(NodeId n, DofType d) const {
    const DofMask bit = dof_bit(d);
    if (!(_mask[n] & bit)) return -1;
    return _first[n] + std::popcount(static_cast<unsigned>(_mask[n] & (bit - 1u)));
  }
  NodeId slot_node(LocalIndex s) const { return _slot_node[s]; }
  DofType slot_dof(LocalIndex s) const { return _slot_dof[s]; }
  Field slot_field(LocalIndex s) const { return field_of(_slot_dof[s]); }
  bool slot_is_temperature(LocalIndex s) const { return is_temperature(_slot_dof[s]); }
  /// Largest number of temperature DOFs (11, 12, …) at any node: 0 without temperatures, 1
  /// unless heat-transfer shells carry temperatures through their thickness.
  int max_temperature_points() const { return _max_temperature_points; }

 private:
  std::vector<DofMask> _mask;
  std::vector<LocalIndex> _first;
  std::vector<NodeId> _slot_node;
  std::vector<DofType> _slot_dof;
  int _max_temperature_points = 0;
};

/// The equation numbering of one step, on one process. Equations [0, n_owned) are owned by this
/// process; [n_owned, n_eq()) are ghosts, owned by another process and present because a local
/// element touches them (a distributed backend sums their rows into their owner's). Owned
/// equations are numbered globally from first_global on, ghosts by ghost_global. A serial run owns
/// every equation and has no ghosts, so its global numbers are its local ones.
struct EquationMap {
  std::vector<LocalIndex> slot_eq; ///< per slot: equation or -1 (prescribed)
  std::vector<LocalIndex> eq_slot; ///< per equation: its slot
  LocalIndex n_owned = 0;          ///< owned equations come first
  GlobalIndex first_global = 0;    ///< global number of equation 0
  std::vector<GlobalIndex> ghost_global; ///< per ghost (equation n_owned + k): its global number
  LocalIndex n_eq() const { return static_cast<LocalIndex>(eq_slot.size()); }
  bool owned(LocalIndex eq) const { return eq < n_owned; }
  GlobalIndex global(LocalIndex eq) const {
    return eq < n_owned ? first_global + eq : ghost_global[static_cast<std::size_t>(eq - n_owned)];
  }
  /// Number the free slots (prescribed[s] == true → -1) in slot order, all owned (serial).
  static EquationMap build(std::span<const std::uint8_t> prescribed);
};

} // namespace gapfem
