// Hard stops on moving supports (docs/theory/dynamics.md §5, "Hard gaps: impacts"): the impact
// makes the velocities compatible with the gap's row including the support's own velocity, and
// the impact's energy is reported (ALLKL), not hidden.
//
// 1. A point mass m at rest (node 2, free along x only); a wall (node 3) at clearance d moving at
//    the constant velocity -V (*BOUNDARY, TYPE=VELOCITY) toward it along a GAPUNI. The wall reaches
//    the mass at t_c = d / V. Abaqus/Standard's fully plastic impact: "the two impacting surfaces
//    instantaneously acquire the same velocity in the direction of the impact" (Theory Guide,
//    "Intermittent contact/impact",
//    https://abaqus-docs.mit.edu/2017/English/SIMACAETHERefMap/simathe-c-intercontact.htm). So from
//    the increment in which the gap closes the mass moves with the wall, v = -V, a = 0, and the
//    wall pushes it with no force (nothing resists): V and A of the mass to 1e-10 (rounding only),
//    its kinetic energy 1/2 m V^2. The energies of a plastic impact with a wall moving at V: the
//    wall's impulse m V works m V^2 (ALLWK), half becomes kinetic energy, half is lost (ALLKL).
//    With the trapezoidal rule (ALPHA=0) the accounting is exact: those values to 1e-12, ALLIE = 0.
//    With HHT's weights the increment in which the gap closes does not split exactly (the impulse
//    falls inside it); its imbalance is the impact's (ALLKL), so ETOTAL stays constant to rounding.
//    Without the wall's velocity in the projection the mass was stopped dead (v = 0) and the wall
//    then drove it on; the next increment added 0.64 m V^2 of spurious work (the start forces of
//    the energy trapezoid were the impulsive ones).
// 2. A mass on a table shaken vertically (base acceleration A sin(w t), A > g, so the mass flies
//    off and lands again: a hard GAPUNI, gravity as a load): the landings are plastic impacts on a
//    moving support. Checked for every application and the trapezoidal rule: the mass never sinks
//    into the table (1e-9 of the stroke), lands with the table's velocity at every landing
//    (1e-9), ALLKL grows at each landing, and ETOTAL stays constant: to 1e-6 of the largest
//    energy with the trapezoidal rule (the books are exact to the Newton tolerance: measured
//    6.9e-8); with HHT it never grows (1e-8) and falls by less than 1e-4 (measured -1.5e-5 with
//    TRANSIENT FIDELITY, -2.3e-5 with MODERATE DISSIPATION). A lift-off is released at its
//    increment's start (verification_release_test.cpp) and its increment's HHT imbalance is the
//    contacts' (ALLKL), as an impact's; when the contact's force fell to zero inside the increment
//    instead, HHT gained 2.5e-6 (TF) and 8.3e-6 (MD). Before, the
//    projection stopped the mass dead instead of giving it the table's velocity, ALLIE went to -5.7
//    and ETOTAL lost 31 %.
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>

namespace gapfem {
namespace {

constexpr double kM = 2.0, kV = 0.5, kD = 0.01;

std::string moving_stop_deck(const char* application) {
  return fmt::format(R"(*HEADING
A wall at constant speed hits a mass at rest
*NODE
2, 0., 0., 0.
3, {}, 0., 0.
*ELEMENT, TYPE=MASS, ELSET=PM
5, 2
*MASS, ELSET=PM
{}
*ELEMENT, TYPE=GAPUNI, ELSET=G
10, 2, 3
*GAP, ELSET=G
{}, 1., 0., 0.
*AMPLITUDE, NAME=CONST
0., 1., 10., 1.
*BOUNDARY
2, 2, 3
3, 2, 3
*STEP, INC=1000
*DYNAMIC, DIRECT, APPLICATION={}
0.003, 0.06
*BOUNDARY, TYPE=VELOCITY, AMPLITUDE=CONST
3, 1, 1, {}
*NODE PRINT, FREQUENCY=1
V, A
*END STEP
)",
                     kD, kM, kD, application, -kV);
}

void expect_plastic_impact_with_the_wall(const char* application, bool exact_split) {
  const JobResult r = test::run_deck(moving_stop_deck(application));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const LocalIndex mass = r.model->mesh.find_node(2), wall = r.model->mesh.find_node(3);
  const double scale = kM * kV * kV, t_c = kD / kV;
  int after = 0;
  for (const Frame& f : r.frames) {
    if (f.increment == 0) continue;
    EXPECT_NEAR(f.nodes.V.at(wall)[0], -kV, 1e-12);
    ASSERT_TRUE(f.energies.has_value());
    const Energies& e = *f.energies;
    EXPECT_NEAR(e.etotal(), 0.0, 1e-12 * scale) << "t = " << f.step_time;
    if (f.step_time < t_c - 1e-12) { // before the impact: at rest
      EXPECT_EQ(f.nodes.V.at(mass)[0], 0.0);
      continue;
    }
    EXPECT_NEAR(f.nodes.V.at(mass)[0], -kV, 1e-10 * kV) << "t = " << f.step_time;
    EXPECT_NEAR(f.nodes.A.at(mass)[0], 0.0, 1e-8 * kV / 0.003) << "t = " << f.step_time;
    EXPECT_NEAR(e.allke, 0.5 * scale, 1e-10 * scale);
    EXPECT_NEAR(e.allie, 0.0, 1e-12 * scale);
    if (exact_split) {
      EXPECT_NEAR(e.allwk, scale, 1e-12 * scale);
      EXPECT_NEAR(e.allkl, 0.5 * scale, 1e-12 * scale);
    } else { // the wall's work over the impact increment is a trapezoid of the impulse
      EXPECT_NEAR(e.allwk, scale, 0.05 * scale);
      EXPECT_NEAR(e.allkl, 0.5 * scale, 0.05 * scale);
    }
    ++after;
  }
  EXPECT_EQ(after, 14); // t = 0.021 ... 0.06
  EXPECT_LT(t_c, 0.021);
}

TEST(VerificationMovingStop, TransientFidelityMassTakesTheWallsVelocity) {
  expect_plastic_impact_with_the_wall("TRANSIENT FIDELITY", false);
}

TEST(VerificationMovingStop, ModerateDissipationMassTakesTheWallsVelocity) {
  expect_plastic_impact_with_the_wall("MODERATE DISSIPATION", false);
}

TEST(VerificationMovingStop, TrapezoidalRuleSplitsThePlasticImpactExactly) {
  expect_plastic_impact_with_the_wall("TRANSIENT FIDELITY, ALPHA=0.", true);
}

constexpr double kTableA = 20.0, kOmega = 31.4159, kG = 9.81, kMass = 2.0;

std::string shaken_table_deck(const char* integrator) {
  return fmt::format(R"(*HEADING
A mass on a table shaken vertically: it flies off and lands again
*NODE
1, 0., 0., 0.
2, 0., 0., 0.
*ELEMENT, TYPE=MASS, ELSET=PM
5, 2
*MASS, ELSET=PM
{}
*ELEMENT, TYPE=GAPUNI, ELSET=G
10, 2, 1
*GAP, ELSET=G
0., 0., 0., -1., 1.
*AMPLITUDE, NAME=SHAKE, DEFINITION=PERIODIC
1, {}, 0., 0.
0., 1.
*AMPLITUDE, NAME=ON
0., 1., 10., 1.
*BOUNDARY
2, 1, 2
1, 1, 2
*STEP, INC=10000
*DYNAMIC, DIRECT, {}
0.001, 2.
*BOUNDARY, TYPE=ACCELERATION, AMPLITUDE=SHAKE
1, 3, 3, {}
*CLOAD, AMPLITUDE=ON
2, 3, {}
*NODE PRINT, FREQUENCY=1
U, V
*END STEP
)",
                     kMass, kOmega, integrator, kTableA, -kMass * kG);
}

/// ETOTAL at the end within [-loss_tol, gain_tol] of the largest energy.
void expect_landings_on_the_table(const char* integrator, double gain_tol, double loss_tol) {
  const JobResult r = test::run_deck(shaken_table_deck(integrator));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  for (const std::string& w : r.run.warnings)
    EXPECT_EQ(w.find("energy balance"), std::string::npos) << w;
  const LocalIndex mass = r.model->mesh.find_node(2), table = r.model->mesh.find_node(1);
  const double stroke = kTableA / (kOmega * kOmega);
  double scale = 0.0, kl = 0.0;
  int landings = 0;
  bool touching = true;
  for (const Frame& f : r.frames) {
    if (f.increment == 0 || !f.energies) continue;
    const Energies& e = *f.energies;
    scale = std::max(scale, e.scale());
    const double gap = f.nodes.U.at(mass)[2] - f.nodes.U.at(table)[2];
    EXPECT_GE(gap, -1e-9 * stroke) << "t = " << f.step_time;
    const bool on = gap <= 1e-12 * stroke;
    if (on && !touching) { // a landing: the impact gave the mass the table's velocity
      ++landings;
      EXPECT_NEAR(f.nodes.V.at(mass)[2], f.nodes.V.at(table)[2], 1e-9) << "t = " << f.step_time;
      EXPECT_GT(e.allkl, kl) << "t = " << f.step_time;
    }
    touching = on;
    kl = e.allkl;
  }
  EXPECT_GE(landings, 3);
  ASSERT_GT(scale, 0.0);
  ASSERT_FALSE(r.frames.empty());
  ASSERT_TRUE(r.frames.back().energies.has_value());
  EXPECT_LE(r.frames.back().energies->etotal(), gain_tol * scale);
  EXPECT_GE(r.frames.back().energies->etotal(), -loss_tol * scale);
}

TEST(VerificationMovingStop, ShakenTableLandingsTransientFidelity) {
  expect_landings_on_the_table("APPLICATION=TRANSIENT FIDELITY", 1e-8, 1e-4);
}

TEST(VerificationMovingStop, ShakenTableLandingsModerateDissipation) {
  expect_landings_on_the_table("APPLICATION=MODERATE DISSIPATION", 1e-8, 1e-4);
}

TEST(VerificationMovingStop, ShakenTableLandingsTrapezoidalRule) {
  expect_landings_on_the_table("ALPHA=0.", 1e-6, 1e-6);
}

// 3. A mass thrown at a fixed stop against a constant pull F away from it (v0 = 1, F/m = 2 m/s^2,
//    trapezoidal rule): the plastic impact stops it on the stop, and the pull then takes it away
//    at once. The accelerations after the impact treat the contact as unilateral: the gap whose
//    force would pull is dropped (docs/theory/dynamics.md §5), so the state the next increment
//    starts from is u = d, v = 0, a = -F/m, and the free flight that follows is exact for the
//    trapezoidal rule under a constant force: u(t) = d - (F/m) (t - t_n)^2 / 2 from the impact
//    increment's end t_n, to 1e-12. Held bilaterally, the contact kept a = 0 at t_n and the first
//    increment lagged by (F/m) dt^2 / 4.
TEST(VerificationMovingStop, APulledMassLeavesTheStopAtOnce) {
  constexpr double kF = 4.0, kDt = 0.003;
  const JobResult r = test::run_deck(fmt::format(R"(*HEADING
A mass thrown at a stop against a pull
*NODE
2, 0., 0., 0.
3, 0.5, 0., 0.
*ELEMENT, TYPE=MASS, ELSET=PM
5, 2
*MASS, ELSET=PM
{}
*ELEMENT, TYPE=GAPUNI, ELSET=G
10, 2, 3
*GAP, ELSET=G
{}, 1., 0., 0., 1.
*AMPLITUDE, NAME=CONST
0., 1., 10., 1.
*BOUNDARY
2, 2, 3
3, 1, 3
*INITIAL CONDITIONS, TYPE=VELOCITY
2, 1, 1.
*STEP, INC=1000
*DYNAMIC, DIRECT, ALPHA=0.
{}, 0.06
*CLOAD, AMPLITUDE=CONST
2, 1, {}
*NODE PRINT, FREQUENCY=1
U, V, A
*END STEP
)",
                                                 kM, kD, kDt, -kF));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const LocalIndex mass = r.model->mesh.find_node(2);
  double t_n = -1.0;
  int after = 0;
  for (const Frame& f : r.frames) {
    if (f.increment == 0) continue;
    const double u = f.nodes.U.at(mass)[0];
    if (t_n < 0.0) {
      if (u < kD - 1e-12) continue;
      t_n = f.step_time; // the impact increment's end: on the stop, at rest, pulled away
      EXPECT_NEAR(u, kD, 1e-12);
      EXPECT_NEAR(f.nodes.V.at(mass)[0], 0.0, 1e-12);
      EXPECT_NEAR(f.nodes.A.at(mass)[0], -kF / kM, 1e-12);
      continue;
    }
    const double tau = f.step_time - t_n;
    EXPECT_NEAR(u, kD - 0.5 * kF / kM * tau * tau, 1e-12) << f.step_time;
    EXPECT_NEAR(f.nodes.V.at(mass)[0], -kF / kM * tau, 1e-10) << f.step_time;
    ++after;
  }
  EXPECT_GT(t_n, 0.0);
  EXPECT_GE(after, 10);
}

} // namespace
} // namespace gapfem
