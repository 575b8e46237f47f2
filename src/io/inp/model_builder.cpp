#include "io/inp/model_builder.hpp"

#include "fe/element_faces.hpp"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>

namespace gapfem::inp {

// ---------------------------------------------------------------- scope

Vec3 BuildState::from_system(const Vec3& x) const {
  if (!scope.local_system) return x;
  const auto& A = scope.system_axes;
  Vec3 out{};
  for (int i = 0; i < 3; ++i)
    out[i] = scope.system_origin[i] + A[3 * i] * x[0] + A[3 * i + 1] * x[1] + A[3 * i + 2] * x[2];
  return out;
}

Vec3 BuildState::place(const Vec3& x) const {
  if (!scope.placed) return x;
  // translation first, then the rotation about the axis through axis_point (Abaqus *INSTANCE)
  Vec3 y{x[0] + scope.translation[0] - scope.axis_point[0],
         x[1] + scope.translation[1] - scope.axis_point[1],
         x[2] + scope.translation[2] - scope.axis_point[2]};
  const auto& R = scope.rotation;
  Vec3 out{};
  for (int i = 0; i < 3; ++i)
    out[i] = scope.axis_point[i] + R[3 * i] * y[0] + R[3 * i + 1] * y[1] + R[3 * i + 2] * y[2];
  return out;
}

// ---------------------------------------------------------------- numbers

int dof_number(const FieldReader& r, std::size_t i, std::string_view what) {
  const long long n = r.integer(i, what, 1, kMaxAbaqusDof, kUnknownDof);
  DofType d{};
  if (!dof_from_abaqus(static_cast<int>(n), d))
    r.fail(fmt::format("field {} ({})", i + 1, what), fmt::format(fmt::runtime(kUnknownDof), n));
  return static_cast<int>(n);
}

long long read_label(BuildState& s, const FieldReader& r, std::string_view what) {
  long long v = 0;
  if (!r.blank(0) && check_integer(r.text(0), 1, kMaxLabel, v) == IntCheck::OutOfRange)
    s.label_out_of_range = true;
  return r.integer(0, what, 1, kMaxLabel, kLabelRule);
}

std::string_view article(std::string_view word) {
  if (word.empty()) return "a";
  const char first = static_cast<char>(std::toupper(static_cast<unsigned char>(word[0])));
  const bool spelled = word.size() > 1 && std::isdigit(static_cast<unsigned char>(word[1]));
  const std::string_view vowel_sound = spelled ? "AEFHILMNORSX" : "AEIO";
  return vowel_sound.find(first) == std::string_view::npos ? "a" : "an";
}

std::string with_article(std::string_view word) {
  return fmt::format("{} {}", article(word), word);
}

// ---------------------------------------------------------------- references

EntityRef parse_reference(BuildState& s, const FieldReader& r, std::size_t field) {
  std::string t = std::string(trim(r.text(field)));
  // a name in double quotes (Abaqus allows them for names with blanks): the name inside
  if (const auto quotes = std::count(t.begin(), t.end(), '"'); quotes > 0) {
    if (quotes != 2 || t.size() < 2 || t.front() != '"' || t.back() != '"') {
      std::string bare = t;
      std::erase(bare, '"');
      r.fail(fmt::format("field {} ({})", field + 1, t),
             fmt::format("a double quote (\") in this name is not closed; a quoted name is "
                         "enclosed in two, as in \"{}\"",
                         bare));
    }
    t = std::string(trim(std::string_view(t).substr(1, t.size() - 2)));
  }
  EntityRef ref;
  // a number out of range names nothing: reported, unless its definition was (read_label)
  auto label = [&](std::string_view text) -> std::optional<long long> {
    long long v = 0;
    const IntCheck c = check_integer(text, 1, kMaxLabel, v);
    if (c == IntCheck::NotWhole) return std::nullopt;
    r.mark_integer(field);
    if (c == IntCheck::Ok) return v;
    if (s.label_out_of_range) {
      ref.failed = true;
      return std::nullopt;
    }
    r.fail(fmt::format("field {}", field + 1), fmt::format(fmt::runtime(kLabelRule), text));
  };
  const auto dot = t.find('.');
  if (dot == std::string::npos) {
    if (const auto l = label(t))
      ref.key = s.key(*l);
    else if (!ref.failed)
      ref.set = s.set_name(to_upper(t));
    return ref;
  }
  // qualified by an instance: INSTANCE.label or INSTANCE.SET
  const std::string inst = to_upper(trim(std::string_view(t).substr(0, dot)));
  const std::string rest = std::string(trim(std::string_view(t).substr(dot + 1)));
  const auto it = s.instance_index.find(inst);
  if (it == s.instance_index.end() && s.bad_instances.count(inst)) {
    ref.failed = true;
    return ref;
  }
  if (it == s.instance_index.end())
    r.fail(fmt::format("'{}'", t),
           s.instance_index.empty()
               ? fmt::format("'{}' is not a number or set name of this deck, and the deck defines "
                             "no part instances (*INSTANCE) that it could qualify",
                             t)
               : fmt::format("instance {} is not defined; define it with *INSTANCE, NAME={} inside "
                             "*ASSEMBLY before it is used, or check the spelling",
                             inst, inst));
  if (const auto l = label(rest))
    ref.key = make_key(it->second, *l);
  else if (!ref.failed)
    ref.set = inst + "." + to_upper(rest);
  return ref;
}

namespace {
/// Outside *ELEMENT and *NSET a node must have its coordinates when a keyword names it: one named
/// earlier by an *ELEMENT or *NSET and defined further down is an error naming that line.
void check_not_awaiting(const BuildState& s, const FieldReader& r,
                        const std::vector<NodeId>& nodes) {
  if (s.awaiting.empty() || s.forward_nodes_ok) return;
  for (NodeId n : nodes)
    if (s.awaiting.count(n) && !s.bad_nodes.count(s.model.mesh.node_labels[n])) {
      const Label key = s.model.mesh.node_labels[n];
      r.fail(fmt::format("node {}", s.model.label_of_key(key)),
             node_defined_later(s, key, s.node_src[n], r.loc().keyword));
    }
}
} // namespace

std::vector<NodeId> resolve_nodes(BuildState& s, const FieldReader& r, std::size_t field) {
  const std::string& t = r.text(field);
  if (t.empty())
    r.fail(fmt::format("field {}", field + 1), "a node number or node set name is required here");
  const EntityRef ref = parse_reference(s, r, field);
  if (ref.failed) return {};
  const std::string& keyword = r.loc().keyword;
  if (ref.key) {
    NodeId n = s.model.mesh.find_node(*ref.key);
    if (n < 0 && s.bad_nodes.count(*ref.key)) return {};
    if (n < 0 && s.forward_nodes_ok) n = forward_node(s, *ref.key);
    if (n >= 0) {
      check_not_awaiting(s, r, {n});
      return {n};
    }
    const std::string entity = fmt::format("node {}", s.model.label_of_key(*ref.key));
    if (const SourceRef* later = later_node_line(s, *ref.key))
      r.fail(entity, node_defined_later(s, *ref.key, *later, keyword));
    r.fail(entity, undefined_node(s, *ref.key, true, !s.forward_nodes_ok));
  }
  if (const auto* set = find_nset(s, ref.set)) {
    check_not_awaiting(s, r, *set);
    return *set;
  }
  if (s.bad_sets.count(ref.set)) return {};
  const std::string why =
      undefined_name(s, ref.set, NameKind::NodeSet, keyword, "a node or a node set",
                     "define it with *NSET (or NSET= on *NODE) before use, or check the spelling");
  r.fail(why.starts_with("this ") ? fmt::format("node set {}", ref.set) : std::string(), why);
}

std::vector<ElemId> resolve_elements(BuildState& s, const FieldReader& r, std::size_t field) {
  const std::string& t = r.text(field);
  if (t.empty())
    r.fail(fmt::format("field {}", field + 1),
           "an element number or element set name is required here");
  const EntityRef ref = parse_reference(s, r, field);
  if (ref.failed) return {};
  if (ref.key) {
    const ElemId e = s.model.mesh.find_element(*ref.key);
    if (e >= 0) return {e};
    if (s.bad_elements.count(*ref.key)) return {};
    r.fail(fmt::format("element {}", s.model.label_of_key(*ref.key)),
           key_instance(*ref.key) > 0
               ? fmt::format("instance {} (part {}) has no element {}; check the number",
                             s.model.instances[key_instance(*ref.key) - 1],
                             s.instance_parts[key_instance(*ref.key) - 1], key_local(*ref.key))
               : "this element is not defined; define it with *ELEMENT before use");
  }
  if (const auto* set = find_elset(s, ref.set)) return *set;
  if (s.bad_sets.count(ref.set)) return {};
  const std::string why = undefined_name(
      s, ref.set, NameKind::ElementSet, r.loc().keyword, "an element or an element set",
      "define it with *ELSET (or ELSET= on *ELEMENT) before use, or check the spelling");
  r.fail(why.starts_with("this ") ? fmt::format("element set {}", ref.set) : std::string(), why);
}

const std::vector<ElemId>* find_elset(BuildState& s, const std::string& name) {
  const auto it = s.model.elsets.find(name);
  if (it != s.model.elsets.end()) return &it->second;
  if (name == "EALL") { // CalculiX's implicit set of every element (when the deck has none)
    s.all_elements.resize(static_cast<std::size_t>(s.model.mesh.n_elements()));
    for (ElemId e = 0; e < s.model.mesh.n_elements(); ++e) s.all_elements[e] = e;
    return &s.all_elements;
  }
  return nullptr;
}

const std::vector<NodeId>* find_nset(BuildState& s, const std::string& name) {
  const auto it = s.model.nsets.find(name);
  if (it != s.model.nsets.end()) return &it->second;
  if (name == "NALL") { // CalculiX's implicit set of every node (when the deck has none)
    s.all_nodes.resize(static_cast<std::size_t>(s.model.mesh.n_nodes()));
    for (NodeId n = 0; n < s.model.mesh.n_nodes(); ++n) s.all_nodes[n] = n;
    return &s.all_nodes;
  }
  return nullptr;
}

/// The single node named by a parameter value (a label, or a set holding one node).
NodeId param_node(BuildState& s, const Keyword& kw, std::string_view param) {
  const std::string value = param_value(kw, param, true);
  DataLine line;
  line.fields = {value};
  line.file = kw.file;
  line.line = kw.line;
  const FieldReader r(line, kw.loc);
  const std::vector<NodeId> nodes = resolve_nodes(s, r, 0);
  if (nodes.size() != 1)
    throw InputError(
        kw.loc, fmt::format("{}={}", param, value),
        fmt::format("{} names one node; this set holds {}", display_upper(param), nodes.size()));
  return nodes[0];
}

int amplitude_param(BuildState& s, const Keyword& kw, std::string_view param) {
  if (!kw.has(param)) return -1;
  const std::string name = name_param(kw, param, true);
  const auto it = s.amplitude_index.find(name);
  if (it == s.amplitude_index.end() && s.bad_amplitudes.count(name)) return -1; // reported
  if (it == s.amplitude_index.end())
    throw InputError(
        kw.loc, fmt::format("{}={}", display_upper(param), name),
        fmt::format(
            "amplitude {} is not defined; define it with *AMPLITUDE, NAME={} before this keyword",
            name, name));
  return it->second;
}

// ---------------------------------------------------------------- parameters

std::string param_value(const Keyword& kw, std::string_view param, bool required) {
  const Parameter* p = kw.find(param);
  if (!p) {
    if (required)
      throw InputError(kw.loc, "",
                       fmt::format("the parameter {}= is required; add it to the keyword line",
                                   display_upper(param)));
    return {};
  }
  if (!p->has_value || p->value.empty())
    throw InputError(kw.loc, p->name,
                     fmt::format("the parameter {} needs a value; write {}=...", p->name, p->name));
  return p->value;
}

std::string name_param(const Keyword& kw, std::string_view param, bool required) {
  return to_upper(trim(param_value(kw, param, required)));
}

std::string set_param(BuildState& s, const Keyword& kw, std::string_view param, bool required) {
  const std::string name = name_param(kw, param, required);
  if (name.empty()) return name;
  const auto dot = name.find('.');
  if (dot != std::string::npos && s.instance_index.count(name.substr(0, dot))) return name;
  return s.set_name(name);
}

int enum_param(const Keyword& kw, std::string_view param,
               std::initializer_list<std::string_view> choices, int def) {
  const Parameter* p = kw.find(param);
  if (!p) return def;
  const std::string v = canonical(p->value);
  int i = 0, prefix_of = -1, prefixes = 0;
  for (auto c : choices) {
    if (canonical(c) == v) return i;
    if (v.size() >= 3 && canonical(c).starts_with(v)) {
      prefix_of = i;
      ++prefixes;
    }
    ++i;
  }
  // Abaqus reads a value from as many first letters as tell it apart (Input Syntax Rules)
  if (prefixes == 1) return prefix_of;
  std::string list;
  for (auto c : choices) list += (list.empty() ? "" : ", ") + std::string(c);
  throw InputError(kw.loc, fmt::format("{}={}", p->name, p->value),
                   fmt::format("this value is not supported by gapfem; use one of: {}", list));
}

bool yes_no_param(const Keyword& kw, std::string_view param, bool def) {
  const Parameter* p = kw.find(param);
  if (!p) return def;
  if (!p->has_value) return true;
  const std::string v = canonical(p->value);
  if (v == "YES" || v == "ON" || v == "TRUE") return true;
  if (v == "NO" || v == "OFF" || v == "FALSE") return false;
  throw InputError(kw.loc, fmt::format("{}={}", p->name, p->value), "write YES or NO");
}

std::optional<double> real_param(const Keyword& kw, std::string_view param) {
  if (!kw.has(param)) return std::nullopt;
  const std::string v = param_value(kw, param, true);
  const auto x = parse_real(v);
  if (!x)
    throw InputError(kw.loc, fmt::format("{}={}", display_upper(param), v),
                     real_out_of_range(v)
                         ? "the value is out of range (larger than 1.8E308 in "
                           "magnitude, the largest number gapfem holds)"
                         : "the value is not a number; write it like 0.5 or 1.E-3");
  return x;
}

std::optional<long long> int_param(const Keyword& kw, std::string_view param, std::string_view what,
                                   long long min, long long max) {
  if (!kw.has(param)) return std::nullopt;
  const std::string v = param_value(kw, param, true);
  kw.find(param)->integer = true;
  long long x = 0;
  const IntCheck c = check_integer(v, min, max, x);
  if (c != IntCheck::Ok)
    throw InputError(kw.loc, fmt::format("{}={}", display_upper(param), v),
                     fmt::format("{} must be a whole number from {} to {}{}", what, min, max,
                                 c == IntCheck::NotWhole ? " (digits only)" : ""));
  return x;
}

long long dependencies_param(const Keyword& kw) {
  return int_param(kw, "DEPENDENCIES", "the number of field variables", 0, kMaxInt).value_or(0);
}

std::string param_text(const Keyword& kw, std::string_view param) {
  const Parameter* p = kw.find(param);
  if (!p) return {};
  return p->has_value ? fmt::format("{}={}", p->name, p->value) : p->name;
}

void reject_param(const Keyword& kw, std::string_view param, std::string_view why) {
  if (const Parameter* p = kw.find(param))
    throw InputError(kw.loc, p->has_value ? fmt::format("{}={}", p->name, p->value) : p->name,
                     fmt::format("this parameter is not supported by gapfem; {}", why));
}

PropertyTable read_property_table(BuildState& s, const Keyword& kw, std::span<const DataLine> lines,
                                  std::vector<std::string_view> names, RowCheck check,
                                  std::size_t required) {
  if (const auto dep = dependencies_param(kw); dep > 0)
    throw InputError(kw.loc, fmt::format("DEPENDENCIES={}", dep),
                     "field-variable dependencies are not supported by gapfem; tabulate the data "
                     "against temperature only");
  const int nv = static_cast<int>(names.size());
  std::string layout;
  for (auto n : names) layout += std::string(n) + ", ";
  layout += "temperature";
  struct Row {
    std::vector<double> v;
    double t;
    SourceLocation loc;
  };
  std::vector<Row> rows;
  const int errors_before = s.diag.n_errors();
  for_each_line(s, lines, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(nv + 1, layout);
    Row row;
    for (int i = 0; i < nv; ++i)
      row.v.push_back(static_cast<std::size_t>(i) < required ? r.real(i, names[i])
                                                             : r.real_or(i, 0.0, names[i]));
    row.t = r.real_or(nv, 0.0, "temperature");
    row.loc = r.loc();
    if (check) {
      const std::string problem = check(row.v);
      if (!problem.empty()) r.fail("", problem);
    }
    rows.push_back(std::move(row));
  });
  PropertyTable table;
  table.n_values = nv;
  if (rows.empty()) {
    if (errors_before == s.diag.n_errors())
      throw InputError(kw.loc, "", fmt::format("a data line is required: {}", layout));
    return table;
  }
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.t < b.t; });
  for (std::size_t i = 1; i < rows.size(); ++i)
    if (rows[i].t == rows[i - 1].t)
      throw InputError(rows[i].loc, "",
                       fmt::format("two data lines are given for temperature {}; give each "
                                   "temperature once (a blank temperature means 0)",
                                   rows[i].t));
  for (const Row& row : rows) {
    table.values.insert(table.values.end(), row.v.begin(), row.v.end());
    table.keys.push_back(row.t);
  }
  return table;
}

template <typename T>
static void add_sorted(std::vector<T>& set, const std::vector<T>& add) {
  set.insert(set.end(), add.begin(), add.end());
  std::sort(set.begin(), set.end());
  set.erase(std::unique(set.begin(), set.end()), set.end());
}

void add_to_nset(BuildState& s, const std::string& name, const std::vector<NodeId>& nodes) {
  add_sorted(s.model.nsets[name], nodes);
}
void add_to_elset(BuildState& s, const std::string& name, const std::vector<ElemId>& elems) {
  add_sorted(s.model.elsets[name], elems);
}

namespace {
/// Faces of the element's cell (the ends of a link), whatever they are used for.
int cell_faces(ElementType type) {
  const ElementTypeInfo& info = element_info(type);
  if (!info.cell || info.family == ElementFamily::Gap) return 0;
  if (shape_dim(*info.cell) == 1) return info.temperature ? 2 : 0; // the ends of a link
  return static_cast<int>(element_faces(*info.cell).size());
}
} // namespace

int n_faces(ElementType type, FaceUse use) {
  const ElementTypeInfo& info = element_info(type);
  if (info.family == ElementFamily::Shell) // SNEG (1) and SPOS (2)
    return (use == FaceUse::Thermal && !info.temperature) ||
                   (use == FaceUse::Pressure && !info.displacement)
               ? 0
               : 2;
  const int pressure =
      info.family == ElementFamily::Continuum && info.displacement ? cell_faces(type) : 0;
  const int thermal = info.temperature && info.family != ElementFamily::Gap ? cell_faces(type) : 0;
  switch (use) {
  case FaceUse::Pressure:
    return pressure;
  case FaceUse::Thermal:
    return thermal;
  case FaceUse::Any:
    break;
  }
  return std::max(pressure, thermal);
}

} // namespace gapfem::inp
