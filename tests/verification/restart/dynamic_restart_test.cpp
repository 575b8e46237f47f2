// Restart across dynamic steps on every solver backend (issue 46: "restart across dynamic steps
// on each"). A C3D8 block (324 equations, so that mpirun -np 2 really splits it) is thrown onto
// 36 GAPUNI supports: hard gaps with Coulomb friction and penalty gaps with friction, an initial
// velocity, gravity, two *DYNAMIC steps (HHT with fixed increments, then HHT with HAFTOL automatic
// increments and a lateral push), *RESTART, WRITE, FREQUENCY=3. For each backend (CHOLMOD, MUMPS
// and the iterative method on one process, MUMPS and the iterative method under mpirun -np 2) the
// run is (a) left alone and (b) killed after an increment in step 1 (the impact increment, the
// last record two increments before it) and after one in step 2, then continued with --restart.
// The continued run's U, V, A of every node at every increment, the gap forces, slips and statuses
// (open or closed), the energies of every frame and the history rows (values and energies) must
// be the uninterrupted run's to 1e-8 of each field's largest value (issue 46's criterion between
// backends), and each backend's the CHOLMOD run's. A record written by one backend is continued
// by another (CHOLMOD's by MUMPS, and by the iterative method under mpirun): the record holds the
// state, not the solver.
//
// The oracle is always an uninterrupted gapfem run: restart must not change the answer. All runs
// use --factor-reuse never, so that no decision depends on measured times (docs/restart.md).
// Measured (largest difference of any field over its largest value): a continued run on one
// process is the uninterrupted one bit for bit on each backend, under mpirun within 1.6e-13
// (MUMPS on two ranks is not bitwise repeatable); backends against CHOLMOD within 1.5e-13; a
// CHOLMOD record continued by another backend within 1.2e-14; a restart deck (--oldjob) bit for
// bit with CHOLMOD, within 2.5e-14 with MUMPS on two ranks.
// Before the fix in analysis_restart.cpp both methods hung under mpirun at the first restart
// point (rank 0 alone dropped its factor there, and the ranks factor together).
#include "parallel/parallel.hpp"
#include "solver/restart_file.hpp"
#include "test_util.hpp"

#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

using namespace gapfem;
using gapfem::test::slurp;
namespace fs = std::filesystem;

namespace {

constexpr int kNx = 8, kNy = 3, kNz = 2; // C3D8 elements; 9 x 4 x 3 = 108 nodes, 324 equations
constexpr int kStep1Increments = 12;     // DIRECT, 0.01 over 0.12

int node_id(int i, int j, int k) {
  return 1 + i + (kNx + 1) * (j + (kNy + 1) * k);
}

/// What every step writes: U, V, A of every node and the gaps' forces every increment (JSON
/// frames), the monitored nodes' U, V, A and the energies as history output.
constexpr const char* kOutput = R"(*NODE PRINT, NSET=BLOCK
U, V, A
*EL PRINT, ELSET=GAPS
S
*OUTPUT, HISTORY
*NODE OUTPUT, NSET=MON
U, V, A
*ENERGY OUTPUT
ALLKE, ALLSE, ALLFD, ALLWK, ALLKL, ETOTAL
)";

/// Step 2: a push on one top corner, automatic increments from the half-increment residual.
std::string step2() {
  return fmt::format("*STEP, INC=1000\n*DYNAMIC, HAFTOL=5.\n0.01, 0.08\n*CLOAD\n{}, 1, -5.\n",
                     node_id(kNx, kNy, kNz)) +
         kOutput + "*END STEP\n";
}

/// The block on its supports. The bottom nodes alternate between hard frictional gaps (clearance
/// 0.01, mu 0.3) and penalty gaps (*SURFACE BEHAVIOR, PENALTY 1e4, clearance 0.012, mu 0.2); the
/// block starts moving down at 0.2 and sideways at 0.3, so the hard gaps close with an impact in
/// increment 5 of step 1 and the block slides and rocks; step 2 pushes one top corner back.
std::string dynamic_block() {
  const double h = 0.5;
  std::string d = "*HEADING\nblock thrown onto gap supports: restart across dynamic steps\n";
  d += "*NODE, NSET=BLOCK\n";
  for (int k = 0; k <= kNz; ++k)
    for (int j = 0; j <= kNy; ++j)
      for (int i = 0; i <= kNx; ++i)
        d += fmt::format("{}, {}, {}, {}\n", node_id(i, j, k), h * i, h * j, h * k);
  d += "*NODE, NSET=GROUND\n";
  for (int j = 0; j <= kNy; ++j)
    for (int i = 0; i <= kNx; ++i)
      d += fmt::format("{}, {}, {}, -0.1\n", 1000 + node_id(i, j, 0), h * i, h * j);
  d += "*ELEMENT, TYPE=C3D8, ELSET=SOLID\n";
  int e = 1;
  for (int k = 0; k < kNz; ++k)
    for (int j = 0; j < kNy; ++j)
      for (int i = 0; i < kNx; ++i)
        d += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", e++, node_id(i, j, k),
                         node_id(i + 1, j, k), node_id(i + 1, j + 1, k), node_id(i, j + 1, k),
                         node_id(i, j, k + 1), node_id(i + 1, j, k + 1),
                         node_id(i + 1, j + 1, k + 1), node_id(i, j + 1, k + 1));
  std::string hard = "*ELEMENT, TYPE=GAPUNI, ELSET=HARD\n";
  std::string soft = "*ELEMENT, TYPE=GAPUNI, ELSET=SOFT\n";
  for (int j = 0; j <= kNy; ++j)
    for (int i = 0; i <= kNx; ++i) {
      const int n = node_id(i, j, 0);
      ((i + j) % 2 ? soft : hard) += fmt::format("{}, {}, {}\n", 1000 + n, n, 1000 + n);
    }
  d += hard + soft;
  d += fmt::format("*ELSET, ELSET=GAPS\nHARD, SOFT\n*NSET, NSET=MON\n{}, {}\n",
                   node_id(kNx, kNy, kNz), node_id(0, 0, 0));
  d += R"(*MATERIAL, NAME=STEEL
*ELASTIC
2000., 0.3
*DENSITY
1.
*SOLID SECTION, ELSET=SOLID, MATERIAL=STEEL
*GAP, ELSET=HARD
0.01, 0., 0., -1., 1.
*FRICTION
0.3
*GAP, ELSET=SOFT
0.012, 0., 0., -1., 1.
*SURFACE BEHAVIOR, PENALTY
1.E4
*FRICTION
0.2
*BOUNDARY
GROUND, 1, 3
*INITIAL CONDITIONS, TYPE=VELOCITY
BLOCK, 1, 0.3
BLOCK, 3, -0.2
*RESTART, WRITE, FREQUENCY=3
)";
  const std::string output = kOutput;
  // Residual tolerance 1e-10 and correction tolerance 1e-8 instead of Abaqus's 5e-3 and 1e-2
  // (*CONTROLS, PARAMETERS=FIELD, in effect in both steps: Abaqus Analysis User's Guide,
  // "Commonly used control parameters", the values "remain in effect for the remainder of the
  // analysis", https://abaqus.uclouvain.be/English/SIMACAEANLRefMap/simaanl-c-convergecontrol.htm;
  // the restart deck's step 2 has them from the old job's step 1): with the default ones the first
  // increment of step 2 (a sudden push, sliding gaps at the stick/slip threshold) turns a
  // round-off difference in the start state into a converged state 3e-8 of max |U| away (another
  // stick/slip choice in an iteration, another equally converged point), as MUMPS on two ranks,
  // which is not bitwise repeatable, shows between two runs of the same deck (1e-8 apart). With
  // them every backend's histories agree to 1.5e-13, and the comparisons see the restart alone.
  d += "*STEP, INC=1000\n*DYNAMIC, DIRECT\n0.01, 0.12\n*CONTROLS, PARAMETERS=FIELD\n1e-10, 1e-8\n"
       "*DLOAD\nSOLID, GRAV, 10., 0., 0., -1.\n" +
       output + "*END STEP\n";
  return d + step2();
}

bool have_mpirun() {
  return std::system("command -v mpirun > /dev/null 2>&1") == 0;
}

/// A way of solving: the --solver name, its extra arguments and the number of processes (0: one,
/// without mpirun).
struct Backend {
  std::string solver;
  int ranks = 0;
  std::string args() const {
    // GMRES to 1e-13 (a PETSc option, passed through), as tests/cli/mpi_test.cpp: the default
    // Krylov tolerance would leave the restarted run's iterates (another start vector) 1e-9 apart
    std::string a = "--no-vtu -q --factor-reuse never";
    if (solver != "cholmod") a += " --solver " + solver;
    if (solver == "iterative") a += " -ksp_rtol 1e-13";
    return a;
  }
  std::string name() const { return ranks ? fmt::format("{}-np{}", solver, ranks) : solver; }
};

/// Why `b` cannot run here ("" when it can).
std::string unavailable(const Backend& b) {
  if (b.solver != "cholmod" && !parallel::available())
    return "no PETSc build (Debian's petsc-dev): --solver " + b.solver + " is not run";
  if (b.ranks > 0 && !have_mpirun()) return "no mpirun here (Debian's openmpi-bin): not run";
  return "";
}

/// gapfem in `dir` on its job.inp with the backend's arguments and `extra`; `env` prefixes the
/// command (GAPFEM_TEST_KILL_AFTER_INCREMENT=n). Returns the exit status; the terminal output
/// goes to `log`. Open MPI passes mpirun's environment on to the ranks it starts on this host. A
/// run that hangs (ranks waiting for each other) is stopped after 120 s (status 124). Waiting
/// ranks yield the processor (on a loaded machine an mpirun run took 8.6 s instead of 13.5 s).
int run(const fs::path& dir, const Backend& b, const std::string& extra,
        const std::string& env = "", std::string* log = nullptr,
        const std::string& deck = "job.inp") {
  const fs::path out = dir / "terminal.log";
  const std::string launcher = b.ranks > 0 ? fmt::format("mpirun -np {} ", b.ranks) : "";
  // in the sanitized build mpirun's ranks do not count leaks (as tests/cli/mpi_test.cpp): Open
  // MPI keeps a few bytes in components it unloads, which LeakSanitizer cannot name to suppress
  std::string asan;
  if (b.ranks > 0) {
    asan = "detect_leaks=0";
    if (const char* e = std::getenv("ASAN_OPTIONS")) asan = std::string(e) + ":detect_leaks=0";
    asan = "ASAN_OPTIONS='" + asan + "' ";
  }
  // the shell's own messages (a failed cd, a launcher it cannot start) go beside the directory,
  // so that a failure that never reached gapfem still says why (the terminal log is then empty)
  const fs::path shell = dir.parent_path() / (dir.filename().string() + ".shell.log");
  const std::string cmd = fmt::format(
      "( cd '{}' && OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
      "OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_mpi_yield_when_idle=1 {}{} timeout 120 {}'{}' "
      "{} {} {} > '{}' 2>&1 ) 2> '{}'",
      dir.string(), asan, env, launcher, GAPFEM_EXE, b.args(), extra, deck, out.string(),
      shell.string());
  const int rc = std::system(cmd.c_str());
  if (log) {
    *log = slurp(out);
    if (log->empty()) *log = "(no terminal output; the shell said: " + slurp(shell) + ")";
  }
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

fs::path fresh_dir(const fs::path& d) {
  fs::remove_all(d);
  fs::create_directories(d);
  std::ofstream(d / "job.inp") << dynamic_block();
  return d;
}

/// Kill the run after its n-th converged increment (every rank counts its own and raises SIGKILL
/// there), then continue it with --restart on `then`.
void kill_and_restart(const fs::path& dir, const Backend& first, int n, const Backend& then) {
  std::string log;
  const int killed =
      run(dir, first, "", fmt::format("GAPFEM_TEST_KILL_AFTER_INCREMENT={}", n), &log);
  ASSERT_NE(killed, 0) << log;
  ASSERT_EQ(slurp(dir / "job.sta").find("COMPLETED"), std::string::npos) << "not killed\n" << log;
  const RestartIndex idx = read_restart_index(dir / "job.res");
  ASSERT_FALSE(idx.records.empty());
  // the record the run continues from lies before the kill: increments are solved again
  const RestartRecordInfo& last = idx.records.back();
  const int step = n > kStep1Increments ? 2 : 1,
            increment = n > kStep1Increments ? n - kStep1Increments : n;
  EXPECT_TRUE(last.step < step || last.increment < increment)
      << "record step " << last.step << " increment " << last.increment;
  ASSERT_EQ(run(dir, then, "--restart", "", &log), 0) << log;
}

/// Every number of every frame (each node's U, V, A; each gap's forces and status; the frame's
/// energies and times) and of the history tables, by field, in the order written.
using Fields = std::map<std::string, std::vector<double>>;
void collect(const nlohmann::json& j, const std::string& field, Fields& out) {
  if (j.is_number()) {
    out[field].push_back(j.get<double>());
  } else if (j.is_string()) {
    // a gap's status, open or closed: a closed gap whose friction force is mu N to round-off
    // (it slid and comes to rest, or sticks on the edge of the cone) is called sticking or
    // slipping by the sign of a round-off difference, as seen between CHOLMOD and MUMPS; its
    // friction force and slip, compared as numbers, decide what it does
    out[field].push_back(j.get<std::string>() == "open" ? 0.0 : 1.0);
  } else if (j.is_array() || j.is_object()) {
    for (const auto& [k, v] : j.items())
      collect(v, std::isdigit(static_cast<unsigned char>(k[0])) ? field : k, out);
  }
}
Fields fields(const fs::path& dir, const std::string& job = "job") {
  const nlohmann::json j = nlohmann::json::parse(slurp(dir / (job + ".results.json")));
  Fields out;
  for (const auto& step : j.at("steps")) {
    for (const auto& frame : step.at("frames")) {
      for (const char* key : {"increment", "step_time", "dt"}) out[key].push_back(frame.at(key));
      collect(frame.at("nodes"), "nodes", out);
      collect(frame.at("energies"), "energies", out);
      for (const auto& [label, e] : frame.at("elements").items())
        if (e.contains("gap")) collect(e.at("gap"), "gap", out);
    }
    for (const char* table : {"values", "energies"}) {
      const auto& t = step.at("history").at(table);
      for (const auto& row : t.at("rows"))
        for (std::size_t c = 0; c < row.size(); ++c)
          out["history " + t.at("columns").at(c).get<std::string>()].push_back(row.at(c));
    }
  }
  return out;
}

/// Each field of `got` within 1e-8 of the largest value of that field in `want` (issue 46).
void expect_same_histories(const Fields& want, const Fields& got, const std::string& what) {
  SCOPED_TRACE(what);
  ASSERT_EQ(want.size(), got.size());
  for (const auto& [field, a] : want) {
    ASSERT_TRUE(got.count(field)) << field;
    const auto& b = got.at(field);
    ASSERT_EQ(a.size(), b.size()) << field;
    double scale = 0.0, diff = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      scale = std::max(scale, std::abs(a[i]));
      diff = std::max(diff, std::abs(a[i] - b[i]));
    }
    EXPECT_LE(diff, 1e-8 * scale) << field << " (largest " << scale << ")";
  }
}

/// The uninterrupted run of `b` in `root`/whole, checked to be the dynamics this test is about.
Fields uninterrupted(const fs::path& root, const Backend& b) {
  const fs::path dir = fresh_dir(root / "whole");
  std::string log;
  EXPECT_EQ(run(dir, b, "", "", &log), 0) << log;
  Fields f = fields(dir);
  // every increment of both steps is a frame (12 fixed ones, then automatic ones), the hard
  // gaps close in step 1 (an impact: kinetic energy lost to the impact, ALLKL > 0) and friction
  // dissipates
  EXPECT_GT(f["increment"].size(), static_cast<std::size_t>(kStep1Increments + 5));
  double allkl = 0.0, allfd = 0.0, closed = 0.0;
  for (double v : f["ALLKL"]) allkl = std::max(allkl, v);
  for (double v : f["ALLFD"]) allfd = std::max(allfd, v);
  for (double v : f["status"]) closed += v;
  EXPECT_GT(allkl, 0.0);
  EXPECT_GT(allfd, 0.0);
  EXPECT_GT(closed, 0.0);
  return f;
}

/// (a) and (b) for one backend, and its uninterrupted answer against CHOLMOD's.
void restart_on(const Backend& b) {
  if (const std::string why = unavailable(b); !why.empty()) GTEST_SKIP() << why;
  const fs::path root = test::test_dir();
  const Fields whole = uninterrupted(root, b);
  // in step 1 at the impact (increment 5, last record 3), in step 2 (its increment 5, last
  // record 3), and with CHOLMOD in step 2's first increment too (the record is step 1's end; the
  // restart deck test continues from there on MUMPS; a PETSc run costs 1-2 s to start)
  std::vector<int> kills = {5, kStep1Increments + 5};
  if (b.solver == "cholmod") kills.push_back(kStep1Increments + 1);
  for (int n : kills) {
    SCOPED_TRACE(fmt::format("{} killed after increment {}", b.name(), n));
    const fs::path dir = fresh_dir(root / fmt::format("killed{}", n));
    kill_and_restart(dir, b, n, b);
    if (::testing::Test::HasFatalFailure()) return;
    expect_same_histories(whole, fields(dir), "continued against uninterrupted");
  }
  if (b.solver != "cholmod") {
    // issue 46's criterion between backends
    const Fields cholmod = uninterrupted(root / "cholmod", Backend{"cholmod"});
    expect_same_histories(cholmod, whole, b.name() + " against cholmod");
  }
}

} // namespace

TEST(DynamicRestart, Cholmod) {
  restart_on(Backend{"cholmod"});
}

TEST(DynamicRestart, Mumps) {
  restart_on(Backend{"mumps"});
}

TEST(DynamicRestart, Iterative) {
  restart_on(Backend{"iterative"});
}

TEST(DynamicRestart, MumpsOnTwoProcesses) {
  restart_on(Backend{"mumps", 2});
}

TEST(DynamicRestart, IterativeOnTwoProcesses) {
  restart_on(Backend{"iterative", 2});
}

// The record holds the state, not the solver: a CHOLMOD run killed in step 2 is continued by MUMPS
// on one process and by the iterative method on two, and both end with CHOLMOD's uninterrupted
// histories.
TEST(DynamicRestart, ARecordOfOneBackendIsContinuedByAnother) {
  const Backend cholmod{"cholmod"};
  const fs::path root = test::test_dir();
  const Fields whole = uninterrupted(root, cholmod);
  for (const Backend& then : {Backend{"mumps"}, Backend{"iterative", 2}}) {
    if (const std::string why = unavailable(then); !why.empty()) {
      std::cout << "[  SKIPPED ] " << then.name() << ": " << why << "\n";
      continue;
    }
    SCOPED_TRACE("cholmod record continued by " + then.name());
    const fs::path dir = fresh_dir(root / then.name());
    kill_and_restart(dir, cholmod, kStep1Increments + 5, then);
    if (::testing::Test::HasFatalFailure()) return;
    expect_same_histories(whole, fields(dir), "continued against uninterrupted");
  }
}

// A restart deck (*RESTART, READ with --oldjob, docs/restart.md) continues the old job from the
// end of its first dynamic step, and from the middle of it, with step 2 given anew: the new job's
// results files (the old job's up to the restart point, then its own) hold the uninterrupted
// run's histories, on one process with CHOLMOD and on two with MUMPS.
TEST(DynamicRestart, RestartDeckContinuesTheMotion) {
  const fs::path root = test::test_dir();
  for (const Backend& b : {Backend{"cholmod"}, Backend{"mumps", 2}}) {
    if (const std::string why = unavailable(b); !why.empty()) {
      std::cout << "[  SKIPPED ] " << b.name() << ": " << why << "\n";
      continue;
    }
    SCOPED_TRACE(b.name());
    const fs::path dir = fresh_dir(root / b.name());
    std::string log;
    ASSERT_EQ(run(dir, b, "", "", &log), 0) << log;
    const Fields whole = fields(dir);
    for (int inc : {kStep1Increments, 6}) {
      SCOPED_TRACE(fmt::format("*RESTART, READ, STEP=1, INC={}", inc));
      const std::string name = fmt::format("new{}", inc);
      std::ofstream(dir / (name + ".inp"))
          << fmt::format("*HEADING\ncontinued\n*RESTART, READ, STEP=1, INC={}\n", inc) + step2();
      ASSERT_EQ(run(dir, b, "--oldjob job", "", &log, name + ".inp"), 0) << log;
      expect_same_histories(whole, fields(dir, name), "restart deck against uninterrupted");
    }
  }
}
