// Restart (docs/restart.md): a run killed after a converged increment and continued with
// `gapfem --restart` gives the same results files as the run that was never interrupted, to the
// last digit; a restart deck (*RESTART, READ with --oldjob) continues an old job and gives what
// one deck with the same history gives; bad restarts are input errors that say what there is.
//
// The oracle is always an uninterrupted gapfem run of the same history: restart must not change
// the answer. The runs use --factor-reuse never, so that no decision depends on measured times.
#include "solver/restart_file.hpp"
#include "test_util.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <sstream>
#include <sys/wait.h>

using namespace gapfem;
using gapfem::test::slurp;

namespace {

namespace fs = std::filesystem;

/// A block on six frictional gap supports: gravity and a ramped load press it down in step 1 (8
/// fixed increments; `restart_write` is the restart request in the model data), a lateral load
/// makes it slide in step 2 (automatic increments).
std::string block_deck(const std::string& restart_write, const std::string& heading = "block",
                       double x2 = 2.0) {
  return fmt::format(R"(*HEADING
{}
*NODE, NSET=BLOCK
1, 0., 0., 0.
2, 1., 0., 0.
3, {}, 0., 0.
4, 0., 1., 0.
5, 1., 1., 0.
6, 2., 1., 0.
7, 0., 0., 1.
8, 1., 0., 1.
9, 2., 0., 1.
10, 0., 1., 1.
11, 1., 1., 1.
12, 2., 1., 1.
*NODE, NSET=GROUND
101, 0., 0., 0.
102, 1., 0., 0.
103, 2., 0., 0.
104, 0., 1., 0.
105, 1., 1., 0.
106, 2., 1., 0.
*NSET, NSET=TOP
7, 8, 9, 10, 11, 12
*NSET, NSET=YFACE
1, 2, 3, 7, 8, 9
*ELEMENT, TYPE=C3D8, ELSET=SOLID
1, 1, 2, 5, 4, 7, 8, 11, 10
2, 2, 3, 6, 5, 8, 9, 12, 11
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*DENSITY
7.85E-9
*SOLID SECTION, ELSET=SOLID, MATERIAL=STEEL
*ELEMENT, TYPE=GAPUNI, ELSET=SUPPORT
201, 1, 101
202, 2, 102
203, 3, 103
204, 4, 104
205, 5, 105
206, 6, 106
*GAP, ELSET=SUPPORT
0., 0., 0., -1., 1000.
*FRICTION
0.3
*BOUNDARY
GROUND, 1, 3
YFACE, 2, 2
{}
*STEP, NAME=PRESS, INC=50
*STATIC, DIRECT
0.125, 1.
*CLOAD
TOP, 3, -500.
*DLOAD
SOLID, GRAV, 9810., 0., 0., -1.
*NODE PRINT, NSET=TOP
U
*EL PRINT, ELSET=SUPPORT
S
*END STEP
*STEP, NAME=SLIDE, INC=50
*STATIC
0.1, 1.
*CLOAD
TOP, 1, 70.
*NODE PRINT, NSET=TOP
U
*NODE PRINT, NSET=GROUND, TOTALS=YES
RF
*EL PRINT, ELSET=SUPPORT
S, E
*END STEP
)",
                     heading, x2, restart_write);
}

struct Cli {
  int status = -1;
  bool killed = false;
  std::string output;
};

Cli gapfem_cli(const fs::path& dir, const std::string& args, const std::string& env = "") {
  const fs::path log = dir / "cli.log";
  const std::string cmd = fmt::format("cd '{}' && {} '{}' -q --factor-reuse never {} > '{}' 2>&1",
                                      dir.string(), env, GAPFEM_EXE, args, log.string());
  const int rc = std::system(cmd.c_str());
  Cli r;
  r.status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  // the shell reports a child killed by SIGKILL as status 128 + 9
  r.killed = r.status == 128 + 9;
  r.output = slurp(log);
  return r;
}

fs::path fresh_dir(const std::string& name) {
  const fs::path d = gapfem::test::test_dir() / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

/// The lines of a text file without those that hold times, dates or memory.
std::string steady_lines(const fs::path& p) {
  std::istringstream in(slurp(p));
  std::string line, out;
  while (std::getline(in, line))
    if (line.find("SECONDS") == std::string::npos && line.find("MEMORY") == std::string::npos &&
        line.find("DATE") == std::string::npos)
      out += line + "\n";
  return out;
}

/// Two results documents are equal but for timings and the job name.
void expect_same_json(const nlohmann::json& a, const nlohmann::json& b, const std::string& at) {
  ASSERT_EQ(a.type(), b.type()) << at;
  if (a.is_object()) {
    for (const auto& [k, v] : a.items()) {
      if (k == "seconds" || k == "wall_seconds" || k == "publication_seconds" ||
          k == "peak_memory_kb" || k == "job")
        continue;
      ASSERT_TRUE(b.contains(k)) << at << "/" << k;
      expect_same_json(v, b.at(k), at + "/" + k);
    }
    EXPECT_EQ(a.size(), b.size()) << at;
  } else if (a.is_array()) {
    ASSERT_EQ(a.size(), b.size()) << at;
    for (std::size_t i = 0; i < a.size(); ++i)
      expect_same_json(a[i], b[i], fmt::format("{}[{}]", at, i));
  } else if (a.is_number()) {
    const double x = a.get<double>(), y = b.get<double>();
    EXPECT_NEAR(x, y, 1e-12 * std::max(1.0, std::abs(x))) << at;
  } else {
    EXPECT_EQ(a, b) << at;
  }
}

nlohmann::json results(const fs::path& dir, const std::string& job) {
  return nlohmann::json::parse(slurp(dir / (job + ".results.json")));
}

/// The uninterrupted run of `deck` in its own directory.
fs::path reference_run(const std::string& deck) {
  const fs::path dir = fresh_dir("reference");
  std::ofstream(dir / "job.inp") << deck;
  const Cli r = gapfem_cli(dir, "job.inp");
  EXPECT_EQ(r.status, 0) << r.output;
  return dir;
}

/// Kill the run after its n-th converged increment, then continue it with --restart.
fs::path killed_and_restarted(const std::string& deck, int n, const std::string& name) {
  const fs::path dir = fresh_dir(name);
  std::ofstream(dir / "job.inp") << deck;
  const Cli killed =
      gapfem_cli(dir, "job.inp", fmt::format("GAPFEM_TEST_KILL_AFTER_INCREMENT={}", n));
  EXPECT_TRUE(killed.killed) << "status " << killed.status << ": " << killed.output;
  const Cli again = gapfem_cli(dir, "--restart job.inp");
  EXPECT_EQ(again.status, 0) << again.output;
  return dir;
}

void expect_same_files(const fs::path& ref, const fs::path& got) {
  EXPECT_EQ(steady_lines(ref / "job.dat"), steady_lines(got / "job.dat"));
  EXPECT_EQ(steady_lines(ref / "job.sta"), steady_lines(got / "job.sta"));
  expect_same_json(results(ref, "job"), results(got, "job"), "");
  EXPECT_EQ(slurp(ref / "job.pvd"), slurp(got / "job.pvd"));
  for (const auto& e : fs::directory_iterator(ref))
    if (e.path().extension() == ".vtu")
      EXPECT_TRUE(fs::exists(got / e.path().filename())) << e.path().filename();
}

} // namespace

// FREQUENCY=2: killed after increment 3 the last record is increment 2, so the output of
// increment 3 is cut from every file and increment 3 is solved again.
TEST(Restart, KilledRunContinuesAsIfUninterrupted) {
  const std::string deck = block_deck("*RESTART, WRITE, FREQUENCY=2");
  const fs::path ref = reference_run(deck);
  const nlohmann::json rj = results(ref, "job");
  ASSERT_GT(rj.at("steps").size(), 1u);
  for (int n : {3, 9, 11}) { // in step 1; in step 2 (step 1 has 8 increments)
    SCOPED_TRACE(n);
    const fs::path got = killed_and_restarted(deck, n, fmt::format("killed{}", n));
    expect_same_files(ref, got);
  }
}

// OVERLAY keeps only the newest record; NUMBER INTERVAL writes at marks of the step time; the
// restart request in history data applies from its step on.
TEST(Restart, OverlayAndNumberInterval) {
  for (const char* req :
       {"*RESTART, WRITE, FREQUENCY=1, OVERLAY", "*RESTART, WRITE, NUMBER INTERVAL=3"}) {
    SCOPED_TRACE(req);
    const std::string deck = block_deck(req);
    const fs::path ref = reference_run(deck);
    const fs::path got = killed_and_restarted(deck, 6, "killed");
    expect_same_files(ref, got);
    const RestartIndex idx = read_restart_index(got / "job.res");
    if (std::string(req).find("OVERLAY") != std::string::npos) {
      ASSERT_EQ(idx.records.size(), 1u);
      EXPECT_EQ(idx.records[0].step, 2);
      EXPECT_TRUE(idx.records[0].step_end);
    } else {
      // 3 marks in each step: at 1/3, 2/3 and the end
      std::vector<int> steps;
      for (const auto& r : idx.records) steps.push_back(r.step);
      EXPECT_EQ(steps, (std::vector<int>{1, 1, 1, 2, 2, 2}));
    }
  }
}

// The examples: a coupled temperature-displacement step with DELTMX control (fuel pin), beams on
// frictional gaps under weight then heat (pipe on supports), an interference fit (shrink fit).
// Each is killed after its 3rd and after its middle increment, restarted from FREQUENCY=2 records,
// and must end with the uninterrupted run's files.
TEST(Restart, ExamplesContinueAsIfUninterrupted) {
  const fs::path src = fs::path(GAPFEM_SOURCE_DIR) / "examples";
  for (const char* ex : {"03_fuel_pin/fuel_pin.inp", "01_pipe_on_supports/pipe_on_supports.inp",
                         "02_shrink_fit/shrink_fit.inp"}) {
    SCOPED_TRACE(ex);
    const std::string deck = "*RESTART, WRITE, FREQUENCY=2\n" + slurp(src / ex);
    const fs::path ref = reference_run(deck);
    const int increments = results(ref, "job").at("summary").at("increments").get<int>();
    ASSERT_GT(increments, 3);
    for (int n : {3, increments / 2 + 1}) {
      SCOPED_TRACE(n);
      expect_same_files(ref, killed_and_restarted(deck, n, fmt::format("killed{}", n)));
    }
  }
}

// A damaged last record (the run was killed while writing it) is skipped: the one before it is
// used, and the result is still that of the uninterrupted run.
TEST(Restart, DamagedLastRecordIsSkipped) {
  const std::string deck = block_deck("*RESTART, WRITE, FREQUENCY=1");
  const fs::path ref = reference_run(deck);
  const fs::path dir = fresh_dir("damaged");
  std::ofstream(dir / "job.inp") << deck;
  gapfem_cli(dir, "job.inp", "GAPFEM_TEST_KILL_AFTER_INCREMENT=5");
  const RestartIndex before = read_restart_index(dir / "job.res");
  ASSERT_EQ(before.records.size(), 5u);
  fs::resize_file(dir / "job.res", before.records.back().end - 7);
  const RestartIndex after = read_restart_index(dir / "job.res");
  ASSERT_EQ(after.records.size(), 4u);
  const Cli again = gapfem_cli(dir, "--restart job.inp");
  ASSERT_EQ(again.status, 0) << again.output;
  expect_same_files(ref, dir);
}

// *RESTART, READ, STEP=1, INC=4 in a new deck continues the old job's step 1 after its 4th
// increment and then runs the new deck's step. The oracle: one deck with step 1 and the new step.
TEST(Restart, OldJobContinuedByRestartDeck) {
  const fs::path dir = fresh_dir("oldjob");
  std::ofstream(dir / "old.inp") << block_deck("*RESTART, WRITE, FREQUENCY=1");
  ASSERT_EQ(gapfem_cli(dir, "old.inp").status, 0);
  const std::string new_step = R"(*STEP, NAME=PULL, INC=50
*STATIC
0.1, 1.
*CLOAD
TOP, 1, -100.
*NODE PRINT, NSET=TOP
U
*END STEP
)";
  std::ofstream(dir / "new.inp") << "*HEADING\ncontinued\n*RESTART, READ, STEP=1, INC=4\n" +
                                        new_step;
  const Cli r = gapfem_cli(dir, "new.inp --oldjob old");
  ASSERT_EQ(r.status, 0) << r.output;

  std::string one = block_deck("*RESTART, WRITE, FREQUENCY=1");
  one = one.substr(0, one.find("*STEP, NAME=SLIDE")) + new_step;
  // the reference is named like the old job: a restart job's files keep the old job's header
  const fs::path ref = fresh_dir("reference");
  std::ofstream(ref / "old.inp") << one;
  ASSERT_EQ(gapfem_cli(ref, "old.inp").status, 0);
  expect_same_json(results(ref, "old"), results(dir, "new"), "");
  EXPECT_EQ(steady_lines(ref / "old.dat"), steady_lines(dir / "new.dat"));
  EXPECT_TRUE(fs::exists(dir / "new.res"));

  // the restart job killed in its new step continues from its own new.res
  const fs::path again = fresh_dir("again");
  fs::copy_file(dir / "new.inp", again / "new.inp");
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().rfind("old", 0) == 0)
      fs::copy_file(e.path(), again / e.path().filename());
  // total increments: 8 in step 1 (4 of them the old job's), then 2 of PULL
  const Cli killed =
      gapfem_cli(again, "new.inp --oldjob old", "GAPFEM_TEST_KILL_AFTER_INCREMENT=10");
  EXPECT_TRUE(killed.killed) << killed.output;
  const Cli resumed = gapfem_cli(again, "new.inp --oldjob old --restart");
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  expect_same_json(results(dir, "new"), results(again, "new"), "");
  EXPECT_EQ(steady_lines(dir / "new.dat"), steady_lines(again / "new.dat"));
}

// The modes a *FREQUENCY step kept travel in the restart records of the general steps after it:
// a restart job's *STEADY STATE DYNAMICS step works on them as the uninterrupted run's does.
TEST(Restart, ModesOfAFrequencyStepReachAModeBasedStepAfterARestart) {
  const std::string model = R"(*HEADING
SDOF
*NODE
1, 0., 0., 0.
*ELEMENT, TYPE=SPRING1, ELSET=K
1, 1
*SPRING, ELSET=K
1
100.
*ELEMENT, TYPE=MASS, ELSET=M
2, 1
*MASS, ELSET=M
1.
*BOUNDARY
1, 2, 3
*RESTART, WRITE, FREQUENCY=1
*STEP
*STATIC
*CLOAD
1, 1, 1.
*END STEP
*STEP
*FREQUENCY
1
*END STEP
*STEP
*STATIC
*CLOAD
1, 1, 2.
*END STEP
)";
  const std::string ssd = R"(*STEP
*STEADY STATE DYNAMICS, INTERVAL=RANGE
1., 2., 4
*MODAL DAMPING
1, 1, 0.05
*CLOAD
1, 1, 1.
*END STEP
)";
  const fs::path dir = fresh_dir("modes");
  std::ofstream(dir / "old.inp") << model;
  ASSERT_EQ(gapfem_cli(dir, "old.inp").status, 0);
  std::ofstream(dir / "new.inp") << "*HEADING\ncontinued\n*RESTART, READ, STEP=3, INC=1\n" + ssd;
  const Cli r = gapfem_cli(dir, "new.inp --oldjob old");
  ASSERT_EQ(r.status, 0) << r.output;
  const fs::path ref = fresh_dir("modes_reference");
  std::ofstream(ref / "old.inp") << model + ssd;
  ASSERT_EQ(gapfem_cli(ref, "old.inp").status, 0);
  const nlohmann::json a = results(ref, "old"), b = results(dir, "new");
  const auto& fa = a["steps"][3]["frames"];
  const auto& fb = b["steps"][3]["frames"];
  ASSERT_EQ(fa.size(), 4u);
  ASSERT_EQ(fb.size(), fa.size());
  for (std::size_t k = 0; k < fa.size(); ++k) {
    EXPECT_EQ(fa[k]["frequency"], fb[k]["frequency"]);
    EXPECT_EQ(fa[k]["nodes"]["1"]["U_imaginary"], fb[k]["nodes"]["1"]["U_imaginary"]);
    EXPECT_NE(fb[k]["nodes"]["1"]["U_amplitude"][0].get<double>(), 0.0);
  }
}

// END STEP: the old step ends at the restart point with its loads there. The oracle: step 1 of
// period 0.5 with half the load (the same ramp: every increment sees the same load).
TEST(Restart, EndStepEndsTheStepAtTheRestartPoint) {
  const fs::path dir = fresh_dir("endstep");
  std::string old_deck = block_deck("*RESTART, WRITE, FREQUENCY=1");
  // gravity ramped too, so that the step's loads at time 0.5 are half of the step's
  const std::string ramp = "*DLOAD\nSOLID, GRAV, 9810., 0., 0., -1.\n";
  std::ofstream(dir / "old.inp") << old_deck;
  ASSERT_EQ(gapfem_cli(dir, "old.inp").status, 0);
  std::string slide = old_deck.substr(old_deck.find("*STEP, NAME=SLIDE"));
  std::ofstream(dir / "new.inp")
      << "*HEADING\nended early\n*RESTART, READ, STEP=1, INC=4, END STEP\n" + slide;
  const Cli r = gapfem_cli(dir, "new.inp --oldjob old.res");
  ASSERT_EQ(r.status, 0) << r.output;
  const nlohmann::json got = results(dir, "new");

  std::string one = old_deck;
  auto replace = [&](const std::string& a, const std::string& b) {
    const auto at = one.find(a);
    ASSERT_NE(at, std::string::npos) << a;
    one.replace(at, a.size(), b);
  };
  replace("0.125, 1.\n*CLOAD\nTOP, 3, -500.\n" + ramp,
          "0.125, 0.5\n*CLOAD\nTOP, 3, -250.\n*DLOAD\nSOLID, GRAV, 4905., 0., 0., -1.\n");
  const fs::path ref = fresh_dir("reference");
  std::ofstream(ref / "job.inp") << one;
  ASSERT_EQ(gapfem_cli(ref, "job.inp").status, 0);
  const nlohmann::json want = results(ref, "job");
  // the step results (the last frame of each step) agree; the step time of step 1 is 0.5 in both
  ASSERT_EQ(got.at("steps").size(), want.at("steps").size());
  expect_same_json(want.at("steps").back(), got.at("steps").back(), "steps[-1]");
}

// What a user gets wrong: each is an input error (exit 1) that says what to do.
TEST(Restart, BadRestartsAreInputErrors) {
  const fs::path dir = fresh_dir("bad");
  std::ofstream(dir / "job.inp") << block_deck("*RESTART, WRITE, FREQUENCY=2");
  // no restart file yet
  Cli r = gapfem_cli(dir, "--restart job.inp");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("cannot read the restart file"), std::string::npos) << r.output;
  ASSERT_EQ(gapfem_cli(dir, "job.inp").status, 0);

  // a restart deck without --oldjob, and an increment that has no record
  std::ofstream(dir / "new.inp")
      << "*HEADING\n*RESTART, READ, STEP=1, INC=3\n*STEP\n*STATIC\n*END STEP\n";
  r = gapfem_cli(dir, "new.inp");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("--oldjob"), std::string::npos) << r.output;
  r = gapfem_cli(dir, "new.inp --oldjob job");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("new.inp:2: *RESTART: STEP=1, INC=3: there is no such restart point"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("step 1 increments 2, 4, 6, 8; step 2 increments"), std::string::npos)
      << r.output;
  r = gapfem_cli(dir, "new.inp --oldjob nosuchjob");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("cannot read the restart file"), std::string::npos) << r.output;
  // --oldjob for a deck that does not continue anything
  r = gapfem_cli(dir, "job.inp --oldjob job");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("no *RESTART, READ"), std::string::npos) << r.output;

  // a file that is not a gapfem restart file
  std::ofstream(dir / "other.res") << "** an Abaqus restart file is binary, this is not one\n";
  std::ofstream(dir / "next.inp") << "*RESTART, READ\n*STEP\n*STATIC\n*END STEP\n";
  r = gapfem_cli(dir, "next.inp --oldjob other.res");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("not a gapfem restart file"), std::string::npos) << r.output;

  // the deck changed its mesh since the restart data was written
  std::ofstream(dir / "job.inp") << block_deck("*RESTART, WRITE, FREQUENCY=2", "block", 2.5);
  r = gapfem_cli(dir, "--restart job.inp");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("written for another model"), std::string::npos) << r.output;
}
