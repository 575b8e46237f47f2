#pragma once
/// @file krylov_eigen.hpp
/// The Krylov method under the eigen solvers (eigen_solver.hpp): the eigenpairs of an operator
///
///     T = S A,   T x = theta x,   x^T B x = 1,
///
/// self-adjoint in the inner product of a symmetric positive semi-definite B, S a solve with the
/// caller's factor: those largest in magnitude (or largest algebraically). *FREQUENCY gives
/// S = (K - sigma M)^-1_C, A = B = M; *BUCKLE S = K0^-1_C, A = G, B = K0. The caller applies S, A
/// and B; the method only combines vectors. Which method a run uses is its solver backend's choice
/// (ConstrainedSolver::krylov_eigen_solver): Spectra's implicitly restarted Lanczos on one process
/// (here), SLEPc's Krylov-Schur on the PETSc backend (parallel/petsc_slepc_krylov.cpp), whose
/// vectors are distributed over the ranks. Either way the caller's vectors are whole: n entries on
/// every process, and every process calls the maps alike (they may be collective).
#include "common/types.hpp"

#include <functional>
#include <memory>
#include <string_view>
#include <vector>

namespace gapfem {

/// y = A x for whole vectors of n entries.
using VectorMap = std::function<void(const double* x, double* y)>;

struct KrylovRequest {
  LocalIndex n = 0;
  VectorMap solve;          ///< y = S x
  VectorMap apply;          ///< y = A x
  VectorMap inner;          ///< y = B x, the inner product's matrix
  int nev = 1;              ///< eigenpairs wanted
  int ncv = 0;              ///< the Krylov space's dimension (nev < ncv <= n)
  double tolerance = 1e-10; ///< relative accuracy of the Ritz values
  int max_restarts = 1000;
  bool largest_algebraic = false; ///< largest theta rather than largest |theta|
  std::vector<double> start;      ///< the first Krylov vector (n entries), in the range of S
};

struct KrylovResult {
  bool converged = false;      ///< all nev pairs to the tolerance
  std::vector<double> theta;   ///< the nev eigenvalues of T, best first
  std::vector<double> vectors; ///< n per eigenvalue, column after column, x^T B x = 1
  int restarts = 0;
};

/// One Krylov method (a strategy of the eigen solvers).
class KrylovEigenSolver {
 public:
  virtual ~KrylovEigenSolver() = default;
  virtual std::string_view name() const = 0;
  /// The nev eigenpairs of T that req asks for; converged is false when the method stopped
  /// short of them (max_restarts). Throws std::invalid_argument on an impossible request.
  virtual KrylovResult solve(const KrylovRequest& req) = 0;
};

/// Spectra's implicitly restarted Lanczos (one process).
std::unique_ptr<KrylovEigenSolver> make_spectra_krylov();

} // namespace gapfem
