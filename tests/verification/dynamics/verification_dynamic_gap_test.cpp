// *DYNAMIC with a hard gap stop (docs/theory/dynamics.md §5, impacts): the bar of the SDOF tests
// (k = 500, m = 0.5 at node 2) with a GAPUNI from node 2 to a fixed node, clearance 0.005 along
// +x. The model has contact, so Abaqus's default APPLICATION is MODERATE DISSIPATION.
// - A constant force F = 5 (static F/k = 0.01) drives the mass onto the stop at 0.005
//   (w t = pi/3); the impact is fully plastic (the mass takes the stop's zero velocity), so it
//   stays there with the gap force F - k 0.005 = 2.5. Without the impact rule the mass bounced
//   off ever higher (HHT with a hard constraint gains energy at each impact).
// - The force acts until t = 0.06 and is then removed: from rest at u = 0.005 the spring swings
//   the mass back; it never comes back further than 0.005 from 0 on either side (no energy
//   gained; HHT only dissipates): released from rest at the stop it comes back just short of it.
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>

namespace gapfem {
namespace {

using test::run_deck;

std::string gap_deck(const std::string& amplitude, double period) {
  return fmt::format(R"(*HEADING
a mass on a bar driven onto a hard stop
*NODE
1, 0., 0., 0.
2, 1., 0., 0.
3, 2., 0., 0.
*ELEMENT, TYPE=T3D2, ELSET=BAR
1, 1, 2
*MATERIAL, NAME=M
*ELASTIC
1000., 0.
*DENSITY
2.
*SOLID SECTION, ELSET=BAR, MATERIAL=M
0.5
*ELEMENT, TYPE=GAPUNI, ELSET=G
10, 2, 3
*GAP, ELSET=G
0.005, 1., 0., 0., 1.
*BOUNDARY
1, 1, 3
2, 2, 3
3, 1, 3
*AMPLITUDE, NAME=A
{}
*STEP, INC=100000
*DYNAMIC, DIRECT
0.002, {}
*CLOAD, AMPLITUDE=A
2, 1, 5.
*NODE PRINT, FREQUENCY=1
U
*EL PRINT, ELSET=G, FREQUENCY=1
S
*END STEP
)",
                     amplitude, period);
}

TEST(VerificationDynamicGap, AMassDrivenOntoAStopStaysThereAfterAPlasticImpact) {
  const JobResult r = run_deck(gap_deck("0., 1., 1000., 1.", 0.4));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  double umax = 0.0;
  for (const Frame& f : r.frames) umax = std::max(umax, test::U(r, f, 2)[0]);
  EXPECT_LE(umax, 0.005 + 1e-9);
  const Frame& end = test::last_frame(r);
  EXPECT_NEAR(test::U(r, end, 2)[0], 0.005, 1e-9);
  EXPECT_NEAR(test::gap(r, end, 10).normal_force, 2.5, 1e-6);
  // the stop was reached after w t = pi/3 (as HHT tracks it: within two increments)
  double t_hit = -1.0;
  for (const Frame& f : r.frames)
    if (t_hit < 0.0 && test::U(r, f, 2)[0] >= 0.005 - 1e-9) t_hit = f.step_time;
  EXPECT_NEAR(t_hit, std::acos(0.5) / std::sqrt(1000.0), 0.004);
}

TEST(VerificationDynamicGap, AMassSwingingAgainstAStopNeverGainsEnergy) {
  const JobResult r = run_deck(gap_deck("0., 1., 0.06, 1., 0.0601, 0., 1000., 0.", 1.0));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  double lo = 0.0, hi = -1.0;
  for (const Frame& f : r.frames) {
    if (f.step_time < 0.07) continue;
    const double u = test::U(r, f, 2)[0];
    lo = std::min(lo, u);
    hi = std::max(hi, u);
  }
  EXPECT_GE(lo, -0.005 - 1e-9); // never further out than it started
  EXPECT_LE(hi, 0.005 + 1e-9);  // never through the stop
  EXPECT_LT(lo, -0.003);        // it did swing back (HHT-MD damps it only slowly)
  EXPECT_GT(hi, 0.003);         // and came back towards the stop
}

} // namespace
} // namespace gapfem
