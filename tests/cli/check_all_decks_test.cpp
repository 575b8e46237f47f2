// `gapfem check` on every deck of the repository: the verification and regression decks under
// tests/ pass it, and every deck of the bad-input corpus fails it with exit 1 and the same message
// the analysis gives (its .expected line), so datacheck finds what a run would, before solving.
// (The examples are checked in tests/regression/examples_test.cpp.)
#include "app/check.hpp"
#include "test_util.hpp"

#include <algorithm>
#include <sstream>

namespace gapfem {
namespace {

using gapfem::test::slurp;

namespace fs = std::filesystem;

TEST(CheckEveryDeck, TestDecksPass) {
  int decks = 0;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(GAPFEM_TEST_DIR))) {
    if (e.path().extension() != ".inp" ||
        e.path().string().find("/bad_input/") != std::string::npos)
      continue;
    JobOptions o;
    o.deck = e.path();
    o.quiet = true;
    const CheckResult c = check_job(o);
    EXPECT_EQ(c.exit_code, kExitOk) << e.path() << ": " << c.error;
    EXPECT_NE(c.summary.find("step 1"), std::string::npos) << e.path() << "\n" << c.summary;
    ++decks;
  }
  EXPECT_GE(decks, 29);
}

TEST(CheckEveryDeck, BadInputDecksFailWithTheMessageOfARun) {
  const fs::path corpus = fs::path(GAPFEM_TEST_DIR) / "bad_input";
  std::vector<fs::path> decks;
  for (const auto& e : fs::directory_iterator(corpus))
    if (e.path().extension() == ".inp") decks.push_back(e.path());
  std::sort(decks.begin(), decks.end());
  const fs::path cwd = fs::current_path();
  fs::current_path(corpus); // the expected messages name the deck relative to the corpus
  for (const fs::path& deck : decks) {
    SCOPED_TRACE(deck.filename().string());
    JobOptions o;
    o.deck = deck.filename();
    o.quiet = true;
    const CheckResult c = check_job(o);
    EXPECT_EQ(c.exit_code, kExitInputError);
    std::string expected = slurp(fs::path(deck).replace_extension(".expected"));
    if (expected.rfind("error: ", 0) == 0) expected.erase(0, 7);
    while (!expected.empty() && expected.back() == '\n') expected.pop_back();
    EXPECT_EQ(c.error, expected);
  }
  fs::current_path(cwd);
}

} // namespace
} // namespace gapfem
