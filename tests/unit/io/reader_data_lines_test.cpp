// Every data line belongs to a keyword that reads it (issue 43): a line no handler read is an
// error naming the line and the keyword, whatever the keyword; the lines Abaqus itself ignores are
// read with a warning; lines of only commas are data lines of blank fields.
#include "unit/io/reader_test_util.hpp"

namespace gapfem {
namespace {

using test::count_warnings;
using test::error_text;
using test::kTrussModel;
using test::read;

/// The truss model with one step; `model_extra` goes before the boundary conditions, `step_extra`
/// at the end of the step and `after` after it.
std::string deck(const std::string& model_extra = "", const std::string& step_extra = "",
                 const std::string& after = "") {
  return std::string(kTrussModel) + model_extra +
         "*BOUNDARY\n1, 1, 3\n*STEP\n*STATIC\n0.5, 1.\n*CLOAD\n2, 1, 10.\n" + step_extra +
         "*END STEP\n" + after;
}

int n_lines(const std::string& text) {
  return 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

/// Expects exactly one error, containing `part`.
void expect_one_error(const std::string& text, const std::string& part) {
  const std::string e = error_text(text);
  EXPECT_CONTAINS(e, part);
  EXPECT_EQ(n_lines(e), 1) << e;
}

TEST(ReaderDataLines, ALineNoKeywordReadsIsAnErrorNamingIt) {
  std::string d = deck();
  d.insert(d.find("*ELASTIC"), "7850.\n");
  expect_one_error(d, "deck.inp:7: *MATERIAL: *MATERIAL takes no data lines; line 7 is one: "
                      "'7850.'. Remove it, or put the keyword line it belongs to above it");
  expect_one_error(deck("", "", "2, 1, 20.\n"),
                   "deck.inp:19: *END STEP: *END STEP takes no data lines; line 19 is one");
  d = deck();
  d.insert(d.find("*CLOAD"), "0.25, 1.\n");
  expect_one_error(d, "deck.inp:16: *STATIC: *STATIC takes one data line; line 16 is a second "
                      "one: '0.25, 1.'");
  d = deck();
  d.insert(d.find("*ELEMENT"), ",,,\n");
  expect_one_error(d, "deck.inp:4: *NODE: line 4 holds only commas (,,,), no value: *NODE reads "
                      "nothing from it");
  d = deck();
  d.insert(d.find("*BOUNDARY"), "2.\n3.\n");
  expect_one_error(d, "*SOLID SECTION takes one data line; line 11 is a second one: '2.' (and 1 "
                      "more line after it). Remove it");
}

TEST(ReaderDataLines, FixedLineKeywordsReportTheirExtraLines) {
  // three lines at most for the time incrementation controls
  expect_one_error(deck("", "*CONTROLS, PARAMETERS=TIME INCREMENTATION\n4\n0.25\n1.\n2.\n"),
                   "*CONTROLS takes 3 data lines; line 22 is one more: '2.'");
  // a *STEP has one line, its title
  std::string d = deck();
  d.insert(d.find("*STATIC"), "Title\nmore title\n");
  expect_one_error(d, "*STEP takes one data line; line 15 is a second one: 'more title'");
}

TEST(ReaderDataLines, LinesOfCommasAreBlankFieldsWhereALineIsTaken) {
  // *SOLID SECTION followed by "," as Abaqus/CAE writes it for solids
  std::string d = deck();
  d.replace(d.find("1.\n*BOUNDARY"), 2, ",");
  EXPECT_EQ(read(d).solid_sections.at(0).thickness_given, false);
  // *STATIC with a line of blank fields: the defaults
  d = deck();
  d.replace(d.find("0.5, 1.\n"), 7, ",,,");
  EXPECT_EQ(read(d).steps.at(0).inc.period, 1.0);
  // *CONTROLS: a first line of blank fields keeps its place, the second line is the factors
  d = deck("", "*CONTROLS, PARAMETERS=TIME INCREMENTATION\n,,,,,,,,\n0.3,,0.6\n");
  const Model m = read(d);
  EXPECT_EQ(m.steps.at(0).controls.cutback, 0.3);
  EXPECT_EQ(m.steps.at(0).controls.shrink, 0.6);
}

TEST(ReaderDataLines, LinesAbaqusIgnoresAreReadWithAWarning) {
  // the step title; one that reads as numbers is probably a line whose keyword is missing
  std::string d = deck();
  d.insert(d.find("*STATIC"), "Pull the truss\n");
  EXPECT_EQ(count_warnings(read(d), "title"), 0);
  d = deck();
  d.insert(d.find("*STATIC"), "2, 1, 20.\n");
  EXPECT_EQ(count_warnings(read(d), "the data line under *STEP is the step's title (Abaqus), "
                                    "but '2, 1, 20.' reads as numbers"),
            1);
  // print controls and history output: ignored with a note, their lines too
  EXPECT_NO_THROW(read(deck("", "*CONTACT PRINT\nCSTRESS\n*OUTPUT, HISTORY\n*NODE OUTPUT\nU\n")));
  // *HEADING: every line is text
  EXPECT_NO_THROW(read("*HEADING\nline one\n2, 3, 4\n" + deck()));
}

TEST(ReaderDataLines, AKeywordLineInErrorKeepsTheStepsInPlace) {
  // a parameter given twice is the one error: the step's keywords are not "outside a step"
  std::string d = deck();
  d.replace(d.find("*STEP\n"), 6, "*STEP, INC=5, INC=6\n");
  expect_one_error(d, "INC: this parameter is given twice");
  d = deck();
  d.replace(d.find("*END STEP\n"), 10, "*END STEP, X=1, X=2\n");
  expect_one_error(d, "X: this parameter is given twice");
}

TEST(ReaderDataLines, ASetThatListsItselfIsSaidSo) {
  expect_one_error(deck("*NSET, NSET=ENDS\n1, ENDS\n"),
                   "*NSET: node set ENDS: the set lists itself; a set cannot be defined in terms "
                   "of itself");
  expect_one_error(deck("*ELSET, ELSET=MORE\nMORE, 1\n"),
                   "*ELSET: element set MORE: the set lists itself");
  // a set that exists already may be named again (its members are added once)
  EXPECT_EQ(read(deck("*NSET, NSET=ENDS\n1\n*NSET, NSET=ENDS\nENDS, 2\n")).nsets.at("ENDS").size(),
            2u);
}

TEST(ReaderDataLines, AnElementOnOneNodeTwiceIsAnError) {
  std::string d = deck();
  d.replace(d.find("1, 1, 2\n"), 7, "1, 1, 1");
  expect_one_error(d, "element 1: node 1 is both nodes of this T3D2 element, so it has no length "
                      "or direction");
  const std::string gap = "*NODE\n3, 1., 0., 0.\n*ELEMENT, TYPE=GAPUNI, ELSET=G\n9, 3, 3\n"
                          "*GAP, ELSET=G\n0.1, 1., 0., 0.\n";
  expect_one_error(deck(gap), "element 9: node 3 is both nodes of this gap, so its clearance "
                              "never changes from d");
  // a SPRING2 may couple two DOFs of one node, but not one DOF with itself
  const std::string spring = "*ELEMENT, TYPE=SPRING2, ELSET=S\n9, 2, 2\n*SPRING, ELSET=S\n{}\n5.\n";
  EXPECT_NO_THROW(read(deck(fmt::format(fmt::runtime(spring), "1, 2"))));
  expect_one_error(deck(fmt::format(fmt::runtime(spring), "2, 2")),
                   "element 9 (SPRING2): node 2 is both nodes of this spring and both DOFs are 2");
}

} // namespace
} // namespace gapfem
