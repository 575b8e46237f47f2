// *DASHPOT (DASHPOT1, DASHPOT2, DASHPOTA): Abaqus Keywords Reference, *DASHPOT,
// https://abaqus-docs.mit.edu/2017/English/SIMACAEKEYRefMap/simakey-r-dashpot.htm. The behaviour
// is kept in a SpringSection (dashpot = true) next to the *SPRING ones: the same first data line
// (the DOFs, blank for DASHPOTA; checked with the element types, model_validate.cpp), the same
// element binding. Decisions (docs/theory/dynamics.md, "Dashpots and point-element damping"):
// a negative coefficient is refused (the dashpot would feed energy in); the frequency column is
// for steady-state dynamics, which gapfem does not have (a value there is refused, a blank
// accepted); NONLINEAR takes one table (force, relative velocity) in strictly ascending velocity,
// without temperature dependence; ORIENTATION= (DASHPOT1/2 only) makes the DOFs local
// (orientation.cpp). *SPRING, NONLINEAR reads its (force, relative displacement) table here too.
#include "io/inp/handlers.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace gapfem::inp {
namespace {

/// Linear: rows `c[, frequency[, temperature]]` into a table of c keyed by temperature.
PropertyTable read_coefficients(BuildState& s, const Keyword& kw, std::span<const DataLine> rows,
                                const std::string& entity) {
  struct Row {
    double c, t;
    SourceLocation loc;
  };
  std::vector<Row> list;
  for (const DataLine& line : rows) {
    if (line.empty()) continue;
    const FieldReader r = s.reader(kw, line);
    r.at_most(3, "dashpot coefficient, frequency, temperature");
    const double c = r.real(0, "dashpot coefficient");
    if (c < 0.0)
      r.fail(entity, fmt::format("the dashpot coefficient must not be negative, not {} (a "
                                 "negative coefficient would feed energy into the model)",
                                 c));
    if (!r.blank(1))
      r.fail(entity, "field 2 (frequency) is for steady-state dynamics, which gapfem does not "
                     "have; leave it blank");
    list.push_back({c, r.real_or(2, 0.0, "temperature"), r.loc()});
  }
  std::stable_sort(list.begin(), list.end(), [](const Row& a, const Row& b) { return a.t < b.t; });
  PropertyTable table;
  table.n_values = 1;
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (i > 0 && list[i].t == list[i - 1].t)
      throw InputError(list[i].loc, entity,
                       fmt::format("two data lines are given for temperature {}; give each "
                                   "temperature once (a blank temperature means 0)",
                                   list[i].t));
    table.values.push_back(list[i].c);
    table.keys.push_back(list[i].t);
  }
  return table;
}

/// NONLINEAR: rows `force, relative velocity` (dashpot) or `force, relative displacement`
/// (spring), the second strictly ascending, at least two.
void read_table(BuildState& s, const Keyword& kw, std::span<const DataLine> rows,
                const std::string& entity, SpringSection& sec) {
  const char* x = sec.dashpot ? "relative velocity" : "relative displacement";
  const char* what = sec.dashpot ? "dashpot" : "spring";
  SourceLocation last = kw.loc;
  for (const DataLine& line : rows) {
    if (line.empty()) continue;
    const FieldReader r = s.reader(kw, line);
    r.at_most(3, fmt::format("force, {}, temperature", x));
    const double F = r.real(0, "force");
    const double w = r.real(1, x);
    if (!r.blank(2))
      r.fail(entity, fmt::format("temperature-dependent nonlinear {}s are not in gapfem; give one "
                                 "table of force and {} without field 3",
                                 what, x));
    if (!sec.relative.empty() && !(w > sec.relative.back()))
      r.fail(entity,
             fmt::format("the relative {} must increase from line to line; {} follows {}",
                         sec.dashpot ? "velocities" : "displacements", w, sec.relative.back()));
    sec.force.push_back(F);
    sec.relative.push_back(w);
    last = r.loc();
  }
  if (sec.relative.size() < 2)
    throw InputError(last, entity,
                     fmt::format("a nonlinear {} needs at least two (force, {}) lines; give the "
                                 "force over the range of {} it will see",
                                 what, x, sec.dashpot ? "velocities" : "displacements"));
}

} // namespace

void read_nonlinear_spring(BuildState& s, const Keyword& kw, SpringSection sec) {
  const std::string entity = fmt::format("ELSET={}", sec.elset);
  if (kw.data.empty())
    throw InputError(kw.loc, entity,
                     "data lines are missing: line 1 gives the DOF(s) (blank for SPRINGA), the "
                     "following lines force and relative displacement");
  const std::span<const DataLine> rows(kw.data.data() + 1, kw.data.size() - 1);
  read_table(s, kw, rows, entity, sec);
  s.model.spring_sections.push_back(std::move(sec));
  kw.data[0].read = true; // (read by check_spring once the element types are known)
  s.spring_dof_line.push_back(kw.data[0]);
}

void handle_dashpot(BuildState& s, const Keyword& kw) {
  reject_param(kw, "RTOL", "RTOL is an Abaqus/Explicit parameter; remove it");
  if (const auto dep = dependencies_param(kw); dep > 0)
    throw InputError(kw.loc, fmt::format("DEPENDENCIES={}", dep),
                     "field-variable dependencies are not supported by gapfem; tabulate the "
                     "coefficient against temperature only");
  SpringSection sec;
  sec.dashpot = true;
  sec.nonlinear = kw.has("NONLINEAR");
  sec.elset = set_param(s, kw, "ELSET", true);
  sec.loc = kw.loc;
  if (kw.has("ORIENTATION")) // (resolved with the element types: orientation.cpp)
    sec.orientation = s.set_name(name_param(kw, "ORIENTATION", true));
  const std::string entity = fmt::format("ELSET={}", sec.elset);
  if (kw.data.empty())
    throw InputError(kw.loc, entity,
                     sec.nonlinear ? "data lines are missing: line 1 gives the DOF(s) (blank for "
                                     "DASHPOTA), the following lines force and relative velocity"
                                   : "data lines are missing: line 1 gives the DOF(s) (blank for "
                                     "DASHPOTA), the second line the dashpot coefficient");
  const std::span<const DataLine> rows(kw.data.data() + 1, kw.data.size() - 1);
  bool any_row = false;
  for (const auto& d : rows) any_row = any_row || !d.empty();
  if (!any_row)
    throw InputError(s.loc(kw, kw.data[0]), entity,
                     sec.nonlinear ? "the force-velocity table is missing; give it from the second "
                                     "data line on (the first line holds the DOFs, blank for "
                                     "DASHPOTA)"
                                   : "the dashpot coefficient is missing; give it on the second "
                                     "data line (the first line holds the DOFs, blank for "
                                     "DASHPOTA)");
  if (sec.nonlinear)
    read_table(s, kw, rows, entity, sec);
  else
    sec.stiffness = read_coefficients(s, kw, rows, entity);
  s.model.spring_sections.push_back(std::move(sec));
  kw.data[0].read = true; // (read by check_spring once the element types are known)
  s.spring_dof_line.push_back(kw.data[0]);
}

} // namespace gapfem::inp
