// *STATIC steps: Newton increments with Abaqus's automatic incrementation; what is particular to
// them is the automatic stabilization (*STATIC, STABILIZE; carried into later steps with
// CONTINUE=YES). Theory: docs/theory/stabilization.md.
#include "common/log.hpp"
#include "solver/analysis_impl.hpp"
#include "solver/procedures.hpp"
#include "solver/stabilization.hpp"

#include <fmt/format.h>

namespace gapfem {

namespace {

class StaticProcedure final : public StepProcedure {
 public:
  using StepProcedure::StepProcedure;

  void set_up(StepRun& r, bool resuming) override;
  void report_set_up(const StepRun& r) const override;
  void accepted(StepRun& r, double dt) override;
  void rejected(StepRun& r) override;
  void finish(StepRun& r) override;
  void save(ArchiveWriter& a, const StepRun& r) const override;
  void restore(ArchiveReader& in, StepRun& r) override;

 private:
  bool _on = false;       ///< the step is stabilized (its own STABILIZE or a carried one)
  Stabilization _spec;    ///< which
  bool _own = false;      ///< the step's own STABILIZE (not carried from an earlier step)
  int _carried_from = -1; ///< carried: the step whose STABILIZE it is
  double _c0 = 0.0;       ///< the step's initial damping factor
};

void StaticProcedure::set_up(StepRun& r, bool resuming) {
  Analysis::Impl& a = _a;
  const Step& step = *r.step;
  _own = step.stabilize.on;
  _on = _own || a.carried_stabilization.on;
  if (!_on) return;
  _spec = _own ? step.stabilize : a.carried_stabilization;
  _carried_from = a.carried_stabilization_step;
  StepProblem& prob = *r.prob;
  if (!a.unit_mass)
    a.unit_mass = std::make_shared<const std::vector<double>>(
        unit_density_mass(a.disc, a.assembler, prob.fields(), prob.context()));
  if (resuming) {
    // the record's factors (restore)
  } else if (_own) {
    const std::vector<double> diag =
        a.assembler.diagonal_stiffness(prob.fields(), prob.context(), /*skip_gaps=*/true);
    const double dt0 = step.inc.initial > 0 ? step.inc.initial : r.loads->period();
    _c0 = initial_stabilization_factor(_spec, dt0, *a.unit_mass, diag);
  } else {
    _c0 = a.carried_factor;
  }
  prob.set_stabilization(a.unit_mass, _c0);
}

void StaticProcedure::report_set_up(const StepRun& r) const {
  if (!_on) return;
  log::progress("  automatic stabilization: damping factor {:.4g}{}",
                r.prob->stabilization_factor(),
                _spec.allsdtol > 0 ? fmt::format(" (adaptive, ALLSDTOL {:.3g})", _spec.allsdtol)
                                   : std::string());
}

void StaticProcedure::accepted(StepRun& r, double dt) {
  if (!_on) return;
  const SolutionState& st = _a.st;
  r.prob->set_stabilization(
      _a.unit_mass,
      adapted_stabilization_factor(_spec, r.prob->stabilization_factor(), st.allsd, st.allie));
}

void StaticProcedure::rejected(StepRun& r) {
  if (_on && r.prob->stabilization_factor() < 1e3 * _c0) // more damping for the retry
    r.prob->set_stabilization(_a.unit_mass, 2.0 * r.prob->stabilization_factor());
}

void StaticProcedure::finish(StepRun& r) {
  Analysis::Impl& a = _a;
  const SolutionState& st = a.st;
  const double factor = r.prob->stabilization_factor();
  if (_on) {
    StepChecks& c = r.sum.checks;
    c.stabilized = true;
    c.stabilization_factor = factor;
    c.allsd = st.allsd;
    c.allie = st.allie;
    if (_spec.allsdtol > 0 && st.allie > 0 && st.allsd > _spec.allsdtol * st.allie)
      a.solver_warnings.push_back(
          fmt::format("step {}: the stabilization dissipated {:.3g} of the internal energy "
                      "(ALLSD {:.4g}, ALLIE {:.4g}), more than ALLSDTOL {:.3g}; check that the "
                      "damping does not change the answer",
                      r.step->number, st.allsd / st.allie, st.allsd, st.allie, _spec.allsdtol));
  }
  // what the next step continues (CONTINUE=YES), replacing what this one was given
  const bool carry = _on && _spec.carry;
  a.carried_stabilization = carry ? _spec : Stabilization{};
  a.carried_stabilization_step = !carry ? -1 : (_own ? r.index : _carried_from);
  a.carried_factor = _on ? factor : 0.0;
}

void StaticProcedure::save(ArchiveWriter& a, const StepRun& r) const {
  a.pod(r.prob->stabilization_factor());
  a.pod(_c0);
}

void StaticProcedure::restore(ArchiveReader& in, StepRun& r) {
  const auto factor = in.get<double>();
  in.pod(_c0);
  if (_on) r.prob->set_stabilization(_a.unit_mass, factor);
}

} // namespace

std::unique_ptr<StepProcedure> make_static_procedure(Analysis::Impl& a) {
  return std::make_unique<StaticProcedure>(a);
}

} // namespace gapfem
