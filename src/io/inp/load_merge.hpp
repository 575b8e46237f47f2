#pragma once
/// @file load_merge.hpp
/// What the load and condition handlers share (handlers_loads.cpp, handlers_temperature.cpp):
/// OP=NEW/MOD and the merge of a keyword's entries into the step's active list (the rules are in
/// handlers_loads.cpp's file comment).
#include "io/inp/handlers.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <map>
#include <string>
#include <vector>

namespace gapfem::inp {

inline bool op_new(const Keyword& kw) {
  return enum_param(kw, "OP", {"MOD", "NEW"}, 0) == 1;
}

/// Merges `incoming` into `active` (see the file comment). `family` selects the entries of the
/// keyword's family, `key` gives the identity of an entry.
template <typename T, typename Family, typename Key>
void merge(std::vector<T>& active, std::vector<T>& incoming, bool is_new, Family family, Key key) {
  if (is_new) std::erase_if(active, [&](const T& e) { return family(e) && e.propagated; });
  using K = decltype(key(incoming.front()));
  std::map<K, std::size_t> where;
  for (std::size_t i = 0; i < active.size(); ++i)
    if (family(active[i])) where[key(active[i])] = i;
  for (T& e : incoming) {
    e.propagated = false;
    const auto it = where.find(key(e));
    if (it != where.end()) {
      active[it->second] = std::move(e);
    } else {
      where[key(e)] = active.size();
      active.push_back(std::move(e));
    }
  }
}

/// "element 12 (C3D8)"
inline std::string elem_entity(const BuildState& s, ElemId e) {
  return fmt::format("element {} ({})", s.model.element_label(e),
                     element_info(s.model.mesh.elem_types[e]).name);
}

} // namespace gapfem::inp
