// Couplings (issue 12) on a C3D8 column 1 x 1 x 4 (2 x 2 x 4 elements) whose top face is coupled to
// a reference node:
// - kinematic coupling of DOF 3 under an axial force: uniaxial stress, u3 = F L / (E A) and the
//   lateral contraction nu F / (E A) x (closed form, exact for C3D8), with *KINEMATIC COUPLING
//   and with *COUPLING + *KINEMATIC on an element-based surface;
// - kinematic coupling of DOFs 1-6 with a prescribed reference rotation: every top node moves
//   rigidly, u = theta x d, and the base reactions balance the reference node's reaction moment;
// - distributing coupling (uniform weights at the face centroid; linear weights from an offset
//   reference node; a node-based surface): the answer of the same force and moment distributed by
//   the test itself with the Abaqus formula F_n = w_n (F + (T^-1 M^) x r_n) as *CLOADs, to 1e-10,
//   and the reference node's motion u_R = sum w_n u_n + theta x r_R, theta = T^-1 sum w_n r_n x
//   u_n;
// - bad couplings are input errors.
#include "test_util.hpp"

#include <Eigen/Dense>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <map>

using namespace gapfem;
using namespace gapfem::test;

namespace {

constexpr int kNx = 2, kNy = 2, kNz = 4;
constexpr double kH = 0.5, kL = 4.0, kE = 1000.0, kNu = 0.3;
int label(int i, int j, int k) {
  return 1 + i + (kNx + 1) * (j + (kNy + 1) * k);
}
Vec3 coord(int i, int j, int k) {
  return {i * kH, j * kH, k * 1.0};
}

/// The column with sets TOP (nodes), BOT, and the surface TOPS (faces S2 of the top layer).
std::string column(const Vec3& ref) {
  std::string d = "*HEADING\ncolumn\n*NODE\n";
  for (int k = 0; k <= kNz; ++k)
    for (int j = 0; j <= kNy; ++j)
      for (int i = 0; i <= kNx; ++i) {
        const Vec3 x = coord(i, j, k);
        d += fmt::format("{}, {}, {}, {}\n", label(i, j, k), x[0], x[1], x[2]);
      }
  d += fmt::format("9999, {:.17g}, {:.17g}, {:.17g}\n*ELEMENT, TYPE=C3D8, ELSET=ALL\n", ref[0],
                   ref[1], ref[2]);
  int e = 1;
  std::string top_elems;
  for (int k = 0; k < kNz; ++k)
    for (int j = 0; j < kNy; ++j)
      for (int i = 0; i < kNx; ++i) {
        d += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", e, label(i, j, k),
                         label(i + 1, j, k), label(i + 1, j + 1, k), label(i, j + 1, k),
                         label(i, j, k + 1), label(i + 1, j, k + 1), label(i + 1, j + 1, k + 1),
                         label(i, j + 1, k + 1));
        if (k == kNz - 1) top_elems += fmt::format("{}{}", top_elems.empty() ? "" : ", ", e);
        ++e;
      }
  d += "*ELSET, ELSET=TOPE\n" + top_elems + "\n*SURFACE, NAME=TOPS\nTOPE, S2\n";
  std::string top, bot;
  for (int j = 0; j <= kNy; ++j)
    for (int i = 0; i <= kNx; ++i) {
      top += fmt::format("{}{}", top.empty() ? "" : ", ", label(i, j, kNz));
      bot += fmt::format("{}{}", bot.empty() ? "" : ", ", label(i, j, 0));
    }
  d += "*NSET, NSET=TOP\n" + top + "\n*NSET, NSET=BOT\n" + bot + "\n";
  d += fmt::format("*NSET, NSET=PINX\n{}, {}\n*NSET, NSET=PINY\n{}, {}\n", label(0, 0, 0),
                   label(0, kNy, 0), label(0, 0, 0), label(kNx, 0, 0));
  return d + fmt::format("*MATERIAL, NAME=M\n*ELASTIC\n{}, {}\n*SOLID SECTION, ELSET=ALL, "
                         "MATERIAL=M\n",
                         kE, kNu);
}

Vec3 sub(const Vec3& a, const Vec3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

} // namespace

TEST(Coupling, KinematicAxialForceGivesUniaxialStress) {
  const std::string step = "*STEP\n*STATIC\n*BOUNDARY\nBOT, 3, 3\nPINX, 1, 1\nPINY, 2, 2\n"
                           "9999, 4, 5\n*CLOAD\n9999, 3, 10.\n*END STEP\n";
  for (const std::string coupling :
       {std::string("*KINEMATIC COUPLING, REF NODE=9999\nTOP, 3, 3\n"),
        std::string("*NSET, NSET=RP\n9999\n*COUPLING, CONSTRAINT NAME=C1, REF NODE=RP, "
                    "SURFACE=TOPS\n*KINEMATIC\n3, 3\n")}) {
    const JobResult r = run_deck(column({0.5, 0.5, 5.0}) + coupling + step);
    ASSERT_EQ(r.exit_code, 0) << r.error;
    const Frame& f = last_frame(r);
    const double strain = 10.0 / (kE * 1.0); // F / (E A), A = 1
    for (int j = 0; j <= kNy; ++j)
      for (int i = 0; i <= kNx; ++i) {
        const Vec3& u = U(r, f, label(i, j, kNz));
        EXPECT_NEAR(u[2], strain * kL, 1e-12);
        EXPECT_NEAR(u[0], -kNu * strain * i * kH, 1e-12);
        EXPECT_NEAR(u[1], -kNu * strain * j * kH, 1e-12);
      }
    EXPECT_NEAR(U(r, f, 9999)[2], strain * kL, 1e-12);
    EXPECT_EQ(r.increments.front().iterations, 1);
  }
}

TEST(Coupling, KinematicRotationMovesTheFaceRigidlyAndBalances) {
  const Vec3 ref{0.3, 0.7, 4.5}, theta{0.002, -0.001, 0.003};
  std::string d = column(ref) + "*KINEMATIC COUPLING, REF NODE=9999\nTOP\n" +
                  "*STEP\n*STATIC\n*BOUNDARY\nBOT, 1, 3\n9999, 1, 3\n";
  for (int i = 0; i < 3; ++i) d += fmt::format("9999, {0}, {0}, {1}\n", i + 4, theta[i]);
  const JobResult r = run_deck(d + "*END STEP\n");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  const double tol = 1e-10 * 0.01; // of the largest displacement, about 0.003
  for (int j = 0; j <= kNy; ++j)
    for (int i = 0; i <= kNx; ++i) {
      const Vec3 rigid = cross(theta, sub(coord(i, j, kNz), ref));
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(U(r, f, label(i, j, kNz))[c], rigid[c], tol);
    }
  // equilibrium of the whole model about the reference node: base reactions and the reaction
  // force and moment of the reference node sum to zero
  Vec3 force = RF(r, f, 9999), moment = f.nodes.RM[r.model->mesh.find_node(9999)];
  double scale = 0.0;
  for (int j = 0; j <= kNy; ++j)
    for (int i = 0; i <= kNx; ++i) {
      const Vec3& rf = RF(r, f, label(i, j, 0));
      const Vec3 m = cross(sub(coord(i, j, 0), ref), rf);
      for (int c = 0; c < 3; ++c) {
        force[c] += rf[c];
        moment[c] += m[c];
        scale = std::max(scale, std::abs(rf[c]));
      }
    }
  ASSERT_GT(scale, 0.0);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(force[c], 0.0, 1e-9 * scale);
    EXPECT_NEAR(moment[c], 0.0, 1e-9 * scale);
  }
}

namespace {

enum class Weights { UniformArea, LinearArea, NodeUniform };

/// The test's own distribution of (F, M) at the reference node over the top nodes.
struct Distribution {
  std::map<int, double> w; ///< label -> normalised weight
  Vec3 xbar{};
  Eigen::Matrix3d T = Eigen::Matrix3d::Zero();
};

Distribution distribution(const Vec3& ref, Weights kind) {
  Distribution D;
  double total = 0.0, r0 = 0.0;
  for (int j = 0; j <= kNy; ++j)
    for (int i = 0; i <= kNx; ++i)
      r0 = std::max(r0, std::sqrt([&] {
                      const Vec3 d = sub(coord(i, j, kNz), ref);
                      return d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                    }()));
  for (int j = 0; j <= kNy; ++j)
    for (int i = 0; i <= kNx; ++i) {
      // tributary area of a regular grid node: (h/2 or h) x (h/2 or h)
      const double ax = (i == 0 || i == kNx) ? kH / 2 : kH, ay = (j == 0 || j == kNy) ? kH / 2 : kH;
      const Vec3 d = sub(coord(i, j, kNz), ref);
      const double r = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      double w = kind == Weights::NodeUniform ? 1.0 : ax * ay;
      if (kind == Weights::LinearArea) w *= 1.0 - r / r0;
      if (w <= 0) continue;
      D.w[label(i, j, kNz)] = w;
      total += w;
    }
  for (auto& [l, w] : D.w) w /= total;
  for (const auto& [l, w] : D.w) {
    const int k = l - 1, i = k % (kNx + 1), j = (k / (kNx + 1)) % (kNy + 1);
    const Vec3 x = coord(i, j, kNz);
    for (int c = 0; c < 3; ++c) D.xbar[c] += w * x[c];
  }
  for (const auto& [l, w] : D.w) {
    const int k = l - 1, i = k % (kNx + 1), j = (k / (kNx + 1)) % (kNy + 1);
    const Vec3 r = sub(coord(i, j, kNz), D.xbar);
    const Eigen::Vector3d v(r[0], r[1], r[2]);
    D.T += w * (v.squaredNorm() * Eigen::Matrix3d::Identity() - v * v.transpose());
  }
  return D;
}

Vec3 top_coord(int l) {
  const int k = l - 1, i = k % (kNx + 1), j = (k / (kNx + 1)) % (kNy + 1);
  return coord(i, j, kNz);
}

void check_distributing(const Vec3& ref, Weights kind) {
  const Vec3 F{1.0, -2.0, 5.0}, M{0.4, 0.3, -0.6};
  const std::string support = "*BOUNDARY\nBOT, 1, 3\n";
  std::string coupling;
  if (kind == Weights::NodeUniform)
    coupling = "*SURFACE, NAME=TOPN, TYPE=NODE\nTOP\n*COUPLING, CONSTRAINT NAME=D1, "
               "REF NODE=9999, SURFACE=TOPN\n*DISTRIBUTING\n";
  else
    coupling = fmt::format("*COUPLING, CONSTRAINT NAME=D1, REF NODE=9999, SURFACE=TOPS\n"
                           "*DISTRIBUTING, WEIGHTING METHOD={}\n",
                           kind == Weights::LinearArea ? "LINEAR" : "UNIFORM");
  std::string loads = "*CLOAD\n";
  for (int c = 0; c < 3; ++c) loads += fmt::format("9999, {}, {:.17g}\n", c + 1, F[c]);
  for (int c = 0; c < 3; ++c) loads += fmt::format("9999, {}, {:.17g}\n", c + 4, M[c]);
  const JobResult a =
      run_deck(column(ref) + coupling + "*STEP\n*STATIC\n" + support + loads + "*END STEP\n", false,
               "coupled");
  ASSERT_EQ(a.exit_code, 0) << a.error;
  // flat: F_n = w_n (F + (T^-1 (M + r_R x F)) x r_n)
  const Distribution D = distribution(ref, kind);
  const Vec3 rR = sub(ref, D.xbar), Mh0 = cross(rR, F);
  const Eigen::Vector3d Mh(M[0] + Mh0[0], M[1] + Mh0[1], M[2] + Mh0[2]);
  const Eigen::Vector3d q = D.T.inverse() * Mh;
  const Vec3 qv{q(0), q(1), q(2)};
  std::string flat_loads = "*CLOAD\n";
  for (const auto& [l, w] : D.w) {
    const Vec3 m = cross(qv, sub(top_coord(l), D.xbar));
    for (int c = 0; c < 3; ++c)
      flat_loads += fmt::format("{}, {}, {:.17g}\n", l, c + 1, w * (F[c] + m[c]));
  }
  const JobResult f = run_deck(
      column(ref) + "*STEP\n*STATIC\n" + support + flat_loads + "*END STEP\n", false, "flat");
  ASSERT_EQ(f.exit_code, 0) << f.error;
  const Frame& fa = last_frame(a);
  const Frame& ff = last_frame(f);
  double scale = 0.0;
  for (const Vec3& u : ff.nodes.U)
    scale = std::max({scale, std::abs(u[0]), std::abs(u[1]), std::abs(u[2])});
  for (int k = 0; k <= kNz; ++k)
    for (int j = 0; j <= kNy; ++j)
      for (int i = 0; i <= kNx; ++i)
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(U(a, fa, label(i, j, k))[c], U(f, ff, label(i, j, k))[c], 1e-10 * scale)
              << "node " << label(i, j, k);
  // the reference node's motion from the flat deck's coupling nodes
  Eigen::Vector3d s = Eigen::Vector3d::Zero();
  Vec3 ubar{};
  for (const auto& [l, w] : D.w) {
    const Vec3& u = U(f, ff, l);
    const Vec3 m = cross(sub(top_coord(l), D.xbar), u);
    for (int c = 0; c < 3; ++c) {
      ubar[c] += w * u[c];
      s(c) += w * m[c];
    }
  }
  const Eigen::Vector3d th = D.T.inverse() * s;
  const Vec3 thv{th(0), th(1), th(2)};
  const Vec3 uR = cross(thv, rR);
  const NodeId nR = a.model->mesh.find_node(9999);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(fa.nodes.U[nR][c], ubar[c] + uR[c], 1e-10 * scale);
    EXPECT_NEAR(fa.nodes.UR[nR][c], thv[c], 1e-10 * scale);
  }
}

} // namespace

TEST(Coupling, DistributingUniformAtTheCentroid) {
  check_distributing({0.5, 0.5, 4.0}, Weights::UniformArea);
}
TEST(Coupling, DistributingLinearFromAnOffsetReferenceNode) {
  check_distributing({0.8, 0.3, 4.6}, Weights::LinearArea);
}
TEST(Coupling, DistributingOnANodeBasedSurface) {
  check_distributing({0.2, 0.6, 4.3}, Weights::NodeUniform);
}

TEST(Coupling, BadCouplingsAreInputErrors) {
  const std::string base = column({0.5, 0.5, 5.0});
  const std::string step = "*STEP\n*STATIC\n*BOUNDARY\nBOT, 1, 3\n*CLOAD\n9999, 3, 1.\n*END STEP\n";
  auto error_of = [&](const std::string& model) {
    const JobResult r = run_deck(base + model + step);
    EXPECT_EQ(r.exit_code, kExitInputError) << model;
    return r.error;
  };
  auto has = [](const std::string& text, const std::string& what) {
    return text.find(what) != std::string::npos;
  };
  std::string e = error_of("*KINEMATIC\n1, 3\n");
  EXPECT_TRUE(has(e, "*KINEMATIC must follow *COUPLING")) << e;
  // a failed *COUPLING: one message, its *KINEMATIC is skipped quietly
  e = error_of("*COUPLING, CONSTRAINT NAME=C, REF NODE=9999, SURFACE=NOPE\n*KINEMATIC\n");
  EXPECT_TRUE(has(e, "SURFACE=NOPE: this surface is not defined")) << e;
  EXPECT_EQ(std::count(e.begin(), e.end(), '\n'), 0) << e;
  // a *COUPLING rejected for its first parameter still opens its block (this crashed once)
  e = error_of("*COUPLING, CONSTRAINT NAME=C, REF NODE=9999, SURFACE=TOPS, ORIENTATION=OR1\n"
               "*KINEMATIC\n");
  EXPECT_TRUE(has(e, "ORIENTATION")) << e;
  EXPECT_EQ(std::count(e.begin(), e.end(), '\n'), 0) << e;
  e = error_of("*COUPLING, CONSTRAINT NAME=C, REF NODE=TOP, SURFACE=TOPS\n*KINEMATIC\n");
  EXPECT_TRUE(has(e, "REF NODE names one node; this set holds 9")) << e;
  e = error_of("*COUPLING, CONSTRAINT NAME=C, REF NODE=9999, SURFACE=TOPS, INFLUENCE RADIUS=0.1\n"
               "*KINEMATIC\n");
  EXPECT_TRUE(has(e, "no node of the surface lies within the influence radius")) << e;
  // a node in two kinematic couplings
  e = error_of("*KINEMATIC COUPLING, REF NODE=9999\nTOP, 1, 3\n*KINEMATIC COUPLING, REF NODE=1\n" +
               std::to_string(label(1, 1, kNz)) + ", 3, 3\n");
  EXPECT_TRUE(has(e, "already the dependent DOF of the constraint at kinematic coupling to node "
                     "9999"))
      << e;
  // collinear coupling nodes cannot carry the reference node's rotations
  e = error_of("*SURFACE, NAME=LINE, TYPE=NODE\n" + std::to_string(label(0, 0, kNz)) + "\n" +
               std::to_string(label(1, 0, kNz)) + "\n" + std::to_string(label(2, 0, kNz)) +
               "\n*COUPLING, CONSTRAINT NAME=D, REF NODE=9999, SURFACE=LINE\n*DISTRIBUTING\n");
  EXPECT_TRUE(has(e, "coupling D: the coupling nodes lie on one line")) << e;
  e = error_of("*COUPLING, CONSTRAINT NAME=C, REF NODE=9999, SURFACE=TOPS\n*DISTRIBUTING, "
               "COUPLING=STRUCTURAL\n");
  EXPECT_TRUE(has(e, "COUPLING=STRUCTURAL")) << e;
}
