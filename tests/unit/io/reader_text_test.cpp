// Deck text before any keyword (issue 43): encodings, byte-order marks, NUL and control bytes, line
// ends, lines over the length limit, and the true reason a path cannot be read.
#include "io/inp/deck_text.hpp"
#include "io/inp/fields.hpp"
#include "io/inp/lexer.hpp"
#include "unit/io/reader_test_util.hpp"

#include <unistd.h>

namespace gapfem {
namespace {

namespace fs = std::filesystem;
using namespace std::string_literals;
using test::error_text;
using test::kTrussModel;
using test::read;

/// The truss model with one step: a deck that reads without error.
std::string truss_deck() {
  return std::string(kTrussModel) + "*BOUNDARY\n1, 1, 3\n*STEP\n*STATIC\n*CLOAD\n2, 1, 10.\n"
                                    "*END STEP\n";
}

/// The message of reading the deck file `path` ("" when it reads).
std::string file_error(const fs::path& path) {
  try {
    read_deck(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

int n_lines(const std::string& text) {
  return 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

TEST(ReaderText, PrintableEscapesControlBytesAndBrokenUtf8Only) {
  using inp::printable;
  EXPECT_EQ(printable("1.\0, 2"s), "1.\\x00, 2");
  EXPECT_EQ(printable("a\x1b[31mb"), "a\\x1B[31mb");
  EXPECT_EQ(printable("tab\there\nnext"), "tab\there\nnext");
  EXPECT_EQ(printable("Grüße ✓"), "Grüße ✓"); // valid UTF-8 stays
  EXPECT_EQ(printable("GR\xffOUND"), "GR\\xFFOUND");
  EXPECT_EQ(printable("\xc3"), "\\xC3");                   // a cut sequence
  EXPECT_EQ(printable("\xc0\xaf"), "\\xC0\\xAF");          // overlong
  EXPECT_EQ(printable("\xed\xa0\x80"), "\\xED\\xA0\\x80"); // a surrogate
  EXPECT_EQ(printable("\xc2\x9b"), "\\xC2\\x9B");          // C1 control (CSI)
  EXPECT_EQ(printable("\x7f"), "\\x7F");
  EXPECT_EQ(printable(printable("a\0b"s)), printable("a\0b"s)); // idempotent
}

TEST(ReaderText, ForeignEncodingsAreRecognisedWithAndWithoutByteOrderMark) {
  using inp::foreign_encoding;
  const std::string ascii = "*HEADING\nx\n";
  auto widen = [&](int width, bool little) {
    std::string out;
    for (char c : ascii) {
      std::string unit(static_cast<std::size_t>(width), '\0');
      unit[little ? 0 : width - 1] = c;
      out += unit;
    }
    return out;
  };
  EXPECT_EQ(foreign_encoding(widen(2, true)), "UTF-16 (little-endian)");
  EXPECT_EQ(foreign_encoding(widen(2, false)), "UTF-16 (big-endian)");
  EXPECT_EQ(foreign_encoding(widen(4, true)), "UTF-32 (little-endian)");
  EXPECT_EQ(foreign_encoding(widen(4, false)), "UTF-32 (big-endian)");
  EXPECT_EQ(foreign_encoding("\xff\xfe" + widen(2, true)),
            "UTF-16 (little-endian, with a byte-order mark)");
  EXPECT_EQ(foreign_encoding("\xfe\xff" + widen(2, false)),
            "UTF-16 (big-endian, with a byte-order mark)");
  EXPECT_EQ(foreign_encoding(ascii), "");
  EXPECT_EQ(foreign_encoding("\xef\xbb\xbf" + ascii), "");
  EXPECT_EQ(foreign_encoding("*HEADING\nGrüße\n"), "");
  EXPECT_EQ(foreign_encoding("ab"), ""); // too short to tell
}

TEST(ReaderText, LineEndsOfEveryKindGiveTheSameLines) {
  using inp::split_lines;
  const std::vector<std::string_view> want = {"*NODE", "1, 0.", "", "2, 1."};
  EXPECT_EQ(split_lines("*NODE\n1, 0.\n\n2, 1.\n"), want);
  EXPECT_EQ(split_lines("*NODE\r\n1, 0.\r\n\r\n2, 1.\r\n"), want);
  EXPECT_EQ(split_lines("*NODE\r1, 0.\r\r2, 1.\r"), want); // classic Mac OS
  EXPECT_EQ(split_lines("*NODE\r1, 0.\n\r\n2, 1."), want); // mixed, no final line end
  EXPECT_EQ(split_lines("a  \t\nb"), (std::vector<std::string_view>{"a", "b"}));
}

TEST(ReaderText, AUtf8ByteOrderMarkIsSkippedInDecksIncludesAndDataFiles) {
  const std::string bom = "\xef\xbb\xbf";
  // directly before the first keyword (no heading): no "data line before the first keyword"
  EXPECT_EQ(read(bom + truss_deck()).mesh.n_nodes(), 2);
  const fs::path dir = test::fresh_dir();
  test::write_file(dir / "nodes.inp", bom + "1, 0., 0., 0.\n2, 1., 0., 0.\n");
  test::write_file(dir / "load.inp", bom + "*CLOAD\n2, 1, 10.\n");
  std::string deck = truss_deck();
  deck.replace(0, deck.find("*ELEMENT"), "*NODE, NSET=ALL, INPUT=nodes.inp\n");
  deck.replace(deck.find("*CLOAD\n2, 1, 10.\n"), 17, "*INCLUDE, INPUT=load.inp\n");
  test::write_file(dir / "deck.inp", deck);
  EXPECT_EQ(file_error(dir / "deck.inp"), "");
  EXPECT_EQ(read_deck(dir / "deck.inp").steps.at(0).cloads.size(), 1u);
}

TEST(ReaderText, ClassicMacLineEndsReadAsLines) {
  std::string deck = truss_deck();
  std::replace(deck.begin(), deck.end(), '\n', '\r');
  EXPECT_EQ(read(deck).mesh.n_nodes(), 2);
  deck.replace(deck.find("200000."), 7, "2x0000.");
  EXPECT_CONTAINS(error_text(deck), "deck.inp:8: *ELASTIC: field 1");
}

TEST(ReaderText, AUtf16DeckIsOneMessageNamingTheEncoding) {
  std::string utf16;
  for (char c : truss_deck()) utf16 += std::string{c, '\0'};
  for (const std::string& deck : {utf16, "\xff\xfe" + utf16}) {
    const std::string e = error_text(deck);
    EXPECT_CONTAINS(e, "deck.inp: the deck is UTF-16 (little-endian");
    EXPECT_CONTAINS(e, "save it as ASCII or UTF-8");
    EXPECT_EQ(n_lines(e), 1) << e;
  }
}

TEST(ReaderText, AnIncludedFileInUtf16IsOneMessageAtTheInclude) {
  const fs::path dir = test::fresh_dir();
  std::string utf16 = "\xff\xfe";
  for (char c : "*CLOAD\n2, 1, 10.\n"s) utf16 += std::string{c, '\0'};
  test::write_file(dir / "load.inp", utf16);
  std::string deck = truss_deck();
  deck.replace(deck.find("*CLOAD\n2, 1, 10.\n"), 17, "*INCLUDE, INPUT=load.inp\n");
  test::write_file(dir / "deck.inp", deck);
  const std::string e = file_error(dir / "deck.inp");
  EXPECT_CONTAINS(e, "deck.inp:15: *INCLUDE: INPUT=load.inp: file 'load.inp' is UTF-16");
  EXPECT_EQ(n_lines(e), 1) << e;
}

TEST(ReaderText, ANulByteIsOneMessageWithTheBytesShownAndNoFollowOn) {
  // in a number: the node is a failed definition, so its element raises nothing more
  std::string deck = truss_deck();
  deck.replace(deck.find("2, 1., 0., 0."), 13, "2, 1.\0, 0., 0."s);
  std::string e = error_text(deck);
  EXPECT_CONTAINS(e, "deck.inp:3: the line holds a NUL byte (shown as \\x00)");
  EXPECT_CONTAINS(e, "'2, 1.\\x00, 0., 0.'");
  EXPECT_EQ(n_lines(e), 1) << e;
  // in a keyword name: the names the line defines are noted as failed, so their uses are quiet
  deck = truss_deck();
  deck.replace(deck.find("*ELEMENT"), 8, "*ELE\0MENT"s);
  e = error_text(deck);
  EXPECT_CONTAINS(e, "'*ELE\\x00MENT, TYPE=T3D2, ELSET=TRUSS'");
  EXPECT_EQ(n_lines(e), 1) << e;
  // on many lines: a binary file, one message
  e = error_text(std::string(100, '\0') + "\n\0\n\0\n\0\n"s + truss_deck());
  EXPECT_CONTAINS(e,
                  "holds binary data, not text: 4 of its lines hold NUL bytes, the first line 1");
  EXPECT_EQ(n_lines(e), 1) << e;
}

TEST(ReaderText, ALineOverTheLimitDefinesNothingThatIsReportedAgain) {
  const std::string pad(inp::kMaxLineLength, ' ');
  // a node line: the element and the load on that node stay quiet
  std::string deck = truss_deck();
  deck.replace(deck.find("2, 1., 0., 0."), 13, "2, 1.," + pad + "0., 0.");
  std::string e = error_text(deck);
  EXPECT_CONTAINS(e, "deck.inp:3: the line is");
  EXPECT_EQ(n_lines(e), 1) << e;
  // an element line: its set's section and the element's uses stay quiet
  deck = truss_deck() + "*STEP\n*STATIC\n*EL PRINT, ELSET=TRUSS\nS\n*END STEP\n";
  deck.replace(deck.find("1, 1, 2\n"), 7, "1," + pad + "1, 2");
  e = error_text(deck);
  EXPECT_EQ(n_lines(e), 1) << e;
  // a keyword line continued on a line over the limit: the keyword's names are noted
  deck = truss_deck();
  deck.replace(deck.find("*ELEMENT, TYPE=T3D2, ELSET=TRUSS"), 32,
               "*ELEMENT, TYPE=T3D2,\nELSET=" + pad + "TRUSS");
  e = error_text(deck);
  EXPECT_CONTAINS(e, "deck.inp:5: the line is");
  EXPECT_EQ(n_lines(e), 1) << e;
}

TEST(ReaderText, APathThatCannotBeReadGetsItsTrueReason) {
  const fs::path dir = test::fresh_dir();
  ASSERT_EQ(::symlink("loop.inp", (dir / "loop.inp").c_str()), 0);
  ASSERT_EQ(::symlink("gone.inp", (dir / "dangling.inp").c_str()), 0);
  test::write_file(dir / "file.inp", truss_deck());
  EXPECT_CONTAINS(file_error(dir / "loop.inp"), "cannot read the input deck: it is a symbolic "
                                                "link loop");
  EXPECT_CONTAINS(file_error(dir / "dangling.inp"), "it is a symbolic link to 'gone.inp', which "
                                                    "does not exist");
  EXPECT_CONTAINS(file_error(dir / "file.inp" / "x.inp"), "a part of its path is a file");
  EXPECT_CONTAINS(file_error(dir / "none.inp"), "it does not exist");
  // the same reasons for *INCLUDE and INPUT= files, at the line that names them
  std::string deck = truss_deck();
  deck.replace(deck.find("*CLOAD\n2, 1, 10.\n"), 17, "*INCLUDE, INPUT=loop.inp\n");
  test::write_file(dir / "include.inp", deck);
  EXPECT_CONTAINS(file_error(dir / "include.inp"),
                  "include.inp:15: *INCLUDE: INPUT=loop.inp: cannot read file");
  EXPECT_CONTAINS(file_error(dir / "include.inp"), "symbolic link loop");
  deck = truss_deck();
  deck.replace(0, deck.find("*ELEMENT"), "*NODE, NSET=ALL, INPUT=dangling.inp\n");
  test::write_file(dir / "input.inp", deck);
  EXPECT_CONTAINS(file_error(dir / "input.inp"), "symbolic link to 'gone.inp'");
}

TEST(ReaderText, MessagesQuoteDeckTextPrintably) {
  std::string deck = truss_deck();
  deck.replace(deck.find("200000."), 7, "2e5\x1b[2J");
  EXPECT_CONTAINS(error_text(deck), "'2e5\\x1B[2J' is not a number");
  deck = truss_deck();
  deck.replace(deck.find("1, 1, 3"), 1, "N\xff");
  EXPECT_CONTAINS(error_text(deck), "node set N\\xFF: this node set is not defined");
}

TEST(ReaderText, ARealBeyondTheDoubleRangeIsOutOfRange) {
  std::string deck = truss_deck();
  deck.replace(deck.find("200000."), 7, "1e400");
  EXPECT_CONTAINS(error_text(deck), "'1e400' is out of range (larger than 1.8E308");
  deck = truss_deck();
  deck.replace(deck.find("*STATIC"), 7, "*STATIC, STABILIZE=-1e999");
  EXPECT_CONTAINS(error_text(deck), "STABILIZE=-1e999: the value is out of range");
  EXPECT_FALSE(inp::real_out_of_range("1e300"));
  EXPECT_FALSE(inp::real_out_of_range("x"));
  EXPECT_TRUE(inp::real_out_of_range("-1.0D400"));
}

} // namespace
} // namespace gapfem
