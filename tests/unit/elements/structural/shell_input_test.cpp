// Shell input end to end: *SHELL SECTION, *NODAL THICKNESS, *TRANSVERSE SHEAR STIFFNESS after a
// shell section, P/GRAV on shells, and bad input: exit 1 with file:line, the entity and a remedy,
// never a crash or a follow-on error.
#include "test_util.hpp"

#include <array>
#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <sstream>

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
  const JobResult e =
      test::run_deck(deck("*SHELL SECTION, ELSET=S, MATERIAL=M\n0.1\n",
                          "*DLOAD\nS, P, -1.\n1, GRAV, 9810., 0, 0, -1\n", "*DENSITY\n7.8e-9\n"));
  EXPECT_EQ(e.exit_code, kExitOk) << e.error;
  EXPECT_LT(tip_w(e), 0.0);
}

TEST(ShellInput, SurfacePressurePushesAgainstTheSideItIsOn) {
  // *DLOAD P pushes along +n (here +z); a surface pressure pushes against its side's outward
  // normal: on SPOS (S2 in CalculiX) along -n, on SNEG (S1) along +n.
  const std::string sec = "*SHELL SECTION, ELSET=S, MATERIAL=M\n0.1\n";
  const JobResult p = test::run_deck(deck(sec, "*DLOAD\nS, P, -1.\n"));
  ASSERT_EQ(p.exit_code, kExitOk) << p.error;
  ASSERT_LT(tip_w(p), 0.0);
  auto surface = [&](const std::string& side, double magnitude) {
    std::string text = deck(sec, fmt::format("*DSLOAD\nTOP, P, {}\n", magnitude));
    text.replace(text.find("*BOUNDARY"), 0,
                 "*ELSET, ELSET=_TOP_" + side + "\n1, 2\n*SURFACE, TYPE=ELEMENT, NAME=TOP\n_TOP_" +
                     side + ", " + side + "\n");
    const JobResult r = test::run_deck(text);
    EXPECT_EQ(r.exit_code, kExitOk) << r.error;
    return tip_w(r);
  };
  const double w = tip_w(p);
  EXPECT_NEAR(surface("SPOS", 1.0), w, 1e-12 * std::abs(w));
  EXPECT_NEAR(surface("S2", 1.0), w, 1e-12 * std::abs(w));
  EXPECT_NEAR(surface("SNEG", -1.0), w, 1e-12 * std::abs(w));
  EXPECT_NEAR(surface("S1", 1.0), -w, 1e-12 * std::abs(w));
  // both sides loaded by the same pressure cancel (two entries, not one replacing the other)
  std::string both = deck(sec, "*DSLOAD\nUP, P, 1.\nDN, P, 1.\n");
  both.replace(both.find("*BOUNDARY"), 0,
               "*SURFACE, NAME=UP\nS, SPOS\n*SURFACE, NAME=DN\nS, SNEG\n");
  const JobResult b = test::run_deck(both);
  ASSERT_EQ(b.exit_code, kExitOk) << b.error;
  EXPECT_NEAR(tip_w(b), 0.0, 1e-12 * std::abs(w));
}

TEST(ShellInput, SurfacePressureFollowsTheShellUnderNlgeom) {
  // the SPOS pressure and -P are the same follower load: same answer under NLGEOM
  const std::string sec = "*SHELL SECTION, ELSET=S, MATERIAL=M\n0.1\n";
  std::string a = deck(sec, "*DLOAD\nS, P, -2.\n");
  std::string b = deck(sec, "*DSLOAD\nTOP, P, 2.\n");
  b.replace(b.find("*BOUNDARY"), 0, "*SURFACE, NAME=TOP\nS, SPOS\n");
  for (std::string* t : {&a, &b}) t->replace(t->find("*STEP"), 5, "*STEP, NLGEOM");
  const JobResult ra = test::run_deck(a), rb = test::run_deck(b);
  ASSERT_EQ(ra.exit_code, kExitOk) << ra.error;
  ASSERT_EQ(rb.exit_code, kExitOk) << rb.error;
  EXPECT_LT(tip_w(ra), -0.1); // large enough for the follower effect to matter
  EXPECT_NEAR(tip_w(ra), tip_w(rb), 1e-9 * std::abs(tip_w(ra)));
}

/// The data rows of the first S table in job.dat: {element, PT, SEC, S11}.
std::vector<std::array<double, 4>> s_rows(const std::string& text) {
  const JobResult r = test::run_deck(text, true);
  EXPECT_EQ(r.exit_code, kExitOk) << r.error;
  std::ifstream in(test::test_dir() / "job.dat");
  std::vector<std::array<double, 4>> rows;
  std::string line;
  bool table = false;
  while (std::getline(in, line)) {
    if (line.find("PT SEC FOOT-") != std::string::npos && line.find("S11") != std::string::npos) {
      table = true;
      continue;
    }
    if (!table) continue;
    std::istringstream ls(line);
    std::array<double, 4> row{};
    if (ls >> row[0] >> row[1] >> row[2] >> row[3])
      rows.push_back(row);
    else if (!rows.empty())
      break;
  }
  return rows;
}

TEST(ShellInput, DatFilePrintsTheRequestedSectionPoints) {
  // 5 Simpson points; a tip moment bends the strip: S11 is linear through the thickness
  const std::string sec = "*SHELL SECTION, ELSET=S, MATERIAL=M\n0.1, 5\n";
  const std::string load = "*CLOAD\n3, 5, 1.\n6, 5, 1.\n";
  // the default: SNEG and SPOS (points 1 and 5) at each integration point (S4R: one)
  const auto d = s_rows(deck(sec, load + "*EL PRINT, ELSET=S\nS\n"));
  ASSERT_EQ(d.size(), 4u);
  EXPECT_EQ(d[0][1], 1.0);
  EXPECT_EQ(d[0][2], 1.0);
  EXPECT_EQ(d[1][2], 5.0);
  EXPECT_NEAR(d[0][3], -d[1][3], 1e-9 * std::abs(d[0][3]));
  EXPECT_GT(std::abs(d[0][3]), 1.0);
  // a data line of numbers selects section points: 2 and 3 (the mid-surface, zero in bending)
  const auto m = s_rows(deck(sec, load + "*EL PRINT, ELSET=S\n3, 2\nS\n"));
  ASSERT_EQ(m.size(), 4u);
  EXPECT_EQ(m[0][2], 2.0);
  EXPECT_EQ(m[1][2], 3.0);
  EXPECT_NEAR(m[0][3], 0.5 * d[0][3], 1e-9 * std::abs(d[0][3]));
  EXPECT_NEAR(m[1][3], 0.0, 1e-9 * std::abs(d[0][3]));
  // SM (Abaqus's section moments) prints the SF table, which holds the moments SM1-SM3
  {
    const JobResult r = test::run_deck(deck(sec, load + "*EL PRINT, ELSET=S\nSM\n"), true);
    ASSERT_EQ(r.exit_code, kExitOk) << r.error;
    std::ifstream in(test::test_dir() / "job.dat");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("SM1"), std::string::npos);
  }
  // section point 0 does not exist
  expect_input_error(deck(sec, load + "*EL PRINT, ELSET=S\n0\nS\n"),
                     "section points are numbered from 1");
}

TEST(ShellInput, GeneralSectionWithAMaterialIsTheHomogeneousSection) {
  // Abaqus/CAE writes *SHELL GENERAL SECTION for a homogeneous section integrated "before the
  // analysis": for an elastic material it is the same section
  const JobResult a = test::run_deck(deck("*SHELL SECTION, ELSET=S, MATERIAL=M\n0.1, 5\n"));
  const JobResult b =
      test::run_deck(deck("*SHELL GENERAL SECTION, ELSET=S, MATERIAL=M, OFFSET=SMID\n0.1,\n"));
  ASSERT_EQ(a.exit_code, kExitOk) << a.error;
  ASSERT_EQ(b.exit_code, kExitOk) << b.error;
  EXPECT_NEAR(tip_w(b), tip_w(a), 1e-12 * std::abs(tip_w(a)));
  EXPECT_EQ(b.model->shell_sections.at(0).n_points, 3);
  // *TRANSVERSE SHEAR STIFFNESS belongs to it as to *SHELL SECTION: a stiffer shear, less sag
  const JobResult c = test::run_deck(deck("*SHELL GENERAL SECTION, ELSET=S, MATERIAL=M\n0.1\n"
                                          "*TRANSVERSE SHEAR STIFFNESS\n1.e9, 1.e9\n"));
  ASSERT_EQ(c.exit_code, kExitOk) << c.error;
  EXPECT_LT(std::abs(tip_w(c)), std::abs(tip_w(a)));
  expect_input_error(deck("*SHELL GENERAL SECTION, ELSET=S\n1., 2., 3.\n"),
                     "a general shell section given by its stiffness matrix is not supported");
  expect_input_error(deck("*SHELL GENERAL SECTION, ELSET=S, MATERIAL=M\n0.1, 5\n"),
                     "this data line has at most 1 fields (thickness)");
}

TEST(ShellInput, AbaqusCaeLayoutWithTheSectionInThePart) {
  // Abaqus/CAE puts the shell section (and *NODAL THICKNESS, *TRANSVERSE SHEAR STIFFNESS) in the
  // part and the SPOS surface in the assembly: the same answer as the flat deck
  const std::string part =
      "*Part, name=Strip\n*Node\n1, 0, 0, 0\n2, 1, 0, 0\n3, 2, 0, 0\n4, 0, 1, 0\n5, 1, 1, 0\n"
      "6, 2, 1, 0\n*Element, type=S4R\n1, 1, 2, 5, 4\n2, 2, 3, 6, 5\n*Elset, elset=All\n1, 2\n"
      "*Shell Section, elset=All, material=M, nodal thickness\n, 5\n*Transverse Shear "
      "Stiffness\n1.e5, 1.e5\n*Nodal Thickness\n1, 0.1\n2, 0.1\n3, 0.1\n4, 0.1\n5, 0.1\n"
      "6, 0.1\n*End Part\n";
  const std::string assembly =
      "*Assembly, name=Assembly\n*Instance, name=Strip-1, part=Strip\n*End Instance\n"
      "*Nset, nset=Root, instance=Strip-1\n1, 4\n*Elset, elset=_Top_SPOS, internal, "
      "instance=Strip-1\n1, 2\n*Surface, type=ELEMENT, name=Top\n_Top_SPOS, SPOS\n"
      "*End Assembly\n*Material, name=M\n*Elastic\n210000., 0.3\n*Boundary\nRoot, "
      "ENCASTRE\n*Step, name=Step-1\n*Static\n*Dsload\nTop, P, 1.\n*End Step\n";
  const JobResult cae = test::run_deck(part + assembly);
  ASSERT_EQ(cae.exit_code, kExitOk) << cae.error;
  const JobResult flat = test::run_deck(deck("*SHELL SECTION, ELSET=S, MATERIAL=M\n0.1, 5\n"
                                             "*TRANSVERSE SHEAR STIFFNESS\n1.e5, 1.e5\n",
                                             "*DLOAD\nS, P, -1.\n"));
  ASSERT_EQ(flat.exit_code, kExitOk) << flat.error;
  const Frame& f = test::last_frame(cae);
  const double w = f.nodes.U[cae.model->mesh.find_node(make_key(1, 3))][2]; // instance 1, node 3
  EXPECT_NEAR(w, tip_w(flat), 1e-12 * std::abs(tip_w(flat)));
  EXPECT_LT(w, 0.0);
}

TEST(ShellInput, TemperatureGradientsAtNodesWithoutShellsOrBeamsAreReported) {
  // node 7 belongs to no element: its gradient would have no effect, which the reader says
  std::string text = deck("*SHELL SECTION, ELSET=S, MATERIAL=M\n0.1\n", "", "*EXPANSION\n1e-5\n");
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
  {
    std::string t = deck("*SHELL SECTION, ELSET=S, MATERIAL=M\n0.1\n", "*DSLOAD\nE, P, 1.\n");
    t.replace(t.find("*BOUNDARY"), 0, "*SURFACE, NAME=E\nS, S3\n");
    expect_input_error(t, "face 'S3' of a shell is an edge");
  }
  expect_input_error(deck("*SHELL SECTION, ELSET=S, MATERIAL=M\n0.\n"),
                     "the shell thickness must be positive, not 0");
  expect_input_error(deck("*SHELL SECTION, ELSET=S, MATERIAL=M\n-0.1\n"),
                     "the shell thickness must be positive, not -0.1");
  expect_input_error(deck("*SHELL SECTION, ELSET=S, MATERIAL=M\n0.1, 4\n"),
                     "Simpson's rule needs an odd number of points from 3 to 15 (1 for a "
                     "heat-transfer shell without a gradient through its thickness), not 4");
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
  expect_input_error(
      deck("*SHELL SECTION, ELSET=S, MATERIAL=M\n0.1\n", "*DLOAD\n1, GRAV, 9810., 0, 0, -1\n"),
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

namespace gapfem {
namespace {

/// An S4R strip (10 x 1 x 0.1, E = 1e6, nu = 0) clamped at x = 0; its two tip nodes rest on
/// GAPUNI elements to ground with clearance 0.1 (or, for the oracle, are held at -0.1).
std::string strip_on_gaps(bool gaps) {
  std::string s = "*NODE\n";
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 1; ++j)
      s += std::to_string(2 * i + j + 1) + ", " + std::to_string(2.5 * i) + ", " +
           std::to_string(j) + ", 0\n";
  s += "21, 10, 0, -1\n22, 10, 1, -1\n*ELEMENT, TYPE=S4R, ELSET=S\n";
  for (int i = 0; i < 4; ++i)
    s += std::to_string(i + 1) + ", " + std::to_string(2 * i + 1) + ", " +
         std::to_string(2 * i + 3) + ", " + std::to_string(2 * i + 4) + ", " +
         std::to_string(2 * i + 2) + "\n";
  s += "*SHELL SECTION, ELSET=S, MATERIAL=M\n0.1\n*MATERIAL, NAME=M\n*ELASTIC\n1e6, 0\n";
  if (gaps)
    s += "*ELEMENT, TYPE=GAPUNI, ELSET=G\n11, 9, 21\n12, 10, 22\n*GAP, ELSET=G\n0.1, 0, 0, -1\n";
  s += "*BOUNDARY\n1, 1, 6\n2, 1, 6\n21, 1, 3\n22, 1, 3\n";
  s += "*STEP\n*STATIC\n";
  if (!gaps) s += "*BOUNDARY\n9, 3, 3, -0.1\n10, 3, 3, -0.1\n";
  s += "*CLOAD\n9, 3, -0.05\n10, 3, -0.05\n*END STEP\n";
  return s;
}

TEST(ShellGaps, StripOnGapUniSupportsMatchesTheHeldStrip) {
  // free, the tip would deflect F L^3 / (3 E I) = 0.4 > 0.1: both gaps close, the tip sits at
  // -0.1 and each gap carries what holding the tip there costs (the oracle's reaction)
  const JobResult a = test::run_deck(strip_on_gaps(true));
  ASSERT_EQ(a.exit_code, kExitOk) << a.error;
  const JobResult b = test::run_deck(strip_on_gaps(false));
  ASSERT_EQ(b.exit_code, kExitOk) << b.error;
  const Frame& fa = test::last_frame(a);
  const Frame& fb = test::last_frame(b);
  for (Label n : {9, 10}) {
    EXPECT_NEAR(test::U(a, fa, n)[2], -0.1, 1e-9);
    const GapRecord& g = test::gap(a, fa, n + 2);
    EXPECT_EQ(g.status, ContactStatus::Closed);
    EXPECT_NEAR(g.normal_force, test::RF(b, fb, n)[2], 1e-9);
    EXPECT_GT(g.normal_force, 0.0);
  }
}

} // namespace
} // namespace gapfem
