#pragma once
/// @file petsc_runtime.hpp
/// PETSc error codes as exceptions (only for the PETSc sources).

namespace gapfem::parallel {

/// Throw std::runtime_error naming `what` and PETSc's message when `code` is not 0.
void petsc_check(int code, const char* what);

} // namespace gapfem::parallel
