#include "fem/rigid_body_modes.hpp"

#include <algorithm>
#include <cmath>

namespace gapfem {

namespace {

/// The padded nodal numbering when every equation is a translation (UX, UY[, UZ]) of its node.
void nodal_blocks(const DofMap& dofs, const EquationMap& eqs, int block, NearNullSpace& out) {
  const LocalIndex n = eqs.n_eq();
  for (LocalIndex e = 0; e < n; ++e)
    if (static_cast<int>(dofs.slot_dof(eqs.eq_slot[e])) >= block) return;
  out.padded.resize(static_cast<std::size_t>(n));
  LocalIndex blocks = 0;
  NodeId last = -1;
  for (LocalIndex e = 0; e < n; ++e) { // equations follow the slots: node by node
    const NodeId node = dofs.slot_node(eqs.eq_slot[e]);
    if (node != last) ++blocks;
    last = node;
    out.padded[e] = block * (blocks - 1) + static_cast<int>(dofs.slot_dof(eqs.eq_slot[e]));
  }
  out.block_size = block;
}

} // namespace

NearNullSpace rigid_body_modes(const DofMap& dofs, const EquationMap& eqs,
                               std::span<const Vec3> coords, bool two_d) {
  const LocalIndex n = eqs.n_eq();
  bool temperatures = false;
  for (LocalIndex e = 0; e < n; ++e) temperatures |= dofs.slot_is_temperature(eqs.eq_slot[e]);
  const int mech = two_d ? 3 : 6;
  NearNullSpace out;
  out.count = mech + (temperatures ? 1 : 0);
  out.vectors.assign(static_cast<std::size_t>(out.count) * n, 0.0);
  auto at = [&](int mode, LocalIndex e) -> double& {
    return out.vectors[static_cast<std::size_t>(mode) * n + e];
  };
  for (LocalIndex e = 0; e < n; ++e) {
    const LocalIndex slot = eqs.eq_slot[e];
    const DofType d = dofs.slot_dof(slot);
    if (is_temperature(d)) {
      at(mech, e) = 1.0;
      continue;
    }
    const Vec3& x = coords[dofs.slot_node(slot)];
    const int c = static_cast<int>(d);
    if (two_d) {
      // modes: u_x, u_y, rotation about z (x, y) -> (-y, x); a rotational DOF UR3 is 1 in it
      if (c < 2) at(c, e) = 1.0;
      if (c == 0) at(2, e) = -x[1];
      if (c == 1) at(2, e) = x[0];
      if (d == DofType::UR3) at(2, e) = 1.0;
      continue;
    }
    if (c < 3) {
      at(c, e) = 1.0;
      // rotation k: u = e_k x X, component c
      const int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
      at(3 + c1, e) = x[c2];  // (e_c1 x X)_c = X_c2 (cyclic)
      at(3 + c2, e) = -x[c1]; // (e_c2 x X)_c = -X_c1
    } else if (c < 6) {
      at(3 + (c - 3), e) = 1.0;
    }
  }
  nodal_blocks(dofs, eqs, two_d ? 2 : 3, out);
  for (int m = 0; m < out.count; ++m) {
    double big = 0.0;
    for (LocalIndex e = 0; e < n; ++e) big = std::max(big, std::abs(at(m, e)));
    if (big > 0)
      for (LocalIndex e = 0; e < n; ++e) at(m, e) /= big;
  }
  return out;
}

} // namespace gapfem
