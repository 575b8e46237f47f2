// The bad-input corpus (tests/bad_input/, README there): every deck holds one mistake and gapfem
// must reject it with exit status 1 and exactly the one line of its .expected file (file:line,
// keyword, the label or value at fault, what to do) — no crash, no follow-on error.
#include "test_util.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

namespace {

using gapfem::test::slurp;

namespace fs = std::filesystem;

} // namespace

TEST(BadInput, EveryDeckOfTheCorpusGivesItsOneLineMessage) {
  const fs::path corpus = fs::path(GAPFEM_TEST_DIR) / "bad_input";
  std::vector<fs::path> decks;
  for (const auto& e : fs::directory_iterator(corpus))
    if (e.path().extension() == ".inp") decks.push_back(e.path());
  std::sort(decks.begin(), decks.end());
  EXPECT_GE(decks.size(), 80u);
  const fs::path out = gapfem::test::test_dir();
  for (const fs::path& deck : decks) {
    SCOPED_TRACE(deck.filename().string());
    const fs::path expected_file = fs::path(deck).replace_extension(".expected");
    ASSERT_TRUE(fs::exists(expected_file)) << "no " << expected_file.filename();
    const fs::path log = out / (deck.stem().string() + ".log");
    const std::string cmd = "cd '" + corpus.string() + "' && '" + GAPFEM_EXE +
                            "' -q --no-vtu -o '" + out.string() + "' '" + deck.filename().string() +
                            "' > /dev/null 2> '" + log.string() + "'";
    const int rc = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(rc)) << "gapfem did not exit normally";
    const std::string got = slurp(log);
    EXPECT_EQ(WEXITSTATUS(rc), 1) << got;
    EXPECT_EQ(got, slurp(expected_file));
    EXPECT_EQ(std::count(got.begin(), got.end(), '\n'), 1) << got;
  }
}
