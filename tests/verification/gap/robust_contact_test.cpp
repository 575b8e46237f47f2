// Robust contact (issue 11), part 2: a block on an incline (ANSYS VM29 data, contact direction
// from inclined node coordinates), augmented Lagrange through close / open / reclose against hard
// contact, *STEP UNSYMM=NO, and the diagnosis of a crushed NLGEOM element.
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>

using namespace gapfem;
using namespace gapfem::test;

namespace {

// VM29: a block on a 20 degree incline under Fy = -100 and a horizontal push Fx, mu = 0.3. The
// incline rises along +x; the gap runs from the block (node 1) to a ground node (2) one unit
// into the incline, so its direction (sin 20, -cos 20) comes from the coordinates. An axial spring
// (k = 1, SPRINGA to node 3 up the slope) holds the block once it slides. Closed form:
//   N = Fx sin 20 + 100 cos 20, driving force down the slope D = 100 sin 20 - Fx cos 20;
//   sticks while D <= mu N (Fx >= 5.76728: VM29's 5.7674 sticks, 5.7672 slides).
const double kTheta = 20.0 * std::acos(-1.0) / 180.0;

std::string incline_deck(double fx, const std::string& friction, bool planar) {
  const double s = std::sin(kTheta), c = std::cos(kTheta);
  std::string d = fmt::format(
      "*NODE\n1, 0., 0., 0.\n2, {:.17g}, {:.17g}, 0.\n3, {:.17g}, {:.17g}, 0.\n", s, -c, c, s);
  d += "*ELEMENT, TYPE=GAPUNI, ELSET=G\n10, 1, 2\n*GAP, ELSET=G\n0., , , , 1.\n" + friction + "\n";
  if (planar) // the spring as a truss up the slope: the model is planar
    d += "*ELEMENT, TYPE=T2D2, ELSET=S\n20, 1, 3\n*SOLID SECTION, ELSET=S, MATERIAL=M\n1.\n"
         "*MATERIAL, NAME=M\n*ELASTIC\n1., 0.3\n*BOUNDARY\n2, 1, 2\n3, 1, 2\n";
  else
    d += "*ELEMENT, TYPE=SPRINGA, ELSET=S\n20, 1, 3\n*SPRING, ELSET=S\n\n1.\n"
         "*BOUNDARY\n2, 1, 3\n3, 1, 3\n1, 3, 3\n";
  d += fmt::format("*STEP\n*STATIC\n*CLOAD\n1, 1, {}\n1, 2, -100.\n*EL PRINT\nS, E\n*END STEP\n",
                   fx);
  return d;
}

} // namespace

TEST(RobustContact, Vm29BlockOnInclineSticksAndSlidesAtTheImpendingForce) {
  const double s = std::sin(kTheta), c = std::cos(kTheta);
  for (bool planar : {false, true})
    for (const auto& [fr, gamma] :
         {std::pair<std::string, double>{"*FRICTION, LAGRANGE\n0.3", 0.0},
          {"*FRICTION, ELASTIC SLIP=1e-6\n0.3", 1e-6},
          {"*FRICTION\n0.3", 0.005}}) // default: SLIP TOLERANCE 0.005 x the spring's length 1
      for (double fx : {5.7674, 5.7672, 10.0, 2.0}) {
        SCOPED_TRACE(fmt::format("{} Fx = {} {}", fr, fx, planar ? "planar" : "3-D"));
        const JobResult r = run_deck(incline_deck(fx, fr, planar));
        ASSERT_EQ(r.exit_code, 0) << r.error;
        for (const IncrementInfo& inc : r.increments) EXPECT_TRUE(inc.converged);
        const GapRecord& g = gap(r, last_frame(r), 10);
        const double N = fx * s + 100 * c, D = 100 * s - fx * c;
        EXPECT_NEAR(g.normal_force, N, 1e-6 * N);
        // with an elastic slip gamma the block creeps by e = D / (k_s + k) in stick, k_s = mu N /
        // gamma, and the spring (k = 1) takes k e: it sticks while D <= mu N + k gamma
        const bool sticks = D <= 0.3 * N + gamma;
        EXPECT_EQ(g.status, sticks ? ContactStatus::Stick : ContactStatus::Slip);
        const double friction = std::hypot(g.friction_force[0], g.friction_force[1]);
        if (sticks)
          EXPECT_NEAR(friction, gamma > 0 ? D * (0.3 * N / gamma) / (0.3 * N / gamma + 1) : D,
                      1e-6 * N);
        else
          EXPECT_NEAR(friction, 0.3 * N, 1e-6 * N);
        // slide distance down the slope: the spring (k = 1) takes D - mu N
        const Vec3& u = U(r, last_frame(r), 1);
        const double along = u[0] * c + u[1] * s;
        if (!sticks) EXPECT_NEAR(along, -(D - 0.3 * N), 1e-6 + 1e-6 * std::abs(along));
      }
  // VM29's targets: N = 95.942, friction 28.783 at the impending force
  const JobResult r = run_deck(incline_deck(5.7674, "*FRICTION, LAGRANGE\n0.3", false));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  EXPECT_NEAR(gap(r, last_frame(r), 10).normal_force, 95.942, 5e-4);
}

namespace {

// Spec M1 with the augmented-Lagrange method: node 10 on a spring k = 100 (y), GAPUNI d = 0.5,
// closure direction (0,-1,0). Fy = -100 closes it (force 50), -40 opens it (u = -0.4), -150
// recloses it (force 100); hard contact has exactly these answers.
std::string m1_deck(const std::string& behaviour) {
  std::string d = R"(*NODE
10, 0., 0., 0.
12, 0., -1., 0.
*ELEMENT, TYPE=SPRING1, ELSET=SY
1, 10
*SPRING, ELSET=SY
2
100.
*ELEMENT, TYPE=GAPUNI, ELSET=G1
101, 10, 12
*GAP, ELSET=G1
0.5, 0., -1., 0., 1.
)" + behaviour + R"(
*BOUNDARY
12, 1, 3
10, 1, 1
10, 3, 3
)";
  for (double f : {-100.0, -40.0, -150.0, -40.0, -100.0})
    d += fmt::format("*STEP\n*STATIC\n*CLOAD\n10, 2, {}\n*EL PRINT\nS, E\n*END STEP\n", f);
  return d;
}

} // namespace

TEST(RobustContact, AugmentedLagrangeFollowsHardContactThroughCloseOpenReclose) {
  const double force[] = {50.0, 0.0, 100.0, 0.0, 50.0};
  const double uy[] = {-0.5, -0.4, -0.5, -0.4, -0.5};
  for (const std::string k : {"", "1000.", "100.", "10.", "1."}) {
    SCOPED_TRACE("penalty stiffness " + (k.empty() ? std::string("automatic") : k));
    const JobResult r = run_deck(m1_deck("*SURFACE BEHAVIOR, AUGMENTED LAGRANGE\n" + k));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    for (const IncrementInfo& inc : r.increments) EXPECT_TRUE(inc.converged);
    // tolerance: 1e-3 of the characteristic length (the gap's node distance, 1)
    for (int s = 1; s <= 5; ++s) {
      const Frame& f = last_frame(r, s);
      const GapRecord& g = gap(r, f, 101);
      EXPECT_EQ(g.status == ContactStatus::Open, force[s - 1] == 0.0) << "step " << s;
      EXPECT_NEAR(U(r, f, 10)[1], uy[s - 1], 1e-3) << "step " << s;
      EXPECT_NEAR(g.normal_force, force[s - 1], 100 * 1e-3) << "step " << s;
      if (force[s - 1] == 0.0) {
        EXPECT_EQ(g.normal_force, 0.0) << "an open gap carries no force (step " << s << ")";
        EXPECT_NEAR(g.clearance, 0.1, 1e-9) << "step " << s;
      }
    }
  }
}

TEST(RobustContact, UnsymmNoSolvesFrictionWithTheSymmetricPartOnly) {
  // spec M3 slip (Fx = 40 > mu N = 30) with the symmetric solver only: the same answer
  const std::string deck = R"(*NODE
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
*FRICTION
0.3
*BOUNDARY
12, 1, 3
10, 3, 3
*STEP, UNSYMM=NO
*STATIC
*CLOAD
10, 2, -100.
10, 1, 40.
*END STEP
)";
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  EXPECT_NEAR(U(r, last_frame(r), 10)[0], 0.1, 1e-3);
  EXPECT_NEAR(std::abs(gap(r, last_frame(r), 101).friction_force[0]), 30.0, 0.2);
}

namespace {
std::string cube_deck(const std::string& load) {
  return R"(*NODE
1, 0., 0., 0.
2, 1., 0., 0.
3, 1., 1., 0.
4, 0., 1., 0.
5, 0., 0., 1.
6, 1., 0., 1.
7, 1., 1., 1.
8, 0., 1., 1.
*ELEMENT, TYPE=C3D8, ELSET=E
1, 1,2,3,4,5,6,7,8
*SOLID SECTION, ELSET=E, MATERIAL=M
*MATERIAL, NAME=M
*ELASTIC
1000., 0.3
*NSET, NSET=BOT
1,2,3,4
*NSET, NSET=TOP
5,6,7,8
*BOUNDARY
BOT, 3, 3
1, 1, 2
2, 2, 2
*STEP, NLGEOM
*STATIC
0.1, 1.
)" + load +
         "*END STEP\n";
}
} // namespace

TEST(RobustContact, CrushedElementIsNamedAndNeverDiagnosedAsARigidBody) {
  // crushed through its own height by a prescribed displacement: the element turns inside out
  const JobResult crushed = run_deck(cube_deck("*BOUNDARY\nTOP, 3, 3, -1.2\n"));
  ASSERT_EQ(crushed.exit_code, kExitNoConvergence);
  EXPECT_NE(crushed.error.find("element 1"), std::string::npos) << crushed.error;
  EXPECT_NE(crushed.error.find("inside out"), std::string::npos) << crushed.error;
  EXPECT_EQ(crushed.error.find("rigid body"), std::string::npos) << crushed.error;
  // pressed beyond its limit load (St. Venant-Kirchhoff softens in compression): the stiffness
  // turns singular in a supported model, which is a limit load, not a missing support
  const JobResult limit = run_deck(cube_deck("*CLOAD\nTOP, 3, -300.\n"));
  ASSERT_EQ(limit.exit_code, kExitNoConvergence);
  EXPECT_NE(limit.error.find("limit load"), std::string::npos) << limit.error;
  EXPECT_EQ(limit.error.find("rigid body"), std::string::npos) << limit.error;
  // a genuinely unsupported model keeps the rigid-body diagnosis
  std::string free_deck = cube_deck("*CLOAD\nTOP, 3, -1.\n");
  free_deck.replace(free_deck.find("BOT, 3, 3"), 9, "BOT, 1, 1");
  const JobResult unsupported = run_deck(free_deck);
  ASSERT_NE(unsupported.exit_code, 0);
  EXPECT_NE(unsupported.error.find("rigid body"), std::string::npos) << unsupported.error;
}
