// The mode-based dynamic procedures (docs/theory/modal_dynamics.md): *STEADY STATE DYNAMICS
// (harmonic response on the modes), *MODAL DYNAMIC (transient response on the modes) and their
// *BASE MOTION. Direct (non-modal) steady-state dynamics is not what these run: DIRECT and
// SUBSPACE PROJECTION are refused.
#include "io/inp/handlers.hpp"

#include <fmt/format.h>

namespace gapfem::inp {
namespace {

/// One frequency range: lower, upper (0: one frequency), points, bias, frequency scale.
SteadyStateSettings::Range frequency_range(const FieldReader& r) {
  r.at_most(5, "lower frequency, upper frequency, number of points, bias, frequency scale");
  SteadyStateSettings::Range g;
  g.lower = r.real(0, "lower frequency");
  g.upper = r.real_or(1, 0.0, "upper frequency");
  if (g.lower < 0.0 || g.upper < 0.0)
    r.fail("fields 1-2 (frequencies)", "frequencies (cycles per time) must not be negative");
  if (g.upper != 0.0 && g.upper < g.lower)
    r.fail("field 2 (upper frequency)",
           fmt::format("the upper frequency {} is below the lower frequency {}", g.upper, g.lower));
  const long long n = r.integer_or(2, 20, "number of points", 0, 100000);
  g.points = n < 2 ? 20 : static_cast<int>(n); // 0 or 1: Abaqus's default 20
  if (const auto b = r.opt_real(3, "bias parameter")) {
    if (!(*b > 0.0)) r.fail("field 4 (bias)", "the bias parameter must be positive");
    g.bias = *b;
  }
  g.scale = r.real_or(4, 1.0, "frequency scale multiplier");
  if (!(g.scale > 0.0)) r.fail("field 5 (frequency scale)", "the multiplier must be positive");
  return g;
}

} // namespace

void handle_steady_state_dynamics(BuildState& s, const Keyword& kw) {
  set_procedure(s, kw, Procedure::SteadyStateDynamics); // first: no follow-on "no procedure"
  reject_param(kw, "DIRECT",
               "gapfem's steady-state dynamics is mode-based (on the modes of a *FREQUENCY step "
               "before it): remove DIRECT and add a *FREQUENCY step");
  reject_param(kw, "SUBSPACE PROJECTION",
               "gapfem's steady-state dynamics is mode-based: remove SUBSPACE PROJECTION and add "
               "a *FREQUENCY step before it");
  SteadyStateSettings& ss = s.step.steady_state;
  ss.loc = kw.loc;
  if (kw.has("HARMONIC") && !yes_no_param(kw, "HARMONIC", true))
    throw InputError(kw.loc, "HARMONIC=NO",
                     "CalculiX's non-harmonic periodic excitation is not run by gapfem; give the "
                     "excitation as harmonic loads (HARMONIC=YES, the default)");
  if (kw.has("REAL ONLY"))
    s.warn(kw.loc, "REAL ONLY applies to direct steady-state dynamics; the mode-based response "
                   "keeps the modal damping");
  ss.logarithmic = enum_param(kw, "FREQUENCY SCALE", {"LOGARITHMIC", "LINEAR"}, 0) == 0;
  const int interval = enum_param(kw, "INTERVAL", {"EIGENFREQUENCY", "RANGE", "SPREAD"}, 0);
  if (interval == 2)
    throw InputError(kw.loc, "INTERVAL=SPREAD",
                     "gapfem spreads the frequency points by eigenfrequency intervals or over the "
                     "range: use INTERVAL=EIGENFREQUENCY (the default) or INTERVAL=RANGE");
  ss.interval = static_cast<SteadyStateSettings::Interval>(interval);
  for (const DataLine& line : kw.data)
    if (!line.blank()) ss.ranges.push_back(frequency_range(s.reader(kw, line)));
  if (ss.ranges.empty())
    throw InputError(kw.loc, "",
                     "no frequency range is given; add a data line: lower frequency, upper "
                     "frequency, number of points (cycles per time)");
}

void handle_modal_dynamic(BuildState& s, const Keyword& kw) {
  set_procedure(s, kw, Procedure::ModalDynamic);
  ModalDynamicSettings& md = s.step.modal_dynamic;
  md.loc = kw.loc;
  for (const char* p : {"SOLVER", "DIRECT", "DELTMX"})
    if (kw.has(p)) {
      s.warn(kw.loc, fmt::format("*MODAL DYNAMIC, {}: a CalculiX option of its own solver and "
                                 "incrementation; gapfem integrates each mode exactly over the "
                                 "fixed increments of the data line",
                                 p));
      break;
    }
  if (kw.has("CONTINUE") && yes_no_param(kw, "CONTINUE", false))
    throw InputError(kw.loc, "CONTINUE=YES",
                     "gapfem starts every *MODAL DYNAMIC step from rest (CONTINUE=NO); merge the "
                     "steps into one with an amplitude that covers both");
  for (const DataLine& line : kw.data) {
    if (line.blank()) continue;
    const FieldReader r = s.reader(kw, line);
    r.at_most(2, "time increment, time period");
    md.dt = r.real(0, "time increment");
    md.period = r.real(1, "time period");
    if (!(md.dt > 0.0)) r.fail("field 1 (time increment)", "the time increment must be positive");
    if (!(md.period > 0.0)) r.fail("field 2 (time period)", "the time period must be positive");
    if (md.period / md.dt > 1e7)
      r.fail("field 1 (time increment)",
             fmt::format("{:.3g} increments: choose a larger time increment", md.period / md.dt));
    break;
  }
  if (!(md.dt > 0.0))
    throw InputError(kw.loc, "",
                     "give the data line: time increment, time period (the modal integration is "
                     "exact for loads that vary linearly over each increment)");
}

void handle_base_motion(BuildState& s, const Keyword& kw) {
  BaseMotion b;
  b.loc = kw.loc;
  reject_param(kw, "BASE NAME",
               "secondary bases are not supported by gapfem; the base motion moves every "
               "DOF the *FREQUENCY step's boundary conditions hold (the primary base)");
  reject_param(kw, "LOAD CASE", "load cases belong to random response, which gapfem does not run");
  const auto dof = int_param(kw, "DOF", "the DOF of the base motion", 1, 6);
  if (!dof)
    throw InputError(kw.loc, "", "give the DOF the base moves along: DOF=1 to 6 (global axes)");
  dof_from_abaqus(static_cast<int>(*dof), b.dof);
  b.amplitude = amplitude_param(s, kw);
  if (const auto sc = real_param(kw, "SCALE")) b.scale = *sc;
  b.type = static_cast<BaseMotion::Type>(
      enum_param(kw, "TYPE", {"ACCELERATION", "VELOCITY", "DISPLACEMENT"}, 0));
  b.imaginary = kw.has("IMAGINARY");
  s.step.base_motions.push_back(b);
}

} // namespace gapfem::inp
