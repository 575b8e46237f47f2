// The recipe "adding a backend" (docs/architecture.md) proven by toys: a backend is its own code
// plus one register_solver_backend() call; the analysis finds it by name and solves through it
// with the same answers. CountingSolver wraps the serial solver and counts the systems;
// DenseToySolver implements only the seam's minimum (name, analyze, factorize and its factor's
// solve) by a dense LU of the whole bordered system: this file is all it needed (1 file, no
// other file touched).
#include "linalg/constrained_solver.hpp"
#include "linalg/kkt_solver.hpp"
#include "test_util.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

using namespace gapfem;
using namespace gapfem::test;

namespace {

/// The toy backend: KktSolver underneath, counting what passes through the seam.
class CountingSolver final : public ConstrainedSolver {
 public:
  explicit CountingSolver(int& systems) : _systems(systems) {}
  std::string_view name() const override { return "toy"; }
  void analyze(std::shared_ptr<const SparsityPattern> pattern) override {
    _inner.analyze(std::move(pattern));
  }
  void forget_factor() override { _inner.forget_factor(); }
  bool matrix_optional() const override { return _inner.matrix_optional(); }
  std::unique_ptr<ConstrainedFactor> factorize(const CsrMatrix& K, const ConstraintBlock& C,
                                               bool symmetric, RunStatistics* stats) override {
    return _inner.factorize(K, C, symmetric, stats);
  }
  KktStatistics solve(CsrMatrix& K, std::span<const double> b, const ConstraintBlock& C,
                      std::span<double> du, std::span<double> dl, bool symmetric,
                      const KktOptions& options, RunStatistics* stats) override {
    ++_systems;
    return _inner.solve(K, b, C, du, dl, symmetric, options, stats);
  }

 private:
  KktSolver _inner;
  int& _systems;
};

/// The minimal backend's factor: [K D; C -E] as a dense matrix, LU with full pivoting.
class DenseToyFactor final : public ConstrainedFactor {
 public:
  DenseToyFactor(const CsrMatrix& K, const ConstraintBlock& C) : _n(K.n()), _m(C.n_rows()) {
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(_n + _m, _n + _m);
    const SparsityPattern& p = K.pattern();
    for (LocalIndex r = 0; r < _n; ++r)
      for (LocalIndex k = p.row_ptr[r]; k < p.row_ptr[r + 1]; ++k) A(r, p.col[k]) = K.values()[k];
    for (int r = 0; r < _m; ++r) {
      for (LocalIndex k = C.row_ptr[r]; k < C.row_ptr[r + 1]; ++k) {
        A(_n + r, C.col[k]) = C.val[k];
        A(C.col[k], _n + r) = C.column_value(k);
      }
      A(_n + r, _n + r) = -C.row_compliance(r);
    }
    _lu.compute(A);
  }
  void solve(std::span<const double> b, std::span<const double> g, std::span<double> x,
             std::span<double> l, int k) override {
    Eigen::VectorXd rhs(_n + _m);
    for (int j = 0; j < k; ++j) {
      for (int i = 0; i < _n; ++i) rhs[i] = b[j * _n + i];
      for (int r = 0; r < _m; ++r) rhs[_n + r] = -g[j * _m + r];
      const Eigen::VectorXd y = _lu.solve(rhs);
      for (int i = 0; i < _n; ++i) x[j * _n + i] = y[i];
      for (int r = 0; r < _m; ++r) l[j * _m + r] = y[_n + r];
    }
  }

 private:
  int _n, _m;
  Eigen::FullPivLU<Eigen::MatrixXd> _lu;
};

/// The minimum a backend implements; Newton's solve() is the seam's default (a fresh factor per
/// system: reuse "never").
class DenseToySolver final : public ConstrainedSolver {
 public:
  explicit DenseToySolver(int& factors) : _factors(factors) {}
  std::string_view name() const override { return "dense-toy"; }
  void analyze(std::shared_ptr<const SparsityPattern>) override {}
  std::unique_ptr<ConstrainedFactor> factorize(const CsrMatrix& K, const ConstraintBlock& C, bool,
                                               RunStatistics*) override {
    ++_factors;
    return std::make_unique<DenseToyFactor>(K, C);
  }

 private:
  int& _factors;
};

const std::string kDeck = std::string("*HEADING\na spring pushed onto a gap\n") +
                          kSpringOnGapModel +
                          R"(*STEP
*STATIC
0.25, 1.
*CLOAD
10, 2, -100.
*END STEP
)";

} // namespace

TEST(SolverRegistry, ANewBackendIsOneRegistration) {
  int systems = 0;
  register_solver_backend(
      {"toy", "a counting wrapper of the serial solver (test)", true, false, "",
       [&systems](const KktTuning&) { return std::make_unique<CountingSolver>(systems); }});
  ASSERT_NE(find_solver_backend("toy"), nullptr);
  JobOptions o;
  o.deck = write_deck(kDeck);
  o.write_files = false;
  o.quiet = true;
  o.solver = "toy";
  const JobResult toy = run_job(o);
  ASSERT_EQ(toy.exit_code, 0) << toy.error;
  EXPECT_GT(systems, 0);
  EXPECT_EQ(systems, toy.run.stats.iterations);
  o.solver = "cholmod";
  const JobResult serial = run_job(o);
  ASSERT_EQ(serial.exit_code, 0) << serial.error;
  // the spring stops at the gap: 0.5 down, the rest of the load on the gap
  const Frame& a = last_frame(toy);
  const Frame& b = last_frame(serial);
  EXPECT_DOUBLE_EQ(U(toy, a, 10)[1], U(serial, b, 10)[1]);
  EXPECT_NEAR(U(toy, a, 10)[1], -0.5, 1e-12);
}

TEST(SolverRegistry, ABackendOfTheMinimumRunsAGapModel) {
  int factors = 0;
  register_solver_backend(
      {"dense-toy", "a dense LU of the bordered system, the seam's minimum only (test)", true,
       false, "",
       [&factors](const KktTuning&) { return std::make_unique<DenseToySolver>(factors); }});
  JobOptions o;
  o.deck = write_deck(kDeck);
  o.write_files = false;
  o.quiet = true;
  o.solver = "dense-toy";
  const JobResult toy = run_job(o);
  ASSERT_EQ(toy.exit_code, 0) << toy.error;
  // no factor is ever reused: one per Newton system
  EXPECT_EQ(factors, toy.run.stats.iterations);
  EXPECT_EQ(toy.run.stats.factorizations, 0) << "the toy counts nothing itself";
  o.solver = "cholmod";
  const JobResult serial = run_job(o);
  ASSERT_EQ(serial.exit_code, 0) << serial.error;
  EXPECT_EQ(toy.run.stats.increments, serial.run.stats.increments);
  const Frame& a = last_frame(toy);
  const Frame& b = last_frame(serial);
  EXPECT_NEAR(U(toy, a, 10)[1], U(serial, b, 10)[1], 1e-12);
  EXPECT_NEAR(U(toy, a, 10)[1], -0.5, 1e-12);
  // the gap carries the rest of the load: 100 - 100 x 0.5
  EXPECT_NEAR(RF(toy, a, 12)[1], RF(serial, b, 12)[1], 1e-9);
  EXPECT_NEAR(RF(toy, a, 12)[1], 50.0, 1e-9);
}

TEST(SolverRegistry, AnUnknownOrUnavailableBackendIsNamed) {
  try {
    make_constrained_solver("pardiso");
    ADD_FAILURE() << "an unknown backend was made";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("there is no solver 'pardiso'; this gapfem has: cholmod"),
              std::string::npos)
        << e.what();
  }
  register_solver_backend({"broken",
                           "a backend this build lacks (test)",
                           false,
                           true,
                           "this build has no broken solver",
                           {}});
  EXPECT_THROW(make_constrained_solver("broken"), std::runtime_error);
}
