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
#include "linalg/multiplier_columns.hpp"

#include <memory>
#include <unordered_map>

namespace gapfem {

class KktSolver final : public ConstrainedSolver {
 public:
  explicit KktSolver(const KktTuning& tuning = {});
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
  /// A factor is kept, the stiffness's drift from it, last measured plus twice its growth over
  /// the iteration before, stays within the reuse limit, and reusing the factor paid with as
  /// many changed rows as the last system had.
  bool matrix_optional() const override;
  /// A factor of its own for many right-hand sides (KktFactor, kkt_factor.hpp), with the
  /// augmentation of KktOptions's default; the Newton state (the kept factor) is untouched.
  std::unique_ptr<ConstrainedFactor> factorize(const CsrMatrix& K, const ConstraintBlock& C,
                                               bool symmetric,
                                               RunStatistics* stats = nullptr) override;
  /// CHOLMOD's symbolic estimate for the analysed pattern (the analysis is the one the next
  /// factorisation uses; the memory check stays with that factorisation).
  std::size_t factor_bytes_estimate() override;
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
  /// What to do with the kept factor for a system.
  struct Plan {
    bool exact_same = false; ///< the factor is of this very matrix and rows
    bool stale = false;      ///< reuse it (modified Newton)
    int changes = 0;         ///< constraint rows that differ from the factored ones
  };
  /// One system as the kept factor sees it, built by solve()'s stages.
  struct System {
    const ConstraintBlock* C = nullptr;  ///< the rows
    const ConstraintBlock* Cs = nullptr; ///< C, force columns scaled for the factor's springs
    const ConstraintBlock* Ch = nullptr; ///< Cs and the anti-rows of the rows gone
    ConstraintBlock scaled, ext;         ///< Cs's and Ch's storage where they differ from C
    std::vector<int> p_of;               ///< row of _frows each row repeats (-1: new)
    std::vector<int> gone;               ///< rows of _frows no longer present
    std::vector<double> R, ks;           ///< C's augmentation weights, stiffness along each row
    std::vector<double> d, p;            ///< Ch's Schur diagonal and preconditioner
    bool dense = false;                  ///< the dense multiplier path serves it
    bool cg = true;                      ///< the multiplier system is symmetric (CG, not GMRES)
    int max_iterations = 0;              ///< of the multiplier iteration
  };
  /// solve()'s stages: the rows' weights (from K or, without it, the factored diagonal); whether
  /// the dense multiplier path serves the factor (`reused`: it is kept from before); the rows as
  /// the factor sees them (Cs, Ch, d, p, the iteration's kind and limit); one solve for the
  /// right-hand side (bb, -gg).
  void row_weights(const CsrMatrix& K, const ConstraintBlock& C, const KktOptions& opt,
                   System& sys) const;
  bool use_dense(const System& sys, bool reused, const KktOptions& opt) const;
  void prepare_rows(System& sys, const KktOptions& opt, bool stale, bool unsymmetric) const;
  SchurResult solve_step(const System& sys, std::span<const double> bb, std::span<const double> gg,
                         std::span<double> x_u, std::span<double> x_l, const KktOptions& opt,
                         RunStatistics* stats);
  /// Compare a system with what the factor is of: p_of[r] is the row of _frows that row r of C
  /// repeats (-1: a new row), `gone` the rows of _frows no longer present.
  Plan compare(const CsrMatrix& K, const ConstraintBlock& C, bool symmetric, const KktOptions& opt,
               std::vector<int>& p_of, std::vector<int>& gone);
  /// A dense multiplier matrix of `rows` rows (unsymmetric with force `columns` of their own)
  /// pays (its factorisation against the solves it saves) and fits in memory.
  bool dense_pays(int rows, bool columns) const;
  /// Reusing the factor for a system of `rows` rows, `changes` of them changed, costs less than
  /// a factorisation (from the measured times).
  bool reuse_pays(int changes, int rows) const;
  /// The dense multiplier path can serve the current factor.
  bool dense_possible() const;
  /// The measured time of a solve with the current factor, or its estimate before one is timed.
  double solve_seconds() const;
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
  /// The current rows of C and the anti-rows of the rows gone (`gone`, rows of _frows) as
  /// combinations of kept columns (MultiplierColumns), made where missing; `cols` the same for
  /// their force columns when D (C, or C with columns scaled for the factor's springs) has
  /// columns of its own. False when the backend declines.
  bool dense_columns(const ConstraintBlock& C, const ConstraintBlock& D, std::span<const int> gone,
                     MultiplierColumns::Combination& rows, MultiplierColumns::Combination& cols,
                     RunStatistics* stats);
  /// The step for the right-hand side (bb, -gg) with the unmodified kept factor and the dense
  /// multiplier matrix Z_C^T Z_D - diag(d) of the current rows and the anti-rows of the rows
  /// gone: one forward and one backward solve. False (nothing solved) when it cannot be used: the
  /// backend declines the columns, or the matrix is singular (redundant rows).
  bool dense_step(const ConstraintBlock& C, const ConstraintBlock& D, std::span<const int> p_of,
                  std::span<const int> gone, std::span<const double> d, std::span<const double> bb,
                  std::span<const double> gg, std::span<double> x_u, std::span<double> x_l,
                  RunStatistics* stats);
  /// b1 = bb - C_P^T R_F gg: the right-hand side with the factor's springs of the kept rows.
  std::vector<double> spring_rhs(const ConstraintBlock& C, std::span<const int> p_of,
                                 std::span<const double> bb, std::span<const double> gg) const;
  /// dl = w + R_F (C du + gg) on the kept rows (w on the others), from the extended system's w.
  void multipliers(const ConstraintBlock& C, std::span<const int> p_of, std::span<const double> w,
                   std::span<const double> du, std::span<const double> gg,
                   std::span<double> dl) const;
  /// Solves (Ch M^-1 Ch^T - diag(d)) w = rhs with preconditioner diag(p); x = M^-1 Ch^T w.
  SchurResult schur(const ConstraintBlock& Ch, std::span<const double> d, std::span<const double> p,
                    std::span<const double> rhs, std::span<double> w, std::span<double> x, bool cg,
                    int max_iterations, std::span<const double> tol, RunStatistics* stats);

  /// The dense multiplier matrix is used up to this many rows, where its factorisation costs
  /// less than the back-substitutions it saves (at kDenseFlopRate flop/s, what one core's BLAS
  /// does).
  static constexpr int kMaxDenseRows = 4000;
  static constexpr double kDenseFlopRate = 1e10;
  /// Below this factorisation time the measured costs are noise: no reuse.
  static constexpr double kMinReusedFactorSeconds = 2e-3;

  std::shared_ptr<const SparsityPattern> _pattern;
  std::unique_ptr<LinearSolver> _cholmod, _umfpack;
  LinearSolver* _active = nullptr;
  bool _cholmod_ready = false, _umfpack_ready = false;
  bool _memory_checked = false; ///< check_memory() done for the analysed pattern
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
  bool _modify = true;        ///< modify the factor for changed rows (KktTuning::factor_updates)
  double _drift = 0.0;        ///< of the last system with its matrix, against the factored one
  double _drift_step = 0.0;   ///< its growth since the measurement before (infinity: unknown)
  double _max_drift = 1e-3;   ///< KktOptions::max_drift of that system
  int _last_changes = 0;      ///< changed rows of the last system
  int _last_rows = 0;         ///< its rows
  FactorReuse _reuse = FactorReuse::Auto; ///< KktOptions::reuse of the last system
  /// the dense multiplier path (KktTuning::dense_multipliers): the columns of the current
  /// factor, and whether the path failed for it (the Krylov path then serves the factor)
  bool _dense = true;
  bool _dense_failed = false;
  MultiplierColumns _mcols;
  double _dense_residual = 0.0; ///< max |S w - rhs| of the last dense step
};

} // namespace gapfem
