// Beam input end to end: what is read (GENERAL section constants, blank lines keeping defaults,
// *TRANSVERSE SHEAR STIFFNESS), and bad input: exit 1 with file:line, the entity and a remedy,
// never a crash or a follow-on error.
#include "test_util.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <numbers>

namespace gapfem {
namespace {

/// Two B31 (or `type`) elements along x on a clamped root with a tip load.
std::string deck(const std::string& type, const std::string& section, const std::string& step = "",
                 bool planar = false) {
  const bool three = type == "B32" || type == "B22" || type == "PIPE32";
  std::string s = "*NODE, NSET=ALL\n";
  for (int i = 0; i <= (three ? 4 : 2); ++i)
    s += std::to_string(i + 1) + ", " + std::to_string(i * (three ? 0.5 : 1.0)) +
         (planar ? ", 0\n" : ", 0, 0\n");
  s += "*ELEMENT, TYPE=" + type + ", ELSET=B\n" +
       (three ? "1, 1, 2, 3\n2, 3, 4, 5\n" : "1, 1, 2\n2, 2, 3\n");
  s += "*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3\n" + section;
  s += planar ? "*BOUNDARY\n1, 1, 2\n1, 6\n" : "*BOUNDARY\n1, ENCASTRE\n";
  s += "*STEP\n*STATIC\n" +
       (step.empty() ? std::string("*CLOAD\n") + (three ? "5" : "3") + ", 2, 100.\n" : step) +
       "*END STEP\n";
  return s;
}

void expect_input_error(const std::string& text, const std::string& what) {
  const JobResult r = test::run_deck(text);
  EXPECT_EQ(r.exit_code, kExitInputError) << r.error;
  EXPECT_NE(r.error.find(what), std::string::npos) << r.error;
  // one error: nothing about a missing section or material after it
  EXPECT_EQ(r.error.find("has no section"), std::string::npos) << r.error;
  EXPECT_EQ(r.error.find("input errors"), std::string::npos) << r.error;
}

TEST(BeamInput, GeneralSectionAndTransverseShearAreRead) {
  // line 2 blank: default n1; line 3: E, G, alpha. K23 given: the shear stiffness along n2.
  const std::string gen = "*BEAM GENERAL SECTION, ELSET=B, DENSITY=7.8e-9\n"
                          "100., 1000., 0., 500., 800.\n\n200000., 80000., 1.2e-5\n"
                          "*TRANSVERSE SHEAR STIFFNESS\n5.e5, 4.e5\n";
  const JobResult r = test::run_deck(deck("B31", gen));
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  const BeamSection& s = r.model->beam_sections.at(0);
  EXPECT_TRUE(s.general);
  EXPECT_EQ(s.dims, (std::vector<double>{100., 1000., 0., 500., 800.}));
  EXPECT_FALSE(s.n1_given);
  EXPECT_EQ(s.E, 200000.);
  EXPECT_EQ(s.G, 80000.);
  EXPECT_EQ(s.alpha, 1.2e-5);
  EXPECT_EQ(s.density, 7.8e-9);
  EXPECT_EQ(s.k23, 5.e5);
  EXPECT_EQ(s.k13, 4.e5);
  // tip of a two-element cantilever, L = 2, F = 100 along n2: exact prismatic element with
  // shear stiffness K23: F L^3 / (3 E I11) + F L / K23
  const double w = 100.0 * 8.0 / (3 * 200000.0 * 1000.0) + 100.0 * 2.0 / 5.e5;
  EXPECT_NEAR(test::U(r, test::last_frame(r), 3)[1], w, 1e-12 * w);
}

/// A PIPE31 run of n elements from (0, 0, 0) to `end`, clamped at node 1.
std::string pipe_run(const Vec3& end, int n, const std::string& step) {
  std::string s = "*NODE, NSET=ALL\n";
  for (int i = 0; i <= n; ++i)
    s += fmt::format("{}, {}, {}, {}\n", i + 1, end[0] * i / n, end[1] * i / n, end[2] * i / n);
  s += "*ELEMENT, TYPE=PIPE31, ELSET=B\n";
  for (int i = 1; i <= n; ++i) s += fmt::format("{}, {}, {}\n", i, i, i + 1);
  s += "*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3\n*BEAM SECTION, ELSET=B, MATERIAL=M, "
       "SECTION=PIPE\n0.5, 0.05\n0., 1., 0.\n*BOUNDARY\n1, ENCASTRE\n*STEP\n*STATIC\n" +
       step + "*END STEP\n";
  return s;
}

TEST(BeamInput, HydrostaticPipePressureSumsToArchimedes) {
  // A closed vertical column 10 long in water up to z0 = 10 (rho g = 9810, p1 = 98100 at
  // z1 = 0), HPE: the pressure on the closed pipe sums to the buoyancy rho g (pi r^2) h upward,
  // whatever the mesh, so the clamp holds it down: RF3 = -9810 pi 0.25 10.
  const double buoyancy = 9810.0 * std::numbers::pi * 0.25 * 10.0;
  for (int n : {1, 4, 7}) {
    const JobResult r =
        test::run_deck(pipe_run({0, 0, 10}, n, "*DLOAD\nB, HPE, 98100., 10., 0.\n"));
    ASSERT_EQ(r.exit_code, kExitOk) << r.error;
    EXPECT_NEAR(test::RF(r, test::last_frame(r), 1)[2], -buoyancy, 1e-9 * buoyancy) << n;
  }
  // Half the column above the water (z0 = 5): only the wet part is buoyed (element midpoints
  // below z0: with 10 elements, the five lower ones).
  const JobResult h = test::run_deck(pipe_run({0, 0, 10}, 10, "*DLOAD\nB, HPE, 49050., 5., 0.\n"));
  ASSERT_EQ(h.exit_code, kExitOk) << h.error;
  EXPECT_NEAR(test::RF(h, test::last_frame(h), 1)[2], -0.5 * buoyancy, 1e-9 * buoyancy);
  // A level pipe at z = 0 under HPI with its reference height there is PI with the same
  // pressure (same hoop stress, same axial thrust) plus the contents' weight rho g pi r_i^2 L
  // downward: RF3 = +9810 pi 0.45^2 4, RF1 the same as PI's.
  const JobResult a = test::run_deck(pipe_run({4, 0, 0}, 4, "*DLOAD\nB, HPI, 5., 10., 0.\n"));
  const JobResult b = test::run_deck(pipe_run({4, 0, 0}, 4, "*DLOAD\nB, PI, 5.\n"));
  ASSERT_EQ(a.exit_code, kExitOk) << a.error;
  ASSERT_EQ(b.exit_code, kExitOk) << b.error;
  const double weight = 0.5 * std::numbers::pi * 0.45 * 0.45 * 4.0; // rho g = 5 / 10
  EXPECT_NEAR(test::RF(a, test::last_frame(a), 1)[2], weight, 1e-9 * weight);
  EXPECT_NEAR(test::RF(a, test::last_frame(a), 1)[0], test::RF(b, test::last_frame(b), 1)[0], 1e-9);
  const auto* sa = a.step_end(1)->element(0)->data.find(ElemVar::S);
  const auto* sb = b.step_end(1)->element(0)->data.find(ElemVar::S);
  ASSERT_TRUE(sa && sb);
  EXPECT_NEAR(sa->values[1], sb->values[1], 1e-9 * std::abs(sb->values[1])); // hoop S22
  EXPECT_GT(sb->values[1], 0.0);
  // bad input: equal heights; PI and HPI on one element
  expect_input_error(pipe_run({4, 0, 0}, 2, "*DLOAD\nB, HPI, 5., 1., 1.\n"),
                     "the zero-pressure height and the reference height");
  expect_input_error(pipe_run({4, 0, 0}, 2, "*DLOAD\nB, PI, 5.\n*DLOAD\nB, HPI, 5., 10., 0.\n"),
                     "the pipe has both PI and HPI");
}

TEST(BeamInput, SectionPointsOfAGeneralSectionReportTheAxialStress) {
  // GENERAL A = 100, I11 = 1000, I22 = 500, J = 800 under a tip moment of 1000 about n1 (DOF 6,
  // n1 = -z): uniform bending M1 = 1000, S11 = M1 x2 / I11 at the points (x1, x2) of *SECTION
  // POINTS: +-2 at (0, +-2), 0 on x2 = 0. The (0, 0) closing the first line is dropped, the one
  // alone on the second line is kept.
  const std::string gen = "*BEAM GENERAL SECTION, ELSET=B\n100., 1000., 0., 500., 800.\n\n"
                          "200000., 80000.\n*SECTION POINTS\n0., 2., 0., -2., 3., 0., 0., 0.\n"
                          "0., 0.\n";
  const JobResult r = test::run_deck(deck("B31", gen, "*CLOAD\n3, 6, -1000.\n"));
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  const OutputBlock* S = r.step_end(1)->element(0)->data.find(ElemVar::S);
  ASSERT_NE(S, nullptr);
  ASSERT_EQ(S->section_points, 4);
  const std::size_t nc = S->names.size();
  EXPECT_NEAR(std::abs(S->values[0]), 2.0, 1e-9);
  EXPECT_NEAR(S->values[nc], -S->values[0], 1e-9);
  EXPECT_NEAR(S->values[2 * nc], 0.0, 1e-9);
  EXPECT_NEAR(S->values[3 * nc], 0.0, 1e-9);
  expect_input_error(deck("B31", "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=RECT\n1., 1.\n"
                                 "*SECTION POINTS\n0., 0.5\n"),
                     "*SECTION POINTS belongs to a *BEAM GENERAL SECTION");
  expect_input_error(
      deck("B31", gen.substr(0, gen.find("*SECTION")) + "*SECTION POINTS\n1., 2., 3.\n"),
      "give the points as pairs x1, x2");
}

TEST(BeamInput, BadSectionsAreOneClearError) {
  expect_input_error(deck("B31", "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=BOX\n"
                                 "1., 1., 0.6, 0.1, 0.6, 0.1\n"),
                     "ELSET=B: SECTION=BOX: the walls at +x1 and -x1 are thicker than the box is "
                     "wide: t1 + t3 = 1.2 must be below a = 1");
  expect_input_error(deck("B31", "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=BOX\n"
                                 "1., 1., 0.1, 0.6, 0.1, 0.6\n"),
                     "SECTION=BOX: the walls at +x2 and -x2 are thicker than the box is high: t2 "
                     "+ t4 = 1.2 must be below b = 1");
  expect_input_error(deck("B31", "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=I\n"
                                 "0.5, 1., 1., 1., 0.6, 0.6, 0.1\n"),
                     "SECTION=I: the flanges (t1 + t2 = 1.2) must be thinner than the height");
  expect_input_error(deck("B31", "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=PIPE\n0.1, 0.1\n"),
                     "the wall thickness 0.1 must be smaller than the outer radius 0.1");
  expect_input_error(deck("B31", "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=HEX\n1., 0.9\n"),
                     "SECTION=HEX: the wall thickness t = 0.9 must be smaller than r sqrt(3) / 2");
  expect_input_error(deck("B31", "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=RECT\n-1., 1.\n"),
                     "section dimensions must be positive, not -1");
  expect_input_error(deck("PIPE31", "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=RECT\n1., 1.\n"),
                     "PIPE31 elements are pipes and need SECTION=PIPE");
  expect_input_error(deck("B21",
                          "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=RECT\n1., 1.\n0., 1., 0.\n",
                          "", true),
                     "B21 is a planar beam, whose n1 direction is always (0, 0, -1)");
  expect_input_error(deck("B31", "*BEAM GENERAL SECTION, ELSET=B\n1., 1., 0., 1., 1.\n"),
                     "the elastic constants are missing");
  expect_input_error(deck("B31", "*BEAM GENERAL SECTION, ELSET=B\n1., 1., 2., 1., 1.\n\n1., 1.\n"),
                     "I11 I22 - I12^2 = -3 must be positive");
  expect_input_error(
      deck("B31", "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=ARBITRARY\n1,1,1,1\n"),
      "SECTION=ARBITRARY: this section is not available in gapfem");
  expect_input_error(deck("B31", "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=L\n1,1,1,0.5\n"),
                     "SECTION=L: the leg along axis 1 is too thick: its thickness t1 = 1 must be "
                     "below b = 1, the length of the other leg");
  expect_input_error(
      deck("B31", "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=TRAPEZOID\n1,1,-1,0.5\n"),
      "SECTION=TRAPEZOID: the widths a and c and the height b must be positive");
}

TEST(BeamInput, MisplacedShearStiffnessAndBadLoadsAreErrors) {
  const std::string rect = "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=RECT\n1., 1.\n";
  const JobResult r = test::run_deck(deck("B31", "*TRANSVERSE SHEAR STIFFNESS\n1., 1.\n" + rect));
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("*TRANSVERSE SHEAR STIFFNESS must follow *BEAM SECTION, *BEAM GENERAL "
                         "SECTION or *SHELL SECTION"),
            std::string::npos)
      << r.error;
  expect_input_error(deck("B21", rect, "*DLOAD\nB, PZ, 1.\n", true),
                     "PZ acts out of the plane of a planar beam; a B21 takes P2");
  expect_input_error(deck("B21", rect, "*DLOAD\nB, P1, 1.\n", true),
                     "P1 is not a load of a planar beam (it acts along n1 = (0, 0, -1), out of the "
                     "plane); a B21 takes P2 (force per length along the section's n2), PX, PY "
                     "(global directions), BX, BY (force per volume) and GRAV");
  expect_input_error(deck("B21", rect, "*DLOAD\nB, BZ, 1.\n", true),
                     "BZ acts out of the plane of a planar beam");
  // a face pressure on a beam was once read as a line load without a direction (zero)
  expect_input_error(deck("B31", rect, "*DLOAD\nB, P, 1.\n"),
                     "P is not a beam load: a beam has no faces for a pressure; a B31 takes P1, "
                     "P2 (force per length along the section's n1, n2), PX, PY, PZ (global "
                     "directions), BX, BY, BZ (force per volume) and GRAV");
  expect_input_error(deck("B31", rect, "*DLOAD\nB, PI, 1.\n"),
                     "PI (internal pipe pressure) acts on pipe elements (PIPE31, PIPE32) only; a "
                     "B31 takes P1, P2");
  expect_input_error(deck("B21", rect, "*DLOAD\nB, PE, 1.\n", true),
                     "gapfem's pipe elements (PIPE31, PIPE32) are in space");
  expect_input_error(deck("B31", rect, "*DLOAD\nB, GRAV, 9.81, 0, -1, 0\n"),
                     "GRAV needs the mass density of material M");
  expect_input_error(deck("B31", "*BEAM GENERAL SECTION, ELSET=B\n1., 1., 0., 1., 1.\n\n1., 1.\n",
                          "*DLOAD\nB, GRAV, 9.81, 0, -1, 0\n"),
                     "add DENSITY=<rho> to *BEAM GENERAL SECTION, ELSET=B");
}

TEST(BeamInput, FoldedThreeNodeBeamAndN1AlongTheAxisAreNamed) {
  const std::string rect = "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=RECT\n1., 1.\n";
  std::string folded = deck("B32", rect);
  const std::string mid = "\n2, " + std::to_string(0.5) + ", 0, 0";
  ASSERT_NE(folded.find(mid), std::string::npos);
  folded.replace(folded.find(mid), mid.size(), "\n2, 1.5, 0, 0"); // middle node beyond the end
  expect_input_error(folded, "folds back on itself");
  expect_input_error(deck("B32", "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=RECT\n1., 1.\n"
                                 "1., 0., 0.\n"),
                     "is parallel to the beam axis");
}

} // namespace
} // namespace gapfem
