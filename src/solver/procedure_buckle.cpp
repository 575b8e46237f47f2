// *BUCKLE steps (docs/theory/buckling.md): no increments; the load multipliers lambda at which
// the base state's stiffness K0 plus lambda times the differential stiffness K_Delta of the
// step's perturbation load becomes singular (Abaqus, "Eigenvalue buckling prediction"): the
// perturbation's static response du about the base state (perturbation_solve), K_Delta the
// change of the tangent along it (StepProblem::differential_stiffness), then Lanczos on
// K0 x = lambda (-K_Delta) x (linalg/buckling_solver.cpp). The writers get a frame per mode.
#include "solver/analysis_impl.hpp"
#include "solver/modal_quantities.hpp"
#include "solver/mode_frames.hpp"
#include "solver/perturbation_solve.hpp"
#include "solver/procedures.hpp"

#include <cmath>
#include <fmt/format.h>

namespace gapfem {
namespace {

EigenRequest request(const BuckleSettings& b) {
  EigenRequest req;
  req.count = b.count;
  if (b.min_eigenvalue) req.lower = *b.min_eigenvalue;
  if (b.max_eigenvalue && b.solver == BuckleSettings::Solver::Lanczos)
    req.upper = *b.max_eigenvalue;
  return req;
}

class BuckleProcedure final : public StepProcedure {
 public:
  using StepProcedure::StepProcedure;
  bool incremental() const override { return false; }
  void check(const Step& step) const override;
  void run(StepRun& r) override;

 private:
  EigenPairs extract(StepRun& r, const StepProblem::PerturbationOperators& ops);
  EigenSummary summary(const StepRun& r, EigenPairs& pairs) const;
};

EigenPairs BuckleProcedure::extract(StepRun& r, const StepProblem::PerturbationOperators& ops) {
  const BuckleSettings& b = r.step->buckle;
  const std::string what = fmt::format("step {}", r.step->number);
  PerturbationResponse resp;
  try {
    resp = solve_perturbation(*_a.solver, *r.prob, ops, &_a.stats);
  } catch (const SingularSystem& e) {
    throw InputError(b.loc, what,
                     fmt::format("the stiffness of the base state cannot be factorised ({}): the "
                                 "model is free to move (add boundary conditions) or the base "
                                 "state is past a stability limit",
                                 e.what()));
  }
  if (!resp.any)
    throw InputError(b.loc, what,
                     "the *BUCKLE step has no perturbation load: the buckling loads are multiples "
                     "of the loads given in the step (*CLOAD, *DLOAD, *DSLOAD or nonzero "
                     "*BOUNDARY values); give the load pattern there");
  const bool follower = std::any_of(r.step->dloads.begin(), r.step->dloads.end(),
                                    [](const DistributedLoad& d) { return !d.propagated; });
  CsrMatrix G = r.prob->differential_stiffness(resp.du, follower);
  for (double& v : G.values()) v = -v;
  EigenPairs pairs;
  try {
    pairs = constrained_buckling_pairs(*_a.solver, ops.K, G, ops.C, request(b), &_a.stats,
                                       std::move(resp.factor));
  } catch (const EigenProblemError& e) {
    throw InputError(b.loc, what, e.what());
  } catch (const SingularSystem& e) {
    throw InputError(
        b.loc, what,
        fmt::format("the stiffness of the base state cannot be factorised ({})", e.what()));
  }
  // SUBSPACE: eigenvalues until the count is reached or one exceeds the maximum of interest
  if (b.solver == BuckleSettings::Solver::Subspace && b.max_eigenvalue) {
    const std::size_t n = static_cast<std::size_t>(r.prob->equations().n_eq());
    std::size_t keep = 0;
    while (keep < pairs.values.size() && (keep == 0 || pairs.values[keep - 1] <= *b.max_eigenvalue))
      ++keep;
    if (keep < pairs.values.size() && static_cast<int>(keep) < b.count)
      _a.solver_warnings.push_back(fmt::format(
          "step {}: the maximum eigenvalue of interest {} (field 2 of *BUCKLE) ended the "
          "extraction after {} of {} eigenvalues, as in Abaqus; in CalculiX's layout this field "
          "is the accuracy: leave it blank to get all {}",
          r.step->number, *b.max_eigenvalue, keep, b.count, b.count));
    pairs.values.resize(keep);
    pairs.vectors.resize(keep * n);
  }
  return pairs;
}

void BuckleProcedure::check(const Step& step) const {
  const auto given = [](const auto& e) { return !e.propagated; };
  const bool loads =
      std::any_of(step.cloads.begin(), step.cloads.end(), given) ||
      std::any_of(step.dloads.begin(), step.dloads.end(), given) ||
      std::any_of(step.boundary.begin(), step.boundary.end(),
                  [](const BoundaryEntry& b) { return !b.propagated && b.value != 0.0; });
  if (!loads)
    throw InputError(step.buckle.loc, fmt::format("step {}", step.number),
                     "the *BUCKLE step has no perturbation load: the buckling loads are multiples "
                     "of the loads given in the step (*CLOAD, *DLOAD, *DSLOAD or nonzero "
                     "*BOUNDARY values); give the load pattern there");
}

/// The largest displacement entry +1, the largest rotation where no node moves (Abaqus's
/// normalisation of buckling modes).
EigenSummary BuckleProcedure::summary(const StepRun& r, EigenPairs& pairs) const {
  EigenSummary sum;
  sum.buckling = true;
  const EquationMap& eqm = r.prob->equations();
  const DofMap& dofs = _a.disc.dofs();
  const auto n = static_cast<std::size_t>(eqm.n_eq());
  for (std::size_t k = 0; k < pairs.values.size(); ++k) {
    std::span<double> phi(pairs.vectors.data() + k * n, n);
    double big = 0.0;
    for (std::size_t eq = 0; eq < n; ++eq)
      if (static_cast<int>(dofs.slot_dof(eqm.eq_slot[eq])) < 3 &&
          std::abs(phi[eq]) > std::abs(big) * (1.0 + 1e-12))
        big = phi[eq];
    if (big == 0.0) big = phi[largest_entry(phi, dofs, eqm)];
    if (big != 0.0)
      for (double& v : phi) v /= big;
    ModeInfo m;
    m.mode = static_cast<int>(k) + 1;
    m.eigenvalue = pairs.values[k];
    sum.modes.push_back(m);
  }
  return sum;
}

void BuckleProcedure::run(StepRun& r) {
  check(*r.step);
  const StepProblem::PerturbationOperators ops = r.prob->perturbation_operators(false);
  EigenPairs pairs = extract(r, ops);
  EigenSummary sum = summary(r, pairs);
  log::progress("  {} buckling eigenvalue(s) (load multipliers of the step's loads):",
                sum.modes.size());
  for (const ModeInfo& m : sum.modes)
    log::progress("  mode {:4d}  eigenvalue {:13.6e}", m.mode, m.eigenvalue);
  log::progress("  eigensolver {}: {} factorisation(s), {} back-substitutions, {} restarts",
                pairs.method, pairs.factorizations, pairs.operations, pairs.restarts);
  if (std::any_of(sum.modes.begin(), sum.modes.end(),
                  [](const ModeInfo& m) { return m.eigenvalue < 0.0; }))
    _a.solver_warnings.push_back(fmt::format(
        "step {}: negative buckling eigenvalues: the structure would buckle under the "
        "perturbation load reversed (give a minimum eigenvalue of 0 with EIGENSOLVER=LANCZOS "
        "to leave them out)",
        r.step->number));
  write_mode_frames(_a, r, pairs, sum);
  r.sum.increments = static_cast<int>(sum.modes.size());
}

} // namespace

std::unique_ptr<StepProcedure> make_buckle_procedure(Analysis::Impl& a) {
  return std::make_unique<BuckleProcedure>(a);
}

} // namespace gapfem
