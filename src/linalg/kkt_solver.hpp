#pragma once
/// @file kkt_solver.hpp
/// Exact solution of the Newton system with Lagrange-multiplier constraints
///
///     [ K  C^T ] [du]   [ b ]
///     [ C   0  ] [dl] = [-g ]
///
/// without ever factorising an indefinite matrix (docs/theory/gap_elements.md, "Solving the
/// constrained system"): K is augmented to M = K + C^T R C (R diagonal, R_i ~ 100 x the stiffness
/// at the constraint's DOFs), which leaves the solution unchanged and is positive definite even when
/// a body is held only by closed gaps; the multipliers then solve the Schur system
/// (C M^-1 C^T) dl = C M^-1 b1 + g by preconditioned CG (GMRES when K is unsymmetric) with the
/// preconditioner R, whose spectrum is clustered in [1/(1+1/100), 1], so a few back-substitutions
/// with one factor give the exact step. The augmentation only touches entries inside each gap
/// element's block, so the sparsity pattern never changes with contact status.
#include "common/timer.hpp"
#include "linalg/constraint_block.hpp"
#include "linalg/linear_solver.hpp"

#include <memory>

namespace gapfem {

struct KktOptions {
  double augmentation = 100.0;       ///< R_i = augmentation x stiffness at the row's DOFs
  double constraint_tolerance = 0.0; ///< stop the multiplier iteration when |C du + g| below this
  int max_iterations = 200;
};

struct KktStatistics {
  int schur_iterations = 0;
  int solves = 0;
  bool used_unsymmetric = false;
  bool reused_factor = false; ///< the matrix equalled the one already factored
  double constraint_residual = 0.0;
};

class KktSolver {
public:
  KktSolver();
  ~KktSolver();
  /// Symbolic analysis for a pattern (once per step).
  void analyze(std::shared_ptr<const SparsityPattern> pattern);
  /// Solve; K is modified in place (augmented). du has n entries, dl one per constraint row.
  /// Throws SingularSystem when M is singular (a rigid-body mode).
  KktStatistics solve(CsrMatrix& K, std::span<const double> b, const ConstraintBlock& C,
                      std::span<double> du, std::span<double> dl, bool symmetric,
                      const KktOptions& options, RunStatistics* stats = nullptr);

private:
  void factorize(const CsrMatrix& M, bool symmetric, RunStatistics* stats);
  void back_solve(std::span<const double> b, std::span<double> x, RunStatistics* stats);
  std::shared_ptr<const SparsityPattern> _pattern;
  std::unique_ptr<LinearSolver> _cholmod, _umfpack;
  LinearSolver* _active = nullptr;
  bool _cholmod_ready = false, _umfpack_ready = false;
  int _solves = 0;
  std::vector<double> _factored; ///< the matrix values behind the current factor
  bool _factored_symmetric = true;
};

} // namespace gapfem
