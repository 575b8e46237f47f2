// What gapfem writes and what it never touches (docs/results.md, issue 43): a symbolic link, a
// named pipe or a directory in the place of any results file is refused before solving (exit 1,
// one message naming it) and no file outside the output folder changes; --restart never truncates
// through a link; a hard link to an earlier result is replaced, not written; two runs of one job
// in one folder are stopped by job.lck; a killed run's lock is taken over.
#include "app/job_files.hpp"
#include "test_util.hpp"

#include <array>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

using namespace gapfem;
using namespace gapfem::test;
namespace fs = std::filesystem;

namespace {

const std::string kDeck =
    std::string("*HEADING\nspring and gap, with restart data and a .frd file\n") +
    kSpringOnGapModel + R"(*RESTART, WRITE, FREQUENCY=1
*STEP, INC=20
*STATIC
0.5, 1.
*CLOAD
10, 2, -100.
*NODE PRINT
U
*NODE FILE
U
*END STEP
)";

/// Every name a job writes or stages a file under (docs/results.md).
const std::array<const char*, 18> kNames = {"job.dat",
                                            "job.sta",
                                            "job.msg",
                                            "job.frd",
                                            "job.results.json",
                                            "job.results.json.part",
                                            "job.results.json.a",
                                            "job.results.json.b",
                                            "job.results.json.tmp",
                                            "job.pvd",
                                            "job.pvd.tmp",
                                            "job.report.html",
                                            "job.report.html.tmp",
                                            "job.res",
                                            "job.res.tmp",
                                            "job.lck",
                                            "job_1_2.vtu",
                                            "job_1_2.vtu.tmp"};

struct CliRun {
  int status = -1;
  std::string output;
};

/// gapfem on dir/job.inp into dir/out (60 s at most: a run that hangs fails the test).
CliRun run(const fs::path& dir, const std::string& args = "") {
  const std::string cmd = "cd '" + dir.string() + "' && timeout -s KILL 60 '" + GAPFEM_EXE +
                          "' -q --no-vtu -o out " + args + " job.inp > run.log 2>&1";
  const int rc = std::system(cmd.c_str());
  return {WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, slurp(dir / "run.log")};
}

fs::path fresh(const std::string& name) {
  const fs::path dir = test_dir() / name;
  fs::remove_all(dir);
  fs::create_directories(dir / "out");
  std::ofstream(dir / "job.inp") << kDeck;
  return dir;
}

/// A file outside the output folder whose bytes and time must not change.
struct Sentinel {
  fs::path path;
  fs::file_time_type time;
  explicit Sentinel(const fs::path& dir) : path(dir / "outside.txt") {
    std::ofstream(path) << "precious\n";
    time = fs::last_write_time(path);
  }
  bool intact() const { return slurp(path) == "precious\n" && fs::last_write_time(path) == time; }
};

} // namespace

TEST(ResultsSafety, EveryResultsNameAsALinkPipeOrDirectoryIsRefusedBeforeSolving) {
  int cases = 0;
  for (const char* name : kNames) {
    for (const std::string kind : {"symbolic link", "named pipe (FIFO)", "directory"}) {
      const fs::path dir = fresh("c" + std::to_string(cases++));
      const Sentinel outside(dir);
      const fs::path at = dir / "out" / name;
      if (kind == "symbolic link") fs::create_symlink(outside.path, at);
      if (kind == "named pipe (FIFO)") ASSERT_EQ(::mkfifo(at.c_str(), 0644), 0);
      if (kind == "directory") fs::create_directory(at);
      const CliRun r = run(dir);
      EXPECT_EQ(r.status, 1) << name << " as " << kind << ": " << r.output;
      EXPECT_NE(r.output.find(std::string(name) + "': it is a " + kind), std::string::npos)
          << r.output;
      EXPECT_NE(r.output.find("remove it or choose another output directory with -o"),
                std::string::npos)
          << r.output;
      EXPECT_TRUE(outside.intact()) << name << " as " << kind;
      const char* other = std::string(name) == "job.dat" ? "job.sta" : "job.dat";
      EXPECT_FALSE(fs::exists(dir / "out" / other)) << "solved although " << name;
    }
  }
}

TEST(ResultsSafety, ARestartNeverWritesThroughALinkPlantedAfterTheRun) {
  for (const char* name : {"job.dat", "job.sta", "job.msg", "job.frd", "job.res"}) {
    const fs::path dir = fresh(std::string("r_") + name);
    ASSERT_EQ(run(dir).status, 0);
    const Sentinel outside(dir);
    const fs::path at = dir / "out" / name;
    fs::remove(at);
    fs::create_symlink(outside.path, at);
    const CliRun r = run(dir, "--restart");
    EXPECT_EQ(r.status, 1) << name << ": " << r.output;
    EXPECT_NE(r.output.find("is a symbolic link"), std::string::npos) << r.output;
    EXPECT_TRUE(outside.intact()) << name;
  }
}

TEST(ResultsSafety, AHardLinkToAnEarlierResultIsReplacedNotWritten) {
  const fs::path dir = fresh("hard");
  const Sentinel outside(dir);
  for (const char* name : {"job.dat", "job.sta", "job.results.json", "job.pvd"})
    ASSERT_EQ(::link(outside.path.c_str(), (dir / "out" / name).c_str()), 0);
  const CliRun r = run(dir);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(outside.intact());
  EXPECT_NE(slurp(dir / "out" / "job.dat").find("spring and gap"), std::string::npos);
}

TEST(ResultsSafety, ASecondRunOfTheJobStopsAtOnceNamingTheFirst) {
  const fs::path dir = fresh("lock");
  {
    const JobLock held = JobLock::take(dir / "out", "job"); // a run of the job in progress
    const auto t0 = std::chrono::steady_clock::now();
    const CliRun r = run(dir);
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("job 'job': it is already running in 'out' (process " +
                            std::to_string(::getpid())),
              std::string::npos)
        << r.output;
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(20));
    EXPECT_FALSE(fs::exists(dir / "out" / "job.sta"));
    const CliRun restart = run(dir, "--restart"); // --restart respects it too
    EXPECT_EQ(restart.status, 1) << restart.output;
    EXPECT_NE(restart.output.find("already running"), std::string::npos) << restart.output;
  }
  EXPECT_FALSE(fs::exists(dir / "out" / "job.lck")); // released with the run
  const CliRun after = run(dir);
  EXPECT_EQ(after.status, 0) << after.output;
  EXPECT_FALSE(fs::exists(dir / "out" / "job.lck"));
}

TEST(ResultsSafety, TheLockOfAKilledRunIsTakenOverWithAWarning) {
  const fs::path dir = fresh("stale");
  // what a run killed with SIGKILL leaves: the file, but no process holds its lock
  std::ofstream(dir / "out" / "job.lck") << "gapfem pid 99999999 host elsewhere start 1\n";
  const std::string cmd =
      "cd '" + dir.string() + "' && '" + GAPFEM_EXE + "' --no-vtu -o out job.inp > run.log 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(dir / "run.log");
  EXPECT_NE(slurp(dir / "run.log")
                .find("the lock file 'out/job.lck' was left by process 99999999 on host "
                      "elsewhere, which no longer runs; taking it over"),
            std::string::npos)
      << slurp(dir / "run.log");
  EXPECT_FALSE(fs::exists(dir / "out" / "job.lck"));
}

// The same in a private mount namespace, with /etc/passwd itself as the target (a copy bound over
// it, so the real one is never at risk): no file outside the output folder changes.
TEST(ResultsSafety, NoSystemFileChangesWhenEveryResultsNameIsALinkToIt) {
  const fs::path dir = fresh("namespace");
  if (std::system("unshare --mount --propagation private true > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "this user cannot create a private mount namespace (unshare --mount); the "
                    "same refusal is checked with a file of the test's own above";
  std::string script = "set -e\ncd '" + dir.string() + "'\n";
  script += "cp /etc/passwd passwd.copy\nmount --bind passwd.copy /etc/passwd\n";
  script += "sum0=$(sha256sum < /etc/passwd)\n";
  for (const char* name : kNames) script += std::string("ln -s /etc/passwd out/") + name + "\n";
  script += "set +e\ntimeout -s KILL 60 '" + std::string(GAPFEM_EXE) +
            "' -q -o out job.inp > run.log 2>&1; echo $? > rc\n";
  script += "(cd out && timeout -s KILL 60 '" + std::string(GAPFEM_EXE) +
            "' -q --restart -o . ../job.inp >> ../run.log 2>&1; echo $? >> ../rc)\n";
  script += "[ \"$(sha256sum < /etc/passwd)\" = \"$sum0\" ] && echo unchanged > verdict\n";
  std::ofstream(dir / "probe.sh") << script;
  const std::string cmd =
      "unshare --mount --propagation private sh '" + (dir / "probe.sh").string() + "'";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(dir / "run.log");
  EXPECT_EQ(slurp(dir / "verdict"), "unchanged\n") << slurp(dir / "run.log");
  EXPECT_EQ(slurp(dir / "rc"), "1\n1\n") << slurp(dir / "run.log");
}
