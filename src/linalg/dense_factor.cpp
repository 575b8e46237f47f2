#include "linalg/dense_factor.hpp"

#include <algorithm>

extern "C" {
void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info);
void dpotrs_(const char* uplo, const int* n, const int* nrhs, const double* a, const int* lda,
             double* b, const int* ldb, int* info);
void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv, int* info);
void dgetrs_(const char* trans, const int* n, const int* nrhs, const double* a, const int* lda,
             const int* ipiv, double* b, const int* ldb, int* info);
void dgecon_(const char* norm, const int* n, const double* a, const int* lda, const double* anorm,
             double* rcond, double* work, int* iwork, int* info);
}

namespace gapfem {

bool DenseCholesky::compute(Eigen::MatrixXd A) {
  _L = std::move(A);
  const int n = static_cast<int>(_L.rows());
  if (n == 0) return true;
  int info = 0;
  dpotrf_("L", &n, _L.data(), &n, &info);
  return info == 0;
}

double DenseCholesky::min_pivot() const {
  return _L.rows() > 0 ? _L.diagonal().cwiseAbs2().minCoeff() : 1.0;
}

void DenseCholesky::solve_in_place(Eigen::MatrixXd& B) const {
  const int n = static_cast<int>(_L.rows()), nrhs = static_cast<int>(B.cols());
  if (n == 0 || nrhs == 0) return;
  int info = 0;
  dpotrs_("L", &n, &nrhs, _L.data(), &n, B.data(), &n, &info);
}

Eigen::VectorXd DenseCholesky::solve(const Eigen::VectorXd& b) const {
  Eigen::MatrixXd x = b;
  solve_in_place(x);
  return x.col(0);
}

bool DenseLu::compute(Eigen::MatrixXd A) {
  _LU = std::move(A);
  const int n = static_cast<int>(_LU.rows());
  _norm1 = 0.0;
  for (int j = 0; j < n; ++j) _norm1 = std::max(_norm1, _LU.col(j).cwiseAbs().sum());
  _piv.assign(static_cast<std::size_t>(n), 0);
  if (n == 0) return true;
  int info = 0;
  dgetrf_(&n, &n, _LU.data(), &n, _piv.data(), &info);
  return info == 0;
}

double DenseLu::rcond() const {
  const int n = static_cast<int>(_LU.rows());
  if (n == 0) return 1.0;
  std::vector<double> work(4 * static_cast<std::size_t>(n));
  std::vector<int> iwork(static_cast<std::size_t>(n));
  double rc = 0.0;
  int info = 0;
  dgecon_("1", &n, _LU.data(), &n, &_norm1, &rc, work.data(), iwork.data(), &info);
  return info == 0 ? rc : 0.0;
}

Eigen::VectorXd DenseLu::solve(const Eigen::VectorXd& b) const {
  Eigen::VectorXd x = b;
  const int n = static_cast<int>(_LU.rows()), nrhs = 1;
  if (n == 0) return x;
  int info = 0;
  dgetrs_("N", &n, &nrhs, _LU.data(), &n, _piv.data(), x.data(), &n, &info);
  return x;
}

} // namespace gapfem
