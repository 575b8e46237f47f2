#pragma once
/// @file mesh.hpp
/// Nodes and elements as read from the deck: labels, reference coordinates and connectivity, in
/// structure-of-arrays form, with label → internal index maps. Immutable after model building.
#include "common/error.hpp"
#include "common/types.hpp"
#include "model/element_types.hpp"

#include <fmt/format.h>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

namespace gapfem {

/// Node and element keys: the deck label, with the index of its part instance (1-based; 0 for a
/// flat deck and for assembly-level nodes and elements) in the bits above kInstanceShift, so that
/// `Part-1-1.12` and `Part-2-1.12` are different keys and a flat deck's keys are its labels.
inline constexpr int kInstanceShift = 40;
inline constexpr Label kLocalLabelMask = (Label{1} << kInstanceShift) - 1;
constexpr Label make_key(int instance, Label local) {
  return (static_cast<Label>(instance) << kInstanceShift) | local;
}
constexpr int key_instance(Label key) {
  return static_cast<int>(key >> kInstanceShift);
}
constexpr Label key_local(Label key) {
  return key & kLocalLabelMask;
}

/// A node or element label as the deck names it: the number of a flat deck (or of an
/// assembly-level node), or `INSTANCE.number` for one of a part instance. Formats with fmt like a
/// string (widths apply), so messages and tables name entities the way Abaqus does.
struct EntityLabel {
  Label key = 0;
  const std::vector<std::string>* instances = nullptr; ///< Model::instances
  Label local() const { return key_local(key); }
  int instance() const { return key_instance(key); }
  std::string str() const;
};

/// Compact deck location of an entity: index into Model::source_files plus line and keyword id.
struct SourceRef {
  std::int32_t file = -1;
  std::int32_t line = 0;
};

struct Mesh {
  // nodes (labels are keys: see make_key)
  std::vector<Label> node_labels;
  std::vector<Vec3> coords; ///< reference coordinates X (2-D models: z = 0)
  std::unordered_map<Label, NodeId> node_index;

  // elements
  std::vector<Label> elem_labels;
  std::vector<ElementType> elem_types;
  std::vector<std::int64_t> conn_offset{
      0}; ///< element e has nodes conn[conn_offset[e] .. conn_offset[e+1])
  std::vector<NodeId> conn;
  std::vector<SourceRef> elem_src; ///< where each element was defined (*ELEMENT data line)
  /// Per element, which deck-defined type a USER or SUBSTRUCTURE element is (index into
  /// Model::user_elements / Model::substructures; -1 for the library types). Empty while the
  /// model has no such element.
  std::vector<std::int32_t> elem_variant;
  std::unordered_map<Label, ElemId> elem_index;

  std::int32_t n_nodes() const { return static_cast<std::int32_t>(node_labels.size()); }
  /// The deck-defined type of element e (see elem_variant), -1 for a library type.
  std::int32_t variant(ElemId e) const {
    return elem_variant.empty() ? -1 : elem_variant[static_cast<std::size_t>(e)];
  }
  std::int32_t n_elements() const { return static_cast<std::int32_t>(elem_labels.size()); }

  /// Internal index of a node key, or -1.
  NodeId find_node(Label label) const {
    auto it = node_index.find(label);
    return it == node_index.end() ? -1 : it->second;
  }
  /// Internal index of an element key, or -1.
  ElemId find_element(Label label) const {
    auto it = elem_index.find(label);
    return it == elem_index.end() ? -1 : it->second;
  }
  std::span<const NodeId> element_nodes(ElemId e) const {
    return {conn.data() + conn_offset[e],
            static_cast<std::size_t>(conn_offset[e + 1] - conn_offset[e])};
  }
};

} // namespace gapfem

template <>
struct fmt::formatter<gapfem::EntityLabel> : fmt::formatter<std::string_view> {
  template <typename Ctx>
  auto format(const gapfem::EntityLabel& l, Ctx& ctx) const {
    const std::string s = l.str();
    return fmt::formatter<std::string_view>::format(std::string_view(s), ctx);
  }
};
