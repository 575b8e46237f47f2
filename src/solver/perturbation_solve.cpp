#include "solver/perturbation_solve.hpp"

namespace gapfem {

PerturbationResponse solve_perturbation(ConstrainedSolver& solver, StepProblem& prob,
                                        const StepProblem::PerturbationOperators& ops,
                                        RunStatistics* stats) {
  PerturbationResponse out;
  StepProblem::PerturbationLoad p = prob.perturbation_load(ops.C);
  out.any = p.any;
  out.du = p.prescribed;
  out.forces.assign(p.g.size(), 0.0);
  const EquationMap& eqm = prob.equations();
  const auto n = static_cast<std::size_t>(eqm.n_eq());
  if (!p.any || n == 0) return out;
  out.factor = solver.factorize(ops.K, ops.C, true, stats);
  std::vector<double> x(n, 0.0);
  {
    ScopedTimer timer(stats, TimeCategory::Solve);
    out.factor->solve(p.b, p.g, x, out.forces, 1);
  }
  for (std::size_t eq = 0; eq < n; ++eq) out.du[eqm.eq_slot[eq]] = x[eq];
  return out;
}

} // namespace gapfem
