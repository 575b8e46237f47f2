#pragma once
/// @file perturbation_solve.hpp
/// The linear static response to a perturbation about the base state (docs/theory/buckling.md
/// §1), shared by static perturbation steps and *BUCKLE: K0 du = b under the rows the base state
/// holds (closed gaps frozen, sticking friction, MPCs), the step's perturbation loads and
/// prescribed values as right sides.
#include "solver/step_problem.hpp"

namespace gapfem {

struct PerturbationResponse {
  std::vector<double> du;     ///< per slot: the perturbation's displacements (prescribed ones too)
  std::vector<double> forces; ///< per row of the operators' C: the rows' forces (multipliers)
  bool any = false;           ///< the step has a perturbation (a load or a prescribed value)
  /// the factorisation of (K0, C) the solve used (null when nothing was solved)
  std::unique_ptr<ConstrainedFactor> factor;
};

/// Solves the step's perturbation with `ops` (StepProblem::perturbation_operators of `prob`).
/// Throws SingularSystem when K0 under the rows is singular.
PerturbationResponse solve_perturbation(ConstrainedSolver& solver, StepProblem& prob,
                                        const StepProblem::PerturbationOperators& ops,
                                        RunStatistics* stats);

} // namespace gapfem
