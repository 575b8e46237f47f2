// *COUPLING, ORIENTATION=: the DOFs of *KINEMATIC and the rotations of *DISTRIBUTING are those of
// the orientation's local axes. Oracle: the same column turned as a whole by Q (30 degrees about
// z, then 20 about x), with the orientation's axes Q's columns and the load turned by Q, gives
// Q u of the unturned column coupled in global DOFs, node for node (the model is linear, so the
// turned problem is the original one seen in other axes). A cylindrical orientation couples each
// node in its own radial / tangential / axial axes: with the tangential DOF only, a torque about
// the axis turns the coupled face rigidly (every node's tangential displacement theta r) while
// its radial displacements stay free.
#include "test_util.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

using namespace gapfem;
using namespace gapfem::test;

namespace {

constexpr int kN = 2, kNz = 3;
constexpr double kH = 0.5;

int label(int i, int j, int k) {
  return 1 + i + (kN + 1) * (j + (kN + 1) * k);
}

Eigen::Matrix3d turn() {
  const double a = 30.0 * std::numbers::pi / 180, b = 20.0 * std::numbers::pi / 180;
  Eigen::Matrix3d Rz, Rx;
  Rz << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  Rx << 1, 0, 0, 0, std::cos(b), -std::sin(b), 0, std::sin(b), std::cos(b);
  return Rx * Rz;
}

/// A column of kN x kN x kNz C3D8 (0.5 wide, 1 per layer), fixed at its base, its top face
/// coupled to node 9999 one above the top's centre; the geometry and the load turned by Q.
/// `coupling`: the *KINEMATIC or *DISTRIBUTING block; `oriented`: ORIENTATION=OR (Q's axes).
std::string column(const Eigen::Matrix3d& Q, bool oriented, const std::string& coupling,
                   const Eigen::Vector3d& force, const Eigen::Vector3d& moment) {
  auto place = [&](double x, double y, double z) {
    return Eigen::Vector3d(Q * Eigen::Vector3d(x, y, z));
  };
  std::string d = "*HEADING\ncoupling in a local system\n*NODE\n";
  for (int k = 0; k <= kNz; ++k)
    for (int j = 0; j <= kN; ++j)
      for (int i = 0; i <= kN; ++i) {
        const Eigen::Vector3d x = place(i * kH, j * kH, k);
        d += fmt::format("{}, {:.17g}, {:.17g}, {:.17g}\n", label(i, j, k), x[0], x[1], x[2]);
      }
  const Eigen::Vector3d r = place(kN * kH / 2, kN * kH / 2, kNz + 1.0);
  d += fmt::format("9999, {:.17g}, {:.17g}, {:.17g}\n*ELEMENT, TYPE=C3D8, ELSET=ALL\n", r[0], r[1],
                   r[2]);
  int e = 1;
  std::string top;
  for (int k = 0; k < kNz; ++k)
    for (int j = 0; j < kN; ++j)
      for (int i = 0; i < kN; ++i) {
        d += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", e, label(i, j, k),
                         label(i + 1, j, k), label(i + 1, j + 1, k), label(i, j + 1, k),
                         label(i, j, k + 1), label(i + 1, j, k + 1), label(i + 1, j + 1, k + 1),
                         label(i, j + 1, k + 1));
        if (k == kNz - 1) top += fmt::format("{}{}", top.empty() ? "" : ", ", e);
        ++e;
      }
  d += "*ELSET, ELSET=TOPE\n" + top + "\n*SURFACE, NAME=TOPS\nTOPE, S2\n*NSET, NSET=BOT\n";
  for (int j = 0; j <= kN; ++j)
    for (int i = 0; i <= kN; ++i) d += fmt::format("{}\n", label(i, j, 0));
  d += "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*SOLID SECTION, ELSET=ALL, MATERIAL=M\n";
  if (oriented) {
    const Eigen::Vector3d a = Q.col(0), b = Q.col(1);
    d += fmt::format("*ORIENTATION, NAME=OR\n{:.17g}, {:.17g}, {:.17g}, {:.17g}, {:.17g}, "
                     "{:.17g}\n",
                     a[0], a[1], a[2], b[0], b[1], b[2]);
  }
  d += fmt::format("*COUPLING, CONSTRAINT NAME=C, REF NODE=9999, SURFACE=TOPS{}\n{}",
                   oriented ? ", ORIENTATION=OR" : "", coupling);
  d += "*BOUNDARY\nBOT, 1, 3\n*STEP\n*STATIC\n*CLOAD\n";
  const Eigen::Vector3d F = Q * force, M = Q * moment;
  for (int i = 0; i < 3; ++i) {
    if (F[i] != 0.0) d += fmt::format("9999, {}, {:.17g}\n", i + 1, F[i]);
    if (M[i] != 0.0) d += fmt::format("9999, {}, {:.17g}\n", i + 4, M[i]);
  }
  return d + "*NODE PRINT\nU\n*END STEP\n";
}

void expect_turned(const std::string& coupling, const Eigen::Vector3d& F,
                   const Eigen::Vector3d& M) {
  const Eigen::Matrix3d Q = turn();
  const JobResult a =
      run_deck(column(Eigen::Matrix3d::Identity(), false, coupling, F, M), false, "global");
  ASSERT_EQ(a.exit_code, 0) << a.error;
  const JobResult b = run_deck(column(Q, true, coupling, F, M), false, "local");
  ASSERT_EQ(b.exit_code, 0) << b.error;
  double scale = 0.0;
  for (int n = 1; n <= label(kN, kN, kNz); ++n) {
    const Vec3& u = U(a, last_frame(a), n);
    scale = std::max(scale, Eigen::Vector3d(u[0], u[1], u[2]).norm());
  }
  ASSERT_GT(scale, 0.0);
  for (int n = 1; n <= label(kN, kN, kNz); ++n) {
    const Vec3& ua = U(a, last_frame(a), n);
    const Vec3& ub = U(b, last_frame(b), n);
    const Eigen::Vector3d d =
        Eigen::Vector3d(ub[0], ub[1], ub[2]) - Q * Eigen::Vector3d(ua[0], ua[1], ua[2]);
    EXPECT_LT(d.norm(), 1e-9 * scale) << "node " << n;
  }
}

} // namespace

TEST(CouplingOrientation, KinematicLocalDofsAreTheTurnedGlobalOnes) {
  // the translations only (the reference node's rotations follow the face through the rigid
  // links): the top's nodes keep their own rotations-free motion in the local axes
  expect_turned("*KINEMATIC\n1, 3\n", {2.0, 1.0, -3.0}, {0.0, 0.0, 0.0});
  // every DOF: the reference node's moment bends and twists the column through the coupling
  expect_turned("*KINEMATIC\n", {1.0, 0.5, -2.0}, {0.3, -0.2, 0.4});
}

TEST(CouplingOrientation, DistributingLocalRotationsAreTheTurnedGlobalOnes) {
  // every rotation of the reference node, formed along the local axes (a partial set would leave
  // the reference node's other local rotations free in the turned model, where none are global)
  expect_turned("*DISTRIBUTING\n1, 6\n", {1.0, 0.5, -2.0}, {0.3, -0.1, 0.2});
}

// A cylindrical system about the column's axis: the tangential DOF (2) of every top node follows
// the reference node's rotation about the axis, theta r; the reference node sits on the axis, so
// its translations do not enter (d is along the axis).
TEST(CouplingOrientation, CylindricalTangentialCouplingTurnsTheFaceRigidly) {
  std::string d = column(Eigen::Matrix3d::Identity(), false, "*KINEMATIC\n2, 2\n", {0.0, 0.0, 0.0},
                         {0.0, 0.0, 5.0});
  d.replace(d.find("*COUPLING"), 0,
            "*ORIENTATION, NAME=CYL, SYSTEM=CYLINDRICAL\n0.5, 0.5, 0., 0.5, 0.5, 1.\n");
  d.replace(d.find("SURFACE=TOPS"), 12, "SURFACE=TOPS, ORIENTATION=CYL");
  // the top's centre node lies on the axis, where the radial direction is undefined: leave it
  // out of the surface by coupling the faces' outer nodes only (a node-based surface)
  std::string outer = "*NSET, NSET=RIM\n";
  for (int j = 0; j <= kN; ++j)
    for (int i = 0; i <= kN; ++i)
      if (i != 1 || j != 1) outer += fmt::format("{}\n", label(i, j, kNz));
  d.replace(d.find("*COUPLING"), 0, outer + "*SURFACE, NAME=RIMS, TYPE=NODE\nRIM\n");
  d.replace(d.find("SURFACE=TOPS"), 12, "SURFACE=RIMS");
  d.replace(d.find("*BOUNDARY\n") + 10, 0, "9999, 1, 3\n");
  const JobResult r = run_deck(d, false, "cylindrical");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const double theta = last_frame(r).nodes.UR.at(r.model->mesh.find_node(9999))[2];
  ASSERT_GT(std::abs(theta), 0.0);
  for (int j = 0; j <= kN; ++j)
    for (int i = 0; i <= kN; ++i) {
      if (i == 1 && j == 1) continue;
      const Vec3& u = U(r, last_frame(r), label(i, j, kNz));
      const double x = i * kH - 0.5, y = j * kH - 0.5, rad = std::hypot(x, y);
      const double tangential = (-y * u[0] + x * u[1]) / rad;
      EXPECT_NEAR(tangential, theta * rad, 1e-10 * std::abs(theta)) << i << " " << j;
    }
}
