// RowElimination against a dense solve of the whole saddle-point system, on random systems with
// every kind of row: pinned (one coefficient on an equation no other row touches), exact rows of
// several coefficients, single-coefficient rows sharing their equation, compliant rows, and rows
// with their own columns (friction's D != C^T).
#include "linalg/row_elimination.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>
#include <random>
#include <set>

using namespace gapfem;

namespace {

struct Random {
  std::mt19937 gen;
  explicit Random(unsigned seed) : gen(seed) {}
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(gen); }
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(gen); }
};

struct System {
  int n = 0;
  std::shared_ptr<SparsityPattern> pattern;
  Eigen::MatrixXd K;
  ConstraintBlock C;
  Eigen::VectorXd b;
};

/// A banded SPD (or slightly unsymmetric) K of n equations with a full pattern, and rows of every
/// kind. Equations 0..n/3 are pinned candidates.
System random_system(Random& rnd, int n, bool with_columns, bool unsymmetric) {
  System s;
  s.n = n;
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = std::max(0, i - 3); j <= std::min(n - 1, i + 3); ++j) B(i, j) = rnd.uniform(-1, 1);
  s.K = B * B.transpose() + n * Eigen::MatrixXd::Identity(n, n);
  if (unsymmetric)
    for (int i = 0; i + 1 < n; ++i) s.K(i, i + 1) += 0.2 * rnd.uniform(-1, 1);
  std::vector<LocalIndex> all(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) all[i] = i;
  const std::vector<std::span<const LocalIndex>> one{all};
  s.pattern = build_pattern(n, one);
  s.b = Eigen::VectorXd::Random(n);

  int index = 0;
  auto add = [&](std::vector<LocalIndex> eqs, double E) {
    std::vector<double> c, d;
    for (std::size_t k = 0; k < eqs.size(); ++k) {
      c.push_back(rnd.uniform(0.5, 2.0) * (rnd.pick(2) ? 1 : -1));
      d.push_back(with_columns ? c.back() * rnd.uniform(0.8, 1.2) : c.back());
    }
    s.C.add_row(eqs, c, rnd.uniform(-0.1, 0.1), index++,
                with_columns ? std::span<const double>(d) : std::span<const double>{}, E);
  };
  // pinned: distinct equations among the first third
  for (int j = 0; j < n / 3; j += 2) add({j}, 0.0);
  // two single-coefficient rows on one equation would be redundant; one single row plus a row of
  // several coefficients on the same equation keeps it from being pinned
  add({1}, 0.0);
  add({1, n / 2}, 0.0);
  // exact rows of several coefficients, compliant rows of one and of several coefficients
  add({n / 2 + 1, n / 2 + 3, n - 1}, 0.0);
  add({n / 2 + 2}, 1.0 / (n * rnd.uniform(1, 100)));
  add({n / 2 + 4, n - 2}, 1.0 / (n * rnd.uniform(1, 100)));
  add({n / 3 + 1}, 0.0); // pinned too
  return s;
}

Eigen::MatrixXd dense_rows(const ConstraintBlock& C, int n, bool columns) {
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(C.n_rows(), n);
  for (int r = 0; r < C.n_rows(); ++r)
    for (LocalIndex k = C.row_ptr[r]; k < C.row_ptr[r + 1]; ++k)
      M(r, C.col[k]) = columns && C.has_columns() ? C.dval[k] : C.val[k];
  return M;
}

/// The dense solution of [K D; C -E] [du; dl] = [b; -g].
Eigen::VectorXd dense_solve(const Eigen::MatrixXd& K, const ConstraintBlock& C,
                            const Eigen::VectorXd& b) {
  const int n = static_cast<int>(K.rows()), m = C.n_rows();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n + m, n + m);
  A.topLeftCorner(n, n) = K;
  A.topRightCorner(n, m) = dense_rows(C, n, true).transpose();
  A.bottomLeftCorner(m, n) = dense_rows(C, n, false);
  Eigen::VectorXd rhs(n + m);
  rhs.head(n) = b;
  for (int r = 0; r < m; ++r) {
    A(n + r, n + r) = C.compliance.empty() ? 0.0 : -C.compliance[r];
    rhs[n + r] = -C.g[r];
  }
  return A.fullPivLu().solve(rhs);
}

CsrMatrix to_csr(const System& s) {
  CsrMatrix A(s.pattern);
  for (LocalIndex r = 0; r < s.n; ++r)
    for (LocalIndex k = s.pattern->row_ptr[r]; k < s.pattern->row_ptr[r + 1]; ++k)
      A.values()[k] = s.K(r, s.pattern->col[k]);
  return A;
}

} // namespace

TEST(RowElimination, TheReducedSystemHasTheSolutionOfTheWholeOne) {
  Random rnd(11);
  for (int trial = 0; trial < 60; ++trial) {
    const bool columns = trial % 3 == 1, unsym = trial % 3 == 2;
    const int n = 14 + rnd.pick(20);
    const System s = random_system(rnd, n, columns, unsym);
    const Eigen::VectorXd ref = dense_solve(s.K, s.C, s.b);

    CsrMatrix K = to_csr(s);
    const std::vector<double> original(K.values().begin(), K.values().end());
    RowElimination elim;
    elim.reduce(K, {s.b.data(), static_cast<std::size_t>(n)}, s.C);
    // rows 0, 2, 4, ... (< n/3, but not 1), the last single row, and both compliant rows go
    const int pinned = (n / 3 + 1) / 2 + 1;
    EXPECT_EQ(static_cast<int>(elim.pinned_count()), pinned) << "trial " << trial;
    EXPECT_EQ(elim.eliminated_rows(), pinned + 2) << "trial " << trial;
    const ConstraintBlock& Cr = elim.reduced_rows();
    EXPECT_EQ(Cr.n_rows(), 3); // the shared single row, its partner and the exact row of three
    // the rows that are springs in the reduced K (AMG's rebuild test): all but the pinned ones,
    // in their order; each pinned equation is its row's single column
    const ConstraintBlock springs = elim.unpinned_rows(s.C);
    ASSERT_EQ(springs.n_rows(), s.C.n_rows() - pinned) << "trial " << trial;
    std::set<LocalIndex> pinned_eqs(elim.pinned_equations().begin(), elim.pinned_equations().end());
    for (int r = 0, q = 0; r < s.C.n_rows(); ++r) {
      const LocalIndex k0 = s.C.row_ptr[r];
      const bool is_pinned = s.C.row_ptr[r + 1] - k0 == 1 && s.C.row_compliance(r) == 0 &&
                             pinned_eqs.count(s.C.col[k0]) == 1;
      if (is_pinned) continue;
      ASSERT_LT(q, springs.n_rows());
      EXPECT_EQ(springs.multiplier[q], s.C.multiplier[r]) << "trial " << trial << " row " << r;
      EXPECT_EQ(springs.row_compliance(q), s.C.row_compliance(r));
      EXPECT_TRUE(std::equal(s.C.val.begin() + k0, s.C.val.begin() + s.C.row_ptr[r + 1],
                             springs.val.begin() + springs.row_ptr[q]));
      ++q;
    }

    Eigen::MatrixXd Kr(n, n);
    Kr.setZero();
    for (LocalIndex r = 0; r < n; ++r)
      for (LocalIndex k = s.pattern->row_ptr[r]; k < s.pattern->row_ptr[r + 1]; ++k)
        Kr(r, s.pattern->col[k]) = K.values()[k];
    const auto rb = elim.reduced_b();
    const Eigen::VectorXd red =
        dense_solve(Kr, Cr, Eigen::Map<const Eigen::VectorXd>(rb.data(), n));
    std::vector<double> du(red.data(), red.data() + n), dl(static_cast<std::size_t>(s.C.n_rows()));
    std::vector<double> dlr(red.data() + n, red.data() + n + Cr.n_rows());
    du[0] += 1.0; // recover() sets the pinned equations exactly, whatever the solver left there
    elim.recover({s.b.data(), static_cast<std::size_t>(n)}, s.C, du, dlr, dl);
    for (int i = 0; i < n; ++i)
      EXPECT_NEAR(du[i], ref[i], 1e-10) << "trial " << trial << " du " << i;
    for (int r = 0; r < s.C.n_rows(); ++r)
      EXPECT_NEAR(dl[r], ref[n + r], 1e-8 * (1 + std::abs(ref[n + r])))
          << "trial " << trial << " dl " << r;

    elim.restore(K);
    EXPECT_TRUE(std::equal(original.begin(), original.end(), K.values().begin()))
        << "restore() gives K back bit for bit";
  }
}

TEST(RowElimination, WithoutPinningOnlyCompliantRowsAreFolded) {
  Random rnd(5);
  const System s = random_system(rnd, 20, false, false);
  CsrMatrix K = to_csr(s);
  RowElimination elim;
  elim.reduce(K, {s.b.data(), 20}, s.C, false);
  EXPECT_EQ(elim.pinned_count(), 0u);
  EXPECT_EQ(elim.eliminated_rows(), 2);
}
