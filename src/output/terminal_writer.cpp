#include "output/terminal_writer.hpp"

#include "common/log.hpp"
#include "model/model.hpp"

namespace gapfem {

void TerminalWriter::begin(const Model& model) {
  log::info("{}: {} nodes, {} elements, {} step(s)",
            model.job_name.empty() ? "job" : model.job_name, model.mesh.n_nodes(),
            model.mesh.n_elements(), model.steps.size());
}

void TerminalWriter::begin_step(const Model& model, int step_index) {
  const Step& step = model.steps[step_index];
  if (step.perturbation) // no time: a perturbation about the base state
    log::info("Step {}{}{}: {} (linear perturbation)", step.number, step.name.empty() ? "" : " ",
              step.name, procedure_name(step.procedure));
  else
    log::info("Step {}{}{}: {}, time period {:g}", step.number, step.name.empty() ? "" : " ",
              step.name, procedure_name(step.procedure), step.inc.period);
}

void TerminalWriter::increment(const IncrementInfo& info) {
  log::progress("  step {} inc {:>4} att {}  step time {:<11.5g} dt {:<11.4g} "
                "{:>3} iterations{}",
                info.step, info.increment, info.attempts, info.step_time, info.dt, info.iterations,
                info.deltmx_exceeded ? fmt::format("  {}: repeated", info.accuracy_check)
                : info.converged     ? std::string()
                                     : std::string("  not converged: cut back"));
}

void TerminalWriter::end_step(const Model& model, int step_index, const StepSummary& s) {
  if (step_index >= 0 && step_index < static_cast<int>(model.steps.size()) &&
      model.steps[step_index].perturbation) { // no equilibrium to check: the base state stays
    if (model.steps[step_index].procedure == Procedure::Frequency)
      log::info("Step {} completed: {} eigenvalues", s.step, s.increments);
    else
      log::info("Step {} completed (linear perturbation)", s.step);
    return;
  }
  if (s.converged)
    log::info("Step {} completed: {} increments ({} attempts), {} iterations", s.step, s.increments,
              s.attempts, s.iterations);
  else
    log::info("Step {} NOT completed: {}", s.step,
              s.failure.empty() ? "no reason given" : s.failure);
  const StepChecks& c = s.checks;
  if (c.n_gaps > 0) {
    log::info("  gaps: {} open, {} closed, {} stick, {} slip; max penetration "
              "{:.4g}{}",
              c.n_open, c.n_closed, c.n_stick, c.n_slip, c.max_penetration,
              c.max_penetration_elem
                  ? fmt::format(" (element {})", model.label_of_key(c.max_penetration_elem))
                  : "");
    if (c.max_tensile_force > 0)
      log::info("  max tensile force in a closed gap {:.4g} (element {})", c.max_tensile_force,
                model.label_of_key(c.max_tensile_elem));
  }
  const bool mechanical = step_index < 0 || step_index >= static_cast<int>(model.steps.size()) ||
                          model.steps[step_index].procedure != Procedure::HeatTransfer;
  if (mechanical) {
    if (c.force_scale > 0)
      log::info("  equilibrium error {:.3e} ({:.2e} of force scale {:.4g})", c.equilibrium_error,
                c.relative_equilibrium, c.force_scale);
    else
      log::info("  equilibrium error {:.3e}", c.equilibrium_error);
  }
  if (c.thermal) {
    // below the zero-flux level (1e-5 x 1e-2, newton.hpp) no heat flows: a ratio would be noise
    if (c.heat_scale > 0 && c.heat_scale <= 1e-7)
      log::info("  heat balance error {:.3e} (no heat flows: heat scale {:.3g})",
                c.heat_balance_error, c.heat_scale);
    else if (c.heat_scale > 0)
      log::info("  heat balance error {:.3e} ({:.2e} of heat scale {:.4g})", c.heat_balance_error,
                c.relative_heat_balance, c.heat_scale);
    else
      log::info("  heat balance error {:.3e}", c.heat_balance_error);
  }
  if (c.max_damping_force != 0.0) log::info("  max damping force {:.4g}", c.max_damping_force);
  if (c.hourglass)
    log::info("  hourglass control: ALLAE {:.4g}, ALLSE {:.4g}{}", c.allae, c.allse,
              c.allse + c.allae > 0
                  ? fmt::format(" (ALLAE/(ALLSE+ALLAE) {:.3g})", c.allae / (c.allse + c.allae))
                  : std::string());
  if (c.dynamic)
    log::info("  energies: ALLKE {:.4g}, ALLIE {:.4g} (ALLSE {:.4g}), ALLVD {:.4g}, ALLFD {:.4g}, "
              "ALLKL {:.4g}, ALLWK {:.4g}; ETOTAL changed by {:.3g} in the step ({:.2e} of the "
              "largest energy{})",
              c.energies.allke, c.energies.allie, c.energies.allse, c.energies.allvd,
              c.energies.allfd, c.energies.allkl, c.energies.allwk, c.energy_change,
              c.energy_scale > 0 ? c.energy_change / c.energy_scale : 0.0,
              c.conserving ? "; trapezoidal rule: conserving" : "; HHT dissipates");
  if (c.stabilized)
    log::info("  stabilization: damping factor {:.4g}, ALLSD {:.4g}, ALLIE {:.4g}{}",
              c.stabilization_factor, c.allsd, c.allie,
              c.allie > 0 ? fmt::format(" (ALLSD/ALLIE {:.3g})", c.allsd / c.allie)
                          : std::string());
}

void TerminalWriter::end(const Model& model, const RunSummary& s) {
  const RunStatistics& st = s.stats;
  if (s.completed)
    log::info("Analysis completed in {:.2f} s", s.wall_seconds);
  else
    log::info("Analysis NOT completed after {:.2f} s: {}", s.wall_seconds,
              s.failure.empty() ? "no reason given" : s.failure);
  log::info("  {} increments ({} attempts), {} iterations, {} factorizations ({} contact rows "
            "updated in a factor), {} solves, {} evaluations ({} with the tangent)",
            st.increments, st.attempts, st.iterations, st.factorizations, st.factor_updates,
            st.linear_solves, st.evaluations, st.tangent_assemblies);
  double total = 0.0;
  for (double t : st.seconds) total += t;
  if (total > 0)
    for (int c = 0; c < kNumTimeCategories; ++c)
      if (st.seconds[c] > 0)
        log::info("  {:<14}{:>10.3f} s {:>6.1f} %",
                  time_category_name(static_cast<TimeCategory>(c)), st.seconds[c],
                  100.0 * st.seconds[c] / total);
  if (s.peak_memory_kb > 0) log::info("  peak memory {:.1f} MiB", s.peak_memory_kb / 1024.0);
  if (!s.warnings.empty()) {
    log::info("{} warning(s):", s.warnings.size());
    for (const auto& w : s.warnings) log::info("  {}", w);
  }
}

} // namespace gapfem
