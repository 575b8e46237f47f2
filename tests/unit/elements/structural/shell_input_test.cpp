// Shell input end to end: *SHELL SECTION, *NODAL THICKNESS, *TRANSVERSE SHEAR STIFFNESS after a
// shell section, P/GRAV on shells, and bad input: exit 1 with file:line, the entity and a remedy,
// never a crash or a follow-on error.
#include "test_util.hpp"

#include <gtest/gtest.h>

namespace gapfem {
namespace {

/// Two S4R elements (a 2 x 1 strip) clamped at x = 0, tip load at x = 2.
std::string deck(const std::string& section, const std::string& step = "",
                 const std::string& material = "") {
  const std::string type = "S4R";
  std::string s = "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 2, 0, 0\n4, 0, 1, 0\n5, 1, 1, 0\n6, 2, 1, 0\n";
  s += "*ELEMENT, TYPE=" + type + ", ELSET=S\n1, 1, 2, 5, 4\n2, 2, 3, 6, 5\n";
  s += "*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3\n" + material + section;
  s += "*BOUNDARY\n1, ENCASTRE\n4, ENCASTRE\n*STEP\n*STATIC\n" +
       (step.empty() ? std::string("*CLOAD\n3, 3, -1.\n6, 3, -1.\n") : step) + "*END STEP\n";
  return s;
}

void expect_input_error(const std::string& text, const std::string& what) {
  const JobResult r = test::run_deck(text);
  EXPECT_EQ(r.exit_code, kExitInputError) << r.error;
  EXPECT_NE(r.error.find(what), std::string::npos) << r.error;
  EXPECT_EQ(r.error.find("has no section"), std::string::npos) << r.error;
  EXPECT_EQ(r.error.find("input errors"), std::string::npos) << r.error;
}

double tip_w(const JobResult& r) {
  const Frame* f = r.step_end(1);
  if (f == nullptr) return NAN;
  return f->nodes.U[JobResult::node(*r.model, 3)][2];
}

TEST(ShellInput, SectionThicknessShearStiffnessAndLoadsAreRead) {
  const JobResult a = test::run_deck(deck("*SHELL SECTION, ELSET=S, MATERIAL=M\n0.1, 3\n"));
  ASSERT_EQ(a.exit_code, kExitOk) << a.error;
  // a stiffer section (twice the thickness) deflects about 8 times less
  const JobResult b = test::run_deck(deck("*SHELL SECTION, ELSET=S, MATERIAL=M\n0.2\n"));
  ASSERT_EQ(b.exit_code, kExitOk) << b.error;
  EXPECT_NEAR(tip_w(a) / tip_w(b), 8.0, 0.2);
  // NODAL THICKNESS: the nodes' values replace the (blank) section thickness
  const JobResult c = test::run_deck(deck("*SHELL SECTION, ELSET=S, MATERIAL=M, NODAL THICKNESS\n"
                                          ",3\n*NODAL THICKNESS\n1, 0.1\n2, 0.1\n3, 0.1\n4, 0.1\n"
                                          "5, 0.1\n6, 0.1\n"));
  ASSERT_EQ(c.exit_code, kExitOk) << c.error;
  EXPECT_NEAR(tip_w(c), tip_w(a), 1e-12 * std::abs(tip_w(a)));
  // a soft transverse shear stiffness adds shear deflection
  const JobResult d = test::run_deck(deck("*SHELL SECTION, ELSET=S, MATERIAL=M\n0.1, 3\n"
                                          "*TRANSVERSE SHEAR STIFFNESS\n10., 10.\n"));
  ASSERT_EQ(d.exit_code, kExitOk) << d.error;
  EXPECT_LT(tip_w(d), 1.5 * tip_w(a));
  // P and GRAV on shells
  const JobResult e = test::run_deck(
      deck("*SHELL SECTION, ELSET=S, MATERIAL=M\n0.1\n",
           "*DLOAD\nS, P, 1.\n1, GRAV, 9810., 0, 0, -1\n", "*DENSITY\n7.8e-9\n"));
  EXPECT_EQ(e.exit_code, kExitOk) << e.error;
  EXPECT_LT(tip_w(e), 0.0);
}

TEST(ShellInput, TemperatureGradientsAtNodesWithoutShellsOrBeamsAreReported) {
  // node 7 belongs to no element: its gradient would have no effect, which the reader says
  std::string text = deck("*SHELL SECTION, ELSET=S, MATERIAL=M\n0.1\n", "",
                          "*EXPANSION\n1e-5\n");
  text.replace(text.find("*ELEMENT"), 0, "7, 5, 5, 0\n");
  text.replace(text.find("*CLOAD"), 0, "*TEMPERATURE\n1, 20., 10.\n7, 20., 10.\n");
  const JobResult r = test::run_deck(text);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  int found = 0;
  for (const std::string& w : r.model->warnings)
    found += w.find("node 7 has no shell or beam element") != std::string::npos;
  EXPECT_EQ(found, 1);
}

TEST(ShellInput, BadSectionsAndLoadsAreErrors) {
  expect_input_error(deck("*SHELL SECTION, ELSET=S, MATERIAL=M\n0.\n"),
                     "the shell thickness must be positive, not 0");
  expect_input_error(deck("*SHELL SECTION, ELSET=S, MATERIAL=M\n-0.1\n"),
                     "the shell thickness must be positive, not -0.1");
  expect_input_error(deck("*SHELL SECTION, ELSET=S, MATERIAL=M\n0.1, 4\n"),
                     "Simpson's rule needs an odd number of points from 3 to 15, not 4");
  expect_input_error(deck("*SHELL SECTION, ELSET=S, MATERIAL=M\n"), "the data line is missing");
  expect_input_error(deck("*SHELL SECTION, ELSET=S, MATERIAL=M, COMPOSITE\n0.1\n"), "COMPOSITE");
  expect_input_error(deck("*SHELL SECTION, ELSET=S, MATERIAL=M, OFFSET=TOP\n0.1\n"),
                     "give SPOS, SNEG, SMID or the offset");
  expect_input_error(deck("*SHELL SECTION, ELSET=S, MATERIAL=M, SECTION INTEGRATION=GAUSS\n0.1\n"),
                     "SECTION INTEGRATION");
  expect_input_error(deck("*SHELL SECTION, ELSET=S, MATERIAL=M, NODAL THICKNESS\n\n"
                          "*NODAL THICKNESS\n1, 0.1\n"),
                     "has no thickness; give it in *NODAL THICKNESS");
  expect_input_error(deck("*SHELL SECTION, ELSET=S, MATERIAL=M\n0.1\n*NODAL THICKNESS\n1, -2.\n"),
                     "must be positive, not -2");
  expect_input_error(deck("*SHELL SECTION, ELSET=S, MATERIAL=M\n0.1\n"
                          "*TRANSVERSE SHEAR STIFFNESS\n10., 10., 3.\n"),
                     "K12 must be 0 or blank");
  expect_input_error(deck("*SHELL SECTION, ELSET=S, MATERIAL=M\n0.1\n", "*DLOAD\n1, P2, 1.\n"),
                     "is a shell (S4R), loaded on its reference surface by P");
  expect_input_error(deck("*SHELL SECTION, ELSET=S, MATERIAL=M\n0.1\n",
                          "*DLOAD\n1, GRAV, 9810., 0, 0, -1\n"),
                     "GRAV needs the mass density of material M");
  expect_input_error(deck("*SOLID SECTION, ELSET=S, MATERIAL=M\n0.1\n"),
                     "needs a *SHELL SECTION, not a *SOLID SECTION");
  // a folded element: nodes not numbered around it
  std::string folded = deck("*SHELL SECTION, ELSET=S, MATERIAL=M\n0.1\n");
  folded.replace(folded.find("1, 1, 2, 5, 4"), 13, "1, 1, 5, 2, 4");
  const JobResult r = test::run_deck(folded);
  EXPECT_EQ(r.exit_code, kExitInputError) << r.error;
  EXPECT_NE(r.error.find("element 1 (S4R): its surface"), std::string::npos) << r.error;
}

} // namespace
} // namespace gapfem
