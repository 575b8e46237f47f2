#pragma once
/// @file eigen_solver.hpp
/// The generalized symmetric eigenproblem of a constrained system,
///
///     K x = lambda M x,   C x = 0   (exact rows; compliant rows add their stiffness C^T C / E),
///
/// by shift-invert Lanczos over a ConstrainedFactor of K - sigma M: the operator
/// x -> (K - sigma M)^-1_C M x, whose eigenvalues nu = 1 / (lambda - sigma) are largest for the
/// eigenvalues nearest the shift (docs/theory/frequency.md). Small systems are solved densely
/// through the same operator. Used by *FREQUENCY (solver/procedure_frequency.cpp); the backend
/// is whatever ConstrainedSolver the run has, and the Krylov method the one it gives
/// (krylov_eigen.hpp: Spectra on one process, SLEPc on the PETSc backend).
#include "linalg/constrained_solver.hpp"

#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace gapfem {

struct EigenRequest {
  int count = 0; ///< eigenvalues wanted; 0: every one in [lower, upper]
  double lower = -std::numeric_limits<double>::infinity(); ///< eigenvalue range (omega^2)
  double upper = std::numeric_limits<double>::infinity();
  /// The shift sigma (omega^2); none: 0, or a small negative one when K is singular
  std::optional<double> shift;
  double tolerance = 1e-10; ///< Lanczos's relative tolerance of the Ritz values
};

struct EigenPairs {
  std::vector<double> values;  ///< ascending
  std::vector<double> vectors; ///< n per value, column after column; x^T M x = 1
  double shift = 0.0;          ///< the shift used
  /// sum K_ii / sum M_ii over the equations with mass: the size of the eigenvalues (|lambda|
  /// below about 1e-11 of it is a rigid-body mode)
  double scale = 1.0;
  /// Eigenvalues of the model there are at most (free equations with mass less independent
  /// exact rows, or the dense solve's count); -1 when not known
  long finite_modes = -1;
  int factorizations = 0, operations = 0, restarts = 0;
  /// How the pairs were found: the Krylov method's name, or "dense" (small systems)
  std::string method = "dense";
};

/// What the extraction could not do (no mass, no convergence, too many modes asked for).
class EigenProblemError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A fixed vector of n entries in [0.5, 1.5) (xorshift): the start of every Lanczos run, so a run
/// finds the same modes each time.
std::vector<double> fixed_start_vector(std::size_t n);

/// The eigenpairs of (K, M) under C that `req` asks for. K and M share a pattern; C's right sides
/// are ignored (the problem is homogeneous). Throws EigenProblemError, or SingularSystem when no
/// shift makes K - sigma M factorisable.
EigenPairs constrained_eigenpairs(ConstrainedSolver& solver, const CsrMatrix& K, const CsrMatrix& M,
                                  const ConstraintBlock& C, const EigenRequest& req,
                                  RunStatistics* stats = nullptr);

/// The buckling eigenpairs of K0 x = lambda G x under C (linalg/buckling_solver.cpp): G = -K_Delta
/// symmetric and indefinite, K0 positive definite where the rows leave the model free (compliant
/// rows add their stiffness), lambda the multipliers of the perturbation load. Returned: the
/// `count` eigenvalues of smallest magnitude in [lower, upper] (all in it when count is 0), by
/// ascending magnitude, x^T K0 x = 1. Lanczos on G x = (1 / lambda) K0 x in the K0 inner product
/// (over one factorisation of K0, by the backend's Krylov method); small systems densely. Throws
/// EigenProblemError (no load stiffness, K0 not positive definite, no convergence) or
/// SingularSystem (K0 cannot be factorised). `factor`: a factorisation of (K0, C) the caller has
/// already (the perturbation's static solve), used instead of a new one.
EigenPairs constrained_buckling_pairs(ConstrainedSolver& solver, const CsrMatrix& K0,
                                      const CsrMatrix& G, const ConstraintBlock& C,
                                      const EigenRequest& req, RunStatistics* stats = nullptr,
                                      std::unique_ptr<ConstrainedFactor> factor = nullptr);

} // namespace gapfem
