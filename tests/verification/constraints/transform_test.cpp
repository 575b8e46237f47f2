// *TRANSFORM (issue 12): boundary conditions, loads, *EQUATION terms and nodal output in local
// systems.
// - An inclined roller (rectangular system rotated by theta about z) at the end of a T3D2 bar
//   along x: the node moves along e1 only; a load P along e1 (given in the local system) gives
//   s = P / (k cos^2 theta), the roller's reaction along e2 is -P tan(theta) (closed form); the
//   same with the roller written as a one-term *EQUATION on the local DOF 2.
// - A CPE4 ring sector under internal pressure, with one symmetry edge held by global boundary
//   conditions and the other, inclined, by a cylindrical system, gives (rotated) the answer of
//   the same sector rotated so that the roles of the two edges swap (to 1e-10).
// - Bad transforms are input errors.
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>

using namespace gapfem;
using namespace gapfem::test;

namespace {
const double kPi = std::acos(-1.0);

std::string roller(double theta_deg, bool as_equation) {
  const double t = theta_deg * kPi / 180.0;
  std::string d = fmt::format(
      "*HEADING\ninclined roller\n*NODE\n1, 0., 0., 0.\n2, 2., 0., 0.\n*NSET, NSET=END\n2\n"
      "*TRANSFORM, NSET=END\n{:.17g}, {:.17g}, 0., {:.17g}, {:.17g}, 0.\n"
      "*ELEMENT, TYPE=T3D2, ELSET=BAR\n1, 1, 2\n*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n"
      "*SOLID SECTION, ELSET=BAR, MATERIAL=M\n0.5\n",
      std::cos(t), std::sin(t), -std::sin(t), std::cos(t));
  if (as_equation) d += "*EQUATION\n1\n2, 2, 1.\n";
  d += "*STEP\n*STATIC\n*BOUNDARY\n1, 1, 3\n2, 3, 3\n";
  if (!as_equation) d += "2, 2, 2\n";
  return d + "*CLOAD\n2, 1, 3.\n*END STEP\n";
}
} // namespace

TEST(Transform, InclinedRollerClosedForm) {
  const double theta = 25.0, t = theta * kPi / 180.0, P = 3.0, k = 1000.0 * 0.5 / 2.0;
  const double s = P / (k * std::cos(t) * std::cos(t));
  for (bool eq : {false, true}) {
    const JobResult r = run_deck(roller(theta, eq));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    const Frame& f = last_frame(r);
    // output in the local system: U1 = s along the roller, U2 = 0 across it
    EXPECT_NEAR(U(r, f, 2)[0], s, 1e-12);
    EXPECT_NEAR(U(r, f, 2)[1], 0.0, 1e-14);
    EXPECT_NEAR(f.nodes.CF[r.model->mesh.find_node(2)][0], P, 1e-14);
    if (!eq) EXPECT_NEAR(RF(r, f, 2)[1], -P * std::tan(t), 1e-10);
    // the bar's support takes the axial force N = k s cos(theta)
    EXPECT_NEAR(RF(r, f, 1)[0], -k * s * std::cos(t), 1e-10);
    EXPECT_EQ(r.increments.front().iterations, 1);
  }
}

// *NODE PRINT prints U at a *TRANSFORM node in its local system by default and in global
// components with GLOBAL=YES: (s, 0) and s (cos theta, sin theta).
TEST(Transform, NodePrintGlobalYesPrintsGlobalComponents) {
  const double theta = 25.0, t = theta * kPi / 180.0, P = 3.0, k = 1000.0 * 0.5 / 2.0;
  const double s = P / (k * std::cos(t) * std::cos(t));
  for (bool global : {false, true}) {
    std::string d = roller(theta, false);
    d.insert(d.find("*END STEP"),
             global ? "*NODE PRINT, NSET=END, GLOBAL=YES\nU\n" : "*NODE PRINT, NSET=END\nU\n");
    const JobResult r = run_deck(d, true, global ? "global" : "local");
    ASSERT_EQ(r.exit_code, 0) << r.error;
    std::ifstream in(test_dir() / (global ? "global.dat" : "local.dat"));
    std::string line, row;
    while (std::getline(in, line))
      if (line.rfind("          2    ", 0) == 0) row = line;
    ASSERT_FALSE(row.empty());
    const double u1 = std::stod(row.substr(15, 12)), u2 = std::stod(row.substr(27, 12));
    EXPECT_NEAR(u1, global ? s * std::cos(t) : s, 1e-4 * s) << row;
    EXPECT_NEAR(u2, global ? s * std::sin(t) : 0.0, 1e-4 * s) << row;
  }
}

namespace {
// Ring sector 1 <= r <= 2, theta0 <= theta <= theta0 + 30 degrees, CPE4 4 x 6, internal pressure
// 10 on the inner edge. Node (i, j) = 1 + i + 5 j (i radial, j angular).
std::string sector(double theta0_deg, bool transform_at_top) {
  std::string d = "*HEADING\nring sector\n*NODE\n";
  for (int j = 0; j <= 6; ++j)
    for (int i = 0; i <= 4; ++i) {
      const double r = 1.0 + 0.25 * i, a = (theta0_deg + 5.0 * j) * kPi / 180.0;
      d += fmt::format("{}, {:.17g}, {:.17g}\n", 1 + i + 5 * j, r * std::cos(a), r * std::sin(a));
    }
  d += "*ELEMENT, TYPE=CPE4, ELSET=ALL\n";
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 4; ++i) {
      const int n = 1 + i + 5 * j;
      d += fmt::format("{}, {}, {}, {}, {}\n", 1 + i + 4 * j, n, n + 1, n + 6, n + 5);
    }
  d += "*NSET, NSET=EDGE0\n1, 2, 3, 4, 5\n*NSET, NSET=EDGE1\n31, 32, 33, 34, 35\n"
       "*ELSET, ELSET=INNER\n1, 5, 9, 13, 17, 21\n*SURFACE, NAME=IN\nINNER, S4\n"
       "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*SOLID SECTION, ELSET=ALL, MATERIAL=M\n";
  // the inclined edge gets a cylindrical system (axis z through the origin); the other is
  // aligned with x and held by a global boundary condition
  const char* inclined = transform_at_top ? "EDGE1" : "EDGE0";
  const char* aligned = transform_at_top ? "EDGE0" : "EDGE1";
  d += fmt::format("*TRANSFORM, NSET={}, TYPE=C\n0., 0., 0., 0., 0., 1.\n", inclined);
  d += fmt::format("*STEP\n*STATIC\n*BOUNDARY\n{}, 2, 2\n{}, 2, 2\n*DSLOAD\nIN, P, 10.\n"
                   "*END STEP\n",
                   aligned, inclined);
  return d;
}
} // namespace

TEST(Transform, CylindricalSymmetryEdgeMatchesTheRotatedSector) {
  const JobResult a = run_deck(sector(0.0, true), false, "a");    // edge at 30 deg: local
  const JobResult b = run_deck(sector(-30.0, false), false, "b"); // edge at -30 deg: local
  ASSERT_EQ(a.exit_code, 0) << a.error;
  ASSERT_EQ(b.exit_code, 0) << b.error;
  const Frame& fa = last_frame(a);
  const Frame& fb = last_frame(b);
  // deck b is deck a rotated by -30 degrees: u_b = R(-30) u_a at every node (global components;
  // the transformed nodes report (u_r, u_theta), the same in both decks)
  const double c = std::cos(-kPi / 6), s = std::sin(-kPi / 6);
  auto global = [](const JobResult& r, const Frame& f, int label) {
    const NodeId n = r.model->mesh.find_node(label);
    Vec3 u = f.nodes.U[n];
    const auto it = f.nodes.local_axes.find(n);
    if (it != f.nodes.local_axes.end()) {
      const auto& Q = it->second;
      u = {Q[0] * u[0] + Q[3] * u[1], Q[1] * u[0] + Q[4] * u[1], 0.0};
    }
    return u;
  };
  double scale = 0.0;
  for (int l = 1; l <= 35; ++l) scale = std::max(scale, std::abs(global(a, fa, l)[0]));
  ASSERT_GT(scale, 0.0);
  for (int l = 1; l <= 35; ++l) {
    const Vec3 ua = global(a, fa, l), ub = global(b, fb, l);
    EXPECT_NEAR(ub[0], c * ua[0] - s * ua[1], 1e-10 * scale) << l;
    EXPECT_NEAR(ub[1], s * ua[0] + c * ua[1], 1e-10 * scale) << l;
  }
  // at the transformed edge the tangential displacement is zero and the radial reaction too
  for (int l = 31; l <= 35; ++l) {
    EXPECT_NEAR(U(a, fa, l)[1], 0.0, 1e-12 * scale);
    EXPECT_NEAR(RF(a, fa, l)[0], 0.0, 1e-9);
  }
}

// A bar along the axis of a cylindrical system: its nodes have an arbitrary radial direction,
// which nothing depends on when local 1 and 2 are held together; the axial load P along local 3
// gives u3 = P L / (E A) (L = 2, E A = 1000 x 0.5).
TEST(Transform, NodesOnTheCylinderAxisHeldInBothDirections) {
  const std::string d =
      "*NODE\n1, 0., 0., 0.\n2, 0., 0., 2.\n*NSET, NSET=ALLN\n1, 2\n*TRANSFORM, NSET=ALLN, TYPE=C\n"
      "0., 0., -1., 0., 0., 1.\n*ELEMENT, TYPE=T3D2, ELSET=B\n1, 1, 2\n*MATERIAL, NAME=M\n"
      "*ELASTIC\n1000., 0.3\n*SOLID SECTION, ELSET=B, MATERIAL=M\n0.5\n*STEP\n*STATIC\n"
      "*BOUNDARY\n1, 1, 3\n2, 1, 2\n*CLOAD\n2, 3, 7.\n*END STEP\n";
  const JobResult r = run_deck(d);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  EXPECT_NEAR(U(r, f, 2)[2], 7.0 * 2.0 / 500.0, 1e-14);
  EXPECT_NEAR(RF(r, f, 1)[2], -7.0, 1e-12);
}

TEST(Transform, BadTransformsAreInputErrors) {
  const std::string head = "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=T3D2, ELSET=B\n"
                           "1, 1, 2\n*MATERIAL, NAME=M\n*ELASTIC\n1., 0.3\n*SOLID SECTION, "
                           "ELSET=B, MATERIAL=M\n1.\n*NSET, NSET=ALLN\n1, 2\n";
  const std::string step = "*STEP\n*STATIC\n*BOUNDARY\n1, 1, 3\n*END STEP\n";
  auto error_of = [&](const std::string& t) {
    const JobResult r = run_deck(head + t + step);
    EXPECT_EQ(r.exit_code, kExitInputError) << t;
    return r.error;
  };
  EXPECT_NE(error_of("*TRANSFORM, NSET=ALLN, TYPE=S\n0,0,0,0,0,1\n").find("TYPE=S: spherical"),
            std::string::npos);
  // both nodes lie on the axis (x) of the system: local 1 and 2 are arbitrary there, so a boundary
  // condition on local 1 alone is ambiguous
  const std::string on_axis = "*TRANSFORM, NSET=ALLN, TYPE=C\n0,0,0,1,0,0\n";
  const JobResult r = run_deck(head + on_axis + "*STEP\n*STATIC\n*BOUNDARY\n1, 1, 1\n*END STEP\n");
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("node 1: the node lies on the axis of its cylindrical *TRANSFORM"),
            std::string::npos)
      << r.error;
  EXPECT_NE(r.error.find("hold local DOFs 1 and 2 together at zero"), std::string::npos);
  EXPECT_NE(error_of("*TRANSFORM, NSET=ALLN, TYPE=C\n0,0,0,0,0,0\n")
                .find("a = (0, 0, 0), b = (0, 0, 0): the two points of the cylindrical "
                      "system's axis coincide"),
            std::string::npos);
  EXPECT_NE(error_of("*TRANSFORM, NSET=ALLN\n1,0,0,2,0,0\n")
                .find("a = (1, 0, 0), b = (2, 0, 0): b lies on the line of a"),
            std::string::npos);
  EXPECT_NE(error_of("*TRANSFORM, NSET=ALLN\n0,0,0,0,1,0\n").find("a is the origin"),
            std::string::npos);
  EXPECT_NE(error_of("*TRANSFORM, NSET=ALLN\n1,0,0,0,1,0\n*TRANSFORM, NSET=ALLN\n1,1,0,0,1,0\n")
                .find("node 1: the node already has a local system"),
            std::string::npos);
}
