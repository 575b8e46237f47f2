#include "elements/user/user_kernel_common.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <mutex>
#include <string>

namespace gapfem {
namespace {

/// "NFORC1" … "NFORC6", "NFORC11" … "NFORC25", indexed by DofType (static storage for the views).
const std::array<std::string, kNumDofTypes>& nforc_table() {
  static const std::array<std::string, kNumDofTypes> names = [] {
    std::array<std::string, kNumDofTypes> n;
    for (int d = 0; d < kNumDofTypes; ++d)
      n[static_cast<std::size_t>(d)] =
          "NFORC" + std::to_string(abaqus_number(static_cast<DofType>(d)));
    return n;
  }();
  return names;
}

/// The NFORC names of a DOF set, interned for the life of the program: output blocks keep views
/// of their names beyond the kernels that made them.
std::span<const std::string_view> interned_names(const std::vector<DofType>& dofs) {
  static std::mutex mutex;
  static std::map<std::vector<DofType>, std::vector<std::string_view>> lists;
  const std::lock_guard lock(mutex);
  auto [it, added] = lists.try_emplace(dofs);
  if (added)
    for (DofType d : dofs) it->second.emplace_back(nforc_table()[static_cast<std::size_t>(d)]);
  return it->second;
}

} // namespace

NodeDofTable::NodeDofTable(const std::vector<std::vector<int>>& abaqus) {
  for (const auto& node : abaqus) {
    for (int number : node) {
      DofType d{};
      FE_CHECK(dof_from_abaqus(number, d), "user element DOF not checked by the reader");
      _dofs.push_back(d);
      if (std::find(_nforc_dofs.begin(), _nforc_dofs.end(), d) == _nforc_dofs.end())
        _nforc_dofs.push_back(d);
    }
    _offset.push_back(static_cast<int>(_dofs.size()));
  }
  std::sort(_nforc_dofs.begin(), _nforc_dofs.end());
  _nforc = interned_names(_nforc_dofs);
}

int NodeDofTable::nforc_column(DofType d) const {
  return static_cast<int>(std::lower_bound(_nforc_dofs.begin(), _nforc_dofs.end(), d) -
                          _nforc_dofs.begin());
}

void add_nodal_forces(const NodeDofTable& dofs, std::span<const double> f, ElementRecovery& out) {
  OutputBlock b;
  b.var = ElemVar::NFORC;
  b.names = dofs.nforc_names();
  b.n_points = dofs.n_nodes();
  const std::size_t nc = b.names.size();
  b.values.assign(static_cast<std::size_t>(b.n_points) * nc, 0.0);
  std::size_t k = 0;
  for (int a = 0; a < dofs.n_nodes(); ++a)
    for (DofType d : dofs.node(a))
      b.values[static_cast<std::size_t>(a) * nc + static_cast<std::size_t>(dofs.nforc_column(d))] =
          f[k++] + 0.0; // (no -0 in the tables)
  out.blocks.push_back(std::move(b));
}

} // namespace gapfem
