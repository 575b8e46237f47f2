// The Krylov methods behind the eigen solvers (linalg/krylov_eigen.hpp): Spectra's Lanczos and,
// where this build has PETSc and SLEPc, SLEPc's Krylov-Schur (the PETSc backend's method, here on
// one process) find the eigenpairs of T = S A in the B inner product that a dense generalized
// eigensolver finds (the independent oracle), for random pencils of both forms the eigen solvers
// pose: shift-invert (S = K^-1, A = B = M, M only semi-definite) and buckling (S = K^-1, A = G
// indefinite, B = K), largest in magnitude and largest algebraically.
#include "linalg/constrained_solver.hpp"
#include "linalg/krylov_eigen.hpp"
#include "parallel/parallel.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <gtest/gtest.h>
#include <random>

using namespace gapfem;

namespace {

Eigen::MatrixXd random_spd(int n, std::mt19937& gen, double floor) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd R(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) R(i, j) = u(gen);
  return R * R.transpose() + floor * n * Eigen::MatrixXd::Identity(n, n);
}

struct Pencil {
  Eigen::MatrixXd S, A, B;
  std::vector<double> theta; ///< every eigenvalue of S A (the oracle's)
};

/// S = K^-1, A = B = M with `massless` rows of M zero (their theta are 0).
Pencil shift_invert(int n, unsigned seed, int massless) {
  std::mt19937 gen(seed);
  const Eigen::MatrixXd K = random_spd(n, gen, 0.5);
  Eigen::MatrixXd M = random_spd(n, gen, 0.2);
  for (int i = 0; i < massless; ++i) {
    M.row(n - 1 - i).setZero();
    M.col(n - 1 - i).setZero();
  }
  Pencil p{K.inverse(), M, M, {}};
  // theta = 1 / lambda for K x = lambda M x on the massive part, 0 on the rest: the eigenvalues
  // of K^-1 M, which is similar to the symmetric K^-1/2 M K^-1/2
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> kk(K);
  const Eigen::MatrixXd Kih = kk.operatorInverseSqrt();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> se(Kih * M * Kih);
  p.theta.assign(se.eigenvalues().data(), se.eigenvalues().data() + n);
  return p;
}

/// S = K^-1, A = G (symmetric indefinite), B = K: the buckling form.
Pencil buckling(int n, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Eigen::MatrixXd K = random_spd(n, gen, 0.5);
  Eigen::MatrixXd G(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= i; ++j) G(i, j) = G(j, i) = u(gen);
  Pencil p{K.inverse(), G, K, {}};
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ge(G, K); // G x = theta K x
  p.theta.assign(ge.eigenvalues().data(), ge.eigenvalues().data() + n);
  return p;
}

VectorMap product(const Eigen::MatrixXd& X) {
  return [&X](const double* x, double* y) {
    Eigen::Map<Eigen::VectorXd>(y, X.rows()) = X * Eigen::Map<const Eigen::VectorXd>(x, X.cols());
  };
}

/// `method` on `p` for nev pairs: the oracle's eigenvalues, and T x = theta x, x^T B x = 1.
void expect_pairs(KrylovEigenSolver& method, const Pencil& p, int nev, bool algebraic,
                  const std::string& what) {
  const int n = static_cast<int>(p.A.rows());
  KrylovRequest req;
  req.n = n;
  req.solve = product(p.S);
  req.apply = product(p.A);
  req.inner = product(p.B);
  req.nev = nev;
  req.ncv = std::min(n, 2 * nev + 12);
  req.largest_algebraic = algebraic;
  Eigen::VectorXd w = Eigen::VectorXd::LinSpaced(n, 0.5, 1.5);
  Eigen::VectorXd start = p.S * (p.A * w); // in the range of T
  req.start.assign(start.data(), start.data() + n);
  const KrylovResult r = method.solve(req);
  ASSERT_TRUE(r.converged) << what;
  ASSERT_EQ(r.theta.size(), static_cast<std::size_t>(nev)) << what;
  std::vector<double> want = p.theta;
  std::sort(want.begin(), want.end(),
            [&](double a, double b) { return algebraic ? a > b : std::abs(a) > std::abs(b); });
  want.resize(static_cast<std::size_t>(nev));
  std::vector<double> got = r.theta;
  std::sort(want.begin(), want.end());
  std::sort(got.begin(), got.end());
  const double scale = std::abs(want.front()) + std::abs(want.back());
  for (int k = 0; k < nev; ++k) EXPECT_NEAR(got[k], want[k], 1e-9 * scale) << what << " k " << k;
  const Eigen::MatrixXd T = p.S * p.A;
  for (int k = 0; k < nev; ++k) {
    const Eigen::Map<const Eigen::VectorXd> x(r.vectors.data() + std::size_t(k) * n, n);
    EXPECT_NEAR(x.dot(p.B * x), 1.0, 1e-9) << what;
    EXPECT_LE((T * x - r.theta[k] * x).norm(), 1e-8 * scale * x.norm()) << what << " k " << k;
  }
}

/// Both methods where this build has them.
std::vector<std::unique_ptr<KrylovEigenSolver>> methods() {
  std::vector<std::unique_ptr<KrylovEigenSolver>> out;
  out.push_back(make_spectra_krylov());
  parallel::register_backends();
  const SolverBackend* mumps = find_solver_backend("mumps");
  if (mumps && mumps->unavailable.empty())
    out.push_back(make_constrained_solver("mumps")->krylov_eigen_solver());
  else
    std::cout << "[ SKIPPED  ] no PETSc in this build: SLEPc's method is not checked here\n";
  return out;
}

} // namespace

TEST(KrylovEigen, ShiftInvertPencilsGiveTheDenseEigenvalues) {
  for (const auto& method : methods())
    for (unsigned seed = 1; seed <= 6; ++seed) {
      const Pencil p = shift_invert(70, seed, seed % 3 == 0 ? 9 : 0);
      expect_pairs(*method, p, 6, false,
                   std::string(method->name()) + " seed " + std::to_string(seed));
    }
}

TEST(KrylovEigen, BucklingPencilsGiveTheDenseEigenvaluesByMagnitudeAndBySign) {
  for (const auto& method : methods())
    for (unsigned seed = 11; seed <= 16; ++seed) {
      const Pencil p = buckling(70, seed);
      const std::string what = std::string(method->name()) + " seed " + std::to_string(seed);
      expect_pairs(*method, p, 5, false, what + " |theta|");
      expect_pairs(*method, p, 5, true, what + " theta");
    }
}

TEST(KrylovEigen, TheBackendsChooseTheirMethod) {
  EXPECT_EQ(make_constrained_solver("cholmod")->krylov_eigen_solver()->name(),
            make_spectra_krylov()->name());
  parallel::register_backends();
  const SolverBackend* mumps = find_solver_backend("mumps");
  if (!mumps || !mumps->unavailable.empty()) GTEST_SKIP() << "this build has no PETSc";
  const auto method = make_constrained_solver("mumps")->krylov_eigen_solver();
  if (method->name() == make_spectra_krylov()->name())
    GTEST_SKIP() << "this build has PETSc without SLEPc (slepc-dev): one process only";
  EXPECT_NE(method->name().find("SLEPc"), std::string_view::npos);
}
