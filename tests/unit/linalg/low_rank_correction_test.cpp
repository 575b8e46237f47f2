// Rank-one changes of a CHOLMOD factor (LinearSolver::modify: the Woodbury correction of
// linalg/low_rank_correction.hpp with sparse forward solves) against dense solves.
#include "common/memory.hpp"
#include "linalg/linear_solver.hpp"
#include "linalg/low_rank_correction.hpp"

#include <Eigen/Dense>
#include <cstdlib>
#include <gtest/gtest.h>
#include <random>

using namespace gapfem;

namespace {

/// A 3-D grid of nx^3 points, 7-point stencil plus a small diagonal shift: CHOLMOD orders it by
/// nested dissection into real supernodes with a non-trivial permutation.
struct Grid {
  int n = 0;
  std::shared_ptr<SparsityPattern> pattern;
  Eigen::MatrixXd A;
  explicit Grid(int nx) {
    n = nx * nx * nx;
    A = Eigen::MatrixXd::Zero(n, n);
    std::vector<std::vector<LocalIndex>> elems;
    auto id = [nx](int i, int j, int k) { return (k * nx + j) * nx + i; };
    for (int k = 0; k < nx; ++k)
      for (int j = 0; j < nx; ++j)
        for (int i = 0; i < nx; ++i) {
          const int p = id(i, j, k);
          A(p, p) += 0.05;
          const int nb[3] = {i + 1 < nx ? id(i + 1, j, k) : -1, j + 1 < nx ? id(i, j + 1, k) : -1,
                             k + 1 < nx ? id(i, j, k + 1) : -1};
          for (int q : nb) {
            if (q < 0) continue;
            A(p, p) += 1.0;
            A(q, q) += 1.0;
            A(p, q) -= 1.0;
            A(q, p) -= 1.0;
            elems.push_back({p, q});
          }
        }
    std::vector<std::span<const LocalIndex>> spans(elems.begin(), elems.end());
    pattern = build_pattern(n, spans);
  }
  CsrMatrix csr(const Eigen::MatrixXd& M) const {
    CsrMatrix C(pattern);
    for (LocalIndex r = 0; r < n; ++r)
      for (LocalIndex k = pattern->row_ptr[r]; k < pattern->row_ptr[r + 1]; ++k)
        C.values()[k] = M(r, pattern->col[k]);
    return C;
  }
};

/// One column with one to `most` entries (anywhere: a factor change needs no pattern).
SparseColumns random_column(std::mt19937& rng, int n, double scale, int most = 3) {
  std::uniform_int_distribution<int> row(0, n - 1), count(1, most);
  std::uniform_real_distribution<double> val(-1.0, 1.0);
  std::vector<LocalIndex> rows;
  for (int c = count(rng); c > 0; --c) rows.push_back(row(rng));
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  SparseColumns W;
  for (LocalIndex r : rows) {
    W.row.push_back(r);
    W.val.push_back(scale * val(rng));
  }
  W.ptr = {0, static_cast<LocalIndex>(rows.size())};
  return W;
}

Eigen::MatrixXd dense(const SparseColumns& W, int n) {
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(n, W.n_cols());
  for (int j = 0; j < W.n_cols(); ++j)
    for (LocalIndex k = W.ptr[j]; k < W.ptr[j + 1]; ++k) D(W.row[k], j) += W.val[k];
  return D;
}

} // namespace

// Random histories of springs added, removed again, and removed from the factored matrix itself
// (the way contact rows change under a kept factor): every solve, single and blocked, matches a
// dense solve of the current matrix.
TEST(CholmodModify, RandomRankOneHistoriesMatchDenseSolves) {
  const Grid g(7); // 343 equations
  std::mt19937 rng(17);
  for (int trial = 0; trial < 6; ++trial) {
    // the factored matrix holds a few springs of its own (to ground: on its diagonal, inside the
    // pattern), which a history may remove
    std::vector<SparseColumns> base, added;
    Eigen::MatrixXd A = g.A;
    for (int i = 0; i < 8; ++i) {
      base.push_back(random_column(rng, g.n, 3.0, 1));
      const Eigen::MatrixXd w = dense(base.back(), g.n);
      A += w * w.transpose();
    }
    auto solver = make_cholmod_solver();
    solver->analyze(*g.pattern);
    solver->factorize(g.csr(A));
    std::uniform_int_distribution<int> what(0, 2);
    for (int step = 0; step < 25; ++step) {
      const int kind = what(rng);
      SparseColumns W;
      bool add = true;
      if (kind == 1 && !added.empty()) { // an added spring goes again
        W = added.back();
        added.pop_back();
        add = false;
      } else if (kind == 2 && !base.empty()) { // one of the factored matrix's springs goes
        W = base.back();
        base.pop_back();
        add = false;
      } else {
        W = random_column(rng, g.n, 2.0);
        added.push_back(W);
      }
      ASSERT_TRUE(solver->modify(add, W));
      const Eigen::MatrixXd w = dense(W, g.n);
      A += (add ? 1.0 : -1.0) * w * w.transpose();
      const Eigen::LDLT<Eigen::MatrixXd> ref(A);
      Eigen::MatrixXd b = Eigen::MatrixXd::Random(g.n, 3);
      std::vector<double> x(3 * g.n);
      solver->solve_many({b.data(), static_cast<std::size_t>(b.size())}, x, 3);
      const Eigen::MatrixXd want = ref.solve(b);
      const Eigen::Map<const Eigen::MatrixXd> got(x.data(), g.n, 3);
      EXPECT_LT((got - want).cwiseAbs().maxCoeff(), 1e-9 * want.cwiseAbs().maxCoeff())
          << "trial " << trial << " step " << step;
      solver->solve({b.data(), std::size_t(g.n)}, {x.data(), std::size_t(g.n)});
      EXPECT_LT((got.col(0) - want.col(0)).cwiseAbs().maxCoeff(),
                1e-9 * want.cwiseAbs().maxCoeff());
    }
    // a new factorisation forgets the changes
    solver->factorize(g.csr(g.A));
    Eigen::VectorXd b = Eigen::VectorXd::Random(g.n);
    std::vector<double> x(g.n);
    solver->solve({b.data(), std::size_t(g.n)}, x);
    const Eigen::VectorXd want = g.A.ldlt().solve(b);
    EXPECT_LT((Eigen::Map<const Eigen::VectorXd>(x.data(), g.n) - want).cwiseAbs().maxCoeff(),
              1e-10 * want.cwiseAbs().maxCoeff());
  }
}

// Removing more than the factored matrix holds leaves it indefinite: refused, as is a removal
// that leaves it singular.
TEST(CholmodModify, RemovingMoreThanTheMatrixHoldsIsRefused) {
  const Grid g(4);
  auto solver = make_cholmod_solver();
  solver->analyze(*g.pattern);
  solver->factorize(g.csr(g.A));
  SparseColumns W; // 5 e_3: 25 against a diagonal of about 3
  W.row = {3};
  W.val = {5.0};
  W.ptr = {0, 1};
  EXPECT_THROW(solver->modify(false, W), SingularSystem);
}

// The correction's scratch (a block of dense columns) must fit in the memory left; where it does
// not, modify() declines and the caller factorises afresh.
TEST(CholmodModify, DeclinesWhereItsScratchDoesNotFit) {
  const Grid g(4);
  auto solver = make_cholmod_solver();
  solver->analyze(*g.pattern);
  solver->factorize(g.csr(g.A));
  SparseColumns W;
  W.row = {3};
  W.val = {1.0};
  W.ptr = {0, 1};
  set_memory_limit(64); // bytes: no room for the correction's scratch
  const bool modified = solver->modify(true, W);
  set_memory_limit(std::nullopt);
  EXPECT_FALSE(modified);
  EXPECT_TRUE(solver->modify(true, W));
}

// The correction alone, on L = I: a term that undoes another cancels it, and a removal larger
// than the identity leaves an indefinite matrix.
TEST(LowRankCorrection, CancelsOppositeTermsAndRefusesIndefiniteResults) {
  LowRankCorrection c(4);
  LowRankCorrection::Column u;
  u.u_row = u.y_row = {1, 2};
  u.u_val = u.y_val = {0.6, 0.3};
  c.add(u);
  c.factorize();
  std::vector<double> y{1.0, 1.0, 1.0, 1.0};
  c.apply(y, 1); // (I + u u^T)^-1 y = y - u (u.y) / (1 + u.u)
  const double f = (0.6 + 0.3) / (1.0 + 0.36 + 0.09);
  EXPECT_NEAR(y[1], 1.0 - 0.6 * f, 1e-15);
  EXPECT_NEAR(y[2], 1.0 - 0.3 * f, 1e-15);
  EXPECT_EQ(y[0], 1.0);
  const std::vector<LocalIndex> rows{1, 2};
  const std::vector<double> vals{0.6, 0.3};
  EXPECT_FALSE(c.cancel(rows, vals, 1.0)); // the same sign does not undo it
  EXPECT_TRUE(c.cancel(rows, vals, -1.0));
  EXPECT_TRUE(c.empty());
  LowRankCorrection::Column v;
  v.u_row = v.y_row = {0};
  v.u_val = v.y_val = {1.5};
  v.sign = -1.0; // I - 2.25 e0 e0^T
  c.add(v);
  EXPECT_THROW(c.factorize(), SingularSystem);
}
