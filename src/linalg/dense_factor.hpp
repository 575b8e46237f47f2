#pragma once
/// @file dense_factor.hpp
/// Dense Cholesky and LU factorisations by LAPACK (OpenBLAS on Debian: blocked, threaded, with
/// the machine's vector instructions chosen at run time), for the dense multiplier matrices of
/// linalg/kkt_dense.cpp. Column-major Eigen matrices in, solves in place.
#include <Eigen/Dense>
#include <vector>

namespace gapfem {

/// A = L L^T (lower triangle of A read).
class DenseCholesky {
 public:
  /// False when A is not (numerically) positive definite.
  bool compute(Eigen::MatrixXd A);
  /// The smallest squared pivot min L_ii^2 (of a matrix scaled to a unit diagonal: how far from
  /// singular).
  double min_pivot() const;
  /// B := A^-1 B.
  void solve_in_place(Eigen::MatrixXd& B) const;
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

 private:
  Eigen::MatrixXd _L;
};

/// P A = L U with partial pivoting.
class DenseLu {
 public:
  /// False when a pivot is exactly zero.
  bool compute(Eigen::MatrixXd A);
  /// LAPACK's estimate of the reciprocal condition number in the 1-norm.
  double rcond() const;
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

 private:
  Eigen::MatrixXd _LU;
  std::vector<int> _piv;
  double _norm1 = 0.0;
};

} // namespace gapfem
