#pragma once
/// @file constrained_solver.hpp
/// The seam between Newton and the linear algebra: a solver of the constrained Newton system
///
///     [ K  D ] [du]   [ b ]          D = C^T unless the rows carry their own columns,
///     [ C -E ] [dl] = [-g ]          E = diag(compliance): 0 for exact constraints, 1/k for
///                                    compliant rows (a penalty gap of stiffness k)
///
/// over the free equations of one process. Newton, the analysis and the step drivers know only
/// this interface; the backends are chosen by make_constrained_solver(). The matrix K is the
/// locally assembled tangent (the problem writes it through a MatrixInserter); a distributed
/// backend sums the owned and ghost rows of every process into its own storage (EquationMap's
/// owned/ghost layout), a serial one factorises it as it is.
#include "common/timer.hpp"
#include "linalg/constraint_block.hpp"
#include "linalg/csr_matrix.hpp"
#include "linalg/factor_reuse.hpp"
#include "linalg/linear_solver.hpp" // SingularSystem

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace gapfem {

class KrylovEigenSolver; // linalg/krylov_eigen.hpp

struct KktOptions {
  double augmentation = 100.0;       ///< R_i = augmentation x stiffness at the row's DOFs
  double constraint_tolerance = 0.0; ///< stop the multiplier iteration when |C du + g| below this
  int max_iterations = 200;
  FactorReuse reuse = FactorReuse::Auto;
  bool force_fresh = false; ///< factorise the current matrix (the caller saw slow convergence)
  double max_drift = 1e-3;  ///< reuse only if |K - K_F|_ij <= max_drift sqrt(|K_F,ii K_F,jj|)
  /// An iterative backend may stop at this relative residual (Newton's forcing term; 0: the
  /// backend's own default). Direct backends solve exactly whatever it says.
  double relative_tolerance = 0.0;
  /// K holds the tangent of this system. When false (Newton assembled the residual alone, having
  /// been told matrix_optional()), K's values are stale and must not be used: the backend solves
  /// with the factor it keeps (a modified-Newton step; the constraint rows are the current ones)
  /// or, where it would not (no factor, too many changes, a stalled multiplier iteration), sets
  /// KktStatistics::needs_matrix and solves nothing.
  bool matrix_current = true;
};

struct KktStatistics {
  int schur_iterations = 0;
  int solves = 0;
  bool used_unsymmetric = false;
  bool reused_factor = false; ///< no factorisation was done for this system
  bool stale_factor = false;  ///< ... and the factor was of a different matrix (modified Newton)
  int changed_rows = 0;       ///< constraint rows that differ from the factored ones
  double constraint_residual = 0.0;
  /// Nothing was solved: the system needs the current tangent (KktOptions::matrix_current).
  bool needs_matrix = false;
};

/// Vectors an algebraic multigrid should interpolate well (the rigid-body modes): `count` vectors
/// of n entries each, one after the other.
struct NearNullSpace {
  int count = 0;
  std::vector<double> vectors;
  /// Nodal blocks, for aggregating nodes rather than equations: when block_size > 1, every
  /// equation is a translation of a node whose equations are all translations, and padded[e] is
  /// its place in a numbering where the k-th node with equations holds [block_size k,
  /// block_size (k + 1)) (its prescribed translations pad the block). Empty when block_size is 1.
  int block_size = 1;
  std::vector<LocalIndex> padded;
};

/// One factorisation of a constrained system: the system above with K and the rows of C (their
/// coefficients, columns and compliances) fixed, solved for as many right-hand sides (b, g) as the
/// caller has ("factorise once, solve many": a shift-invert eigensolver, the reduction
/// K_II^-1 K_IR of a substructure, the recovery of its internal DOFs). Made by
/// ConstrainedSolver::factorize(); independent of the solver's own kept factor (Newton's) and of
/// every other factor, so several may live at once. It must not outlive its solver.
class ConstrainedFactor {
 public:
  virtual ~ConstrainedFactor() = default;
  /// Solve for k right-hand sides at once, column-major: b and x are n x k, g and l are m x k (n
  /// equations, m rows of the factored system; g and l empty when m = 0). The rows' values are g,
  /// never the C.g the factor was made with. b, g may not alias x, l.
  virtual void solve(std::span<const double> b, std::span<const double> g, std::span<double> x,
                     std::span<double> l, int k = 1) = 0;
};

/// The backend interface. What a new backend must implement at minimum: name(), analyze() and
/// factorize() with its factor's solve(); everything else has a default. Such a backend works
/// everywhere: Newton's solve() then factorises every system afresh (its factor reuse is "never",
/// whatever KktOptions::reuse says, and matrix_optional() is false).
///
/// Where the factor-reuse policy lives: inside a backend's own solve() override, because it
/// works on the factor's insides. KktOptions (reuse, force_fresh, max_drift, matrix_current) says
/// what Newton allows; KktSolver decides per system whether its kept factor serves (kkt_reuse.cpp:
/// identical system, drift and the measured factor/solve/update times), corrects it for changed
/// rows (Woodbury, the dense multiplier matrix) and solves a stale one as modified Newton;
/// PetscKktSolver keeps MUMPS's factor for the identical system only. factorize() never reuses.
class ConstrainedSolver {
 public:
  virtual ~ConstrainedSolver() = default;

  // ---- the minimum
  virtual std::string_view name() const = 0;
  /// Symbolic analysis for a pattern (once per step, or before the factorisations of another
  /// matrix: a substructure's K_II). Drops any kept factor.
  virtual void analyze(std::shared_ptr<const SparsityPattern> pattern) = 0;
  /// Factorise (K, C) once, K of the analysed pattern and unchanged (a row's DOF block must lie in
  /// the pattern: the backend may augment K by C^T R C), for solves with many right-hand sides.
  /// `symmetric`: K is (a backend may then use one triangle). Throws SingularSystem when the
  /// system is singular; the factorisation's time and count go to `stats` (when given).
  virtual std::unique_ptr<ConstrainedFactor> factorize(const CsrMatrix& K, const ConstraintBlock& C,
                                                       bool symmetric,
                                                       RunStatistics* stats = nullptr) = 0;

  // ---- optional, with defaults
  /// The bytes a factor of the analysed pattern will hold (the symbolic analysis's prediction;
  /// 0: the backend cannot tell). `gapfem check` reports it; it never stops anything.
  virtual std::size_t factor_bytes_estimate() { return 0; }
  /// True when the backend uses a near null space (an AMG preconditioner): the analysis then
  /// gives it one per step, after analyze().
  virtual bool wants_near_null_space() const { return false; }
  virtual void set_near_null_space(NearNullSpace modes) { (void)modes; }
  /// Drop any kept factor: the next solve starts afresh, exactly as a new solver would (restart
  /// points). The default keeps none.
  virtual void forget_factor() {}
  /// True when the next solve can most likely do without the tangent's values (a kept factor of
  /// a stiffness that has barely drifted): Newton then assembles the residual alone and solves
  /// with KktOptions::matrix_current = false.
  virtual bool matrix_optional() const { return false; }
  /// The Krylov method the eigen solvers (*FREQUENCY, *BUCKLE) use with this backend's factors
  /// (krylov_eigen.hpp): Spectra's Lanczos on one process by default; a distributed backend gives
  /// one whose vectors live on its processes.
  virtual std::unique_ptr<KrylovEigenSolver> krylov_eigen_solver() const;
  /// Newton's system; K may be modified in place. du has one entry per equation, dl one per
  /// constraint row. Throws SingularSystem when K (with the constraints) is singular, and
  /// AnalysisError when the factor cannot fit in memory. The default factorises (K, C) with
  /// factorize() and solves once; without the current matrix it sets needs_matrix.
  virtual KktStatistics solve(CsrMatrix& K, std::span<const double> b, const ConstraintBlock& C,
                              std::span<double> du, std::span<double> dl, bool symmetric,
                              const KktOptions& options, RunStatistics* stats = nullptr);
};

/// How the serial backend (KktSolver) works, never what it solves (docs/performance.md). Set by the
/// application layer from GAPFEM_FACTOR_UPDATES and GAPFEM_DENSE_MULTIPLIERS (app/environment).
struct KktTuning {
  bool factor_updates = true; ///< correct a kept factor for changed rows (Woodbury); off: refactor
  bool dense_multipliers = true; ///< the dense multiplier system of a kept factor; off: Krylov
};

/// A backend behind the seam, chosen by name (`--solver NAME`). Backends register themselves
/// with register_solver_backend(): "cholmod" (KktSolver) here in linalg, "mumps" and "iterative"
/// (PetscKktSolver) by parallel::register_backends(). A new backend is its own files plus one
/// registration (docs/architecture.md, "Adding a backend").
struct SolverBackend {
  std::string name;             ///< as --solver spells it
  std::string summary;          ///< one line: what it is
  bool one_process = false;     ///< solves on one process only (not under mpirun with several)
  bool needs_processes = false; ///< MPI/PETSc are started before the run (parallel::start)
  std::string unavailable;      ///< why this build cannot use it ("" when it can)
  std::function<std::unique_ptr<ConstrainedSolver>(const KktTuning&)> make;
};

/// Adds a backend (or replaces the one of the same name).
void register_solver_backend(SolverBackend backend);
/// The backend of that name, or nullptr.
const SolverBackend* find_solver_backend(std::string_view name);
/// Every registered backend's name, in the order of registration.
std::vector<std::string> solver_backend_names();
/// The backend's solver; std::runtime_error naming the backends there are when `name` is not one,
/// or the reason when this build cannot use it.
std::unique_ptr<ConstrainedSolver> make_constrained_solver(std::string_view name,
                                                           const KktTuning& tuning = {});

/// Augmentation weights of the rows of C: ks_r is the structure's stiffness along row r (from the
/// diagonal of K at its DOFs), R_r = augmentation x ks_r, kept below half the stiffness 1/E_r of a
/// compliant row. Both backends augment K + C^T R C with these.
void augmentation_weights(const CsrMatrix& K, const ConstraintBlock& C, double augmentation,
                          std::vector<double>& R, std::vector<double>& ks);

} // namespace gapfem
