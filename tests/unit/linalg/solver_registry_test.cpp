// The recipe "adding a backend" (docs/architecture.md) proven by a toy: a backend is its own code
// plus one register_solver_backend() call; the analysis finds it by name and solves through it
// (here a wrapper of the serial solver that counts the systems), with the same answers.
#include "linalg/constrained_solver.hpp"
#include "linalg/kkt_solver.hpp"
#include "test_util.hpp"

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
