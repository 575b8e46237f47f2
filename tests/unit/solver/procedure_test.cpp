// Procedures as objects (solver/procedure.hpp): the recipe "Adding a procedure" of
// docs/architecture.md proven by toy procedures that live in this file alone (one file, no
// other file touched). A toy registered for *STATIC steps replaces StaticProcedure for the test:
// the analysis calls its stages in order, its accuracy check drives automatic incrementation (a
// growth bound of 1 keeps the initial increment; a redo repeats the first increment at half its
// size), its restart state is saved and restored, and a procedure without increments runs once.
#include "solver/analysis_impl.hpp"
#include "solver/procedure.hpp"
#include "solver/procedures.hpp"
#include "test_util.hpp"

#include <gtest/gtest.h>
#include <string>
#include <vector>

using namespace gapfem;
using namespace gapfem::test;

namespace {

/// What the toys saw, in order.
std::vector<std::string> g_calls;

/// Fixed increments: every increment's growth is bounded by 1; optionally the first converged
/// increment is judged inaccurate and repeated at half its size.
class ToyFixedIncrements final : public StepProcedure {
 public:
  ToyFixedIncrements(Analysis::Impl& a, bool redo_first) : StepProcedure(a), _redo(redo_first) {}
  void configure(const Step&, StepContext&) const override { g_calls.push_back("configure"); }
  void set_up(StepRun&, bool resuming) override {
    g_calls.push_back(resuming ? "set_up(resuming)" : "set_up");
  }
  IncrementAccuracy check_accuracy(StepRun& r, const IncrementInfo&, double dt) override {
    g_calls.push_back("check");
    IncrementAccuracy acc;
    acc.growth = 1.0;
    if (_redo) {
      _redo = false;
      acc.redo = r.ctrl->retry_smaller(0.5);
    }
    return acc;
  }
  void accepted(StepRun&, double dt) override {
    g_calls.push_back("accepted " + std::to_string(dt));
    ++_accepted;
  }
  void finish(StepRun& r) override {
    g_calls.push_back("finish");
    r.sum.checks.allie = 1000.0 + _accepted; // the toy's mark on the step's summary
  }

 private:
  bool _redo;
  int _accepted = 0;
};

/// No increments: run() does the step's work.
class ToyOneShot final : public StepProcedure {
 public:
  using StepProcedure::StepProcedure;
  bool incremental() const override { return false; }
  void run(StepRun& r) override {
    g_calls.push_back("run");
    r.sum.checks.allie = 42.0;
  }
};

/// Registers a toy for *STATIC steps for the scope of a test, StaticProcedure again after.
struct ToyForStatic {
  explicit ToyForStatic(ProcedureFactory make) {
    g_calls.clear();
    register_procedure(Procedure::Static, std::move(make));
  }
  ~ToyForStatic() { register_procedure(Procedure::Static, make_static_procedure); }
};

/// The spring on a gap, loaded to 100 in -y over a step of period 1 in increments of 0.25.
std::string deck() {
  return std::string("*HEADING\ntoy procedures\n") + kSpringOnGapModel +
         "*STEP\n*STATIC\n0.25, 1.\n*CLOAD\n10, 2, -100.\n*END STEP\n";
}

} // namespace

TEST(Procedure, ToyProcedureRunsEveryStageInOrder) {
  ToyForStatic toy(
      [](Analysis::Impl& a) { return std::make_unique<ToyFixedIncrements>(a, false); });
  const JobResult r = run_deck(deck());
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const std::vector<std::string> expected = {"configure", "set_up",
                                             "check",     "accepted 0.250000",
                                             "check",     "accepted 0.250000",
                                             "check",     "accepted 0.250000",
                                             "check",     "accepted 0.250000",
                                             "finish"};
  EXPECT_EQ(g_calls, expected) << "a growth bound of 1 keeps the initial increment of 0.25";
  ASSERT_EQ(r.steps.size(), 1u);
  EXPECT_EQ(r.steps[0].increments, 4);
  EXPECT_DOUBLE_EQ(r.steps[0].checks.allie, 1004.0) << "finish() sees the step's summary";
  // the physics is untouched: spring 100 closes the gap at -0.5, the gap takes the rest
  EXPECT_NEAR(U(r, last_frame(r), 10)[1], -0.5, 1e-9);
}

TEST(Procedure, AccuracyCheckRepeatsAnIncrementSmaller) {
  ToyForStatic toy([](Analysis::Impl& a) { return std::make_unique<ToyFixedIncrements>(a, true); });
  const JobResult r = run_deck(deck());
  ASSERT_EQ(r.exit_code, 0) << r.error;
  ASSERT_GE(g_calls.size(), 4u);
  EXPECT_EQ(g_calls[2], "check");
  EXPECT_EQ(g_calls[3], "check") << "the first increment was repeated, not accepted";
  EXPECT_EQ(g_calls[4], "accepted 0.125000") << "at half its size";
  // 0.125 then increments of 0.125 (growth bound 1) to the step end: 8 increments
  EXPECT_EQ(r.steps[0].increments, 8);
  EXPECT_NEAR(U(r, last_frame(r), 10)[1], -0.5, 1e-9);
}

TEST(Procedure, ProcedureWithoutIncrementsRunsOnce) {
  ToyForStatic toy([](Analysis::Impl& a) { return std::make_unique<ToyOneShot>(a); });
  const JobResult r = run_deck(deck());
  ASSERT_EQ(r.exit_code, 0) << r.error;
  EXPECT_EQ(g_calls, std::vector<std::string>{"run"});
  ASSERT_EQ(r.steps.size(), 1u);
  EXPECT_TRUE(r.steps[0].converged);
  EXPECT_EQ(r.steps[0].increments, 0);
  EXPECT_DOUBLE_EQ(r.steps[0].checks.allie, 42.0);
}

TEST(Procedure, EveryProcedureOfTheModelHasAClass) {
  // each value of the enum a deck can name is registered (a new procedure that forgets its
  // registration fails here, not in a user's run)
  for (Procedure p : {Procedure::Static, Procedure::HeatTransfer, Procedure::CoupledTempDisp,
                      Procedure::SubstructureGenerate, Procedure::Dynamic, Procedure::Frequency,
                      Procedure::ResponseSpectrum, Procedure::Buckle,
                      Procedure::SteadyStateDynamics, Procedure::ModalDynamic}) {
    Model m;
    std::vector<ResultWriter*> none;
    Analysis::Impl impl(m, none, AnalysisOptions{});
    Step step;
    step.procedure = p;
    EXPECT_NE(make_procedure(step, impl), nullptr) << procedure_name(p);
    step.perturbation = true; // a static perturbation step has its own class
    EXPECT_NE(make_procedure(step, impl), nullptr) << procedure_name(p);
  }
}
