#pragma once
/// @file petsc_detail.hpp
/// What the two methods of PetscKktSolver share: PETSc handles, per-rank row lists, the helpers
/// of the bordered system and the solver's state. Included only by petsc_kkt_solver.cpp (the
/// class, MUMPS) and petsc_iterative.cpp (the iterative method).
#include "linalg/constrained_solver.hpp"
#include "parallel/kkt_layout.hpp"
#include "parallel/petsc_kkt_solver.hpp"

#include <petscksp.h>
#include <span>
#include <string>
#include <vector>

namespace gapfem {
namespace petsc_detail {

constexpr double kDefaultRtol = 1e-10;
constexpr int kGmresRestart = 100;
constexpr int kMaxIterations = 2000;
constexpr int kRowsAbsorbed = 20;
/// Pinned equations that may change (as a share of the equations) before the AMG is rebuilt.
constexpr double kPinnedShareAbsorbed = 0.005;
/// After CG failed on a system, the solves that use GMRES before CG is tried again.
constexpr int kGmresAfterCgFailure = 2;
/// Nodal aggregation from this many equations on: below, GAMG's hierarchy has a level or two and
/// aggregating nodes rather than equations changes nothing but the round-off.
constexpr int kNodalBlocksFrom = 1000;
/// A graph partitioner chooses the ranks' rows from this many equations on; below, contiguous
/// blocks of the numbering.
constexpr int kPartitionFrom = 10000;
/// MUMPS's factor (with its pivoting and workspace) against CHOLMOD's symbolic estimate.
constexpr double kDirectMemoryFactor = 1.5;
/// A solve whose true relative residual exceeds this many times the tolerance has failed.
constexpr double kTrueResidualSlack = 100.0;

/// Rows of b that a does not have (same multiplier, same coefficients), plus rows of a gone.
int changed_rows(const ConstraintBlock& a, const ConstraintBlock& b);
/// The factor f = 1 - R E of a compliant row's equation in the bordered matrix MUMPS factorises
/// (see petsc_kkt_solver.cpp).
double row_factor(std::span<const double> R, const ConstraintBlock& C, int r);
/// The multiplier scale s: the mean of |diag K| (1 for an empty or zero diagonal).
double multiplier_scale(const CsrMatrix& K);
/// The serial backend's symbolic estimate of a direct factor of the pattern (CHOLMOD's; MUMPS's
/// is near it): the memory checks and factor_bytes_estimate() use it.
std::size_t serial_factor_bytes(std::shared_ptr<const SparsityPattern> pattern);

/// Destroys a PETSc object when it goes (PETSc's XxxDestroy set the handle to null).
template <class T, PetscErrorCode (*Destroy)(T*)>
struct Handle {
  T h = nullptr;
  Handle() = default;
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() { reset(); }
  void reset() {
    if (h) Destroy(&h);
    h = nullptr;
  }
  operator T() const { return h; }
  T* out() {
    reset();
    return &h;
  }
};
using MatH = Handle<Mat, MatDestroy>;
using VecH = Handle<Vec, VecDestroy>;
using KspH = Handle<KSP, KSPDestroy>;
using ScatterH = Handle<VecScatter, VecScatterDestroy>;

/// A matrix of `rows` x `cols` (global), with this rank's rows given as lists of (column, value).
/// Built whole each time (its preallocation is exact).
struct RowLists {
  std::vector<std::vector<PetscInt>> cols;
  std::vector<std::vector<PetscScalar>> vals;
  explicit RowLists(PetscInt local_rows)
      : cols(static_cast<std::size_t>(local_rows)), vals(static_cast<std::size_t>(local_rows)) {}
  void add(PetscInt local_row, PetscInt col, double v) {
    cols[local_row].push_back(col);
    vals[local_row].push_back(v);
  }
};
void create_matrix(Mat* out, const RowLists& rows, PetscInt local_cols, PetscInt global_rows,
                   PetscInt global_cols, PetscInt block = 1);
/// An AIJ matrix with this rank's rows preallocated (entries per row in the diagonal block and
/// off it), values to be set; returns the global number of this rank's first row.
PetscInt create_preallocated(Mat* out, std::span<const PetscInt> diagonal_block,
                             std::span<const PetscInt> off_diagonal, PetscInt local_cols,
                             PetscInt global_rows, PetscInt global_cols, PetscInt block);
/// The whole of a distributed vector on every rank.
void gather_all(Vec x, std::vector<double>& out);
/// A = K + C^T R C in place (the springs lie inside each row's own block of the pattern).
void augment(CsrMatrix& K, const ConstraintBlock& C, std::span<const double> R, double sign = 1.0);
/// This rank's part of the right-hand side [b - C^T R g; -s f g] of the augmented system (f:
/// the rows' factors, row_factor(), when `scaled_rows`; unpad: row of A -> equation, when A is
/// numbered by nodes).
void fill_rhs(Vec rhs, std::span<const double> b, const ConstraintBlock& C,
              std::span<const double> R, double s, const KktLayout& L, bool scaled_rows,
              std::span<const LocalIndex> unpad = {});

} // namespace petsc_detail

struct BorderedSystem;

struct PetscKktSolver::Impl {
  Method method;
  std::shared_ptr<const SparsityPattern> pattern;
  // MUMPS: the bordered matrix and its solver (kept while the rows keep their pattern)
  petsc_detail::MatH kkt;
  petsc_detail::KspH direct;
  std::vector<LocalIndex> kkt_row_ptr, kkt_col; ///< the rows' pattern the matrix was made for
  bool kkt_symmetric = false;
  std::vector<double> factored; ///< what the factor is of (K values, rows)
  ConstraintBlock factored_rows;
  // Iterative: A with K's pattern, and its AMG cycle. A's rows follow the nodal numbering of
  // NearNullSpace::padded when there is one (padding rows: a diagonal), so that the AMG
  // aggregates nodes.
  int block = 1;
  std::vector<LocalIndex> pad, unpad; ///< equation -> row of A; row of A -> equation or -1
  LocalIndex row_of(LocalIndex i) const { return pad.empty() ? i : pad[i]; }
  LocalIndex eq_of(LocalIndex p) const { return unpad.empty() ? p : unpad[p]; }
  LocalIndex a_size(LocalIndex n) const {
    return unpad.empty() ? n : static_cast<LocalIndex>(unpad.size());
  }
  /// First row of A of each rank (size + 1) when a graph partitioner chose them (pad then numbers
  /// each rank's blocks contiguously); empty: A's rows split as PETSc splits a vector.
  std::vector<int> u_starts;
  /// Rank p's blocks of A after partitioning (see petsc_partition.cpp); empty when one rank or a
  /// small model.
  void partition_blocks();
  /// The blocks of A coupled to blocks first..first+count-1 in K's pattern (without themselves).
  std::vector<std::vector<PetscInt>> block_adjacency(PetscInt first, PetscInt count) const;
  petsc_detail::MatH A;
  NearNullSpace modes; ///< the rigid-body modes A's AMG interpolates (set per step)
  petsc_detail::KspH amg;
  bool amg_ready = false;
  /// GMRES iterations per decade of residual reduction, after the last build and in the last solve
  /// (solves to different forcing terms compare so)
  double per_decade_after_build = 0.0, per_decade_last = 0.0;
  ConstraintBlock amg_rows;         ///< the spring rows (not pinned) in A when its AMG was built
  std::vector<LocalIndex> amg_pins; ///< the pinned equations then, sorted
  bool direct_fallback = false;     ///< GMRES failed in this step: MUMPS solves until the next step
  /// CG found the cycle or the tangent indefinite: the solves left on GMRES before CG is tried
  /// again (a tangent is indefinite for an iteration or two, e.g. after a first step in which
  /// almost no gap held a plate, not for the rest of the step)
  int gmres_before_cg = 0;

  KktStatistics solve_mumps(CsrMatrix& K, std::span<const double> b, const ConstraintBlock& C,
                            std::span<double> du, std::span<double> dl, bool symmetric,
                            const KktOptions& opt, RunStatistics* stats);
  KktStatistics solve_iterative(CsrMatrix& K, std::span<const double> b, const ConstraintBlock& C,
                                std::span<double> du, std::span<double> dl, bool symmetric,
                                const KktOptions& opt, RunStatistics* stats);
  void build_kkt(const CsrMatrix& K, const ConstraintBlock& C, std::span<const double> R, double s,
                 bool symmetric, const KktLayout& L);
  /// MUMPS's stages: factorise the bordered matrix of K + C^T R C (K augmented in place; b only
  /// for naming a singular system), and solve with that factor for b and C.g.
  void factor_mumps(CsrMatrix& K, const ConstraintBlock& C, std::span<const double> R, double s,
                    bool symmetric, const KktLayout& L, std::span<const double> b,
                    RunStatistics* stats);
  void solve_direct(std::span<const double> b, const ConstraintBlock& C, std::span<const double> R,
                    double s, const KktLayout& L, std::span<double> du, std::span<double> dl,
                    RunStatistics* stats) const;
  /// Factorise kkt with MUMPS (workspace relaxation ICNTL(14) in percent); MUMPS's INFOG(1),
  /// -10 also for null pivots.
  PetscInt factorize_mumps(int workspace_percent);
  void fill_a(const CsrMatrix& K, const KktLayout& L, double padding);
  /// The iterative method's stages: the rows left in the bordered system (its D', C, E and the
  /// Schur estimate); the AMG hierarchy, returning whether it was built anew; the Krylov solve.
  void build_rows(BorderedSystem& sys, const ConstraintBlock& Cr, std::span<const double> R,
                  std::span<const double> ks, double s) const;
  bool prepare_amg(const ConstraintBlock& springs, std::span<const LocalIndex> pinned, LocalIndex n,
                   const KktOptions& opt, RunStatistics* stats);
  struct KrylovRun {
    PetscInt iterations = 0;
    KSPConvergedReason reason{};
    double true_ratio = 0.0; ///< |b - A x| / |b| of the bordered system
  };
  KrylovRun run_krylov(BorderedSystem& sys, Vec rhs, Vec x, bool cg, double rtol, int max_it,
                       RunStatistics* stats) const;
  void attach_near_null_space(const KktLayout& L);
  /// AnalysisError naming `what` when a direct factor of the pattern (CHOLMOD's symbolic estimate,
  /// 1.5x for MUMPS's pivoting and workspace) cannot fit in the memory left on some rank.
  void require_direct_fits(const std::string& what) const;
  [[noreturn]] void singular(const CsrMatrix& K, std::span<const double> b,
                             const ConstraintBlock& C, bool symmetric, const std::string& what);
};

} // namespace gapfem
