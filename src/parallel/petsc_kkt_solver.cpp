#include "parallel/petsc_kkt_solver.hpp"

#include "common/error.hpp"
#include "common/log.hpp"
#include "common/memory.hpp"
#include "linalg/kkt_solver.hpp"
#include "linalg/row_elimination.hpp"
#include "parallel/kkt_layout.hpp"
#include "parallel/parallel.hpp"
#include "parallel/petsc_runtime.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <petscksp.h>
#include <unordered_map>

namespace gapfem {

using parallel::petsc_check;

namespace {

constexpr double kDefaultRtol = 1e-10;
constexpr int kGmresRestart = 100;
constexpr int kMaxIterations = 2000;
constexpr int kRowsAbsorbed = 20;
/// Nodal aggregation from this many equations on: below, GAMG's hierarchy has a level or two and
/// aggregating nodes rather than equations changes nothing but the round-off.
constexpr int kNodalBlocksFrom = 1000;
/// MUMPS's factor (with its pivoting and workspace) against CHOLMOD's symbolic estimate.
constexpr double kDirectMemoryFactor = 1.5;
/// A solve whose true relative residual exceeds this many times the tolerance has failed.
constexpr double kTrueResidualSlack = 100.0;

double compliance_of(const ConstraintBlock& C, int r) {
  return static_cast<std::size_t>(r) < C.compliance.size() ? C.compliance[r] : 0.0;
}
double column_value(const ConstraintBlock& C, LocalIndex k) {
  return C.has_columns() ? C.dval[k] : C.val[k];
}

/// Rows of b that a does not have (same multiplier, same coefficients), plus rows of a gone.
int changed_rows(const ConstraintBlock& a, const ConstraintBlock& b) {
  std::unordered_map<std::int64_t, int> row_of;
  for (int r = 0; r < a.n_rows(); ++r) row_of.emplace(a.multiplier[r], r);
  int kept = 0;
  for (int r = 0; r < b.n_rows(); ++r) {
    const auto it = row_of.find(b.multiplier[r]);
    if (it == row_of.end()) continue;
    const int q = it->second;
    kept += std::equal(b.col.begin() + b.row_ptr[r], b.col.begin() + b.row_ptr[r + 1],
                       a.col.begin() + a.row_ptr[q], a.col.begin() + a.row_ptr[q + 1]) &&
            std::equal(b.val.begin() + b.row_ptr[r], b.val.begin() + b.row_ptr[r + 1],
                       a.val.begin() + a.row_ptr[q], a.val.begin() + a.row_ptr[q + 1]);
  }
  return (b.n_rows() - kept) + (a.n_rows() - kept);
}

/// The factor f = 1 - R E of a compliant row's equation in the bordered matrix MUMPS factorises:
/// the augmentation makes the row's column s (1 - R E) C^T, so the row is scaled alike and the
/// matrix stays symmetric (f >= 1/2, R being at most half the row's stiffness).
double row_factor(std::span<const double> R, const ConstraintBlock& C, int r) {
  return 1.0 - R[r] * compliance_of(C, r);
}

/// The multiplier scale s: the mean of |diag K| (1 for an empty or zero diagonal).
double multiplier_scale(const CsrMatrix& K) {
  double sum = 0.0;
  for (LocalIndex i = 0; i < K.n(); ++i) sum += std::abs(K.diagonal(i));
  const double s = K.n() > 0 ? sum / K.n() : 1.0;
  return s > 0 && std::isfinite(s) ? s : 1.0;
}

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
                   PetscInt global_cols, PetscInt block = 1) {
  const auto nloc = static_cast<PetscInt>(rows.cols.size());
  PetscInt first = 0; // global number of this rank's first row and column
  PetscInt first_col = 0;
  MPI_Exscan(&nloc, &first, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD);
  MPI_Exscan(&local_cols, &first_col, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD);
  if (parallel::rank() == 0) first = first_col = 0;
  std::vector<PetscInt> d(rows.cols.size(), 0), o(rows.cols.size(), 0);
  for (std::size_t i = 0; i < rows.cols.size(); ++i)
    for (PetscInt c : rows.cols[i]) ++(c >= first_col && c < first_col + local_cols ? d[i] : o[i]);
  petsc_check(MatCreate(PETSC_COMM_WORLD, out), "MatCreate");
  petsc_check(MatSetSizes(*out, nloc, local_cols, global_rows, global_cols), "MatSetSizes");
  petsc_check(MatSetType(*out, MATAIJ), "MatSetType");
  if (block > 1) petsc_check(MatSetBlockSize(*out, block), "MatSetBlockSize");
  petsc_check(MatSeqAIJSetPreallocation(*out, 0, d.data()), "MatSeqAIJSetPreallocation");
  petsc_check(MatMPIAIJSetPreallocation(*out, 0, d.data(), 0, o.data()),
              "MatMPIAIJSetPreallocation");
  for (std::size_t i = 0; i < rows.cols.size(); ++i) {
    const PetscInt row = first + static_cast<PetscInt>(i);
    if (rows.cols[i].empty()) continue;
    petsc_check(MatSetValues(*out, 1, &row, static_cast<PetscInt>(rows.cols[i].size()),
                             rows.cols[i].data(), rows.vals[i].data(), ADD_VALUES),
                "MatSetValues");
  }
  petsc_check(MatAssemblyBegin(*out, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  petsc_check(MatAssemblyEnd(*out, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
}

/// The whole of a distributed vector on every rank.
void gather_all(Vec x, std::vector<double>& out) {
  ScatterH scatter;
  VecH all;
  petsc_check(VecScatterCreateToAll(x, scatter.out(), all.out()), "VecScatterCreateToAll");
  petsc_check(VecScatterBegin(scatter, x, all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
  petsc_check(VecScatterEnd(scatter, x, all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
  PetscInt n = 0;
  petsc_check(VecGetSize(all, &n), "VecGetSize");
  const PetscScalar* a = nullptr;
  petsc_check(VecGetArrayRead(all, &a), "VecGetArrayRead");
  out.assign(a, a + n);
  petsc_check(VecRestoreArrayRead(all, &a), "VecRestoreArrayRead");
}

} // namespace

// ---------------------------------------------------------------------------------------------
// The iterative method's operator and preconditioner (PETSc shell callbacks)

struct BorderedSystem {
  KktLayout layout;
  Mat A = nullptr; ///< K + C^T R C (u numbering)
  MatH Dp;         ///< s (D - C^T R E), n x m
  MatH Cm;         ///< s C, m x n
  VecH Ev;         ///< s^2 E (l layout)
  VecH Sinv;       ///< 1 / (s^2 (E + (1 - R E) / (R + ks))) (l layout)
  KSP inner = nullptr;
  VecH xu, xl, yu, yl, tu, tl; ///< views into the bordered vectors, and work vectors
  bool has_rows() const { return layout.m > 0; }

  void make_views() {
    const PetscInt nu = layout.u_local(), nl = layout.l_local();
    petsc_check(VecCreateMPIWithArray(PETSC_COMM_WORLD, 1, nu, layout.n, nullptr, xu.out()),
                "VecCreateMPIWithArray");
    petsc_check(VecCreateMPIWithArray(PETSC_COMM_WORLD, 1, nu, layout.n, nullptr, yu.out()),
                "VecCreateMPIWithArray");
    petsc_check(VecCreateMPI(PETSC_COMM_WORLD, nu, layout.n, tu.out()), "VecCreateMPI");
    if (!has_rows()) return;
    petsc_check(VecCreateMPIWithArray(PETSC_COMM_WORLD, 1, nl, layout.m, nullptr, xl.out()),
                "VecCreateMPIWithArray");
    petsc_check(VecCreateMPIWithArray(PETSC_COMM_WORLD, 1, nl, layout.m, nullptr, yl.out()),
                "VecCreateMPIWithArray");
    petsc_check(VecCreateMPI(PETSC_COMM_WORLD, nl, layout.m, tl.out()), "VecCreateMPI");
  }
  /// Point the views at the two parts of x (read) and y (written).
  void place(Vec x, Vec y, const PetscScalar*& xa, PetscScalar*& ya) {
    petsc_check(VecGetArrayRead(x, &xa), "VecGetArrayRead");
    petsc_check(VecGetArray(y, &ya), "VecGetArray");
    auto* xw = const_cast<PetscScalar*>(xa); // the views of x are only read
    petsc_check(VecPlaceArray(xu, xw), "VecPlaceArray");
    petsc_check(VecPlaceArray(yu, ya), "VecPlaceArray");
    if (has_rows()) {
      petsc_check(VecPlaceArray(xl, xw + layout.u_local()), "VecPlaceArray");
      petsc_check(VecPlaceArray(yl, ya + layout.u_local()), "VecPlaceArray");
    }
  }
  void unplace(Vec x, Vec y, const PetscScalar*& xa, PetscScalar*& ya) {
    petsc_check(VecResetArray(xu), "VecResetArray");
    petsc_check(VecResetArray(yu), "VecResetArray");
    if (has_rows()) {
      petsc_check(VecResetArray(xl), "VecResetArray");
      petsc_check(VecResetArray(yl), "VecResetArray");
    }
    petsc_check(VecRestoreArrayRead(x, &xa), "VecRestoreArrayRead");
    petsc_check(VecRestoreArray(y, &ya), "VecRestoreArray");
  }
  /// y = [A Dp; Cm -Ev] x
  void multiply(Vec x, Vec y) {
    const PetscScalar* xa = nullptr;
    PetscScalar* ya = nullptr;
    place(x, y, xa, ya);
    petsc_check(MatMult(A, xu, yu), "MatMult");
    if (has_rows()) {
      petsc_check(MatMultAdd(Dp, xl, yu, yu), "MatMultAdd");
      petsc_check(MatMult(Cm, xu, yl), "MatMult");
      petsc_check(VecPointwiseMult(tl, Ev, xl), "VecPointwiseMult");
      petsc_check(VecAXPY(yl, -1.0, tl), "VecAXPY");
    }
    unplace(x, y, xa, ya);
  }
  /// y = P^-1 r with P = [A Dp; 0 -S]: y_l = -S^-1 r_l, y_u = AMG(r_u - Dp y_l)
  void precondition(Vec r, Vec y) {
    const PetscScalar* ra = nullptr;
    PetscScalar* ya = nullptr;
    place(r, y, ra, ya);
    petsc_check(VecCopy(xu, tu), "VecCopy");
    if (has_rows()) {
      petsc_check(VecPointwiseMult(yl, Sinv, xl), "VecPointwiseMult");
      petsc_check(VecScale(yl, -1.0), "VecScale");
      petsc_check(MatMult(Dp, yl, yu), "MatMult");
      petsc_check(VecAXPY(tu, -1.0, yu), "VecAXPY");
    }
    petsc_check(KSPSolve(inner, tu, yu), "KSPSolve (AMG cycle)");
    unplace(r, y, ra, ya);
  }
};

namespace {
/// A PETSc shell callback (MATOP_MULT, PCShellSetApply) calling `Apply` on the BorderedSystem kept
/// as the shell's context; exceptions become PETSc error codes.
template <class Object, PetscErrorCode (*GetContext)(Object, void*),
          void (BorderedSystem::*Apply)(Vec, Vec)>
PetscErrorCode shell_call(Object object, Vec in, Vec out) {
  void* ctx = nullptr;
  GetContext(object, &ctx);
  try {
    (static_cast<BorderedSystem*>(ctx)->*Apply)(in, out);
  } catch (const std::exception&) {
    return PETSC_ERR_LIB;
  }
  return 0;
}
constexpr auto shell_multiply = shell_call<Mat, MatShellGetContext, &BorderedSystem::multiply>;
constexpr auto shell_precondition =
    shell_call<PC, PCShellGetContext, &BorderedSystem::precondition>;
} // namespace

// ---------------------------------------------------------------------------------------------

struct PetscKktSolver::Impl {
  Method method;
  std::shared_ptr<const SparsityPattern> pattern;
  // MUMPS: the bordered matrix and its solver (kept while the rows keep their pattern)
  MatH kkt;
  KspH direct;
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
  MatH A;
  NearNullSpace modes; ///< the rigid-body modes A's AMG interpolates (set per step)
  KspH amg;
  bool amg_ready = false;
  /// GMRES iterations per decade of residual reduction, after the last build and in the last solve
  /// (solves to different forcing terms compare so)
  double per_decade_after_build = 0.0, per_decade_last = 0.0;
  ConstraintBlock amg_rows;     ///< the rows whose springs were in A when its AMG was built
  bool direct_fallback = false; ///< GMRES failed in this step: MUMPS solves until the next step
  bool no_cg = false; ///< CG failed in this step (the AMG cycle was not definite): GMRES instead

  KktStatistics solve_mumps(CsrMatrix& K, std::span<const double> b, const ConstraintBlock& C,
                            std::span<double> du, std::span<double> dl, bool symmetric,
                            const KktOptions& opt, RunStatistics* stats);
  KktStatistics solve_iterative(CsrMatrix& K, std::span<const double> b, const ConstraintBlock& C,
                                std::span<double> du, std::span<double> dl, bool symmetric,
                                const KktOptions& opt, RunStatistics* stats);
  void build_kkt(const CsrMatrix& K, const ConstraintBlock& C, std::span<const double> R, double s,
                 bool symmetric, const KktLayout& L);
  /// Factorise kkt with MUMPS (workspace relaxation ICNTL(14) in percent); MUMPS's INFOG(1),
  /// -10 also for null pivots.
  PetscInt factorize_mumps(int workspace_percent);
  void fill_a(const CsrMatrix& K, const KktLayout& L, double padding);
  void attach_near_null_space(const KktLayout& L);
  /// AnalysisError naming `what` when a direct factor of the pattern (CHOLMOD's symbolic estimate,
  /// 1.5x for MUMPS's pivoting and workspace) cannot fit in the memory left on some rank.
  void require_direct_fits(const std::string& what) const;
  [[noreturn]] void singular(const CsrMatrix& K, std::span<const double> b,
                             const ConstraintBlock& C, bool symmetric, const std::string& what);
};

PetscKktSolver::PetscKktSolver(Method method) : _impl(std::make_unique<Impl>()) {
  _impl->method = method;
}
PetscKktSolver::~PetscKktSolver() = default;

std::string_view PetscKktSolver::name() const {
  return _impl->method == Method::Mumps ? "mumps" : "iterative";
}

void PetscKktSolver::analyze(std::shared_ptr<const SparsityPattern> pattern) {
  _impl->pattern = std::move(pattern);
  _impl->block = 1;
  _impl->pad.clear();
  _impl->unpad.clear();
  _impl->direct_fallback = false;
  _impl->no_cg = false;
  forget_factor();
  _impl->A.reset();
}

bool PetscKktSolver::wants_near_null_space() const {
  return _impl->method == Method::Iterative;
}
void PetscKktSolver::set_near_null_space(NearNullSpace modes) {
  Impl& m = *_impl;
  m.block = 1;
  m.pad.clear();
  m.unpad.clear();
  if (modes.block_size > 1 && m.pattern && m.pattern->n >= kNodalBlocksFrom &&
      modes.padded.size() == static_cast<std::size_t>(m.pattern->n)) {
    m.block = modes.block_size;
    m.pad = std::move(modes.padded);
    const LocalIndex last = m.pad.empty() ? -1 : *std::max_element(m.pad.begin(), m.pad.end());
    m.unpad.assign(static_cast<std::size_t>(m.block * (last / m.block + 1)), -1);
    for (std::size_t i = 0; i < m.pad.size(); ++i) m.unpad[m.pad[i]] = static_cast<LocalIndex>(i);
  }
  _impl->modes = std::move(modes);
  _impl->A.reset(); // made again with them
}

void PetscKktSolver::forget_factor() {
  _impl->direct.reset();
  _impl->kkt.reset();
  _impl->kkt_row_ptr.clear();
  _impl->kkt_col.clear();
  _impl->factored.clear();
  _impl->factored_rows.clear();
  _impl->amg.reset();
  _impl->amg_ready = false;
}

KktStatistics PetscKktSolver::solve(CsrMatrix& K, std::span<const double> b,
                                    const ConstraintBlock& C, std::span<double> du,
                                    std::span<double> dl, bool symmetric, const KktOptions& opt,
                                    RunStatistics* stats) {
  FE_CHECK(_impl->pattern && K.n() == _impl->pattern->n,
           "PETSc solver not analysed for this pattern");
  if (_impl->method == Method::Mumps || _impl->direct_fallback)
    return _impl->solve_mumps(K, b, C, du, dl, symmetric, opt, stats);
  return _impl->solve_iterative(K, b, C, du, dl, symmetric, opt, stats);
}

void PetscKktSolver::Impl::singular(const CsrMatrix& K, std::span<const double> b,
                                    const ConstraintBlock& C, bool symmetric,
                                    const std::string& what) {
  // One process: let the CHOLMOD backend name the equations without stiffness (its pivots do),
  // so that the diagnosis names the nodes as in a CHOLMOD run
  if (parallel::size() == 1) {
    KktSolver diagnosis;
    diagnosis.analyze(pattern);
    CsrMatrix copy = K;
    std::vector<double> du(static_cast<std::size_t>(K.n())),
        dl(static_cast<std::size_t>(C.n_rows()));
    diagnosis.solve(copy, b, C, du, dl, symmetric, KktOptions{}); // throws SingularSystem
  }
  throw SingularSystem(what, {});
}

void PetscKktSolver::Impl::require_direct_fits(const std::string& what) const {
  auto estimate = make_cholmod_solver();
  estimate->analyze(*pattern);
  const double need = kDirectMemoryFactor * static_cast<double>(estimate->factor_bytes());
  // the rank with the least memory left decides, for every rank alike
  const auto available = available_memory_bytes();
  const double here =
      available ? static_cast<double>(*available) : std::numeric_limits<double>::infinity();
  const double least = -parallel::max_over_ranks(-here);
  if (!(need > least)) return;
  throw AnalysisError(fmt::format(
      "--solver iterative: {}, and factorising it instead (MUMPS) would need about {} of memory, "
      "more than is available ({}{}). Try another multigrid (-inner_pc_type hypre), more "
      "iterations (-ksp_max_it), a smaller increment, or more ranks on more machines (mpirun -np "
      "N)",
      what, memory_size_text(need), memory_size_text(least),
      parallel::size() > 1 ? " on the rank with the least" : ""));
}

// ---------------------------------------------------------------------------------------------
// MUMPS

void PetscKktSolver::Impl::build_kkt(const CsrMatrix& K, const ConstraintBlock& C,
                                     std::span<const double> R, double s, bool symmetric,
                                     const KktLayout& L) {
  const SparsityPattern& pat = K.pattern();
  const auto vals = K.values();
  RowLists rows(L.u_local() + L.l_local());
  for (PetscInt i = L.u0(); i < L.u1(); ++i)
    for (LocalIndex k = pat.row_ptr[i]; k < pat.row_ptr[i + 1]; ++k)
      rows.add(i - L.u0(), L.kkt_u(pat.col[k]), vals[k]);
  for (int r = 0; r < C.n_rows(); ++r) {
    const bool own_row = r >= L.l0() && r < L.l1();
    const double E = compliance_of(C, r), f = row_factor(R, C, r);
    for (LocalIndex k = C.row_ptr[r]; k < C.row_ptr[r + 1]; ++k) {
      const LocalIndex i = C.col[k];
      if (i >= L.u0() && i < L.u1())
        rows.add(i - L.u0(), L.kkt_l(r), s * (column_value(C, k) - C.val[k] * R[r] * E));
      if (own_row) rows.add(L.u_local() + r - L.l0(), L.kkt_u(i), s * f * C.val[k]);
    }
    if (own_row) rows.add(L.u_local() + r - L.l0(), L.kkt_l(r), -s * s * f * E);
  }
  const PetscInt N = L.n + L.m;
  create_matrix(kkt.out(), rows, L.u_local() + L.l_local(), N, N);
  kkt_symmetric = symmetric && !C.has_columns();
  if (kkt_symmetric) petsc_check(MatSetOption(kkt, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
}

namespace {

/// A = K + C^T R C in place (the springs lie inside each row's own block of the pattern).
void augment(CsrMatrix& K, const ConstraintBlock& C, std::span<const double> R, double sign = 1.0) {
  auto vals = K.values();
  const SparsityPattern& pat = K.pattern();
  for (int r = 0; r < C.n_rows(); ++r)
    for (LocalIndex a = C.row_ptr[r]; a < C.row_ptr[r + 1]; ++a)
      for (LocalIndex c = C.row_ptr[r]; c < C.row_ptr[r + 1]; ++c) {
        const LocalIndex pos = pat.find(C.col[a], C.col[c]);
        FE_CHECK(pos >= 0, "constraint row outside the sparsity pattern");
        vals[pos] += sign * R[r] * C.val[a] * C.val[c];
      }
}

/// This rank's part of the right-hand side [b - C^T R g; -s f g] of the augmented system (f:
/// the rows' factors, row_factor(); 1 when not given).
void fill_rhs(Vec rhs, std::span<const double> b, const ConstraintBlock& C,
              std::span<const double> R, double s, const KktLayout& L, bool scaled_rows,
              std::span<const LocalIndex> unpad = {}) {
  std::vector<double> bb(b.begin(), b.end()), Rg(static_cast<std::size_t>(C.n_rows()));
  for (int r = 0; r < C.n_rows(); ++r) Rg[r] = R[r] * C.g[r];
  C.add_transpose_multiply(Rg, -1.0, bb);
  PetscScalar* a = nullptr;
  petsc_check(VecGetArray(rhs, &a), "VecGetArray");
  for (PetscInt p = L.u0(); p < L.u1(); ++p) {
    const LocalIndex i = unpad.empty() ? p : unpad[p];
    a[p - L.u0()] = i >= 0 ? bb[i] : 0.0;
  }
  for (PetscInt r = L.l0(); r < L.l1(); ++r)
    a[L.u_local() + r - L.l0()] = -s * (scaled_rows ? row_factor(R, C, r) : 1.0) * C.g[r];
  petsc_check(VecRestoreArray(rhs, &a), "VecRestoreArray");
}

/// MUMPS's INFOG(1) for a factor that ran out of its workspace estimate.
bool mumps_workspace_short(PetscInt info1) {
  return info1 == -8 || info1 == -9 || info1 == -14;
}

} // namespace

PetscInt PetscKktSolver::Impl::factorize_mumps(int workspace_percent) {
  petsc_check(KSPCreate(PETSC_COMM_WORLD, direct.out()), "KSPCreate");
  petsc_check(KSPSetOperators(direct, kkt, kkt), "KSPSetOperators");
  petsc_check(KSPSetType(direct, KSPPREONLY), "KSPSetType");
  PC pc = nullptr;
  petsc_check(KSPGetPC(direct, &pc), "KSPGetPC");
  petsc_check(PCSetType(pc, kkt_symmetric ? PCCHOLESKY : PCLU), "PCSetType");
  petsc_check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
  petsc_check(PCFactorSetUpMatSolverType(pc), "PCFactorSetUpMatSolverType");
  Mat F = nullptr;
  petsc_check(PCFactorGetMatrix(pc, &F), "PCFactorGetMatrix");
  petsc_check(MatMumpsSetIcntl(F, 24, 1), "MatMumpsSetIcntl"); // detect null pivots
  petsc_check(MatMumpsSetIcntl(F, 14, workspace_percent), "MatMumpsSetIcntl");
  petsc_check(KSPSetErrorIfNotConverged(direct, PETSC_FALSE), "KSPSetErrorIfNotConverged");
  petsc_check(KSPSetFromOptions(direct), "KSPSetFromOptions");
  const PetscErrorCode setup = KSPSetUp(direct);
  PetscInt info1 = 0, null_pivots = 0;
  MatMumpsGetInfog(F, 1, &info1);
  MatMumpsGetInfog(F, 28, &null_pivots);
  if (info1 >= 0 && setup != 0) info1 = -1; // PETSc's own failure
  if (info1 >= 0 && null_pivots > 0) info1 = -10;
  return info1;
}

KktStatistics PetscKktSolver::Impl::solve_mumps(CsrMatrix& K, std::span<const double> b,
                                                const ConstraintBlock& C, std::span<double> du,
                                                std::span<double> dl, bool symmetric,
                                                const KktOptions& opt, RunStatistics* stats) {
  KktStatistics out;
  const KktLayout L(K.n(), C.n_rows());
  const double s = multiplier_scale(K);
  // the identical system (a linear step's next increment) keeps its factor
  const auto vals = K.values();
  const bool same = direct && !opt.force_fresh && opt.reuse != FactorReuse::Never &&
                    kkt_symmetric == (symmetric && !C.has_columns()) &&
                    std::equal(vals.begin(), vals.end(), factored.begin(), factored.end()) &&
                    factored_rows.row_ptr == C.row_ptr && factored_rows.col == C.col &&
                    factored_rows.val == C.val && factored_rows.dval == C.dval &&
                    factored_rows.compliance == C.compliance;
  // augmented as the iterative method is: A = K + C^T R C is definite where the rows hold a body
  // that K alone leaves free, which spares MUMPS most delayed pivots
  std::vector<double> R, ks;
  augmentation_weights(K, C, opt.augmentation, R, ks);
  if (!same) {
    ScopedTimer timer(stats, TimeCategory::Factorization);
    if (stats) ++stats->factorizations;
    factored.assign(vals.begin(), vals.end());
    factored_rows = C;
    augment(K, C, R);
    build_kkt(K, C, R, s, symmetric, L);
    PetscInt info1 = 0;
    for (int percent = 35; percent <= 35 * 16; percent *= 2)
      if (info1 = factorize_mumps(percent); !mumps_workspace_short(info1)) break;
    if (info1 < 0) {
      direct.reset();
      factored.clear();
      if (info1 == -10) {
        augment(K, C, R, -1.0);
        singular(K, b, C, symmetric, "the system of equations is singular (MUMPS's factor)");
      }
      throw std::runtime_error(
          fmt::format("MUMPS could not factorise the system of {} equations and {} constraint rows "
                      "(INFOG(1) = {}{})",
                      L.n, L.m, info1,
                      mumps_workspace_short(info1) || info1 == -13 || info1 == -19
                          ? ": not enough memory; more ranks (mpirun -np N) or --solver iterative"
                          : ""));
    }
  } else {
    out.reused_factor = true;
  }
  // right-hand side [b; -s g] in this rank's rows
  VecH rhs, x;
  petsc_check(MatCreateVecs(kkt, x.out(), rhs.out()), "MatCreateVecs");
  fill_rhs(rhs, b, C, R, s, L, true);
  {
    ScopedTimer timer(stats, TimeCategory::Solve);
    petsc_check(KSPSolve(direct, rhs, x), "KSPSolve");
    if (stats) ++stats->linear_solves;
  }
  std::vector<double> all;
  gather_all(x, all);
  for (PetscInt i = 0; i < L.n; ++i) du[i] = all[L.kkt_u(i)];
  for (PetscInt r = 0; r < L.m; ++r) dl[r] = s * all[L.kkt_l(r)];
  out.solves = 1;
  log::debug("  MUMPS: {} factor of {} equations and {} rows", same ? "same" : "new", L.n, L.m);
  return out;
}

// ---------------------------------------------------------------------------------------------
// Iterative

void PetscKktSolver::Impl::fill_a(const CsrMatrix& K, const KktLayout& L, double padding) {
  const SparsityPattern& pat = K.pattern();
  const auto vals = K.values();
  if (!A) {
    RowLists rows(L.u_local());
    for (PetscInt p = L.u0(); p < L.u1(); ++p) {
      const LocalIndex i = eq_of(p);
      if (i < 0)
        rows.add(p - L.u0(), p, padding);
      else
        for (LocalIndex k = pat.row_ptr[i]; k < pat.row_ptr[i + 1]; ++k)
          rows.add(p - L.u0(), row_of(pat.col[k]), vals[k]);
    }
    create_matrix(A.out(), rows, L.u_local(), L.n, L.n, block);
    petsc_check(MatSetOption(A, MAT_NEW_NONZERO_LOCATION_ERR, PETSC_TRUE), "MatSetOption");
    attach_near_null_space(L);
    amg.reset(); // a new matrix: a new hierarchy
    amg_ready = false;
    return;
  }
  std::vector<PetscInt> cols;
  for (PetscInt p = L.u0(); p < L.u1(); ++p) {
    const LocalIndex i = eq_of(p);
    if (i < 0) continue; // a padding row keeps its diagonal
    const LocalIndex k0 = pat.row_ptr[i], k1 = pat.row_ptr[i + 1];
    cols.resize(static_cast<std::size_t>(k1 - k0));
    for (LocalIndex k = k0; k < k1; ++k) cols[k - k0] = row_of(pat.col[k]);
    petsc_check(MatSetValues(A, 1, &p, k1 - k0, cols.data(), vals.data() + k0, INSERT_VALUES),
                "MatSetValues");
  }
  petsc_check(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  petsc_check(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
}

void PetscKktSolver::Impl::attach_near_null_space(const KktLayout& L) {
  if (modes.count == 0 ||
      modes.vectors.size() != static_cast<std::size_t>(modes.count) * pattern->n)
    return;
  // orthonormal (modified Gram-Schmidt); modes the free equations do not carry are dropped
  std::vector<Vec> kept;
  for (int k = 0; k < modes.count; ++k) {
    Vec v = nullptr;
    petsc_check(VecCreateMPI(PETSC_COMM_WORLD, L.u_local(), L.n, &v), "VecCreateMPI");
    PetscScalar* a = nullptr;
    petsc_check(VecGetArray(v, &a), "VecGetArray");
    const double* mode = modes.vectors.data() + static_cast<std::size_t>(k) * pattern->n;
    for (PetscInt p = L.u0(); p < L.u1(); ++p) {
      const LocalIndex i = eq_of(p);
      a[p - L.u0()] = i >= 0 ? mode[i] : 0.0;
    }
    petsc_check(VecRestoreArray(v, &a), "VecRestoreArray");
    for (Vec q : kept) {
      PetscScalar dot = 0;
      petsc_check(VecDot(v, q, &dot), "VecDot");
      petsc_check(VecAXPY(v, -dot, q), "VecAXPY");
    }
    PetscReal norm = 0;
    petsc_check(VecNorm(v, NORM_2, &norm), "VecNorm");
    if (norm > 1e-8 * std::sqrt(static_cast<double>(L.n))) {
      petsc_check(VecScale(v, 1.0 / norm), "VecScale");
      kept.push_back(v);
    } else {
      VecDestroy(&v);
    }
  }
  MatNullSpace space = nullptr;
  petsc_check(MatNullSpaceCreate(PETSC_COMM_WORLD, PETSC_FALSE, static_cast<PetscInt>(kept.size()),
                                 kept.data(), &space),
              "MatNullSpaceCreate");
  petsc_check(MatSetNearNullSpace(A, space), "MatSetNearNullSpace");
  MatNullSpaceDestroy(&space);
  for (Vec& v : kept) VecDestroy(&v);
}

KktStatistics PetscKktSolver::Impl::solve_iterative(CsrMatrix& K, std::span<const double> b,
                                                    const ConstraintBlock& C, std::span<double> du,
                                                    std::span<double> dl, bool symmetric,
                                                    const KktOptions& opt, RunStatistics* stats) {
  KktStatistics out;
  // rows that fix one equation, and compliant rows, leave the bordered system exactly; what
  // remains is (K', b', C')
  RowElimination elim;
  elim.reduce(K, b, C);
  const ConstraintBlock& Cr = elim.reduced_rows();
  const auto br = elim.reduced_b();
  const KktLayout L(a_size(K.n()), Cr.n_rows(), parallel::rank(), parallel::size(), block);
  const double s = multiplier_scale(K);
  std::vector<double> R, ks;
  augmentation_weights(K, Cr, opt.augmentation, R, ks);
  const int m = Cr.n_rows();
  augment(K, Cr, R);
  BorderedSystem sys;
  sys.layout = L;
  fill_a(K, L, s);
  sys.A = A;
  if (m > 0) {
    RowLists d(L.u_local()), c(L.l_local());
    for (int r = 0; r < m; ++r) {
      const double E = compliance_of(Cr, r);
      const bool own_row = r >= L.l0() && r < L.l1();
      for (LocalIndex k = Cr.row_ptr[r]; k < Cr.row_ptr[r + 1]; ++k) {
        const LocalIndex i = row_of(Cr.col[k]);
        if (i >= L.u0() && i < L.u1())
          d.add(i - L.u0(), r, s * (column_value(Cr, k) - Cr.val[k] * R[r] * E));
        if (own_row) c.add(r - L.l0(), i, s * Cr.val[k]);
      }
    }
    create_matrix(sys.Dp.out(), d, L.l_local(), L.n, L.m);
    create_matrix(sys.Cm.out(), c, L.u_local(), L.m, L.n);
    petsc_check(VecCreateMPI(PETSC_COMM_WORLD, L.l_local(), L.m, sys.Ev.out()), "VecCreateMPI");
    petsc_check(VecDuplicate(sys.Ev, sys.Sinv.out()), "VecDuplicate");
    PetscScalar *e = nullptr, *p = nullptr;
    petsc_check(VecGetArray(sys.Ev, &e), "VecGetArray");
    petsc_check(VecGetArray(sys.Sinv, &p), "VecGetArray");
    for (PetscInt r = L.l0(); r < L.l1(); ++r) {
      const double E = compliance_of(Cr, r);
      e[r - L.l0()] = s * s * E;
      p[r - L.l0()] = 1.0 / (s * s * (E + (1.0 - R[r] * E) / (R[r] + ks[r])));
    }
    petsc_check(VecRestoreArray(sys.Ev, &e), "VecRestoreArray");
    petsc_check(VecRestoreArray(sys.Sinv, &p), "VecRestoreArray");
  }
  sys.make_views();

  // the AMG cycle: rebuilt when asked, when the iterations it takes have doubled, or when more
  // rows changed than GMRES absorbs cheaply (each changed row moves A by a stiff spring at its
  // DOFs, an outlier eigenvalue of the preconditioned system: about one iteration each)
  const int changed = changed_rows(amg_rows, C);
  const bool rebuild = !amg_ready || opt.force_fresh || opt.reuse == FactorReuse::Never ||
                       per_decade_last > 2 * per_decade_after_build + 0.5 ||
                       changed > kRowsAbsorbed;
  if (!amg) {
    petsc_check(KSPCreate(PETSC_COMM_WORLD, amg.out()), "KSPCreate");
    petsc_check(KSPSetOptionsPrefix(amg, "inner_"), "KSPSetOptionsPrefix");
    petsc_check(KSPSetType(amg, KSPPREONLY), "KSPSetType");
    PC pc = nullptr;
    petsc_check(KSPGetPC(amg, &pc), "KSPGetPC");
    petsc_check(PCSetType(pc, PCGAMG), "PCSetType");
    petsc_check(KSPSetFromOptions(amg), "KSPSetFromOptions");
  }
  petsc_check(KSPSetOperators(amg, A, A), "KSPSetOperators");
  petsc_check(KSPSetReusePreconditioner(amg, rebuild ? PETSC_FALSE : PETSC_TRUE),
              "KSPSetReusePreconditioner");
  if (rebuild) {
    ScopedTimer timer(stats, TimeCategory::Factorization);
    if (stats) ++stats->factorizations;
    petsc_check(KSPSetUp(amg), "KSPSetUp (AMG)");
    amg_ready = true;
    amg_rows = C;
  }
  sys.inner = amg;

  // GMRES on the bordered operator
  const PetscInt local = L.u_local() + L.l_local(), N = L.n + L.m;
  MatH op;
  petsc_check(MatCreateShell(PETSC_COMM_WORLD, local, local, N, N, &sys, op.out()),
              "MatCreateShell");
  petsc_check(
      MatShellSetOperation(op, MATOP_MULT, reinterpret_cast<void (*)(void)>(shell_multiply)),
      "MatShellSetOperation");
  KspH ksp;
  petsc_check(KSPCreate(PETSC_COMM_WORLD, ksp.out()), "KSPCreate");
  petsc_check(KSPSetOperators(ksp, op, op), "KSPSetOperators");
  // K' alone and symmetric: CG (the AMG cycle is symmetric), on the true residual's norm
  const bool cg = m == 0 && symmetric && !C.has_columns() && !no_cg;
  if (cg) {
    petsc_check(KSPSetType(ksp, KSPCG), "KSPSetType");
    petsc_check(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
  } else {
    petsc_check(KSPSetType(ksp, KSPGMRES), "KSPSetType");
    petsc_check(KSPGMRESSetRestart(ksp, kGmresRestart), "KSPGMRESSetRestart");
  }
  petsc_check(KSPSetPCSide(ksp, cg ? PC_LEFT : PC_RIGHT), "KSPSetPCSide");
  // a reused hierarchy gets a few times the iterations of a new one before it is replaced
  const double rtol = opt.relative_tolerance > 0 ? opt.relative_tolerance : kDefaultRtol;
  const double decades = std::max(1.0, -std::log10(rtol));
  const int max_it =
      rebuild ? kMaxIterations : static_cast<int>((3 * per_decade_after_build + 3) * decades);
  petsc_check(KSPSetTolerances(ksp, rtol, 1e-300, PETSC_DEFAULT, max_it), "KSPSetTolerances");
  petsc_check(KSPSetFromOptions(ksp), "KSPSetFromOptions");
  PC pc = nullptr;
  petsc_check(KSPGetPC(ksp, &pc), "KSPGetPC");
  petsc_check(PCSetType(pc, PCSHELL), "PCSetType");
  petsc_check(PCShellSetContext(pc, &sys), "PCShellSetContext");
  petsc_check(PCShellSetApply(pc, shell_precondition), "PCShellSetApply");

  VecH rhs, x;
  petsc_check(VecCreateMPI(PETSC_COMM_WORLD, local, N, rhs.out()), "VecCreateMPI");
  petsc_check(VecDuplicate(rhs, x.out()), "VecDuplicate");
  fill_rhs(rhs, br, Cr, R, s, L, false, unpad);
  KSPConvergedReason reason{};
  PetscInt its = 0;
  {
    ScopedTimer timer(stats, TimeCategory::Solve);
    petsc_check(KSPSolve(ksp, rhs, x), "KSPSolve");
    petsc_check(KSPGetConvergedReason(ksp, &reason), "KSPGetConvergedReason");
    petsc_check(KSPGetIterationNumber(ksp, &its), "KSPGetIterationNumber");
  }
  // GMRES's residual is an estimate (from its least-squares problem) that round-off can part from
  // the true one: the true residual of the bordered system is checked, so that a "converged" step
  // is never a wrong one
  double true_ratio = 0.0;
  {
    VecH r;
    petsc_check(VecDuplicate(rhs, r.out()), "VecDuplicate");
    petsc_check(MatMult(op, x, r), "MatMult");
    petsc_check(VecAYPX(r, -1.0, rhs), "VecAYPX");
    PetscReal rn = 0, bn = 0;
    petsc_check(VecNorm(r, NORM_2, &rn), "VecNorm");
    petsc_check(VecNorm(rhs, NORM_2, &bn), "VecNorm");
    true_ratio = bn > 0 ? rn / bn : 0.0;
    if (reason > 0 && !(true_ratio <= kTrueResidualSlack * rtol)) reason = KSP_DIVERGED_BREAKDOWN;
  }
  if (stats) stats->linear_solves += its;
  per_decade_last = static_cast<double>(its) / decades;
  if (rebuild) per_decade_after_build = per_decade_last;
  log::debug("  {}: {} iterations ({} AMG), {} equations ({} pinned) and {} rows ({} left), true "
             "residual {:.1e}, reason {}",
             cg ? "CG" : "GMRES", its, rebuild ? "new" : "reused", K.n(), elim.pinned_count(),
             C.n_rows(), L.m, true_ratio, static_cast<int>(reason));
  if (reason < 0) {
    augment(K, Cr, R, -1.0); // back to K
    elim.restore(K);
    if (!rebuild || cg) {  // the old hierarchy, or CG, may be what failed: once more with a new
      amg_ready = false;   // hierarchy, and GMRES for the rest of the step if CG found the cycle
      no_cg = no_cg || cg; // indefinite (its Chebyshev smoothing bounds can miss)
      return solve_iterative(K, b, C, du, dl, symmetric, opt, stats);
    }
    // GMRES cannot solve this system with this preconditioner (an indefinite tangent that the
    // Chebyshev smoother does not expect, rotations of beams and shells, or a singular system):
    // it and the rest of the step are factorised, which also diagnoses a singular system
    const std::string what =
        fmt::format("{} did not converge on a system of {} equations and {} constraint rows ({} "
                    "iterations, PETSc reason {})",
                    cg ? "CG" : "GMRES", K.n(), C.n_rows(), its, static_cast<int>(reason));
    require_direct_fits(what);
    log::warning("--solver iterative: {}; the rest of the step is solved by MUMPS", what);
    direct_fallback = true;
    return solve_mumps(K, b, C, du, dl, symmetric, opt, stats);
  }
  std::vector<double> all;
  gather_all(x, all);
  for (LocalIndex i = 0; i < K.n(); ++i) du[i] = all[L.kkt_u(row_of(i))];
  std::vector<double> dl_reduced(static_cast<std::size_t>(m));
  for (PetscInt r = 0; r < L.m; ++r) dl_reduced[r] = s * all[L.kkt_l(r)];
  elim.recover(b, C, du, dl_reduced, dl);
  out.reused_factor = !rebuild;
  out.solves = static_cast<int>(its);
  out.schur_iterations = static_cast<int>(its);
  return out;
}

} // namespace gapfem
