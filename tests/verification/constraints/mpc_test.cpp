// *MPC (issue 12): PIN and TIE joining duplicated interface nodes give the merged mesh's answer;
// a rigid arm (MPC BEAM) on a B31 cantilever gives the answer of the same load moved to the beam
// tip (force and its moment d x F), and the arm's end moves rigidly; MPC LINK keeps a distance
// (closed form); bad MPCs and NLGEOM with a small-rotation MPC are input errors.
#include "verification/constraints/split_blocks.hpp"

#include <gtest/gtest.h>

using namespace gapfem;
using namespace gapfem::test;

namespace {

std::string block_deck(const SplitBlocks& g, const std::string& join) {
  const bool split = !join.empty();
  std::string d = "*HEADING\nblocks\n" + g.mesh(split) + "*NSET, NSET=CLAMP\n" + g.plane(0) +
                  "*NSET, NSET=FAR\n" + g.plane(g.nx, split);
  if (split)
    d += "*NSET, NSET=L-IF\n" + g.plane(g.m) + "*NSET, NSET=R-IF\n" + g.plane(g.m, true) + join;
  d += "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*SOLID SECTION, ELSET=ALL, MATERIAL=M\n"
       "*STEP\n*STATIC\n*BOUNDARY\nCLAMP, 1, 3\n*CLOAD\nFAR, 1, 2.\nFAR, 2, 0.5\nFAR, 3, -0.4\n"
       "*END STEP\n";
  return d;
}

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

} // namespace

TEST(Mpc, PinAndTieJoinLikeMergedNodes) {
  SplitBlocks g;
  g.ny = 2;
  const JobResult flat = run_deck(block_deck(g, ""), false, "flat");
  ASSERT_EQ(flat.exit_code, 0) << flat.error;
  for (const char* type : {"PIN", "TIE"}) {
    const JobResult j = run_deck(block_deck(g, fmt::format("*MPC\n{}, R-IF, L-IF\n", type)), false,
                                 std::string("mpc_") + type);
    ASSERT_EQ(j.exit_code, 0) << j.error;
    expect_same_nodes(flat, j, g, 1e-10);
  }
}

namespace {
// A B31 cantilever along x (L = 4, 4 elements), clamped at node 1; node 100 sits on a rigid arm
// d = (0, 0.5, 0.3) from the tip node 5 and carries the load.
const Vec3 kArm{0.0, 0.5, 0.3};
const Vec3 kForce{1.0, 2.0, 3.0}, kMoment{0.1, -0.2, 0.05};

std::string cantilever(bool arm) {
  std::string d = "*HEADING\ncantilever\n*NODE\n";
  for (int n = 1; n <= 5; ++n) d += fmt::format("{}, {}, 0., 0.\n", n, n - 1);
  if (arm) d += fmt::format("100, 4., {}, {}\n", kArm[1], kArm[2]);
  d += "*ELEMENT, TYPE=B31, ELSET=BEAM\n1, 1, 2\n2, 2, 3\n3, 3, 4\n4, 4, 5\n"
       "*MATERIAL, NAME=STEEL\n*ELASTIC\n2.1E5, 0.3\n"
       "*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=RECT\n0.2, 0.3\n0., 0., -1.\n";
  if (arm) d += "*MPC\nBEAM, 100, 5\n";
  d += "*STEP\n*STATIC\n*BOUNDARY\n1, ENCASTRE\n*CLOAD\n";
  const int at = arm ? 100 : 5;
  // without the arm the tip carries the force and its moment about the tip, d x F
  const Vec3 M =
      arm ? kMoment
          : Vec3{kMoment[0] + cross(kArm, kForce)[0], kMoment[1] + cross(kArm, kForce)[1],
                 kMoment[2] + cross(kArm, kForce)[2]};
  for (int i = 0; i < 3; ++i) d += fmt::format("{}, {}, {:.17g}\n", at, i + 1, kForce[i]);
  for (int i = 0; i < 3; ++i) d += fmt::format("{}, {}, {:.17g}\n", at, i + 4, M[i]);
  return d + "*END STEP\n";
}
} // namespace

TEST(Mpc, BeamArmTransfersForceAndMomentRigidly) {
  const JobResult a = run_deck(cantilever(true), false, "arm");
  const JobResult f = run_deck(cantilever(false), false, "flat");
  ASSERT_EQ(a.exit_code, 0) << a.error;
  ASSERT_EQ(f.exit_code, 0) << f.error;
  const Frame& fa = last_frame(a);
  const Frame& ff = last_frame(f);
  double scale = 0.0;
  for (int n = 1; n <= 5; ++n)
    for (int i = 0; i < 3; ++i) {
      scale = std::max(scale, std::abs(U(f, ff, n)[i]));
      scale = std::max(scale, std::abs(ff.nodes.UR[f.model->mesh.find_node(n)][i]));
    }
  for (int n = 1; n <= 5; ++n) {
    const NodeId na = a.model->mesh.find_node(n), nf = f.model->mesh.find_node(n);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(fa.nodes.U[na][i], ff.nodes.U[nf][i], 1e-10 * scale) << n;
      EXPECT_NEAR(fa.nodes.UR[na][i], ff.nodes.UR[nf][i], 1e-10 * scale) << n;
    }
  }
  // the arm's end: u_100 = u_5 + theta_5 x d, theta_100 = theta_5
  const NodeId tip = f.model->mesh.find_node(5), end = a.model->mesh.find_node(100);
  const Vec3 rot = cross(ff.nodes.UR[tip], kArm);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(fa.nodes.U[end][i], ff.nodes.U[tip][i] + rot[i], 1e-10 * scale);
    EXPECT_NEAR(fa.nodes.UR[end][i], ff.nodes.UR[tip][i], 1e-10 * scale);
  }
}

TEST(Mpc, LinkKeepsTheDistance) {
  // node 1 on x and y springs (k = 10) pulled by (3, 4); a link to the fixed node 2 along x:
  // u1x = 0, u1y = 4 / 10, and the link carries 3 to node 2 (reaction -3)
  const std::string d = "*HEADING\nlink\n*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n"
                        "*ELEMENT, TYPE=SPRING1, ELSET=KX\n1, 1\n*ELEMENT, TYPE=SPRING1, ELSET=KY\n"
                        "2, 1\n*SPRING, ELSET=KX\n1\n10.\n*SPRING, ELSET=KY\n2\n10.\n"
                        "*MPC\nLINK, 1, 2\n*STEP\n*STATIC\n*BOUNDARY\n2, 1, 3\n*CLOAD\n1, 1, 3.\n"
                        "1, 2, 4.\n*END STEP\n";
  const JobResult r = run_deck(d);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  EXPECT_NEAR(U(r, f, 1)[0], 0.0, 1e-14);
  EXPECT_NEAR(U(r, f, 1)[1], 0.4, 1e-12);
  EXPECT_NEAR(RF(r, f, 2)[0], -3.0, 1e-10);
  EXPECT_NEAR(RF(r, f, 2)[1], 0.0, 1e-10);
}

TEST(Mpc, BadMpcsAreInputErrors) {
  auto error_of = [](const std::string& deck) {
    const JobResult r = run_deck(deck);
    EXPECT_EQ(r.exit_code, kExitInputError) << deck;
    return r.error;
  };
  auto has = [](const std::string& text, const std::string& what) {
    return text.find(what) != std::string::npos;
  };
  const std::string arm = cantilever(true);
  auto with = [&](const std::string& from, const std::string& to) {
    std::string d = arm;
    d.replace(d.find(from), from.size(), to);
    return d;
  };
  std::string e = error_of(with("BEAM, 100, 5", "SLIDER, 100, 5"));
  EXPECT_TRUE(has(e, "job.inp:")) << e;
  EXPECT_TRUE(has(e, "MPC type SLIDER: this MPC type is not supported")) << e;
  e = error_of(with("BEAM, 100, 5", "BEAM, 100, 100"));
  EXPECT_TRUE(has(e, "an MPC joins two different nodes")) << e;
  e = error_of(with("BEAM, 100, 5", "BEAM, 100, 77"));
  EXPECT_TRUE(has(e, "node 77")) << e;
  // the first node's DOFs are eliminated: no boundary condition on them
  e = error_of(with("1, ENCASTRE\n", "1, ENCASTRE\n100, 2, 2\n"));
  EXPECT_TRUE(has(e, "node 100: DOF 2 has a boundary condition and is the dependent")) << e;
  // NLGEOM: the rigid arm is the small-rotation form
  e = error_of(with("*STEP\n", "*STEP, NLGEOM\n"));
  EXPECT_TRUE(has(e, "step 1 has NLGEOM, but this constraint is linear in the rotations")) << e;
  e = error_of(with("*MPC\nBEAM, 100, 5\n", "*MPC\nBEAM, 100, 5\nPIN, 100, 4\n"));
  EXPECT_TRUE(has(e, "already the dependent DOF of the constraint at")) << e;
}

// A BEAM MPC between truss nodes gives the independent node rotations that nothing holds about
// the link's line: the singular system names the constraint as the cause, not rigid-body motion.
TEST(Mpc, BeamBetweenNodesWithoutRotationsNamesTheFreeRotation) {
  const std::string d =
      "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n3, 2., 0., 0.\n4, 3., 0., 0.\n*ELEMENT, TYPE=T3D2, "
      "ELSET=B\n1, 1, 2\n2, 3, 4\n*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*SOLID SECTION, "
      "ELSET=B, MATERIAL=M\n1.\n*MPC\nBEAM, 3, 2\n*STEP\n*STATIC\n*BOUNDARY\n1, 1, 3\n2, 2, 3\n2, "
      "5, 6\n"
      "4, 2, 3\n*CLOAD\n4, 1, 1.\n*END STEP\n";
  const JobResult r = gapfem::test::run_deck(d);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.error.find("DOF 4: no element gives these nodes rotations"), std::string::npos)
      << r.error;
}
