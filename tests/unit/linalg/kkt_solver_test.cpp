// The constrained (KKT) solve against a dense solve of the saddle-point system.
#include "linalg/kkt_solver.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <random>

using namespace gapfem;

namespace {

struct Problem {
  std::shared_ptr<SparsityPattern> pattern;
  Eigen::MatrixXd K;
};

/// A chain of springs of stiffness 1..n coupling neighbours (tridiagonal), optionally unsymmetric.
Problem chain(int n, bool grounded, double skew = 0.0) {
  Problem p;
  p.K = Eigen::MatrixXd::Zero(n, n);
  std::vector<std::vector<LocalIndex>> elems;
  for (int i = 0; i + 1 < n; ++i) {
    const double k = 1.0 + i;
    p.K(i, i) += k;
    p.K(i + 1, i + 1) += k;
    p.K(i, i + 1) -= k - skew;
    p.K(i + 1, i) -= k + skew;
    elems.push_back({i, i + 1});
  }
  if (grounded) p.K(0, 0) += 10.0;
  elems.push_back({0, n - 1}); // room for a constraint between the ends
  std::vector<std::span<const LocalIndex>> spans(elems.begin(), elems.end());
  p.pattern = build_pattern(n, spans);
  return p;
}

CsrMatrix to_csr(const Problem& p) {
  CsrMatrix A(p.pattern);
  for (LocalIndex r = 0; r < p.pattern->n; ++r)
    for (LocalIndex k = p.pattern->row_ptr[r]; k < p.pattern->row_ptr[r + 1]; ++k)
      A.values()[k] = p.K(r, p.pattern->col[k]);
  return A;
}

void compare_with_dense(bool grounded, bool symmetric) {
  const int n = 8;
  Problem p = chain(n, grounded, symmetric ? 0.0 : 0.3);
  ConstraintBlock C;
  const std::vector<LocalIndex> e0{0, n - 1}, e1{3};
  const std::vector<double> c0{1.0, -1.0}, c1{1.0};
  C.add_row(e0, c0, 0.2, 0); // u0 - u7 = -0.2
  C.add_row(e1, c1, -0.1, 1); // u3 = 0.1
  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  // dense KKT
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n + 2, n + 2);
  A.topLeftCorner(n, n) = p.K;
  A(n, 0) = A(0, n) = 1.0;
  A(n, n - 1) = A(n - 1, n) = -1.0;
  A(n + 1, 3) = A(3, n + 1) = 1.0;
  Eigen::VectorXd rhs(n + 2);
  rhs << b, -0.2, 0.1;
  const Eigen::VectorXd ref = A.fullPivLu().solve(rhs);

  CsrMatrix K = to_csr(p);
  KktSolver solver;
  solver.analyze(p.pattern);
  std::vector<double> du(n), dl(2);
  KktOptions opt;
  opt.constraint_tolerance = 1e-14;
  const auto stats = solver.solve(K, {b.data(), static_cast<std::size_t>(n)}, C, du, dl, symmetric, opt);
  for (int i = 0; i < n; ++i) EXPECT_NEAR(du[i], ref[i], 1e-11);
  EXPECT_NEAR(dl[0], ref[n], 1e-9);
  EXPECT_NEAR(dl[1], ref[n + 1], 1e-9);
  EXPECT_LE(stats.schur_iterations, 10) << "the augmented preconditioner clusters the spectrum";
  EXPECT_EQ(stats.used_unsymmetric, !symmetric);
}

} // namespace

TEST(KktSolver, MatchesDenseSaddlePointSolve) { compare_with_dense(true, true); }
TEST(KktSolver, FloatingChainHeldOnlyByConstraints) {
  // Without the ground spring K is singular (rigid translation); the constraint u3 = 0.1 removes
  // the mode, and the augmented matrix stays positive definite.
  compare_with_dense(false, true);
}
TEST(KktSolver, UnsymmetricTangentUsesLuAndGmres) { compare_with_dense(true, false); }

TEST(KktSolver, SingularMatrixNamesTheEquation) {
  Problem p = chain(5, false);
  CsrMatrix K = to_csr(p);
  KktSolver solver;
  solver.analyze(p.pattern);
  std::vector<double> b(5, 1.0), du(5), dl;
  ConstraintBlock C;
  EXPECT_THROW(solver.solve(K, b, C, du, dl, true, KktOptions{}), SingularSystem);
}
