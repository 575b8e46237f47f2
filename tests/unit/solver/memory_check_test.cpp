// A model whose factor cannot fit in the memory left stops before anything is factorised, with a
// message that gives the size CHOLMOD's symbolic analysis predicts and what to do, and the results
// of the steps before (GAPFEM_MEMORY_LIMIT stands in for a small machine).
#include "common/memory.hpp"
#include "test_util.hpp"

#include <cstdlib>
#include <fmt/format.h>

using namespace gapfem;
using namespace gapfem::test;

namespace {

/// Two steps of a bar of 400 trusses: in step 1 every node but the last is held (1 equation),
/// in step 2 only the first (400 equations).
std::string deck() {
  std::string d = "*HEADING\nmemory\n*NODE, NSET=ALL\n";
  for (int i = 0; i <= 400; ++i) d += fmt::format("{}, {}., 0., 0.\n", i + 1, i);
  d += "*NSET, NSET=HELD, GENERATE\n1, 400, 1\n*ELEMENT, TYPE=T3D2, ELSET=BAR\n";
  for (int i = 1; i <= 400; ++i) d += fmt::format("{}, {}, {}\n", i, i, i + 1);
  d += "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*SOLID SECTION, ELSET=BAR, MATERIAL=M\n1.\n";
  d += "*BOUNDARY\nALL, 2, 3\n*STEP\n*STATIC\n*BOUNDARY\nHELD, 1, 1\n*CLOAD\n401, 1, 1.\n"
       "*END STEP\n*STEP\n*STATIC\n*BOUNDARY, OP=NEW\nALL, 2, 3\n1, 1, 1\n*END STEP\n";
  return d;
}

} // namespace

TEST(MemoryCheck, AFactorThatCannotFitStopsBeforeFactorising) {
  ASSERT_TRUE(available_memory_bytes().has_value()); // /proc/meminfo is there on Linux
  // room for step 1's factor (one equation) but not for step 2's (400)
  ::setenv("GAPFEM_MEMORY_LIMIT", "1000", 1);
  const JobResult r = run_deck(deck(), true);
  ::unsetenv("GAPFEM_MEMORY_LIMIT");
  EXPECT_EQ(r.exit_code, kExitNoConvergence);
  EXPECT_NE(r.error.find("step 2: the factor of this step's 400 equations needs about"),
            std::string::npos)
      << r.error;
  EXPECT_NE(r.error.find("KiB of memory are available; nothing was factorised"), std::string::npos)
      << r.error;
  ASSERT_EQ(r.steps.size(), 2u);
  EXPECT_TRUE(r.steps[0].converged); // step 1 and its results are there
  EXPECT_NEAR(U(r, last_frame(r, 1), 401)[0], 1e-3, 1e-15);
  // the results files are complete documents that say why the run stopped
  const std::string json = slurp(test_dir() / "job.results.json");
  EXPECT_NE(json.find("\"completed\":false"), std::string::npos);
  EXPECT_NE(json.find("nothing was factorised"), std::string::npos);
  // with the memory there, the same deck runs
  EXPECT_EQ(run_deck(deck()).exit_code, 0);
}
