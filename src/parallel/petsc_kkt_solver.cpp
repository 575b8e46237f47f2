#include "parallel/petsc_kkt_solver.hpp"

#include "common/error.hpp"
#include "common/log.hpp"
#include "common/memory.hpp"
#include "linalg/kkt_solver.hpp"
#include "linalg/row_elimination.hpp"
#include "parallel/kkt_layout.hpp"
#include "parallel/parallel.hpp"
#include "parallel/petsc_detail.hpp"
#include "parallel/petsc_runtime.hpp"
#include "parallel/petsc_slepc_krylov.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <petscksp.h>
#include <unordered_map>

namespace gapfem {

using parallel::petsc_check;

namespace petsc_detail {

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
  return 1.0 - R[r] * C.row_compliance(r);
}

std::size_t serial_factor_bytes(std::shared_ptr<const SparsityPattern> pattern) {
  KktSolver serial;
  serial.analyze(std::move(pattern));
  return serial.factor_bytes_estimate();
}

/// The multiplier scale s: the mean of |diag K| (1 for an empty or zero diagonal).
double multiplier_scale(const CsrMatrix& K) {
  double sum = 0.0;
  for (LocalIndex i = 0; i < K.n(); ++i) sum += std::abs(K.diagonal(i));
  const double s = K.n() > 0 ? sum / K.n() : 1.0;
  return s > 0 && std::isfinite(s) ? s : 1.0;
}

PetscInt create_preallocated(Mat* out, std::span<const PetscInt> diagonal_block,
                             std::span<const PetscInt> off_diagonal, PetscInt local_cols,
                             PetscInt global_rows, PetscInt global_cols, PetscInt block) {
  const auto nloc = static_cast<PetscInt>(diagonal_block.size());
  PetscInt first = 0; // global number of this rank's first row
  MPI_Exscan(&nloc, &first, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD);
  if (parallel::rank() == 0) first = 0;
  petsc_check(MatCreate(PETSC_COMM_WORLD, out), "MatCreate");
  petsc_check(MatSetSizes(*out, nloc, local_cols, global_rows, global_cols), "MatSetSizes");
  petsc_check(MatSetType(*out, MATAIJ), "MatSetType");
  if (block > 1) petsc_check(MatSetBlockSize(*out, block), "MatSetBlockSize");
  petsc_check(MatSeqAIJSetPreallocation(*out, 0, diagonal_block.data()),
              "MatSeqAIJSetPreallocation");
  petsc_check(MatMPIAIJSetPreallocation(*out, 0, diagonal_block.data(), 0, off_diagonal.data()),
              "MatMPIAIJSetPreallocation");
  return first;
}

PetscInt first_column(PetscInt local_cols) {
  PetscInt first_col = 0;
  MPI_Exscan(&local_cols, &first_col, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD);
  return parallel::rank() == 0 ? 0 : first_col;
}

void create_matrix(Mat* out, const RowLists& rows, PetscInt local_cols, PetscInt global_rows,
                   PetscInt global_cols, PetscInt block) {
  const PetscInt first_col = first_column(local_cols);
  std::vector<PetscInt> d(rows.cols.size(), 0), o(rows.cols.size(), 0);
  for (std::size_t i = 0; i < rows.cols.size(); ++i)
    for (PetscInt c : rows.cols[i]) ++(c >= first_col && c < first_col + local_cols ? d[i] : o[i]);
  const PetscInt first =
      create_preallocated(out, d, o, local_cols, global_rows, global_cols, block);
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

/// A = K + C^T R C in place (the springs lie inside each row's own block of the pattern).
void augment(CsrMatrix& K, const ConstraintBlock& C, std::span<const double> R, double sign) {
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
              std::span<const LocalIndex> unpad) {
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

} // namespace petsc_detail

using namespace petsc_detail;

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
  _impl->u_starts.clear();
  _impl->direct_fallback = false;
  _impl->gmres_before_cg = 0;
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
  m.u_starts.clear();
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
  const double need = kDirectMemoryFactor * static_cast<double>(serial_factor_bytes(pattern));
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
    const double E = C.row_compliance(r), f = row_factor(R, C, r);
    for (LocalIndex k = C.row_ptr[r]; k < C.row_ptr[r + 1]; ++k) {
      const LocalIndex i = C.col[k];
      if (i >= L.u0() && i < L.u1())
        rows.add(i - L.u0(), L.kkt_l(r), s * (C.column_value(k) - C.val[k] * R[r] * E));
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

void PetscKktSolver::Impl::factor_mumps(CsrMatrix& K, const ConstraintBlock& C,
                                        std::span<const double> R, double s, bool symmetric,
                                        const KktLayout& L, std::span<const double> b,
                                        RunStatistics* stats) {
  ScopedTimer timer(stats, TimeCategory::Factorization);
  if (stats) ++stats->factorizations;
  const auto vals = K.values();
  factored.assign(vals.begin(), vals.end());
  factored_rows = C;
  augment(K, C, R);
  build_kkt(K, C, R, s, symmetric, L);
  PetscInt info1 = 0;
  for (int percent = 35; percent <= 35 * 16; percent *= 2)
    if (info1 = factorize_mumps(percent); !mumps_workspace_short(info1)) break;
  if (info1 >= 0) return;
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

void PetscKktSolver::Impl::solve_direct(std::span<const double> b, const ConstraintBlock& C,
                                        std::span<const double> R, double s, const KktLayout& L,
                                        std::span<double> du, std::span<double> dl,
                                        RunStatistics* stats) const {
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
  if (!same)
    factor_mumps(K, C, R, s, symmetric, L, b, stats);
  else
    out.reused_factor = true;
  solve_direct(b, C, R, s, L, du, dl, stats);
  out.solves = 1;
  log::debug("  MUMPS: {} factor of {} equations and {} rows", same ? "same" : "new", L.n, L.m);
  return out;
}

/// MUMPS's factor of one bordered system for many right-hand sides (both methods: a shift-invert
/// eigensolver or a reduction needs a direct factor), with a bordered matrix of its own.
class PetscKktSolver::Factor final : public ConstrainedFactor {
 public:
  Factor(std::shared_ptr<const SparsityPattern> pattern, const CsrMatrix& K,
         const ConstraintBlock& C, bool symmetric, RunStatistics* stats)
      : _layout(K.n(), C.n_rows()), _s(multiplier_scale(K)), _rows(C) {
    _impl.method = Method::Mumps;
    _impl.pattern = std::move(pattern);
    std::vector<double> ks;
    augmentation_weights(K, C, KktOptions{}.augmentation, _R, ks);
    CsrMatrix A = K;
    const std::vector<double> zero(static_cast<std::size_t>(K.n()), 0.0);
    _impl.factor_mumps(A, C, _R, _s, symmetric, _layout, zero, stats);
  }
  void solve(std::span<const double> b, std::span<const double> g, std::span<double> x,
             std::span<double> l, int k) override {
    const auto n = static_cast<std::size_t>(_layout.n), m = static_cast<std::size_t>(_layout.m);
    for (std::size_t j = 0; j < static_cast<std::size_t>(k); ++j) {
      std::copy(g.begin() + j * m, g.begin() + (j + 1) * m, _rows.g.begin());
      _impl.solve_direct(b.subspan(j * n, n), _rows, _R, _s, _layout, x.subspan(j * n, n),
                         l.subspan(j * m, m), nullptr);
    }
  }

 private:
  Impl _impl;
  KktLayout _layout;
  double _s;
  ConstraintBlock _rows; ///< g: the right-hand side being solved
  std::vector<double> _R;
};

std::unique_ptr<ConstrainedFactor> PetscKktSolver::factorize(const CsrMatrix& K,
                                                             const ConstraintBlock& C,
                                                             bool symmetric, RunStatistics* stats) {
  FE_CHECK(_impl->pattern && K.n() == _impl->pattern->n,
           "PETSc solver not analysed for this pattern");
  return std::make_unique<Factor>(_impl->pattern, K, C, symmetric, stats);
}

std::unique_ptr<KrylovEigenSolver> PetscKktSolver::krylov_eigen_solver() const {
  return parallel::make_slepc_krylov();
}

std::size_t PetscKktSolver::factor_bytes_estimate() {
  FE_CHECK(_impl->pattern, "PETSc solver not analysed");
  return serial_factor_bytes(_impl->pattern);
}

namespace parallel {

void register_backends() {
  auto make = [](PetscKktSolver::Method method) {
    return [method](const KktTuning&) -> std::unique_ptr<ConstrainedSolver> {
      start(); // MPI and PETSc, when the run did not start them yet
      return std::make_unique<PetscKktSolver>(method);
    };
  };
  register_solver_backend({"mumps",
                           "PETSc + MUMPS: LDL^T (LU when unsymmetric) of the whole bordered "
                           "system, any number of processes",
                           false, true, "", make(PetscKktSolver::Method::Mumps)});
  register_solver_backend({"iterative",
                           "PETSc: GMRES on the bordered system with an AMG block preconditioner, "
                           "any number of processes",
                           false, true, "", make(PetscKktSolver::Method::Iterative)});
}

} // namespace parallel

} // namespace gapfem
