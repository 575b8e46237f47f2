// *BUCKLE and static perturbation steps against closed forms (docs/theory/buckling.md).
// Column: L = 1, E = 2e11, RECT 0.01 x 0.01 (EI = 2e11 x 1e-8 / 12 = 166.667), 40 B31, held out
// of the x-y plane (DOFs 3-5), axial load -1 at the top: eigenvalues are Euler loads.
// 1. Pinned-pinned (node 1 held in 1, 2; the top in 2): P_n = n^2 pi^2 EI / L^2 = 1644.934,
//    6579.736, 14804.41. The Timoshenko member with 40 elements is within +2.6e-4, +1.1e-3,
//    +2.4e-3 of them (a separate beam model with the consistent geometric stiffness, the
//    decks' helper script): tolerances 1e-3, 5e-3, 5e-3.
// 2. Cantilever (node 1 clamped): P_n = (2n - 1)^2 pi^2 EI / (4 L^2) = 411.2335, 3701.102.
// 3. The pinned column with a GAPUNI brace at mid-height (clearance 1e-4, direction +y to a
//    fixed node): pushed against it by 10 in a general step, the closed brace is a bilateral
//    support in the perturbation (frozen contact status, Abaqus): the first mode is the second
//    Euler mode 4 pi^2 EI / L^2 = 6579.736, the next the half column pinned-clamped
//    (tan(beta) = beta, beta = 4.4934: P = (2 beta)^2 EI / L^2 = 80.763 EI = 13460.5). With a
//    clearance of 1e-2 the brace stays open and adds nothing: pi^2 EI / L^2 again.
//    With half the Euler load applied first in an NLGEOM general step, the eigenvalues are what
//    is left of each load (P + lambda Q buckles): P_E - P_E / 2.
// 4. Static perturbation: a B31 cantilever (L = 1, 10 elements) under 10 along y, then a
//    perturbation step with -4 along y and 2 along z at the tip: the response is the
//    perturbation alone, c = L^3 / (3 EI) + L / (k G A) per unit load (B31 is exact for
//    end-loaded members; k = 10 (1 + nu) / (12 + 11 nu) = 0.85 for a rectangle, Abaqus's
//    table: c = 2.0001529411765e-3), and the next general step carries on from the base state,
//    not from the perturbation.
// 5. The von Mises truss: two T2D2 (EA = 1e4) from (-1, 0) and (1, 0), pinned, to the apex (0,
// 0.2),
//    load -1 along y at the apex. Each bar (n = (+-cos a, sin a), sin a = 0.2 / L, L = sqrt(1.04))
//    carries N = -P / (2 sin a); K0 = EA / L diag(2 cos^2 a, 2 sin^2 a), and the initial-stress
//    matrix of the NLGEOM tangent with N in place of the force, N / L (I - n n^T) per bar, sums to
//    2 N / L diag(sin^2 a, cos^2 a): lambda_y = 2 EA sin^3 a / (P cos^2 a) = 156.8929 (the
//    symmetric mode), lambda_x = 2 EA cos^2 a / (P sin a) = 98058.07. The same with SPRINGA of
//    k = EA / L (in space: the nodes held along z). (The difference of the NLGEOM tangent along the
//    perturbation, which the element would get without its own matrix, adds the bars' rotation
//    terms EA / L (dn n^T + n dn^T): 3 times the stress term in y here.)
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>

namespace gapfem {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kEI = 2e11 * 1e-8 / 12.0;

/// The column of 40 B31 along x, with `extra` model data and `steps` history.
std::string column(bool pinned, const std::string& extra, const std::string& steps) {
  std::string d = "*HEADING\nA column\n*NODE, NSET=ALL\n";
  const int n = 40;
  for (int i = 0; i <= n; ++i) d += fmt::format("{}, {:.17g}, 0., 0.\n", i + 1, double(i) / n);
  d += "*NSET, NSET=TOP\n41\n*NSET, NSET=MID\n21\n*ELEMENT, TYPE=B31, ELSET=COL\n";
  for (int i = 1; i <= n; ++i) d += fmt::format("{}, {}, {}\n", i, i, i + 1);
  d += extra;
  d += "*BEAM SECTION, ELSET=COL, MATERIAL=STEEL, SECTION=RECT\n0.01, 0.01\n0., 0., -1.\n"
       "*MATERIAL, NAME=STEEL\n*ELASTIC\n2e11, 0.3\n*BOUNDARY\nALL, 3, 5\n";
  d += pinned ? "1, 1, 2\nTOP, 2, 2\n" : "1, 1, 6\n";
  return d + steps;
}

const EigenSummary& modes_of(const JobResult& r, int step_index) {
  for (const auto& [index, m] : r.modes)
    if (index == step_index) return m;
  throw std::runtime_error("no modes for that step");
}

constexpr const char* kBuckleStep = "*STEP\n*BUCKLE\n3\n*CLOAD\nTOP, 1, -1.\n*END STEP\n";

TEST(VerificationBuckle, PinnedColumnGivesTheEulerLoads) {
  const JobResult r = test::run_deck(column(true, "", kBuckleStep));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const EigenSummary& m = modes_of(r, 0);
  ASSERT_EQ(m.modes.size(), 3u);
  EXPECT_TRUE(m.buckling);
  const double pe = kPi * kPi * kEI;
  EXPECT_NEAR(m.modes[0].eigenvalue, pe, 1e-3 * pe);
  EXPECT_NEAR(m.modes[1].eigenvalue, 4 * pe, 5e-3 * 4 * pe);
  EXPECT_NEAR(m.modes[2].eigenvalue, 9 * pe, 5e-3 * 9 * pe);
  // mode 1: a half sine, largest at mid-height, normalised to 1 there
  ASSERT_EQ(r.frames.size(), 3u);
  EXPECT_NEAR(std::abs(test::U(r, r.frames[0], 21)[1]), 1.0, 1e-9);
  EXPECT_NEAR(test::U(r, r.frames[0], 11)[1] / test::U(r, r.frames[0], 21)[1], std::sin(kPi / 4),
              1e-3);
}

TEST(VerificationBuckle, AnNlgeomPreloadIsPartOfTheBaseState) {
  // half the Euler load applied in a general NLGEOM step: K0 holds its initial stress, and the
  // perturbation load's multiplier is what is left, P_E - P (the buckling load is P + lambda Q)
  const double pe = kPi * kPi * kEI, preload = 0.5 * pe;
  const JobResult r = test::run_deck(
      column(true, "",
             fmt::format("*STEP, NLGEOM\n*STATIC\n*CLOAD\nTOP, 1, {:.17g}\n*END STEP\n{}", -preload,
                         kBuckleStep)));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const EigenSummary& m = modes_of(r, 1);
  EXPECT_NEAR(m.modes[0].eigenvalue, pe - preload, 1e-3 * pe);
  EXPECT_NEAR(m.modes[1].eigenvalue, 4 * pe - preload, 5e-3 * 4 * pe);
}

TEST(VerificationBuckle, CantileverGivesTheEffectiveLengthTwoL) {
  const JobResult r = test::run_deck(column(false, "", kBuckleStep));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const EigenSummary& m = modes_of(r, 0);
  ASSERT_EQ(m.modes.size(), 3u);
  const double p1 = kPi * kPi * kEI / 4;
  EXPECT_NEAR(m.modes[0].eigenvalue, p1, 1e-3 * p1);
  EXPECT_NEAR(m.modes[1].eigenvalue, 9 * p1, 5e-3 * 9 * p1);
}

std::string braced(double clearance) {
  const std::string brace = fmt::format("*NODE\n900, 0.5, 0.01, 0.\n*ELEMENT, TYPE=GAPUNI, "
                                        "ELSET=BRACE\n901, 21, 900\n*GAP, ELSET=BRACE\n{}, 0., "
                                        "1., 0.\n",
                                        clearance);
  return column(true, brace,
                "*BOUNDARY\n900, 1, 6\n*STEP\n*STATIC\n*CLOAD\nMID, 2, 10.\n*END STEP\n" +
                    std::string(kBuckleStep));
}

TEST(VerificationBuckle, ClosedGapBraceIsASupportAndAnOpenOneIsNothing) {
  const double pe = kPi * kPi * kEI;
  const JobResult closed = test::run_deck(braced(1e-4));
  ASSERT_EQ(closed.exit_code, 0) << closed.error;
  const EigenSummary& mc = modes_of(closed, 1);
  ASSERT_EQ(mc.modes.size(), 3u);
  EXPECT_NEAR(mc.modes[0].eigenvalue, 4 * pe, 5e-3 * 4 * pe);
  const double beta = 4.493409457909064; // tan(beta) = beta
  const double half = 4 * beta * beta * kEI;
  EXPECT_NEAR(mc.modes[1].eigenvalue, half, 5e-3 * half);
  const JobResult open = test::run_deck(braced(1e-2));
  ASSERT_EQ(open.exit_code, 0) << open.error;
  const EigenSummary& mo = modes_of(open, 1);
  EXPECT_NEAR(mo.modes[0].eigenvalue, pe, 1e-3 * pe);
}

TEST(VerificationBuckle, NoPerturbationLoadIsAClearError) {
  const JobResult r = test::run_deck(column(true, "", "*STEP\n*BUCKLE\n1\n*END STEP\n"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.error.find("no perturbation load"), std::string::npos) << r.error;
}

TEST(VerificationBuckle, TensionOnlyGivesNegativeEigenvaluesWithAWarning) {
  // a pull: the column buckles only under the load reversed (eigenvalue -P_E)
  const JobResult r =
      test::run_deck(column(true, "", "*STEP\n*BUCKLE\n1\n*CLOAD\nTOP, 1, 1.\n*END STEP\n"));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const double pe = kPi * kPi * kEI;
  EXPECT_NEAR(modes_of(r, 0).modes[0].eigenvalue, -pe, 1e-3 * pe);
}

/// A B31 cantilever of 10 elements along x (same section), steps as given.
std::string cantilever(const std::string& steps) {
  std::string d = "*HEADING\nA cantilever\n*NODE, NSET=ALL\n";
  for (int i = 0; i <= 10; ++i) d += fmt::format("{}, {:.17g}, 0., 0.\n", i + 1, i / 10.0);
  d += "*NSET, NSET=TIP\n11\n*ELEMENT, TYPE=B31, ELSET=BEAM\n";
  for (int i = 1; i <= 10; ++i) d += fmt::format("{}, {}, {}\n", i, i, i + 1);
  d += "*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=RECT\n0.01, 0.01\n0., 0., -1.\n"
       "*MATERIAL, NAME=STEEL\n*ELASTIC\n2e11, 0.3\n*BOUNDARY\n1, 1, 6\n";
  return d + steps;
}

TEST(VerificationBuckle, StaticPerturbationIsTheLinearResponseAlone) {
  const JobResult r = test::run_deck(
      cantilever("*STEP\n*STATIC\n*CLOAD\nTIP, 2, 10.\n*END STEP\n"
                 "*STEP, PERTURBATION\n*STATIC\n*CLOAD\nTIP, 2, -4.\nTIP, 3, 2.\n*END STEP\n"
                 "*STEP\n*STATIC\n*END STEP\n"));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  // c = L^3 / (3 EI) + L / (k G A): k = 0.85, G = E / 2.6
  const double c = 1.0 / (3 * kEI) + 1.0 / (0.85 * 2e11 / 2.6 * 1e-4);
  const Frame& base = test::last_frame(r, 1);
  const Frame& pert = test::last_frame(r, 2);
  const Frame& after = test::last_frame(r, 3);
  EXPECT_NEAR(test::U(r, base, 11)[1], 10 * c, 1e-9 * 10 * c);
  EXPECT_NEAR(test::U(r, pert, 11)[1], -4 * c, 1e-9 * 4 * c);
  EXPECT_NEAR(test::U(r, pert, 11)[2], 2 * c, 1e-9 * 2 * c);
  EXPECT_NEAR(test::U(r, after, 11)[1], 10 * c, 1e-9 * 10 * c);
  EXPECT_NEAR(test::U(r, after, 11)[2], 0.0, 1e-12);
}

TEST(VerificationBuckle, StaticPerturbationStressesAreThePerturbations) {
  // a bar (A = 1e-4) pulled by 1000, then a perturbation of 10: S11 = 10 / A = 1e5 in the
  // perturbation step, 1e7 again in the general step after it
  const std::string deck = R"(*HEADING
A bar
*NODE
1, 0., 0., 0.
2, 1., 0., 0.
3, 2., 0., 0.
*ELEMENT, TYPE=T3D2, ELSET=BAR
1, 1, 2
2, 2, 3
*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL
1e-4
*MATERIAL, NAME=STEEL
*ELASTIC
2e11, 0.3
*BOUNDARY
1, 1, 3
2, 2, 3
3, 2, 3
*STEP
*STATIC
*CLOAD
3, 1, 1000.
*END STEP
*STEP, PERTURBATION
*STATIC
*CLOAD
3, 1, 10.
*EL PRINT
S
*END STEP
*STEP
*STATIC
*END STEP
)";
  const JobResult r = test::run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto s11 = [&](int step) {
    const Frame& f = test::last_frame(r, step);
    const ElementResult* e = f.element(r.model->mesh.find_element(2));
    const OutputBlock* b = e ? e->data.find(ElemVar::S) : nullptr;
    return b ? b->values.at(0) : -1.0;
  };
  EXPECT_NEAR(s11(2), 1e5, 1e-6 * 1e5);
  EXPECT_NEAR(s11(3), 1e7, 1e-9 * 1e7);
  EXPECT_NEAR(test::U(r, test::last_frame(r, 2), 3)[0], 10.0 * 2.0 / (2e11 * 1e-4), 1e-15);
}

} // namespace
TEST(VerificationBuckle, TheVonMisesTrussGivesItsBifurcationLoads) {
  const double L = std::sqrt(1.04), sa = 0.2 / L, ca = 1.0 / L, EA = 1e4;
  const double ly = 2 * EA * sa * sa * sa / (ca * ca), lx = 2 * EA * ca * ca / sa;
  const std::string nodes = "*NODE\n1, -1., 0.\n2, 1., 0.\n3, 0., 0.2\n";
  const std::string rest = "*BOUNDARY\n1, 1, 2\n2, 1, 2\n*STEP\n*BUCKLE\n2\n*CLOAD\n3, 2, "
                           "-1.\n*END STEP\n";
  const std::string in_plane = "*BOUNDARY\n1, 3, 3\n2, 3, 3\n3, 3, 3\n";
  const std::string truss = nodes +
                            "*ELEMENT, TYPE=T2D2, ELSET=BARS\n1, 1, 3\n2, 2, 3\n"
                            "*SOLID SECTION, ELSET=BARS, MATERIAL=M\n1.\n*MATERIAL, "
                            "NAME=M\n*ELASTIC\n1e4, 0.3\n" +
                            rest;
  const std::string springs = nodes +
                              fmt::format("*ELEMENT, TYPE=SPRINGA, ELSET=BARS\n1, 1, 3\n"
                                          "2, 2, 3\n*SPRING, ELSET=BARS\n\n{:.17g}\n",
                                          EA / L) +
                              in_plane + rest;
  for (const std::string& deck : {truss, springs}) {
    const JobResult r = test::run_deck(deck);
    ASSERT_EQ(r.exit_code, 0) << r.error;
    const EigenSummary& m = modes_of(r, 0);
    ASSERT_EQ(m.modes.size(), 2u);
    EXPECT_NEAR(m.modes[0].eigenvalue, ly, 1e-9 * ly);
    EXPECT_NEAR(m.modes[1].eigenvalue, lx, 1e-9 * lx);
    EXPECT_NEAR(std::abs(test::U(r, r.frames[0], 3)[1]), 1.0, 1e-12); // the apex drops
  }
}

} // namespace gapfem
