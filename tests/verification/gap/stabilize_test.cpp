// *STATIC, STABILIZE (issue 12): Abaqus's automatic stabilization holds a body that rests on open
// gaps until they close. A C3D8 block (1 x 1 x 1) on four GAPUNI supports with a clearance of
// 0.01 under a pressure of 10 (held laterally at three base nodes): without stabilization the step
// stops (the block floats, with a remedy naming STABILIZE); with it the gaps close and each carries
// a quarter of the load, 2.5, up to the stabilization's residual viscous force (ALLSD / ALLIE far
// below ALLSDTOL). A stable model is barely changed; FACTOR sets the damping factor; CONTINUE=YES
// carries it to the next step; bad parameters are input errors.
#include "test_util.hpp"

#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

using namespace gapfem;
using namespace gapfem::test;

namespace {

std::string block(double clearance, const std::string& static_line,
                  const std::string& second_step = "") {
  std::string d = "*HEADING\nblock on four gaps\n*NODE\n";
  auto lab = [](int i, int j, int k) { return 1 + i + 3 * j + 9 * k; };
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        d += fmt::format("{}, {}, {}, {}\n", lab(i, j, k), 0.5 * i, 0.5 * j, k);
  const int corners[4][2] = {{0, 0}, {2, 0}, {0, 2}, {2, 2}};
  for (int n = 0; n < 4; ++n)
    d += fmt::format("{}, {}, {}, {}\n", 101 + n, 0.5 * corners[n][0], 0.5 * corners[n][1],
                     -clearance);
  d += "*ELEMENT, TYPE=C3D8, ELSET=B\n";
  int e = 1;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i, ++e)
      d += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", e, lab(i, j, 0), lab(i + 1, j, 0),
                       lab(i + 1, j + 1, 0), lab(i, j + 1, 0), lab(i, j, 1), lab(i + 1, j, 1),
                       lab(i + 1, j + 1, 1), lab(i, j + 1, 1));
  d += "*ELEMENT, TYPE=GAPUNI, ELSET=G\n";
  for (int n = 0; n < 4; ++n)
    d += fmt::format("{}, {}, {}\n", 201 + n, lab(corners[n][0], corners[n][1], 0), 101 + n);
  d += fmt::format("*GAP, ELSET=G\n{}, 0., 0., -1., 1.\n", clearance);
  d += "*NSET, NSET=GROUND\n101, 102, 103, 104\n*ELSET, ELSET=TOPE\n1, 2, 3, 4\n"
       "*SURFACE, NAME=TOP\nTOPE, S2\n*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n"
       "*SOLID SECTION, ELSET=B, MATERIAL=M\n";
  d += "*STEP\n" + static_line +
       "\n0.1, 1.\n*BOUNDARY\nGROUND, 1, 3\n1, 1, 2\n3, 2, 2\n7, 1, 1\n*DSLOAD\nTOP, P, 10.\n"
       "*END STEP\n";
  return d + second_step;
}

} // namespace

TEST(Stabilize, HoldsABodyOnOpenGapsUntilTheyClose) {
  const JobResult plain = run_deck(block(0.01, "*STATIC"), false, "plain");
  EXPECT_EQ(plain.exit_code, kExitNoConvergence);
  EXPECT_NE(plain.error.find("*STATIC, STABILIZE"), std::string::npos) << plain.error;

  const JobResult r = run_deck(block(0.01, "*STATIC, STABILIZE"), true, "stab");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  for (Label g : {201, 202, 203, 204}) {
    EXPECT_NE(gap(r, f, g).status, ContactStatus::Open) << g;
    EXPECT_NEAR(gap(r, f, g).normal_force, 2.5, 2.5e-3) << g; // the viscous residual
  }
  const StepChecks& c = r.steps.front().checks;
  EXPECT_TRUE(c.stabilized);
  EXPECT_GT(c.stabilization_factor, 0.0);
  EXPECT_GT(c.allsd, 0.0);
  EXPECT_GT(c.allie, 0.0);
  EXPECT_LT(c.allsd, 0.05 * c.allie) << "ALLSDTOL";
  // the energies reach job.dat and the JSON
  std::ifstream dat(test_dir() / "stab.dat");
  std::stringstream text;
  text << dat.rdbuf();
  EXPECT_NE(text.str().find("ALLSD (ENERGY DISSIPATED)"), std::string::npos);
  std::ifstream json(test_dir() / "stab.results.json");
  std::stringstream jtext;
  jtext << json.rdbuf();
  EXPECT_NE(jtext.str().find("\"ALLSD\":"), std::string::npos);
}

TEST(Stabilize, BarelyChangesAStableModel) {
  const JobResult plain = run_deck(block(0.0, "*STATIC"), false, "plain");
  const JobResult stab = run_deck(block(0.0, "*STATIC, STABILIZE"), false, "stab");
  ASSERT_EQ(plain.exit_code, 0) << plain.error;
  ASSERT_EQ(stab.exit_code, 0) << stab.error;
  for (Label g : {201, 202, 203, 204})
    EXPECT_NEAR(gap(stab, last_frame(stab), g).normal_force,
                gap(plain, last_frame(plain), g).normal_force, 1e-3)
        << g;
}

TEST(Stabilize, FactorAndContinue) {
  const std::string step2 = "*STEP\n*STATIC\n*DSLOAD\nTOP, P, 12.\n*END STEP\n";
  const JobResult r = run_deck(block(0.01, "*STATIC, STABILIZE, FACTOR=0.03, CONTINUE=YES", step2));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  ASSERT_EQ(r.steps.size(), 2u);
  EXPECT_DOUBLE_EQ(r.steps[0].checks.stabilization_factor, 0.03) << "constant without ALLSDTOL";
  EXPECT_TRUE(r.steps[1].checks.stabilized) << "CONTINUE=YES";
  EXPECT_DOUBLE_EQ(r.steps[1].checks.stabilization_factor, 0.03);
  const JobResult n = run_deck(block(0.01, "*STATIC, STABILIZE, FACTOR=0.03", step2), false, "no");
  ASSERT_EQ(n.exit_code, 0) << n.error;
  EXPECT_FALSE(n.steps[1].checks.stabilized) << "CONTINUE=NO is the default";
}

TEST(Stabilize, BadParametersAreInputErrors) {
  for (const char* line : {"*STATIC, ALLSDTOL=0.05", "*STATIC, STABILIZE, FACTOR=-1.",
                           "*STATIC, STABILIZE=0.", "*STATIC, CONTINUE=YES"}) {
    const JobResult r = run_deck(block(0.01, line));
    EXPECT_EQ(r.exit_code, kExitInputError) << line;
    EXPECT_NE(r.error.find("*STATIC"), std::string::npos) << r.error;
  }
}
