#include "fem/dof_map.hpp"

#include <algorithm>
#include <bit>

namespace gapfem {

DofMap::DofMap(std::vector<DofMask> masks) : _mask(std::move(masks)) {
  _first.resize(_mask.size());
  LocalIndex next = 0;
  for (std::size_t n = 0; n < _mask.size(); ++n) {
    _first[n] = next;
    for (int d = 0; d < kNumDofTypes; ++d)
      if (_mask[n] & dof_bit(static_cast<DofType>(d))) {
        _slot_node.push_back(static_cast<NodeId>(n));
        _slot_dof.push_back(static_cast<DofType>(d));
        ++next;
      }
    _max_temperature_points =
        std::max(_max_temperature_points, std::popcount(_mask[n] & kTemperatureBits));
  }
}

EquationMap EquationMap::build(std::span<const std::uint8_t> prescribed) {
  EquationMap m;
  m.slot_eq.assign(prescribed.size(), -1);
  for (std::size_t s = 0; s < prescribed.size(); ++s)
    if (!prescribed[s]) {
      m.slot_eq[s] = static_cast<LocalIndex>(m.eq_slot.size());
      m.eq_slot.push_back(static_cast<LocalIndex>(s));
    }
  m.n_owned = m.n_eq();
  return m;
}

} // namespace gapfem
