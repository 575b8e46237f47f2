// job.dat: the step's end, its self-checks and the run's summary (dat_writer.hpp).
#include "model/model.hpp"
#include "output/dat_writer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

namespace gapfem {

using output::append_e12;

namespace {

/// Dynamic steps: the whole-model energies at the step end and the balance over the step
/// (docs/theory/dynamics.md, "Energies").
void write_energies(fmt::memory_buffer& buf, const StepChecks& c) {
  auto out = std::back_inserter(buf);
  const Energies& e = c.energies;
  fmt::format_to(out, " ENERGIES (SINCE THE ANALYSIS START)\n");
  const std::pair<const char*, double> rows[] = {{"ALLKE (KINETIC ENERGY)            ", e.allke},
                                                 {"ALLIE (INTERNAL ENERGY)           ", e.allie},
                                                 {"ALLVD (VISCOUS DISSIPATION)       ", e.allvd},
                                                 {"ALLFD (FRICTIONAL DISSIPATION)    ", e.allfd},
                                                 {"ALLSD (STABILIZATION DISSIPATION) ", e.allsd},
                                                 {"ALLKL (KINETIC ENERGY LOST, IMPACT)", e.allkl},
                                                 {"ALLWK (EXTERNAL WORK)             ", e.allwk},
                                                 {"ETOTAL (ENERGY BALANCE)           ", e.etotal()},
                                                 {"ALLSE (STRAIN ENERGY, OF ALLIE)   ", e.allse},
                                                 {"ALLAE (ARTIFICIAL ENERGY, OF ALLIE)", e.allae}};
  for (const auto& [name, v] : rows) {
    fmt::format_to(out, "   {:<36}", name);
    append_e12(buf, v);
    fmt::format_to(out, "\n");
  }
  fmt::format_to(out, " ENERGY BALANCE OVER THE STEP\n   CHANGE OF ETOTAL                  ");
  append_e12(buf, c.energy_change);
  fmt::format_to(out, "\n   ENERGY SCALE (LARGEST ENERGY)     ");
  append_e12(buf, c.energy_scale);
  fmt::format_to(out, "\n   RELATIVE CHANGE                   ");
  if (c.energy_scale > 0)
    append_e12(buf, c.energy_change / c.energy_scale);
  else
    fmt::format_to(out, "{:>12}", "N/A");
  fmt::format_to(out, "\n   {}\n\n",
                 c.conserving ? "(TRAPEZOIDAL RULE: ENERGY IS CONSERVED UP TO THE TOLERANCES)"
                              : "(THE INTEGRATOR'S NUMERICAL DISSIPATION LOWERS ETOTAL)");
}

} // namespace

void DatWriter::end_step(const Model& model, int step_index, const StepSummary& summary) {
  if (step_index >= 0 && step_index < static_cast<int>(model.steps.size()) &&
      model.steps[step_index].perturbation) { // no increments, the base state unchanged
    if (model.steps[step_index].procedure == Procedure::Frequency)
      fmt::format_to(std::back_inserter(_out.buffer()),
                     "\n\n STEP {} COMPLETED: {} EIGENVALUES EXTRACTED\n", summary.step,
                     summary.increments);
    else
      fmt::format_to(std::back_inserter(_out.buffer()),
                     "\n\n STEP {} COMPLETED (LINEAR PERTURBATION)\n", summary.step);
    _out.flush();
    return;
  }
  write_checks(model, step_index, summary);
  _out.flush();
}

void DatWriter::write_checks(const Model& model, int step_index, const StepSummary& s) {
  const StepChecks& c = s.checks;
  auto& buf = _out.buffer();
  auto out = std::back_inserter(buf);
  const bool mechanical = step_index < 0 || step_index >= static_cast<int>(model.steps.size()) ||
                          model.steps[step_index].procedure != Procedure::HeatTransfer;
  fmt::format_to(out, "\n\n\n{:>19}{}\n\n", "",
                 output::spaced(fmt::format("STEP {} SELF-CHECKS", s.step)));
  if (s.converged)
    fmt::format_to(out, " STEP {} COMPLETED: {} INCREMENTS ({} ATTEMPTS), {} ITERATIONS\n\n",
                   s.step, s.increments, s.attempts, s.iterations);
  else
    fmt::format_to(out,
                   " STEP {} WAS NOT COMPLETED: {}\n   ({} INCREMENTS, {} "
                   "ATTEMPTS, {} ITERATIONS)\n\n",
                   s.step, s.failure.empty() ? "no reason given" : s.failure, s.increments,
                   s.attempts, s.iterations);

  if (c.n_gaps > 0) {
    fmt::format_to(out, " GAP ELEMENTS {:>33}\n", c.n_gaps);
    fmt::format_to(out, "   OPEN {:>39}\n", c.n_open);
    fmt::format_to(out, "   CLOSED (FRICTIONLESS) {:>22}\n", c.n_closed);
    fmt::format_to(out, "   CLOSED, STICKING {:>27}\n", c.n_stick);
    fmt::format_to(out, "   CLOSED, SLIPPING {:>27}\n", c.n_slip);
    fmt::format_to(out, " MAXIMUM PENETRATION OF A CLOSED GAP  ");
    append_e12(buf, c.max_penetration);
    if (c.max_penetration_elem != 0)
      fmt::format_to(out, "   AT ELEMENT {}", model.label_of_key(c.max_penetration_elem));
    fmt::format_to(out, "\n MAXIMUM TENSILE FORCE IN A CLOSED GAP");
    append_e12(buf, c.max_tensile_force);
    if (c.max_tensile_elem != 0)
      fmt::format_to(out, "   AT ELEMENT {}", model.label_of_key(c.max_tensile_elem));
    fmt::format_to(out, "\n\n");
  }
  if (mechanical) {
    fmt::format_to(out, " EQUILIBRIUM (FORCE COMPONENTS 1 2 3)\n");
    fmt::format_to(out, "   SUM OF REACTION FORCES RF         ");
    for (double v : c.reaction_sum) append_e12(buf, v);
    fmt::format_to(out, "\n   SUM OF APPLIED LOADS              ");
    for (double v : c.applied_sum) append_e12(buf, v);
    fmt::format_to(out, "\n   ERROR |SUM RF + SUM LOADS|        ");
    append_e12(buf, c.equilibrium_error);
    fmt::format_to(out, "\n   FORCE SCALE                       ");
    append_e12(buf, c.force_scale);
    fmt::format_to(out, "\n   RELATIVE ERROR                    ");
    if (c.force_scale > 0)
      append_e12(buf, c.relative_equilibrium);
    else
      fmt::format_to(out, "{:>12}", "N/A");
    fmt::format_to(out, "\n\n");
  }
  if (c.thermal) {
    fmt::format_to(out, " HEAT BALANCE\n");
    fmt::format_to(out, "   SUM OF REACTION FLUXES RFL        ");
    append_e12(buf, c.reaction_flux_sum);
    fmt::format_to(out, "\n   SUM OF APPLIED FLUXES             ");
    append_e12(buf, c.applied_flux_sum);
    fmt::format_to(out, "\n   STORED HEAT                       ");
    append_e12(buf, c.stored_heat);
    fmt::format_to(out, "\n   HEAT BALANCE ERROR                ");
    append_e12(buf, c.heat_balance_error);
    fmt::format_to(out, "\n   HEAT SCALE                        ");
    append_e12(buf, c.heat_scale);
    fmt::format_to(out, "\n   RELATIVE ERROR                    ");
    if (c.heat_scale > 0)
      append_e12(buf, c.relative_heat_balance);
    else
      fmt::format_to(out, "{:>12}", "N/A");
    fmt::format_to(out, "\n\n");
  }
  if (c.max_damping_force != 0.0) {
    fmt::format_to(out, " MAXIMUM DAMPING FORCE IN A GAP      ");
    append_e12(buf, c.max_damping_force);
    fmt::format_to(out, "\n\n");
  }
  if (c.hourglass) {
    fmt::format_to(out, " HOURGLASS CONTROL\n   ALLAE (ARTIFICIAL STRAIN ENERGY)  ");
    append_e12(buf, c.allae);
    fmt::format_to(out, "\n   ALLSE (STRAIN ENERGY)             ");
    append_e12(buf, c.allse);
    fmt::format_to(out, "\n   ALLAE / (ALLSE + ALLAE)           ");
    if (c.allse + c.allae > 0)
      append_e12(buf, c.allae / (c.allse + c.allae));
    else
      fmt::format_to(out, "{:>12}", "N/A");
    fmt::format_to(out, "\n\n");
  }
  if (c.dynamic) write_energies(buf, c);
  if (c.stabilized) {
    fmt::format_to(out, " AUTOMATIC STABILIZATION\n   DAMPING FACTOR AT STEP END        ");
    append_e12(buf, c.stabilization_factor);
    fmt::format_to(out, "\n   ALLSD (ENERGY DISSIPATED)         ");
    append_e12(buf, c.allsd);
    fmt::format_to(out, "\n   ALLIE (INTERNAL ENERGY)           ");
    append_e12(buf, c.allie);
    fmt::format_to(out, "\n   ALLSD / ALLIE                     ");
    if (c.allie > 0)
      append_e12(buf, c.allsd / c.allie);
    else
      fmt::format_to(out, "{:>12}", "N/A");
    fmt::format_to(out, "\n\n");
  }
}

void DatWriter::end(const Model& model, const RunSummary& summary) {
  if (!_out.is_open()) return;
  auto out = std::back_inserter(_out.buffer());
  fmt::format_to(out, "\n\n\n{:>19}{}\n\n", "", output::spaced("ANALYSIS SUMMARY"));
  const RunStatistics& st = summary.stats;
  fmt::format_to(out, " WALL CLOCK TIME (SECONDS) {:>20.2f}\n", summary.wall_seconds);
  fmt::format_to(out, " INCREMENTS {:>35}\n", st.increments);
  fmt::format_to(out, " INCREMENT ATTEMPTS (WITH CUT-BACKS) {:>10}\n", st.attempts);
  fmt::format_to(out, " ITERATIONS {:>35}\n", st.iterations);
  fmt::format_to(out, " FACTORIZATIONS {:>31}\n", st.factorizations);
  if (!summary.warnings.empty()) {
    fmt::format_to(out, "\n {} WARNING(S):\n", summary.warnings.size());
    for (const auto& w : summary.warnings) fmt::format_to(out, "   {}\n", w);
  }
  if (summary.completed)
    fmt::format_to(out, "\n\n{:>10}THE ANALYSIS HAS BEEN COMPLETED\n", "");
  else
    fmt::format_to(out, "\n\n ***ERROR: {}\n\n{:>10}THE ANALYSIS HAS NOT BEEN COMPLETED\n",
                   summary.failure.empty() ? "the analysis stopped" : summary.failure, "");
  _out.close();
}

} // namespace gapfem
