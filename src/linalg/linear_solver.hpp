#pragma once
/// @file linear_solver.hpp
/// Sparse direct solvers behind one interface: analyse a pattern once (symbolic factorisation,
/// fill-reducing ordering), factorise many times, solve many times. A distributed backend would
/// implement the same interface on its owned rows.
#include "linalg/csr_matrix.hpp"

#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace gapfem {

/// The matrix is singular (or not positive definite where that is required). `equations` lists the
/// equations whose pivots vanished, so the caller can name nodes and DOFs.
class SingularSystem : public std::runtime_error {
 public:
  SingularSystem(std::string what, std::vector<LocalIndex> equations, bool indefinite = false)
      : std::runtime_error(std::move(what)), _equations(std::move(equations)),
        _indefinite(indefinite) {}
  const std::vector<LocalIndex>& equations() const { return _equations; }
  /// A negative pivot (matrix indefinite) rather than a zero one.
  bool indefinite() const { return _indefinite; }

 private:
  std::vector<LocalIndex> _equations;
  bool _indefinite;
};

/// k sparse columns of length n (equation numbers), column-major: column j holds
/// row[ptr[j]..ptr[j+1]) with values val[...].
struct SparseColumns {
  std::vector<LocalIndex> ptr{0};
  std::vector<LocalIndex> row;
  std::vector<double> val;
  int n_cols() const { return static_cast<int>(ptr.size()) - 1; }
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  virtual std::string_view name() const = 0;
  /// True when the solver assumes (and uses only one triangle of) a symmetric matrix.
  virtual bool symmetric() const = 0;
  /// Symbolic analysis of a pattern: once per pattern.
  virtual void analyze(const SparsityPattern& pattern) = 0;
  /// Numeric factorisation; throws SingularSystem.
  virtual void factorize(const CsrMatrix& matrix) = 0;
  /// x = A^{-1} b with the current factor (b and x may not alias).
  virtual void solve(std::span<const double> b, std::span<double> x) = 0;
  /// Solve for several right-hand sides at once (column-major n x k); default loops.
  virtual void solve_many(std::span<const double> b, std::span<double> x, int k);
  /// Rank-k modification of the current factor: A := A + W W^T (add) or A - W W^T. Returns false
  /// when the backend cannot modify factors or declines to (too many changes, no memory for
  /// them; nothing changed); throws SingularSystem when the modified matrix is not positive
  /// definite (the factor is then unusable: factorise afresh). With `scale` (one per column, an
  /// addition only) the backend may add s_j W_j, 0 < s_j <= 1, instead of W_j where that keeps
  /// the modified factor accurate, and says so in scale[j] (a spring much stiffer than the
  /// matrix along it, see CholmodSolver). With `gain` (an addition only) it reports
  /// s_j^2 W_j^T A^-1 W_j, A the matrix before the column was added, where it knows it (0: not
  /// known): how stiff the spring is against the matrix along it.
  virtual bool modify(bool add, const SparseColumns& W, std::span<double> scale = {},
                      std::span<double> gain = {}) {
    (void)add;
    (void)W;
    (void)scale;
    (void)gain;
    return false;
  }
  /// Split solves with a Cholesky factor L L^T = P A P^T (P a permutation), for backends that
  /// have them (CHOLMOD) and whose factor carries no modification: t = L^-1 P b (forward),
  /// x = P^T L^-T t (backward) and, for sparse columns W, Z = L^-1 P W with Z's rows in the
  /// factor's ordering (forward_sparse; false when its scratch does not fit in memory).
  virtual bool has_split_solves() const { return false; }
  virtual void forward(std::span<const double> b, std::span<double> t);
  virtual void backward(std::span<const double> t, std::span<double> x);
  virtual bool forward_sparse(const SparseColumns& W, SparseColumns& Z);
  /// Bytes held by the factor (for reports).
  virtual std::size_t factor_bytes() const { return 0; }
};

/// CHOLMOD supernodal Cholesky with METIS/AMD ordering (symmetric positive definite).
std::unique_ptr<LinearSolver> make_cholmod_solver();
/// UMFPACK LU (any nonsingular matrix).
std::unique_ptr<LinearSolver> make_umfpack_solver();

} // namespace gapfem
