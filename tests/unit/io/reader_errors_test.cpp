// How input errors are reported: collected over the whole deck, one per line, capped, with file,
// line, keyword and the offending label in each.
#include "unit/io/reader_test_util.hpp"

#include <algorithm>

namespace gapfem {
namespace {

using test::read_error;

TEST(ReaderErrors, MessageNamesFileLineKeywordAndLabel) {
  // 16 lines of nodes and comments, then the element on line 17 of beam.inp
  std::string deck = "*NODE\n";
  for (int i = 1; i <= 14; ++i) deck += std::to_string(i) + ", " + std::to_string(i) + ".\n";
  deck += "*ELEMENT, TYPE=B31, ELSET=B\n12, 1, 99\n";
  const InputError e = read_error(deck, {}, "beam.inp");
  EXPECT_STREQ(e.what(),
               "beam.inp:17: *ELEMENT: element 12: node 99 is not defined; define it with *NODE");
  EXPECT_EQ(e.location().file, "beam.inp");
  EXPECT_EQ(e.location().line, 17);
  EXPECT_EQ(e.location().keyword, "*ELEMENT");
  EXPECT_EQ(e.entity(), "element 12");
}

TEST(ReaderErrors, AllProblemsAreListedOnePerLine) {
  const InputError e = read_error(R"(*NODE
1, 0, 0, 0
2, x
*ELEMENT, TYPE=T3D2, ELSET=T
5, 1, 77
*MATERIAL, NAME=M
*ELASTIC
0., 0.3
*STEP
*STATIC
*CLOAD
1, 9, 1.
*END STEP
)");
  const std::string text = e.what();
  EXPECT_CONTAINS(text, "the deck has 4 input errors");
  EXPECT_CONTAINS(text, "\ndeck.inp:3: *NODE: field 2 (x)");
  EXPECT_CONTAINS(text, "\ndeck.inp:5: *ELEMENT: element 5: node 77 is not defined");
  EXPECT_CONTAINS(text, "\ndeck.inp:8: *ELASTIC: Young's modulus must be positive");
  EXPECT_CONTAINS(text, "\ndeck.inp:12: *CLOAD: field 2 (DOF)");
  // the failed node and element raise no follow-up errors (no "no section" for element 5)
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 4) << text;
  // location() is the first problem's
  EXPECT_EQ(e.location().line, 3);
  EXPECT_EQ(e.location().keyword, "*NODE");
}

// The sub-options of an unsupported block keyword belong to it: one error for *SURFACE
// INTERACTION, none for its *FRICTION and *SURFACE BEHAVIOR, which never attach to the *GAP
// before it.
TEST(ReaderErrors, SubOptionsOfAnUnsupportedBlockRaiseNoFollowOnErrors) {
  const InputError e = read_error(R"(*NODE
1, 0, 0, 0
2, 1, 0, 0
*ELEMENT, TYPE=GAPUNI, ELSET=G
1, 1, 2
*GAP, ELSET=G
0.1, 1., 0., 0.
*SURFACE INTERACTION, NAME=SI
*FRICTION
0.3
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD
*STEP
*STATIC
*END STEP
)");
  const std::string text = e.what();
  EXPECT_CONTAINS(text, "deck.inp:8: *SURFACE INTERACTION: the keyword *SURFACE INTERACTION is not "
                        "supported by gapfem");
  EXPECT_EQ(text.find("must follow"), std::string::npos) << text;
  EXPECT_EQ(text.find("*FRICTION"), std::string::npos) << text;
}

TEST(ReaderErrors, ErrorsInHistoryAreCollectedToo) {
  const InputError e =
      read_error(std::string(test::kTrussModel) +
                 "*STEP\n*STATIC\n*CLOAD\n1, 9, 1.\n3, 1, 1.\n*BOUNDARY\n1, 8\n*END STEP\n");
  const std::string text = e.what();
  EXPECT_CONTAINS(text, "deck.inp:14: *CLOAD: field 2 (DOF)");
  EXPECT_CONTAINS(text, "deck.inp:15: *CLOAD: node 3");
  EXPECT_CONTAINS(text, "deck.inp:17: *BOUNDARY: field 2 (degree of freedom)");
}

TEST(ReaderErrors, ListIsCappedAtFifty) {
  std::string deck = "*NODE\n";
  for (int i = 1; i <= 80; ++i) deck += std::to_string(i) + ", bad\n";
  const InputError e = read_error(deck);
  const std::string text = e.what();
  EXPECT_CONTAINS(text, "at least 50 input errors (reading stopped there)");
  // the same mistake on every line: three are listed, the rest counted
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 4) << text;
  EXPECT_CONTAINS(text, "deck.inp:4: *NODE");
  EXPECT_CONTAINS(text, "... and 47 more errors with the same message (*NODE: ");
  EXPECT_EQ(e.location().line, 2);
}

TEST(ReaderErrors, DifferentMistakesAreAllListed) {
  std::string deck = "*NODE\n";
  for (int i = 1; i <= 6; ++i) deck += std::to_string(i) + ", bad" + std::to_string(i) + "\n";
  const std::string text = read_error(deck).what();
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 6) << text;
  EXPECT_EQ(text.find("more errors with the same message"), std::string::npos) << text;
}

TEST(ReaderErrors, IgnoreUnknownTurnsOnlyUnknownsIntoWarnings) {
  // an unused definition and an output request's unknown parameter are skipped with a warning
  const std::string deck = std::string(test::kTrussModel) +
                           "*INTEGRATED OUTPUT SECTION, NAME=IOS1, SURFACE=S1\n"
                           "*NODE\n3\n*STEP\n*STATIC\n*NODE PRINT, FOO=1\nU\n*END STEP\n";
  const Model m = test::read(deck, ReadOptions{true});
  EXPECT_EQ(m.warnings.size(), 2u);
  EXPECT_EQ(m.mesh.n_nodes(), 3);
  // what would change the model stays an error with --ignore-unknown
  EXPECT_CONTAINS(
      test::error_text(std::string(test::kTrussModel) + "*NODE, FOO=1\n3\n", ReadOptions{true}),
      "the parameter FOO of *NODE is not supported by gapfem, and --ignore-unknown "
      "does not skip it: it would change the model");
  EXPECT_CONTAINS(test::error_text(std::string(test::kTrussModel) +
                                       "*MEMBRANE SECTION, ELSET=TRUSS, MATERIAL=STEEL\n1.\n",
                                   ReadOptions{true}),
                  "the keyword *MEMBRANE SECTION is not supported by gapfem, and --ignore-unknown "
                  "does not skip it");
  // real errors stay errors
  const InputError e =
      read_error(std::string(test::kTrussModel) + "*NODE\n3\n*NODE\n3\n", ReadOptions{true});
  EXPECT_CONTAINS(e.what(), "*NODE: node 3: this node number is defined twice");
}

} // namespace
} // namespace gapfem
