// Deck-level verification of the structural elements: each deck in this directory is run through
// gapfem::run_job and compared with a closed-form answer (derivations next to each check).
// Linear decks solve exactly up to round-off, so the tolerances are relative 1e-8 of the checked
// quantity; the NLGEOM deck's free DOF stays at zero by symmetry and every other DOF is prescribed,
// so its forces are exact functions of the prescribed motion and the same tolerance applies.
#include "structural_deck_support.hpp"

#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <numbers>
#include <string>

namespace gapfem {
namespace {

TEST(VerificationStructuralTruss, PlanarDeterminateTriangleAndThreeBarTruss) {
  DeckRun run("truss_2d.inp");
  if (!run.ok()) return;
  // Triangle: apex equilibrium 2 N sin(a) = -P gives N = -1200 / 1.2 = -1000 in both diagonals;
  // roller node 2 in x: N12 = -N23 cos(a) = 800. EA = 2e7.
  EXPECT_REL(run.el(1, ElemVar::SF, 0), 800.0);
  EXPECT_REL(run.el(2, ElemVar::SF, 0), -1000.0);
  EXPECT_REL(run.el(3, ElemVar::SF, 0), -1000.0);
  EXPECT_REL(run.el(2, ElemVar::S, 0), -10.0); // N / A
  EXPECT_REL(run.el(1, ElemVar::E, 0), 4e-5);  // N / (E A)
  // Elongations 1.6e-4 (chord) and -1.25e-4 (diagonals): u2 = 1.6e-4; at the apex
  // 0.8 u + 0.6 v = -1.25e-4 and -0.8 (u - 1.6e-4) + 0.6 v = -1.25e-4 give u = 8e-5,
  // v = -3.15e-4 (= sum N n L / EA by virtual work).
  EXPECT_SCALED(run.U(2)[0], 1.6e-4, 1.6e-4);
  EXPECT_SCALED(run.U(3)[0], 8e-5, 3.15e-4);
  EXPECT_SCALED(run.U(3)[1], -3.15e-4, 3.15e-4);
  // Supports carry 600 each upward; node 1 has no horizontal reaction.
  EXPECT_REL(run.RF(1)[1], 600.0);
  EXPECT_REL(run.RF(2)[1], 600.0);
  EXPECT_SCALED(run.RF(1)[0], 0.0, 1200.0);

  // Three-bar truss, theta = 45 deg: compatibility N_side = N_mid cos^2, equilibrium
  // N_mid (1 + 2 cos^3) = P: N_mid = 1000 / (1 + 1/sqrt 2), v = -N_mid L / (E A), EA = 7e5.
  const double c = std::cos(std::numbers::pi / 4);
  const double n_mid = 1000.0 / (1.0 + 2.0 * c * c * c), n_side = n_mid * c * c;
  EXPECT_REL(run.el(12, ElemVar::SF, 0), n_mid);
  EXPECT_REL(run.el(11, ElemVar::SF, 0), n_side);
  EXPECT_REL(run.el(13, ElemVar::SF, 0), n_side);
  const double v = n_mid * 1.0 / 7e5;
  EXPECT_SCALED(run.U(14)[1], -v, v);
  EXPECT_SCALED(run.U(14)[0], 0.0, v);
}

TEST(VerificationStructuralTruss, SpatialTripod) {
  DeckRun run("truss_3d_tripod.inp");
  if (!run.ok()) return;
  // Each leg (L = 5, cos(beta) = 0.8): N = -P / (3 cos beta) = -375; apex
  // w = P L / (3 E A cos^2 beta) = 900 * 5 / (3 * 1e7 * 0.64) = 2.34375e-4.
  for (Label e : {1, 2, 3}) EXPECT_REL(run.el(e, ElemVar::SF, 0), -375.0);
  EXPECT_SCALED(run.U(4)[2], -2.34375e-4, 2.34375e-4);
  EXPECT_SCALED(run.U(4)[0], 0.0, 2.34375e-4);
  EXPECT_SCALED(run.U(4)[1], 0.0, 2.34375e-4);
  for (Label n : {1, 2, 3}) EXPECT_REL(run.RF(n)[2], 300.0);
  // Horizontal reaction 375 * 0.6 = 225: the compressed leg pushes support 1 outwards (+x), so
  // the support pushes the structure towards the axis: RF_x = -225.
  EXPECT_REL(run.RF(1)[0], -225.0);
}

TEST(VerificationStructuralTruss, ThermalStrainInAConstrainedTruss) {
  DeckRun run("truss_thermal.inp");
  if (!run.ok()) return;
  // Total elongation zero: N (L1/A1 + L2/A2) / E = -alpha dT (L1 + L2)
  //   N = -1.2e-5 * 100 * 500 * 2e5 / (3 + 1) = -30000.
  // Bar 1: elongation N L1/(E A1) + alpha dT L1 = -0.45 + 0.36 = -0.09 = u2.
  EXPECT_REL(run.el(1, ElemVar::SF, 0), -30000.0);
  EXPECT_REL(run.el(2, ElemVar::SF, 0), -30000.0);
  EXPECT_REL(run.el(1, ElemVar::S, 0), -300.0);
  EXPECT_REL(run.el(2, ElemVar::S, 0), -150.0);
  EXPECT_SCALED(run.el(1, ElemVar::E, 0), -0.09 / 300.0, 1e-3); // total strain
  EXPECT_SCALED(run.el(2, ElemVar::E, 0), 0.09 / 200.0, 1e-3);
  EXPECT_SCALED(run.U(2)[0], -0.09, 0.09);
  EXPECT_REL(run.RF(1)[0], 30000.0);
  EXPECT_REL(run.RF(3)[0], -30000.0);
}

TEST(VerificationStructuralTruss, LargeRotationWithNlgeom) {
  DeckRun run("truss_nlgeom.inp");
  if (!run.ok()) return;
  const double EA = 200000.0 * 10.0;
  int checked = 0;
  for (const Frame& f : run.res.frames) {
    if (f.step != 1 || f.step_time <= 0.0) continue;
    const double t = f.step_time; // ramped boundary conditions: fraction of the final values
    // A: apex at (0, 20 - w), w = 40 t. Bars from (+-100, 0): l = sqrt(100^2 + (20 - w)^2),
    // N = EA ln(l/L), L = sqrt(100^2 + 20^2); the apex reaction is the sum of the bar forces'
    // y components: RF_y = 2 N (20 - w) / l (zero at w = 20 and again at w = 40).
    const double w = 40.0 * t, h = 20.0 - w;
    const double L = std::hypot(100.0, 20.0), l = std::hypot(100.0, h);
    const double N = EA * std::log(l / L);
    const NodeId apex = run.node(3);
    EXPECT_NEAR(f.nodes.RF[apex][1], 2.0 * N * h / l, kRel * EA * 0.1) << "t = " << t;
    EXPECT_NEAR(f.nodes.U[apex][0], 0.0, 1e-9) << "t = " << t;
    // B: node 12 at (300 - 100 t, 120 t): d = (100 - 100 t, 120 t), N = EA ln(|d| / 100),
    // RF(12) = N d / |d|.
    const double dx = 100.0 - 100.0 * t, dy = 120.0 * t, lb = std::hypot(dx, dy);
    const double Nb = EA * std::log(lb / 100.0);
    const NodeId tip = run.node(12);
    EXPECT_NEAR(f.nodes.RF[tip][0], Nb * dx / lb, kRel * EA * 0.2) << "t = " << t;
    EXPECT_NEAR(f.nodes.RF[tip][1], Nb * dy / lb, kRel * EA * 0.2) << "t = " << t;
    ++checked;
  }
  EXPECT_GE(checked, 10); // ten fixed increments, each printed (FREQUENCY=1)
  // End state of B: turned by 90 degrees, l = 120: log strain ln 1.2, true stress E ln 1.2.
  EXPECT_REL(run.el(11, ElemVar::E, 0), std::log(1.2));
  EXPECT_REL(run.el(11, ElemVar::S, 0), 200000.0 * std::log(1.2));
  EXPECT_REL(run.el(11, ElemVar::SF, 0), EA * std::log(1.2));
  EXPECT_SCALED(run.el(1, ElemVar::SF, 0), 0.0, EA * 1e-3); // A is back at its initial length
}

TEST(VerificationStructuralSpring, SpringChainInSeriesAndToGround) {
  DeckRun run("spring_chain.inp");
  if (!run.ok()) return;
  // Series stiffness 1/(1/1000 + 1/2000 + 1/4000) = 4000/7 in parallel with 500 at node 4:
  // u4 = 300 / (4000/7 + 500) = 0.28; chain force 160, ground spring 140;
  // u2 = 160/1000 = 0.16, u3 = u2 + 160/2000 = 0.24.
  EXPECT_REL(run.U(2)[0], 0.16);
  EXPECT_REL(run.U(3)[0], 0.24);
  EXPECT_REL(run.U(4)[0], 0.28);
  EXPECT_REL(run.RF(1)[0], -160.0);
  EXPECT_REL(run.el(1, ElemVar::S, 0), 160.0); // SPRINGA: force, elongation
  EXPECT_REL(run.el(1, ElemVar::E, 0), 0.16);
  EXPECT_REL(run.el(2, ElemVar::S, 0), -160.0); // SPRING2: du = u1(2) - u1(3) = -0.08
  EXPECT_REL(run.el(2, ElemVar::E, 0), -0.08);
  EXPECT_REL(run.el(3, ElemVar::S, 0), 160.0);
  EXPECT_REL(run.el(4, ElemVar::S, 0), 140.0); // SPRING1: k u4
  EXPECT_REL(run.el(4, ElemVar::E, 0), 0.28);
}

/// St. Venant torsion constant of an a x b rectangle (a >= b), series of Timoshenko & Goodier
/// §109, written out here independently of the library.
double rect_J(double a, double b) {
  double s = 0.0;
  for (int n = 1; n < 60; n += 2)
    s += std::tanh(n * std::numbers::pi * a / (2 * b)) / std::pow(n, 5);
  return a * b * b * b / 3.0 * (1.0 - 192.0 / std::pow(std::numbers::pi, 5) * (b / a) * s);
}

struct BeamCase {
  Label tip, root_elem;
  double A, I11, I22, J, k;
  double c1, c2; ///< coordinates of section point 1 (local 1, local 2)
};

TEST(VerificationStructuralBeam, CantileverTipDeflectionAndRotationIncludingShear) {
  DeckRun run("beam_cantilevers.inp");
  if (!run.ok()) return;
  const double pi = std::numbers::pi;
  const double E = 210000.0, G = E / 2.6, L = 200.0, Py = 1000.0, Pz = 500.0, T = 20000.0;
  const double rp = 20.0, ri = 17.0; // PIPE outer radius, inner radius r - t
  const BeamCase cases[] = {
      // RECT a = 20 (local 1 = -z), b = 40 (local 2 = +y): I11 = a b^3/12, I22 = b a^3/12,
      // Abaqus shear factor 0.85. Section point 1 at (a/2, b/2).
      {5, 1, 800.0, 20.0 * 64000.0 / 12.0, 40.0 * 8000.0 / 12.0, rect_J(40.0, 20.0), 0.85, 10.0,
       20.0},
      // CIRC r = 15: I = pi r^4/4, J = pi r^4/2, k = 0.89. Point 1 at (r, 0).
      {15, 11, pi * 225.0, pi * 50625.0 / 4.0, pi * 50625.0 / 4.0, pi * 50625.0 / 2.0, 0.89, 15.0,
       0.0},
      // PIPE r = 20, t = 3: exact annulus, k = 0.53.
      {25, 21, pi * (rp * rp - ri * ri), pi * (std::pow(rp, 4) - std::pow(ri, 4)) / 4.0,
       pi * (std::pow(rp, 4) - std::pow(ri, 4)) / 4.0,
       pi * (std::pow(rp, 4) - std::pow(ri, 4)) / 2.0, 0.53, 20.0, 0.0},
  };
  for (const BeamCase& c : cases) {
    SCOPED_TRACE(::testing::Message() << "tip node " << c.tip);
    const double kGA = c.k * G * c.A;
    // Timoshenko cantilever under a tip force: w = P L^3/(3 E I) + P L/(k G A), slope
    // P L^2/(2 E I); twist T L/(G J). Fy bends about local 1 (-z) with I11, Fz about local 2
    // (+y) with I22; rotation about +z is positive for Fy, about +y negative for Fz.
    const double uy = Py * L * L * L / (3 * E * c.I11) + Py * L / kGA;
    const double uz = Pz * L * L * L / (3 * E * c.I22) + Pz * L / kGA;
    EXPECT_SCALED(run.U(c.tip)[1], uy, uy);
    EXPECT_SCALED(run.U(c.tip)[2], uz, uz);
    EXPECT_SCALED(run.U(c.tip)[0], 0.0, uy);
    EXPECT_SCALED(run.UR(c.tip)[2], Py * L * L / (2 * E * c.I11), uy / L);
    EXPECT_SCALED(run.UR(c.tip)[1], -Pz * L * L / (2 * E * c.I22), uy / L);
    EXPECT_SCALED(run.UR(c.tip)[0], T * L / (G * c.J), T * L / (G * c.J));
    // Section forces at the integration point (x = 25) of the root element, on the face with
    // outward normal +x: SF2 (along n2 = +y) = Fy, SF3 (along n1 = -z) = -Fz,
    // SM1 (about n1 = -z) = -Fy (L - 25), SM2 (about n2 = +y) = -Fz (L - 25), SM3 = T.
    EXPECT_SCALED(run.el(c.root_elem, ElemVar::SF, 0), 0.0, Py);
    EXPECT_REL(run.el(c.root_elem, ElemVar::SF, 1), Py);
    EXPECT_REL(run.el(c.root_elem, ElemVar::SF, 2), -Pz);
    const double M1 = -Py * 175.0, M2 = -Pz * 175.0;
    EXPECT_REL(run.el(c.root_elem, ElemVar::SF, 3), M1);
    EXPECT_REL(run.el(c.root_elem, ElemVar::SF, 4), M2);
    EXPECT_REL(run.el(c.root_elem, ElemVar::SF, 5), T);
    // Axial stress at section point 1: S11 = M1 x2 / I11 - M2 x1 / I22.
    EXPECT_REL(run.el(c.root_elem, ElemVar::S, 0, 0), M1 * c.c2 / c.I11 - M2 * c.c1 / c.I22);
  }
  // Reactions at the clamped roots balance the tip loads.
  EXPECT_REL(run.RF(1)[1], -Py);
  EXPECT_REL(run.RF(11)[2], -Pz);
  EXPECT_REL(run.end->nodes.RM[run.node(21)][0], -T);
}

TEST(VerificationStructuralBeam, CantileverUnderOwnWeightIsNodallyExact) {
  DeckRun run("beam_gravity.inp");
  if (!run.ok()) return;
  // q = rho A g = 7.85e-9 * 800 * 9810 per length in -y. Consistent loads (qL/2, qL^2/12) and the
  // exact element stiffness make the nodal values exact for any mesh:
  // w(L) = q L^4/(8 E I) + q L^2/(2 k G A), slope q L^3/(6 E I); I = I11 = 20 * 40^3 / 12.
  const double E = 210000.0, G = E / 2.6, L = 200.0, A = 800.0, I = 20.0 * 64000.0 / 12.0;
  const double q = 7.85e-9 * A * 9810.0;
  const double w = q * std::pow(L, 4) / (8 * E * I) + q * L * L / (2 * 0.85 * G * A);
  EXPECT_SCALED(run.U(6)[1], -w, w);
  EXPECT_SCALED(run.UR(6)[2], -q * L * L * L / (6 * E * I), w / L);
  // The root carries the whole weight and its moment q L^2/2 (counter-clockwise, about +z).
  EXPECT_REL(run.RF(1)[1], q * L);
  EXPECT_REL(run.end->nodes.RM[run.node(1)][2], q * L * L / 2);
  // Root element: shear at the integration point (x = 20) is q (L - 20) along +y... carried by
  // the positive face as -q (L - 20) (the load beyond the cut acts in -y).
  EXPECT_REL(run.el(1, ElemVar::SF, 1), -q * (L - 20.0));
}

} // namespace
} // namespace gapfem
