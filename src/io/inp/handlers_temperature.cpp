// *TEMPERATURE (predefined temperatures and their gradients) and *CONTACT INTERFERENCE, merged
// into the step's active lists as the other loads are (handlers_loads.cpp, load_merge.hpp).
#include "io/inp/handlers.hpp"
#include "io/inp/load_merge.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <tuple>

namespace gapfem::inp {

void handle_temperature(BuildState& s, const Keyword& kw) {
  reject_param(kw, "FILE", "give the temperatures on data lines (node or node set, value)");
  const int amplitude = amplitude_param(s, kw);
  std::vector<NodalTemperature> entries;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(4, "node or node set, temperature, gradients (shells: dT/dn; beams: dT/dx2, dT/dx1)");
    const double value = r.real(1, "temperature");
    const std::array<double, 2> gradient{r.real_or(2, 0.0, "first temperature gradient"),
                                         r.real_or(3, 0.0, "second temperature gradient")};
    if (gradient[0] != 0.0 || gradient[1] != 0.0) s.model.has_temperature_gradients = true;
    for (NodeId n : resolve_nodes(s, r, 0)) {
      NodalTemperature t;
      t.node = n;
      t.value = value;
      t.gradient = gradient;
      t.amplitude = amplitude;
      t.loc = r.loc();
      entries.push_back(t);
    }
  });
  merge(
      s.step.temperatures, entries, op_new(kw), [](const NodalTemperature&) { return true; },
      [](const NodalTemperature& t) { return t.node; });
}

namespace {
/// Gradients (values 2, 3 of *TEMPERATURE) act on shells and beams; at a node of other elements
/// only they would be dropped, so that is reported (once per data line).
void check_temperature_gradients(BuildState& s) {
  const Mesh& mesh = s.model.mesh;
  std::vector<std::uint8_t> sectioned;
  std::vector<std::pair<std::string, int>> reported;
  for (const NodalTemperature& t : s.step.temperatures) {
    if (t.propagated || (t.gradient[0] == 0.0 && t.gradient[1] == 0.0)) continue;
    if (sectioned.empty()) {
      sectioned.assign(static_cast<std::size_t>(mesh.n_nodes()), 0);
      for (ElemId e = 0; e < mesh.n_elements(); ++e) {
        const ElementFamily f = element_info(mesh.elem_types[e]).family;
        if (f == ElementFamily::Shell || f == ElementFamily::Beam)
          for (NodeId n : mesh.element_nodes(e)) sectioned[n] = 1;
      }
    }
    const auto where = std::pair(t.loc.file, t.loc.line);
    if (sectioned[t.node] || std::find(reported.begin(), reported.end(), where) != reported.end())
      continue;
    reported.push_back(where);
    s.warn(t.loc, fmt::format("node {} has no shell or beam element, so the temperature gradients "
                              "given for it (values 2 and 3) have no effect there",
                              s.model.node_label(t.node)));
  }
}
} // namespace

void check_predefined_temperatures(BuildState& s) {
  check_temperature_gradients(s);
  // The Abaqus Analysis User's Guide ("Predefined Fields", Restrictions; 2023:
  // docs.software.vt.edu/abaqusv2023/English/SIMACAEPRCRefMap/simaprc-c-fields.htm) says not to
  // give predefined temperatures in heat transfer and fully coupled temperature-displacement
  // analyses but to prescribe the temperature DOF 11 with a boundary condition; the CalculiX
  // manual (*TEMPERATURE) says the same. gapfem applies it per node: a node with DOF 11 is
  // rejected, while nodes of purely mechanical elements of a coupled step may still take a
  // predefined temperature. A *STATIC step has no node with DOF 11 (thermal_step.hpp), so its
  // *TEMPERATURE is not checked.
  const Step& st = s.step;
  if (!is_thermal(st.procedure) || st.temperatures.empty()) return;
  // Entries carried over from an earlier heat transfer or coupled step were reported there.
  const Step* prev = s.model.steps.empty() ? nullptr : &s.model.steps.back();
  const bool prev_checked = prev && is_thermal(prev->procedure);
  const Mesh& mesh = s.model.mesh;
  std::vector<ElemId> carrier(static_cast<std::size_t>(mesh.n_nodes()), -1);
  for (ElemId e = 0; e < mesh.n_elements(); ++e)
    if (element_info(mesh.elem_types[e]).temperature)
      for (NodeId n : mesh.element_nodes(e))
        if (carrier[n] < 0) carrier[n] = e;
  std::vector<std::pair<std::string, int>> reported; // one error per *TEMPERATURE data line
  for (const NodalTemperature& t : st.temperatures) {
    if ((t.propagated && prev_checked) || carrier[t.node] < 0) continue;
    const auto where = std::pair(t.loc.file, t.loc.line);
    if (std::find(reported.begin(), reported.end(), where) != reported.end()) continue;
    reported.push_back(where);
    const ElemId e = carrier[t.node];
    std::string message = fmt::format(
        "this node carries the temperature DOF 11 (element {} is {} element), so in a *{} step "
        "its temperature is a solution variable, not a predefined field; prescribe it with "
        "*BOUNDARY on DOF 11 instead (node, 11, 11, temperature)",
        s.model.element_label(e), with_article(element_info(mesh.elem_types[e]).name),
        procedure_name(st.procedure));
    if (t.propagated)
      message += fmt::format(", and remove this *TEMPERATURE from step {} with *TEMPERATURE, "
                             "OP=NEW",
                             st.number);
    s.error(t.loc, fmt::format("node {}", s.model.node_label(t.node)), message);
  }
}

void handle_contact_interference(BuildState& s, const Keyword& kw) {
  const int type = enum_param(kw, "TYPE", {"ELEMENT", "CONTACT PAIR"}, -1);
  if (type < 0) throw InputError(kw.loc, "", "TYPE=ELEMENT is required (gap-element interference)");
  if (type == 1)
    throw InputError(kw.loc, "TYPE=CONTACT PAIR",
                     "gapfem has no contact pairs; use TYPE=ELEMENT with gap elements");
  const bool shrink = kw.has("SHRINK");
  if (shrink && s.step.number != 1)
    throw InputError(kw.loc, "SHRINK", "SHRINK can be used in the first step only (Abaqus rule)");
  int amplitude = amplitude_param(s, kw);
  if (shrink && amplitude >= 0) {
    s.warn(kw.loc,
           "AMPLITUDE is ignored with SHRINK: the interference is removed linearly over the step");
    amplitude = -1;
  }
  std::vector<InterferenceEntry> entries;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    double v = 0.0;
    if (shrink) {
      r.at_most(1, "element or element set (SHRINK takes no value)");
    } else {
      r.at_most(2, "element or element set, allowable interference v");
      v = r.real(1, "allowable interference v");
    }
    for (ElemId e : resolve_elements(s, r, 0)) {
      const ElementType t = s.model.mesh.elem_types[e];
      if (element_info(t).family != ElementFamily::Gap || t == ElementType::DGAP)
        r.fail(elem_entity(s, e), "*CONTACT INTERFERENCE, TYPE=ELEMENT applies to mechanical gap "
                                  "elements (GAPUNI, GAPCYL, GAPSPHER, GAPUNIT) only");
      InterferenceEntry i;
      i.elem = e;
      i.allowance = v;
      i.shrink = shrink;
      i.amplitude = amplitude;
      i.loc = r.loc();
      entries.push_back(i);
    }
  });
  merge(
      s.step.interference, entries, op_new(kw), [](const InterferenceEntry&) { return true; },
      [](const InterferenceEntry& i) { return i.elem; });
}

} // namespace gapfem::inp
