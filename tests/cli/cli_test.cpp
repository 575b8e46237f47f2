// The gapfem executable: exit statuses (0 success, 1 input error, 2 no convergence), the files it
// writes, --ignore-unknown, and the sentences users see.
#include "test_util.hpp"

#include <cstdio>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

using namespace gapfem::test;

namespace {

struct CliRun {
  int status = -1;
  std::string output;
};

CliRun run_cli(const std::filesystem::path& deck, const std::string& args = "") {
  const auto log = deck.parent_path() / "cli.log";
  const std::string cmd = std::string("'") + GAPFEM_EXE + "' " + args + " '" + deck.string() +
                          "' > '" + log.string() + "' 2>&1";
  const int rc = std::system(cmd.c_str());
  CliRun r;
  r.status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  std::ifstream in(log);
  std::stringstream ss;
  ss << in.rdbuf();
  r.output = ss.str();
  return r;
}

const std::string kGood = std::string("*HEADING\nspring and gap\n") + kSpringOnGapModel + R"(*STEP
*STATIC
*CLOAD
10, 2, -100.
*NODE PRINT
U
*END STEP
)";

} // namespace

TEST(Cli, SuccessWritesAllResultFiles) {
  const auto deck = write_deck(kGood, "good");
  const CliRun r = run_cli(deck);
  EXPECT_EQ(r.status, 0) << r.output;
  for (const char* ext : {".dat", ".sta", ".results.json", ".pvd"})
    EXPECT_TRUE(std::filesystem::exists(deck.parent_path() / (std::string("good") + ext))) << ext;
  EXPECT_NE(r.output.find("Analysis completed"), std::string::npos) << r.output;
}

// `gapfem good` (no extension, as `abaqus job=good` or `ccx -i good`) runs good.inp; a name that
// is neither a file nor one with .inp added is an error naming it.
TEST(Cli, DeckWithoutExtensionReadsTheInpFile) {
  const auto deck = write_deck(kGood, "good");
  std::filesystem::remove(deck.parent_path() / "good.dat");
  const CliRun r = run_cli(deck.parent_path() / "good");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(deck.parent_path() / "good.dat"));
  const CliRun missing = run_cli(deck.parent_path() / "nosuchjob");
  EXPECT_EQ(missing.status, 1) << missing.output;
  EXPECT_NE(missing.output.find("nosuchjob"), std::string::npos) << missing.output;
}

// A warning found while solving (a boundary condition on DOF 11 of a node that has only
// displacements) is a warning like the deck's: in job.dat, in the JSON and in the terminal's
// count, and silent with -q.
TEST(Cli, SolverWarningsReachEveryResultsFileAndObeyQuiet) {
  std::string deck = kGood;
  deck.replace(deck.find("*STATIC\n"), 8, "*STATIC\n*BOUNDARY\n10, 11, 11, 5.\n");
  const auto path = write_deck(deck, "warned");
  const CliRun loud = run_cli(path);
  EXPECT_EQ(loud.status, 0) << loud.output;
  EXPECT_NE(loud.output.find("1 warning(s)"), std::string::npos) << loud.output;
  EXPECT_NE(loud.output.find("refer to DOFs that no element at the node has"), std::string::npos);
  auto text = [&](const char* ext) {
    std::ifstream in(path.parent_path() / (std::string("warned") + ext));
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  };
  EXPECT_NE(text(".dat").find("refer to DOFs that no element"), std::string::npos);
  EXPECT_NE(text(".results.json").find("refer to DOFs that no element"), std::string::npos);
  const CliRun quiet = run_cli(path, "-q");
  EXPECT_EQ(quiet.status, 0) << quiet.output;
  EXPECT_EQ(quiet.output.find("refer to DOFs"), std::string::npos) << quiet.output;
}

// `gapfem check` validates without solving: a summary (elements by type, gaps with their status
// at the start, each step's equations and factor size), exit 0, no results files; errors found
// only when a step is set up (a load on a DOF no element has) still make it exit 1.
TEST(Cli, CheckSummarisesWithoutSolving) {
  const auto deck = write_deck(kGood, "checked");
  const CliRun r = run_cli(deck, "check");
  EXPECT_EQ(r.status, 0) << r.output;
  for (const char* want : {"nodes 2, elements 2: GAPUNI 1, SPRING1 1",
                           "gaps 1, status at the start: "
                           "GAPUNI 1 (1 open, 0 closed)",
                           "steps 1", "step 1 Step-1 (STATIC): 1 equations", "factor of K about",
                           "nothing was solved"})
    EXPECT_NE(r.output.find(want), std::string::npos) << want << "\n" << r.output;
  EXPECT_FALSE(std::filesystem::exists(deck.parent_path() / "checked.dat"));
  std::string bad = kGood;
  bad.replace(bad.find("10, 2, -100."), 12, "10, 5, -100.");
  const CliRun e = run_cli(write_deck(bad, "checkbad"), "check");
  EXPECT_EQ(e.status, 1) << e.output;
  EXPECT_NE(e.output.find("DOF 5"), std::string::npos) << e.output;
}

TEST(Cli, InputErrorExitsWithOneBeforeSolving) {
  std::string text = kGood;
  text.replace(text.find("101, 10, 12"), 11, "101, 10, 99");
  const auto deck = write_deck(text, "bad");
  const CliRun r = run_cli(deck);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("bad.inp:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("node 99"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(deck.parent_path() / "bad.sta"));
}

TEST(Cli, UnknownKeywordIsAnErrorUnlessIgnored) {
  // a definition gapfem never uses: an error, skipped with a warning under --ignore-unknown
  std::string text = kGood;
  text.insert(text.find("*BOUNDARY"), "*NODE RESPONSE, NAME=R1\n");
  const auto deck = write_deck(text, "unknown");
  const CliRun strict = run_cli(deck);
  EXPECT_EQ(strict.status, 1);
  EXPECT_NE(strict.output.find("*NODE RESPONSE"), std::string::npos) << strict.output;
  const CliRun lenient = run_cli(deck, "--ignore-unknown");
  EXPECT_EQ(lenient.status, 0) << lenient.output;
  EXPECT_NE(lenient.output.find("*NODE RESPONSE"), std::string::npos) << "listed as a warning";
  // an output keyword gapfem lacks never stops a run
  text = kGood;
  text.insert(text.find("*BOUNDARY"), "*INTEGRATED OUTPUT SECTION, NAME=IOS1, SURFACE=S1\n");
  const CliRun output = run_cli(write_deck(text, "output"));
  EXPECT_EQ(output.status, 0) << output.output;
  EXPECT_NE(output.output.find("*INTEGRATED OUTPUT SECTION"), std::string::npos)
      << "listed as a warning";
}

TEST(Cli, UnconstrainedModelStopsWithTheNodesAndDofs) {
  // a truss with only one node fixed in x: free to move in y and z
  const auto deck = write_deck(R"(*NODE
1, 0., 0., 0.
2, 1., 0., 0.
*ELEMENT, TYPE=T3D2, ELSET=BAR
1, 1, 2
*MATERIAL, NAME=STEEL
*ELASTIC
2.E5, 0.3
*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL
1.
*BOUNDARY
1, 1, 1
*STEP
*STATIC
*CLOAD
2, 1, 10.
*END STEP
)",
                               "free");
  const CliRun r = run_cli(deck);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("singular"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("node "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("DOF"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("*BOUNDARY"), std::string::npos) << "the remedy is named";
  EXPECT_TRUE(std::filesystem::exists(deck.parent_path() / "free.sta"));
}

TEST(Cli, NoConvergenceExitsWithTwoAndKeepsResults) {
  // the minimum increment is reached: a DIRECT step whose contact needs more than one iteration
  // limit (INC=1 with two increments needed)
  std::string text = kGood;
  text.replace(text.find("*STEP\n*STATIC\n"), 14, "*STEP, INC=1\n*STATIC\n0.5, 1.\n");
  const auto deck = write_deck(text, "stops");
  const CliRun r = run_cli(deck);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("INC"), std::string::npos) << r.output;
  EXPECT_TRUE(std::filesystem::exists(deck.parent_path() / "stops.results.json"));
}
