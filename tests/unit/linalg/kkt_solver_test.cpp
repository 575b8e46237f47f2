// The constrained (KKT) solve against a dense solve of the saddle-point system.
#include "common/memory.hpp"
#include "linalg/kkt_solver.hpp"

#include <Eigen/Dense>
#include <cstdlib>
#include <gtest/gtest.h>
#include <limits>
#include <optional>
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
  C.add_row(e0, c0, 0.2, 0);  // u0 - u7 = -0.2
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
  const auto stats =
      solver.solve(K, {b.data(), static_cast<std::size_t>(n)}, C, du, dl, symmetric, opt);
  for (int i = 0; i < n; ++i) EXPECT_NEAR(du[i], ref[i], 1e-11);
  EXPECT_NEAR(dl[0], ref[n], 1e-9);
  EXPECT_NEAR(dl[1], ref[n + 1], 1e-9);
  EXPECT_LE(stats.schur_iterations, 10) << "the augmented preconditioner clusters the spectrum";
  EXPECT_EQ(stats.used_unsymmetric, !symmetric);
}

} // namespace

TEST(KktSolver, MatchesDenseSaddlePointSolve) {
  compare_with_dense(true, true);
}
TEST(KktSolver, FloatingChainHeldOnlyByConstraints) {
  // Without the ground spring K is singular (rigid translation); the constraint u3 = 0.1 removes
  // the mode, and the augmented matrix stays positive definite.
  compare_with_dense(false, true);
}
TEST(KktSolver, UnsymmetricTangentUsesLuAndGmres) {
  compare_with_dense(true, false);
}

TEST(KktSolver, SingularMatrixNamesTheEquation) {
  Problem p = chain(5, false);
  CsrMatrix K = to_csr(p);
  KktSolver solver;
  solver.analyze(p.pattern);
  std::vector<double> b(5, 1.0), du(5), dl;
  ConstraintBlock C;
  EXPECT_THROW(solver.solve(K, b, C, du, dl, true, KktOptions{}), SingularSystem);
}

namespace {
/// Dense solution of [K C^T; C 0] [du; dl] = [b; -g] for rows given as (eqs, coeffs, g).
struct Row {
  std::vector<LocalIndex> eqs;
  std::vector<double> c;
  double g;
  std::int64_t id;
};
/// Dense solution of [K D; C -E] [du; dl] = [b; -g]: E[r] the rows' compliances (none: 0),
/// columns[r] row r's own column D_r (none, or empty: D_r = C_r^T).
Eigen::VectorXd dense_bordered(const Eigen::MatrixXd& K, const Eigen::VectorXd& b,
                               const std::vector<Row>& rows, const std::vector<double>& E = {},
                               const std::vector<std::vector<double>>& columns = {}) {
  const int n = static_cast<int>(K.rows()), m = static_cast<int>(rows.size());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n + m, n + m);
  A.topLeftCorner(n, n) = K;
  Eigen::VectorXd rhs(n + m);
  rhs.head(n) = b;
  for (int r = 0; r < m; ++r) {
    const bool own = static_cast<std::size_t>(r) < columns.size() && !columns[r].empty();
    for (std::size_t k = 0; k < rows[r].eqs.size(); ++k) {
      A(n + r, rows[r].eqs[k]) = rows[r].c[k];
      A(rows[r].eqs[k], n + r) = own ? columns[r][k] : rows[r].c[k];
    }
    if (static_cast<std::size_t>(r) < E.size()) A(n + r, n + r) = -E[r];
    rhs[n + r] = -rows[r].g;
  }
  return A.fullPivLu().solve(rhs);
}
Eigen::VectorXd dense_kkt(const Eigen::MatrixXd& K, const Eigen::VectorXd& b,
                          const std::vector<Row>& rows) {
  return dense_bordered(K, b, rows);
}
ConstraintBlock block(const std::vector<Row>& rows) {
  ConstraintBlock C;
  for (const Row& r : rows) C.add_row(r.eqs, r.c, r.g, r.id);
  return C;
}
} // namespace

// A factor of K + C_F^T R C_F is reused for a new contact set: rows that closed since are plain
// multiplier rows, rows that opened are cancelled by anti-rows; with an unchanged K the step is
// exactly the one of a fresh factorisation.
TEST(KktSolver, StaleFactorWithChangedRowsGivesTheExactStep) {
  const int n = 8;
  Problem p = chain(n, true);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  const Row a{{0, n - 1}, {1.0, -1.0}, 0.2, 10}, keep{{3}, {1.0}, -0.1, 11},
      fresh{{5}, {1.0}, 0.05, 12};
  KktSolver solver;
  solver.analyze(p.pattern);
  KktOptions opt;
  opt.constraint_tolerance = 1e-14;
  opt.reuse = FactorReuse::Always;
  RunStatistics stats;
  std::vector<double> du(n), dl(2);
  {
    CsrMatrix K = to_csr(p);
    const auto s =
        solver.solve(K, {b.data(), std::size_t(n)}, block({a, keep}), du, dl, true, opt, &stats);
    EXPECT_FALSE(s.reused_factor);
  }
  // gap "a" opened, gap "fresh" closed
  const std::vector<Row> rows{keep, fresh};
  CsrMatrix K = to_csr(p);
  const auto s =
      solver.solve(K, {b.data(), std::size_t(n)}, block(rows), du, dl, true, opt, &stats);
  EXPECT_TRUE(s.stale_factor);
  EXPECT_EQ(s.changed_rows, 2);
  EXPECT_EQ(stats.factorizations, 1);
  const Eigen::VectorXd ref = dense_kkt(p.K, b, rows);
  for (int i = 0; i < n; ++i) EXPECT_NEAR(du[i], ref[i], 1e-10) << i;
  EXPECT_NEAR(dl[0], ref[n], 1e-9);
  EXPECT_NEAR(dl[1], ref[n + 1], 1e-9);
}

// With a drifted K the stale step is a modified-Newton step: the constraint rows hold exactly, the
// displacements differ from the exact step by O(drift). Beyond max_drift the matrix is
// refactorised.
TEST(KktSolver, DriftedTangentKeepsConstraintsExactAndRefactorsBeyondTheLimit) {
  const int n = 8;
  Problem p = chain(n, true);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  const Row keep{{3}, {1.0}, -0.1, 11}, fresh{{0, n - 1}, {1.0, -1.0}, 0.2, 12};
  KktSolver solver;
  solver.analyze(p.pattern);
  KktOptions opt;
  opt.constraint_tolerance = 1e-14;
  opt.reuse = FactorReuse::Always;
  opt.max_drift = 1e-3;
  RunStatistics stats;
  std::vector<double> du(n), dl(2);
  {
    CsrMatrix K = to_csr(p);
    std::vector<double> dl1(1);
    solver.solve(K, {b.data(), std::size_t(n)}, block({keep}), du, dl1, true, opt, &stats);
  }
  Problem q = p;
  q.K *= 1.0 + 1e-5; // within the drift limit (max|dK| / max|diag K| = 1e-5)
  const std::vector<Row> rows{keep, fresh};
  CsrMatrix K = to_csr(q);
  auto s = solver.solve(K, {b.data(), std::size_t(n)}, block(rows), du, dl, true, opt, &stats);
  EXPECT_TRUE(s.stale_factor);
  EXPECT_EQ(stats.factorizations, 1);
  EXPECT_NEAR(du[3], 0.1, 1e-13);              // u3 = 0.1 exactly
  EXPECT_NEAR(du[0] - du[n - 1], -0.2, 1e-13); // u0 - u7 = -0.2 exactly
  const Eigen::VectorXd ref = dense_kkt(q.K, b, rows);
  for (int i = 0; i < n; ++i) EXPECT_NEAR(du[i], ref[i], 1e-4 * ref.head(n).cwiseAbs().maxCoeff());

  Problem big = p;
  big.K *= 1.01; // drift 1e-2 > max_drift: a fresh factor and the exact step
  CsrMatrix K2 = to_csr(big);
  s = solver.solve(K2, {b.data(), std::size_t(n)}, block(rows), du, dl, true, opt, &stats);
  EXPECT_FALSE(s.reused_factor);
  EXPECT_EQ(stats.factorizations, 2);
  const Eigen::VectorXd ref2 = dense_kkt(big.K, b, rows);
  for (int i = 0; i < n; ++i) EXPECT_NEAR(du[i], ref2[i], 1e-10) << i;
}

TEST(KktSolver, IdenticalSystemReusesTheFactorAndNeverPolicyRefactors) {
  const int n = 8;
  Problem p = chain(n, true);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  const Row keep{{3}, {1.0}, -0.1, 11}, other{{5}, {1.0}, 0.05, 12};
  KktSolver solver;
  solver.analyze(p.pattern);
  KktOptions opt;
  opt.reuse = FactorReuse::Never;
  RunStatistics stats;
  std::vector<double> du(n), dl(1);
  for (int k = 0; k < 2; ++k) {
    CsrMatrix K = to_csr(p);
    const auto s =
        solver.solve(K, {b.data(), std::size_t(n)}, block({keep}), du, dl, true, opt, &stats);
    EXPECT_EQ(s.reused_factor, k == 1);
    EXPECT_FALSE(s.stale_factor);
  }
  EXPECT_EQ(stats.factorizations, 1);
  CsrMatrix K = to_csr(p);
  solver.solve(K, {b.data(), std::size_t(n)}, block({other}), du, dl, true, opt, &stats);
  EXPECT_EQ(stats.factorizations, 2) << "a changed contact set is refactorised under Never";
}

// The multiplier iteration stops once the constraint values are within the tolerance; the spring
// force R (C du + g) the factor still carries belongs to the multipliers, so the step is in
// equilibrium, K du + C^T dl = b, to round-off however loose the constraint tolerance is (it
// was left in the residual, ~R x tolerance, so Newton stalled at a residual floor).
TEST(KktSolver, LooseConstraintToleranceKeepsTheStepInEquilibrium) {
  const int n = 8;
  Problem p = chain(n, true);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  const std::vector<Row> rows{{{0, n - 1}, {1.0, -1.0}, 0.2, 10}, {{3}, {1.0}, -0.1, 11}};
  KktSolver solver;
  solver.analyze(p.pattern);
  KktOptions opt;
  opt.constraint_tolerance = 1e-3; // loose: few or no multiplier iterations
  std::vector<double> du(n), dl(2);
  CsrMatrix K = to_csr(p);
  solver.solve(K, {b.data(), std::size_t(n)}, block(rows), du, dl, true, opt);
  Eigen::VectorXd r = b;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) r[i] -= p.K(i, j) * du[j];
  for (int q = 0; q < 2; ++q)
    for (std::size_t k = 0; k < rows[q].eqs.size(); ++k) r[rows[q].eqs[k]] -= rows[q].c[k] * dl[q];
  EXPECT_LE(r.cwiseAbs().maxCoeff(), 1e-10 * b.cwiseAbs().maxCoeff());
  // and the constraints hold within the tolerance
  EXPECT_LE(std::abs(du[0] - du[n - 1] + 0.2), 1e-3);
  EXPECT_LE(std::abs(du[3] - 0.1), 1e-3);
}

// Compliant rows (penalty gaps as rows): [K C^T; C -E] [du; dl] = [b; -g] with E = diag(1/k).
// Randomised sequences of row sets on one factor (rows appearing, disappearing, changing their
// compliance, stiff and soft against the chain) against a dense solve of the same system; the
// fresh factor, the stale factor with changed rows and the unsymmetric path all give the step.
namespace {
Eigen::VectorXd dense_compliant(const Eigen::MatrixXd& K, const Eigen::VectorXd& b,
                                const std::vector<Row>& rows, const std::vector<double>& E) {
  return dense_bordered(K, b, rows, E);
}
} // namespace

TEST(KktSolver, CompliantRowsMatchTheDenseSystemOverRandomContactHistories) {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const int n = 12;
  for (int trial = 0; trial < 40; ++trial) {
    const bool symmetric = trial % 4 != 3;
    Problem p = chain(n, trial % 5 != 0, symmetric ? 0.0 : 0.2);
    // candidate rows: single DOFs (a gap to ground) and the end pair
    std::vector<Row> candidates;
    for (int i = 0; i < n; ++i) candidates.push_back({{i}, {1.0}, 0.0, 100 + i});
    candidates.push_back({{0, n - 1}, {1.0, -1.0}, 0.0, 99});
    KktSolver solver;
    solver.analyze(p.pattern);
    KktOptions opt;
    opt.constraint_tolerance = 1e-15;
    opt.reuse = trial % 2 ? FactorReuse::Always : FactorReuse::Never;
    RunStatistics stats;
    const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
    for (int step = 0; step < 5; ++step) {
      std::vector<Row> rows;
      std::vector<double> E;
      ConstraintBlock C;
      for (const Row& cand : candidates) {
        if (u01(rng) > 0.4) continue;
        Row r = cand;
        r.g = 0.1 * (u01(rng) - 0.5);
        // stiffness from 1e-3 to 1e6 times the chain's (1..n); a fifth of them exact
        const double E_r = u01(rng) < 0.2 ? 0.0 : std::pow(10.0, -6.0 + 9.0 * u01(rng));
        rows.push_back(r);
        E.push_back(E_r);
        C.add_row(r.eqs, r.c, r.g, r.id, {}, E_r);
      }
      const bool held = trial % 5 != 0 || [&] {
        for (std::size_t r = 0; r < rows.size(); ++r)
          if (rows[r].eqs.size() == 1) return true;
        return false;
      }();
      if (!held) continue; // a floating chain needs a row to ground it
      CsrMatrix K = to_csr(p);
      std::vector<double> du(n), dl(rows.size());
      solver.solve(K, {b.data(), std::size_t(n)}, C, du, dl, symmetric, opt, &stats);
      const Eigen::VectorXd ref = dense_compliant(p.K, b, rows, E);
      const double su = ref.head(n).cwiseAbs().maxCoeff();
      for (int i = 0; i < n; ++i)
        EXPECT_NEAR(du[i], ref[i], 1e-9 * su) << "trial " << trial << " step " << step << " " << i;
      for (std::size_t r = 0; r < rows.size(); ++r) {
        const double sl = std::max(1.0, std::abs(ref[n + static_cast<int>(r)]));
        EXPECT_NEAR(dl[r], ref[n + static_cast<int>(r)], 1e-8 * sl)
            << "trial " << trial << " step " << step << " row " << r;
      }
    }
    if (opt.reuse == FactorReuse::Always && symmetric)
      EXPECT_LT(stats.factorizations, 5) << "rows that change reuse the factor";
  }
}

// A compliant row gives the penalty force: eliminating dl = (C du + g) / E gives
// (K + C^T C / E) du = b - C^T g / E, the matrix of a spring of stiffness 1/E.
TEST(KktSolver, ACompliantRowIsTheSpringItStandsFor) {
  const int n = 6;
  Problem p = chain(n, true);
  const double k = 1e4, g = 0.02;
  ConstraintBlock C;
  const std::vector<LocalIndex> eq{4};
  const std::vector<double> c{1.0};
  C.add_row(eq, c, g, 7, {}, 1.0 / k);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
  CsrMatrix K = to_csr(p);
  KktSolver solver;
  solver.analyze(p.pattern);
  std::vector<double> du(n), dl(1);
  KktOptions opt;
  opt.constraint_tolerance = 1e-15;
  solver.solve(K, {b.data(), std::size_t(n)}, C, du, dl, true, opt);
  Eigen::MatrixXd Ks = p.K;
  Ks(4, 4) += k;
  Eigen::VectorXd bs = b;
  bs[4] -= k * g;
  const Eigen::VectorXd ref = Ks.ldlt().solve(bs);
  for (int i = 0; i < n; ++i) EXPECT_NEAR(du[i], ref[i], 1e-12 * ref.cwiseAbs().maxCoeff());
  EXPECT_NEAR(dl[0], k * (du[4] + g), 1e-9 * k * std::abs(du[4] + g) + 1e-12);
}

// LinearSolver::modify (the Woodbury correction of the supernodal factor): A + W W^T, then back to
// A, against dense solves; and the KKT solver uses it so that a reused factor with changed rows
// needs only the multiplier iterations of a fresh one.
TEST(CholmodModify, UpdateAndDowndateMatchDenseSolves) {
  const int n = 10;
  Problem p = chain(n, true);
  std::vector<std::vector<LocalIndex>> elems;
  auto solver = make_cholmod_solver();
  solver->analyze(*p.pattern);
  CsrMatrix A = to_csr(p);
  solver->factorize(A);
  SparseColumns W; // two columns inside the pattern: DOF 3, and DOFs 0 and n-1
  W.row = {3, 0, n - 1};
  W.val = {30.0, 5.0, -5.0};
  W.ptr = {0, 1, 3};
  Eigen::MatrixXd Wd = Eigen::MatrixXd::Zero(n, 2);
  Wd(3, 0) = 30.0;
  Wd(0, 1) = 5.0;
  Wd(n - 1, 1) = -5.0;
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  std::vector<double> x(n);
  ASSERT_TRUE(solver->modify(true, W));
  solver->solve({b.data(), std::size_t(n)}, x);
  Eigen::VectorXd ref = (p.K + Wd * Wd.transpose()).ldlt().solve(b);
  for (int i = 0; i < n; ++i) EXPECT_NEAR(x[i], ref[i], 1e-12 * ref.cwiseAbs().maxCoeff()) << i;
  ASSERT_TRUE(solver->modify(false, W));
  solver->solve({b.data(), std::size_t(n)}, x);
  ref = p.K.ldlt().solve(b);
  for (int i = 0; i < n; ++i) EXPECT_NEAR(x[i], ref[i], 1e-10 * ref.cwiseAbs().maxCoeff()) << i;
  // a factorisation after modifications starts again from the supernodal analysis
  solver->factorize(A);
  solver->solve({b.data(), std::size_t(n)}, x);
  for (int i = 0; i < n; ++i) EXPECT_NEAR(x[i], ref[i], 1e-12 * ref.cwiseAbs().maxCoeff()) << i;
}

TEST(CholmodModify, DowndatingTheOnlySupportIsRefused) {
  // a floating chain held by one row: removing its spring leaves a singular matrix
  const int n = 5;
  Problem p = chain(n, false);
  p.K(2, 2) += 100.0;
  auto solver = make_cholmod_solver();
  solver->analyze(*p.pattern);
  CsrMatrix A = to_csr(p);
  solver->factorize(A);
  SparseColumns W;
  W.row = {2};
  W.val = {10.0};
  W.ptr = {0, 1};
  EXPECT_THROW(solver->modify(false, W), SingularSystem);
}

namespace {
/// One factor, two systems: rows {a, keep} then {keep, fresh} (gap "a" opened, "fresh" closed),
/// reuse forced; the second step, its statistics and the dense solution of the second system.
struct ChangedRows {
  static constexpr int n = 8;
  Problem p = chain(n, true);
  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  RunStatistics stats;
  KktStatistics second;
  std::vector<double> du = std::vector<double>(n), dl = std::vector<double>(2);
  Eigen::VectorXd ref;
  std::optional<std::uint64_t> memory_limit_between; ///< set_memory_limit for the second solve
  KktTuning tuning;
  void run() {
    const Row a{{0, n - 1}, {1.0, -1.0}, 0.2, 10}, keep{{3}, {1.0}, -0.1, 11},
        fresh{{5}, {1.0}, 0.05, 12};
    KktSolver solver(tuning);
    solver.analyze(p.pattern);
    KktOptions opt;
    opt.constraint_tolerance = 1e-14;
    opt.reuse = FactorReuse::Always;
    CsrMatrix K1 = to_csr(p);
    solver.solve(K1, {b.data(), std::size_t(n)}, block({a, keep}), du, dl, true, opt, &stats);
    const std::vector<Row> rows{keep, fresh};
    CsrMatrix K2 = to_csr(p);
    if (memory_limit_between) set_memory_limit(memory_limit_between);
    second = solver.solve(K2, {b.data(), std::size_t(n)}, block(rows), du, dl, true, opt, &stats);
    set_memory_limit(std::nullopt);
    ref = dense_kkt(p.K, b, rows);
  }
  void expect_exact_step() const {
    for (int i = 0; i < n; ++i) EXPECT_NEAR(du[i], ref[i], 1e-10) << i;
    EXPECT_NEAR(dl[0], ref[n], 1e-9);
    EXPECT_NEAR(dl[1], ref[n + 1], 1e-9);
  }
};
} // namespace

// The Woodbury path (no dense multipliers, GAPFEM_DENSE_MULTIPLIERS=0): the kept factor is made
// exact for the current rows, and the multipliers are solved by CG on it.
TEST(KktSolver, AReusedFactorIsUpdatedForChangedRows) {
  ChangedRows c;
  c.tuning.dense_multipliers = false;
  c.run();
  EXPECT_TRUE(c.second.stale_factor);
  EXPECT_EQ(c.stats.factorizations, 1);
  EXPECT_EQ(c.stats.factor_updates, 2); // "fresh" added, "a" removed
  EXPECT_LE(c.second.schur_iterations, 3) << "CG on an exact factor, no anti-rows";
  c.expect_exact_step();
}

// Keeping a factor exact for changed rows needs scratch memory next to it (linalg/
// low_rank_correction.hpp): where that does not fit (set_memory_limit stands in for a machine
// that has filled up since the factorisation) the solver factorises afresh instead, with the same
// exact step.
TEST(KktSolver, NoFactorUpdateWhereItsScratchDoesNotFit) {
  ChangedRows c;
  c.tuning.dense_multipliers = false;
  c.memory_limit_between = 64; // bytes: less than one dense column of the 8 equations, twice
  c.run();
  EXPECT_EQ(c.stats.factor_updates, 0);
  EXPECT_EQ(c.stats.factorizations, 2);
  c.expect_exact_step();
}

// The default path: the factor stays as it is; the multiplier matrix of the kept row, the new row
// and the anti-row of the row gone is dense (one column L^-1 P c^T per row), and the step is one
// forward and one backward solve.
TEST(KktSolver, DenseMultipliersServeChangedRowsInOneSolve) {
  ChangedRows c;
  c.run();
  EXPECT_TRUE(c.second.stale_factor);
  EXPECT_EQ(c.stats.factorizations, 1);
  EXPECT_EQ(c.second.schur_iterations, 0);
  EXPECT_EQ(c.second.solves, 1);
  EXPECT_EQ(c.stats.factor_updates, 3); // the columns of "keep", "a" (its anti-row) and "fresh"
  c.expect_exact_step();
}

// Redundant rows (two gaps enforcing the same motion) make the dense multiplier matrix singular:
// the Krylov iteration serves the kept factor instead (CG converges on the consistent system), with
// the same step; the multipliers share the force.
TEST(KktSolver, RedundantRowsGoToTheKrylovPath) {
  const int n = 8;
  Problem p = chain(n, true);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  const Row keep{{3}, {1.0}, -0.1, 11}, twice{{3}, {2.0}, -0.2, 12};
  KktSolver solver;
  solver.analyze(p.pattern);
  KktOptions opt;
  opt.constraint_tolerance = 1e-14;
  opt.reuse = FactorReuse::Always;
  std::vector<double> du(n), dl(2);
  CsrMatrix K1 = to_csr(p);
  RunStatistics stats;
  solver.solve(K1, {b.data(), std::size_t(n)}, block({keep}), du, dl, true, opt, &stats);
  CsrMatrix K2 = to_csr(p);
  const KktStatistics st =
      solver.solve(K2, {b.data(), std::size_t(n)}, block({keep, twice}), du, dl, true, opt, &stats);
  EXPECT_TRUE(st.stale_factor);
  EXPECT_EQ(stats.factorizations, 1);
  EXPECT_GT(st.schur_iterations, 0) << "the Krylov path";
  const Eigen::VectorXd ref = dense_kkt(p.K, b, {keep});
  for (int i = 0; i < n; ++i) EXPECT_NEAR(du[i], ref[i], 1e-10) << i;
  EXPECT_NEAR(dl[0] + 2.0 * dl[1], ref[n], 1e-9);
}

// Without the current matrix (Newton evaluated the residual alone) the solver uses its kept
// factor or asks for the matrix: it never reads the matrix's values.
TEST(KktSolver, WithoutTheMatrixOnlyTheKeptFactorIsUsed) {
  const int n = 8;
  Problem p = chain(n, true);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  const Row keep{{3}, {1.0}, -0.1, 11}, fresh{{5}, {1.0}, 0.05, 12};
  KktSolver solver;
  solver.analyze(p.pattern);
  KktOptions opt;
  opt.constraint_tolerance = 1e-14;
  opt.reuse = FactorReuse::Always;
  std::vector<double> du(n), dl(2);
  CsrMatrix K = to_csr(p);
  opt.matrix_current = false;
  EXPECT_FALSE(solver.matrix_optional()) << "no factor yet";
  const KktStatistics none =
      solver.solve(K, {b.data(), std::size_t(n)}, block({keep}), du, dl, true, opt);
  EXPECT_TRUE(none.needs_matrix);
  opt.matrix_current = true;
  EXPECT_FALSE(
      solver.solve(K, {b.data(), std::size_t(n)}, block({keep}), du, dl, true, opt).needs_matrix);
  // a matrix whose values would give any other answer: NaN
  CsrMatrix junk = to_csr(p);
  for (double& v : junk.values()) v = std::numeric_limits<double>::quiet_NaN();
  opt.matrix_current = false;
  const KktStatistics st =
      solver.solve(junk, {b.data(), std::size_t(n)}, block({keep, fresh}), du, dl, true, opt);
  EXPECT_FALSE(st.needs_matrix);
  EXPECT_TRUE(st.stale_factor);
  const Eigen::VectorXd ref = dense_kkt(p.K, b, {keep, fresh});
  for (int i = 0; i < n; ++i) EXPECT_NEAR(du[i], ref[i], 1e-10) << i;
  EXPECT_NEAR(dl[0], ref[n], 1e-9);
  EXPECT_NEAR(dl[1], ref[n + 1], 1e-9);
  // refusing: a fresh factor was asked for
  opt.force_fresh = true;
  EXPECT_TRUE(solver.solve(junk, {b.data(), std::size_t(n)}, block({keep}), du, dl, true, opt)
                  .needs_matrix);
}

// Friction as rows (issue 16): a slipping gap's compliant row turns with its slip direction (the
// same two equations, other coefficients, another compliance each iteration), and a normal row's
// force column follows the friction it carries (D = c^T + q dtau/dN, unsymmetric). On a kept
// factor the dense path gives the step (LU of Z_C^T Z_D - diag(d)), and the turning rows and the
// columns are combinations of the equations' columns: no forward solve after the first system.
// Against a dense solve of [K D; C -E] over random histories.
namespace {
struct GapRows {
  Row row;
  std::vector<double> column; ///< empty: D = C^T
  double E = 0.0;
};
Eigen::VectorXd dense_columns(const Eigen::MatrixXd& K, const Eigen::VectorXd& b,
                              const std::vector<GapRows>& rows) {
  std::vector<Row> r;
  std::vector<double> E;
  std::vector<std::vector<double>> columns;
  for (const GapRows& g : rows) {
    r.push_back(g.row);
    E.push_back(g.E);
    columns.push_back(g.column);
  }
  return dense_bordered(K, b, r, E, columns);
}
} // namespace

TEST(KktSolver, TurningRowsAndOwnColumnsMatchTheDenseSystem) {
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const int n = 12;
  for (int trial = 0; trial < 20; ++trial) {
    Problem p = chain(n, true);
    KktSolver solver;
    solver.analyze(p.pattern);
    KktOptions opt;
    opt.constraint_tolerance = 1e-15;
    opt.reuse = FactorReuse::Always;
    RunStatistics stats;
    const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
    long columns_after_first = -1;
    for (int step = 0; step < 6; ++step) {
      std::vector<GapRows> rows;
      ConstraintBlock C;
      // gaps on equation pairs (i, i + 1): a normal row along i, exact, its column turned by
      // the friction it carries; a compliant friction row across a random slip direction
      for (int i = 0; i + 1 < n; i += 2) {
        const std::vector<LocalIndex> eqs{i, i + 1};
        if (u01(rng) < 0.7) {
          GapRows g{{eqs, {1.0, 0.0}, 0.05 * (u01(rng) - 0.5), 100 + i}, {}, 0.0};
          if (u01(rng) < 0.6) {
            const double phi = 6.283 * u01(rng), mu = 0.5 * u01(rng);
            g.column = {1.0 + mu * std::cos(phi), mu * std::sin(phi)};
          }
          rows.push_back(g);
        }
        if (u01(rng) < 0.6) {
          const double theta = 6.283 * u01(rng);
          rows.push_back({{eqs, {std::cos(theta), std::sin(theta)}, 0.0, 200 + i},
                          {},
                          std::pow(10.0, -3.0 + 4.0 * u01(rng))});
        }
      }
      for (const GapRows& g : rows) C.add_row(g.row.eqs, g.row.c, g.row.g, g.row.id, g.column, g.E);
      CsrMatrix K = to_csr(p);
      std::vector<double> du(n), dl(rows.size());
      const KktStatistics st =
          solver.solve(K, {b.data(), std::size_t(n)}, C, du, dl, true, opt, &stats);
      if (step > 0) {
        EXPECT_TRUE(st.stale_factor);
        EXPECT_EQ(st.schur_iterations, 0) << "the dense path, trial " << trial << " step " << step;
      }
      const Eigen::VectorXd ref = dense_columns(p.K, b, rows);
      const double su = ref.head(n).cwiseAbs().maxCoeff();
      for (int i = 0; i < n; ++i)
        EXPECT_NEAR(du[i], ref[i], 1e-9 * su) << "trial " << trial << " step " << step << " " << i;
      for (std::size_t r = 0; r < rows.size(); ++r) {
        const double sl = std::max(1.0, std::abs(ref[n + static_cast<int>(r)]));
        EXPECT_NEAR(dl[r], ref[n + static_cast<int>(r)], 1e-8 * sl)
            << "trial " << trial << " step " << step << " row " << r;
      }
      if (step == 1) columns_after_first = stats.factor_updates;
    }
    EXPECT_EQ(stats.factorizations, 1);
    // from the second system on, rows are combinations of the equations' columns; new columns
    // only for equations no row touched before
    EXPECT_LE(stats.factor_updates - columns_after_first, n) << "trial " << trial;
  }
}
