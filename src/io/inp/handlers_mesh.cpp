// Mesh keywords: *HEADING, *PREPRINT, *NODE, *ELEMENT, *NSET, *ELSET, *SURFACE.
#include "io/inp/handlers.hpp"

#include <fmt/format.h>

namespace gapfem::inp {
namespace {

std::string where(const BuildState& s, SourceRef ref) {
  return fmt::format("{}:{}", s.model.source_files[ref.file], ref.line);
}

/// Largest number of members one GENERATE line may produce (guards against typos like 1,1E9).
constexpr long long kMaxGenerate = 100'000'000;

struct Range {
  long long first, last, step;
};

Range read_range(const FieldReader& r) {
  r.at_most(3, "first, last, increment");
  Range g{r.integer(0, "first"), r.integer_or(1, r.integer(0, "first"), "last"),
          r.integer_or(2, 1, "increment")};
  if (g.step <= 0)
    r.fail("field 3 (increment)",
           fmt::format("the increment must be a positive integer, not {}", g.step));
  if (g.first <= 0) r.fail("field 1 (first)", "labels must be positive integers");
  if (g.last < g.first)
    r.fail(fmt::format("range {}-{}", g.first, g.last),
           "with GENERATE the last label must not be smaller than the first; write first, last, "
           "increment");
  if ((g.last - g.first) / g.step > kMaxGenerate)
    r.fail(fmt::format("range {}-{}", g.first, g.last), "this range is too large");
  return g;
}

} // namespace

void handle_heading(BuildState& s, const Keyword& kw) {
  std::vector<std::string> lines;
  for (const auto& d : kw.data) lines.emplace_back(trim(d.text));
  while (!lines.empty() && lines.back().empty()) lines.pop_back();
  for (const auto& l : lines) {
    if (!s.model.heading.empty()) s.model.heading += '\n';
    s.model.heading += l;
  }
}

void handle_preprint(BuildState&, const Keyword&) {}

void handle_node(BuildState& s, const Keyword& kw) {
  reject_param(kw, "SYSTEM",
               "give the coordinates in the global rectangular system (SYSTEM=R is the default)");
  const std::string nset = name_param(kw, "NSET", false);
  Mesh& mesh = s.model.mesh;
  std::vector<NodeId> added;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    const long long label = r.integer(0, "node number");
    try {
      if (label <= 0)
        r.fail(fmt::format("node {}", label), "node numbers must be positive integers");
      r.at_most(4, "node number, x, y, z");
      const Vec3 x{r.real_or(1, 0.0, "x"), r.real_or(2, 0.0, "y"), r.real_or(3, 0.0, "z")};
      if (const NodeId old = mesh.find_node(label); old >= 0)
        r.fail(fmt::format("node {}", label),
               fmt::format(
                   "this node number is defined twice (first at {}); give each node its own number",
                   where(s, s.node_src[old])));
      const NodeId id = mesh.n_nodes();
      mesh.node_labels.push_back(label);
      mesh.coords.push_back(x);
      mesh.node_index.emplace(label, id);
      s.node_src.push_back(s.ref(line));
      added.push_back(id);
    } catch (const InputError&) {
      if (mesh.find_node(label) < 0) s.bad_nodes.insert(label);
      throw;
    }
  });
  if (!nset.empty()) add_to_nset(s, nset, added);
}

void handle_element(BuildState& s, const Keyword& kw) {
  const std::string elset = name_param(kw, "ELSET", false);
  std::optional<ElementType> type;
  try {
    const std::string tname = param_value(kw, "TYPE", true);
    type = element_type_from_name(tname);
    if (!type) {
      std::string known;
      for (const auto& info : all_element_types())
        known += (known.empty() ? "" : ", ") + std::string(info.name);
      throw InputError(
          kw.loc, fmt::format("TYPE={}", to_upper(tname)),
          fmt::format("gapfem does not know this element type; supported types: {}", known));
    }
  } catch (const InputError& e) {
    // remember the labels so that later references do not raise follow-up errors
    for (const auto& d : kw.data)
      if (!d.fields.empty())
        if (auto l = parse_integer(d.fields[0])) s.bad_elements.insert(*l);
    if (!elset.empty()) s.bad_sets.insert(elset);
    throw;
  }
  const ElementTypeInfo& info = element_info(*type);
  Mesh& mesh = s.model.mesh;
  std::vector<ElemId> added;
  for (std::size_t i = 0; i < kw.data.size(); ++i) {
    if (kw.data[i].empty()) continue;
    // a line ending with a comma continues on the next line until all nodes are given
    const SourceRef first_line = s.ref(kw.data[i]);
    // (copied only when it is continued: most element lines are complete)
    const DataLine* line = &kw.data[i];
    DataLine joined;
    if (line->trailing_comma && static_cast<int>(line->fields.size()) < info.n_nodes + 1) {
      joined = *line;
      while (joined.trailing_comma && static_cast<int>(joined.fields.size()) < info.n_nodes + 1 &&
             i + 1 < kw.data.size()) {
        ++i;
        const DataLine& next = kw.data[i];
        joined.fields.insert(joined.fields.end(), next.fields.begin(), next.fields.end());
        joined.trailing_comma = next.trailing_comma;
      }
      line = &joined;
    }
    const FieldReader r = s.reader(kw, *line);
    long long label = 0;
    try {
      label = r.integer(0, "element number");
      const std::string ent = fmt::format("element {}", label);
      if (label <= 0) r.fail(ent, "element numbers must be positive integers");
      if (const ElemId old = mesh.find_element(label); old >= 0)
        r.fail(ent, fmt::format("this element number is defined twice (first at {}); give each "
                                "element its own number",
                                where(s, mesh.elem_src[old])));
      std::vector<long long> node_labels;
      for (std::size_t f = 1; f < line->fields.size(); ++f) {
        if (line->fields[f].empty()) continue;
        node_labels.push_back(r.integer(f, "node number"));
      }
      if (static_cast<int>(node_labels.size()) != info.n_nodes)
        r.fail(ent,
               fmt::format("{} needs {} nodes but {} are given; list exactly {} node numbers after "
                           "the element number (continue on the next line after a trailing comma)",
                           info.name, info.n_nodes, node_labels.size(), info.n_nodes));
      std::vector<NodeId> nodes;
      bool skip = false;
      for (long long nl : node_labels) {
        const NodeId n = mesh.find_node(nl);
        if (n < 0) {
          if (s.bad_nodes.count(nl)) {
            skip = true;
            continue;
          }
          r.fail(ent, fmt::format("node {} is not defined; define it with *NODE before use", nl));
        }
        nodes.push_back(n);
      }
      if (skip) {
        s.bad_elements.insert(label);
        continue;
      }
      const ElemId id = mesh.n_elements();
      mesh.elem_labels.push_back(label);
      mesh.elem_types.push_back(*type);
      mesh.conn.insert(mesh.conn.end(), nodes.begin(), nodes.end());
      mesh.conn_offset.push_back(static_cast<std::int64_t>(mesh.conn.size()));
      mesh.elem_src.push_back(first_line);
      mesh.elem_index.emplace(label, id);
      added.push_back(id);
    } catch (const InputError& e) {
      if (label > 0 && mesh.find_element(label) < 0) s.bad_elements.insert(label);
      s.diag.error(e);
    }
  }
  if (!elset.empty()) add_to_elset(s, elset, added);
}

/// *NSET and *ELSET share their syntax: labels and set names, or GENERATE
/// ranges.
template <bool Nodes>
static void handle_set(BuildState& s, const Keyword& kw) {
  const std::string name = name_param(kw, Nodes ? "NSET" : "ELSET", true);
  const bool generate = kw.has("GENERATE");
  std::vector<std::int32_t> members;
  long long missing = 0, first_missing = 0;
  const char* what = Nodes ? "node" : "element";
  auto find = [&](long long label) {
    return Nodes ? s.model.mesh.find_node(label) : s.model.mesh.find_element(label);
  };
  auto bad = [&](long long label) {
    return Nodes ? s.bad_nodes.count(label) > 0 : s.bad_elements.count(label) > 0;
  };
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    if (generate) {
      const Range g = read_range(r);
      for (long long l = g.first; l <= g.last; l += g.step) {
        const std::int32_t id = find(l);
        if (id >= 0)
          members.push_back(id);
        else if (!bad(l) && missing++ == 0)
          first_missing = l;
      }
      return;
    }
    for (std::size_t f = 0; f < line.fields.size(); ++f) {
      if (line.fields[f].empty()) continue;
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

void handle_surface(BuildState& s, const Keyword& kw) {
  const int type = enum_param(kw, "TYPE", {"ELEMENT", "NODE"}, 0);
  if (type == 1)
    throw InputError(kw.loc, "TYPE=NODE",
                     "node-based surfaces are not supported by gapfem; connect nodes with gap "
                     "elements, or define an element-based surface (TYPE=ELEMENT)");
  const std::string name = name_param(kw, "NAME", true);
  Surface& surf = s.model.surfaces[name];
  if (surf.name.empty()) {
    surf.name = name;
    surf.loc = kw.loc;
  }
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(2, "element or element set, face label S1..S6");
    const auto elems = resolve_elements(s, r, 0);
    const std::string face_text = canonical(r.text(1));
    const auto face = face_text.size() >= 2 && face_text[0] == 'S'
                          ? parse_integer(std::string_view(face_text).substr(1))
                          : std::nullopt;
    if (!face || *face < 1)
      r.fail(fmt::format("face '{}'", r.text(1)),
             "write the face as S1, S2, … (the face numbers of the element type)");
    for (ElemId e : elems) {
      const ElementType t = s.model.mesh.elem_types[e];
      const int nf = n_faces(t);
      if (*face > nf)
        r.fail(fmt::format("element {} ({})", s.model.element_label(e), element_info(t).name),
               nf == 0 ? std::string("this element type has no faces for a surface")
                       : fmt::format("face S{} does not exist; this element type has faces S1-S{}",
                                     *face, nf));
      surf.faces.push_back({e, static_cast<int>(*face)});
    }
  });
}

} // namespace gapfem::inp
