// Sentences for names a deck uses but does not define as the use needs them (model_builder.hpp):
// a node set that is an element set or a surface, a set of a part named without its instance, a
// node number of a part used in the assembly, a node named before the *NODE line that defines it.
#include "io/inp/model_builder.hpp"

#include <fmt/format.h>
#include <limits>

namespace gapfem::inp {
namespace {

const char* kind_name(NameKind k) {
  switch (k) {
  case NameKind::NodeSet:
    return "node set";
  case NameKind::ElementSet:
    return "element set";
  case NameKind::Surface:
    return "surface";
  }
  return "name";
}

bool defined_as(const BuildState& s, const std::string& name, NameKind k) {
  switch (k) {
  case NameKind::NodeSet:
    return s.model.nsets.count(name) > 0;
  case NameKind::ElementSet:
    return s.model.elsets.count(name) > 0;
  case NameKind::Surface:
    return s.model.surfaces.count(name) > 0;
  }
  return false;
}

/// The instances whose part defines `name` as a `kind` ("BLOCK-1.CORNERS" exists), when `name` is
/// looked up outside any instance.
std::vector<std::string> instances_defining(const BuildState& s, const std::string& name,
                                            NameKind kind) {
  std::vector<std::string> out;
  if (name.find('.') != std::string::npos) return out;
  for (const std::string& inst : s.model.instances)
    if (defined_as(s, inst + "." + name, kind)) out.push_back(inst);
  return out;
}

std::string qualified_examples(const std::vector<std::string>& instances, const std::string& name) {
  std::vector<std::string> q;
  for (std::size_t i = 0; i < instances.size() && i < 3; ++i)
    q.push_back(instances[i] + "." + name);
  std::string out;
  for (std::size_t i = 0; i < q.size(); ++i)
    out += (i == 0 ? "" : i + 1 == q.size() ? " or " : ", ") + q[i];
  return out;
}

} // namespace

std::string undefined_name(const BuildState& s, const std::string& name, NameKind kind,
                           std::string_view keyword, std::string_view need,
                           std::string_view remedy) {
  const char* wanted = kind_name(kind);
  // a set of a part, named outside the part without an instance
  if (const auto insts = instances_defining(s, name, kind); !insts.empty())
    return fmt::format(
        "{} {} is defined in part {}; outside the part, name it through an "
        "instance, e.g. {}",
        wanted, name,
        s.instance_parts[static_cast<std::size_t>(s.instance_index.at(insts.front()) - 1)],
        qualified_examples(insts, name));
  // another kind of name: here, or in a part
  for (NameKind other : {NameKind::ElementSet, NameKind::NodeSet, NameKind::Surface}) {
    if (other == kind) continue;
    std::string is =
        fmt::format("{} {}", other == NameKind::ElementSet ? "an" : "a", kind_name(other));
    if (!defined_as(s, name, other)) {
      const auto insts = instances_defining(s, name, other);
      if (insts.empty()) continue;
      is += fmt::format(
          " of part {}",
          s.instance_parts[static_cast<std::size_t>(s.instance_index.at(insts.front()) - 1)]);
    }
    const std::string fix =
        kind == NameKind::Surface ? "define one with *SURFACE and name it"
        : kind == NameKind::NodeSet
            ? fmt::format("list the nodes of {} {} in an *NSET and name that set", kind_name(other),
                          name)
            : "list the elements in an *ELSET and name that set";
    return fmt::format("{} is {}, not {} {}; {} needs {} here: {}", name, is,
                       kind == NameKind::ElementSet ? "an" : "a", wanted, keyword, need, fix);
  }
  return fmt::format("this {} is not defined; {}", wanted, remedy);
}

std::string undefined_node(const BuildState& s, Label key, bool named, bool before_use) {
  const int inst = key_instance(key);
  const Label local = key_local(key);
  if (inst > 0 && inst <= static_cast<int>(s.instance_parts.size())) {
    const auto i = static_cast<std::size_t>(inst - 1);
    return fmt::format("instance {} (part {}) has no node {}; check the number",
                       s.model.instances[i], s.instance_parts[i], local);
  }
  if (inst == 0) {
    std::vector<std::string> insts;
    for (std::size_t i = 0; i < s.model.instances.size(); ++i)
      if (s.model.mesh.find_node(make_key(static_cast<int>(i) + 1, local)) >= 0)
        insts.push_back(s.model.instances[i]);
    if (!insts.empty())
      return fmt::format("node {} is not an assembly node; a node of a part instance is named "
                         "INSTANCE.node, e.g. {}",
                         local, qualified_examples(insts, std::to_string(local)));
  }
  const char* when = before_use ? " before use" : "";
  return named ? fmt::format("this node is not defined; define it with *NODE{}", when)
               : fmt::format("node {} is not defined; define it with *NODE{}",
                             s.model.label_of_key(key), when);
}

const SourceRef* later_node_line(const BuildState& s, Label key) {
  if (s.model_done || !s.node_lines || key_instance(key) != s.node_lines_instance) return nullptr;
  const auto it = s.node_lines->find(key_local(key));
  return it == s.node_lines->end() ? nullptr : &it->second;
}

NodeId forward_node(BuildState& s, Label key) {
  const SourceRef* line = later_node_line(s, key);
  if (!line) return -1;
  Mesh& mesh = s.model.mesh;
  const NodeId id = mesh.n_nodes();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  mesh.node_labels.push_back(key);
  mesh.coords.push_back({nan, nan, nan});
  mesh.node_index.emplace(key, id);
  s.node_src.push_back(*line);
  s.awaiting.insert(id);
  return id;
}

std::string node_defined_later(const BuildState& s, Label key, SourceRef line,
                               std::string_view keyword) {
  return fmt::format("node {} is defined further down, at {}:{}; {} needs its nodes defined "
                     "above it (only *ELEMENT and *NSET may name a node defined further down): "
                     "move that *NODE line up",
                     s.model.label_of_key(key), s.model.source_files[line.file], line.line,
                     keyword);
}

} // namespace gapfem::inp
