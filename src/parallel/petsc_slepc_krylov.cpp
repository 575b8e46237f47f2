// SLEPc's Krylov-Schur behind the KrylovEigenSolver seam (petsc_slepc_krylov.hpp). T = S A is posed
// to SLEPc as the generalized Hermitian problem (A, B), so that its bases are orthogonal in the B
// inner product, with the plain shift transformation (sigma = 0: the operator B^-1 A, eigenvalues
// theta unchanged) whose "solve with B" is the caller's S: a preconditioner-only KSP whose
// preconditioner applies S. A and B are shell matrices applying the caller's maps.
#include "parallel/petsc_slepc_krylov.hpp"

#include "parallel/kkt_layout.hpp"
#include "parallel/parallel.hpp"
#include "parallel/petsc_detail.hpp"
#include "parallel/petsc_runtime.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <stdexcept>

#ifdef GAPFEM_HAVE_SLEPC
#include <slepceps.h>
#endif

namespace gapfem::parallel {

#ifdef GAPFEM_HAVE_SLEPC
namespace {

using petsc_detail::MatH;
using petsc_detail::ScatterH;
using petsc_detail::VecH;
using EpsH = petsc_detail::Handle<EPS, EPSDestroy>;

/// What the shells share: the gather of a distributed vector to every rank, and the first
/// exception a map threw (PETSc's callbacks return codes; it is thrown again after the solve).
struct Gather {
  KktLayout layout;
  ScatterH to_all;
  VecH whole;
  std::vector<double> y;
  std::exception_ptr failure;

  /// y = map(x) on this rank's rows.
  PetscErrorCode apply(const VectorMap& map, Vec x, Vec yv) {
    try {
      petsc_check(VecScatterBegin(to_all, x, whole, INSERT_VALUES, SCATTER_FORWARD), "gather");
      petsc_check(VecScatterEnd(to_all, x, whole, INSERT_VALUES, SCATTER_FORWARD), "gather");
      const PetscScalar* xa = nullptr;
      petsc_check(VecGetArrayRead(whole, &xa), "VecGetArrayRead");
      y.resize(static_cast<std::size_t>(layout.n));
      map(xa, y.data());
      petsc_check(VecRestoreArrayRead(whole, &xa), "VecRestoreArrayRead");
      PetscScalar* ya = nullptr;
      petsc_check(VecGetArray(yv, &ya), "VecGetArray");
      std::copy(y.begin() + layout.u0(), y.begin() + layout.u1(), ya);
      petsc_check(VecRestoreArray(yv, &ya), "VecRestoreArray");
      return 0;
    } catch (...) {
      if (!failure) failure = std::current_exception();
      return PETSC_ERR_USER;
    }
  }
};

/// One of the caller's maps as a shell's context.
struct ShellMap {
  Gather* gather;
  const VectorMap* map;
};

PetscErrorCode matrix_product(Mat A, Vec x, Vec y) {
  ShellMap* m = nullptr;
  MatShellGetContext(A, &m);
  return m->gather->apply(*m->map, x, y);
}

PetscErrorCode preconditioner_solve(PC pc, Vec x, Vec y) {
  ShellMap* m = nullptr;
  PCShellGetContext(pc, &m);
  return m->gather->apply(*m->map, x, y);
}

/// A shell matrix of the request's size applying `m`.
void shell_matrix(Mat* out, PetscInt n, PetscInt local, ShellMap& m) {
  petsc_check(MatCreateShell(PETSC_COMM_WORLD, local, local, n, n, &m, out), "MatCreateShell");
  petsc_check(
      MatShellSetOperation(*out, MATOP_MULT, reinterpret_cast<void (*)(void)>(matrix_product)),
      "MatShellSetOperation");
}

class SlepcKrylov final : public KrylovEigenSolver {
 public:
  std::string_view name() const override { return "SLEPc (Krylov-Schur)"; }
  KrylovResult solve(const KrylovRequest& req) override;

 private:
  static void configure(EPS eps, const KrylovRequest& req, Vec start, ShellMap& solve);
  static KrylovResult results(EPS eps, const Gather& gather, const KrylovRequest& req);
};

void SlepcKrylov::configure(EPS eps, const KrylovRequest& req, Vec start, ShellMap& solve) {
  petsc_check(EPSSetProblemType(eps, EPS_GHEP), "EPSSetProblemType");
  petsc_check(EPSSetType(eps, EPSKRYLOVSCHUR), "EPSSetType");
  petsc_check(
      EPSSetWhichEigenpairs(eps, req.largest_algebraic ? EPS_LARGEST_REAL : EPS_LARGEST_MAGNITUDE),
      "EPSSetWhichEigenpairs");
  petsc_check(EPSSetDimensions(eps, req.nev, std::min<PetscInt>(req.ncv, req.n), PETSC_DEFAULT),
              "EPSSetDimensions");
  petsc_check(EPSSetTolerances(eps, req.tolerance, req.max_restarts), "EPSSetTolerances");
  petsc_check(EPSSetConvergenceTest(eps, EPS_CONV_REL), "EPSSetConvergenceTest");
  petsc_check(EPSSetInitialSpace(eps, 1, &start), "EPSSetInitialSpace");
  ST st = nullptr;
  petsc_check(EPSGetST(eps, &st), "EPSGetST");
  petsc_check(STSetType(st, STSHIFT), "STSetType");
  petsc_check(STSetShift(st, 0.0), "STSetShift");
  KSP ksp = nullptr;
  petsc_check(STGetKSP(st, &ksp), "STGetKSP");
  petsc_check(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
  PC pc = nullptr;
  petsc_check(KSPGetPC(ksp, &pc), "KSPGetPC");
  petsc_check(PCSetType(pc, PCSHELL), "PCSetType");
  petsc_check(PCShellSetContext(pc, &solve), "PCShellSetContext");
  petsc_check(PCShellSetApply(pc, preconditioner_solve), "PCShellSetApply");
}

KrylovResult SlepcKrylov::results(EPS eps, const Gather& gather, const KrylovRequest& req) {
  KrylovResult out;
  PetscInt nconv = 0, its = 0;
  petsc_check(EPSGetConverged(eps, &nconv), "EPSGetConverged");
  petsc_check(EPSGetIterationNumber(eps, &its), "EPSGetIterationNumber");
  out.restarts = static_cast<int>(its);
  out.converged = nconv >= req.nev;
  if (!out.converged) return out;
  const std::size_t n = static_cast<std::size_t>(req.n);
  VecH x;
  petsc_check(VecCreateMPI(PETSC_COMM_WORLD, gather.layout.u_local(), req.n, x.out()), "VecCreate");
  std::vector<double> whole, bx(n);
  for (PetscInt k = 0; k < req.nev; ++k) {
    PetscScalar theta = 0.0;
    petsc_check(EPSGetEigenpair(eps, k, &theta, nullptr, x, nullptr), "EPSGetEigenpair");
    petsc_detail::gather_all(x, whole);
    req.inner(whole.data(), bx.data()); // x^T B x = 1 whatever SLEPc's normalisation
    double xbx = 0.0;
    for (std::size_t i = 0; i < n; ++i) xbx += whole[i] * bx[i];
    const double scale = xbx > 0.0 ? 1.0 / std::sqrt(xbx) : 1.0;
    for (double& v : whole) v *= scale;
    out.theta.push_back(theta);
    out.vectors.insert(out.vectors.end(), whole.begin(), whole.end());
  }
  return out;
}

KrylovResult SlepcKrylov::solve(const KrylovRequest& req) {
  if (req.nev >= req.ncv || req.ncv > req.n || req.start.size() != std::size_t(req.n))
    throw std::invalid_argument("nev < ncv <= n and a start vector of n entries are needed");
  Gather gather;
  gather.layout = KktLayout(static_cast<int>(req.n), 0);
  const PetscInt local = gather.layout.u_local();
  VecH start;
  petsc_check(VecCreateMPI(PETSC_COMM_WORLD, local, req.n, start.out()), "VecCreateMPI");
  PetscScalar* s = nullptr;
  petsc_check(VecGetArray(start, &s), "VecGetArray");
  std::copy(req.start.begin() + gather.layout.u0(), req.start.begin() + gather.layout.u1(), s);
  petsc_check(VecRestoreArray(start, &s), "VecRestoreArray");
  petsc_check(VecScatterCreateToAll(start, gather.to_all.out(), gather.whole.out()),
              "VecScatterCreateToAll");
  ShellMap apply{&gather, &req.apply}, inner{&gather, &req.inner}, solve{&gather, &req.solve};
  MatH A, B;
  shell_matrix(A.out(), req.n, local, apply);
  shell_matrix(B.out(), req.n, local, inner);
  EpsH eps;
  petsc_check(EPSCreate(PETSC_COMM_WORLD, eps.out()), "EPSCreate");
  petsc_check(EPSSetOperators(eps, A, B), "EPSSetOperators");
  configure(eps, req, start, solve);
  const PetscErrorCode rc = EPSSolve(eps);
  if (gather.failure) std::rethrow_exception(gather.failure);
  petsc_check(rc, "EPSSolve");
  return results(eps, gather, req);
}

} // namespace

std::unique_ptr<KrylovEigenSolver> make_slepc_krylov() {
  return std::make_unique<SlepcKrylov>();
}

#else // a PETSc build without SLEPc

std::unique_ptr<KrylovEigenSolver> make_slepc_krylov() {
  if (size() > 1)
    throw std::runtime_error("this build of gapfem has no SLEPc (Debian's slepc-dev), which "
                             "extracts eigenvalues on several processes: run the job without "
                             "mpirun, or rebuild gapfem with slepc-dev installed");
  return make_spectra_krylov();
}

#endif

} // namespace gapfem::parallel
