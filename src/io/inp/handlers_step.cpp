// History structure: *STEP … *END STEP, the procedures *STATIC, *HEAT TRANSFER and
// *COUPLED TEMPERATURE-DISPLACEMENT, and *CHANGE FRICTION. A new step starts from the complete
// active lists of the previous step (model-data *BOUNDARY for step 1) with propagated = true; the
// load handlers then modify them (handlers_loads.cpp).
#include "io/inp/handlers.hpp"

#include <cmath>
#include <fmt/format.h>

namespace gapfem::inp {
namespace {

template <typename T>
std::vector<T> carried(const std::vector<T>& prev) {
  std::vector<T> out = prev;
  for (auto& e : out) e.propagated = true;
  return out;
}

/// initial, period, min, max (0 or blank = default; a blank period is 1).
void read_incrementation(BuildState& s, const Keyword& kw, std::size_t max_fields) {
  Incrementation& inc = s.step.inc;
  for (const DataLine& line : kw.data) {
    if (line.blank()) continue; // (a line of only commas is the data line: all defaults)
    const FieldReader r = s.reader(kw, line);
    r.at_most(max_fields, "initial increment, time period, minimum increment, maximum increment");
    inc.initial = r.real_or(0, 0.0, "initial increment");
    inc.period = r.real_or(1, 1.0, "time period");
    inc.minimum = r.real_or(2, 0.0, "minimum increment");
    inc.maximum = r.real_or(3, 0.0, "maximum increment");
    if (inc.period <= 0)
      r.fail("field 2 (time period)",
             fmt::format("the time period must be positive, not {}", inc.period));
    const char* names[] = {"initial increment", "minimum increment", "maximum increment"};
    const double vals[] = {inc.initial, inc.minimum, inc.maximum};
    const int fields[] = {1, 3, 4};
    for (int i = 0; i < 3; ++i)
      if (vals[i] < 0)
        r.fail(fmt::format("field {} ({})", fields[i], names[i]),
               "increments must not be negative (0 or blank selects the default)");
    if (inc.minimum > 0 && inc.maximum > 0 && inc.minimum > inc.maximum)
      r.fail("field 3 (minimum increment)",
             fmt::format("the minimum increment {} is larger than the maximum increment {}",
                         inc.minimum, inc.maximum));
    if (inc.initial > inc.period)
      r.fail("field 1 (initial increment)",
             fmt::format("the initial increment {} is larger than the time period {}", inc.initial,
                         inc.period));
    if (inc.maximum > 0 && inc.initial > inc.maximum)
      r.fail("field 1 (initial increment)",
             fmt::format("the initial increment {} is larger than the maximum increment {}",
                         inc.initial, inc.maximum));
    return; // one data line: the parser reports any further ones
  }
}

/// STEADY STATE, DELTMX= and the CAE-written END=PERIOD (shared by heat transfer and coupled).
void read_thermal_procedure(BuildState& s, const Keyword& kw) {
  const bool steady = kw.has("STEADY STATE");
  if (kw.has("END") && enum_param(kw, "END", {"PERIOD", "SS"}, 0) == 1)
    throw InputError(kw.loc, "END=SS",
                     steady ? "END=SS ends a transient step once the temperatures stop changing; "
                              "this step is STEADY STATE already: remove END=SS"
                            : "ending a transient step when the temperatures stop changing is not "
                              "supported by gapfem; remove END=SS and give a time period long "
                              "enough to reach steady state, or make the step STEADY STATE");
  s.step.inc.steady_state = steady;
  s.scratch.transient = !steady;
  if (auto d = real_param(kw, "DELTMX")) {
    if (*d <= 0)
      throw InputError(kw.loc, param_text(kw, "DELTMX"),
                       "the largest temperature change per increment (DELTMX) must be positive");
    s.step.inc.deltmx = *d;
  }
  read_incrementation(s, kw, 5);
}

/// The optional data line of *STEP, Abaqus's step title (printed nowhere by gapfem). A title that
/// reads as numbers is more likely a data line whose keyword line went missing: a warning.
void read_step_title(BuildState& s, const Keyword& kw) {
  for (const DataLine& line : kw.data) {
    if (line.blank()) continue;
    line.read = true; // one line; the parser reports any further ones
    if (!line.fields.empty() && parse_real(line.fields[0]))
      s.warn(s.loc(kw, line),
             fmt::format("the data line under *STEP is the step's title (Abaqus), but '{}' reads "
                         "as numbers: is a keyword line (such as *CLOAD) missing above it?",
                         trim(line.text)));
    return;
  }
}

/// The loads given in a perturbation step whose loads are the perturbation (*BUCKLE, a static
/// perturbation): their full value at the step's end, whatever amplitude they name (Abaqus ignores
/// amplitudes there), from zero.
template <class List>
void perturbation_values(List& list) {
  for (auto& e : list)
    if (!e.propagated) e.amplitude = -1;
}

/// A perturbation step (*FREQUENCY, *BUCKLE, *STEP, PERTURBATION): the procedure must be one;
/// the loads of an eigenfrequency extraction are the base state's (those given in the step: a
/// warning), those given in a buckling or static perturbation step its perturbation loads.
void close_perturbation(BuildState& s) {
  Step& st = s.step;
  // a linear perturbation procedure (an eigenvalue extraction, whose elements are evaluated about
  // the frozen base state, or a mode-based procedure on its modes)
  const bool procedure = is_perturbation(st.procedure) || is_mode_based(st.procedure);
  if (procedure)
    st.perturbation = true;
  else if (st.perturbation && st.procedure != Procedure::Static)
    s.error(st.loc, "PERTURBATION",
            fmt::format("*{} runs as a general step in gapfem, whose linear perturbation "
                        "procedures are *STATIC, *FREQUENCY, *BUCKLE and the mode-based ones: "
                        "remove PERTURBATION from *STEP",
                        procedure_name(st.procedure)));
  if ((st.modal_damping || !st.selected_modes.empty()) && !is_mode_based(st.procedure) &&
      !s.scratch.unknown_procedure)
    s.error(st.modal_damping ? st.modal_damping->loc : st.loc, "",
            fmt::format("*MODAL DAMPING and *SELECT EIGENMODES belong to a mode-based step "
                        "(*RESPONSE SPECTRUM, *STEADY STATE DYNAMICS, *MODAL DYNAMIC); this step "
                        "is *{}",
                        procedure_name(st.procedure)));
  const bool harmonic = st.procedure == Procedure::SteadyStateDynamics;
  const bool modal = harmonic || st.procedure == Procedure::ModalDynamic;
  if (!st.base_motions.empty() && !modal)
    s.error(st.base_motions.front().loc, "",
            fmt::format("*BASE MOTION belongs to a mode-based dynamic step (*STEADY STATE "
                        "DYNAMICS, *MODAL DYNAMIC); this step is *{}",
                        procedure_name(st.procedure)));
  for (const NodalLoad& l : st.cloads)
    if (l.imaginary && !l.propagated && !harmonic) {
      s.error(l.loc, "IMAGINARY",
              "an imaginary (out-of-phase) load belongs to a *STEADY STATE DYNAMICS step");
      break;
    }
  for (const BaseMotion& b : st.base_motions)
    if (b.imaginary && !harmonic)
      s.error(b.loc, "IMAGINARY",
              "an imaginary (out-of-phase) base motion belongs to a *STEADY STATE DYNAMICS step");
  if (!st.perturbation) return;
  if (modal) { // the excitation: the loads given in the step, nothing of the base state's
    std::erase_if(st.cloads, [](const NodalLoad& l) { return l.propagated; });
    const auto given = [](const auto& e) { return !e.propagated; };
    for (const BoundaryEntry& b : st.boundary)
      if (given(b) && (b.value != 0.0 || b.type != BoundaryType::Displacement)) {
        s.error(b.loc, "",
                fmt::format("a prescribed motion in a *{} step is a base motion: give it with "
                            "*BASE MOTION (the DOFs the *FREQUENCY step holds move together), "
                            "not *BOUNDARY",
                            procedure_name(st.procedure)));
        break;
      }
    const auto d = std::find_if(st.dloads.begin(), st.dloads.end(), given);
    const auto t = std::find_if(st.temperatures.begin(), st.temperatures.end(), given);
    if (d != st.dloads.end() || t != st.temperatures.end())
      s.error(d != st.dloads.end() ? d->loc : t->loc, "",
              fmt::format("*{} is excited by concentrated loads (*CLOAD) and base motion (*BASE "
                          "MOTION) in gapfem; distributed loads and temperatures given in it are "
                          "not applied: give the excitation as *CLOAD",
                          procedure_name(st.procedure)));
    st.dloads.clear();
    st.temperatures.clear();
    st.interference.clear();
    return;
  }
  const Step* base = nullptr; // the last general step (none: the initial state, no loads)
  for (auto it = s.model.steps.rbegin(); it != s.model.steps.rend() && !base; ++it)
    if (!it->perturbation) base = &*it;
  if (st.procedure == Procedure::Buckle || st.procedure == Procedure::Static) {
    perturbation_values(st.cloads);
    perturbation_values(st.dloads);
    // a concentrated load given where the base state has one replaced it (OP=MOD): the
    // perturbation is the value given, on top of the base load
    if (base)
      for (NodalLoad& q : st.cloads)
        if (!q.propagated)
          for (const NodalLoad& p : base->cloads)
            if (p.node == q.node && p.dof == q.dof && p.amplitude < 0) q.value += p.value;
    if (base) // OP=NEW removed none of the base loads: they stay as they are
      for (const NodalLoad& p : base->cloads)
        if (std::none_of(st.cloads.begin(), st.cloads.end(),
                         [&](const NodalLoad& q) { return q.node == p.node && q.dof == p.dof; })) {
          st.cloads.push_back(p);
          st.cloads.back().propagated = true;
        }
    return;
  }
  if (st.procedure != Procedure::Frequency && st.procedure != Procedure::ResponseSpectrum) return;
  const auto given = [](const auto& list) {
    return std::any_of(list.begin(), list.end(), [](const auto& e) { return !e.propagated; });
  };
  if (given(st.cloads) || given(st.dloads) || given(st.temperatures) || given(st.interference))
    s.warn(st.loc, fmt::format("loads, temperatures and interference given in a *{} step are "
                               "ignored (as in Abaqus): the modes are those of the base state, "
                               "with its loads",
                               procedure_name(st.procedure)));
  st.cloads = base ? carried(base->cloads) : decltype(st.cloads){};
  st.dloads = base ? carried(base->dloads) : decltype(st.dloads){};
  st.temperatures = base ? carried(base->temperatures) : decltype(st.temperatures){};
  st.interference = base ? carried(base->interference) : decltype(st.interference){};
}

} // namespace

void set_procedure(BuildState& s, const Keyword& kw, Procedure p) {
  if (s.scratch.procedure_given)
    throw InputError(kw.loc, fmt::format("step {}", s.step.number),
                     fmt::format("a step has exactly one procedure and this step already has *{}; "
                                 "start a new *STEP for this procedure",
                                 procedure_name(s.step.procedure)));
  s.scratch.procedure_given = true;
  s.step.procedure = p;
}

void handle_step(BuildState& s, const Keyword& kw) {
  if (s.in_step) {
    s.error(
        kw.loc, fmt::format("step {}", s.step.number),
        fmt::format("the step that starts at {} has no *END STEP; add *END STEP before this *STEP",
                    s.step.loc.str()));
    close_step(s);
  }
  if (!s.model_done) finish_model_data(s);
  // the base state: the loads and boundary conditions of the last general step (a perturbation
  // step's own do not carry on, Abaqus)
  const Step* prev = nullptr;
  for (auto it = s.model.steps.rbegin(); it != s.model.steps.rend() && !prev; ++it)
    if (!it->perturbation) prev = &*it;
  s.step = Step{};
  s.scratch = StepScratch{};
  s.in_step = true;
  s.parent = Parent::None;
  s.current_field = s.current_change = -1;
  Step& st = s.step;
  st.number = static_cast<int>(s.model.steps.size()) + 1;
  st.loc = kw.loc;
  if (kw.has("INCF")) // CalculiX: the increments of its fluid solver
    s.warn(kw.loc, "INCF (CalculiX's maximum number of fluid increments) has no meaning in "
                   "gapfem, which has no fluid procedure; it was ignored");
  st.name = kw.has("NAME") ? std::string(trim(param_value(kw, "NAME", true)))
                           : fmt::format("Step-{}", st.number);
  for (const Step& other : s.model.steps)
    if (to_upper(other.name) == to_upper(st.name))
      s.error(kw.loc, fmt::format("NAME={}", st.name),
              fmt::format("step {} at {}:{} already has this name; give each step its own NAME",
                          other.number, other.loc.file, other.loc.line));
  st.boundary = carried(prev ? prev->boundary : s.model_boundary);
  if (!prev) // non-zero model-data values (CalculiX dialect) are reached in the first step
    for (BoundaryEntry& b : st.boundary) b.propagated = b.value == 0.0;
  const Step* last = s.model.steps.empty() ? nullptr : &s.model.steps.back();
  st.monitor = last ? last->monitor : s.model_monitor; // a *MONITOR stays until replaced
  st.restart = last ? last->restart : s.model_restart; // so does *RESTART, WRITE
  if (last) st.controls = last->controls; // *CONTROLS stay in effect until changed or reset
  if (prev) {
    st.cloads = carried(prev->cloads);
    st.dloads = carried(prev->dloads);
    st.temperatures = carried(prev->temperatures);
    st.interference = carried(prev->interference);
  }
  st.perturbation = kw.has("PERTURBATION");
  // once on, nonlinear geometry stays on in every later step (Abaqus); NLGEOM=NO cannot undo it
  const bool was_on = std::any_of(s.model.steps.begin(), s.model.steps.end(),
                                  [](const Step& p) { return p.nlgeom; });
  st.nlgeom = yes_no_param(kw, "NLGEOM", was_on);
  if (was_on && !st.nlgeom) {
    s.warn(kw.loc, "NLGEOM=NO: nonlinear geometry, once on in an earlier step, stays on in all "
                   "later steps (as in "
                   "Abaqus); NLGEOM=NO has no effect");
    st.nlgeom = true;
  }
  if (kw.has("UNSYMM")) {
    st.unsymmetric = yes_no_param(kw, "UNSYMM", false);
    st.symmetric_only = !st.unsymmetric;
  }
  st.extrapolation =
      static_cast<Extrapolation>(enum_param(kw, "EXTRAPOLATION", {"LINEAR", "PARABOLIC", "NO"}, 0));
  if (auto inc = int_param(kw, "INC", "the maximum number of increments", 1, kMaxInt))
    st.max_increments = static_cast<int>(*inc);
  if (kw.has("AMPLITUDE")) {
    s.scratch.amplitude_given = true;
    st.ramp_default = enum_param(kw, "AMPLITUDE", {"RAMP", "STEP"}, 0) == 0;
  }
  read_step_title(s, kw);
}

void close_step(BuildState& s) {
  Step& st = s.step;
  if (!s.scratch.procedure_given)
    s.error(st.loc, fmt::format("step {}", st.number),
            "the step has no procedure; add one after *STEP: *STATIC, *DYNAMIC, *HEAT TRANSFER, "
            "*COUPLED TEMPERATURE-DISPLACEMENT, *FREQUENCY, *BUCKLE, *STEADY STATE DYNAMICS, "
            "*MODAL DYNAMIC or *RESPONSE SPECTRUM");
  // default variation of magnitudes: RAMP, except transient heat transfer / coupled steps (STEP)
  if (!s.scratch.amplitude_given) st.ramp_default = !s.scratch.transient;
  if (s.scratch.procedure_given) close_perturbation(s);
  for (const auto& change : st.friction_changes)
    if (!change.friction.given)
      s.error(change.loc, "", "*CHANGE FRICTION must be followed by *FRICTION with the new data");
  check_predefined_temperatures(s);
  resolve_preset_outputs(s);
  if (st.number == 1 && !s.model.initial_velocities.empty() && st.procedure != Procedure::Dynamic)
    s.warn(s.model.initial_velocity_loc,
           fmt::format("the initial velocities apply at the start of the analysis, but its first "
                       "step is *{}, which has no velocities: they are not used",
                       procedure_name(st.procedure)));
  if (st.nlgeom && !s.model.substructures.empty() &&
      (s.model.steps.empty() || !s.model.steps.back().nlgeom)) // once: NLGEOM stays on
    s.warn(st.loc, fmt::format("step {} has NLGEOM, but gapfem's substructures respond linearly "
                               "(small rotations): a substructure that rotates much is not "
                               "followed; the rest of the model is geometrically nonlinear",
                               st.number));
  // output requests carry over from the previous step unless this step gives its own
  if (!s.model.steps.empty()) {
    const Step& prev = s.model.steps.back();
    if (!s.scratch.node_print_given) st.node_prints = prev.node_prints;
    if (!s.scratch.el_print_given) st.el_prints = prev.el_prints;
    if (!s.scratch.field_given) st.field_outputs = prev.field_outputs;
    for (const FileOutputRequest& r : prev.file_outputs)
      if (!(r.element ? s.scratch.el_file_given : s.scratch.node_file_given))
        st.file_outputs.push_back(r);
  }
  check_rate_outputs(s, st);
  s.model.steps.push_back(std::move(st));
  s.step = Step{};
  s.in_step = false;
  s.parent = Parent::None;
  s.current_field = s.current_change = -1;
}

void handle_end_step(BuildState& s, const Keyword& kw) {
  if (!s.in_step)
    throw InputError(kw.loc, "", "*END STEP without a matching *STEP; remove it or add *STEP");
  close_step(s);
}

namespace {

/// SOLVER= on a procedure (CalculiX: SPOOLES, PARDISO, ITERATIVE SCALING, …): its own choice of
/// linear solver, with no meaning here.
void calculix_solver(BuildState& s, const Keyword& kw) {
  if (const Parameter* p = kw.find("SOLVER"))
    s.warn(kw.loc, fmt::format("{}, SOLVER={}: CalculiX's choice of its linear solver; gapfem "
                               "solves with its own (the command line's --solver) and ignored it",
                               kw.name, p->value));
}

} // namespace

void handle_static(BuildState& s, const Keyword& kw) {
  set_procedure(s, kw, Procedure::Static); // first: a rejected option is no "missing procedure"
  calculix_solver(s, kw);
  reject_param(kw, "RIKS", "use load or displacement control in a general *STATIC step");
  s.step.inc.direct = kw.has("DIRECT");
  s.step.inc.steady_state = true;
  read_incrementation(s, kw, 4);
  Stabilization& st = s.step.stabilize;
  st.on = kw.has("STABILIZE") || kw.has("FACTOR");
  if (!st.on) {
    for (const char* p : {"ALLSDTOL", "CONTINUE"})
      if (kw.has(p))
        throw InputError(kw.loc, p, fmt::format("{} needs STABILIZE (automatic stabilization)", p));
    return;
  }
  st.loc = kw.loc;
  if (const Parameter* p = kw.find("STABILIZE"); p && p->has_value) {
    st.fraction = real_param(kw, "STABILIZE").value_or(2e-4);
    if (!(st.fraction > 0))
      throw InputError(kw.loc, param_text(kw, "STABILIZE"),
                       "the dissipated energy fraction must be positive");
  }
  st.factor = real_param(kw, "FACTOR");
  if (st.factor && !(*st.factor > 0))
    throw InputError(kw.loc, param_text(kw, "FACTOR"), "the damping factor must be positive");
  // adaptive by default; a damping factor given directly stays constant unless ALLSDTOL is given
  st.allsdtol = real_param(kw, "ALLSDTOL").value_or(st.factor ? 0.0 : 0.05);
  if (st.allsdtol < 0)
    throw InputError(kw.loc, param_text(kw, "ALLSDTOL"), "ALLSDTOL must not be negative");
  st.carry = yes_no_param(kw, "CONTINUE", false);
}

namespace {

/// Does the model have contact (gap elements)? Abaqus's default APPLICATION depends on it.
bool model_has_contact(const Model& m) {
  for (ElementType t : m.mesh.elem_types)
    if (element_info(t).family == ElementFamily::Gap) return true;
  return false;
}

/// ALPHA, BETA, GAMMA of *DYNAMIC over the application's defaults (docs/theory/dynamics.md):
/// an explicit ALPHA gives beta = (1 - alpha)^2 / 4 and gamma = 1/2 - alpha unless they are given.
void read_hht_parameters(const Keyword& kw, DynamicSettings& d) {
  if (!d.hht) {
    for (const char* p : {"ALPHA", "BETA", "GAMMA"})
      if (kw.has(p))
        throw InputError(kw.loc, param_text(kw, p),
                         fmt::format("{} is a parameter of the Hilber-Hughes-Taylor integrator; "
                                     "APPLICATION=QUASI-STATIC integrates with backward Euler: "
                                     "remove {} or choose another APPLICATION",
                                     p, p));
    return;
  }
  if (const auto a = real_param(kw, "ALPHA")) {
    if (!(*a >= -0.5 && *a <= 0.0))
      throw InputError(kw.loc, param_text(kw, "ALPHA"),
                       "ALPHA must lie between -0.5 and 0 (Abaqus's range; -0.05 by default)");
    d.alpha = *a;
    d.beta = 0.25 * (1.0 - d.alpha) * (1.0 - d.alpha);
    d.gamma = 0.5 - d.alpha;
  }
  if (const auto b = real_param(kw, "BETA")) d.beta = *b;
  if (const auto g = real_param(kw, "GAMMA")) d.gamma = *g;
  if (!(d.beta > 0.0) || !(d.gamma >= 0.5))
    throw InputError(kw.loc, param_text(kw, kw.has("BETA") ? "BETA" : "GAMMA"),
                     fmt::format("BETA = {} and GAMMA = {} make the integration unstable: give "
                                 "BETA > 0 and GAMMA >= 1/2 (or leave them to ALPHA)",
                                 d.beta, d.gamma));
}

} // namespace

void handle_dynamic(BuildState& s, const Keyword& kw) {
  set_procedure(s, kw, Procedure::Dynamic);
  calculix_solver(s, kw);
  reject_param(kw, "EXPLICIT", "gapfem is an implicit code; use *DYNAMIC without EXPLICIT");
  reject_param(kw, "SUBSPACE", "use the implicit integration of *DYNAMIC (SUBSPACE omitted)");
  reject_param(kw, "ADIABATIC", "gapfem's materials are elastic: there is no plastic heating");
  if (kw.has("IMPACT")) {
    // No Keywords Reference we could read (v6.5, 6.11, 2016-2024) lists IMPACT; old decks used it
    // to ask for the impact conditions that gapfem always applies to hard gaps
    // (docs/theory/dynamics.md, section 5)
    if (!yes_no_param(kw, "IMPACT", true))
      throw InputError(kw.loc, param_text(kw, "IMPACT"),
                       "IMPACT=NO would let a hard gap close without its impact conditions "
                       "(velocities compatible at the impact), which gives energy to the model: "
                       "remove IMPACT=NO, or use a SOFTENED or PENALTY gap for an elastic impact");
    s.warn(kw.loc, "*DYNAMIC, IMPACT: a hard gap that closes is always a fully plastic impact in "
                   "gapfem (as in Abaqus/Standard); the parameter changes nothing");
  }
  DynamicSettings& d = s.step.dynamic;
  d.loc = kw.loc;
  using A = DynamicSettings::Application;
  const int def = model_has_contact(s.model) ? 1 : 0;
  d.application = static_cast<A>(enum_param(
      kw, "APPLICATION", {"TRANSIENT FIDELITY", "MODERATE DISSIPATION", "QUASI-STATIC"}, def));
  // the integrator: the application's, or TIME INTEGRATOR's (HHT-TF, HHT-MD, BWE)
  const int integrator = enum_param(kw, "TIME INTEGRATOR", {"HHT-TF", "HHT-MD", "BWE"},
                                    static_cast<int>(d.application));
  d.hht = integrator != 2;
  if (integrator == 1) {
    d.alpha = 1.0 - std::sqrt(2.0); // -0.41421
    d.beta = 0.25 * (1.0 - d.alpha) * (1.0 - d.alpha);
    d.gamma = 0.5 - d.alpha;
  }
  d.initial_accelerations = yes_no_param(kw, "INITIAL", d.application == A::TransientFidelity);
  read_hht_parameters(kw, d);
  s.step.inc.direct = kw.has("DIRECT");
  if (const auto h = real_param(kw, "HAFTOL")) {
    if (s.step.inc.direct)
      throw InputError(kw.loc, param_text(kw, "HAFTOL"),
                       "DIRECT (fixed increments) and HAFTOL (automatic increments) exclude each "
                       "other; remove one");
    if (!(*h > 0.0))
      throw InputError(kw.loc, param_text(kw, "HAFTOL"),
                       "the half-increment residual tolerance must be a positive force");
    d.haftol = *h;
  }
  s.step.inc.steady_state = true;
  read_incrementation(s, kw, 4);
}

void handle_heat_transfer(BuildState& s, const Keyword& kw) {
  set_procedure(s, kw, Procedure::HeatTransfer);
  calculix_solver(s, kw);
  read_thermal_procedure(s, kw);
}

void handle_coupled(BuildState& s, const Keyword& kw) {
  set_procedure(s, kw, Procedure::CoupledTempDisp);
  calculix_solver(s, kw);
  enum_param(kw, "CREEP", {"NONE"},
             0); // written by Abaqus/CAE; creep is not modelled
  read_thermal_procedure(s, kw);
}

void handle_change_friction(BuildState& s, const Keyword& kw) {
  s.current_change = -1;
  reject_param(kw, "INTERACTION", "gapfem has element-based (gap) contact only; use ELSET=");
  const std::string elset = set_param(s, kw, "ELSET", true);
  const auto* set = find_elset(s, elset);
  if (!set && s.bad_sets.count(elset)) return; // its definition failed (reported)
  if (!set)
    throw InputError(kw.loc, fmt::format("ELSET={}", elset),
                     undefined_name(s, elset, NameKind::ElementSet, kw.name,
                                    "an element set of gap elements",
                                    "define it with *ELSET in the model data"));
  FrictionChange change;
  change.loc = kw.loc;
  for (ElemId e : *set) {
    const ElementType t = s.model.mesh.elem_types[e];
    if (element_info(t).family != ElementFamily::Gap || t == ElementType::DGAP)
      throw InputError(
          kw.loc, fmt::format("element {} ({})", s.model.element_label(e), element_info(t).name),
          fmt::format("*CHANGE FRICTION applies to mechanical gap elements only; remove this "
                      "element from ELSET {}",
                      elset));
    change.elements.push_back(e);
  }
  s.step.friction_changes.push_back(std::move(change));
  s.current_change = static_cast<int>(s.step.friction_changes.size()) - 1;
}

} // namespace gapfem::inp
