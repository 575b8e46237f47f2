// Results that survive: job.results.json is one complete JSON document at every moment, holding
// every increment the .sta has reported converged, when the run is killed (SIGKILL at several
// points) or the disk fills up (an injected write failure); VTU frames and the .pvd are complete
// or absent; the output directory is checked before solving.
#include "output/output_file.hpp"
#include "test_util.hpp"

#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using namespace gapfem;

namespace {

using gapfem::test::slurp;

/// A spring with a gap pushed in `n` fixed increments; *NODE PRINT every `every` increments and
/// field output (VTU) every `every` increments.
std::string stepping_deck(int n, int every) {
  return fmt::format(R"(*HEADING
spring and gap in {} increments
*NODE
10, 0., 0., 0.
12, 0., -1., 0.
*ELEMENT, TYPE=SPRING1, ELSET=SPR
1, 10
*SPRING, ELSET=SPR
2
100.
*ELEMENT, TYPE=GAPUNI, ELSET=G1
101, 10, 12
*GAP, ELSET=G1
0.5, 0., -1., 0., 1.
*BOUNDARY
12, 1, 3
10, 1, 1
10, 3, 3
*STEP, INC={}
*STATIC, DIRECT
{}, 1.
*CLOAD
10, 2, -100.
*NODE PRINT, FREQUENCY={}
U
*OUTPUT, FIELD, FREQUENCY={}
*NODE OUTPUT
U
*END STEP
)",
                     n, n + 10, 1.0 / n, every, every);
}

/// Increments the .sta reports converged (step 1).
std::vector<int> sta_converged(const std::filesystem::path& sta) {
  std::vector<int> incs;
  std::istringstream in(slurp(sta));
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string step, inc, att;
    if (!(ls >> step >> inc >> att)) continue;
    auto digits = [](const std::string& t) {
      return !t.empty() && std::all_of(t.begin(), t.end(), ::isdigit);
    };
    if (digits(step) && digits(inc) && digits(att)) incs.push_back(std::stoi(inc));
  }
  return incs;
}

/// Checks that `dir/job.results.json` is a complete document whose frames hold every increment
/// up to its last converged one that *NODE PRINT asked for; returns that increment (0: none).
int check_results(const std::filesystem::path& dir, int every) {
  const std::string text = slurp(dir / "job.results.json");
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text);
  } catch (const std::exception& e) {
    ADD_FAILURE() << "job.results.json is not valid JSON (" << e.what() << "), " << text.size()
                  << " bytes: " << text.substr(0, 300);
    return -1;
  }
  EXPECT_EQ(doc["schema"], "gapfem.results/1");
  const auto& last = doc["summary"]["last_converged"];
  const int upto = last.is_null() ? 0 : last["increment"].get<int>();
  std::vector<int> frames;
  if (!doc["steps"].empty())
    for (const auto& f : doc["steps"][0]["frames"]) frames.push_back(f["increment"].get<int>());
  for (int i = every; i <= upto; i += every)
    EXPECT_NE(std::find(frames.begin(), frames.end(), i), frames.end())
        << "increment " << i << " is converged (last " << upto << ") but has no frame";
  // VTU: every frame listed in the collection is there and complete
  if (std::filesystem::exists(dir / "job.pvd")) {
    const std::string pvd = slurp(dir / "job.pvd");
    EXPECT_NE(pvd.find("</VTKFile>"), std::string::npos) << pvd;
    for (std::size_t at = pvd.find("file=\""); at != std::string::npos;
         at = pvd.find("file=\"", at + 1)) {
      const std::size_t q = pvd.find('"', at + 6);
      const std::string vtu = slurp(dir / pvd.substr(at + 6, q - at - 6));
      EXPECT_NE(vtu.find("</VTKFile>"), std::string::npos) << pvd.substr(at + 6, q - at - 6);
    }
  }
  return upto;
}

} // namespace

// SIGKILL after 1, 5 and 40 increments (and wherever the clock lands): the document is valid and
// holds at least every increment the .sta had reported converged.
TEST(DurableResults, KillAtAnyPointKeepsEveryReportedIncrement) {
  const int n = 1500, every = 5;
  const auto deck = test::write_deck(stepping_deck(n, every), "job");
  const auto dir = deck.parent_path();
  for (const int kill_after : {1, 5, 40, 120}) {
    for (const char* f : {"job.results.json", "job.sta", "job.pvd"})
      std::filesystem::remove(dir / f);
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      const int devnull = ::open("/dev/null", O_WRONLY);
      ::dup2(devnull, 1);
      ::dup2(devnull, 2);
      ::execl(GAPFEM_EXE, GAPFEM_EXE, "-q", deck.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    const auto start = std::chrono::steady_clock::now();
    int status = 0;
    bool exited = false;
    while (std::chrono::steady_clock::now() - start < std::chrono::seconds(120)) {
      if (::waitpid(pid, &status, WNOHANG) == pid) {
        exited = true;
        break;
      }
      if (static_cast<int>(sta_converged(dir / "job.sta").size()) >= kill_after) break;
      std::this_thread::sleep_for(std::chrono::microseconds(300));
    }
    if (!exited) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
    }
    const std::vector<int> reported = sta_converged(dir / "job.sta");
    const int reported_last = reported.empty() ? 0 : reported.back();
    SCOPED_TRACE(
        fmt::format("killed after {} increments; the .sta reports {}", kill_after, reported_last));
    const int upto = check_results(dir, every);
    EXPECT_GE(upto, reported_last);
    if (exited) EXPECT_EQ(upto, n);
  }
}

// A disk that fills up at several points of the run: exit 2 with a message naming the file and
// the cause; the previous complete job.results.json (if one was published) and every complete
// VTU frame survive, and no partial staging file is left.
TEST(DurableResults, FullDiskKeepsTheLastCompleteFiles) {
  const int n = 30, every = 2;
  const std::string deck = stepping_deck(n, every);
  int failures = 0;
  for (const long long budget : {4000LL, 12000LL, 30000LL, 60000LL, 120000LL}) {
    SCOPED_TRACE(fmt::format("disk full after {} bytes", budget));
    JobOptions o;
    o.deck = test::write_deck(deck, "job");
    const auto dir = o.deck.parent_path();
    for (const auto& e : std::filesystem::directory_iterator(dir))
      if (e.path().extension() != ".inp") std::filesystem::remove(e.path());
    o.quiet = true;
    output::testing::limit_writes(budget);
    const JobResult r = run_job(o);
    output::testing::limit_writes(-1);
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
      EXPECT_NE(e.path().extension(), ".tmp") << e.path();
      EXPECT_NE(e.path().extension(), ".a") << e.path(); // the shadows of job.results.json
      EXPECT_NE(e.path().extension(), ".b") << e.path();
    }
    if (r.exit_code == kExitOk) {
      EXPECT_EQ(check_results(dir, every), n);
      continue;
    }
    ++failures;
    EXPECT_EQ(r.exit_code, kExitNoConvergence) << r.error;
    EXPECT_NE(r.error.find("No space left on device"), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("free space and run again"), std::string::npos) << r.error;
    if (std::filesystem::exists(dir / "job.results.json")) check_results(dir, every);
  }
  EXPECT_GE(failures, 3); // the budgets above are smaller than the run's output
}

// The output directory is checked before anything is solved: below a regular file, or full,
// it is an input error (exit 1) naming the directory; a job name cannot leave it.
TEST(DurableResults, OutputDirectoryProblemsAreInputErrors) {
  JobOptions o;
  o.deck = test::write_deck(stepping_deck(4, 1), "job");
  o.quiet = true;
  const auto dir = o.deck.parent_path();
  std::ofstream(dir / "plain") << "x";
  o.output_dir = dir / "plain" / "out";
  JobResult r = run_job(o);
  EXPECT_EQ(r.exit_code, kExitInputError) << r.error;
  EXPECT_NE(r.error.find("plain"), std::string::npos) << r.error;
  o.output_dir = dir / "plain";
  r = run_job(o);
  EXPECT_EQ(r.exit_code, kExitInputError) << r.error;
  EXPECT_NE(r.error.find("not a directory"), std::string::npos) << r.error;

  o.output_dir = dir / "out";
  output::testing::limit_writes(0);
  r = run_job(o);
  output::testing::limit_writes(-1);
  EXPECT_EQ(r.exit_code, kExitInputError) << r.error;
  EXPECT_NE(r.error.find("cannot write into it"), std::string::npos) << r.error;
  EXPECT_TRUE(r.increments.empty()); // nothing was solved

  for (const char* bad : {"../../x", "a/b", "..", "."}) {
    o.job_name = bad;
    r = run_job(o);
    EXPECT_EQ(r.exit_code, kExitInputError) << bad;
    EXPECT_NE(r.error.find("job name"), std::string::npos) << r.error;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / ".." / ".." / "x.dat"));
}

// A deck with a model but no *STEP has nothing to analyse: an input error, not "completed".
TEST(DurableResults, ADeckWithoutAStepIsAnInputError) {
  JobOptions o;
  o.deck = test::write_deck("*HEADING\nno step\n*NODE\n1, 0., 0., 0.\n", "nostep");
  o.quiet = true;
  const JobResult r = run_job(o);
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("no *STEP"), std::string::npos) << r.error;
}
