// parallel.hpp for a build without PETSc: one process.
#include "linalg/constrained_solver.hpp"
#include "parallel/parallel.hpp"

#include <stdexcept>

namespace gapfem::parallel {

bool available() {
  return false;
}
void register_backends() {
  const std::string why = "this gapfem was built without PETSc, so it has no distributed or "
                          "iterative solver: install Debian's petsc-dev (scripts/install-deps.sh) "
                          "and build again";
  for (const char* name : {"mumps", "iterative"})
    register_solver_backend({name, "PETSc (not in this build)", false, true, why, {}});
}
void start(const std::vector<std::string>&) {
  throw std::runtime_error("this gapfem was built without PETSc, so it has no distributed or "
                           "iterative solver and cannot run under mpirun: install Debian's "
                           "petsc-dev (scripts/install-deps.sh) and build again");
}
bool started() {
  return false;
}
int rank() {
  return 0;
}
int size() {
  return 1;
}
void abort_job(int) {}
int finish(int exit_code, const std::string&) {
  return exit_code;
}
double max_over_ranks(double v) {
  return v;
}
int max_over_ranks(int v) {
  return v;
}
void barrier() {}

} // namespace gapfem::parallel
