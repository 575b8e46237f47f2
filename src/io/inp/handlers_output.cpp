// Output requests: *NODE PRINT, *EL PRINT (.dat tables) and *OUTPUT, FIELD with *NODE OUTPUT /
// *ELEMENT OUTPUT (ParaView frames). Abaqus output keys become typed ids here, once.
#include "io/inp/handlers.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fmt/format.h>

namespace gapfem::inp {
namespace {

/// TOTALS=YES|NO|ONLY.
template <class Request>
void totals_param(const Keyword& kw, Request& req) {
  const int t = enum_param(kw, "TOTALS", {"NO", "YES", "ONLY"}, 0);
  req.totals = t != 0;
  req.totals_only = t == 2;
  if (req.totals_only) req.summary = false;
}

/// "U" or a component such as "U1", "NT11", "S12": the parent variable name, or "" when the name
/// does not have that form.
template <typename V, typename Lookup>
std::optional<V> lookup_with_components(std::string name, Lookup lookup) {
  if (auto v = lookup(name)) return v;
  while (!name.empty() && std::isdigit(static_cast<unsigned char>(name.back()))) name.pop_back();
  if (name.empty()) return std::nullopt;
  return lookup(name);
}

std::optional<NodeVar> node_var(const std::string& name) {
  return lookup_with_components<NodeVar>(canonical(name), node_var_from_name);
}
std::optional<ElemVar> elem_var(const std::string& name) {
  return lookup_with_components<ElemVar>(canonical(name), elem_var_from_name);
}

template <typename T>
void add_unique(std::vector<T>& list, T v) {
  if (std::find(list.begin(), list.end(), v) == list.end()) list.push_back(v);
}

constexpr const char* kNodeVarList = "U, UR, RF, RM, CF, CM, NT, RFL, CFL, V, VR, A, AR";
constexpr const char* kElemVarList = "S, E, SF (with SM), HFL, NFORC, ENER, ELSE, EVOL, COORD";

/// A data line of numbers only (a list of section points, read by read_vars, which says which are
/// not whole numbers in range)?
bool number_line(const DataLine& line) {
  bool any = false;
  for (const auto& f : line.fields) {
    if (f.empty()) continue;
    long long v = 0;
    if (check_integer(f, 0, 0, v) == IntCheck::NotWhole) {
      char* end = nullptr;
      std::strtod(f.c_str(), &end); // a real number (1e20, 2.5) is a section point in error
      if (end == f.c_str() || *end != '\0') return false;
    }
    any = true;
  }
  return any;
}

/// Reads variable names from all data lines; unknown names are left out with a warning.
/// A line of numbers is a list of section points: appended to `points` when given (each must be
/// positive), otherwise reported by `points_note`.
/// `failed` (when given) counts the lines in error (a section point out of range), so that their
/// request gets no false "writes nothing" as well.
template <typename V, typename Parse>
std::vector<V> read_vars(BuildState& s, const Keyword& kw, Parse parse, const char* known,
                         std::vector<int>* points = nullptr, const char* points_note = nullptr,
                         int* failed = nullptr) {
  std::vector<V> vars;
  const int n_failed = for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    if (number_line(line) && (points || points_note)) {
      if (!points) {
        s.warn(r.loc(), points_note);
        return;
      }
      constexpr std::string_view rule =
          "section point {} is out of range: section points are numbered from 1 (the SNEG side "
          "of a shell, the first point of a beam section) up to 2147483647";
      for (std::size_t i = 0; i < line.fields.size(); ++i) {
        if (r.blank(i)) continue;
        const int n = static_cast<int>(r.integer(i, "section point", 1, kMaxInt, rule));
        if (std::find(points->begin(), points->end(), n) == points->end()) points->push_back(n);
      }
      return;
    }
    for (std::size_t i = 0; i < line.fields.size(); ++i) {
      if (line.fields[i].empty()) continue;
      if (const auto v = parse(line.fields[i])) {
        add_unique(vars, *v);
        continue;
      }
      const std::string msg = fmt::format("gapfem does not know the output variable {}; it knows "
                                          "{} (components such as U1 or S11 are accepted)",
                                          line.fields[i], known);
      s.warn(r.loc(), msg + "; the variable was left out");
    }
  });
  if (failed) *failed = n_failed;
  return vars;
}

/// The variables of a print or file request (docs/keywords.md, "Output requests never stop a
/// run"): unknown names are left out with a warning (read_vars); a request without data lines
/// asks for `defaults` (CalculiX's: U for nodes, S for elements); a request whose every name was
/// unknown writes nothing (empty: the caller drops it, with a warning here).
template <typename V, typename Parse>
std::vector<V> request_vars(BuildState& s, const Keyword& kw, Parse parse, const char* known,
                            std::initializer_list<V> defaults, std::vector<int>* points = nullptr) {
  int failed = 0;
  std::vector<V> vars = read_vars<V>(s, kw, parse, known, points, nullptr, &failed);
  if (!vars.empty() || failed > 0) return vars;
  if (kw.data.empty()) return defaults;
  s.warn(kw.loc, fmt::format("{} lists no output variable gapfem writes, so it writes nothing "
                             "(known: {})",
                             kw.name, known));
  return vars;
}

int frequency_param(const Keyword& kw) {
  // FREQ: the abbreviation CalculiX decks use; FREQUENCYF (CalculiX's frequency of its fluid
  // results) has no meaning here and is left aside
  constexpr std::string_view what = "the output frequency (every n-th increment; 0: none)";
  const auto f = int_param(kw, kw.has("FREQUENCY") ? "FREQUENCY" : "FREQ", what, 0, kMaxInt);
  return f ? static_cast<int>(*f) : 1;
}

} // namespace

void handle_node_print(BuildState& s, const Keyword& kw) {
  NodePrintRequest req;
  req.loc = kw.loc;
  req.frequency = frequency_param(kw);
  req.summary = yes_no_param(kw, "SUMMARY", true);
  totals_param(kw, req);
  req.global = yes_no_param(kw, "GLOBAL", false);
  req.nset = set_param(s, kw, "NSET", false);
  if (req.nset.empty()) {
    req.nodes.resize(static_cast<std::size_t>(s.model.mesh.n_nodes()));
    for (NodeId n = 0; n < s.model.mesh.n_nodes(); ++n) req.nodes[n] = n;
  } else {
    const auto* set = find_nset(s, req.nset);
    if (!set && s.bad_sets.count(req.nset)) { // its definition failed (reported)
      kw.mark_read();
      return;
    }
    if (!set)
      throw InputError(kw.loc, fmt::format("NSET={}", req.nset),
                       undefined_name(s, req.nset, NameKind::NodeSet, kw.name, "a node set",
                                      "define it with *NSET in the model data"));
    req.nodes = *set;
  }
  req.vars = request_vars<NodeVar>(s, kw, node_var, kNodeVarList, {NodeVar::U});
  if (req.vars.empty()) return; // its unknown variables were reported
  s.scratch.node_print_given = true;
  s.step.node_prints.push_back(std::move(req));
}

void handle_el_print(BuildState& s, const Keyword& kw) {
  ElPrintRequest req;
  req.loc = kw.loc;
  req.frequency = frequency_param(kw);
  // continuum elements report global components either way; shells report S, E, SF in their local
  // directions (Abaqus's default, GLOBAL=NO), which a GLOBAL=YES request is told below
  const bool global = yes_no_param(kw, "GLOBAL", false);
  req.summary = yes_no_param(kw, "SUMMARY", true);
  totals_param(kw, req);
  // INTEGRATION POINT: the singular spelling Abaqus also accepts; NODES (each element's values
  // extrapolated to its nodes, not averaged): printed averaged, with a warning
  const int pos = enum_param(
      kw, "POSITION",
      {"INTEGRATION POINTS", "CENTROIDAL", "AVERAGED AT NODES", "INTEGRATION POINT", "NODES"}, 0);
  if (pos == 4)
    s.warn(kw.loc, "POSITION=NODES: job.dat prints the element values extrapolated to the nodes "
                   "and averaged there (POSITION=AVERAGED AT NODES), not element by element");
  req.position = pos == 0 || pos == 3 ? ElPosition::IntegrationPoints
                 : pos == 1           ? ElPosition::Centroidal
                                      : ElPosition::Averaged;
  req.elset = set_param(s, kw, "ELSET", false);
  if (req.elset.empty()) {
    req.elements.resize(static_cast<std::size_t>(s.model.mesh.n_elements()));
    for (ElemId e = 0; e < s.model.mesh.n_elements(); ++e) req.elements[e] = e;
  } else {
    const auto* set = find_elset(s, req.elset);
    if (!set && s.bad_sets.count(req.elset)) { // its definition failed (reported)
      kw.mark_read();
      return;
    }
    if (!set)
      throw InputError(kw.loc, fmt::format("ELSET={}", req.elset),
                       undefined_name(s, req.elset, NameKind::ElementSet, kw.name, "an element set",
                                      "define it with *ELSET in the model data"));
    req.elements = *set;
  }
  if (global)
    for (ElemId e : req.elements)
      if (element_info(s.model.mesh.elem_types[e]).family == ElementFamily::Shell) {
        s.warn(kw.loc, fmt::format("GLOBAL=YES: shell element {} ({}) reports S, E, SF and SM in "
                                   "its local shell directions (docs/theory/structural.md §4.1), "
                                   "not in global components",
                                   s.model.element_label(e),
                                   element_info(s.model.mesh.elem_types[e]).name));
        break;
      }
  req.vars =
      request_vars<ElemVar>(s, kw, elem_var, kElemVarList, {ElemVar::S}, &req.section_points);
  std::sort(req.section_points.begin(), req.section_points.end());
  if (req.vars.empty()) return; // its unknown variables were reported
  s.scratch.el_print_given = true;
  s.step.el_prints.push_back(std::move(req));
}

void handle_output(BuildState& s, const Keyword& kw) {
  s.current_field = -1;
  s.parent = Parent::HistoryOutput; // until known: sub-options of a failed
                                    // *OUTPUT are skipped
  for (const char* p : {"NUMBER INTERVAL", "TIME INTERVAL", "TIME MARKS"})
    if (const Parameter* given = kw.find(p))
      s.warn(kw.loc, fmt::format("{} on *OUTPUT is not supported by gapfem: the request writes at "
                                 "the increments FREQUENCY=n gives (every increment by default)",
                                 given->name));
  const bool history = kw.has("HISTORY") && !kw.has("FIELD");
  if (kw.has("FIELD") == kw.has("HISTORY"))
    s.warn(kw.loc, fmt::format("*OUTPUT needs FIELD or HISTORY (one of them); {}: it was read as "
                               "a field output request",
                               kw.has("FIELD") ? "both are given" : "neither is given"));
  const int variable = enum_param(kw, "VARIABLE", {"PRESELECT", "ALL"}, -1);
  s.current_history = -1;
  if (history) { // values over time (docs/results.md, "History output")
    s.parent = Parent::HistoryOutput;
    HistoryOutputRequest req;
    req.loc = kw.loc;
    req.frequency = frequency_param(kw);
    req.energies = variable >= 0; // Abaqus preselects the whole-model energies
    s.step.history_outputs.push_back(std::move(req));
    s.current_history = static_cast<int>(s.step.history_outputs.size()) - 1;
    return;
  }
  s.parent = Parent::FieldOutput;
  FieldOutputRequest req;
  req.loc = kw.loc;
  req.frequency = frequency_param(kw);
  s.scratch.field_given = true;
  s.step.field_outputs.push_back(std::move(req));
  s.current_field = static_cast<int>(s.step.field_outputs.size()) - 1;
  if (variable >= 0) s.scratch.preset_fields.emplace_back(s.current_field, variable == 1);
}

/// The members of NSET= / ELSET= of *NODE OUTPUT / *ELEMENT OUTPUT (which must name a set), or
/// nullptr when the line has none (the whole model) or its set's definition failed (`failed`).
template <bool Nodes>
const std::vector<std::int32_t>* output_set(BuildState& s, const Keyword& kw, bool& failed) {
  const char* param = Nodes ? "NSET" : "ELSET";
  failed = false;
  if (!kw.has(param)) return nullptr;
  const std::string name = set_param(s, kw, param, true);
  const auto* set = Nodes ? find_nset(s, name) : find_elset(s, name);
  if (set) return set;
  failed = s.bad_sets.count(name) > 0; // its definition failed (reported)
  if (failed) return nullptr;
  throw InputError(kw.loc, fmt::format("{}={}", param, name),
                   undefined_name(s, name, Nodes ? NameKind::NodeSet : NameKind::ElementSet,
                                  kw.name, Nodes ? "a node set" : "an element set",
                                  fmt::format("define it with *{} in the model data", param)));
}

/// Adds the variables of one *NODE OUTPUT / *ELEMENT OUTPUT line to its request, on its set.
template <typename V>
void add_field_vars(const std::vector<V>& vars, const std::vector<std::int32_t>* set,
                    std::vector<V>& all, std::vector<V>& everywhere,
                    std::vector<std::pair<V, std::vector<std::int32_t>>>& on_sets) {
  for (V v : vars) {
    add_unique(all, v);
    if (!set) {
      add_unique(everywhere, v);
      continue;
    }
    auto it =
        std::find_if(on_sets.begin(), on_sets.end(), [&](const auto& p) { return p.first == v; });
    if (it == on_sets.end()) {
      on_sets.emplace_back(v, *set);
      continue;
    }
    it->second.insert(it->second.end(), set->begin(), set->end());
    std::sort(it->second.begin(), it->second.end());
    it->second.erase(std::unique(it->second.begin(), it->second.end()), it->second.end());
  }
}

namespace {

/// A history request's *NODE OUTPUT / *ELEMENT OUTPUT line: its variables on its set's members.
/// Without a set (the whole model, which Abaqus refuses for history output) it is a warning.
template <typename V>
void add_history_vars(BuildState& s, const Keyword& kw, const std::vector<V>& vars,
                      const std::vector<std::int32_t>* set, const char* param,
                      std::vector<std::pair<V, std::vector<std::int32_t>>>& into) {
  if (!set) {
    s.warn(kw.loc, fmt::format("history output needs {}= (the values over time of a few nodes or "
                               "elements); this {} line was ignored",
                               param, kw.name));
    return;
  }
  for (V v : vars) into.emplace_back(v, *set);
}

} // namespace

void handle_node_output(BuildState& s, const Keyword& kw) {
  bool failed = false;
  const auto* set = output_set<true>(s, kw, failed);
  if (!failed && s.parent == Parent::HistoryOutput && s.current_history >= 0) {
    add_history_vars(s, kw, read_vars<NodeVar>(s, kw, node_var, kNodeVarList), set, "NSET",
                     s.step.history_outputs[s.current_history].node_vars);
    return;
  }
  if (failed || s.parent != Parent::FieldOutput || s.current_field < 0) {
    kw.mark_read(); // a failed set or request (reported), or history output (a warning)
    return;
  }
  auto& req = s.step.field_outputs[s.current_field];
  add_field_vars(read_vars<NodeVar>(s, kw, node_var, kNodeVarList), set, req.node_vars,
                 req.node_vars_everywhere, req.node_sets);
}

void handle_element_output(BuildState& s, const Keyword& kw) {
  bool failed = false;
  const auto* set = output_set<false>(s, kw, failed);
  if (!failed && s.parent == Parent::HistoryOutput && s.current_history >= 0) {
    add_history_vars(s, kw, read_vars<ElemVar>(s, kw, elem_var, kElemVarList), set, "ELSET",
                     s.step.history_outputs[s.current_history].elem_vars);
    return;
  }
  if (failed || s.parent != Parent::FieldOutput || s.current_field < 0) {
    kw.mark_read(); // a failed set or request (reported), or history output (a warning)
    return;
  }
  auto& req = s.step.field_outputs[s.current_field];
  std::vector<ElemVar> vars =
      read_vars<ElemVar>(s, kw, elem_var, kElemVarList, nullptr,
                         "a list of section points on *ELEMENT OUTPUT: the ParaView "
                         "frames hold each element's average over its points, a "
                         "shell's SNEG and SPOS sides (S_SNEG, S_SPOS) and a beam's "
                         "most stressed section point; print other section points "
                         "with *EL PRINT (a data line of section point numbers)");
  if (const auto it = std::find(vars.begin(), vars.end(), ElemVar::NFORC); it != vars.end()) {
    s.warn(kw.loc, "NFORC (element nodal forces) is not written to the ParaView frames; print it "
                   "with *EL PRINT (job.dat and job.results.json)");
    vars.erase(it);
  }
  add_field_vars(std::move(vars), set, req.elem_vars, req.elem_vars_everywhere, req.elem_sets);
}

void handle_monitor(BuildState& s, const Keyword& kw) {
  DofMonitor m;
  m.loc = kw.loc;
  m.node = param_node(s, kw, "NODE");
  const Parameter* dof = kw.find("DOF");
  if (dof) dof->integer = true;
  long long d = 0;
  DofType type{};
  if (!dof || !dof->has_value || check_integer(dof->value, 1, kMaxAbaqusDof, d) != IntCheck::Ok ||
      !dof_from_abaqus(static_cast<int>(d), type))
    throw InputError(kw.loc, fmt::format("DOF={}", dof ? dof->value : ""),
                     "give the degree of freedom to monitor: DOF=1 … 6, or 11 (temperature)");
  m.dof = static_cast<int>(d);
  m.frequency = frequency_param(kw);
  (s.in_step ? s.step.monitor : s.model_monitor) = m;
}

namespace {

/// The parameters *NODE FILE and *EL FILE share: frequency, CalculiX's OUTPUT=2D|3D, TOTALS.
FileOutputRequest file_request(BuildState& s, const Keyword& kw, bool element) {
  FileOutputRequest req;
  req.element = element;
  req.loc = kw.loc;
  req.frequency = frequency_param(kw);
  if (enum_param(kw, "OUTPUT", {"2D", "3D"}, 0) == 1 && !s.noted_keywords.insert("FRD3D").second)
    s.warn(kw.loc, "OUTPUT=3D: job.frd holds plane, axisymmetric, shell and beam elements as "
                   "they are in the deck (CalculiX's OUTPUT=2D); cgx shows them as such");
  if (kw.has("TOTALS"))
    s.warn(kw.loc, fmt::format("TOTALS on {} has no meaning in job.frd and was ignored; "
                               "column totals are printed by *NODE PRINT / *EL PRINT, TOTALS=YES",
                               kw.name));
  return req;
}

} // namespace

void handle_node_file(BuildState& s, const Keyword& kw) {
  FileOutputRequest req = file_request(s, kw, false);
  req.global = yes_no_param(kw, "GLOBAL", false);
  bool failed = false;
  if (const auto* set = output_set<true>(s, kw, failed)) {
    req.set = set_param(s, kw, "NSET", true);
    req.members = *set;
  }
  if (failed) return kw.mark_read(); // its set's definition failed (reported)
  req.node_vars = request_vars<NodeVar>(s, kw, node_var, kNodeVarList, {NodeVar::U});
  if (req.node_vars.empty()) return; // its unknown variables were reported
  s.scratch.node_file_given = true;
  s.step.file_outputs.push_back(std::move(req));
}

namespace {

/// The elements of *EL FILE: ELSET=, or (CalculiX) NSET=: the elements with a node in that set,
/// whose values job.frd holds at all their nodes (a warning says so). False when the set's
/// definition failed (reported).
bool el_file_members(BuildState& s, const Keyword& kw, FileOutputRequest& req) {
  bool failed = false;
  if (const auto* set = output_set<false>(s, kw, failed)) {
    req.set = set_param(s, kw, "ELSET", true);
    req.members = *set;
  }
  if (failed || !kw.has("NSET")) return !failed;
  const auto* nodes = output_set<true>(s, kw, failed);
  if (failed || !nodes) return !failed;
  if (!req.set.empty())
    throw InputError(kw.loc, "NSET", "give ELSET= or NSET= on *EL FILE, not both");
  req.set = set_param(s, kw, "NSET", true);
  std::vector<char> in(static_cast<std::size_t>(s.model.mesh.n_nodes()), 0);
  for (NodeId n : *nodes) in[n] = 1;
  for (ElemId e = 0; e < s.model.mesh.n_elements(); ++e)
    for (NodeId n : s.model.mesh.element_nodes(e))
      if (in[n]) {
        req.members.push_back(e);
        break;
      }
  s.warn(kw.loc, fmt::format("NSET={} on *EL FILE (CalculiX): job.frd holds the element values of "
                             "the {} elements with a node in the set, at all their nodes",
                             req.set, req.members.size()));
  return true;
}

} // namespace

namespace {
/// Why *EL FILE leaves an element variable out of job.frd.
std::string el_file_left_out(ElemVar v) {
  switch (v) {
  case ElemVar::SF:
    return "section forces (SF) are not written to job.frd (it holds values at the nodes) and "
           "were left out; print them with *EL PRINT or write them to ParaView with *ELEMENT "
           "OUTPUT";
  case ElemVar::NFORC:
    return "element nodal forces (NFORC) are not written to job.frd and were left out; print "
           "them with *EL PRINT (job.dat and job.results.json)";
  default:
    return fmt::format("{} (one value per element or per integration point, not a field at the "
                       "nodes) is not written to job.frd and was left out; print it with *EL "
                       "PRINT (job.dat and job.results.json)",
                       elem_var_name(v));
  }
}
} // namespace

void handle_el_file(BuildState& s, const Keyword& kw) {
  FileOutputRequest req = file_request(s, kw, true);
  const int pos = enum_param(
      kw, "POSITION",
      {"AVERAGED AT NODES", "NODES", "INTEGRATION POINTS", "CENTROIDAL", "INTEGRATION POINT"}, 0);
  if (pos >= 2)
    s.warn(kw.loc, fmt::format("POSITION={}: job.frd holds element output at the nodes only, so "
                               "it is written extrapolated and averaged at the nodes (Abaqus's "
                               "POSITION=AVERAGED AT NODES); *EL PRINT prints it at the points",
                               pos == 3 ? "CENTROIDAL" : "INTEGRATION POINTS"));
  if (!el_file_members(s, kw, req)) return kw.mark_read(); // its set failed (reported)
  req.elem_vars = request_vars<ElemVar>(s, kw, elem_var, "S, E, HFL, ENER", {ElemVar::S});
  for (ElemVar v : {ElemVar::SF, ElemVar::NFORC, ElemVar::ELSE, ElemVar::EVOL, ElemVar::COORD})
    if (const auto it = std::find(req.elem_vars.begin(), req.elem_vars.end(), v);
        it != req.elem_vars.end()) {
      s.warn(kw.loc, el_file_left_out(v));
      req.elem_vars.erase(it);
    }
  if (req.elem_vars.empty()) return; // its unknown variables were reported
  s.scratch.el_file_given = true;
  s.step.file_outputs.push_back(std::move(req));
}

void handle_print_control(BuildState& s, const Keyword& kw) {
  kw.mark_read();                                      // (ignored with the note below)
  if (!s.noted_keywords.insert(kw.key).second) return; // one note per keyword and deck
  s.warn(kw.loc, fmt::format("{} controls Abaqus's printed or results-file output; gapfem writes "
                             "its own job.dat, job.results.json and ParaView files, so it was "
                             "ignored (it does not change the analysis)",
                             kw.name));
}

void handle_output_suboption(BuildState& s, const Keyword& kw) {
  // *ENERGY OUTPUT in a history request: the whole-model energies (by element set or per
  // element, Abaqus's ELSET= and data lines, gapfem has not: the whole model's, with a warning);
  // in a field request these (energy, contact-pair) variables do not exist in gapfem
  kw.mark_read();
  if (s.parent == Parent::HistoryOutput && s.current_history >= 0 && kw.key == "ENERGYOUTPUT") {
    s.step.history_outputs[s.current_history].energies = true;
    if (kw.has("ELSET") || kw.has("VARIABLE"))
      s.warn(kw.loc, "gapfem writes the whole model's energies (ALLKE, ALLIE, ALLSE, ALLAE, "
                     "ALLVD, ALLFD, ALLSD, ALLKL, ALLWK, ETOTAL) as history output; energies per "
                     "element set or per element are not written");
    return;
  }
  if (s.parent != Parent::FieldOutput) {
    if (s.parent == Parent::HistoryOutput)
      s.warn(kw.loc, fmt::format("{} is not written as history output by gapfem (contact "
                                 "pairs: gap elements report through *ELEMENT OUTPUT, S and E)",
                                 kw.name));
    return;
  }
  handle_print_control(s, kw);
}

void resolve_preset_outputs(BuildState& s) {
  Step& st = s.step;
  const bool mech = st.procedure != Procedure::HeatTransfer;
  const bool thermal = is_thermal(st.procedure);
  const bool dynamic = st.procedure == Procedure::Dynamic;
  for (auto [index, all] : s.scratch.preset_fields) {
    FieldOutputRequest& req = st.field_outputs[index];
    // PRESELECT: Abaqus's default field output (U, RF, S, E; NT, HFL for thermal procedures); ALL:
    // every variable gapfem can write for the procedure
    auto node = [&](NodeVar v) {
      add_unique(req.node_vars, v);
      add_unique(req.node_vars_everywhere, v);
    };
    auto elem = [&](ElemVar v) {
      add_unique(req.elem_vars, v);
      add_unique(req.elem_vars_everywhere, v);
    };
    if (mech) {
      for (NodeVar v : {NodeVar::U, NodeVar::RF}) node(v);
      for (ElemVar v : {ElemVar::S, ElemVar::E}) elem(v);
      if (all) {
        for (NodeVar v : {NodeVar::UR, NodeVar::RM, NodeVar::CF, NodeVar::CM}) node(v);
        elem(ElemVar::SF);
      }
    }
    if (dynamic) { // Abaqus/Standard preselects V and A in dynamic steps
      for (NodeVar v : {NodeVar::V, NodeVar::A}) node(v);
      if (all)
        for (NodeVar v : {NodeVar::VR, NodeVar::AR}) node(v);
    }
    if (thermal) {
      node(NodeVar::NT);
      elem(ElemVar::HFL);
      if (all)
        for (NodeVar v : {NodeVar::RFL, NodeVar::CFL}) node(v);
    }
  }
  // a field request without any variable writes nothing: drop it and say so
  for (auto it = st.field_outputs.begin(); it != st.field_outputs.end();) {
    if (it->node_vars.empty() && it->elem_vars.empty()) {
      s.warn(it->loc, "this *OUTPUT, FIELD request has no variables (add VARIABLE=PRESELECT or "
                      "*NODE OUTPUT / *ELEMENT OUTPUT lines) and was ignored");
      it = st.field_outputs.erase(it);
    } else {
      ++it;
    }
  }
}

void check_rate_outputs(BuildState& s, Step& st) {
  if (st.procedure == Procedure::Dynamic) return;
  // V, VR, A, AR requested (or carried over from a dynamic step) where there are no rates: the
  // requests stay (a later dynamic step may inherit them) and the writers leave them out
  std::vector<NodeVar> asked;
  const SourceLocation* where = nullptr;
  auto note = [&](const std::vector<NodeVar>& vars, const SourceLocation& loc) {
    for (NodeVar v : vars) {
      if (!is_rate_var(v)) continue;
      add_unique(asked, v);
      if (!where) where = &loc;
    }
  };
  for (const NodePrintRequest& r : st.node_prints) note(r.vars, r.loc);
  for (const FieldOutputRequest& r : st.field_outputs) note(r.node_vars, r.loc);
  for (const FileOutputRequest& r : st.file_outputs) note(r.node_vars, r.loc);
  if (asked.empty()) return;
  std::string names;
  for (NodeVar v : asked) names += fmt::format("{}{}", names.empty() ? "" : ", ", node_var_name(v));
  s.warn(*where,
         fmt::format("{} {} output of dynamic steps; step {} is *{}: not written", names,
                     asked.size() == 1 ? "is" : "are", st.number, procedure_name(st.procedure)));
}

} // namespace gapfem::inp
