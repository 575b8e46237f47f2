// Verification decks of spec §6.2 (M1, M4-M7) and the extra cases of the gap-elements issue, each
// against its closed-form answer (derivations next to each expectation).
#include "test_util.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <string>

using namespace gapfem;
using namespace gapfem::test;

namespace {

// M1: node 10 at the origin on a spring k = 100 (DOF 2), ground node 12 one unit below;
// GAPUNI 10-12 with clearance d.
std::string m1_deck(const std::string& gap_line, double fy, bool reversed = false) {
  return std::string(R"(*HEADING
M1 GAPUNI open/closed with a spring
*NODE
10, 0., 0., 0.
12, 0., -1., 0.
*ELEMENT, TYPE=SPRING1, ELSET=SPR
1, 10
*SPRING, ELSET=SPR
2
100.
*ELEMENT, TYPE=GAPUNI, ELSET=G1
)") + (reversed ? "101, 12, 10\n" : "101, 10, 12\n") +
         "*GAP, ELSET=G1\n" + gap_line + R"(
*BOUNDARY
12, 1, 3
10, 1, 1
10, 3, 3
*STEP
*STATIC
*CLOAD
10, 2, )" +
         std::to_string(fy) + R"(
*EL PRINT, ELSET=G1
S, E
*NODE PRINT
U, RF
*END STEP
)";
}

} // namespace

TEST(VerificationGap, M1OpenUnderSmallLoad) {
  const JobResult r = run_deck(m1_deck("0.5, 0., -1., 0., 1.", -40.0));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  // open: the spring alone carries 40 → u = -40/100; h = 0.5 + (0,-1,0).(0 - u1) = 0.5 - 0.4
  EXPECT_NEAR(U(r, f, 10)[1], -0.4, 1e-12);
  EXPECT_EQ(gap(r, f, 101).status, ContactStatus::Open);
  EXPECT_NEAR(gap(r, f, 101).clearance, 0.1, 1e-12);
  EXPECT_EQ(gap(r, f, 101).normal_force, 0.0);
}

TEST(VerificationGap, M1ClosedUnderLargeLoad) {
  const JobResult r = run_deck(m1_deck("0.5, 0., -1., 0., 1.", -100.0));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  // closed: u = -d = -0.5 exactly; spring takes 100*0.5 = 50, the gap the other 50
  EXPECT_NEAR(U(r, f, 10)[1], -0.5, 1e-12);
  const GapRecord& g = gap(r, f, 101);
  EXPECT_EQ(g.status, ContactStatus::Closed);
  EXPECT_NEAR(g.normal_force, 50.0, 1e-9);
  EXPECT_NEAR(g.pressure, 50.0, 1e-9); // S11 = F/A, A = 1
  EXPECT_LE(std::abs(g.clearance), 1e-10 * r.model->model_size());
  // the gap pushes ground node 12 down with 50, so its support pushes up: RF_y(12) = +50
  EXPECT_NEAR(RF(r, f, 12)[1], 50.0, 1e-9);
  const auto& c = r.steps.at(0).checks;
  EXPECT_EQ(c.n_closed, 1);
  EXPECT_LE(c.max_penetration, 1e-10 * r.model->model_size());
  EXPECT_EQ(c.max_tensile_force, 0.0);
  EXPECT_LE(c.equilibrium_error, 1e-9 * c.force_scale);
}

TEST(VerificationGap, M1DirectionPointingAwayNeverCloses) {
  // n = (0,+1,0): h = 0.5 + u1y grows as node 10 moves down, so the gap never closes.
  const JobResult r = run_deck(m1_deck("0.5, 0., 1., 0., 1.", -100.0));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  EXPECT_NEAR(U(r, f, 10)[1], -1.0, 1e-12);
  EXPECT_EQ(gap(r, f, 101).status, ContactStatus::Open);
  EXPECT_NEAR(gap(r, f, 101).clearance, 1.5, 1e-12);
}

TEST(VerificationGap, M1ComputedDirectionAndNodeOrderReversal) {
  // blank direction: n = (X12 - X10)/|.| = (0,-1,0), identical to M1; reversed connectivity
  // reverses n, so the answer is the same.
  for (bool reversed : {false, true}) {
    SCOPED_TRACE(reversed ? "reversed" : "forward");
    const JobResult r = run_deck(m1_deck("0.5, , , , 1.", -100.0, reversed));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    const Frame& f = last_frame(r);
    EXPECT_NEAR(U(r, f, 10)[1], -0.5, 1e-12);
    EXPECT_NEAR(gap(r, f, 101).normal_force, 50.0, 1e-9);
  }
}

TEST(VerificationGap, LinearOpenGapTakesOneIteration) {
  // A gap that stays open leaves a linear problem: one Newton iteration per increment.
  const JobResult r = run_deck(m1_deck("0.5, 0., -1., 0., 1.", -40.0));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  for (const auto& inc : r.increments) EXPECT_EQ(inc.iterations, 1);
}

namespace {
// M4: pipe (node 1) in a sleeve (node 2) of radial clearance 0.0208 about the x-axis.
const char* kM4 = R"(*HEADING
M4 GAPCYL d > 0
*NODE
1, 0., 0., 0.
2, 0., 0., 0.
*ELEMENT, TYPE=SPRING1, ELSET=SY
11, 1
*ELEMENT, TYPE=SPRING1, ELSET=SZ
12, 1
*SPRING, ELSET=SY
2
1.E6
*SPRING, ELSET=SZ
3
1.E6
*ELEMENT, TYPE=GAPCYL, ELSET=G
101, 1, 2
*GAP, ELSET=G
0.0208, 1., 0., 0.
*BOUNDARY
2, 1, 3
1, 1, 1
*STEP
*STATIC
*CLOAD
1, 2, 2.E4
*END STEP
*STEP
*STATIC
0.1, 1.
*CLOAD
1, 3, 3.E4
*END STEP
)";
} // namespace

TEST(VerificationGap, M4CylinderPipeInSleeve) {
  const JobResult r = run_deck(kM4);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  // step 1: open, u_y = 2e4/1e6 = 0.02 < 0.0208, E11 = 0.0008
  const Frame& f1 = last_frame(r, 1);
  EXPECT_NEAR(U(r, f1, 1)[1], 0.02, 1e-12);
  EXPECT_EQ(gap(r, f1, 101).status, ContactStatus::Open);
  EXPECT_NEAR(gap(r, f1, 101).clearance, 0.0008, 1e-12);
  // step 2: closed; the node sits on the circle of radius 0.0208 along F/|F|, |F| = 36055.51;
  // contact force = |F| - k*0.0208 = 15255.51
  const Frame& f2 = last_frame(r, 2);
  const double Fm = std::hypot(2e4, 3e4);
  EXPECT_NEAR(U(r, f2, 1)[1], 0.0208 * 2e4 / Fm, 1e-10);
  EXPECT_NEAR(U(r, f2, 1)[2], 0.0208 * 3e4 / Fm, 1e-10);
  const GapRecord& g = gap(r, f2, 101);
  EXPECT_EQ(g.status, ContactStatus::Closed);
  EXPECT_NEAR(g.normal_force, Fm - 1e6 * 0.0208, 1e-6);
  EXPECT_NEAR(g.direction[1], 2e4 / Fm, 1e-9); // n = (0, 0.5547, 0.8321)
  EXPECT_NEAR(g.direction[2], 3e4 / Fm, 1e-9);
}

TEST(VerificationGap, M5ExternalCylinders) {
  // Node 1 (at y = 2) is pulled towards node 2's axis by a spring to a driver moved 5 down; the
  // axes may not come closer than |d| = 1: node 1 stops at y = 1, the spring stretches by 4.
  const JobResult r = run_deck(R"(*NODE
1, 0., 2., 0.
2, 0., 0., 0.
3, 0., 2., 0.
*ELEMENT, TYPE=SPRING2, ELSET=S
11, 1, 3
*SPRING, ELSET=S
2, 2
100.
*ELEMENT, TYPE=GAPCYL, ELSET=G
101, 1, 2
*GAP, ELSET=G
-1., 1., 0., 0.
*BOUNDARY
2, 1, 3
1, 1, 1
1, 3, 3
*STEP
*STATIC
0.1, 1.
*BOUNDARY
3, 2, 2, -5.
*EL PRINT
S, E
*NODE PRINT
U
*END STEP
)");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  EXPECT_NEAR(U(r, f, 1)[1], -1.0, 1e-10);
  const GapRecord& g = gap(r, f, 101);
  EXPECT_NEAR(g.normal_force, 400.0, 1e-7);
  EXPECT_NEAR(g.clearance, 0.0, 1e-10);
  // open while the driver has moved less than 1: the first increment (0.1 of the step, 0.5 down)
  const Frame& first = r.frames.front();
  EXPECT_EQ(gap(r, first, 101).status, ContactStatus::Open);
}

namespace {
std::string m6_deck(double fy, double fz, bool nlgeom = true) {
  return std::string(R"(*NODE
1, 0., 0., 0.
2, 0., 0., 0.
*ELEMENT, TYPE=SPRING1, ELSET=S1
11, 1
*ELEMENT, TYPE=SPRING1, ELSET=S2
12, 1
*ELEMENT, TYPE=SPRING1, ELSET=S3
13, 1
*SPRING, ELSET=S1
1
1.E5
*SPRING, ELSET=S2
2
1.E5
*SPRING, ELSET=S3
3
1.E5
*ELEMENT, TYPE=GAPSPHER, ELSET=G
101, 1, 2
*GAP, ELSET=G
0.208
*BOUNDARY
2, 1, 3
*STEP)") +
         (nlgeom ? ", NLGEOM" : "") + R"(
*STATIC
0.25, 1.
*CLOAD
1, 2, )" +
         std::to_string(fy) + "\n1, 3, " + std::to_string(fz) +
         "\n*NODE PRINT\nU\n*EL PRINT\nS, E\n*END STEP\n";
}
} // namespace

TEST(VerificationGap, M6SphereOpenAndClosed) {
  {
    const JobResult r = run_deck(m6_deck(2e4, 0));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    EXPECT_EQ(gap(r, last_frame(r), 101).status, ContactStatus::Open); // 0.2 < 0.208
  }
  for (double scale : {1.0, 2.0}) {
    const JobResult r = run_deck(m6_deck(2e4 * scale, 3e4 * scale));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    const Frame& f = last_frame(r);
    const double Fm = scale * std::hypot(2e4, 3e4);
    // the node rests on the sphere of radius 0.208 along the load; force = |F| - 1e5 * 0.208
    EXPECT_NEAR(U(r, f, 1)[1], 0.208 * 2 / std::sqrt(13.0), 1e-10);
    EXPECT_NEAR(U(r, f, 1)[2], 0.208 * 3 / std::sqrt(13.0), 1e-10);
    EXPECT_NEAR(gap(r, f, 101).normal_force, Fm - 20800.0, 1e-6); // 15255.5 and 51311.0
  }
}

TEST(VerificationGap, M6RotatingLoadTracksTheSphereWithQuadraticConvergence) {
  // A load of magnitude 4e4 turning from +y to +z: the node must stay on the sphere |u| = 0.208,
  // along the current load direction, in every increment (frictionless contact).
  std::string deck = m6_deck(4e4, 4e4);
  const std::string amp = R"(*AMPLITUDE, NAME=COS
0., 1., 0.25, 0.9238795, 0.5, 0.7071068, 0.75, 0.3826834
1., 0.
*AMPLITUDE, NAME=SIN
0., 0., 0.25, 0.3826834, 0.5, 0.7071068, 0.75, 0.9238795
1., 1.
)";
  deck.insert(deck.find("*BOUNDARY"), amp);
  deck.replace(deck.find("*CLOAD"), 6, "*CLOAD, AMPLITUDE=COS");
  const auto pos = deck.find("1, 3, ");
  deck.insert(pos, "*CLOAD, AMPLITUDE=SIN\n");
  deck.replace(deck.find("0.25, 1."), 8, "0.25, 1., 1e-5, 0.25");
  JobOptions o;
  o.deck = write_deck(deck);
  o.write_files = false;
  o.quiet = true;
  const JobResult r = run_job(o);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  ASSERT_GE(r.frames.size(), 4u);
  for (const Frame& f : r.frames) {
    const Vec3& u = U(r, f, 1);
    const double t = f.step_time;
    EXPECT_NEAR(std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]), 0.208, 1e-10) << "t = " << t;
    EXPECT_EQ(gap(r, f, 101).status, ContactStatus::Closed);
  }
  // Quadratic convergence once the contact set is settled: every increment after the first
  // converges and its error ratio falls at least quadratically, r_{k+1} <= 10 r_k^2, until
  // round-off.
  bool saw_multi_iteration = false;
  for (const auto& inc : r.increments) {
    const auto& h = inc.residual_history;
    for (std::size_t k = 1; k < h.size(); ++k) {
      if (h[k] < 1e-12) break;
      saw_multi_iteration = true;
      EXPECT_LE(h[k], 10.0 * h[k - 1] * h[k - 1])
          << "increment " << inc.increment << " iteration " << k;
    }
  }
  EXPECT_TRUE(saw_multi_iteration);
}

namespace {
std::string m7_deck(const std::string& interference, const std::string& extra = "") {
  return std::string(R"(*NODE
10, 0., 0., 0.
12, 0., -1., 0.
*ELEMENT, TYPE=SPRING1, ELSET=SPR
1, 10
*SPRING, ELSET=SPR
2
100.
*ELEMENT, TYPE=GAPUNI, ELSET=G1
101, 10, 12
*GAP, ELSET=G1
-0.1, 0., -1., 0., 1.
*BOUNDARY
12, 1, 3
10, 1, 1
10, 3, 3
)") + extra +
         R"(*STEP
*STATIC
0.25, 1., 1e-5, 0.25
)" + interference +
         "*NODE PRINT\nU\n*EL PRINT\nS, E\n*END STEP\n";
}
} // namespace

TEST(VerificationGap, M7InterferenceResolvedInFirstIncrement) {
  const JobResult r = run_deck(m7_deck(""));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  // h = -0.1 + u_y = 0 → u_y = 0.1 from the first increment on; spring force 10
  for (const Frame& f : r.frames) {
    EXPECT_NEAR(U(r, f, 10)[1], 0.1, 1e-12);
    EXPECT_NEAR(gap(r, f, 101).normal_force, 10.0, 1e-9);
  }
}

TEST(VerificationGap, M7InterferenceRampedAway) {
  for (const std::string opt : {"*CONTACT INTERFERENCE, TYPE=ELEMENT\nG1, 0.1\n",
                                "*CONTACT INTERFERENCE, TYPE=ELEMENT, SHRINK\nG1\n"}) {
    SCOPED_TRACE(opt);
    const JobResult r = run_deck(m7_deck(opt));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    ASSERT_EQ(r.frames.size(), 4u);
    // allowance v(t) = 0.1 (1 - t): h + v = 0 → u_y = 0.1 t, force 10 t
    for (const Frame& f : r.frames) {
      EXPECT_NEAR(U(r, f, 10)[1], 0.1 * f.step_time, 1e-12) << "t = " << f.step_time;
      EXPECT_NEAR(gap(r, f, 101).normal_force, 10.0 * f.step_time, 1e-9);
    }
  }
}

TEST(VerificationGap, M7InterferenceWithAmplitude) {
  // a(t) = 1 - t^2 sampled at the increments: u_y = 0.1 (1 - a(t)) = 0.1 t^2
  const JobResult r = run_deck(
      m7_deck("*CONTACT INTERFERENCE, TYPE=ELEMENT, AMPLITUDE=A\nG1, 0.1\n",
              "*AMPLITUDE, NAME=A\n0., 1., 0.25, 0.9375, 0.5, 0.75, 0.75, 0.4375\n1., 0.\n"));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  for (const Frame& f : r.frames)
    EXPECT_NEAR(U(r, f, 10)[1], 0.1 * f.step_time * f.step_time, 1e-12) << "t = " << f.step_time;
}

TEST(VerificationGap, BodyHeldOnlyByOpenGapsIsReported) {
  // node 10 has no spring: only the open gap could hold it → singular, with the remedy named.
  const JobResult r = run_deck(R"(*NODE
10, 0., 0., 0.
12, 0., -1., 0.
*ELEMENT, TYPE=GAPUNI, ELSET=G1
101, 10, 12
*GAP, ELSET=G1
0.5, 0., -1., 0., 1.
*BOUNDARY
12, 1, 3
10, 1, 1
10, 3, 3
*STEP
*STATIC
*CLOAD
10, 2, -10.
*END STEP
)");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.error.find("held only by open gap elements 101"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("node 10 DOF 2"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("*CONTACT DAMPING"), std::string::npos) << r.error;
}
