// Cyclic symmetry (*CYCLIC SYMMETRY MODEL + *TIE, CYCLIC SYMMETRY): a sector of a ring with a
// wavy, lopsided outer edge (r_out = 2 (1 + 0.15 cos N theta + 0.05 sin 2 N theta): no mirror
// plane inside the sector), spun (CENTRIF) and pressed on its outer face, gives the displacements
// of the whole ring meshed in full, node for node, whichever side is the slave, with a node-based
// master side (CalculiX's layout) and under NLGEOM.
// The ring's rigid rotation is held by its inner nodes' mean tangential displacement (see ring()),
// so the whole ring's answer is cyclic symmetric (checked too).
#include "test_util.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <string>
#include <vector>

using namespace gapfem;
using namespace gapfem::test;

namespace {

constexpr int kN = 6, kNt = 3, kNr = 2;
constexpr double kH = 0.2;

/// Node (i radial, j around, k through the thickness); j runs 0 .. columns - 1.
int node_id(int i, int j, int k, int columns) {
  return 1 + i + (kNr + 1) * (j + columns * k);
}

std::array<double, 3> position(int i, int j, int k) {
  const double theta = 2 * std::numbers::pi * j / (kN * kNt);
  const double ro = 2.0 * (1 + 0.15 * std::cos(kN * theta) + 0.05 * std::sin(2 * kN * theta));
  const double r = 1.0 + (ro - 1.0) * i / kNr;
  return {r * std::cos(theta), r * std::sin(theta), kH * k};
}

/// The whole ring (sectors = kN, the last column joined to the first) or one sector with its two
/// sides tied; `slave_first`: the theta = 0 side is the slave.
std::string ring(bool sector, bool slave_first, bool nlgeom, int n_param = kN,
                 bool node_master = false) {
  const int cells = sector ? kNt : kN * kNt;
  const int columns = sector ? kNt + 1 : kN * kNt;
  std::string d = "*HEADING\ncyclic ring\n*NODE, NSET=ALLN\n";
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j < columns; ++j)
      for (int i = 0; i <= kNr; ++i) {
        const auto x = position(i, j, k);
        d += fmt::format("{}, {:.17g}, {:.17g}, {:.17g}\n", node_id(i, j, k, columns), x[0], x[1],
                         x[2]);
      }
  d += "*ELEMENT, TYPE=C3D8, ELSET=RING\n";
  int e = 1;
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < kNr; ++i) {
      const int j1 = (j + 1) % columns;
      int c[4] = {node_id(i, j, 0, columns), node_id(i + 1, j, 0, columns),
                  node_id(i + 1, j1, 0, columns), node_id(i, j1, 0, columns)};
      d += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", e++, c[0], c[1], c[2], c[3],
                       c[0] + columns * (kNr + 1), c[1] + columns * (kNr + 1),
                       c[2] + columns * (kNr + 1), c[3] + columns * (kNr + 1));
    }
  d += "*ELSET, ELSET=OUTER, GENERATE\n2, " + std::to_string(e - 1) + ", 2\n";
  d += "*SOLID SECTION, ELSET=RING, MATERIAL=STEEL\n*MATERIAL, NAME=STEEL\n*ELASTIC\n"
       "210000., 0.3\n*DENSITY\n7.85e-9\n";
  d += fmt::format("*NSET, NSET=BOTTOM, GENERATE\n1, {}, 1\n", columns * (kNr + 1));
  if (sector) {
    d += "*ELSET, ELSET=FIRST, GENERATE\n1, 2, 1\n";
    d += fmt::format("*ELSET, ELSET=LAST, GENERATE\n{}, {}, 1\n", e - 2, e - 1);
    d += "*SURFACE, NAME=SIDE0\nFIRST, S3\n*SURFACE, NAME=SIDE1\nLAST, S5\n";
    if (node_master) { // CalculiX's layout: the master side as a node-based surface
      d += "*NSET, NSET=COL0\n";
      for (int k = 0; k <= 1; ++k)
        for (int i = 0; i <= kNr; ++i) d += fmt::format("{}\n", node_id(i, 0, k, columns));
      d += "*SURFACE, NAME=SIDE0N, TYPE=NODE\nCOL0\n";
    }
    d += fmt::format("*CYCLIC SYMMETRY MODEL, N={}{}\n0., 0., 0., 0., 0., 1.\n{}", n_param,
                     node_master ? ", TIE=CYC, NGRAPH=1" : "",
                     node_master ? "ALLN\n" : ""); // CalculiX's: a named tie, a set line
    d += slave_first   ? "*TIE, NAME=CYC, CYCLIC SYMMETRY\nSIDE0, SIDE1\n"
         : node_master ? "*TIE, NAME=CYC, CYCLIC SYMMETRY\nSIDE1, SIDE0N\n"
                       : "*TIE, NAME=CYC, CYCLIC SYMMETRY\nSIDE1, SIDE0\n";
  }
  // The rigid rotation about z: the mean tangential displacement of the inner bottom nodes is
  // zero (all of them in the whole ring; the sector's own, its slave column left out, in the
  // sector: their multiplier is the ring's, sector by sector). Under NLGEOM the pressure on the
  // deformed lopsided edge exerts a torque; this holds it alike in both models, where a boundary
  // condition at one node would hold the whole ring's torque there and the sector's at one node
  // per sector.
  d += "*BOUNDARY\nBOTTOM, 3, 3\n*EQUATION\n";
  std::vector<std::string> terms;
  const int own = sector ? kNt : columns;
  for (int j = 0; j < own; ++j) {
    const int jj = (j + 1) % own; // the first term: node (0, 1, 0) u_y
    const double t = 2 * std::numbers::pi * jj / (kN * kNt);
    if (j > 0)
      terms.push_back(fmt::format("{}, 1, {:.17g}", node_id(0, jj, 0, columns), -std::sin(t)));
    terms.push_back(fmt::format("{}, 2, {:.17g}", node_id(0, jj, 0, columns), std::cos(t)));
    if (j == 0)
      terms.push_back(fmt::format("{}, 1, {:.17g}", node_id(0, jj, 0, columns), -std::sin(t)));
  }
  d += std::to_string(terms.size()) + "\n";
  for (std::size_t k = 0; k < terms.size(); ++k)
    d += terms[k] + (k % 4 == 3 || k + 1 == terms.size() ? "\n" : ", ");
  if (!sector) // the whole ring's translations: a cyclic symmetric field moves its rings' centre
    for (int dof : {1, 2}) { // by nothing, so the inner bottom ring's mean displacement is zero
      d += fmt::format("*EQUATION\n{}\n", columns);
      for (int j = 0; j < columns; ++j) {
        const int jj = (j + dof + 1) % columns; // a first term no other row eliminates
        d += fmt::format("{}, {}, 1.{}", node_id(0, jj, 0, columns), dof,
                         j % 4 == 3 || j + 1 == columns ? "\n" : ", ");
      }
    }
  // NLGEOM: Newton to round-off (R_n, C_n tightened), so that the two models agree to 1e-8
  d += fmt::format("*STEP{}\n*STATIC\n1., 1.\n{}*DLOAD\nRING, CENTRIF, 1.e6, 0., 0., 0., 0., "
                   "0., 1.\nOUTER, P4, 20.\n*NODE PRINT\nU\n*END STEP\n",
                   nlgeom ? ", NLGEOM" : "",
                   nlgeom ? "*CONTROLS, PARAMETERS=FIELD\n1e-10, 1e-10\n" : "");
  return d;
}

Eigen::Vector3d displacement(const JobResult& r, int node) {
  const Vec3& u = U(r, last_frame(r), node);
  return {u[0], u[1], u[2]};
}

} // namespace

TEST(CyclicSymmetry, SectorGivesTheWholeRing) {
  for (bool nlgeom : {false, true}) {
    const JobResult full = run_deck(ring(false, false, nlgeom), true, "full");
    ASSERT_EQ(full.exit_code, 0) << full.error;
    // the whole ring's answer is cyclic symmetric: u(j + kNt) = R u(j)
    const double a = 2 * std::numbers::pi / kN;
    Eigen::Matrix3d R;
    R << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
    double scale = 0.0;
    for (int j = 0; j < kN * kNt; ++j)
      scale = std::max(scale, displacement(full, node_id(kNr, j, 1, kN * kNt)).norm());
    ASSERT_GT(scale, 0.0);
    for (int j = 0; j < kNt; ++j)
      for (int i = 0; i <= kNr; ++i)
        EXPECT_LT((displacement(full, node_id(i, j + kNt, 1, kN * kNt)) -
                   R * displacement(full, node_id(i, j, 1, kN * kNt)))
                      .norm(),
                  1e-8 * scale);
    for (int variant : {0, 1, 2}) { // slave last, slave first, a node-based master
      const bool slave_first = variant == 1;
      SCOPED_TRACE(fmt::format("NLGEOM {}, variant {}", nlgeom, variant));
      const JobResult sec =
          run_deck(ring(true, slave_first, nlgeom, kN, variant == 2), true, "sector");
      ASSERT_EQ(sec.exit_code, 0) << sec.error;
      for (int k = 0; k <= 1; ++k)
        for (int j = 0; j <= kNt; ++j)
          for (int i = 0; i <= kNr; ++i)
            EXPECT_LT((displacement(sec, node_id(i, j, k, kNt + 1)) -
                       displacement(full, node_id(i, j % (kN * kNt), k, kN * kNt)))
                          .norm(),
                      1e-8 * scale)
                << "node " << i << " " << j << " " << k;
    }
  }
}

// A sector angle that does not match N, a cyclic tie without *CYCLIC SYMMETRY MODEL, a frequency
// step (other nodal diameters): one clear message each.
TEST(CyclicSymmetry, BadCyclicModelsAreInputErrors) {
  JobResult r = run_deck(ring(true, false, false, 5), false, "five");
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("turned by 360/N = 72 degrees"), std::string::npos) << r.error;
  std::string d = ring(true, false, false);
  std::string no_model = d;
  no_model.erase(no_model.find("*CYCLIC SYMMETRY MODEL"),
                 no_model.find("*TIE, NAME=CYC") - no_model.find("*CYCLIC SYMMETRY MODEL"));
  r = run_deck(no_model, false, "nomodel");
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("needs *CYCLIC SYMMETRY MODEL"), std::string::npos) << r.error;
  std::string freq = d;
  freq.replace(freq.find("*STATIC\n1., 1.\n"), 15, "*FREQUENCY\n3\n");
  freq.erase(freq.find("*DLOAD"), freq.find("*NODE PRINT") - freq.find("*DLOAD"));
  r = run_deck(freq, false, "freq");
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("nodal diameter"), std::string::npos) << r.error;
}
