// A hard gap that opens (a release, docs/theory/dynamics.md §5): the contact force falls to zero
// before the gap opens, so it does no work. The increment in which a held gap opens is solved
// again with the release at its start (the force zero there, the accelerations without it).
//
// A point mass m (node 2, free along x only) pressed onto a fixed stop (GAPUNI, no clearance) by
// the force F(t) = F0 (1 - t / t*) along +x, which turns into a pull at t* = 0.1 (the stop holds
// lambda = F(t) until then). After t* the exact motion is u(t) = -c (t - t*)^3 / (6 m), c = F0 /
// t*. With increments of dt = 0.03, t* falls inside the fourth increment [0.09, 0.12].
//
// 1. Trapezoidal rule (ALPHA=0): from the release at t_n = 0.09 the mass is free, so the discrete
//    motion is the trapezoidal recursion a_k = F(t_k) / m, v_k+1 = v_k + dt (a_k + a_k+1) / 2,
//    u_k+1 = u_k + dt (v_k + v_k+1) / 2 from u = v = 0 at t_n: U and V to 1e-12 at every frame
//    (held, the contact kept a_n = 0 at t_n, and the increment's trapezoid let its force lambda_n
//    work over the opening: ALLIE = -1/2 lambda_n du = -1.1e-6, kinetic energy from nowhere, and
//    U lagged the recursion by 1.1e-5 after the first increment). The gap does
//    no work: ALLIE = 0, ALLKL = 0, ETOTAL = 0 to 1e-12 of ALLWK. The end displacement against the
//    exact one: the release is resolved to the increment (0.41 % at dt = 0.03 by the recursion
//    above; the bound 2 %).
// 2. HHT (TRANSIENT FIDELITY, MODERATE DISSIPATION): the mass never moves into the stop, the gap
//    does no work (ALLIE = 0 to 1e-12), and ETOTAL never grows (HHT's imbalance of the released
//    force's jump is booked with the contacts, ALLKL, as an impact's). Held, ALLIE was -1.2e-6
//    and ETOTAL grew by up to 3.6e-7 (3.5e-5 of the pull's work).
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>

namespace gapfem {
namespace {

constexpr double kM = 2.0, kF0 = 1.0, kTStar = 0.1, kDt = 0.03, kT = 0.3;

std::string release_deck(const char* integrator) {
  // the amplitude is 1 - t / t* (linear to t = 1); *CLOAD's magnitude F0
  return fmt::format(R"(*HEADING
A mass pressed on a stop, then pulled off
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
0., 1., 0., 0.
*AMPLITUDE, NAME=PULL
0., 1., 1., {}
*BOUNDARY
2, 2, 3
3, 1, 3
*STEP, INC=1000
*DYNAMIC, DIRECT, {}
{}, {}
*CLOAD, AMPLITUDE=PULL
2, 1, {}
*NODE PRINT, FREQUENCY=1
U, V, A
*END STEP
)",
                     kM, 1.0 - 1.0 / kTStar, integrator, kDt, kT, kF0);
}

double force(double t) {
  return kF0 * (1.0 - t / kTStar);
}

TEST(VerificationRelease, TrapezoidalRuleReleasesAtTheIncrementStart) {
  const JobResult r = test::run_deck(release_deck("ALPHA=0."));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const LocalIndex mass = r.model->mesh.find_node(2);
  // the trapezoidal recursion of the free mass from the release at the increment's start
  const double t_n = std::floor(kTStar / kDt) * kDt;
  double u = 0.0, v = 0.0, a = force(t_n) / kM, t = t_n;
  int checked = 0;
  for (const Frame& f : r.frames) {
    if (f.increment == 0) continue;
    const double uf = f.nodes.U.at(mass)[0], vf = f.nodes.V.at(mass)[0];
    if (f.step_time <= t_n + 1e-12) { // held: on the stop, at rest
      EXPECT_NEAR(uf, 0.0, 1e-14) << f.step_time;
      EXPECT_NEAR(vf, 0.0, 1e-14) << f.step_time;
      continue;
    }
    ASSERT_NEAR(f.step_time, t + kDt, 1e-12);
    t += kDt;
    const double a1 = force(t) / kM, v1 = v + 0.5 * kDt * (a + a1), u1 = u + 0.5 * kDt * (v + v1);
    u = u1;
    v = v1;
    a = a1;
    EXPECT_NEAR(uf, u, 1e-12) << f.step_time;
    EXPECT_NEAR(vf, v, 1e-12) << f.step_time;
    ++checked;
  }
  EXPECT_GE(checked, 6);
  ASSERT_TRUE(r.frames.back().energies.has_value());
  const Energies& e = *r.frames.back().energies;
  ASSERT_GT(e.allwk, 0.0);
  EXPECT_NEAR(e.allie, 0.0, 1e-12 * e.allwk);
  EXPECT_NEAR(e.allkl, 0.0, 1e-12 * e.allwk);
  EXPECT_NEAR(e.etotal(), 0.0, 1e-12 * e.allwk);
  EXPECT_NEAR(e.allke, e.allwk, 1e-12 * e.allwk);
  const double c = kF0 / kTStar, tau = kT - kTStar;
  const double exact = -c * tau * tau * tau / (6.0 * kM);
  EXPECT_NEAR(r.frames.back().nodes.U.at(mass)[0], exact, 0.02 * std::abs(exact));
}

void expect_release_without_work(const char* application) {
  const JobResult r = test::run_deck(release_deck(application));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  for (const std::string& w : r.run.warnings)
    EXPECT_EQ(w.find("energy balance"), std::string::npos) << w;
  const LocalIndex mass = r.model->mesh.find_node(2);
  ASSERT_TRUE(r.frames.back().energies.has_value());
  const double scale = r.frames.back().energies->allwk; // the pull's work: the largest energy
  ASSERT_GT(scale, 0.0);
  for (const Frame& f : r.frames) {
    if (f.increment == 0 || !f.energies) continue;
    const Energies& e = *f.energies;
    EXPECT_LE(f.nodes.U.at(mass)[0], 1e-14) << f.step_time; // never into the stop
    EXPECT_NEAR(e.allie, 0.0, 1e-12 * scale) << f.step_time;
    EXPECT_LE(e.etotal(), 1e-12 * scale) << f.step_time;
  }
  EXPECT_LT(r.frames.back().nodes.U.at(mass)[0], 0.0); // pulled off
}

TEST(VerificationRelease, TransientFidelityReleaseDoesNoWork) {
  expect_release_without_work("APPLICATION=TRANSIENT FIDELITY");
}

TEST(VerificationRelease, ModerateDissipationReleaseDoesNoWork) {
  expect_release_without_work("APPLICATION=MODERATE DISSIPATION");
}

} // namespace
} // namespace gapfem
