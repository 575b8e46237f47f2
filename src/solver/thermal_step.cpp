#include "solver/thermal_step.hpp"

#include "fem/element_gather.hpp"
#include "model/model.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace gapfem {

namespace {

/// The stress/displacement type with the same shape as a heat-transfer or coupled type ("" when
/// there is no obvious one): C3D8T -> C3D8, GAPUNIT -> GAPUNI, DC3D8 -> C3D8, DS4 -> S4.
std::string stress_twin(std::string_view t, bool coupled) {
  if (coupled && t.ends_with('T')) return std::string(t.substr(0, t.size() - 1));
  if (t.starts_with("DC3D")) return std::string(t.substr(1)); // DC3D8 -> C3D8
  if (t.starts_with("DS")) return std::string(t.substr(1));
  if (t == "DGAP") return "GAPUNI";
  return {};
}

/// The heat-transfer type with the same shape as a stress or coupled type ("" when none is
/// obvious): C3D8 -> DC3D8, C3D8T -> DC3D8, GAPUNIT -> DGAP.
std::string heat_twin(std::string_view t, bool coupled) {
  std::string s(coupled && t.ends_with('T') ? t.substr(0, t.size() - 1) : t);
  if (s.starts_with("C3D")) return s.insert(0, 1, 'D');
  if (s == "GAPUNI") return "DGAP";
  return {};
}

std::string twin_text(const std::string& from, const std::string& to) {
  return to.empty() ? std::string() : fmt::format(" ({} -> {})", from, to);
}

/// Why an element of type `t` with these fields cannot be used in a step of procedure `p`, with
/// what to do ("" when it can).
std::string procedure_mismatch(Procedure p, const Model::ElementFields& f, std::string_view t) {
  const std::string step = fmt::format("*{}", procedure_name(p)), type(t);
  if (!is_thermal(p) && f.temperature)
    return f.displacement
               ? fmt::format("is a coupled temperature-displacement element and cannot be used "
                             "in a {} step; use *COUPLED TEMPERATURE-DISPLACEMENT, or its "
                             "stress/displacement twin{}",
                             step, twin_text(type, stress_twin(t, true)))
               : fmt::format("is a heat-transfer element and cannot be used in a {} step; use "
                             "*HEAT TRANSFER for a thermal analysis, or a stress/displacement "
                             "element type{} for a stress analysis",
                             step, twin_text(type, stress_twin(t, false)));
  if (p == Procedure::HeatTransfer && f.displacement)
    return f.temperature
               ? fmt::format("is a coupled temperature-displacement element and cannot be used "
                             "in a *HEAT TRANSFER step; use *COUPLED TEMPERATURE-DISPLACEMENT, "
                             "or its heat-transfer twin{}",
                             twin_text(type, heat_twin(t, true)))
               : fmt::format("is a stress/displacement element and cannot be used in a *HEAT "
                             "TRANSFER step; use *STATIC for a stress analysis, or a "
                             "heat-transfer element type{} for a thermal analysis",
                             twin_text(type, heat_twin(t, false)));
  return {};
}

} // namespace

void check_step_procedures(const Model& model) {
  const Mesh& mesh = model.mesh;
  for (const Step& s : model.steps) {
    if (s.procedure == Procedure::CoupledTempDisp) continue;
    for (ElemId e = 0; e < mesh.n_elements(); ++e) {
      const std::string why =
          procedure_mismatch(s.procedure, model.element_fields(e), model.element_type_name(e));
      if (!why.empty())
        throw InputError(s.loc, fmt::format("step {}", s.number),
                         fmt::format("element {} ({}) {}", model.element_label(e),
                                     model.element_type_name(e), why));
    }
  }
}

void set_initial_temperatures(const Model& model, const DofMap& dofs, std::span<double> u) {
  if (model.initial_temperature.empty()) return;
  for (LocalIndex s = 0; s < dofs.n_slots(); ++s)
    if (dofs.slot_is_temperature(s)) { // every temperature through a shell starts at the value
      const NodeId n = dofs.slot_node(s);
      if (n < static_cast<NodeId>(model.initial_temperature.size()))
        u[s] = model.initial_temperature[n];
    }
}

bool fixed_transient_increments(const Step& step) {
  return is_thermal(step.procedure) && !step.inc.steady_state && step.inc.deltmx <= 0.0;
}

double max_free_temperature_change(const DofMap& dofs, const EquationMap& eqs,
                                   std::span<const double> u, std::span<const double> u_start) {
  double m = 0.0;
  for (LocalIndex i = 0; i < eqs.n_eq(); ++i) {
    const LocalIndex s = eqs.eq_slot[i];
    if (dofs.slot_is_temperature(s)) m = std::max(m, std::abs(u[s] - u_start[s]));
  }
  return m;
}

TemperatureAccuracy deltmx_rule(double dT_max, double deltmx, double cutback) {
  // cutback: D_A of *CONTROLS, PARAMETERS=TIME INCREMENTATION (Abaqus's default 0.85)
  constexpr double kMaxGrowth = 2.0; // W_M for diffusion-dominated procedures
  TemperatureAccuracy a;
  if (dT_max > deltmx) {
    a.redo = true;
    a.ratio = cutback * deltmx / dT_max;
    return a;
  }
  a.ratio = dT_max > 0.0 ? std::min(deltmx / dT_max, kMaxGrowth) : kMaxGrowth;
  return a;
}

// ------------------------------------------------------------------------------ heat balance

HeatBalance::HeatBalance(bool active, bool transient, std::span<const double> u_step_start)
    : _active(active), _transient(transient) {
  if (_active && _transient) _u_begin.assign(u_step_start.begin(), u_step_start.end());
}

void HeatBalance::save(ArchiveWriter& a) const {
  a.vec(_u_begin);
  a.pod(_reaction);
  a.pod(_applied);
  a.pod(_scale);
}

void HeatBalance::restore(ArchiveReader& a) {
  a.vec(_u_begin);
  a.pod(_reaction);
  a.pod(_applied);
  a.pod(_scale);
}

void HeatBalance::add_increment(const DofMap& dofs, double dt, std::span<const double> reaction,
                                std::span<const double> f_ext) {
  if (!_active || !_transient) return;
  for (LocalIndex s = 0; s < dofs.n_slots(); ++s) {
    if (!dofs.slot_is_temperature(s)) continue;
    _reaction += dt * reaction[s];
    _applied += dt * f_ext[s];
    _scale += dt * (std::abs(reaction[s]) + std::abs(f_ext[s]));
  }
}

void HeatBalance::finish(Discretization& disc, const StepContext& ctx,
                         std::span<const double> u_now, std::span<const double> reaction,
                         std::span<const double> f_ext, StepChecks& c) const {
  if (!_active) return;
  c.thermal = true;
  // extended precision: fluxes near the double range do not overflow the sums
  long double rfl = 0.0, applied = 0.0, stored = 0.0, scale = 0.0;
  if (_transient) {
    rfl = _reaction;
    applied = _applied;
    stored = total_stored_heat(disc, ctx, u_now, _u_begin);
    scale = static_cast<long double>(_scale) + std::fabs(stored);
  } else {
    const DofMap& dofs = disc.dofs();
    for (LocalIndex s = 0; s < dofs.n_slots(); ++s) {
      if (!dofs.slot_is_temperature(s)) continue;
      rfl += reaction[s];
      applied += f_ext[s];
      scale += std::fabs(static_cast<long double>(reaction[s])) + std::fabs(f_ext[s]);
    }
  }
  const long double error = std::fabs(rfl + applied - stored);
  c.reaction_flux_sum = static_cast<double>(rfl);
  c.applied_flux_sum = static_cast<double>(applied);
  c.stored_heat = static_cast<double>(stored);
  c.heat_scale = static_cast<double>(scale);
  c.heat_balance_error = static_cast<double>(error);
  c.relative_heat_balance = scale > 0 ? static_cast<double>(error / scale) : 0.0;
}

double total_stored_heat(Discretization& disc, const StepContext& ctx, std::span<const double> u,
                         std::span<const double> u_start) {
  ElementGather gather;
  FieldView fields;
  fields.u = u;
  fields.u_start = u_start;
  double Q = 0.0;
  for (auto& b : disc.blocks()) {
    if (!element_info(b.type).temperature) continue;
    for (std::size_t i = 0; i < b.size(); ++i) {
      const ElementInput& in = gather.gather(disc, b, i, fields, &ctx);
      Q += b.kernel->stored_heat(in);
    }
  }
  return Q;
}

} // namespace gapfem
