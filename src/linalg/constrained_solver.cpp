#include "linalg/constrained_solver.hpp"

#include "linalg/kkt_solver.hpp"
#include "parallel/parallel.hpp"
#ifdef GAPFEM_HAVE_PETSC
#include "parallel/petsc_kkt_solver.hpp"
#endif

#include <stdexcept>

namespace gapfem {

std::string_view backend_name(SolverBackend backend) {
  switch (backend) {
  case SolverBackend::Cholmod:
    return "cholmod";
  case SolverBackend::Mumps:
    return "mumps";
  case SolverBackend::Iterative:
    return "iterative";
  }
  return "?";
}

std::unique_ptr<ConstrainedSolver> make_constrained_solver(SolverBackend backend,
                                                           const KktTuning& tuning) {
  if (backend == SolverBackend::Cholmod) {
    if (parallel::size() > 1)
      throw std::runtime_error("--solver cholmod solves on one process, but this run has several "
                               "(mpirun): use --solver mumps or --solver iterative");
    return std::make_unique<KktSolver>(tuning);
  }
#ifdef GAPFEM_HAVE_PETSC
  parallel::start();
  return std::make_unique<PetscKktSolver>(backend == SolverBackend::Mumps
                                              ? PetscKktSolver::Method::Mumps
                                              : PetscKktSolver::Method::Iterative);
#else
  parallel::start(); // throws: this build has no PETSc
  throw std::logic_error("unreachable");
#endif
}

} // namespace gapfem
