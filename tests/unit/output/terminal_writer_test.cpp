// TerminalWriter: progress and summary go through gapfem::log (captured here with a sink).
#include "common/log.hpp"
#include "output/terminal_writer.hpp"
#include "writer_fixture.hpp"

namespace gapfem {
namespace {

using namespace testing_output;

struct Captured {
  std::vector<std::pair<log::Level, std::string>> lines;
  bool contains(log::Level lvl, std::string_view text) const {
    for (const auto& [l, s] : lines)
      if (l == lvl && s.find(text) != std::string::npos) return true;
    return false;
  }
};

TEST(OutputTerminal, ProgressAndSummaryThroughLog) {
  Captured cap;
  const log::Level old_level = log::level();
  log::set_level(log::Level::Info);
  log::Sink old = log::set_sink(
      [&](log::Level lvl, std::string_view msg) { cap.lines.emplace_back(lvl, std::string(msg)); });
  const Model m = make_model();
  TerminalWriter w;
  RunSummary run = make_run();
  run.stats[TimeCategory::Assembly] = 0.75;
  run.stats[TimeCategory::Factorization] = 0.25;
  w.begin(m);
  w.begin_step(m, 0);
  w.increment(inc_info(1, 1, false, 0.5));
  w.increment(inc_info(1, 2, true, 0.5));
  w.end_step(m, 0, make_summary());
  w.end(m, run);
  log::set_sink(std::move(old));
  log::set_level(old_level);

  EXPECT_TRUE(cap.contains(log::Level::Info, "Step 1 Load: STATIC"));
  // Per increment: step, increment, attempt, step time, dt, iterations; cut-backs flagged.
  EXPECT_TRUE(cap.contains(log::Level::Progress, "step 1 inc    1 att 1  step time 0.5"));
  EXPECT_TRUE(cap.contains(log::Level::Progress, "8 iterations  not converged: cut back"));
  EXPECT_TRUE(cap.contains(log::Level::Progress, "dt 0.5"));
  EXPECT_TRUE(
      cap.contains(log::Level::Info, "Step 1 completed: 2 increments (3 attempts), 7 iterations"));
  EXPECT_TRUE(cap.contains(log::Level::Info, "gaps: 0 open, 0 closed, 1 stick, 0 slip"));
  EXPECT_TRUE(cap.contains(log::Level::Info, "Analysis completed in 1.25 s"));
  EXPECT_TRUE(
      cap.contains(log::Level::Info, "2 increments (3 attempts), 7 iterations, 7 factorizations"));
  // Time split: assembly 0.75 of 1.0 s recorded = 75 %.
  EXPECT_TRUE(cap.contains(log::Level::Info, "75.0 %"));
  EXPECT_TRUE(cap.contains(log::Level::Info, "1 warning(s):"));
  EXPECT_TRUE(cap.contains(log::Level::Info, "*GAP: area not given; S11 is a force"));
}

TEST(OutputTerminal, DeltmxRepeatAndHeatBalance) {
  Captured cap;
  const log::Level old_level = log::level();
  log::set_level(log::Level::Info);
  log::Sink old = log::set_sink(
      [&](log::Level lvl, std::string_view msg) { cap.lines.emplace_back(lvl, std::string(msg)); });
  const Model m = make_model();
  TerminalWriter w;
  IncrementInfo deltmx = inc_info(1, 1, false, 0.5);
  deltmx.deltmx_exceeded = true;
  w.increment(deltmx);
  StepSummary s = make_summary();
  s.checks.thermal = true;
  s.checks.heat_balance_error = 2e-9;
  s.checks.heat_scale = 1000.0;
  s.checks.relative_heat_balance = 2e-12;
  w.end_step(m, 0, s);
  log::set_sink(std::move(old));
  log::set_level(old_level);

  EXPECT_TRUE(cap.contains(log::Level::Progress, "DELTMX exceeded: repeated"));
  EXPECT_FALSE(cap.contains(log::Level::Progress, "not converged"));
  // relative heat balance error 2e-9 / 1000 = 2e-12
  EXPECT_TRUE(
      cap.contains(log::Level::Info, "heat balance error 2.000e-09 (2.00e-12 of heat scale 1000)"));
}

} // namespace
} // namespace gapfem
