// *TIE (issue 12): node-to-surface ties between two C3D8 / DC3D8 blocks.
// - Matching meshes: the tied blocks give the merged mesh's answer to 1e-10, node to surface and
//   surface to surface (small and large displacements with a closing gap).
// - Non-matching meshes (3 x 3 faces against 2 x 2, either side the slave): with the default
//   surface-to-surface (mortar) tie a uniaxial stress state and a linear temperature field pass
//   through exactly (patch test: closed form u1 = sigma x / E, T = T0 - q x / k).
// - ADJUST=YES moves slave nodes across a small gap onto the master faces (the answer of the
//   closed gap); ADJUST=NO keeps the gap, which the tie bridges rigidly.
// - A slave node beyond the position tolerance, a node in two ties: input errors; a boundary
//   condition on a slave node holds it (warning).
#include "verification/constraints/split_blocks.hpp"

#include <gtest/gtest.h>

using namespace gapfem;
using namespace gapfem::test;

namespace {

/// Faces of the split mesh at the interface: left elements' S4 (x+), right elements' S6 (x-).
std::string interface_surfaces(const SplitBlocks& g) {
  std::string left, right;
  int e = 1;
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i, ++e) {
        if (i == g.m - 1) left += fmt::format("{}, S4\n", e);
        if (i == g.m) right += fmt::format("{}, S6\n", e);
      }
  return "*SURFACE, NAME=MASTER\n" + left + "*SURFACE, NAME=SLAVE\n" + right;
}

std::string mechanical(const SplitBlocks& g, bool split, bool nlgeom,
                       const std::string& type = "NODE TO SURFACE") {
  std::string d = "*HEADING\nblocks\n" + g.mesh(split);
  const int tip = split ? g.split_label(g.nx, 0, 0) : g.label(g.nx, 0, 0);
  d += fmt::format("*NODE\n90000, {}, 0., -0.002\n*ELEMENT, TYPE=GAPUNI, ELSET=GAPS\n90001, {}, "
                   "90000\n*GAP, ELSET=GAPS\n0.002, 0., 0., -1.\n",
                   g.nx * g.size, tip);
  d += "*NSET, NSET=CLAMP\n" + g.plane(0) + "*NSET, NSET=FAR\n" + g.plane(g.nx, split);
  if (split) d += interface_surfaces(g) + "*TIE, NAME=T1, TYPE=" + type + "\nSLAVE, MASTER\n";
  d += "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*SOLID SECTION, ELSET=ALL, MATERIAL=M\n";
  d += fmt::format("*STEP{}\n*STATIC\n0.5, 1.\n*BOUNDARY\nCLAMP, 1, 3\n90000, 1, 3\n*CLOAD\n"
                   "FAR, 1, 2.\nFAR, 2, 0.5\nFAR, 3, -0.4\n*END STEP\n",
                   nlgeom ? ", NLGEOM" : "");
  return d;
}

// Two boxes [0, 1]^3 (n1 cells per edge) and [1 + gap, 2 + gap] x [0, 1]^2 (n2 cells), the
// second numbered from 10001; element sets A, B; surfaces MASTER (x = 1 of A), SLAVE (x = 1 + gap
// of B); node sets X0 (x = 0) and XEND (far end).
std::string two_boxes(int n1, int n2, const std::string& type, double gap = 0.0) {
  std::string d = "*HEADING\ntwo boxes\n*NODE\n";
  auto box = [&](int n, double x0, int off, const std::string& elset, int eoff) {
    const double h = 1.0 / n;
    auto lab = [&](int i, int j, int k) { return off + 1 + i + (n + 1) * (j + (n + 1) * k); };
    std::string nodes, elems = fmt::format("*ELEMENT, TYPE={}, ELSET={}\n", type, elset);
    for (int k = 0; k <= n; ++k)
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
          nodes += fmt::format("{}, {:.17g}, {:.17g}, {:.17g}\n", lab(i, j, k), x0 + i * h, j * h,
                               k * h);
    std::string faces;
    int e = eoff;
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i, ++e) {
          elems +=
              fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", e, lab(i, j, k), lab(i + 1, j, k),
                          lab(i + 1, j + 1, k), lab(i, j + 1, k), lab(i, j, k + 1),
                          lab(i + 1, j, k + 1), lab(i + 1, j + 1, k + 1), lab(i, j + 1, k + 1));
          if (off == 0 && i == n - 1) faces += fmt::format("{}, S4\n", e);
          if (off != 0 && i == 0) faces += fmt::format("{}, S6\n", e);
        }
    std::string plane;
    for (int k = 0; k <= n; ++k)
      for (int j = 0; j <= n; ++j) plane += fmt::format("{}\n", lab(off == 0 ? 0 : n, j, k));
    return std::tuple{nodes, elems, faces, plane};
  };
  const auto [na, ea, fa, pa] = box(n1, 0.0, 0, "A", 1);
  const auto [nb, eb, fb, pb] = box(n2, 1.0 + gap, 10000, "B", 1001);
  d += na + nb + ea + eb + "*ELSET, ELSET=ALL\nA, B\n*SURFACE, NAME=MASTER\n" + fa +
       "*SURFACE, NAME=SLAVE\n" + fb + "*NSET, NSET=X0\n" + pa + "*NSET, NSET=XEND\n" + pb;
  return d;
}

} // namespace

TEST(Tie, MatchingMeshesGiveTheMergedMeshAnswer) {
  SplitBlocks g;
  g.ny = 2;
  for (bool nlgeom : {false, true}) {
    const JobResult flat = run_deck_exact(mechanical(g, false, nlgeom), "flat");
    ASSERT_EQ(flat.exit_code, 0) << flat.error;
    for (const char* type : {"NODE TO SURFACE", "SURFACE TO SURFACE"}) {
      const JobResult tied = run_deck_exact(mechanical(g, true, nlgeom, type), "tied");
      ASSERT_EQ(tied.exit_code, 0) << tied.error;
      EXPECT_EQ(tied.model->constraints.size(), 4u * (g.ny + 1) * (g.nz + 1)) << "3 + DOF 11";
      expect_same_nodes(flat, tied, g, 1e-10);
    }
  }
}

TEST(Tie, NonMatchingMeshesPassUniaxialStressExactly) {
  // E = 1000, nu = 0.3; x = 0 held in x (one node fully, one in y), end face pulled by a total
  // of 6 as a uniform traction: sigma = 6, u1 = 6 x / 1000
  for (const auto& [n1, n2] : {std::pair{2, 3}, std::pair{3, 2}}) {
    std::string faces;
    for (int k = 0; k < n2; ++k)
      for (int j = 0; j < n2; ++j)
        faces += fmt::format("{}, S4\n", 1001 + (n2 - 1) + n2 * j + n2 * n2 * k);
    const std::string d = two_boxes(n1, n2, "C3D8") +
                          "*TIE, NAME=T\nSLAVE, MASTER\n*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n"
                          "*SOLID SECTION, ELSET=ALL, MATERIAL=M\n*SURFACE, NAME=END\n" +
                          faces +
                          fmt::format("*STEP\n*STATIC\n*BOUNDARY\nX0, 1, 1\n1, 2, 3\n{}, 2, 2\n"
                                      "*DSLOAD\nEND, P, -6.\n*END STEP\n",
                                      1 + (n1 + 1) * (n1 + 1) * n1);
    const JobResult r = run_deck(d);
    ASSERT_EQ(r.exit_code, 0) << r.error;
    const Frame& f = last_frame(r);
    const Model& m = *r.model;
    for (NodeId n = 0; n < m.mesh.n_nodes(); ++n) {
      const Vec3& X = m.mesh.coords[n];
      EXPECT_NEAR(f.nodes.U[n][0], 6.0 * X[0] / 1000.0, 1e-12)
          << n1 << "/" << n2 << " " << m.node_label(n).str();
      EXPECT_NEAR(f.nodes.U[n][1], -0.3 * 6.0 * X[1] / 1000.0, 1e-12) << m.node_label(n).str();
      EXPECT_NEAR(f.nodes.U[n][2], -0.3 * 6.0 * X[2] / 1000.0, 1e-12) << m.node_label(n).str();
    }
  }
}

TEST(Tie, NonMatchingMeshesPassALinearTemperatureExactly) {
  // k = 4; T = 100 at x = 0; a flux of 8 leaves the far end (1 x 1): T = 100 - 8 x / 4
  std::string d = two_boxes(3, 2, "DC3D8") + "*TIE, NAME=T\nSLAVE, MASTER\n"
                                             "*MATERIAL, NAME=M\n*CONDUCTIVITY\n4.\n"
                                             "*SOLID SECTION, ELSET=ALL, MATERIAL=M\n";
  std::string faces;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j) faces += fmt::format("{}, S4\n", 1001 + 1 + 2 * j + 4 * k);
  d += "*SURFACE, NAME=END\n" + faces +
       "*STEP\n*HEAT TRANSFER, STEADY STATE\n*BOUNDARY\nX0, 11, 11, 100.\n*DSFLUX\nEND, S, 8.\n"
       "*END STEP\n";
  // an outward flux of 8 (DSFLUX is heat into the body: -8)
  d.replace(d.find("END, S, 8."), 10, "END, S, -8.");
  const JobResult r = run_deck(d);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  const Model& m = *r.model;
  for (NodeId n = 0; n < m.mesh.n_nodes(); ++n)
    EXPECT_NEAR(f.nodes.NT[n], 100.0 - 2.0 * m.mesh.coords[n][0], 1e-10) << m.node_label(n).str();
}

TEST(Tie, AdjustClosesASmallGapAndNoAdjustBridgesIt) {
  auto deck = [](const std::string& adjust) {
    std::string d =
        two_boxes(2, 2, "C3D8", 0.01) +
        "*TIE, NAME=T, TYPE=NODE TO SURFACE, POSITION TOLERANCE=0.02, ADJUST=" + adjust +
        "\nSLAVE, MASTER\n*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*SOLID SECTION, "
        "ELSET=ALL, MATERIAL=M\n*STEP\n*STATIC\n*BOUNDARY\nX0, 1, 1\n1, 2, 3\n"
        "19, 2, 2\n*CLOAD\n";
    for (int k = 0; k <= 2; ++k)
      for (int j = 0; j <= 2; ++j) {
        const double w = (j == 1 ? 2.0 : 1.0) * (k == 1 ? 2.0 : 1.0) / 16.0; // bilinear shares
        d += fmt::format("{}, 1, {:.17g}\n", 10001 + 2 + 3 * j + 9 * k, 6.0 * w);
      }
    return d + "*END STEP\n";
  };
  const JobResult yes = run_deck(deck("YES"), false, "yes");
  const JobResult no = run_deck(deck("NO"), false, "no");
  ASSERT_EQ(yes.exit_code, 0) << yes.error;
  ASSERT_EQ(no.exit_code, 0) << no.error;
  const Model& my = *yes.model;
  const Model& mn = *no.model;
  for (NodeId n = 0; n < my.mesh.n_nodes(); ++n) {
    const Label l = my.mesh.node_labels[n];
    const double xy = my.mesh.coords[n][0], xn = mn.mesh.coords[mn.mesh.find_node(l)][0];
    if (l > 10000 && (l - 10001) % 3 == 0) EXPECT_DOUBLE_EQ(xy, 1.0) << "slave node moved";
    // ADJUST=YES: the closed form of a 2-long bar; ADJUST=NO: the gap moves rigidly
    EXPECT_NEAR(last_frame(yes).nodes.U[n][0], 6.0 * xy / 1000.0, 1e-12) << l;
    const double x_solid = l > 10000 ? xn - 0.01 : xn;
    EXPECT_NEAR(last_frame(no).nodes.U[mn.mesh.find_node(l)][0], 6.0 * x_solid / 1000.0, 1e-12)
        << l;
  }
}

TEST(Tie, BadTiesAreInputErrorsAndBoundaryConditionsHoldSlaves) {
  const std::string model = "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*SOLID SECTION, ELSET=ALL, "
                            "MATERIAL=M\n";
  const std::string step = "*STEP\n*STATIC\n*BOUNDARY\nX0, 1, 3\n*CLOAD\nXEND, 1, 1.\n*END STEP\n";
  auto run = [&](const std::string& d) { return run_deck(d); };
  // beyond the tolerance
  JobResult r = run(two_boxes(2, 2, "C3D8", 0.1) + "*TIE, NAME=T\nSLAVE, MASTER\n" + model + step);
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("job.inp:"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("*TIE: tie T: 9 slave node(s) of surface SLAVE find no face of the master "
                         "surface MASTER within the position tolerance 0.03536 (the first: node "
                         "10001 at a distance of 0.1); raise POSITION TOLERANCE"),
            std::string::npos)
      << r.error;
  // a node in two ties
  r = run(two_boxes(2, 2, "C3D8") + "*TIE, NAME=T1\nSLAVE, MASTER\n*TIE, NAME=T2\nSLAVE, MASTER\n" +
          model + step);
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("tie T2: node 10001: DOF 1 of this slave node is already tied by tie "
                         "T1 at"),
            std::string::npos)
      << r.error;
  // undefined surfaces, a node-based master
  r = run(two_boxes(2, 2, "C3D8") + "*TIE, NAME=T\nSLAVE, NOPE\n" + model + step);
  EXPECT_NE(r.error.find("master surface NOPE: this surface is not defined"), std::string::npos)
      << r.error;
  r = run(two_boxes(2, 2, "C3D8") + "*SURFACE, NAME=N, TYPE=NODE\nX0\n*TIE, NAME=T\nSLAVE, N\n" +
          model + step);
  EXPECT_NE(r.error.find("the master surface of a tie must be element-based"), std::string::npos)
      << r.error;
  // a boundary condition on slave nodes: the node is held, the tie is not applied there
  r = run(two_boxes(2, 2, "C3D8") + "*TIE, NAME=T\nSLAVE, MASTER\n" + model +
          "*STEP\n*STATIC\n*BOUNDARY\nX0, 1, 3\n10001, 2, 2\n*CLOAD\nXEND, 1, 1.\n*END STEP\n");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  bool warned = false;
  for (const std::string& w : r.run.warnings)
    warned |= w.find("*TIE: tie T: 1 constrained DOF(s) also have boundary conditions") !=
              std::string::npos;
  EXPECT_TRUE(warned);
}
