// Runs at the edges of the machine (issue 43): loads near the double range never end in success
// over non-finite results, and their self-checks do not overflow; an address-space limit ends a
// run promptly with a message instead of hanging in the BLAS.
#include "test_util.hpp"

#include <chrono>
#include <cmath>
#include <gtest/gtest.h>
#include <regex>

using namespace gapfem;
using namespace gapfem::test;
namespace fs = std::filesystem;

namespace {

/// The simply supported S4R plate of the verification suite under pressure `p`.
std::string plate(const std::string& p) {
  std::string deck =
      slurp(fs::path(GAPFEM_TEST_DIR) / "verification/structural/shell_plate_ss.inp");
  const std::string from = "PLATE, P, 1.0\n";
  const std::size_t at = deck.find(from);
  EXPECT_NE(at, std::string::npos) << "the plate deck changed";
  return deck.replace(at, from.size(), "PLATE, P, " + p + "\n");
}

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

} // namespace

// P = 1e308: the recovered section forces overflow. The run stops with exit 2 naming where, and
// writes no frame of the overflowed increment; job.results.json stays valid with no frame.
TEST(NonFiniteResults, AnOverflowStopsTheRunNamingWhereItAppeared) {
  const JobResult r = run_deck(plate("1e308"), true);
  EXPECT_EQ(r.exit_code, 2) << r.error;
  EXPECT_NE(r.error.find("increment 1: the results hold a number that is not finite"),
            std::string::npos)
      << r.error;
  EXPECT_TRUE(std::regex_search(r.error, std::regex("of element [0-9]+ \\(S4R\\)"))) << r.error;
  EXPECT_NE(r.error.find("check their magnitudes and units"), std::string::npos) << r.error;
  EXPECT_TRUE(r.frames.empty());
  const std::string sta = slurp(test_dir() / "job.sta");
  EXPECT_EQ(sta.find("COMPLETED SUCCESSFULLY"), std::string::npos) << sta;
}

// P = 1e200: every number is finite; the balance is exact, and its check (sums of 1e199 forces,
// whose squares overflow a double) reads a small relative error, not INF.
TEST(NonFiniteResults, LargeFiniteLoadsGiveAFiniteSelfCheck) {
  const JobResult r = run_deck(plate("1e200"), true);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const StepChecks& c = r.steps.back().checks;
  EXPECT_TRUE(std::isfinite(c.equilibrium_error));
  EXPECT_TRUE(std::isfinite(c.force_scale));
  EXPECT_GT(c.force_scale, 1e199);
  EXPECT_LT(c.relative_equilibrium, 1e-9);
  const std::string dat = slurp(test_dir() / "job.dat");
  EXPECT_EQ(dat.find("INF"), std::string::npos);
  EXPECT_EQ(dat.find("NAN"), std::string::npos);
}

// ulimit -v: a limit that leaves no room for OpenBLAS's work buffer stops at once (exit 2, the
// limit to set); one that leaves room runs (before: both hung in OpenBLAS's buffer mapping).
TEST(MemoryLimits, AnAddressSpaceLimitEndsTheRunPromptly) {
  if (kAddressSanitizer)
    GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space, so a ulimit -v run "
                    "cannot start under it; the release suite runs this test";
  const fs::path deck = write_deck(plate("1.0"));
  const fs::path dir = deck.parent_path();
  auto run = [&](int kib) {
    const std::string cmd = "cd '" + dir.string() + "' && (ulimit -v " + std::to_string(kib) +
                            "; timeout -s KILL 60 '" + GAPFEM_EXE +
                            "' -q --no-vtu -o out job.inp) > limit.log 2>&1";
    const auto t0 = std::chrono::steady_clock::now();
    const int rc = std::system(cmd.c_str());
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return std::make_pair(WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, s);
  };
  // find a limit with too little room: the message names it (loading alone needs ~150 MiB)
  const auto [tight, tight_s] = run(260000);
  const std::string log = slurp(dir / "limit.log");
  if (tight == 127) GTEST_SKIP() << "the libraries do not load under 260000 KiB here: " << log;
  EXPECT_EQ(tight, 2) << log;
  EXPECT_NE(log.find("address-space limit (ulimit -v 260000 KiB)"), std::string::npos) << log;
  EXPECT_LT(tight_s, 30.0);
  const auto [room, room_s] = run(2000000);
  EXPECT_EQ(room, 0) << slurp(dir / "limit.log");
  EXPECT_LT(room_s, 30.0);
}
