// "Factorise once, solve many" through the solver seam (ConstrainedSolver::factorize): a random
// sparse SPD matrix and a bordered system with exact, compliant and force-column rows against a
// dense Eigen solve, several right-hand sides at once; the factor-size estimate; the seam's
// default Newton solve; the PETSc backend's factor (MUMPS) where this build has it.
#include "linalg/constrained_solver.hpp"
#include "linalg/kkt_factor.hpp"
#include "linalg/kkt_solver.hpp"
#include "parallel/parallel.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>
#include <random>

using namespace gapfem;

namespace {

/// A random sparse symmetric positive definite matrix: overlapping 3x3 element blocks B B^T
/// (each element couples i, i+1, i+5) and a diagonal; `skew` adds an unsymmetric part.
struct RandomSystem {
  int n = 0;
  std::shared_ptr<SparsityPattern> pattern;
  Eigen::MatrixXd K;
  CsrMatrix csr() const {
    CsrMatrix A(pattern);
    for (LocalIndex r = 0; r < n; ++r)
      for (LocalIndex k = pattern->row_ptr[r]; k < pattern->row_ptr[r + 1]; ++k)
        A.values()[k] = K(r, pattern->col[k]);
    return A;
  }
};

RandomSystem random_system(int n, unsigned seed, double skew = 0.0) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  RandomSystem s;
  s.n = n;
  s.K = Eigen::MatrixXd::Zero(n, n);
  std::vector<std::vector<LocalIndex>> elems;
  for (int i = 0; i + 5 < n; ++i) {
    const std::vector<LocalIndex> e{i, i + 1, i + 5};
    Eigen::Matrix3d B;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) B(a, b) = u(gen);
    const Eigen::Matrix3d Ke = B * B.transpose();
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) s.K(e[a], e[b]) += Ke(a, b) + (a < b ? skew : a > b ? -skew : 0);
    elems.push_back(e);
  }
  for (int i = 0; i < n; ++i) s.K(i, i) += 0.5 + std::abs(u(gen));
  std::vector<std::span<const LocalIndex>> spans(elems.begin(), elems.end());
  s.pattern = build_pattern(n, spans);
  return s;
}

/// Rows inside element blocks: an exact tie of three equations, an exact support, a compliant
/// (penalty) row and, when `columns`, a row whose force column differs from its coefficients.
ConstraintBlock rows(bool columns) {
  ConstraintBlock C;
  const std::vector<LocalIndex> e0{0, 1, 5}, e1{10}, e2{20, 21}, e3{30, 31};
  const std::vector<double> c0{1.0, -1.0, 0.5}, c1{1.0}, c2{1.0, -2.0}, c3{1.0, 1.0}, d3{1.0, 0.7};
  C.add_row(e0, c0, 0.2, 0);
  C.add_row(e1, c1, -0.1, 1);
  C.add_row(e2, c2, 0.05, 2, {}, 0.01);
  if (columns) C.add_row(e3, c3, 0.3, 3, d3);
  return C;
}

/// The dense bordered matrix [K D; C -E].
Eigen::MatrixXd bordered(const Eigen::MatrixXd& K, const ConstraintBlock& C) {
  const auto n = K.rows();
  const int m = C.n_rows();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n + m, n + m);
  A.topLeftCorner(n, n) = K;
  for (int r = 0; r < m; ++r) {
    for (LocalIndex k = C.row_ptr[r]; k < C.row_ptr[r + 1]; ++k) {
      A(n + r, C.col[k]) = C.val[k];
      A(C.col[k], n + r) = C.column_value(k);
    }
    A(n + r, n + r) = -C.row_compliance(r);
  }
  return A;
}

/// Solves k right-hand sides with the seam's factor and compares with the dense solve.
void expect_dense_answers(ConstrainedSolver& solver, const RandomSystem& s,
                          const ConstraintBlock& C, bool symmetric, double tol) {
  const int n = s.n, m = C.n_rows(), k = 3;
  solver.analyze(s.pattern);
  const CsrMatrix K = s.csr();
  RunStatistics stats;
  const auto factor = solver.factorize(K, C, symmetric, &stats);
  EXPECT_EQ(stats.factorizations, 1);
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> b(static_cast<std::size_t>(n * k)), g(static_cast<std::size_t>(m * k));
  for (double& v : b) v = u(gen);
  for (double& v : g) v = 0.1 * u(gen);
  std::vector<double> x(b.size()), l(g.size());
  factor->solve(b, g, x, l, k);
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(bordered(s.K, C));
  for (int j = 0; j < k; ++j) {
    Eigen::VectorXd rhs(n + m);
    for (int i = 0; i < n; ++i) rhs[i] = b[j * n + i];
    for (int r = 0; r < m; ++r) rhs[n + r] = -g[j * m + r];
    const Eigen::VectorXd ref = lu.solve(rhs);
    for (int i = 0; i < n; ++i) EXPECT_NEAR(x[j * n + i], ref[i], tol) << "x " << i << " rhs " << j;
    for (int r = 0; r < m; ++r)
      EXPECT_NEAR(l[j * m + r], ref[n + r], tol) << "l " << r << " rhs " << j;
  }
  // one right-hand side at a time gives the same as the block
  std::vector<double> x1(static_cast<std::size_t>(n)), l1(static_cast<std::size_t>(m));
  factor->solve(std::span<const double>(b).subspan(n, n), std::span<const double>(g).subspan(m, m),
                x1, l1, 1);
  for (int i = 0; i < n; ++i) EXPECT_NEAR(x1[i], x[n + i], 1e-13 * (1 + std::abs(x[n + i])));
}

} // namespace

TEST(KktFactor, ARandomSpdMatrixSolvesManyRightHandSides) {
  KktSolver solver;
  expect_dense_answers(solver, random_system(60, 1), ConstraintBlock{}, true, 1e-10);
}

TEST(KktFactor, ABorderedSystemWithExactAndCompliantRows) {
  KktSolver solver;
  expect_dense_answers(solver, random_system(60, 2), rows(false), true, 1e-10);
}

TEST(KktFactor, RowsWithForceColumnsAndAnUnsymmetricMatrix) {
  KktSolver solver;
  expect_dense_answers(solver, random_system(60, 3, 0.05), rows(true), false, 1e-10);
}

TEST(KktFactor, TheFactorIsIndependentOfNewtonsKeptFactor) {
  // a factor made between two Newton solves changes neither
  const RandomSystem s = random_system(40, 4);
  const ConstraintBlock C = rows(false);
  KktSolver a, b;
  a.analyze(s.pattern);
  b.analyze(s.pattern);
  std::vector<double> rhs(40, 1.0), du_a(40), dl_a(3), du_b(40), dl_b(3);
  KktOptions opt;
  opt.reuse = FactorReuse::Always;
  CsrMatrix Ka = s.csr(), Kb = s.csr();
  a.solve(Ka, rhs, C, du_a, dl_a, true, opt);
  b.solve(Kb, rhs, C, du_b, dl_b, true, opt);
  const auto f = a.factorize(s.csr(), C, true);
  Ka = s.csr();
  Kb = s.csr();
  const KktStatistics sa = a.solve(Ka, rhs, C, du_a, dl_a, true, opt);
  b.solve(Kb, rhs, C, du_b, dl_b, true, opt);
  EXPECT_TRUE(sa.reused_factor);
  EXPECT_EQ(du_a, du_b);
  EXPECT_EQ(dl_a, dl_b);
}

TEST(KktFactor, ASingularMatrixIsNamed) {
  RandomSystem s = random_system(20, 5);
  s.K.row(7).setZero();
  s.K.col(7).setZero();
  KktSolver solver;
  solver.analyze(s.pattern);
  try {
    solver.factorize(s.csr(), ConstraintBlock{}, true);
    ADD_FAILURE() << "a singular matrix was factorised";
  } catch (const SingularSystem& e) {
    ASSERT_FALSE(e.equations().empty());
    EXPECT_EQ(e.equations().front(), 7);
  }
}

TEST(KktFactor, TheEstimateIsCholmodsSymbolicPrediction) {
  const RandomSystem s = random_system(200, 6);
  KktSolver solver;
  solver.analyze(s.pattern);
  const std::size_t estimate = solver.factor_bytes_estimate();
  auto cholmod = make_cholmod_solver();
  cholmod->analyze(*s.pattern);
  EXPECT_EQ(estimate, cholmod->factor_bytes());
  EXPECT_GE(estimate, 200 * sizeof(double)); // at least the diagonal
  // the estimate's analysis is the one the Newton solve then uses: same answer as without it
  KktSolver fresh;
  fresh.analyze(s.pattern);
  std::vector<double> b(200, 1.0), x1(200), x2(200);
  CsrMatrix K1 = s.csr(), K2 = s.csr();
  solver.solve(K1, b, ConstraintBlock{}, x1, {}, true, KktOptions{});
  fresh.solve(K2, b, ConstraintBlock{}, x2, {}, true, KktOptions{});
  EXPECT_EQ(x1, x2);
}

namespace {
/// A backend of the minimum (KktFactor underneath): the seam's default solve() serves Newton.
class FactorOnly final : public ConstrainedSolver {
 public:
  std::string_view name() const override { return "factor-only"; }
  void analyze(std::shared_ptr<const SparsityPattern>) override {}
  std::unique_ptr<ConstrainedFactor> factorize(const CsrMatrix& K, const ConstraintBlock& C,
                                               bool symmetric, RunStatistics* stats) override {
    return std::make_unique<KktFactor>(K, C, symmetric, 100.0, stats);
  }
};
} // namespace

TEST(KktFactor, TheSeamsDefaultSolveFactorisesEverySystem) {
  const RandomSystem s = random_system(40, 8);
  const ConstraintBlock C = rows(false);
  FactorOnly solver;
  EXPECT_EQ(solver.factor_bytes_estimate(), 0u);
  EXPECT_FALSE(solver.matrix_optional());
  CsrMatrix K = s.csr();
  std::vector<double> b(40, 1.0), du(40), dl(3);
  RunStatistics stats;
  KktOptions opt;
  opt.reuse = FactorReuse::Always;
  for (int k = 0; k < 2; ++k) {
    const KktStatistics ks = solver.solve(K, b, C, du, dl, true, opt, &stats);
    EXPECT_FALSE(ks.reused_factor);
    EXPECT_LT(ks.constraint_residual, 1e-12);
  }
  EXPECT_EQ(stats.factorizations, 2);
  opt.matrix_current = false;
  EXPECT_TRUE(solver.solve(K, b, C, du, dl, true, opt, &stats).needs_matrix);
  // the same answer as the serial backend's Newton solve
  KktSolver serial;
  serial.analyze(s.pattern);
  std::vector<double> du2(40), dl2(3);
  CsrMatrix K2 = s.csr();
  KktOptions exact;
  exact.constraint_tolerance = 1e-14;
  serial.solve(K2, b, C, du2, dl2, true, exact);
  for (int i = 0; i < 40; ++i) EXPECT_NEAR(du[i], du2[i], 1e-10);
  for (int r = 0; r < 3; ++r) EXPECT_NEAR(dl[r], dl2[r], 1e-8);
}

TEST(KktFactor, ThePetscBackendFactorisesOnceForManySolves) {
  parallel::register_backends();
  const SolverBackend* mumps = find_solver_backend("mumps");
  if (!mumps || !mumps->unavailable.empty()) GTEST_SKIP() << "this build has no PETSc";
  for (const char* name : {"mumps", "iterative"}) {
    SCOPED_TRACE(name);
    const auto solver = make_constrained_solver(name);
    expect_dense_answers(*solver, random_system(60, 9), rows(false), true, 1e-9);
    expect_dense_answers(*solver, random_system(60, 10, 0.05), rows(true), false, 1e-9);
    // its estimate is the serial backend's
    const RandomSystem s = random_system(100, 11);
    solver->analyze(s.pattern);
    KktSolver serial;
    serial.analyze(s.pattern);
    EXPECT_EQ(solver->factor_bytes_estimate(), serial.factor_bytes_estimate());
  }
}
