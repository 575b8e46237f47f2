#pragma once
/// @file procedure.hpp
/// A step's procedure as an object. The analysis (analysis.cpp) runs every step in the same
/// stages — set up, the increments (Newton through the step problem, accept or reject), finish —
/// and asks the step's procedure at each stage for what differs between procedures: *STATIC
/// (automatic stabilization), *HEAT TRANSFER and *COUPLED TEMPERATURE-DISPLACEMENT (transient
/// terms, the DELTMX accuracy rule, the heat balance), *SUBSTRUCTURE GENERATE (no increments: one
/// reduction). A new procedure (*DYNAMIC, *FREQUENCY, *BUCKLE, *MODAL DYNAMIC, *VISCO) is a new
/// class in its own file plus one registration (register_procedure), not a branch in the analysis
/// (docs/architecture.md, "Adding a procedure").
#include "common/archive.hpp"
#include "model/step.hpp"
#include "solver/analysis.hpp"
#include "solver/time_integrator.hpp"

#include <functional>
#include <memory>
#include <string_view>

namespace gapfem {

struct StepRun;
struct StepContext;
struct IncrementRules;
struct IncrementInfo;

/// What a procedure's accuracy check decides after Newton converged (e.g. DELTMX).
struct IncrementAccuracy {
  /// The increment is not accurate enough: repeat it (the procedure has already asked the
  /// increment controller for the smaller size, IncrementController::retry_smaller).
  bool redo = false;
  /// The largest ratio of the next to this increment the procedure allows (0: no bound).
  double growth = 0.0;
  const char* check = "DELTMX exceeded"; ///< why the increment is repeated (its reports)
};

class StepProcedure {
 public:
  explicit StepProcedure(Analysis::Impl& analysis) : _a(analysis) {}
  virtual ~StepProcedure() = default;
  StepProcedure(const StepProcedure&) = delete;
  StepProcedure& operator=(const StepProcedure&) = delete;

  /// The context every element evaluation of the step shares: what the procedure adds to it
  /// (e.g. transient terms).
  virtual void configure(const Step& step, StepContext& ctx) const {}
  /// The step's time integrator (solver/time_integrator.hpp), given to the step problem: none
  /// for a quasi-static procedure (no rates; the default).
  virtual std::unique_ptr<TimeIntegrator> make_integrator(const Step& step,
                                                          const StepContext& ctx) const {
    return nullptr;
  }
  /// The increment controller's rules (e.g. fixed transient increments without DELTMX).
  virtual void adjust_rules(const Step& step, IncrementRules& rules) const {}
  /// After the step problem exists (its loads, equations and stiffness hints). `resuming`: the
  /// step continues from a restart record, whose state restore() brings next.
  virtual void set_up(StepRun& r, bool resuming) {}
  /// The terminal's word on the set-up, after the step's own line (and a resumed step's).
  virtual void report_set_up(const StepRun& r) const {}

  /// `gapfem check` (and the analysis, before the step): what the procedure requires of the
  /// model beyond its loads; InputError when it is missing.
  virtual void check(const Step& step) const {}

  /// False: the procedure has no increments; run() does all of its work.
  virtual bool incremental() const { return true; }
  virtual void run(StepRun& r) {}

  /// After Newton converged on an increment of size `dt`: the accuracy check that drives
  /// automatic incrementation.
  virtual IncrementAccuracy check_accuracy(StepRun& r, const IncrementInfo& info, double dt) {
    return {};
  }
  /// An accepted increment of size dt, committed (before its frame is written).
  virtual void accepted(StepRun& r, double dt) {}
  /// A failed attempt, before the increment is cut back.
  virtual void rejected(StepRun& r) {}
  /// After the step's last increment and its checks (StepSummary::checks).
  virtual void finish(StepRun& r) {}

  /// Restart: the procedure's own state in a record, and back.
  virtual void save(ArchiveWriter& a, const StepRun& r) const {}
  virtual void restore(ArchiveReader& in, StepRun& r) {}

 protected:
  Analysis::Impl& _a;
};

using ProcedureFactory = std::function<std::unique_ptr<StepProcedure>(Analysis::Impl&)>;

/// Adds (or replaces) the class that runs steps of procedure `p`.
void register_procedure(Procedure p, ProcedureFactory make);
/// The procedure object of a step (a *STATIC step with *STEP, PERTURBATION runs as a linear
/// static perturbation); std::logic_error when nothing is registered for it.
std::unique_ptr<StepProcedure> make_procedure(const Step& step, Analysis::Impl& analysis);

} // namespace gapfem
