// The operators of a linear perturbation step about the committed state (*FREQUENCY): what the
// elements' tangent and mass are there, with the constraint rows that hold the state.
#include "solver/step_problem.hpp"

namespace gapfem {

StepProblem::PerturbationOperators StepProblem::perturbation_operators() {
  PerturbationOperators ops;
  const OperatorWeights keep = _weights;
  begin_increment(0.0, 0.0); // the committed state, the step's values at its start
  _weights = {1.0, 0.0, 0.0, 1.0};
  evaluate(true);
  ops.K = _K;
  ops.C = _C;
  _weights = {0.0, 0.0, 1.0, 1.0};
  evaluate(true);
  ops.M = _K;
  _weights = keep;
  return ops;
}

} // namespace gapfem
