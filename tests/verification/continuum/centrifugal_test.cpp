// CENTRIF against closed forms.
// 1. The rotating annular disc (plane stress; Timoshenko & Goodier, "Theory of Elasticity",
//    rotating disks of uniform thickness): inner radius a = 0.2, outer b = 1, free edges,
//    E = 2.1e11, nu = 0.3, rho = 7850, omega^2 = 1e4 (CENTRIF magnitude), the axis through the
//    origin along z. With k = (3 + nu) / 8 rho omega^2,
//      sigma_r     = k (b^2 + a^2 - a^2 b^2 / r^2 - r^2),
//      sigma_theta = k (b^2 + a^2 + a^2 b^2 / r^2 - (1 + 3 nu) / (3 + nu) r^2),
//      u(r)        = r (sigma_theta - nu sigma_r) / E.
//    A quarter of the disc, 16 x 12 CPS8 (symmetry on both cut edges): the radial displacement
//    of every node within 5e-5 of u(b) (measured 2.7e-5, at the inner edge, where the stresses
//    vary fastest; 3.2e-4 with 8 elements across: the error falls as h^3.6); without NLGEOM the
//    load is constant: one iteration per increment.
// 2. A unit C3D8 cube (rho = 1: m = 1) from x = 1 to 2 on eight SPRING1 of 0.25 (k = 2 in all)
//    along x, held in y and z, spun about z with omega^2 = 1: the centroid (r = 1.5) moves out by
//    u with k u = m omega^2 (1.5 + u) under NLGEOM (the force at the current radius): u = 1.5, and
//    by m omega^2 1.5 / k = 0.75 without (the mean of the nodes' x-displacements is the mass
//    average, so the cube's own stretch, 4e-8 with E = 1e6, does not enter). The NLGEOM problem is
//    linear in u, so with the load stiffness -m omega^2 Newton's first iteration solves it.
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <numbers>

namespace gapfem {
namespace {

constexpr double kA = 0.2, kB = 1.0, kE = 2.1e11, kNu = 0.3, kRho = 7850.0, kOmega2 = 1.0e4;
constexpr int kNr = 16, kNt = 12;

double exact_u(double r) {
  const double k = (3 + kNu) / 8 * kRho * kOmega2, a2 = kA * kA, b2 = kB * kB;
  const double sr = k * (b2 + a2 - a2 * b2 / (r * r) - r * r);
  const double st = k * (b2 + a2 + a2 * b2 / (r * r) - (1 + 3 * kNu) / (3 + kNu) * r * r);
  return r * (st - kNu * sr) / kE;
}

Label node_id(int i, int j) {
  return 1 + i + (2 * kNr + 1) * j;
}

std::string disc() {
  std::string d = "*HEADING\nrotating annular disc\n*NODE, NSET=ALL\n";
  for (int j = 0; j <= 2 * kNt; ++j)
    for (int i = 0; i <= 2 * kNr; ++i) {
      if (i % 2 == 1 && j % 2 == 1) continue; // CPS8 has no centre node
      const double r = kA + (kB - kA) * i / (2.0 * kNr);
      const double t = std::numbers::pi / 2 * j / (2.0 * kNt);
      d += fmt::format("{}, {:.17g}, {:.17g}, 0.\n", node_id(i, j), r * std::cos(t),
                       r * std::sin(t));
    }
  d += "*ELEMENT, TYPE=CPS8, ELSET=DISC\n";
  int e = 0;
  for (int ej = 0; ej < kNt; ++ej)
    for (int ei = 0; ei < kNr; ++ei) {
      const int i = 2 * ei, j = 2 * ej;
      d +=
          fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", ++e, node_id(i, j), node_id(i + 2, j),
                      node_id(i + 2, j + 2), node_id(i, j + 2), node_id(i + 1, j),
                      node_id(i + 2, j + 1), node_id(i + 1, j + 2), node_id(i, j + 1));
    }
  d += "*NSET, NSET=YSYM\n";
  for (int i = 0; i <= 2 * kNr; ++i) d += fmt::format("{}\n", node_id(i, 0));
  d += "*NSET, NSET=XSYM\n";
  for (int i = 0; i <= 2 * kNr; ++i) d += fmt::format("{}\n", node_id(i, 2 * kNt));
  d += fmt::format("*SOLID SECTION, ELSET=DISC, MATERIAL=STEEL\n1.\n*MATERIAL, NAME=STEEL\n"
                   "*ELASTIC\n{}, {}\n*DENSITY\n{}\n*BOUNDARY\nYSYM, 2, 2\nXSYM, 1, 1\n",
                   kE, kNu, kRho);
  d += "*STEP\n*STATIC\n";
  d += fmt::format("*DLOAD\nDISC, CENTRIF, {}, 0., 0., 0., 0., 0., 1.\n*END STEP\n", kOmega2);
  return d;
}

/// The largest |radial displacement - u(r)| over every node, relative to u(b).
double worst_error(const JobResult& r) {
  const Frame* f = r.step_end(1);
  EXPECT_NE(f, nullptr);
  if (!f) return 1.0;
  double worst = 0.0;
  for (int j = 0; j <= 2 * kNt; ++j)
    for (int i = 0; i <= 2 * kNr; ++i) {
      if (i % 2 == 1 && j % 2 == 1) continue;
      const double rad = kA + (kB - kA) * i / (2.0 * kNr);
      const Vec3& u = test::U(r, *f, node_id(i, j));
      const double ur = std::hypot(u[0], u[1]);
      worst = std::max(worst, std::abs(ur - exact_u(rad)) / exact_u(kB));
    }
  return worst;
}

TEST(VerificationCentrifugal, RotatingAnnularDiscGivesTheClosedForm) {
  const JobResult r = test::run_deck(disc());
  ASSERT_EQ(r.exit_code, 0) << r.error;
  EXPECT_LT(worst_error(r), 5e-5);
  for (const IncrementInfo& inc : r.increments) EXPECT_EQ(inc.iterations, 1);
}

std::string spinning_block(bool nlgeom) {
  std::string d = "*NODE, NSET=ALL\n";
  const int corners[8][3] = {{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0},
                             {1, 0, 1}, {2, 0, 1}, {2, 1, 1}, {1, 1, 1}};
  for (int a = 0; a < 8; ++a)
    d += fmt::format("{}, {}., {}., {}.\n", a + 1, corners[a][0], corners[a][1], corners[a][2]);
  d += "*ELEMENT, TYPE=C3D8, ELSET=BLOCK\n1, 1, 2, 3, 4, 5, 6, 7, 8\n*ELEMENT, TYPE=SPRING1, "
       "ELSET=K\n";
  for (int a = 1; a <= 8; ++a) d += fmt::format("{}, {}\n", 10 + a, a);
  d += "*SPRING, ELSET=K\n1\n0.25\n*SOLID SECTION, ELSET=BLOCK, MATERIAL=M\n*MATERIAL, NAME=M\n"
       "*ELASTIC\n1e6, 0.\n*DENSITY\n1.\n*BOUNDARY\nALL, 2, 3\n";
  d += nlgeom ? "*STEP, NLGEOM\n*STATIC\n0.25, 1.\n" : "*STEP\n*STATIC\n";
  return d + "*DLOAD\nBLOCK, CENTRIF, 1., 0., 0., 0., 0., 0., 1.\n*END STEP\n";
}

TEST(VerificationCentrifugal, NlgeomPushesAtTheCurrentRadius) {
  for (const bool nlgeom : {false, true}) {
    SCOPED_TRACE(nlgeom ? "NLGEOM" : "small displacements");
    const JobResult r = test::run_deck(spinning_block(nlgeom));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    const Frame* f = r.step_end(1);
    ASSERT_NE(f, nullptr);
    double mean = 0.0;
    for (Label n = 1; n <= 8; ++n) mean += test::U(r, *f, n)[0] / 8.0;
    EXPECT_NEAR(mean, nlgeom ? 1.5 : 0.75, 1e-9);
    // the exact load stiffness: Newton's first iteration solves the increment; the stiff cube's
    // round-off may ask for one or two more (clang's build), where a tangent without the load
    // stiffness (-m omega^2 against k = 2) would converge by halves, some 30 iterations
    for (const IncrementInfo& inc : r.increments) EXPECT_LE(inc.iterations, nlgeom ? 3 : 1);
  }
}

TEST(VerificationCentrifugal, CentrifOnABeamOrWithoutDensityIsAClearError) {
  const std::string beam =
      "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=B31, ELSET=B\n1, 1, 2\n*BEAM "
      "SECTION, ELSET=B, MATERIAL=M, SECTION=RECT\n0.1, 0.1\n0., 0., 1.\n*MATERIAL, NAME=M\n"
      "*ELASTIC\n2e11, 0.3\n*DENSITY\n7850.\n*BOUNDARY\n1, 1, 6\n*STEP\n*STATIC\n*DLOAD\nB, "
      "CENTRIF, 1e4, 0., 0., 0., 0., 0., 1.\n*END STEP\n";
  const JobResult rb = test::run_deck(beam);
  EXPECT_NE(rb.exit_code, 0);
  EXPECT_NE(rb.error.find("CENTRIF is available on continuum elements"), std::string::npos)
      << rb.error;
  std::string d = disc();
  d.erase(d.find("*DENSITY"), d.find("*BOUNDARY") - d.find("*DENSITY"));
  const JobResult rd = test::run_deck(d);
  EXPECT_NE(rd.exit_code, 0);
  EXPECT_NE(rd.error.find("CENTRIF on element"), std::string::npos) << rd.error;
  EXPECT_NE(rd.error.find("needs *DENSITY"), std::string::npos) << rd.error;
}

} // namespace
} // namespace gapfem
