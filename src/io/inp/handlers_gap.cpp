// Gap contact keywords: *GAP and its sub-options *SURFACE BEHAVIOR, *FRICTION, *CONTACT DAMPING,
// *GAP CONDUCTANCE, *GAP RADIATION, *GAP HEAT GENERATION (spec gap-elements.md §2.2, §2.3, §3,
// §4). The checks that need the element types of the ELSET run in model_validate.cpp.
#include "io/inp/handlers.hpp"

#include <fmt/format.h>

namespace gapfem::inp {
namespace {

/// The data lines that hold more than blanks (a line of only commas counts: its fields are blank).
std::vector<const DataLine*> lines_of(const Keyword& kw) {
  std::vector<const DataLine*> out;
  for (const auto& d : kw.data)
    if (!d.blank()) out.push_back(&d);
  return out;
}

GapSection& current_gap(BuildState& s) {
  return s.model.gap_sections[s.current_gap];
}

void once(const Keyword& kw, bool given, const GapSection& gap) {
  if (given)
    throw InputError(kw.loc, fmt::format("*GAP, ELSET={}", gap.elset),
                     fmt::format("{} is given twice for this *GAP; keep one", kw.name));
}

/// At most one data line; returns it or nullptr.
const DataLine* single_line(BuildState& s, const Keyword& kw, const char* what) {
  const auto lines = lines_of(kw);
  if (lines.size() > 1)
    throw InputError(
        s.loc(kw, *lines[1]), "",
        fmt::format("{} takes one data line ({}); remove the extra lines", kw.name, what));
  return lines.empty() ? nullptr : lines[0];
}

void no_data(BuildState& s, const Keyword& kw, const char* why) {
  const auto lines = lines_of(kw);
  if (!lines.empty()) throw InputError(s.loc(kw, *lines[0]), "", why);
}

} // namespace

void handle_gap(BuildState& s, const Keyword& kw) {
  s.current_gap = -1;
  GapSection gap;
  gap.elset = set_param(s, kw, "ELSET", true);
  gap.loc = kw.loc;
  const DataLine* line = single_line(s, kw, "d, n_x, n_y, n_z, A [, k, f]");
  if (!line)
    throw InputError(
        kw.loc, fmt::format("ELSET={}", gap.elset),
        "the data line is missing; give d, n_x, n_y, n_z, A (clearance, direction cosines, area)");
  const FieldReader r = s.reader(kw, *line);
  r.at_most(7, "d, n_x, n_y, n_z, A, and for CalculiX penalty gaps k, f");
  gap.d = r.real_or(0, 0.0, "clearance d");
  gap.direction = {r.real_or(1, 0.0, "n_x"), r.real_or(2, 0.0, "n_y"), r.real_or(3, 0.0, "n_z")};
  gap.direction_given = gap.direction[0] != 0 || gap.direction[1] != 0 || gap.direction[2] != 0;
  const double area = r.real_or(4, 0.0, "area A");
  if (area < 0)
    r.fail("field 5 (area A)", fmt::format("the area must not be negative, not {}", area));
  if (area > 0) {
    gap.area = area;
    gap.area_given = true;
  } else {
    gap.area = 1.0;
    s.warn(r.loc(), fmt::format("ELSET={}: the area (field 5) is blank or zero; gapfem uses A = 1, "
                                "so the contact pressure S11 equals the gap force",
                                gap.elset));
  }
  // CalculiX extension (spec §2.2, §0b): field 6 penalty stiffness, field 7 tension at infinity
  if (auto k = r.opt_real(5, "penalty stiffness k")) {
    if (*k <= 0) r.fail("field 6 (penalty stiffness k)", "the stiffness must be positive");
    gap.ccx_penalty = true;
    gap.ccx_stiffness = *k;
  }
  if (auto f = r.opt_real(6, "tension at infinite opening f")) {
    if (*f < 0) r.fail("field 7 (tension f)", "the tension force must not be negative");
    gap.ccx_tension = *f;
  }
  s.model.gap_sections.push_back(std::move(gap));
  s.current_gap = static_cast<int>(s.model.gap_sections.size()) - 1;
}

void handle_surface_behavior(BuildState& s, const Keyword& kw) {
  if (s.current_gap < 0) return; // the *GAP line itself was in error
  GapSection& gap = current_gap(s);
  once(kw, gap.behavior.given, gap);
  SurfaceBehavior b;
  b.given = true;
  b.loc = kw.loc;
  const int law =
      enum_param(kw, "PRESSURE-OVERCLOSURE", {"HARD", "EXPONENTIAL", "LINEAR", "TABULAR"}, 0);
  b.law = static_cast<PressureOverclosure>(law); // same order as the enum
  b.no_separation = kw.has("NO SEPARATION");
  int n_methods = 0;
  for (auto [name, m] : {std::pair{"PENALTY", ContactMethod::Penalty},
                         std::pair{"AUGMENTED LAGRANGE", ContactMethod::AugmentedLagrange},
                         std::pair{"DIRECT", ContactMethod::Direct}})
    if (kw.has(name)) {
      b.method = m;
      ++n_methods;
    }
  if (n_methods > 1)
    throw InputError(kw.loc, "",
                     "PENALTY, AUGMENTED LAGRANGE and DIRECT exclude each other; give one of them");
  if (b.no_separation && b.law != PressureOverclosure::Hard)
    throw InputError(kw.loc, "NO SEPARATION",
                     "NO SEPARATION cannot be combined with a softened PRESSURE-OVERCLOSURE law "
                     "(Abaqus/Standard rule); remove one of the two parameters");
  if (b.law != PressureOverclosure::Hard &&
      (b.method == ContactMethod::Penalty || b.method == ContactMethod::AugmentedLagrange))
    throw InputError(kw.loc, "",
                     "PENALTY and AUGMENTED LAGRANGE apply to hard contact only; remove the "
                     "parameter or the PRESSURE-OVERCLOSURE law");
  // Data lines per law, from the Abaqus Keywords Reference, *SURFACE BEHAVIOR (v6.5 ch18abk47,
  // v6.6 §18.47, 2017 simakey-r-surfacebehavior):
  //   PENALTY / AUGMENTED LAGRANGE (optional line): penalty stiffness (blank = default),
  //     clearance at which the pressure is zero (default 0), scale factor of the default stiffness;
  //   EXPONENTIAL: c0 (clearance at zero pressure), p0 (pressure at zero clearance), [K_max];
  //   LINEAR: slope of the pressure-overclosure curve (> 0);
  //   TABULAR: pressure, overclosure; ascending overclosure; at least two lines; extrapolated
  //     beyond the last point with the last slope.
  switch (b.law) {
  case PressureOverclosure::Hard:
    if (b.method == ContactMethod::Penalty || b.method == ContactMethod::AugmentedLagrange) {
      if (const DataLine* line = single_line(s, kw, "penalty stiffness")) {
        const FieldReader r = s.reader(kw, *line);
        r.at_most(3, "penalty stiffness, clearance at zero pressure, stiffness scale factor");
        b.penalty_stiffness = r.real_or(0, 0.0, "penalty stiffness");
        if (b.penalty_stiffness < 0)
          r.fail("field 1 (penalty stiffness)", "the penalty stiffness must be positive");
        if (r.real_or(1, 0.0, "clearance at zero pressure") != 0.0)
          r.fail("field 2 (clearance at zero pressure)",
                 "a non-zero clearance for penalty contact is not supported by gapfem; leave the "
                 "field blank");
        if (r.real_or(2, 1.0, "scale factor") != 1.0)
          r.fail("field 3 (scale factor)", "scaling the default penalty stiffness is not supported "
                                           "by gapfem; give the stiffness itself in field 1");
      }
    } else {
      no_data(s, kw, "hard contact with direct enforcement takes no data lines; remove them");
    }
    break;
  case PressureOverclosure::Exponential: {
    const DataLine* line = single_line(s, kw, "c0, p0");
    if (!line)
      throw InputError(kw.loc, "",
                       "EXPONENTIAL needs a data line: c0 (clearance at zero pressure), p0 "
                       "(pressure at zero clearance)");
    const FieldReader r = s.reader(kw, *line);
    r.at_most(3, "c0, p0, maximum stiffness");
    b.c0 = r.real(0, "clearance c0");
    b.p0 = r.real(1, "pressure p0");
    b.max_stiffness = r.real_or(2, 0.0, "maximum stiffness");
    if (b.c0 <= 0) r.fail("field 1 (clearance c0)", "c0 must be positive");
    if (b.p0 <= 0) r.fail("field 2 (pressure p0)", "p0 must be positive");
    if (b.max_stiffness < 0) r.fail("field 3 (maximum stiffness)", "must not be negative");
    break;
  }
  case PressureOverclosure::Linear: {
    const DataLine* line = single_line(s, kw, "slope");
    if (!line)
      throw InputError(kw.loc, "",
                       "LINEAR needs a data line with the slope (pressure per overclosure)");
    const FieldReader r = s.reader(kw, *line);
    r.at_most(1, "slope");
    b.slope = r.real(0, "slope");
    if (b.slope <= 0) r.fail("field 1 (slope)", "the slope must be positive");
    break;
  }
  case PressureOverclosure::Tabular: {
    for_each_line(s, kw, [&](const DataLine& line) {
      const FieldReader r = s.reader(kw, line);
      r.at_most(2, "pressure, overclosure");
      const double p = r.real(0, "pressure");
      const double g = r.real(1, "overclosure");
      if (p < 0) r.fail("field 1 (pressure)", "pressures must not be negative");
      if (!b.table_g.empty() && !(g > b.table_g.back()))
        r.fail("field 2 (overclosure)",
               fmt::format("overclosures must increase from line to line; {} follows {}", g,
                           b.table_g.back()));
      b.table_p.push_back(p);
      b.table_g.push_back(g);
    });
    if (b.table_p.size() < 2)
      throw InputError(kw.loc, "", "TABULAR needs at least two data lines (pressure, overclosure)");
    break;
  }
  }
  gap.behavior = std::move(b);
}

FrictionSpec read_friction(BuildState& s, const Keyword& kw) {
  reject_param(kw, "EXPONENTIAL DECAY", "give a constant (or tabulated) friction coefficient");
  reject_param(kw, "ANISOTROPIC", "gap friction is isotropic");
  reject_param(kw, "USER", "user friction subroutines are not available");
  if (const auto dep = dependencies_param(kw); dep > 0)
    throw InputError(kw.loc, fmt::format("DEPENDENCIES={}", dep),
                     "field-variable dependencies are not supported by gapfem; tabulate the "
                     "friction coefficient against slip rate, contact pressure and temperature "
                     "only, and remove DEPENDENCIES");
  FrictionSpec f;
  f.given = true;
  f.loc = kw.loc;
  f.rough = kw.has("ROUGH");
  f.lagrange = kw.has("LAGRANGE");
  if (auto v = real_param(kw, "ELASTIC SLIP")) {
    if (*v <= 0)
      throw InputError(kw.loc, param_text(kw, "ELASTIC SLIP"), "the elastic slip must be positive");
    f.elastic_slip = *v;
  }
  if (auto v = real_param(kw, "SLIP TOLERANCE")) {
    if (*v <= 0)
      throw InputError(kw.loc, param_text(kw, "SLIP TOLERANCE"),
                       "the slip tolerance must be positive");
    f.slip_tolerance = *v;
  }
  if (auto v = real_param(kw, "TAUMAX")) {
    if (*v <= 0)
      throw InputError(kw.loc, param_text(kw, "TAUMAX"), "the limit shear stress must be positive");
    f.taumax = *v;
  }
  if (f.elastic_slip && kw.has("SLIP TOLERANCE"))
    throw InputError(kw.loc, "", "ELASTIC SLIP and SLIP TOLERANCE exclude each other; give one");
  if (f.lagrange && (f.elastic_slip || kw.has("SLIP TOLERANCE")))
    throw InputError(kw.loc, "LAGRANGE",
                     "LAGRANGE enforces sticking exactly and cannot be combined with ELASTIC SLIP "
                     "or SLIP TOLERANCE");
  if (f.rough) {
    if (!lines_of(kw).empty())
      s.warn(kw.loc, "ROUGH friction takes no data lines; the friction coefficients were ignored");
    kw.mark_read(); // (ignored with the warning above)
    return f;
  }
  const int failed = for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(4, "friction coefficient, slip rate, contact pressure, temperature");
    FrictionSpec::Row row;
    row.mu = r.real(0, "friction coefficient");
    if (row.mu < 0) r.fail("field 1 (friction coefficient)", "must not be negative");
    row.slip_rate = r.real_or(1, 0.0, "slip rate");
    row.pressure = r.real_or(2, 0.0, "contact pressure");
    row.temperature = r.real_or(3, 0.0, "temperature");
    std::size_t used = line.fields.size();
    while (used > 0 && line.fields[used - 1].empty()) --used;
    f.n_columns = std::max(f.n_columns, static_cast<int>(used));
    f.rows.push_back(row);
  });
  if (f.rows.empty() && failed == 0)
    throw InputError(kw.loc, "",
                     "the friction coefficient is missing; add a data line with mu (or use ROUGH)");
  return f;
}

void handle_friction(BuildState& s, const Keyword& kw) {
  if (s.parent == Parent::ChangeFriction) {
    if (s.current_change < 0) return;
    FrictionChange& change = s.step.friction_changes[s.current_change];
    if (change.friction.given)
      throw InputError(kw.loc, "", "*FRICTION is given twice after this *CHANGE FRICTION");
    change.friction = read_friction(s, kw);
    return;
  }
  if (s.current_gap < 0) return;
  GapSection& gap = current_gap(s);
  once(kw, gap.friction.given, gap);
  gap.friction = read_friction(s, kw);
}

void handle_contact_damping(BuildState& s, const Keyword& kw) {
  if (s.current_gap < 0) return;
  GapSection& gap = current_gap(s);
  once(kw, gap.damping.given, gap);
  enum_param(kw, "DEFINITION", {"DAMPING COEFFICIENT"}, 0);
  ContactDampingSpec d;
  d.given = true;
  d.loc = kw.loc;
  d.tangent_fraction = real_param(kw, "TANGENT FRACTION").value_or(0.0);
  if (d.tangent_fraction < 0)
    throw InputError(kw.loc, param_text(kw, "TANGENT FRACTION"),
                     "the tangent fraction must not be negative");
  const DataLine* line = single_line(s, kw, "damping coefficient, clearance, fraction");
  if (!line)
    throw InputError(
        kw.loc, "",
        "the damping coefficient is missing; add a data line: coefficient, clearance c0, fraction");
  const FieldReader r = s.reader(kw, *line);
  r.at_most(3, "damping coefficient, clearance c0, fraction");
  d.coefficient = r.real(0, "damping coefficient");
  d.clearance = r.real_or(1, 0.0, "clearance c0");
  d.fraction = r.real_or(2, 0.0, "fraction");
  if (d.coefficient < 0) r.fail("field 1 (damping coefficient)", "must not be negative");
  if (d.clearance < 0) r.fail("field 2 (clearance c0)", "must not be negative");
  if (d.fraction < 0 || d.fraction > 1)
    r.fail("field 3 (fraction of c0 over which the damping is constant)",
           "must lie between 0 (the damping falls off linearly from zero clearance to c0) and 1 "
           "(it is constant up to c0)");
  gap.damping = d;
}

void handle_gap_conductance(BuildState& s, const Keyword& kw) {
  if (s.current_gap < 0) return;
  GapSection& gap = current_gap(s);
  // Up to two definitions: one against clearance and one against pressure (PRESSURE).
  const bool pressure = kw.has("PRESSURE");
  const bool second = gap.conductance.given && gap.conductance.pressure != pressure;
  if (gap.conductance.given && !second)
    throw InputError(kw.loc, "*GAP, ELSET=" + gap.elset,
                     fmt::format("a {}-dependent *GAP CONDUCTANCE was already given for this *GAP "
                                 "(at line {}); give at most one against clearance and one against "
                                 "pressure (PRESSURE)",
                                 pressure ? "pressure" : "clearance", gap.conductance.loc.line));
  if (gap.conductance_pressure.given)
    throw InputError(
        kw.loc, "*GAP, ELSET=" + gap.elset,
        "this *GAP already has both a clearance- and a pressure-dependent conductance");
  reject_param(kw, "USER", "tabulate the conductance on data lines");
  if (const auto dep = dependencies_param(kw); dep > 0)
    throw InputError(kw.loc, fmt::format("DEPENDENCIES={}", dep),
                     "field-variable dependencies are not supported by gapfem; tabulate the "
                     "conductance against clearance (or pressure, with PRESSURE) and temperature "
                     "only, and remove DEPENDENCIES");
  GapConductanceSpec c;
  c.given = true;
  c.loc = kw.loc;
  c.pressure = kw.has("PRESSURE");
  const char* xname = c.pressure ? "pressure" : "clearance";
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(4, fmt::format("conductance, {}, temperature, mass flow rate", xname));
    GapConductanceSpec::Row row;
    row.k = r.real(0, "conductance");
    row.x = r.real(1, xname);
    row.temperature = r.real_or(2, 0.0, "temperature");
    row.mass_flow = r.real_or(3, 0.0, "mass flow rate");
    if (row.k < 0) r.fail("field 1 (conductance)", "must not be negative");
    if (!r.blank(2)) c.temperature_dependent = true;
    if (!c.rows.empty() && c.rows.back().temperature == row.temperature &&
        !(row.x > c.rows.back().x))
      r.fail(fmt::format("field 2 ({})", xname),
             fmt::format("within one temperature the {} values must increase; {} follows {}", xname,
                         row.x, c.rows.back().x));
    c.rows.push_back(row);
  });
  if (c.rows.size() < 2)
    throw InputError(
        kw.loc, "",
        fmt::format(
            "at least two data lines (conductance, {}) are required to tabulate the conductance",
            xname));
  if (!second) {
    gap.conductance = std::move(c);
  } else if (pressure) {
    gap.conductance_pressure = std::move(c);
  } else {
    // the clearance table came second: keep the convention "conductance = clearance table"
    gap.conductance_pressure = std::move(gap.conductance);
    gap.conductance = std::move(c);
  }
}

void handle_gap_radiation(BuildState& s, const Keyword& kw) {
  if (s.current_gap < 0) return;
  GapSection& gap = current_gap(s);
  once(kw, gap.radiation.given, gap);
  GapRadiationSpec rad;
  rad.given = true;
  rad.loc = kw.loc;
  const auto lines = lines_of(kw);
  if (lines.size() < 2)
    throw InputError(kw.loc, "",
                     "give the emissivities on line 1 (eps_A, eps_B) and at least one line of view "
                     "factor F, clearance d");
  {
    const FieldReader r = s.reader(kw, *lines[0]);
    r.at_most(2, "emissivity of side A, emissivity of side B");
    rad.emissivity_a = r.real(0, "emissivity A");
    rad.emissivity_b = r.real(1, "emissivity B");
    for (int i = 0; i < 2; ++i) {
      const double e = i == 0 ? rad.emissivity_a : rad.emissivity_b;
      if (e <= 0 || e > 1)
        r.fail(fmt::format("field {} (emissivity)", i + 1),
               fmt::format("emissivities must lie in (0, 1], not {}", e));
    }
  }
  for (std::size_t i = 1; i < lines.size(); ++i) {
    try {
      const FieldReader r = s.reader(kw, *lines[i]);
      r.at_most(2, "view factor F, clearance d");
      const double f = r.real(0, "view factor");
      const double d = r.real_or(1, 0.0, "clearance");
      if (f < 0 || f > 1) r.fail("field 1 (view factor)", "the view factor must lie in [0, 1]");
      if (!rad.clearance.empty() && !(d > rad.clearance.back()))
        r.fail("field 2 (clearance)", "clearances must increase from line to line");
      rad.view_factor.push_back(f);
      rad.clearance.push_back(d);
    } catch (const InputError& e) {
      s.diag.error(e);
    }
  }
  gap.radiation = std::move(rad);
}

void handle_gap_heat_generation(BuildState& s, const Keyword& kw) {
  if (s.current_gap < 0) return;
  GapSection& gap = current_gap(s);
  once(kw, gap.heat_generation.given, gap);
  GapHeatGenerationSpec h;
  h.given = true;
  h.loc = kw.loc;
  if (const DataLine* line = single_line(s, kw, "eta, f")) {
    const FieldReader r = s.reader(kw, *line);
    r.at_most(2, "fraction eta of dissipated energy converted to heat, weighting f");
    h.eta = r.real_or(0, 1.0, "eta");
    h.fraction = r.real_or(1, 0.5, "weighting f");
    if (h.eta < 0) r.fail("field 1 (eta)", "must not be negative");
    if (h.fraction < 0 || h.fraction > 1) r.fail("field 2 (f)", "must lie between 0 and 1");
  }
  gap.heat_generation = h;
}

} // namespace gapfem::inp
