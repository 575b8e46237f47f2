#pragma once
/// @file kkt_factor.hpp
/// The serial backend's "factorise once, solve many" (ConstrainedFactor of KktSolver): one
/// factor of M = K + C^T R C (CHOLMOD; UMFPACK when K is unsymmetric or M indefinite, R the
/// augmentation weights of augmentation_weights()) and, when there are rows, the dense m x m
/// matrix S = C M^-1 (D - C^T R E) + E of their multipliers (LAPACK LU). With
/// b1 = b - C^T R g every solve is
///
///     S l = C M^-1 b1 + g,    x = M^-1 (b1 - (D - C^T R E) l)
///
/// (one back-substitution per right-hand side without rows, two with). S costs m solves to make
/// (in blocks of columns) and m^2 doubles: meant for rows in the thousands at most.
#include "linalg/constrained_solver.hpp"
#include "linalg/dense_factor.hpp"
#include "linalg/linear_solver.hpp"

#include <memory>

namespace gapfem {

class KktFactor final : public ConstrainedFactor {
 public:
  /// Analyses K's pattern and factorises; throws SingularSystem (also when the rows are linearly
  /// dependent). The numeric factorisation's time and count go to `stats`.
  KktFactor(const CsrMatrix& K, const ConstraintBlock& C, bool symmetric, double augmentation,
            RunStatistics* stats);
  void solve(std::span<const double> b, std::span<const double> g, std::span<double> x,
             std::span<double> l, int k = 1) override;
  /// True when M was factorised by LU (K unsymmetric, or M indefinite).
  bool unsymmetric() const { return _lu; }

 private:
  void factorize_matrix(bool symmetric, RunStatistics* stats);
  void factorize_rows();
  /// y += alpha (D - C^T R E) w for one column (n entries) and its multipliers (m entries)
  void add_row_columns(std::span<const double> w, double alpha, std::span<double> y) const;

  CsrMatrix _M; ///< K + C^T R C (UMFPACK keeps a pointer to it)
  ConstraintBlock _rows;
  std::vector<double> _R;
  std::unique_ptr<LinearSolver> _solver;
  bool _lu = false;
  DenseLu _S;
};

/// K += C^T R C: each row's spring R_r c c^T added inside its DOF block (which lies in K's
/// pattern).
void add_row_springs(CsrMatrix& K, const ConstraintBlock& C, std::span<const double> R);

} // namespace gapfem
