// Linear cantilevers with the beam section library and the new element layouts; every answer is
// the closed-form Timoshenko cantilever, which these elements reproduce at the nodes for any mesh
// (two-node: exact prismatic stiffness; three-node with two points: exact for the cubic
// deflection of a linearly varying moment and the quartic one of a uniform load).
// E = 210000, nu = 0.3 (G = E / 2.6), L = 1000 along x, n1 = -z (so n2 = +y).
#include "structural_deck_support.hpp"

namespace gapfem {
namespace {

constexpr double E = 210000.0, G = E / 2.6, L = 1000.0;

TEST(VerificationStructuralBeamSections, BoxIGeneralHexAndB32Cantilevers) {
  DeckRun run("beam_sections.inp");
  if (!run.ok()) return;
  {
    // BOX 100 x 200 (outer), walls 5, 10, 5, 10: thin-walled mid-line 95 x 190; tip Fy = 1000.
    // A = 2 (190)(5) + 2 (95)(10); I11 = 2 (5)(190^3)/12 + 2 (10)(95)(95^2); k = 0.44.
    const double w = 95.0, h = 190.0, A = 2 * h * 5 + 2 * w * 10;
    const double I11 = 2 * 5 * h * h * h / 12 + 2 * 10 * w * h * h / 4;
    const double uy = 1000 * L * L * L / (3 * E * I11) + 1000 * L / (0.44 * G * A);
    EXPECT_REL(run.U(5)[1], uy);
  }
  {
    // I: l = 50, h = 300, b1 = 150, b2 = 100, t1 = 12, t2 = 10, t3 = 8. Mid-lines: bottom flange
    // y_b = -50 + 6, top y_t = 300 - 50 - 5, web between them. The node (section origin) lies
    // ybar = -Q2 / A from the centroid (Q2 > 0: below it), so an axial tip force P at the node
    // bends the beam: constant moment -P ybar about the centroid, curvature P ybar / (E Ic), and
    // the node's axial displacement P L (1/(E A) + ybar^2 / (E Ic)).
    const double yb = -44.0, yt = 245.0, Lw = yt - yb;
    const double Ab = 150 * 12, At = 100 * 10, Aw = Lw * 8, A = Ab + At + Aw;
    const double Q2 = Ab * yb + At * yt + Aw * 0.5 * (yb + yt);
    const double I11 = Ab * yb * yb + At * yt * yt + 8 * (yt * yt * yt - yb * yb * yb) / 3;
    const double ybar = Q2 / A, Ic = I11 - Q2 * Q2 / A, P = 10000.0;
    EXPECT_REL(run.U(10)[0], P * L * (1 / (E * A) + ybar * ybar / (E * Ic)));
    EXPECT_REL(run.U(10)[1], P * ybar * L * L / (2 * E * Ic));
    EXPECT_REL(run.UR(10)[2], P * ybar * L / (E * Ic));
  }
  {
    // GENERAL A = 2500, I11 = 4e6, I12 = 1e6, I22 = 2e6, G given, shear factor 1: unsymmetric
    // bending under Fy = 1000. M1 = -F (L - x) about n1; the curvatures are
    // [k1, k2] = (E [[I11, -I12], [-I12, I22]])^-1 [M1, 0], so with v2'' = -k1 (along n2 = y) and
    // v1'' = k2 (along n1 = -z): u_y = F I22 L^3 / (3 E det) + F L / (G A),
    // u_z = F I12 L^3 / (3 E det), det = I11 I22 - I12^2.
    const double A = 2500, I11 = 4e6, I12 = 1e6, I22 = 2e6, det = I11 * I22 - I12 * I12;
    const double Gg = 80769.23076923077, F = 1000.0;
    EXPECT_REL(run.U(21)[1], F * I22 * L * L * L / (3 * E * det) + F * L / (Gg * A));
    EXPECT_REL(run.U(21)[2], F * I12 * L * L * L / (3 * E * det));
  }
  {
    // HEX r = 60 (outer corner radius), t = 4: thin-walled on the mid-line hexagon of side
    // s = r - t / sqrt(3). Each wall at apothem a = s sqrt(3) / 2 adds t (a^2 s + s^3 / 12) =
    // (5/6) t s^3 to the polar moment, so I11 = I22 = (1/2) 6 (5/6) t s^3 = 2.5 t s^3; A = 6 s t;
    // Bredt J = 4 A_m^2 t / (6 s) with A_m = (3 sqrt(3) / 2) s^2, i.e. J = 4.5 t s^3; k = 0.53 (a
    // thin tube). Tip Fy = 1000 and torque Mx = 1e6.
    const double t = 4.0, s = 60.0 - t / std::sqrt(3.0), A = 6 * s * t, I = 2.5 * t * s * s * s;
    const double J = 4.5 * t * s * s * s;
    EXPECT_REL(run.U(31)[1], 1000 * L * L * L / (3 * E * I) + 1000 * L / (0.53 * G * A));
    EXPECT_REL(run.UR(31)[2], 1000 * L * L / (2 * E * I));
    EXPECT_REL(run.UR(31)[0], 1e6 * L / (G * J));
  }
  {
    // B32 (two elements), RECT 20 x 40, Fy = 1000: w = F L^3 / (3 E I) + F L / (0.85 G A),
    // slope F L^2 / (2 E I).
    const double A = 800, I = 20.0 * 64000.0 / 12.0;
    EXPECT_REL(run.U(26)[1], 1000 * L * L * L / (3 * E * I) + 1000 * L / (0.85 * G * A));
    EXPECT_REL(run.UR(26)[2], 1000 * L * L / (2 * E * I));
  }
}

TEST(VerificationStructuralBeamSections, LAndTrapezoidCantilevers) {
  DeckRun run("beam_sections_l_trapezoid.inp");
  if (!run.ok()) return;
  {
    // L a = 80 (leg along 1, thickness t1 = 6), b = 120 (leg along 2, t2 = 5), origin at the
    // centroid. Thin-walled: strips on the mid-lines from the corner (t2/2, t1/2): along 1 of
    // length a - t2/2, along 2 of length b - t1/2. Tip Fx = 1e4 (at the centroid: no bending),
    // Fy = 1000 (unsymmetric bending as the GENERAL section above, k = 0.44), torque 1e4
    // (J = sum L t^3 / 3).
    const double a = 80, b = 120, t1 = 6, t2 = 5, la = a - t2 / 2, lb = b - t1 / 2;
    const double Ah = t1 * la, xh = t2 / 2 + la / 2, yh = t1 / 2;
    const double Av = t2 * lb, xv = t2 / 2, yv = t1 / 2 + lb / 2;
    const double A = Ah + Av, cx = (Ah * xh + Av * xv) / A, cy = (Ah * yh + Av * yv) / A;
    const double I11 =
        Ah * (yh - cy) * (yh - cy) + t2 * lb * lb * lb / 12 + Av * (yv - cy) * (yv - cy);
    const double I22 =
        t1 * la * la * la / 12 + Ah * (xh - cx) * (xh - cx) + Av * (xv - cx) * (xv - cx);
    const double I12 = Ah * (xh - cx) * (yh - cy) + Av * (xv - cx) * (yv - cy);
    const double det = I11 * I22 - I12 * I12, F = 1000.0,
                 J = (la * t1 * t1 * t1 + lb * t2 * t2 * t2) / 3;
    EXPECT_REL(run.U(5)[0], 10000 * L / (E * A));
    EXPECT_REL(run.U(5)[1], F * I22 * L * L * L / (3 * E * det) + F * L / (0.44 * G * A));
    EXPECT_REL(run.U(5)[2], F * I12 * L * L * L / (3 * E * det));
    EXPECT_REL(run.UR(5)[0], 10000 * L / (G * J));
  }
  {
    // TRAPEZOID a = 60 (bottom), b = 100, c = 20 (top), origin d = 20 above the bottom: the
    // centroid lies b (a + 2c) / (3 (a + c)) above the bottom, ybar above the node, and
    // Ic = b^3 (a^2 + 4ac + c^2) / (36 (a + c)). An axial force P at the node bends the beam
    // as the I section's above; a tip Fy bends it about the centroid (k = 0.85).
    const double a = 60, b = 100, c = 20, d = 20, A = 0.5 * (a + c) * b;
    const double ybar = b * (a + 2 * c) / (3 * (a + c)) - d;
    const double Ic = b * b * b * (a * a + 4 * a * c + c * c) / (36 * (a + c)), P = 10000.0;
    EXPECT_REL(run.U(10)[0], P * L * (1 / (E * A) + ybar * ybar / (E * Ic)));
    EXPECT_REL(run.U(10)[1], P * ybar * L * L / (2 * E * Ic));
    EXPECT_REL(run.U(15)[1], 1000 * L * L * L / (3 * E * Ic) + 1000 * L / (0.85 * G * A));
    EXPECT_REL(run.UR(15)[2], 1000 * L * L / (2 * E * Ic));
  }
}

TEST(VerificationStructuralBeamSections, PlanarB21AndB22UnderUniformLoad) {
  DeckRun run("beam_planar_load.inp");
  if (!run.ok()) return;
  // q = 2 along n2 = +y: w = q L^4 / (8 E I) + q L^2 / (2 k G A), slope q L^3 / (6 E I);
  // the root shear force q L and moment q L^2 / 2 (SM1 about n1 = -z: -q (L - x)^2 / 2).
  const double q = 2.0, A = 800, I = 20.0 * 64000.0 / 12.0;
  for (Label tip : {5, 10}) {
    EXPECT_REL(run.U(tip)[1], q * L * L * L * L / (8 * E * I) + q * L * L / (2 * 0.85 * G * A));
    EXPECT_REL(run.UR(tip)[2], q * L * L * L / (6 * E * I));
  }
  EXPECT_REL(run.RF(1)[1], -q * L);
  EXPECT_REL(run.RF(6)[1], -q * L);
  // B21 element 1 (x in [0, 250]): SF2 = q (L - 125) at its point; the one-point element's moment
  // EI (theta_B - theta_A) / l_e is the element's mean moment, -q (1000^3 - 750^3) / (6 * 250)
  EXPECT_REL(run.el(1, ElemVar::SF, 1), q * 875.0);
  EXPECT_REL(run.el(1, ElemVar::SF, 2), -q * (1e9 - 750.0 * 750.0 * 750.0) / (6 * 250.0));
}

} // namespace
} // namespace gapfem

namespace gapfem {
namespace {

// pipe_pressure.inp: PIPE r = 50, t = 5 (a = 45, b = 50), E = 200000, nu = 0.3, legs of 1000.
// Closed-end condition, Lame's thick cylinder with free axial extension (generalised plane
// strain): sigma_z = (p_i a^2 - p_e b^2) / (b^2 - a^2), sigma_r + sigma_theta = 2 sigma_z at every
// radius, so eps_z = (sigma_z - nu (sigma_r + sigma_theta)) / E = (1 - 2 nu) sigma_z / E, the
// wall's axial force sigma_z A = pi (p_i a^2 - p_e b^2), and the hoop stress at the outer radius
// sigma_theta(b) = (2 p_i a^2 - p_e (a^2 + b^2)) / (b^2 - a^2).
TEST(VerificationStructuralBeamSections, PipesUnderInternalAndExternalPressure) {
  DeckRun run("pipe_pressure.inp");
  if (!run.ok()) return;
  const double a = 45.0, b = 50.0, d = b * b - a * a, Ep = 200000.0, nu = 0.3, L = 1000.0;
  const double pi_ = std::acos(-1.0);
  {
    // straight PIPE31 under PI = 10, clamped at node 1, closed free end at node 5
    const double p = 10.0, sz = p * a * a / d;
    EXPECT_REL(run.U(5)[0], (1 - 2 * nu) * sz / Ep * L);
    EXPECT_SCALED(run.U(5)[1], 0.0, 1e-3);
    EXPECT_REL(run.el(2, ElemVar::SF, 0), p * pi_ * a * a);
    EXPECT_REL(run.el(2, ElemVar::S, 0, 0), sz);                // S11 at section point 1
    EXPECT_REL(run.el(2, ElemVar::S, 1, 0), 2 * p * a * a / d); // S22: hoop at r = b
    EXPECT_SCALED(run.RF(1)[0], 0.0, p * pi_ * a * a);          // a closed vessel: no reaction
  }
  {
    // PIPE32 (two elements) under PE = 2: sigma_z = -p b^2 / d
    const double p = 2.0, sz = -p * b * b / d;
    EXPECT_REL(run.U(10)[0], (1 - 2 * nu) * sz / Ep * L);
    EXPECT_REL(run.el(5, ElemVar::SF, 0), -p * pi_ * b * b);
    EXPECT_REL(run.el(5, ElemVar::S, 1, 0), -p * (a * a + b * b) / d);
  }
  {
    // an L of two straight legs held at the corner (node 21) only: each leg is a closed pipe
    // extending freely, and the whole is a closed vessel, so the corner carries no force (the
    // end-cap forces at the kink are the bend's pressure thrust, which the legs' walls take)
    const double p = 10.0, e = (1 - 2 * nu) * p * a * a / d / Ep;
    EXPECT_REL(run.U(23)[0], -e * L);
    EXPECT_REL(run.U(25)[1], e * L);
    for (int i = 0; i < 3; ++i) EXPECT_SCALED(run.RF(21)[i], 0.0, p * pi_ * a * a);
    EXPECT_REL(run.el(7, ElemVar::SF, 0), p * pi_ * a * a);
    EXPECT_REL(run.el(10, ElemVar::SF, 0), p * pi_ * a * a);
  }
}

} // namespace
} // namespace gapfem
