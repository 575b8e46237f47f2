#pragma once
/// @file kkt_solver.hpp
/// Exact solution of the Newton system with Lagrange-multiplier constraints
///
///     [ K  C^T ] [du]   [ b ]
///     [ C   0  ] [dl] = [-g ]
///
/// without ever factorising an indefinite matrix (docs/theory/gap_elements.md, "Solving the
/// constrained system"): K is augmented to M = K + C^T R C (R diagonal, R_i ~ 100 x the stiffness
/// at the constraint's DOFs), which leaves the solution unchanged and is positive definite even
/// when a body is held only by closed gaps; the multipliers then solve the Schur system (C M^-1
/// C^T) dl = C M^-1 b1 + g by preconditioned CG (GMRES when K is unsymmetric) with the
/// preconditioner R, whose spectrum is clustered in [1/(1+1/100), 1], so a few back-substitutions
/// with one factor give the exact step. The augmentation only touches entries inside each gap
/// element's block, so the sparsity pattern never changes with contact status.
///
/// Factorise rarely, solve often (docs/performance.md): the factor of M_F = K_F + C_F^T R C_F is
/// kept. A later system whose K is close to K_F (relative drift below KktOptions::max_drift) and
/// whose contact rows differ from C_F in a few rows is solved with the old factor: rows that closed
/// since are plain multiplier rows, rows that opened are cancelled exactly by "anti-rows" (the
/// spring c R c^T in M_F is removed through an extra unknown mu = R c.du with the equation
/// c.du - mu/R = 0). The constraint rows are then met exactly; only K_F - K is left out, which
/// makes the step a modified-Newton step (the residual is always the true one, so the converged
/// answer is the same). Whether reuse pays is decided from the measured factorisation and solve
/// times.
#include "linalg/constrained_solver.hpp"
#include "linalg/linear_solver.hpp"

#include <memory>
#include <unordered_map>

namespace gapfem {

class KktSolver final : public ConstrainedSolver {
 public:
  KktSolver();
  ~KktSolver() override;
  std::string_view name() const override { return "cholmod"; }
  /// AnalysisError when a factor of `factor_bytes` (the symbolic analysis's prediction) cannot
  /// fit in the memory left (common/memory.hpp), before anything is factorised.
  void check_memory(std::size_t factor_bytes) const;
  /// Symbolic analysis for a pattern (once per step).
  void analyze(std::shared_ptr<const SparsityPattern> pattern) override;
  /// Drop the factor (and the unsymmetric solver's value-dependent analysis): the next solve
  /// factorises afresh, exactly as a new solver would. A restart point calls it, so that a
  /// restarted run repeats the uninterrupted one (docs/restart.md).
  void forget_factor() override;
  /// Solve; K may be modified in place (augmented). du has n entries, dl one per constraint row.
  /// Throws SingularSystem when M is singular (a rigid-body mode).
  KktStatistics solve(CsrMatrix& K, std::span<const double> b, const ConstraintBlock& C,
                      std::span<double> du, std::span<double> dl, bool symmetric,
                      const KktOptions& options, RunStatistics* stats = nullptr) override;

 private:
  struct SchurResult {
    int iterations = 0;
    double residual = 0.0; ///< max |row residual|
    double ratio = 0.0;    ///< max |row residual| / its tolerance (converged: <= 1)
  };
  void factorize(const CsrMatrix& M, bool symmetric, RunStatistics* stats);
  /// Factorise K augmented by the rows of C with weights R, remembering K and the rows.
  void fresh_factor(CsrMatrix& K, const ConstraintBlock& C, std::span<const double> R,
                    std::span<const double> ks, bool symmetric, RunStatistics* stats);
  void back_solve(std::span<const double> b, std::span<double> x, RunStatistics* stats);
  /// Make the factor exact for the current rows: update it with the springs of the new rows
  /// (p_of < 0) and remove the springs of the rows gone (LinearSolver::modify).
  /// Afterwards every row is a kept row. False (factor dropped) when the backend cannot or the
  /// result is not positive definite.
  bool modify_factor(const ConstraintBlock& C, std::span<const double> R,
                     std::span<const double> ks, std::vector<int>& p_of, std::vector<int>& gone,
                     RunStatistics* stats);
  /// Solves (Ch M^-1 Ch^T - diag(d)) w = rhs with preconditioner diag(p); x = M^-1 Ch^T w.
  SchurResult schur(const ConstraintBlock& Ch, std::span<const double> d, std::span<const double> p,
                    std::span<const double> rhs, std::span<double> w, std::span<double> x, bool cg,
                    int max_iterations, std::span<const double> tol, RunStatistics* stats);

  std::shared_ptr<const SparsityPattern> _pattern;
  std::unique_ptr<LinearSolver> _cholmod, _umfpack;
  LinearSolver* _active = nullptr;
  bool _cholmod_ready = false, _umfpack_ready = false;
  int _solves = 0;
  // What the current factor is of: K_F (before augmentation) and the augmenting rows.
  std::vector<double> _factored;
  double _factored_scale = 1.0;       ///< max |diag K_F|
  std::vector<double> _factored_diag; ///< |diag K_F| per row (floored), for the drift measure
  bool _factored_symmetric = true;
  ConstraintBlock _frows;  ///< rows of C_F (g unused)
  std::vector<double> _fR; ///< their weights
  std::vector<double>
      _fks; ///< the structure's stiffness along each (the preconditioner's estimate)
  std::unordered_map<std::int64_t, int> _frow_of; ///< multiplier index -> row of _frows
  double _t_factor = 0.0, _t_solve = 0.0;         ///< measured seconds (last / running mean)
  double _t_update_row = 0.0; ///< measured seconds per row added to or removed from the factor
  bool _modify = true;        ///< modify the factor for changed rows (GAPFEM_FACTOR_UPDATES=0: no)
};

} // namespace gapfem
