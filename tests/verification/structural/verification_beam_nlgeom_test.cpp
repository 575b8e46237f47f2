// Beams under NLGEOM: cantilevers rolled into a full circle by an end moment (beam_rollup_3d.inp:
// B31 and B32; beam_rollup_2d.inp: B21 and B22), checked in every increment.
//
// Closed form (Euler-Bernoulli, inextensible): a constant moment M gives the constant curvature
// kappa = M / EI, so a cantilever of length L bends into an arc: the tip is at
//   x = sin(kappa L) / kappa,  y = (1 - cos(kappa L)) / kappa,  rotation kappa L,
// and M = 2 pi EI / L closes the circle (the tip returns to the root with rotation 2 pi).
//
// Two-node elements (one integration point at mid-length, the rotation there the midpoint of the
// nodal rotations): the moment is carried with zero axial and shear strain when every element
// turns by Delta = kappa L / n and keeps its chord length L / n along its mid-point rotation, so
// the nodes lie on a regular polygon: the tip is at
//   x = (L/n) sum_i cos((i - 1/2) Delta) = L sin(kappa L) / (2 n sin(Delta / 2)),
//   y = L (1 - cos(kappa L)) / (2 n sin(Delta / 2)),
// which is the solution of the discrete equations, and at M = 2 pi EI / L the polygon closes.
// Three-node elements approximate the arc: their error is measured against the circle.
#include "structural_deck_support.hpp"

#include <numbers>

namespace gapfem {
namespace {

constexpr double kL = 10.0, kEI = 1000.0, kM = 2.0 * std::numbers::pi * kEI / kL;

struct RollupCase {
  Label tip;
  int n;      ///< elements (0: compare with the continuous circle)
  double tol; ///< on the tip displacement, relative to L
};

void check_rollup(const std::string& deck, const RollupCase (&cases)[2], int space_dim) {
  DeckRun run(deck);
  if (!run.ok()) return;
  int frames = 0;
  for (const Frame& f : run.res.frames) {
    if (f.step != 1 || f.step_time <= 0.0) continue;
    ++frames;
    const double kappa = f.step_time * kM / kEI, phi = kappa * kL;
    for (const RollupCase& c : cases) {
      SCOPED_TRACE(::testing::Message() << deck << " tip " << c.tip << " time " << f.step_time);
      const double scale = c.n > 0 ? kL / (2.0 * c.n * std::sin(0.5 * phi / c.n)) : 1.0 / kappa;
      const NodeId tip = run.node(c.tip);
      EXPECT_NEAR(f.nodes.U[tip][0], scale * std::sin(phi) - kL, c.tol * kL);
      EXPECT_NEAR(f.nodes.U[tip][1], scale * (1.0 - std::cos(phi)), c.tol * kL);
      EXPECT_NEAR(f.nodes.UR[tip][2], phi, c.tol);
      if (space_dim == 3) {
        EXPECT_NEAR(f.nodes.U[tip][2], 0.0, 1e-12);
        EXPECT_NEAR(f.nodes.UR[tip][0], 0.0, 1e-12);
        EXPECT_NEAR(f.nodes.UR[tip][1], 0.0, 1e-12);
      }
    }
  }
  EXPECT_GE(frames, 10);              // at most 0.05 of the moment per increment
  for (const RollupCase& c : cases) { // the circle closes: the tip is back at the root
    EXPECT_NEAR(run.U(c.tip)[0], -kL, c.tol * kL);
    EXPECT_NEAR(run.U(c.tip)[1], 0.0, c.tol * kL);
    EXPECT_NEAR(run.UR(c.tip)[2], 2.0 * std::numbers::pi, c.tol);
  }
  // the section moment is the end moment everywhere, SM1 about n1 = -z: -M (element 1, the
  // root); no axial or shear force
  EXPECT_NEAR(run.el(1, ElemVar::SF, 0), 0.0, 1e-6 * kM);
  EXPECT_NEAR(run.el(1, ElemVar::SF, 1), 0.0, 1e-6 * kM);
  EXPECT_NEAR(run.el(1, ElemVar::SF, space_dim == 3 ? 3 : 2), -kM, 1e-6 * kM);
}

TEST(VerificationStructuralBeamNlgeom, B31AndB32RollIntoACircle) {
  const RollupCase cases[2] = {{11, 10, 1e-6}, {22, 0, 1e-4}};
  check_rollup("beam_rollup_3d.inp", cases, 3);
}

TEST(VerificationStructuralBeamNlgeom, B21AndB22RollIntoACircle) {
  const RollupCase cases[2] = {{11, 10, 1e-6}, {22, 0, 1e-4}};
  check_rollup("beam_rollup_2d.inp", cases, 2);
}

} // namespace
} // namespace gapfem
