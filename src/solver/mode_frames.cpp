#include "solver/mode_frames.hpp"

#include "solver/analysis_impl.hpp"

namespace gapfem {

void write_mode_frames(Analysis::Impl& a, StepRun& r, const EigenPairs& pairs,
                       const EigenSummary& sum) {
  const Step& step = *r.step;
  for (auto* w : a.writers) w->modes(a.model, r.index, sum);
  const EquationMap& eqm = r.prob->equations();
  const std::size_t n = static_cast<std::size_t>(eqm.n_eq());
  for (std::size_t k = 0; k < sum.modes.size(); ++k) {
    bool field_elements = false;
    std::optional<Frame> fr =
        a.frame_due(step, *r.prob, sum.modes[k].mode, true, 0.0, false, field_elements);
    fr->last_in_step = k + 1 == sum.modes.size();
    fr->mode = sum.modes[k];
    fr->step_time = 0.0;
    std::vector<double> slots(static_cast<std::size_t>(a.disc.dofs().n_slots()), 0.0);
    for (std::size_t eq = 0; eq < n; ++eq) slots[eqm.eq_slot[eq]] = pairs.vectors[k * n + eq];
    a.perturbation_nodes(slots, *fr);
    a.perturbation_elements(step, *r.prob, slots, field_elements, *fr);
    ScopedTimer timer(&a.stats, TimeCategory::Output);
    for (auto* w : a.writers) w->frame(a.model, r.index, *fr);
  }
}

} // namespace gapfem
