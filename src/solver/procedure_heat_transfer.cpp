// *HEAT TRANSFER and *COUPLED TEMPERATURE-DISPLACEMENT steps: transient (capacity) terms, fixed
// increments without DELTMX, the DELTMX accuracy rule that drives automatic incrementation, and
// the heat balance of the step. Theory: docs/theory/thermal.md.
#include "common/log.hpp"
#include "solver/analysis_impl.hpp"
#include "solver/procedures.hpp"
#include "solver/thermal_step.hpp"

#include <optional>

namespace gapfem {

namespace {

class HeatTransferProcedure final : public StepProcedure {
 public:
  using StepProcedure::StepProcedure;

  void configure(const Step& step, StepContext& ctx) const override {
    ctx.transient = !step.inc.steady_state;
  }
  /// Transient steps: backward Euler (Abaqus integrates heat transfer so, "Uncoupled heat
  /// transfer analysis"); steady-state steps have no rates.
  std::unique_ptr<TimeIntegrator> make_integrator(const Step&,
                                                  const StepContext& ctx) const override {
    return ctx.transient ? std::make_unique<BackwardEuler>() : nullptr;
  }
  void adjust_rules(const Step& step, IncrementRules& rules) const override {
    if (fixed_transient_increments(step)) rules.growth = rules.shrink = 1.0;
  }
  void set_up(StepRun& r, bool resuming) override {
    _balance.emplace(_a.has_temperature_dofs, r.base.transient, r.u_step_start);
  }
  IncrementAccuracy check_accuracy(StepRun& r, const IncrementInfo& info, double dt) override;
  void accepted(StepRun& r, double dt) override {
    _balance->add_increment(_a.disc.dofs(), dt, r.prob->reactions(), _a.st.f_ext);
  }
  void finish(StepRun& r) override {
    _balance->finish(_a.disc, r.prob->context(), _a.st.u_start, r.prob->reactions(), _a.st.f_ext,
                     r.sum.checks);
  }
  void save(ArchiveWriter& a, const StepRun&) const override { _balance->save(a); }
  void restore(ArchiveReader& in, StepRun&) override { _balance->restore(in); }

 private:
  std::optional<HeatBalance> _balance;
};

/// Transient steps with DELTMX: the temperature change of the increment against DELTMX.
IncrementAccuracy HeatTransferProcedure::check_accuracy(StepRun& r, const IncrementInfo& info,
                                                        double dt) {
  const Step& step = *r.step;
  if (!r.base.transient || !(step.inc.deltmx > 0.0)) return {};
  const SolutionState& st = _a.st;
  const double dT =
      max_free_temperature_change(_a.disc.dofs(), r.loads->equations(), st.u, st.u_start);
  const TemperatureAccuracy acc = deltmx_rule(dT, step.inc.deltmx, r.rules.deltmx_cutback);
  IncrementAccuracy out;
  if (acc.ratio > 0.0) out.growth = acc.ratio;
  out.redo = acc.redo && r.ctrl->retry_smaller(acc.ratio);
  if (out.redo)
    log::progress("  increment {} attempt {}: temperature change {:.4g} exceeds DELTMX {:.4g}; "
                  "repeating it with a time increment of {:.4g}",
                  info.increment, info.attempts, dT, step.inc.deltmx, r.ctrl->next());
  return out;
}

} // namespace

std::unique_ptr<StepProcedure> make_heat_transfer_procedure(Analysis::Impl& a) {
  return std::make_unique<HeatTransferProcedure>(a);
}

} // namespace gapfem
