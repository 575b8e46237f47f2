// *STATIC steps with *STEP, PERTURBATION (docs/theory/buckling.md §1): no increments; the linear
// response to the step's loads and prescribed values about the base state, whose stiffness and
// frozen contact status it uses (Abaqus, "General and linear perturbation procedures"). The frame
// holds the perturbation alone (U, UR); the base state stays as it was for the next general step.
#include "solver/analysis_impl.hpp"
#include "solver/perturbation_solve.hpp"
#include "solver/procedures.hpp"

#include <fmt/format.h>

namespace gapfem {
namespace {

class StaticPerturbationProcedure final : public StepProcedure {
 public:
  using StepProcedure::StepProcedure;
  bool incremental() const override { return false; }
  void run(StepRun& r) override;
};

void StaticPerturbationProcedure::run(StepRun& r) {
  const Step& step = *r.step;
  const std::string what = fmt::format("step {}", step.number);
  const StepProblem::PerturbationOperators ops = r.prob->perturbation_operators(false);
  PerturbationResponse resp;
  try {
    resp = solve_perturbation(*_a.solver, *r.prob, ops, &_a.stats);
  } catch (const SingularSystem& e) {
    throw InputError(step.loc, what,
                     fmt::format("the stiffness of the base state cannot be factorised ({}): the "
                                 "model is free to move under the perturbation (add boundary "
                                 "conditions)",
                                 e.what()));
  }
  if (!resp.any)
    _a.solver_warnings.push_back(fmt::format(
        "step {} (static perturbation): the step gives no load and no prescribed value: its "
        "response is zero",
        step.number));
  double big = 0.0;
  for (double v : resp.du) big = std::max(big, std::abs(v));
  log::progress("  linear perturbation about the base state: largest |du| {:.6e}", big);
  bool field_elements = false;
  std::optional<Frame> fr = _a.frame_due(step, *r.prob, 1, true, 0.0, false, field_elements);
  fr->step_time = 0.0;
  _a.perturbation_nodes(resp.du, *fr);
  _a.perturbation_elements(step, *r.prob, resp.du, field_elements, *fr);
  ScopedTimer timer(&_a.stats, TimeCategory::Output);
  for (auto* w : _a.writers) w->frame(_a.model, r.index, *fr);
  r.sum.increments = 1;
}

} // namespace

std::unique_ptr<StepProcedure> make_static_perturbation_procedure(Analysis::Impl& a) {
  return std::make_unique<StaticPerturbationProcedure>(a);
}

} // namespace gapfem
