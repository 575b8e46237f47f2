// What the reader refuses instead of exhausting the machine or guessing: decks and include files
// that are not regular files (directories, FIFOs, devices), empty decks, lines and decks beyond
// the limits, include cycles; and the false follow-on errors it must not add after a real one.
#include "io/inp/lexer.hpp"
#include "unit/io/reader_test_util.hpp"

#include <sys/stat.h>

namespace gapfem {
namespace {

/// The message of the InputError reading `path` throws ("" when it reads).
std::string read_error(const std::filesystem::path& path) {
  try {
    read_deck(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// Number of lines of a (multi-error) message.
int n_lines(const std::string& text) {
  return 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

TEST(ReaderLimits, SpecialFilesAreRefusedBeforeTheyAreOpened) {
  const auto dir = test::fresh_dir();
  EXPECT_CONTAINS(read_error(dir), "is a directory");
  EXPECT_CONTAINS(read_error("/dev/null"), "not a regular file");
  EXPECT_CONTAINS(read_error("/dev/zero"), "not a regular file");
  const auto fifo = dir / "fifo.inp";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_CONTAINS(read_error(fifo), "not a regular file"); // opening it would block forever
}

TEST(ReaderLimits, IncludedSpecialFilesNameTheIncludingLine) {
  const auto dir = test::fresh_dir();
  std::filesystem::create_directories(dir / "sub");
  test::write_file(dir / "a.inp", "*HEADING\nx\n*INCLUDE, INPUT=sub\n");
  std::string e = read_error(dir / "a.inp");
  EXPECT_CONTAINS(e, "a.inp:3");
  EXPECT_CONTAINS(e, "INPUT=sub");
  EXPECT_CONTAINS(e, "is a directory");
  test::write_file(dir / "b.inp", "*HEADING\nx\n*NODE, INPUT=/dev/zero\n");
  e = read_error(dir / "b.inp");
  EXPECT_CONTAINS(e, "b.inp:3");
  EXPECT_CONTAINS(e, "not a regular file");
}

TEST(ReaderLimits, EmptyAndCommentOnlyDecksAreErrors) {
  const auto dir = test::fresh_dir();
  test::write_file(dir / "empty.inp", "");
  EXPECT_CONTAINS(read_error(dir / "empty.inp"), "no keyword lines");
  test::write_file(dir / "comments.inp", "** just\n**  comments\n\n");
  EXPECT_CONTAINS(read_error(dir / "comments.inp"), "no keyword lines");
}

TEST(ReaderLimits, ALineLongerThanTheLimitIsOneErrorAtItsLine) {
  const auto dir = test::fresh_dir();
  std::string deck = std::string("*HEADING\n") + std::string(inp::kMaxLineLength + 1, 'h') +
                     "\n*NODE\n1, 0., 0., 0.\n";
  test::write_file(dir / "long.inp", deck);
  const std::string e = read_error(dir / "long.inp");
  EXPECT_CONTAINS(e, "long.inp:2");
  EXPECT_CONTAINS(e, fmt::format("{} characters long", inp::kMaxLineLength + 1));
  EXPECT_EQ(n_lines(e), 1) << e;
  // a line of exactly the limit is read
  deck = std::string("*HEADING\n") + std::string(inp::kMaxLineLength, 'h') + "\n";
  test::write_file(dir / "ok.inp", deck);
  EXPECT_EQ(read_error(dir / "ok.inp"), "");
}

TEST(ReaderLimits, AKeywordLineTooLongDropsItsDataLinesWithoutFurtherErrors) {
  const auto dir = test::fresh_dir();
  const std::string deck = std::string("*HEADING\nx\n*NODE, ") +
                           std::string(inp::kMaxLineLength, 'N') + "\n1, 0., 0., 0.\n2, 1.\n";
  test::write_file(dir / "kw.inp", deck);
  const std::string e = read_error(dir / "kw.inp");
  EXPECT_CONTAINS(e, "kw.inp:3");
  EXPECT_EQ(n_lines(e), 1) << e; // no "data line for *HEADING" about lines 4 and 5
}

TEST(ReaderLimits, AHugeHeadingIsKeptShortInTheModel) {
  std::string deck = "*HEADING\n";
  for (int i = 0; i < 200; ++i) deck += std::string(1000, 'a' + i % 26) + "\n";
  const Model m = test::read(deck + "*NODE\n1, 0., 0., 0.\n");
  EXPECT_LE(m.heading.size(), 4096u);
  EXPECT_EQ(test::count_warnings(m, "the result files keep its first 4096"), 1);
}

TEST(ReaderLimits, AnIncludeCycleIsNamedOnce) {
  const auto dir = test::fresh_dir();
  test::write_file(dir / "main.inp", "*HEADING\nx\n*INCLUDE, INPUT=a.inp\n");
  test::write_file(dir / "a.inp", "*NODE\n1, 0., 0., 0.\n*INCLUDE, INPUT=b.inp\n");
  test::write_file(dir / "b.inp", "*NODE\n2, 1., 0., 0.\n*INCLUDE, INPUT=a.inp\n");
  const std::string e = read_error(dir / "main.inp");
  EXPECT_CONTAINS(e, "b.inp:3");
  EXPECT_CONTAINS(e, "the include files form a cycle");
  EXPECT_CONTAINS(e, "a.inp includes");
  EXPECT_CONTAINS(e, "b.inp includes");
  EXPECT_EQ(n_lines(e), 1) << e; // no "node 1 defined twice" from reading a.inp again
  // the same file included twice in a row is no cycle
  test::write_file(dir / "twice.inp",
                   "*HEADING\nx\n*INCLUDE, INPUT=n.inp\n*INCLUDE, INPUT=n.inp\n");
  test::write_file(dir / "n.inp", "** nothing but a comment\n");
  EXPECT_EQ(read_error(dir / "twice.inp"), "");
}

// A data line in error is the only error about it: the block it belongs to is not reported again
// as missing, and the model-wide checks (elements without a section, materials without
// *ELASTIC) do not run on a deck whose keyword blocks are in error.
TEST(ReaderLimits, NoFalseFollowOnErrors) {
  const std::string model = R"(*HEADING
x
*NODE
1, 0., 0., 0.
2, 1., 0., 0.
*ELEMENT, TYPE=T3D2, ELSET=BAR
1, 1, 2
*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL
1.
*MATERIAL, NAME=STEEL
*ELASTIC
)";
  std::string e = test::error_text(model + "2.1e11x, 0.3\n");
  EXPECT_CONTAINS(e, "2.1e11x");
  EXPECT_EQ(n_lines(e), 1) << e;
  const std::string gap = model + R"(2.1e11, 0.3
*ELEMENT, TYPE=GAPUNI, ELSET=G
2, 1, 2
*GAP, ELSET=G
0.1, 1., 0., zero
)";
  e = test::error_text(gap);
  EXPECT_CONTAINS(e, "zero");
  EXPECT_EQ(n_lines(e), 1) << e; // not "this element has no section"
  e = test::error_text(model + R"(2.1e11, 0.3
*ELEMENT, TYPE=GAPUNI, ELSET=G
2, 1, 2
*GAP, ELSET=G
0.1, 1., 0., 0., 1.
*FRICTION
-0.3
)");
  EXPECT_CONTAINS(e, "-0.3");
  EXPECT_EQ(n_lines(e), 1) << e; // not "the friction coefficient is missing"
}

} // namespace
} // namespace gapfem
