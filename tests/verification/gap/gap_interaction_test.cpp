// Verification decks of the gap interaction models (issue 4) with closed-form answers: spec M3
// (stick then slip), a stick-slip-stick cycle with its hysteresis loop and dissipated energy,
// friction on GAPCYL and GAPSPHER, each softened law at several overclosures, NO SEPARATION in
// tension, augmented Lagrange against DIRECT, contact damping, *CHANGE FRICTION.
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <string>

using namespace gapfem;
using namespace gapfem::test;

namespace {

// M3: node 10 on springs k_x = 100 (and k_y = 1 as a stabiliser) closed against ground node 12
// through a GAPUNI with d = 0, n = (0,-1,0). Step 1 presses with Fy = -100 (normal force 100).
std::string m3_deck(const std::string& friction, double fx, const std::string& extra_steps = "") {
  return fmt::format(R"(*NODE
10, 0., 0., 0.
12, 0., -1., 0.
*ELEMENT, TYPE=SPRING1, ELSET=SX
1, 10
*ELEMENT, TYPE=SPRING1, ELSET=SY
2, 10
*SPRING, ELSET=SX
1
100.
*SPRING, ELSET=SY
2
1.
*ELEMENT, TYPE=GAPUNI, ELSET=G1
101, 10, 12
*GAP, ELSET=G1
0., 0., -1., 0., 1.
{}
*BOUNDARY
12, 1, 3
10, 3, 3
*STEP
*STATIC
*CLOAD
10, 2, -100.
*END STEP
*STEP
*STATIC
0.25, 1.
*CLOAD
10, 1, {}
*EL PRINT
S, E
*END STEP
{})",
                     friction, fx, extra_steps);
}

} // namespace

TEST(VerificationGapFriction, M3StickWithLagrange) {
  const JobResult r = run_deck(m3_deck("*FRICTION, LAGRANGE\n0.3", 20.0));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  const GapRecord& g = gap(r, f, 101);
  EXPECT_EQ(g.status, ContactStatus::Stick);
  EXPECT_NEAR(g.normal_force, 100.0, 1e-9);
  EXPECT_NEAR(U(r, f, 10)[0], 0.0, 1e-12) << "exact stick";
  EXPECT_NEAR(std::abs(g.shear[0]), 20.0, 1e-9); // S12 carries all of Fx
  EXPECT_NEAR(g.slip[0], 0.0, 1e-12);
}

TEST(VerificationGapFriction, M3StickWithElasticSlip) {
  // penalty stick: k_s = mu N / gamma, gamma = ELASTIC SLIP = 1e-4 → k_s = 3e5;
  // u_x = 20 / (100 + 3e5), friction = k_s u_x
  const JobResult r = run_deck(m3_deck("*FRICTION, ELASTIC SLIP=1e-4\n0.3", 20.0));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  const double ux = 20.0 / (100.0 + 3e5);
  EXPECT_NEAR(U(r, f, 10)[0], ux, 1e-12);
  EXPECT_EQ(gap(r, f, 101).status, ContactStatus::Stick);
  EXPECT_NEAR(gap(r, f, 101).shear[0], 3e5 * ux, 1e-8);
}

TEST(VerificationGapFriction, M3Slip) {
  // Fx = 40 > mu N = 30: slip; friction 30, the spring takes 10: u_x = 0.1 = E12.
  for (const std::string fr : {"*FRICTION, LAGRANGE\n0.3", "*FRICTION\n0.3"}) {
    SCOPED_TRACE(fr);
    const JobResult r = run_deck(m3_deck(fr, 40.0));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    const Frame& f = last_frame(r);
    const GapRecord& g = gap(r, f, 101);
    EXPECT_EQ(g.status, ContactStatus::Slip);
    EXPECT_NEAR(U(r, f, 10)[0], 0.1, 1e-10);
    EXPECT_NEAR(g.slip[0], 0.1, 1e-10);
    EXPECT_NEAR(std::abs(g.shear[0]), 30.0, 1e-9);
    EXPECT_NEAR(std::abs(g.friction_force[0]), 30.0, 1e-9);
  }
}

namespace {
// Stick-slip-stick cycle: node 10 pressed with N = 100 (no tangential spring) and driven
// tangentially by a prescribed displacement 0 → +A → -A → +A. Friction mu = 0.3, elastic slip
// gamma: the friction force follows the parallelogram with slopes k_s = mu N / gamma and plateaus
// ±mu N; the dissipated energy is mu N (A - gamma) + 2 mu N (2A - 2 gamma) = mu N (5A - 5 gamma).
std::string cycle_deck(const std::string& friction, double A) {
  std::string d = fmt::format(R"(*NODE
10, 0., 0., 0.
12, 0., -1., 0.
*ELEMENT, TYPE=SPRING1, ELSET=SY
2, 10
*SPRING, ELSET=SY
2
1.
*ELEMENT, TYPE=GAPUNI, ELSET=G1
101, 10, 12
*GAP, ELSET=G1
0., 0., -1., 0., 1.
{}
*BOUNDARY
12, 1, 3
10, 3, 3
10, 1, 1
*STEP
*STATIC
*CLOAD
10, 2, -100.
*END STEP
)",
                              friction);
  for (double target : {A, -A, A})
    d += fmt::format("*STEP\n*STATIC, DIRECT\n0.05, 1.\n*BOUNDARY\n10, 1, 1, {}\n*EL PRINT\nS, E\n"
                     "*NODE PRINT\nU, RF\n*END STEP\n",
                     target);
  return d;
}
} // namespace

TEST(VerificationGapFriction, StickSlipStickHysteresisAndDissipation) {
  const double A = 0.01, gamma = 0.001, muN = 30.0, ks = muN / gamma;
  for (bool lagrange : {false, true}) {
    SCOPED_TRACE(lagrange ? "LAGRANGE" : "elastic slip");
    const std::string fr = lagrange ? "*FRICTION, LAGRANGE\n0.3"
                                    : fmt::format("*FRICTION, ELASTIC SLIP={}\n0.3", gamma);
    const JobResult r = run_deck(cycle_deck(fr, A));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    const double g = lagrange ? 0.0 : gamma;
    const double k = lagrange ? std::numeric_limits<double>::infinity() : ks;
    // the loop: walk the prescribed path and compare the friction force at every frame
    double u_prev = 0.0, tau = 0.0;
    int checked = 0;
    for (const Frame& f : r.frames) {
      if (f.step < 2) continue;
      const double u = U(r, f, 10)[0];
      // closed form of the elastic-perfectly-plastic friction force along the path
      tau = std::clamp(tau + (std::isinf(k) ? (u - u_prev) * 1e300 : k * (u - u_prev)), -muN, muN);
      u_prev = u;
      EXPECT_NEAR(gap(r, f, 101).friction_force[0], tau, 1e-6) << "step " << f.step << " u " << u;
      ++checked;
    }
    EXPECT_GE(checked, 60);
    const double dissipated = gap(r, last_frame(r), 101).dissipation;
    EXPECT_NEAR(dissipated, muN * (5 * A - 5 * g), 1e-9 * muN * A);
  }
}

TEST(VerificationGapFriction, ChangeFrictionLetsAStickingGapSlip) {
  // Fx = 20 sticks with mu = 0.3 (limit 30); *CHANGE FRICTION to mu = 0.1 in step 3 lets it slip:
  // friction 10, spring 100 u = 10 → u = 0.1.
  const JobResult r =
      run_deck(m3_deck("*FRICTION, LAGRANGE\n0.3", 20.0,
                       "*STEP\n*STATIC\n*CHANGE FRICTION, ELSET=G1\n*FRICTION\n0.1\n"
                       "*EL PRINT\nS, E\n*END STEP\n"));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  EXPECT_EQ(gap(r, last_frame(r, 2), 101).status, ContactStatus::Stick);
  const Frame& f = last_frame(r, 3);
  EXPECT_EQ(gap(r, f, 101).status, ContactStatus::Slip);
  EXPECT_NEAR(U(r, f, 10)[0], 0.1, 1e-9);
}

TEST(VerificationGapFriction, CylinderAxialAndCircumferentialFriction) {
  // Pipe (node 1) pressed against its sleeve (node 2, radial clearance 0.02) by Fy = 1e4 through
  // springs k = 1e5 on y and z: contact force N = 1e4 - 1e5 * 0.02 = 8e3. Then an axial force
  // Fx = 2e3 (< mu N = 2.4e3: sticks) and Fx = 3e3 (slips: axial spring 1e4 takes 600 → u_x =
  // 0.06).
  auto deck = [](double fx) {
    return fmt::format(R"(*NODE
1, 0., 0., 0.
2, 0., 0., 0.
*ELEMENT, TYPE=SPRING1, ELSET=SX
11, 1
*ELEMENT, TYPE=SPRING1, ELSET=SY
12, 1
*ELEMENT, TYPE=SPRING1, ELSET=SZ
13, 1
*SPRING, ELSET=SX
1
1.E4
*SPRING, ELSET=SY
2
1.E5
*SPRING, ELSET=SZ
3
1.E5
*ELEMENT, TYPE=GAPCYL, ELSET=G
101, 1, 2
*GAP, ELSET=G
0.02, 1., 0., 0.
*FRICTION, LAGRANGE
0.3
*BOUNDARY
2, 1, 3
*STEP
*STATIC
*CLOAD
1, 2, 1.E4
*END STEP
*STEP
*STATIC
0.25, 1.
*CLOAD
1, 1, {}
*EL PRINT
S, E
*END STEP
)",
                       fx);
  };
  {
    const JobResult r = run_deck(deck(2e3));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    const Frame& f = last_frame(r);
    EXPECT_EQ(gap(r, f, 101).status, ContactStatus::Stick);
    EXPECT_NEAR(U(r, f, 1)[0], 0.0, 1e-12);
    EXPECT_NEAR(gap(r, f, 101).normal_force, 8e3, 1e-6);
    // t1 is the axis (projection of global X): the axial friction is S12
    EXPECT_NEAR(std::abs(gap(r, f, 101).friction_force[0]), 2e3, 1e-6);
  }
  {
    const JobResult r = run_deck(deck(3e3));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    const Frame& f = last_frame(r);
    EXPECT_EQ(gap(r, f, 101).status, ContactStatus::Slip);
    EXPECT_NEAR(U(r, f, 1)[0], (3e3 - 2.4e3) / 1e4, 1e-9);
    EXPECT_NEAR(U(r, f, 1)[1], 0.02, 1e-10) << "stays on the sleeve";
  }
}

TEST(VerificationGapFriction, SphereFriction) {
  // Ball (node 1) pressed into its socket (radius 0.2) along +y by 1e4 through springs k = 1e4:
  // N = 1e4 - 1e4 * 0.2 = 8e3; a tangential force Fx = 3e3 > mu N = 2.4e3 makes it slide around
  // the socket until the tangential spring and friction balance. With elastic slip gamma the
  // sticking case Fx = 1e3 (< 2.4e3) keeps u_x at the elastic value Fx/(k + mu N / gamma).
  const std::string base = R"(*NODE
1, 0., 0., 0.
2, 0., 0., 0.
*ELEMENT, TYPE=SPRING1, ELSET=SX
11, 1
*ELEMENT, TYPE=SPRING1, ELSET=SY
12, 1
*ELEMENT, TYPE=SPRING1, ELSET=SZ
13, 1
*SPRING, ELSET=SX
1
1.E4
*SPRING, ELSET=SY
2
1.E4
*SPRING, ELSET=SZ
3
1.E4
*ELEMENT, TYPE=GAPSPHER, ELSET=G
101, 1, 2
*GAP, ELSET=G
0.2
*FRICTION, ELASTIC SLIP=1e-5
0.3
*BOUNDARY
2, 1, 3
*STEP, NLGEOM
*STATIC
*CLOAD
1, 2, 1.E4
*END STEP
*STEP, NLGEOM
*STATIC
0.25, 1.
*CLOAD
1, 1, 1.E3
*END STEP
)";
  const JobResult r = run_deck(base);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  EXPECT_EQ(gap(r, f, 101).status, ContactStatus::Stick);
  const double ks = 0.3 * 8e3 / 1e-5;
  EXPECT_NEAR(U(r, f, 1)[0], 1e3 / (1e4 + ks), 1e-8);
}

namespace {
// A node pushed into a gap by a prescribed overclosure g (node 12 fixed, d = 0): the gap force is
// the law's F(g) = A p(g), read from the reaction at the fixed node.
std::string softened_deck(const std::string& behavior, double area) {
  std::string d = fmt::format(R"(*NODE
10, 0., 0., 0.
12, 0., -1., 0.
*ELEMENT, TYPE=GAPUNI, ELSET=G1
101, 10, 12
*GAP, ELSET=G1
0., 0., -1., 0., {}
{}
*BOUNDARY
12, 1, 3
10, 1, 1
10, 3, 3
)",
                              area, behavior);
  for (double g : {-0.005, 0.0005, 0.001, 0.002, 0.004})
    d += fmt::format("*STEP\n*STATIC\n*BOUNDARY\n10, 2, 2, {}\n*EL PRINT\nS, E\n*END STEP\n", -g);
  return d;
}
} // namespace

TEST(VerificationGapBehavior, SoftenedLawsAtSeveralOverclosures) {
  const double A = 2.0;
  const std::vector<double> gs = {-0.005, 0.0005, 0.001, 0.002, 0.004};
  struct Law {
    std::string text;
    std::function<double(double)> p;
  };
  const double e = std::exp(1.0);
  const std::vector<Law> laws = {
      {"*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1.E4",
       [](double g) { return g > 0 ? 1e4 * g : 0.0; }},
      {"*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL\n0.01, 20.",
       [e](double g) {
         if (g <= -0.01) return 0.0;
         const double x = g / 0.01 + 1;
         return 20.0 / (e - 1) * x * (std::exp(x) - 1);
       }},
      {"*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TABULAR\n0., 0.\n5., 0.001\n25., 0.002",
       [](double g) { return g <= 0       ? 0.0
                             : g <= 0.001 ? 5e3 * g
                                          : 5.0 + 2e4 * (g - 0.001); }},
  };
  for (const Law& law : laws) {
    SCOPED_TRACE(law.text);
    const JobResult r = run_deck(softened_deck(law.text, A));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    for (std::size_t k = 0; k < gs.size(); ++k) {
      const Frame& f = last_frame(r, static_cast<int>(k + 1));
      EXPECT_NEAR(gap(r, f, 101).normal_force, A * law.p(gs[k]), 1e-9 * (1 + A * law.p(gs[k])))
          << "g = " << gs[k];
      EXPECT_NEAR(gap(r, f, 101).pressure, law.p(gs[k]), 1e-9 * (1 + law.p(gs[k])));
      EXPECT_NEAR(RF(r, f, 12)[1], A * law.p(gs[k]), 1e-8 * (1 + A * law.p(gs[k])));
    }
  }
}

TEST(VerificationGapBehavior, NoSeparationHoldsTension) {
  // d = 0, closed from the start; pulling node 10 away with 25 leaves it in place (the gap carries
  // 25 in tension), and a push of 40 is carried in compression.
  auto deck = [](double fy) {
    return fmt::format(R"(*NODE
10, 0., 0., 0.
12, 0., -1., 0.
*ELEMENT, TYPE=SPRING1, ELSET=SY
2, 10
*SPRING, ELSET=SY
2
100.
*ELEMENT, TYPE=GAPUNI, ELSET=G1
101, 10, 12
*GAP, ELSET=G1
0., 0., -1., 0., 1.
*SURFACE BEHAVIOR, NO SEPARATION
*BOUNDARY
12, 1, 3
10, 1, 1
10, 3, 3
*STEP
*STATIC
*CLOAD
10, 2, {}
*EL PRINT
S, E
*END STEP
)",
                       fy);
  };
  for (double fy : {25.0, -40.0}) {
    const JobResult r = run_deck(deck(fy));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    const Frame& f = last_frame(r);
    EXPECT_NEAR(U(r, f, 10)[1], 0.0, 1e-12);
    EXPECT_EQ(gap(r, f, 101).status, ContactStatus::Closed);
    EXPECT_NEAR(gap(r, f, 101).normal_force, -fy, 1e-9); // compression positive
  }
}

namespace {
/// Model data of the propped spring (spec M1): node 10 on a spring k = 100 in y, a GAPUNI with
/// d = 0.5 closing as node 10 moves in -y, AUGMENTED LAGRANGE with the automatic stiffness.
std::string propped_spring_augmented() {
  return R"(*NODE
10, 0., 0., 0.
12, 0., -1., 0.
*ELEMENT, TYPE=SPRING1, ELSET=SY
2, 10
*SPRING, ELSET=SY
2
100.
*ELEMENT, TYPE=GAPUNI, ELSET=G1
101, 10, 12
*GAP, ELSET=G1
0.5, 0., -1., 0., 1.
*SURFACE BEHAVIOR, AUGMENTED LAGRANGE
*BOUNDARY
12, 1, 3
10, 1, 1
10, 3, 3
)";
}
} // namespace

TEST(VerificationGapBehavior, AugmentedLagrangeMatchesDirectWithinItsTolerance) {
  // Propped spring system: node 10 on k = 100 pushed by 100 against a gap with d = 0.5 (M1).
  // DIRECT: u = -0.5, F = 50. AUGMENTED LAGRANGE (automatic stiffness): same within its
  // penetration tolerance 1e-3 x characteristic length (here the node distance 1).
  const std::string deck = propped_spring_augmented() + R"(*STEP
*STATIC
*CLOAD
10, 2, -100.
*EL PRINT
S, E
*END STEP
)";
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  EXPECT_NEAR(U(r, f, 10)[1], -0.5, 1e-3);
  EXPECT_LE(-gap(r, f, 101).clearance, 1e-3); // penetration within the tolerance
  EXPECT_GE(-gap(r, f, 101).clearance, 0.0);
  EXPECT_NEAR(gap(r, f, 101).normal_force, 50.0, 100.0 * 1e-3);
  // penalty (automatic, 10 x the spring): F = 1000 g and 100 u + F = 100 → g = 0.5/11
  const JobResult p =
      run_deck(std::string(deck).replace(deck.find("AUGMENTED LAGRANGE"), 18, "PENALTY"));
  ASSERT_EQ(p.exit_code, 0) << p.error;
  EXPECT_NEAR(-gap(p, last_frame(p), 101).clearance, 0.5 / 11.0, 1e-10);
}

TEST(VerificationGapBehavior, AugmentedLagrangeGapForgetsItsMultiplierWhenItOpens) {
  // The propped spring of the test above in three steps. Step 1 presses the gap with 1000
  // (F = 1000 - 100 x 0.5 = 950; K = 1000 x 100 = 1e5, so the penalty alone would penetrate
  // 9.5e-3 > the tolerance 1e-3 and the multiplier is augmented to ~950). Step 2 pulls the node
  // away (u = +1, open). Step 3 pushes with 49.98: the spring alone takes the node to
  // u = -0.4998, clearance 2e-4, still open. A gap that kept its multiplier would re-engage at
  // the clearance 950 / 1e5 = 9.5e-3 and carry a force; the Uzawa update max(lambda + K g, 0)
  // resets it when the gap opens.
  const std::string deck = propped_spring_augmented() + R"(*STEP
*STATIC
*CLOAD
10, 2, -1000.
*END STEP
*STEP
*STATIC
*CLOAD
10, 2, 100.
*END STEP
*STEP
*STATIC
*CLOAD
10, 2, -49.98
*END STEP
)";
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  EXPECT_NEAR(gap(r, last_frame(r, 1), 101).normal_force, 950.0, 0.1);
  EXPECT_NEAR(U(r, last_frame(r, 2), 10)[1], 1.0, 1e-12);
  const Frame& f = last_frame(r, 3);
  EXPECT_EQ(gap(r, f, 101).status, ContactStatus::Open);
  EXPECT_EQ(gap(r, f, 101).normal_force, 0.0);
  EXPECT_NEAR(U(r, f, 10)[1], -0.4998, 1e-12);
  EXPECT_NEAR(gap(r, f, 101).clearance, 2e-4, 1e-12);
}

TEST(VerificationGapBehavior, AutomaticPenaltyForAGapBetweenNodesWithoutOtherElements) {
  // Chain along x: node 1 -T3D2 (EA/L = 1000)- node 2 -gap A- node 3 -gap B- node 4 (fixed).
  // Node 3 has only gaps, and so have the ground node 4: gap B has no element stiffness of its own
  // and takes the mean diagonal stiffness of the model's displacement DOFs (1000, the truss at
  // nodes 1 and 2); gap A takes the truss at node 2 (1000). Automatic PENALTY: K = 10 x 1000.
  // Both start overclosed by 0.001 (so the chain is held from the start). P = 100 along -x:
  // each gap carries 100 at g = 100 / 1e4 = 0.01; u3 = 0.001 - 0.01 = -0.009,
  // u2 = u3 + 0.001 - 0.01 = -0.018, u1 = u2 - 100 / 1000 = -0.118.
  const std::string deck = R"(*NODE
1, 2., 0., 0.
2, 1., 0., 0.
3, 1., 0., 0.
4, 0., 0., 0.
*NSET, NSET=ALL
1, 2, 3, 4
*ELEMENT, TYPE=T3D2, ELSET=BAR
1, 1, 2
*MATERIAL, NAME=M
*ELASTIC
1000., 0.
*SOLID SECTION, ELSET=BAR, MATERIAL=M
1.
*ELEMENT, TYPE=GAPUNI, ELSET=GA
11, 3, 2
*GAP, ELSET=GA
-0.001, 1., 0., 0.
*SURFACE BEHAVIOR, PENALTY
*ELEMENT, TYPE=GAPUNI, ELSET=GB
12, 4, 3
*GAP, ELSET=GB
-0.001, 1., 0., 0.
*SURFACE BEHAVIOR, PENALTY
*BOUNDARY
ALL, 2, 3
4, 1, 1
*STEP
*STATIC
*CLOAD
1, 1, -100.
*END STEP
)";
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  EXPECT_NEAR(gap(r, f, 11).normal_force, 100.0, 1e-8);
  EXPECT_NEAR(gap(r, f, 12).normal_force, 100.0, 1e-8);
  EXPECT_NEAR(U(r, f, 3)[0], -0.009, 1e-12);
  EXPECT_NEAR(U(r, f, 2)[0], -0.018, 1e-12);
  EXPECT_NEAR(U(r, f, 1)[0], -0.118, 1e-12);
}

TEST(VerificationGapBehavior, DampingHoldsAFloatingNodeAndVanishesAtConvergence) {
  // Node 10 held only by an open gap (d = 0.5) and pushed down by 10: without damping the system
  // is singular (VerificationGap.BodyHeldOnlyByOpenGapsIsReported). With *CONTACT DAMPING (c0 = 1)
  // the damper holds it while it moves; once the gap closes the node stops and the damping force
  // vanishes, so the final state is the undamped answer: u = -0.5, contact force 10.
  const JobResult r = run_deck(R"(*NODE
10, 0., 0., 0.
12, 0., -1., 0.
*ELEMENT, TYPE=GAPUNI, ELSET=G1
101, 10, 12
*GAP, ELSET=G1
0.5, 0., -1., 0., 1.
*CONTACT DAMPING
1., 1.
*BOUNDARY
12, 1, 3
10, 1, 1
10, 3, 3
*STEP
*STATIC
0.1, 1.
*CLOAD
10, 2, -10.
*EL PRINT
S, E
*END STEP
*STEP
*STATIC
0.5, 1.
*EL PRINT
S, E
*END STEP
)");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r, 2);
  EXPECT_NEAR(U(r, f, 10)[1], -0.5, 1e-10);
  EXPECT_NEAR(gap(r, f, 101).normal_force, 10.0, 1e-9);
  EXPECT_NEAR(gap(r, f, 101).damping_force, 0.0, 1e-9);
  // while the node moved, the damper carried the load: F_d = c (-dh/dt) at the first increment
  bool saw_damping = false;
  for (const Frame& fr : r.frames)
    if (fr.step == 1 && gap(r, fr, 101).status == ContactStatus::Open) {
      EXPECT_NEAR(gap(r, fr, 101).damping_force, 10.0 * fr.step_time, 1e-6);
      saw_damping = true;
    }
  EXPECT_TRUE(saw_damping);
  EXPECT_GT(r.steps.at(0).checks.max_damping_force, 0.0);
}
