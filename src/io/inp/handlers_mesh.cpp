// Mesh keywords: *HEADING, *PREPRINT, *NODE, *ELEMENT, *NSET, *ELSET, *SURFACE.
#include "io/inp/handlers.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace gapfem::inp {
namespace {

std::string where(const BuildState& s, SourceRef ref) {
  return fmt::format("{}:{}", s.model.source_files[ref.file], ref.line);
}

/// Largest number of members one GENERATE line may produce (guards against typos like 1,1E9).
constexpr long long kMaxGenerate = 100'000'000;
/// The most characters of *HEADING text carried into the result files.
constexpr std::size_t kMaxHeading = 4096;

struct Range {
  long long first, last, step;
};

Range read_range(const FieldReader& r) {
  r.at_most(3, "first, last, increment");
  if (r.text(1).empty())
    r.fail("field 2 (last)", "with GENERATE each data line gives first, last and an optional "
                             "increment; add the last label, or remove GENERATE to list labels");
  const long long first = r.integer(0, "first", 1, kMaxLabel, kLabelRule);
  Range g{first, r.integer(1, "last", 1, kMaxLabel, kLabelRule),
          r.integer_or(2, 1, "increment", 1, kMaxLabel,
                       "the increment must be a whole number from 1 to 999999999, not {}")};
  if (g.last < g.first)
    r.fail(fmt::format("range {}-{}", g.first, g.last),
           "with GENERATE the last label must not be smaller than the first; write first, last, "
           "increment");
  if ((g.last - g.first) / g.step > kMaxGenerate)
    r.fail(fmt::format("range {}-{}", g.first, g.last), "this range is too large");
  return g;
}

/// Why an element may not list the same node twice, or "". A cell (continuum, shell, truss,
/// two-node beam), a three-node beam, a gap and a SPRINGA list distinct nodes; SPRING2 may couple
/// two DOFs of one node (its DOFs are checked with its *SPRING), user elements and substructures
/// are what the user makes them.
std::string repeated_node(const BuildState& s, ElementType type, const std::vector<Label>& keys,
                          const std::vector<NodeId>& nodes, std::string_view type_name) {
  const ElementTypeInfo& info = element_info(type);
  const bool gap = info.family == ElementFamily::Gap;
  if (!info.cell && !gap && type != ElementType::SPRINGA && info.family != ElementFamily::Beam)
    return {};
  for (std::size_t a = 0; a < nodes.size(); ++a)
    for (std::size_t b = a + 1; b < nodes.size(); ++b) {
      if (nodes[a] != nodes[b]) continue;
      const EntityLabel node = s.model.label_of_key(keys[a]);
      if (gap)
        return fmt::format("node {} is both nodes of this gap, so its clearance never changes "
                           "from d whatever the model does; {} connects two distinct nodes: "
                           "give the node on the other side (for a gap against a fixed surface, "
                           "a node held by *BOUNDARY)",
                           node, with_article(type_name));
      if (nodes.size() == 2)
        return fmt::format("node {} is both nodes of this {} element, so it has no length or "
                           "direction; give two distinct nodes",
                           node, type_name);
      return fmt::format("node {} is given twice (positions {} and {} of the {} nodes); each node "
                         "of {} element is a distinct node: check the connectivity",
                         node, a + 1, b + 1, nodes.size(), with_article(type_name));
    }
  return {};
}

/// A deck with parts defines nodes and elements in parts, instances or the assembly only.
void check_outside_parts(const BuildState& s, const Keyword& kw, const char* what) {
  if (s.assembly_seen && s.scope.instance == 0 && !s.in_assembly)
    throw InputError(kw.loc, "",
                     fmt::format("this deck uses *PART/*ASSEMBLY, so its {} belong inside a "
                                 "*PART, an *INSTANCE or the *ASSEMBLY (reference points); move "
                                 "this keyword there",
                                 what));
}

/// The nodes of an element line (fields 2 on; `ent` names the element): by number in this part or
/// the assembly, or qualified by an instance (PART-1-1.12: gap elements between instances are
/// written so by Abaqus/CAE); a node defined further down is created now (forward_node). nullopt
/// when a node belongs to an instance in error or its definition failed (both reported there).
std::optional<std::vector<NodeId>> element_nodes(BuildState& s, const FieldReader& r,
                                                 const std::string& ent, ElementType type,
                                                 int n_nodes, std::string_view type_name) {
  std::vector<Label> node_keys;
  bool failed = false;
  for (std::size_t f = 1; f < r.size(); ++f) {
    if (r.blank(f)) continue;
    const EntityRef ref = parse_reference(s, r, f);
    failed |= ref.failed;
    if (ref.failed) continue;
    if (!ref.key)
      r.fail(
          fmt::format("field {}", f + 1),
          fmt::format("'{}' is not a node number; list the element's nodes by number", r.text(f)));
    node_keys.push_back(*ref.key);
  }
  if (failed) return std::nullopt;
  if (const auto given = static_cast<int>(node_keys.size()); given != n_nodes)
    r.fail(ent, fmt::format("{} needs {} nodes but {}; list exactly {} node numbers after the "
                            "element number (continue on the next line after a trailing comma)",
                            type_name, n_nodes,
                            given == 0   ? std::string("none is given")
                            : given == 1 ? std::string("only 1 is given")
                                         : fmt::format("{} are given", given),
                            n_nodes));
  std::vector<NodeId> nodes;
  for (Label nk : node_keys) {
    NodeId n = s.model.mesh.find_node(nk);
    if (n < 0 && s.bad_nodes.count(nk)) failed = true;
    if (n < 0 && !failed) n = forward_node(s, nk); // defined further down (Abaqus allows it)
    if (n < 0 && !failed) r.fail(ent, undefined_node(s, nk, false, false));
    nodes.push_back(n);
  }
  if (failed) return std::nullopt;
  if (const std::string why = repeated_node(s, type, node_keys, nodes, type_name); !why.empty())
    r.fail(ent, why);
  return nodes;
}

/// An *ELEMENT's TYPE=: a library type, a substructure Zn (its library read) or a user element
/// type Un of the deck, with its node count (0: the library's). nullopt for a user element type
/// whose definition was reported (its elements are noted as failed).
struct ElementKind {
  ElementType type;
  std::int32_t variant; ///< the user element or substructure type; -1 for the library's
  int n_nodes;
};
std::optional<ElementKind> element_kind(BuildState& s, const Keyword& kw,
                                        const std::string& elset) {
  std::optional<ElementType> type;
  std::int32_t variant = -1; // a user element type of the deck
  int n_nodes = 0;
  try {
    const std::string tname = param_value(kw, "TYPE", true);
    type = element_type_from_name(tname);
    const std::string upper = to_upper(trim(tname));
    if (!type && upper.size() > 1 && upper[0] == 'Z' && parse_integer(upper.substr(1))) {
      variant = load_substructure_type(s, kw, upper);
      type = ElementType::SUBSTRUCTURE;
      n_nodes = static_cast<int>(s.model.substructures[variant].node_labels.size());
    }
    if (kw.has("FILE") && type != ElementType::SUBSTRUCTURE)
      throw InputError(kw.loc, "FILE", "FILE= names the library of a substructure (TYPE=Zn)");
    if (!type && upper.size() > 1 && upper[0] == 'U' && parse_integer(upper.substr(1))) {
      const auto& defs = s.model.user_elements;
      const auto it = std::find_if(defs.begin(), defs.end(),
                                   [&](const UserElementType& t) { return t.name == upper; });
      if (it == defs.end() && s.bad_user_types.count(upper)) { // its definition was reported
        kw.mark_read();
        for (const auto& d : kw.data)
          if (!d.fields.empty())
            if (auto l = parse_integer(d.fields[0])) s.bad_elements.insert(s.key(*l));
        if (!elset.empty()) s.bad_sets.insert(elset);
        return std::nullopt;
      }
      if (it == defs.end())
        throw InputError(kw.loc, fmt::format("TYPE={}", upper),
                         fmt::format("user element type {} is not defined; define it with *USER "
                                     "ELEMENT, TYPE={} before its elements",
                                     upper, upper));
      type = ElementType::USER;
      variant = static_cast<std::int32_t>(it - defs.begin());
      n_nodes = it->n_nodes;
    }
    if (!type) {
      std::string known;
      for (const auto& info : all_element_types())
        if (info.n_nodes > 0) known += (known.empty() ? "" : ", ") + std::string(info.name);
      throw InputError(
          kw.loc, fmt::format("TYPE={}", to_upper(tname)),
          fmt::format("gapfem does not know this element type; supported types: {}, user "
                      "elements Un (*USER ELEMENT) and substructures Zn",
                      known));
    }
  } catch (const InputError& e) {
    // remember the labels so that later references do not raise follow-up errors
    for (const auto& d : kw.data)
      if (!d.fields.empty())
        if (auto l = parse_integer(d.fields[0])) s.bad_elements.insert(s.key(*l));
    if (!elset.empty()) s.bad_sets.insert(elset);
    throw;
  }
  return ElementKind{*type, variant, n_nodes};
}

} // namespace

void handle_heading(BuildState& s, const Keyword& kw) {
  std::vector<std::string> lines;
  kw.mark_read(); // every line is heading text
  for (const auto& d : kw.data) lines.emplace_back(trim(d.text));
  while (!lines.empty() && lines.back().empty()) lines.pop_back();
  s.heading_untitled = lines.empty();
  std::size_t total = 0;
  for (const auto& l : lines) total += l.size() + 1;
  for (const auto& l : lines) {
    if (!s.model.heading.empty()) s.model.heading += '\n';
    s.model.heading += l;
    if (s.model.heading.size() >= kMaxHeading) break;
  }
  if (s.model.heading.size() > kMaxHeading) {
    s.model.heading.resize(kMaxHeading);
    s.warn(kw.loc, fmt::format("the heading is {} characters long; the result files keep its "
                               "first {}",
                               total, kMaxHeading));
  }
}

void handle_node(BuildState& s, const Keyword& kw) {
  if (enum_param(kw, "SYSTEM", {"R", "C", "S"}, 0) != 0)
    reject_param(kw, "SYSTEM",
                 "give the coordinates in the global rectangular system (SYSTEM=R, the default)");
  check_outside_parts(s, kw, "nodes");
  const std::string nset = set_param(s, kw, "NSET", false);
  Mesh& mesh = s.model.mesh;
  std::vector<NodeId> added;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    const long long label = read_label(s, r, "node number");
    const Label key = s.key(label);
    try {
      r.at_most(7, "node number, x, y, z, and the direction cosines of a normal");
      // fields 5-7: the node's normal (shells, beams); zero or blank ones define none
      for (std::size_t i = 4; i < 7; ++i)
        if (r.real_or(i, 0.0, "direction cosine of the normal") != 0.0)
          r.fail(fmt::format("field {}", i + 1),
                 "normals given on *NODE (fields 5-7) are not supported by gapfem, which takes "
                 "the normals of shells and beams from the elements (*SHELL SECTION, the beam "
                 "section's n1 direction); remove them or leave them blank");
      const Vec3 x = s.place(
          s.from_system({r.real_or(1, 0.0, "x"), r.real_or(2, 0.0, "y"), r.real_or(3, 0.0, "z")}));
      const NodeId old = mesh.find_node(key);
      if (old >= 0 && s.awaiting.erase(old)) { // named by an *ELEMENT or *NSET above
        mesh.coords[old] = x;
        s.node_src[old] = s.ref(line);
        added.push_back(old);
        return;
      }
      if (old >= 0)
        r.fail(fmt::format("node {}", s.model.label_of_key(key)),
               fmt::format(
                   "this node number is defined twice (first at {}); give each node its own number",
                   where(s, s.node_src[old])));
      const NodeId id = mesh.n_nodes();
      mesh.node_labels.push_back(key);
      mesh.coords.push_back(x);
      mesh.node_index.emplace(key, id);
      s.node_src.push_back(s.ref(line));
      added.push_back(id);
    } catch (const InputError&) {
      // (a node named above and awaiting this line failed too: its uses raise nothing more)
      if (const NodeId n = mesh.find_node(key); n < 0 || s.awaiting.count(n))
        s.bad_nodes.insert(key);
      throw;
    }
  });
  if (!nset.empty()) add_to_nset(s, nset, added);
}

void handle_element(BuildState& s, const Keyword& kw) {
  check_outside_parts(s, kw, "elements");
  const std::string elset = set_param(s, kw, "ELSET", false);
  const auto kind = element_kind(s, kw, elset);
  if (!kind) return; // a user element type whose definition was reported
  const auto [type, variant, n_type_nodes] = *kind;
  int n_nodes = n_type_nodes;
  const ElementTypeInfo& info = element_info(type);
  if (variant < 0) n_nodes = info.n_nodes;
  const std::string_view type_name = variant < 0 ? info.name
                                     : type == ElementType::SUBSTRUCTURE
                                         ? std::string_view(s.model.substructures[variant].name)
                                         : std::string_view(s.model.user_elements[variant].name);
  Mesh& mesh = s.model.mesh;
  std::vector<ElemId> added;
  for (std::size_t i = 0; i < kw.data.size(); ++i) {
    if (kw.data[i].empty()) continue;
    kw.data[i].read = true; // (a continued line is read through a joined copy)
    // a line ending with a comma continues on the next line until all nodes are given
    const SourceRef first_line = s.ref(kw.data[i]);
    // (copied only when it is continued: most element lines are complete)
    const DataLine* line = &kw.data[i];
    DataLine joined;
    if (line->trailing_comma && static_cast<int>(line->fields.size()) < n_nodes + 1) {
      joined = *line;
      while (joined.trailing_comma && static_cast<int>(joined.fields.size()) < n_nodes + 1 &&
             i + 1 < kw.data.size()) {
        ++i;
        const DataLine& next = kw.data[i];
        next.read = true;
        joined.fields.insert(joined.fields.end(), next.fields.begin(), next.fields.end());
        joined.trailing_comma = next.trailing_comma;
      }
      line = &joined;
    }
    const FieldReader r = s.reader(kw, *line);
    long long label = 0;
    Label key = 0;
    try {
      label = read_label(s, r, "element number");
      key = s.key(label);
      const std::string ent = fmt::format("element {}", s.model.label_of_key(key));
      if (const ElemId old = mesh.find_element(key); old >= 0)
        r.fail(ent, fmt::format("this element number is defined twice (first at {}); give each "
                                "element its own number",
                                where(s, mesh.elem_src[old])));
      const auto nodes = element_nodes(s, r, ent, type, n_nodes, type_name);
      if (!nodes) { // a node of an instance or a node in error (reported there)
        s.bad_elements.insert(key);
        continue;
      }
      const ElemId id = mesh.n_elements();
      mesh.elem_labels.push_back(key);
      mesh.elem_types.push_back(type);
      if (variant >= 0 || !mesh.elem_variant.empty()) {
        mesh.elem_variant.resize(static_cast<std::size_t>(id), -1);
        mesh.elem_variant.push_back(variant);
      }
      mesh.conn.insert(mesh.conn.end(), nodes->begin(), nodes->end());
      mesh.conn_offset.push_back(static_cast<std::int64_t>(mesh.conn.size()));
      mesh.elem_src.push_back(first_line);
      mesh.elem_index.emplace(key, id);
      added.push_back(id);
    } catch (const InputError& e) {
      if (label > 0 && mesh.find_element(key) < 0) s.bad_elements.insert(key);
      s.diag.error(e);
    }
  }
  if (std::all_of(kw.data.begin(), kw.data.end(), [](const DataLine& d) { return d.empty(); }))
    s.warn(kw.loc, fmt::format("TYPE={}: this *ELEMENT has no data lines and defines no elements; "
                               "add a line per element (number, then its nodes) or remove it",
                               type_name));
  if (!elset.empty()) add_to_elset(s, elset, added);
}

/// *NSET and *ELSET share their syntax: labels and set names, or GENERATE
/// ranges.
template <bool Nodes>
static void handle_set(BuildState& s, const Keyword& kw) {
  const std::string name = set_param(s, kw, Nodes ? "NSET" : "ELSET", true);
  const bool generate = kw.has("GENERATE");
  if (kw.has("UNSORTED")) s.unsorted_sets.insert(name);
  // INSTANCE= (assembly level): the members are numbers and sets of that instance
  const BuildState::Scope outer = s.scope;
  if (kw.has("INSTANCE")) {
    const std::string inst = name_param(kw, "INSTANCE", true);
    const auto it = s.instance_index.find(inst);
    if (it == s.instance_index.end() && s.bad_instances.count(inst)) {
      s.bad_sets.insert(name); // the instance's *INSTANCE was in error (reported)
      kw.mark_read();
      return;
    }
    if (it == s.instance_index.end())
      throw InputError(kw.loc, fmt::format("INSTANCE={}", inst),
                       fmt::format("instance {} is not defined; define it with *INSTANCE, NAME={} "
                                   "inside *ASSEMBLY before this set",
                                   inst, inst));
    s.scope = BuildState::Scope{};
    s.scope.instance = it->second;
    s.scope.prefix = inst + ".";
  }
  // a node set may name nodes defined further down (Abaqus reads the model data in any order)
  struct Restore {
    BuildState& s;
    BuildState::Scope outer;
    ~Restore() {
      s.scope = outer;
      s.forward_nodes_ok = false;
    }
  } restore{s, outer};
  s.forward_nodes_ok = Nodes;
  std::vector<std::int32_t> members;
  long long missing = 0, first_missing = 0;
  const char* what = Nodes ? "node" : "element";
  auto find = [&](long long label) {
    return Nodes ? s.model.mesh.find_node(s.key(label)) : s.model.mesh.find_element(s.key(label));
  };
  auto bad = [&](long long label) {
    return Nodes ? s.bad_nodes.count(s.key(label)) > 0 : s.bad_elements.count(s.key(label)) > 0;
  };
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    if (generate) {
      const Range g = read_range(r);
      const long long count = (g.last - g.first) / g.step + 1;
      const Mesh& mesh = s.model.mesh;
      const auto& labels = Nodes ? mesh.node_labels : mesh.elem_labels;
      // (nodes defined further down count: a set may come before its *NODE lines)
      const std::size_t later = Nodes && s.node_lines ? s.node_lines->size() : 0;
      if (count <= static_cast<long long>(labels.size() + later)) {
        for (long long l = g.first; l <= g.last; l += g.step) {
          std::int32_t id = find(l);
          if (id < 0 && Nodes) id = forward_node(s, s.key(l)); // defined further down
          if (id >= 0)
            members.push_back(id);
          else if (!bad(l) && missing++ == 0)
            first_missing = l;
        }
        return;
      }
      // a range longer than the model has entities (a typo such as 1, 15056603): look at the
      // entities instead of every number of the range, so the cost stays that of the model
      auto in_range = [&](Label key) {
        if (key_instance(key) != s.scope.instance) return false;
        const long long l = key_local(key);
        return l >= g.first && l <= g.last && (l - g.first) % g.step == 0;
      };
      std::vector<std::pair<long long, std::int32_t>> found;
      for (std::size_t id = 0; id < labels.size(); ++id)
        if (in_range(labels[id]))
          found.emplace_back(key_local(labels[id]), static_cast<std::int32_t>(id));
      std::sort(found.begin(), found.end());
      long long n_bad = 0;
      for (Label key : Nodes ? s.bad_nodes : s.bad_elements) n_bad += in_range(key);
      const long long absent = count - static_cast<long long>(found.size()) - n_bad;
      if (absent > 0) {
        if (missing == 0) // the first number of the range neither defined nor in error
          for (long long l = g.first; l <= g.last; l += g.step)
            if (find(l) < 0 && !bad(l)) {
              first_missing = l;
              break;
            }
        missing += absent;
      }
      for (const auto& [label, id] : found) members.push_back(id);
      return;
    }
    for (std::size_t f = 0; f < line.fields.size(); ++f) {
      if (line.fields[f].empty()) continue;
      if (!(Nodes ? find_nset(s, name) : find_elset(s, name)) &&
          parse_reference(s, r, f).set == name)
        r.fail(fmt::format("{} set {}", what, name),
               fmt::format("the set lists itself; a set cannot be defined in terms of itself: list "
                           "its {}s by number, or sets defined before it",
                           what));
      const auto ids = Nodes ? resolve_nodes(s, r, f) : resolve_elements(s, r, f);
      members.insert(members.end(), ids.begin(), ids.end());
    }
  });
  if (missing > 0)
    s.warn(kw.loc, fmt::format("{} {} number(s) of the GENERATE ranges of set {} are not defined "
                               "(the first is {}) and were left out",
                               missing, what, name, first_missing));
  if (Nodes)
    add_to_nset(s, name, members);
  else
    add_to_elset(s, name, members);
}

void handle_nset(BuildState& s, const Keyword& kw) {
  handle_set<true>(s, kw);
}
void handle_elset(BuildState& s, const Keyword& kw) {
  handle_set<false>(s, kw);
}

namespace {

/// The side of a shell named by a surface face: SNEG or S1 (CalculiX's label) is 1, SPOS or S2
/// is 2. Shell edges (Abaqus E1…, CalculiX S3…) carry edge loads, which gapfem does not have.
int shell_side(const BuildState& s, const FieldReader& r, ElemId e, int side, long long face) {
  if (side == 0 && (face == 1 || face == 2)) side = static_cast<int>(face);
  if (side == 0)
    r.fail(fmt::format("element {} ({})", s.model.element_label(e),
                       element_info(s.model.mesh.elem_types[e]).name),
           fmt::format("face '{}' of a shell is an edge; gapfem's shell surfaces are the sides "
                       "SPOS (or S2) and SNEG (or S1): edge loads and edge surfaces are not "
                       "supported",
                       r.text(1)));
  return side;
}

} // namespace

void handle_surface(BuildState& s, const Keyword& kw) {
  const bool node_based = enum_param(kw, "TYPE", {"ELEMENT", "NODE"}, 0) == 1;
  const std::string name = set_param(s, kw, "NAME", true);
  Surface& surf = s.model.surfaces[name];
  if (surf.name.empty()) {
    surf.name = name;
    surf.loc = kw.loc;
    surf.node_based = node_based;
  } else if (surf.node_based != node_based) {
    throw InputError(kw.loc, fmt::format("surface {}", name),
                     fmt::format("the surface is already defined as {}-based ({}); a surface is "
                                 "either element-based or node-based",
                                 surf.node_based ? "node" : "element", surf.loc.str()));
  }
  if (node_based) {
    for_each_line(s, kw, [&](const DataLine& line) {
      const FieldReader r = s.reader(kw, line);
      r.at_most(2, "node or node set, area (or weight)");
      const double area = r.real_or(1, 1.0, "area");
      if (!(area > 0))
        r.fail("field 2 (area)", "the area (weight) of a surface node must be positive");
      const auto nodes = resolve_nodes(s, r, 0);
      if (nodes.empty()) s.incomplete_surfaces.insert(name);
      for (NodeId n : nodes) surf.nodes.push_back({n, area});
    });
    return;
  }
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(2, "element or element set, face label (S1..S6; SPOS, SNEG on shells)");
    const auto elems = resolve_elements(s, r, 0);
    if (elems.empty()) s.incomplete_surfaces.insert(name); // a failed definition (reported)
    const std::string face_text = canonical(r.text(1));
    const auto face = face_text.size() >= 2 && face_text[0] == 'S'
                          ? parse_integer(std::string_view(face_text).substr(1))
                          : std::nullopt;
    const int side = face_text == "SNEG" ? 1 : face_text == "SPOS" ? 2 : 0;
    const long long fnum = face.value_or(0);
    if (fnum < 1 && side == 0)
      r.fail(fmt::format("face '{}'", r.text(1)),
             "write the face as S1, S2, … (the face numbers of the element type; SPOS or SNEG "
             "for the sides of shells)");
    for (ElemId e : elems) {
      const ElementType t = s.model.mesh.elem_types[e];
      if (element_info(t).family == ElementFamily::Shell) {
        surf.faces.push_back({e, shell_side(s, r, e, side, fnum)});
        continue;
      }
      if (side != 0)
        r.fail(fmt::format("element {} ({})", s.model.element_label(e), element_info(t).name),
               "SPOS and SNEG are the sides of shell elements; faces of this element type are "
               "written S1, S2, …");
      const int nf = n_faces(t);
      if (fnum > nf)
        r.fail(fmt::format("element {} ({})", s.model.element_label(e), element_info(t).name),
               nf == 0 ? std::string("this element type has no faces for a surface")
                       : fmt::format("face S{} does not exist; this element type has faces S1-S{}",
                                     fnum, nf));
      surf.faces.push_back({e, static_cast<int>(fnum)});
    }
  });
}

} // namespace gapfem::inp
