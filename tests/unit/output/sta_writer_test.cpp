// StaWriter: Abaqus status-file layout, "U" on attempts that were cut back,
// final line, and flushing after every line.
#include "common/log.hpp"
#include "output/sta_writer.hpp"
#include "test_util.hpp"
#include "writer_fixture.hpp"

#include <fmt/format.h>
#include <fstream>
#include <sstream>

namespace gapfem {
namespace {

using namespace testing_output;

TEST(OutputSta, LinesPerAttemptAndCompletion) {
  const Model m = make_model();
  const auto dir = fresh_dir();
  StaWriter w(dir / "wt.sta");
  run_standard(w, m);
  const auto lines = read_lines(dir / "wt.sta");
  ASSERT_GE(lines.size(), 8u);
  EXPECT_EQ(lines[0].rfind("gapfem ", 0), 0u);
  EXPECT_NE(lines[0].find("DATE "), std::string::npos);
  EXPECT_EQ(lines[1], " SUMMARY OF JOB INFORMATION:");
  EXPECT_EQ(lines[2].rfind(" STEP  INC ATT SEVERE EQUIL TOTAL  TOTAL      STEP       INC OF", 0),
            0u);
  // Columns: STEP(4) INC(6) ATT(4) flag(1) SEVERE(5) EQUIL(6) TOTAL(6), two
  // blanks, then total time, step time (11 wide, left-aligned) and increment.
  // The first attempt of increment 1 was cut back: 8 iterations of which 1
  // severe discontinuity iteration -> EQUIL 7. Like Abaqus, its times are those reached before
  // it (0), with the increment it tried in the last column.
  EXPECT_EQ(lines[5], "   1     1   1U    1     7     8  0          0          0.5");
  EXPECT_EQ(lines[6], "   1     1   2     1     2     3  0.5        0.5        0.5");
  EXPECT_EQ(lines[7], "   1     2   1     1     2     3  1          1          0.5");
  EXPECT_EQ(lines.back(), " THE ANALYSIS HAS COMPLETED SUCCESSFULLY");
}

TEST(OutputSta, MonitorColumnShowsTheDofAfterEachConvergedIncrement) {
  // *MONITOR, NODE=TIP, DOF=2 on a spring pulled in four increments: the DOF MONITOR column of
  // each converged increment is u2 = F t / k, t the step time (k = 10, F = 4)
  const std::string deck =
      "*NODE, NSET=TIP\n1, 0, 0, 0\n*ELEMENT, TYPE=SPRING1, ELSET=S\n1, 1\n*SPRING, ELSET=S\n2\n"
      "10.\n*BOUNDARY\n1, 1, 1\n1, 3, 3\n*MONITOR, NODE=TIP, DOF=2\n*STEP\n*STATIC, DIRECT\n"
      "0.25, 1.\n*CLOAD\n1, 2, 4.\n*END STEP\n";
  const JobResult r = test::run_deck(deck, true);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  const auto lines = read_lines(test::test_dir() / "job.sta");
  ASSERT_GE(lines.size(), 9u);
  EXPECT_NE(lines[2].find("INC OF     DOF"), std::string::npos) << lines[2];
  EXPECT_NE(lines[3].find("TIME       MONITOR"), std::string::npos) << lines[3];
  for (int i = 1; i <= 4; ++i) {
    const std::string& row = lines[4 + static_cast<std::size_t>(i)];
    EXPECT_EQ(row.substr(row.size() - 10), fmt::format("{:.4E}", 0.1 * i)) << row;
  }
}

TEST(OutputMsg, TheMessageFileHoldsEveryIterationWhateverTheTerminalShows) {
  // a quiet run (the terminal shows errors only): job.msg still has the iterations and increments
  const std::string deck =
      "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n*ELEMENT, TYPE=GAPUNI, ELSET=G\n1, 1, 2\n"
      "*GAP, ELSET=G\n0.1, 1., 0., 0., 1.\n*ELEMENT, TYPE=SPRING1, ELSET=S\n2, 2\n"
      "*SPRING, ELSET=S\n1\n10.\n*BOUNDARY\n1, 1, 3\n2, 2, 3\n*STEP\n*STATIC\n*CLOAD\n"
      "2, 1, -5.\n*END STEP\n";
  const JobResult r = test::run_deck(deck, true);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  std::ifstream in(test::test_dir() / "job.msg");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string msg = ss.str();
  EXPECT_NE(msg.find("STEP 1 Step-1 (STATIC)"), std::string::npos) << msg;
  EXPECT_NE(msg.find("  iteration 1: residual/flux"), std::string::npos) << msg;
  EXPECT_NE(msg.find("increment 1 attempt 1: converged in"), std::string::npos) << msg;
  EXPECT_NE(msg.find("THE ANALYSIS HAS COMPLETED SUCCESSFULLY"), std::string::npos) << msg;
  EXPECT_EQ(log::level(), log::Level::Info); // the terminal's level is restored after the run
}

TEST(OutputSta, EveryLineIsFlushedAtOnce) {
  const Model m = make_model();
  const auto dir = fresh_dir();
  StaWriter w(dir / "wt.sta");
  w.begin(m);
  w.begin_step(m, 0);
  w.increment(inc_info(1, 1, true, 0.25));
  // Read while the writer is still open (as `tail -f` would).
  const auto lines = read_lines(dir / "wt.sta");
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines[5].substr(0, 14), "   1     1   1");
}

TEST(OutputSta, DeltmxRepeatHasItsOwnMarker) {
  const Model m = make_model();
  const auto dir = fresh_dir();
  StaWriter w(dir / "wt.sta");
  w.begin(m);
  w.begin_step(m, 0);
  // Newton converged in 3 iterations, but the temperature change exceeded DELTMX: the attempt is
  // repeated smaller. It did not fail, so not "U" but "D".
  IncrementInfo deltmx = inc_info(1, 1, false, 0.5);
  deltmx.iterations = 3;
  deltmx.deltmx_exceeded = true;
  w.increment(deltmx);
  w.increment(inc_info(1, 2, false, 0.25));
  const auto lines = read_lines(dir / "wt.sta");
  ASSERT_EQ(lines.size(), 7u);
  EXPECT_EQ(lines[5], "   1     1   1D    1     2     3  0          0          0.5");
  EXPECT_EQ(lines[6].substr(0, 15), "   1     1   2U");
  EXPECT_EQ(StaWriter::attempt_marker(inc_info(1, 1, true, 0.5)), ' ');
}

// The times of a rejected attempt are the last converged ones: the total time column never runs
// backwards (a cut-back after increment 1 at 0.25 tried 0.25 + 0.5 and then 0.25 + 0.125).
TEST(OutputSta, RejectedAttemptsKeepTheLastConvergedTime) {
  const Model m = make_model();
  const auto dir = fresh_dir();
  StaWriter w(dir / "wt.sta");
  w.begin(m);
  w.begin_step(m, 0);
  auto info = [](int inc, int att, bool ok, double t, double dt) {
    IncrementInfo i = inc_info(inc, att, ok, t);
    i.dt = dt;
    return i;
  };
  w.increment(info(1, 1, true, 0.25, 0.25));
  w.increment(info(2, 1, false, 0.75, 0.5));
  w.increment(info(2, 2, true, 0.375, 0.125));
  const auto lines = read_lines(dir / "wt.sta");
  ASSERT_EQ(lines.size(), 8u);
  EXPECT_EQ(lines[6], "   1     2   1U    1     7     8  0.25       0.25       0.5");
  EXPECT_EQ(lines[7], "   1     2   2     1     2     3  0.375      0.375      0.125");
}

TEST(OutputSta, FailedRun) {
  const Model m = make_model();
  const auto dir = fresh_dir();
  StaWriter w(dir / "wt.sta");
  w.begin(m);
  w.increment(inc_info(1, 1, false, 0.0));
  RunSummary run;
  run.completed = false;
  run.failure = "too many attempts";
  w.end(m, run);
  const auto lines = read_lines(dir / "wt.sta");
  EXPECT_EQ(lines.back(), " THE ANALYSIS HAS NOT BEEN COMPLETED");
  EXPECT_NE(std::find(lines.begin(), lines.end(), " ***ERROR: too many attempts"), lines.end());
}

} // namespace
} // namespace gapfem
