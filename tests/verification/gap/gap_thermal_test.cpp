// Thermal gap decks with closed forms: spec §6.3 T1-T6 (DGAP conduction, conductor in series,
// zero conductance beyond the table, radiation, GAPUNIT frictional heating, pressure-dependent
// conductance under a changing clamp load), clearance-dependent view factor, and a gap closed by
// the thermal expansion of a coupled truss at dT = d / (alpha L).
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>

using namespace gapfem;
using namespace gapfem::test;

namespace {
const Frame& final_frame(const JobResult& r) {
  return last_frame(r);
}
double NT(const JobResult& r, const Frame& f, Label n) {
  return f.nodes.NT.at(r.model->mesh.find_node(n));
}
double RFL(const JobResult& r, const Frame& f, Label n) {
  return f.nodes.RFL.at(r.model->mesh.find_node(n));
}

// Node 1 held at 100 -> DC1D2 of length 0.95 (k = 1, A = 1) -> node 2 -> DGAP (A = 1) -> node 3
// held at 50. `gap_options` are the sub-options of *GAP.
std::string series_deck(double d, const std::string& gap_options, const std::string& extra = "") {
  return fmt::format(R"(*NODE
1, 0., 0., 0.
2, 0.95, 0., 0.
3, 1.95, 0., 0.
*ELEMENT, TYPE=DC1D2, ELSET=ROD
1, 1, 2
*MATERIAL, NAME=M
*CONDUCTIVITY
1.
*SOLID SECTION, ELSET=ROD, MATERIAL=M
1.
*ELEMENT, TYPE=DGAP, ELSET=G
10, 2, 3
*GAP, ELSET=G
{}, , , , 1.
{}
{}*STEP
*HEAT TRANSFER, STEADY STATE
*BOUNDARY
1, 11, 11, 100.
3, 11, 11, 50.
*EL PRINT, ELSET=G
HFL
*NODE PRINT
NT, RFL
*END STEP
)",
                     d, gap_options, extra);
}
} // namespace

TEST(VerificationGapThermal, T1DgapAlone) {
  const JobResult r = run_deck(R"(*NODE
2, 0., 0., 0.
3, 1., 0., 0.
*ELEMENT, TYPE=DGAP, ELSET=G
10, 2, 3
*GAP, ELSET=G
0., , , , 1.
*GAP CONDUCTANCE
10., 0.
10., 1.
*STEP
*HEAT TRANSFER, STEADY STATE
*BOUNDARY
2, 11, 11, 100.
3, 11, 11, 50.
*EL PRINT
HFL
*END STEP
)");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = final_frame(r);
  EXPECT_NEAR(gap(r, f, 10).heat_flux, 500.0, 1e-9); // 10 * (100 - 50)
  EXPECT_NEAR(gap(r, f, 10).heat_flow, 500.0, 1e-9);
  EXPECT_NEAR(RFL(r, f, 2), 500.0, 1e-9);  // heat put in at 100
  EXPECT_NEAR(RFL(r, f, 3), -500.0, 1e-9); // taken out at 50
}

TEST(VerificationGapThermal, T2ConductorInSeriesWithAGap) {
  // q = 50 / (0.95 / 1 + 1 / 10) = 47.619; T_B = 100 - 0.95 q = 54.762
  const JobResult r = run_deck(series_deck(0.0, "*GAP CONDUCTANCE\n10., 0.\n10., 1."));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = final_frame(r);
  const double q = 50.0 / 1.05;
  EXPECT_NEAR(gap(r, f, 10).heat_flux, q, 1e-9);
  EXPECT_NEAR(NT(r, f, 2), 100.0 - 0.95 * q, 1e-9);
  EXPECT_NEAR(r.steps.at(0).checks.heat_balance_error, 0.0, 1e-9);
}

TEST(VerificationGapThermal, T3NoConductanceBeyondTheLastClearance) {
  const JobResult r = run_deck(series_deck(2.0, "*GAP CONDUCTANCE\n10., 0.\n10., 1."));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = final_frame(r);
  EXPECT_EQ(gap(r, f, 10).heat_flux, 0.0);
  EXPECT_NEAR(NT(r, f, 2), 100.0, 1e-9);
}

TEST(VerificationGapThermal, T4Radiation) {
  // C = F sigma / (2/eps - 1) = 5.0e-10; (100 - T_B)/0.95 = C[(T_B+460)^4 - 510^4] by bisection:
  // T_B = 88.98823, q = 11.59134
  const JobResult r = run_deck(
      series_deck(0.0, "*GAP RADIATION\n0.45167, 0.45167\n1., 0.\n1., 1.",
                  "*PHYSICAL CONSTANTS, ABSOLUTE ZERO=-460., STEFAN BOLTZMANN=0.1714E-8\n"));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = final_frame(r);
  EXPECT_NEAR(NT(r, f, 2), 88.988226, 1e-5);
  EXPECT_NEAR(gap(r, f, 10).heat_flux, 11.591341, 1e-5);
}

namespace {
// GAPUNIT between node 1 (on a soft spring in y) and ground node 2 (fixed), d = 0, closure
// direction (0,-1,0), area 1. Both temperatures are held. Step 1 presses node 1 with `fy`.
std::string gapunit_deck(const std::string& gap_options, double fy, const std::string& step2 = "") {
  return fmt::format(R"(*NODE
1, 0., 0., 0.
2, 0., -1., 0.
*ELEMENT, TYPE=SPRING1, ELSET=SY
5, 1
*SPRING, ELSET=SY
2
1.
*ELEMENT, TYPE=GAPUNIT, ELSET=G
10, 1, 2
*GAP, ELSET=G
0., 0., -1., 0., 1.
{}
*BOUNDARY
2, 1, 3
1, 3, 3
*STEP
*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE
*BOUNDARY
1, 1, 1
1, 11, 11, 100.
2, 11, 11, 50.
*CLOAD
1, 2, {}
*EL PRINT
S, E, HFL
*NODE PRINT
U, NT, RFL
*END STEP
{})",
                     gap_options, fy, step2);
}
} // namespace

TEST(VerificationGapThermal, T5FrictionalHeating) {
  // Closed with N = 100, mu = 0.3; node 1 driven along x at speed v = 0.2 (0.2 per unit step
  // time): friction power 30 v = 6, split f = 0.5, eta = 1: 3 enters each node, which the held
  // temperatures take out again (RFL = -3 at each node; no conductance).
  const std::string step2 = R"(*STEP
*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE
0.25, 1.
*BOUNDARY
1, 1, 1, 0.2
*EL PRINT
S, E, HFL
*NODE PRINT
U, NT, RFL
*END STEP
)";
  const JobResult r = run_deck(
      gapunit_deck("*FRICTION, LAGRANGE\n0.3\n*GAP HEAT GENERATION\n1., 0.5", -100.0, step2));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  int checked = 0;
  for (const Frame& f : r.frames) {
    if (f.step != 2) continue;
    ASSERT_EQ(gap(r, f, 10).status, ContactStatus::Slip);
    EXPECT_NEAR(RFL(r, f, 1), -3.0, 1e-9) << "t = " << f.step_time;
    EXPECT_NEAR(RFL(r, f, 2), -3.0, 1e-9);
    ++checked;
  }
  EXPECT_EQ(checked, 4);
  EXPECT_NEAR(gap(r, last_frame(r), 10).dissipation, 0.3 * 100 * 0.2, 1e-9);
}

TEST(VerificationGapThermal, T6PressureDependentConductanceFollowsTheClampLoad) {
  // k(p) = 5 + 0.2 p (table 5 at p = 0, 25 at p = 100), temperatures 100 / 50, area 1:
  // clamp 40 → k = 13, Q = 650; clamp 90 → k = 23, Q = 1150.
  const std::string step2 = R"(*STEP
*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE
*CLOAD
1, 2, -90.
*EL PRINT
S, E, HFL
*END STEP
)";
  const JobResult r =
      run_deck(gapunit_deck("*GAP CONDUCTANCE, PRESSURE\n5., 0.\n25., 100.", -40.0, step2));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const GapRecord& g1 = gap(r, last_frame(r, 1), 10);
  EXPECT_NEAR(g1.pressure, 40.0, 1e-9);
  EXPECT_NEAR(g1.conductance, 13.0, 1e-9);
  EXPECT_NEAR(g1.heat_flow, 650.0, 1e-7);
  const GapRecord& g2 = gap(r, last_frame(r, 2), 10);
  EXPECT_NEAR(g2.conductance, 23.0, 1e-9);
  EXPECT_NEAR(g2.heat_flow, 1150.0, 1e-7);
  EXPECT_NEAR(RFL(r, last_frame(r, 2), 1), 1150.0, 1e-7);
}

TEST(VerificationGapThermal, RadiationViewFactorFollowsTheClearance) {
  // GAPUNIT opened to h = 0.5 by a pull; F(h) = 0.5 at h = 0 to 1 at h = 1 → F = 0.75;
  // q = 0.75 sigma/(1/0.5 + 1/0.5 - 1) [(100+273)^4 - (50+273)^4]
  const std::string opts = "*GAP RADIATION\n0.5, 0.5\n0.5, 0.\n1., 1.";
  std::string d = gapunit_deck(opts, 0.5); // spring k = 1 pulled by +0.5: node 1 moves up 0.5
  d.insert(d.find("*STEP"), "*PHYSICAL CONSTANTS, ABSOLUTE ZERO=-273., STEFAN BOLTZMANN=5.67E-8\n");
  const JobResult r = run_deck(d);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const GapRecord& g = gap(r, last_frame(r), 10);
  EXPECT_NEAR(g.clearance, 0.5, 1e-12);
  const double q = 0.75 * 5.67e-8 / 3.0 * (std::pow(373.0, 4) - std::pow(323.0, 4));
  EXPECT_NEAR(g.heat_flux, q, 1e-9 * q);
}

TEST(VerificationGapThermal, GapClosedByThermalExpansion) {
  // T3D2T bar of length L = 2 (E = 2e5, A = 1, alpha = 1e-5) fixed at x = 0, its far end facing a
  // wall through a GAPUNIT with clearance d = 1e-4; the whole bar is heated from 0 to 10 degrees.
  // Free growth alpha L dT closes the gap at dT_c = d / (alpha L) = 5; beyond it the bar pushes on
  // the wall with E A (alpha dT - d / L) = 2e5 (1e-4 - 5e-5) = 10 at dT = 10.
  const JobResult r = run_deck(R"(*NODE
1, 0., 0., 0.
2, 1., 0., 0.
3, 2., 0., 0.
4, 2., 0., 0.
*ELEMENT, TYPE=T3D2T, ELSET=BAR
1, 1, 2
2, 2, 3
*MATERIAL, NAME=M
*ELASTIC
2.E5, 0.3
*EXPANSION
1.E-5
*CONDUCTIVITY
50.
*SOLID SECTION, ELSET=BAR, MATERIAL=M
1.
*ELEMENT, TYPE=GAPUNIT, ELSET=G
10, 3, 4
*GAP, ELSET=G
1.E-4, 1., 0., 0., 1.
*NSET, NSET=ALL
1, 2, 3, 4
*INITIAL CONDITIONS, TYPE=TEMPERATURE
ALL, 0.
*BOUNDARY
1, 1, 3
2, 2, 3
3, 2, 3
4, 1, 3
*STEP
*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE
0.1, 1.
*BOUNDARY
ALL, 11, 11, 10.
*EL PRINT
S, E
*NODE PRINT
U
*END STEP
)");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  int open = 0, closed = 0;
  for (const Frame& f : r.frames) {
    const double dT = 10.0 * f.step_time;
    const GapRecord& g = gap(r, f, 10);
    if (dT < 5.0 - 1e-9) {
      EXPECT_EQ(g.status, ContactStatus::Open) << "dT = " << dT;
      EXPECT_NEAR(U(r, f, 3)[0], 2e-5 * dT, 1e-13);
      ++open;
    } else if (dT > 5.0 + 1e-9) {
      EXPECT_EQ(g.status, ContactStatus::Closed) << "dT = " << dT;
      EXPECT_NEAR(U(r, f, 3)[0], 1e-4, 1e-13);
      EXPECT_NEAR(g.normal_force, 2e5 * (1e-5 * dT - 5e-5), 1e-8);
      ++closed;
    }
  }
  EXPECT_GT(open, 0);
  EXPECT_GT(closed, 0);
}

TEST(VerificationGapThermal, ClearanceTableWhileOpenPressureTableWhileClosed) {
  // k(h) = 4 - 4 h (0 <= h <= 1) while open, k(p) = 5 + 0.2 p while closed; temperatures 100/50.
  const std::string opts =
      "*GAP CONDUCTANCE\n4., 0.\n0., 1.\n*GAP CONDUCTANCE, PRESSURE\n5., 0.\n25., 100.";
  const std::string step2 = R"(*STEP
*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE
*CLOAD
1, 2, -40.
*EL PRINT
S, E, HFL
*END STEP
)";
  const JobResult r = run_deck(gapunit_deck(opts, 0.25, step2)); // step 1 pulls node 1 up by 0.25
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const GapRecord& open = gap(r, last_frame(r, 1), 10);
  EXPECT_EQ(open.status, ContactStatus::Open);
  EXPECT_NEAR(open.conductance, 3.0, 1e-12);
  EXPECT_NEAR(open.heat_flux, 150.0, 1e-9);
  const GapRecord& closed = gap(r, last_frame(r, 2), 10);
  EXPECT_EQ(closed.status, ContactStatus::Closed);
  EXPECT_NEAR(closed.conductance, 13.0, 1e-9);
  EXPECT_NEAR(closed.heat_flux, 650.0, 1e-7);
  // a second clearance table is an error
  const JobResult bad = run_deck(
      gapunit_deck("*GAP CONDUCTANCE\n4., 0.\n0., 1.\n*GAP CONDUCTANCE\n4., 0.\n0., 1.", 0.25));
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.error.find("already given"), std::string::npos) << bad.error;
}

TEST(VerificationGapThermal, CoupledStepWithoutHeatLoadConvergesOnTheDisplacements) {
  // Two distorted C3D8T blocks (nu = 0, in-plane displacements held) pressed together through four
  // GAPUNITs (A = 0.3) by 4 x 1e5 on the top nodes; every temperature starts at 20 and nothing
  // heats the model, so its heat flux is round-off (~1e-13). The heat field must count as
  // converged by Abaqus's zero-flux rule (residual <= 1e-5 * max(q~, 1e-2)) instead of being held
  // to 0.005 of a round-off flux scale, which no iteration can reach.
  // Closed form: the gaps carry the whole load, sum(S11 * A) = 4e5; the temperature stays 20.
  const JobResult r = run_deck(R"(*HEADING
two distorted C3D8T blocks pressed together through four GAPUNITs, no heat load
*NODE
1, 0.0, 0.0, 0.0
2, 1.1, 0.1, 0.0
3, 0.9, 1.2, 0.0
4, -0.1, 0.8, 0.0
5, 0.05, -0.05, 1.0
6, 1.0, 0.07, 1.0
7, 1.13, 0.93, 1.0
8, 0.02, 1.1, 1.0
11, 0.05, -0.05, 1.0
12, 1.0, 0.07, 1.0
13, 1.13, 0.93, 1.0
14, 0.02, 1.1, 1.0
15, 0.1, 0.03, 2.1
16, 0.97, -0.1, 2.0
17, 1.05, 1.02, 1.9
18, -0.03, 0.96, 2.0
*ELEMENT, TYPE=C3D8T, ELSET=BLOCKS
1, 1, 2, 3, 4, 5, 6, 7, 8
2, 11, 12, 13, 14, 15, 16, 17, 18
*MATERIAL, NAME=STEEL
*ELASTIC
2.e11, 0.
*EXPANSION, ZERO=20.
1.2e-5
*CONDUCTIVITY
50.
*SOLID SECTION, ELSET=BLOCKS, MATERIAL=STEEL
*ELEMENT, TYPE=GAPUNIT, ELSET=G
21, 5, 11
22, 6, 12
23, 7, 13
24, 8, 14
*GAP, ELSET=G
0., 0., 0., 1., 0.3
*GAP CONDUCTANCE
1.e4, 0.
0., 1.e-4
*NSET, NSET=BOTTOM
1, 2, 3, 4
*NSET, NSET=ALL
1, 2, 3, 4, 5, 6, 7, 8, 11, 12, 13, 14, 15, 16, 17, 18
*INITIAL CONDITIONS, TYPE=TEMPERATURE
ALL, 20.
*BOUNDARY
ALL, 1, 2
BOTTOM, 3, 3
*STEP
*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE
0.25, 1.
*BOUNDARY
BOTTOM, 11, 11, 20.
*CLOAD
15, 3, -1.e5
16, 3, -1.e5
17, 3, -1.e5
18, 3, -1.e5
*EL PRINT, ELSET=G
S
*NODE PRINT, NSET=ALL
U, NT
*END STEP
)");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  double total = 0.0;
  for (Label e : {21, 22, 23, 24}) {
    EXPECT_NE(gap(r, f, e).status, ContactStatus::Open) << "gap " << e;
    total += gap(r, f, e).pressure * 0.3;
  }
  EXPECT_NEAR(total, 4e5, 1e-6 * 4e5);
  for (Label n : {1, 6, 7, 12, 13, 16, 17, 18})
    EXPECT_NEAR(NT(r, f, n), 20.0, 1e-9) << "node " << n;
  // nothing is nonlinear once the gaps are closed: one iteration per increment
  EXPECT_EQ(r.run.stats.iterations, r.run.stats.increments);
}
