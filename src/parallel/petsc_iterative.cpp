// The iterative method of PetscKktSolver (`--solver iterative`): the rows that need no
// iteration eliminated (RowElimination), A numbered by nodes, one AMG cycle, CG or GMRES on the
// bordered system, the checks and the fallbacks. See petsc_kkt_solver.hpp.
#include "common/error.hpp"
#include "common/log.hpp"
#include "linalg/row_elimination.hpp"
#include "parallel/parallel.hpp"
#include "parallel/petsc_detail.hpp"
#include "parallel/petsc_runtime.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <iterator>

namespace gapfem {

using parallel::petsc_check;
using namespace petsc_detail;

// The operator and the preconditioner (PETSc shell callbacks)

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

void PetscKktSolver::Impl::fill_a(const CsrMatrix& K, const KktLayout& L, double padding) {
  const SparsityPattern& pat = K.pattern();
  const auto vals = K.values();
  const bool create = !A;
  if (create) { // preallocated from K's pattern, without a copy of this rank's rows
    std::vector<PetscInt> d(static_cast<std::size_t>(L.u_local()), 1), o(d.size(), 0);
    for (PetscInt p = L.u0(); p < L.u1(); ++p)
      if (const LocalIndex i = eq_of(p); i >= 0) {
        d[p - L.u0()] = 0;
        for (LocalIndex k = pat.row_ptr[i]; k < pat.row_ptr[i + 1]; ++k) {
          const PetscInt c = row_of(pat.col[k]);
          ++(c >= L.u0() && c < L.u1() ? d : o)[p - L.u0()];
        }
      }
    create_preallocated(A.out(), d, o, L.u_local(), L.n, L.n, block);
  }
  std::vector<PetscInt> cols;
  for (PetscInt p = L.u0(); p < L.u1(); ++p) {
    const LocalIndex i = eq_of(p);
    if (i < 0) { // a padding row: its diagonal, set once
      if (create)
        petsc_check(MatSetValues(A, 1, &p, 1, &p, &padding, INSERT_VALUES), "MatSetValues");
      continue;
    }
    const LocalIndex k0 = pat.row_ptr[i], k1 = pat.row_ptr[i + 1];
    cols.resize(static_cast<std::size_t>(k1 - k0));
    for (LocalIndex k = k0; k < k1; ++k) cols[k - k0] = row_of(pat.col[k]);
    petsc_check(MatSetValues(A, 1, &p, k1 - k0, cols.data(), vals.data() + k0, INSERT_VALUES),
                "MatSetValues");
  }
  petsc_check(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  petsc_check(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  if (!create) return;
  petsc_check(MatSetOption(A, MAT_NEW_NONZERO_LOCATION_ERR, PETSC_TRUE), "MatSetOption");
  attach_near_null_space(L);
  amg.reset(); // a new matrix: a new hierarchy
  amg_ready = false;
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

void PetscKktSolver::Impl::build_rows(BorderedSystem& sys, const ConstraintBlock& Cr,
                                      std::span<const double> R, std::span<const double> ks,
                                      double s) const {
  const KktLayout& L = sys.layout;
  const int m = Cr.n_rows();
  RowLists d(L.u_local()), c(L.l_local());
  for (int r = 0; r < m; ++r) {
    const double E = Cr.row_compliance(r);
    const bool own_row = r >= L.l0() && r < L.l1();
    for (LocalIndex k = Cr.row_ptr[r]; k < Cr.row_ptr[r + 1]; ++k) {
      const LocalIndex i = row_of(Cr.col[k]);
      if (i >= L.u0() && i < L.u1())
        d.add(i - L.u0(), r, s * (Cr.column_value(k) - Cr.val[k] * R[r] * E));
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
    const double E = Cr.row_compliance(r);
    e[r - L.l0()] = s * s * E;
    p[r - L.l0()] = 1.0 / (s * s * (E + (1.0 - R[r] * E) / (R[r] + ks[r])));
  }
  petsc_check(VecRestoreArray(sys.Ev, &e), "VecRestoreArray");
  petsc_check(VecRestoreArray(sys.Sinv, &p), "VecRestoreArray");
}

bool PetscKktSolver::Impl::prepare_amg(const ConstraintBlock& springs,
                                       std::span<const LocalIndex> pinned, LocalIndex n,
                                       const KktOptions& opt, RunStatistics* stats) {
  // the AMG cycle: rebuilt when asked, when the iterations it takes have doubled, when more
  // spring rows changed than the Krylov method absorbs cheaply (each moves A by a stiff spring at
  // its DOFs, an outlier eigenvalue of the preconditioned system: about one iteration each), or
  // when the pinned equations changed by more than a share of the equations (a pinned row and
  // column become a diagonal: a local change that a cycle built for the other pinned set
  // preconditions nearly as well; measured on a 362k slab whose contact set changes by 100-25,000
  // gaps an iteration: 307 CG iterations with 15 hierarchies at 2,000 changes, 306 with 27 at 20,
  // 670 with 3 at none)
  std::vector<LocalIndex> pins(pinned.begin(), pinned.end());
  std::sort(pins.begin(), pins.end());
  std::vector<LocalIndex> moved;
  std::set_symmetric_difference(pins.begin(), pins.end(), amg_pins.begin(), amg_pins.end(),
                                std::back_inserter(moved));
  const bool rebuild =
      !amg_ready || opt.force_fresh || opt.reuse == FactorReuse::Never ||
      per_decade_last > 2 * per_decade_after_build + 0.5 ||
      changed_rows(amg_rows, springs) > kRowsAbsorbed ||
      static_cast<double>(moved.size()) > std::max<double>(kRowsAbsorbed, kPinnedShareAbsorbed * n);
  if (!amg) {
    petsc_check(KSPCreate(PETSC_COMM_WORLD, amg.out()), "KSPCreate");
    petsc_check(KSPSetOptionsPrefix(amg, "inner_"), "KSPSetOptionsPrefix");
    petsc_check(KSPSetType(amg, KSPPREONLY), "KSPSetType");
    PC pc = nullptr;
    petsc_check(KSPGetPC(amg, &pc), "KSPGetPC");
    petsc_check(PCSetType(pc, PCGAMG), "PCSetType");
    // A rebuilt hierarchy keeps its interpolation (GAMG's default) and recomputes the Galerkin
    // products. The eigenvalue bounds of the Chebyshev smoothers are then estimated on each new
    // operator: the estimate made while smoothing the first prolongator (PETSc's default since
    // 3.17) is stale once gaps pin other equations, and the cycle became indefinite (CG failed on
    // every system of a 362k slab; GMRES took 20-38 iterations a system on the 1M slab).
    petsc_check(PCGAMGSetUseSAEstEig(pc, PETSC_FALSE), "PCGAMGSetUseSAEstEig");
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
    amg_rows = springs;
    amg_pins = std::move(pins);
  }
  return rebuild;
}

PetscKktSolver::Impl::KrylovRun PetscKktSolver::Impl::run_krylov(BorderedSystem& sys, Vec rhs,
                                                                 Vec x, bool cg, double rtol,
                                                                 int max_it,
                                                                 RunStatistics* stats) const {
  const KktLayout& L = sys.layout;
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
  if (cg) { // on the true residual's norm
    petsc_check(KSPSetType(ksp, KSPCG), "KSPSetType");
    petsc_check(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
  } else {
    petsc_check(KSPSetType(ksp, KSPGMRES), "KSPSetType");
    petsc_check(KSPGMRESSetRestart(ksp, kGmresRestart), "KSPGMRESSetRestart");
  }
  petsc_check(KSPSetPCSide(ksp, cg ? PC_LEFT : PC_RIGHT), "KSPSetPCSide");
  petsc_check(KSPSetTolerances(ksp, rtol, 1e-300, PETSC_DEFAULT, max_it), "KSPSetTolerances");
  petsc_check(KSPSetFromOptions(ksp), "KSPSetFromOptions");
  PC pc = nullptr;
  petsc_check(KSPGetPC(ksp, &pc), "KSPGetPC");
  petsc_check(PCSetType(pc, PCSHELL), "PCSetType");
  petsc_check(PCShellSetContext(pc, &sys), "PCShellSetContext");
  petsc_check(PCShellSetApply(pc, shell_precondition), "PCShellSetApply");

  KrylovRun run;
  {
    ScopedTimer timer(stats, TimeCategory::Solve);
    petsc_check(KSPSolve(ksp, rhs, x), "KSPSolve");
    petsc_check(KSPGetConvergedReason(ksp, &run.reason), "KSPGetConvergedReason");
    petsc_check(KSPGetIterationNumber(ksp, &run.iterations), "KSPGetIterationNumber");
  }
  // GMRES's residual is an estimate (from its least-squares problem) that round-off can part from
  // the true one: the true residual of the bordered system is checked, so that a "converged" step
  // is never a wrong one
  VecH r;
  petsc_check(VecDuplicate(rhs, r.out()), "VecDuplicate");
  petsc_check(MatMult(op, x, r), "MatMult");
  petsc_check(VecAYPX(r, -1.0, rhs), "VecAYPX");
  PetscReal rn = 0, bn = 0;
  petsc_check(VecNorm(r, NORM_2, &rn), "VecNorm");
  petsc_check(VecNorm(rhs, NORM_2, &bn), "VecNorm");
  run.true_ratio = bn > 0 ? rn / bn : 0.0;
  if (run.reason > 0 && !(run.true_ratio <= kTrueResidualSlack * rtol))
    run.reason = KSP_DIVERGED_BREAKDOWN;
  return run;
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
  if (!A) partition_blocks(); // the first system of a step
  const KktLayout L = u_starts.empty() ? KktLayout(a_size(K.n()), Cr.n_rows(), parallel::rank(),
                                                   parallel::size(), block)
                                       : KktLayout(u_starts, Cr.n_rows());
  const double s = multiplier_scale(K);
  std::vector<double> R, ks;
  augmentation_weights(K, Cr, opt.augmentation, R, ks);
  const int m = Cr.n_rows();
  augment(K, Cr, R);
  BorderedSystem sys;
  sys.layout = L;
  fill_a(K, L, s);
  sys.A = A;
  if (m > 0) build_rows(sys, Cr, R, ks, s);
  sys.make_views();

  const ConstraintBlock springs = elim.unpinned_rows(C);
  bool rebuild = prepare_amg(springs, elim.pinned_equations(), K.n(), opt, stats);
  sys.inner = amg;

  // K' alone and symmetric: CG (the AMG cycle is symmetric), otherwise GMRES
  bool cg = m == 0 && symmetric && !C.has_columns();
  if (cg && gmres_before_cg > 0) {
    cg = false;
    --gmres_before_cg;
  }
  const double rtol = opt.relative_tolerance > 0 ? opt.relative_tolerance : kDefaultRtol;
  const double decades = std::max(1.0, -std::log10(rtol));
  VecH rhs, x;
  const PetscInt local = L.u_local() + L.l_local(), N = L.n + L.m;
  petsc_check(VecCreateMPI(PETSC_COMM_WORLD, local, N, rhs.out()), "VecCreateMPI");
  petsc_check(VecDuplicate(rhs, x.out()), "VecDuplicate");
  fill_rhs(rhs, br, Cr, R, s, L, false, unpad);
  // a reused hierarchy gets a few times the iterations of a new one before it is replaced
  const auto attempt = [&] {
    const int max_it =
        rebuild ? kMaxIterations : static_cast<int>((3 * per_decade_after_build + 3) * decades);
    const KrylovRun run = run_krylov(sys, rhs, x, cg, rtol, max_it, stats);
    if (stats) stats->linear_solves += run.iterations;
    log::debug("  {}: {} iterations ({} AMG), {} equations ({} pinned) and {} rows ({} left), "
               "true residual {:.1e}, reason {}",
               cg ? "CG" : "GMRES", run.iterations, rebuild ? "new" : "reused", K.n(),
               elim.pinned_count(), C.n_rows(), L.m, run.true_ratio, static_cast<int>(run.reason));
    return run;
  };
  const auto renew_hierarchy = [&] {
    amg_ready = false;
    rebuild = prepare_amg(springs, elim.pinned_equations(), K.n(), opt, stats);
    sys.inner = amg;
  };
  KrylovRun run = attempt();
  if (run.reason < 0 && cg) {
    // CG found the cycle or the tangent indefinite (the Chebyshev smoothers' eigenvalue bounds can
    // miss; an NLGEOM tangent can be indefinite): GMRES, on a new hierarchy unless this one is
    // new, for this solve and the next few
    cg = false;
    gmres_before_cg = kGmresAfterCgFailure;
    if (!rebuild) renew_hierarchy();
    run = attempt();
  } else if (run.reason < 0 && !rebuild) { // the old hierarchy may be what failed
    renew_hierarchy();
    run = attempt();
  }
  const PetscInt its = run.iterations;
  if (run.reason < 0) {
    augment(K, Cr, R, -1.0); // back to K
    elim.restore(K);
    // GMRES cannot solve this system with this preconditioner (an indefinite tangent that the
    // Chebyshev smoother does not expect, rotations of beams and shells, or a singular system):
    // it and the rest of the step are factorised, which also diagnoses a singular system
    const std::string what =
        fmt::format("{} did not converge on a system of {} equations and {} constraint rows ({} "
                    "iterations, PETSc reason {})",
                    cg ? "CG" : "GMRES", K.n(), C.n_rows(), its, static_cast<int>(run.reason));
    require_direct_fits(what);
    log::warning("--solver iterative: {}; the rest of the step is solved by MUMPS", what);
    direct_fallback = true;
    return solve_mumps(K, b, C, du, dl, symmetric, opt, stats);
  }
  per_decade_last = static_cast<double>(its) / decades;
  if (rebuild) per_decade_after_build = per_decade_last;
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
