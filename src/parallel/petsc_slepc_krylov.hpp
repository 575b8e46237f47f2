#pragma once
/// @file petsc_slepc_krylov.hpp
/// The Krylov method of the eigen solvers on the PETSc backend (linalg/krylov_eigen.hpp): SLEPc's
/// Krylov-Schur, its vectors distributed over the ranks as PETSc splits a vector. The caller's
/// operators act on whole vectors (the analysis is replicated): each product gathers the vector on
/// every rank, applies the operator (the factor's solve is MUMPS's, itself distributed) and keeps
/// this rank's rows. Without SLEPc in the build (slepc-dev), Spectra on one process, and an error
/// naming the package on several.
#include "linalg/krylov_eigen.hpp"

#include <memory>

namespace gapfem::parallel {

std::unique_ptr<KrylovEigenSolver> make_slepc_krylov();

} // namespace gapfem::parallel
