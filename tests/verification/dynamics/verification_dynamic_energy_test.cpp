// Energies of dynamic steps (docs/theory/dynamics.md, "Energies"): the SDOF of the other dynamics
// tests, a T3D2 bar of stiffness k = EA/L = 500 with its mass m = rho A L / 2 = 0.5 lumped at the
// free end (w = sqrt(k/m), T = 2 pi / w), under a constant force F = 5 from t = 0.
// - The trapezoidal rule (ALPHA=0): each force's work by the trapezoidal rule is exact for it
//   (the spring force k u is linear in u: sum 1/2 k (u_n + u_n+1)(u_n+1 - u_n) = 1/2 k u^2; F is
//   constant: the work is F u), and Newmark's trapezoidal rule makes the inertia forces' work
//   equal the change of 1/2 m v^2. So at every increment, to rounding (one Newton iteration of
//   a linear system): ALLIE = 1/2 k u^2, ALLWK = F u, ALLKE = 1/2 m v^2 (v the node output V),
//   ETOTAL = ALLKE + ALLIE - ALLWK = 0.
// - HHT (TRANSIENT FIDELITY, alpha = -0.05) only dissipates: ETOTAL falls, by less than a few
//   percent of the largest energy over two periods at dt = T/40 (its numerical damping ratio at
//   w dt = 0.157 is about 0.3 %: a loss of about 2 x 2 pi x 0.003 = 4 % of the oscillation's
//   energy per period at most; the oscillation holds a quarter of the largest energy, ALLWK).
// - From an initial velocity v0 and no load: ALLKE starts at 1/2 m v0^2 and ETOTAL keeps it.
// - A hard stop: the impact's lost kinetic energy ALLKL is 1/2 m v^2 of the speed at the stop (a
//   fully plastic impact) less the closing increment's contact work (in ALLIE); ETOTAL keeps its
//   value exactly.
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <numbers>

namespace gapfem {
namespace {

using test::run_deck;

constexpr double kK = 500.0, kM = 0.5, kF = 5.0;
const double kW = std::sqrt(kK / kM);
const double kT = 2.0 * std::numbers::pi / kW;

std::string sdof_deck(const std::string& dynamic, double dt, double period,
                      const std::string& extra_model = "", double force = kF,
                      const std::string& extra_step = "") {
  return fmt::format(R"(*HEADING
SDOF: a bar with its mass lumped at the free end
*NODE
1, 0., 0., 0.
2, 1., 0., 0.
3, 1.02, 0., 0.
*ELEMENT, TYPE=T3D2, ELSET=BAR
1, 1, 2
*MATERIAL, NAME=M
*ELASTIC
1000., 0.
*DENSITY
2.
*SOLID SECTION, ELSET=BAR, MATERIAL=M
0.5
*BOUNDARY
1, 1, 3
2, 2, 3
3, 1, 3
{}
*AMPLITUDE, NAME=CONST
0., 1., 1000., 1.
*STEP, INC=100000
*DYNAMIC{}
{}, {}
*CLOAD, AMPLITUDE=CONST
2, 1, {}
*NODE PRINT, FREQUENCY=1
U, V
{}
*END STEP
)",
                     extra_model, dynamic, dt, period, force, extra_step);
}

TEST(VerificationDynamicEnergy, TrapezoidalRuleBalancesEveryIncrementExactly) {
  const JobResult r = run_deck(sdof_deck(", DIRECT, ALPHA=0.", kT / 40.0, 2.0 * kT));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  int checked = 0;
  for (const Frame& f : r.frames) {
    if (f.increment == 0) continue;
    ASSERT_TRUE(f.energies.has_value());
    const Energies& e = *f.energies;
    const double u = test::U(r, f, 2)[0];
    const double v = f.nodes.V[static_cast<std::size_t>(JobResult::node(*r.model, 2))][0];
    EXPECT_NEAR(e.allie, 0.5 * kK * u * u, 1e-12) << "t = " << f.step_time;
    EXPECT_NEAR(e.allwk, kF * u, 1e-12);
    EXPECT_NEAR(e.allke, 0.5 * kM * v * v, 1e-12);
    EXPECT_NEAR(e.etotal(), 0.0, 1e-12 * e.scale() + 1e-15);
    EXPECT_EQ(e.allvd, 0.0);
    EXPECT_EQ(e.allkl, 0.0);
    ++checked;
  }
  EXPECT_EQ(checked, 80);
  // the largest energy is the work at the largest displacement 2 F/k: F 2F/k = 0.1
  const StepChecks& c = r.steps.at(0).checks;
  EXPECT_TRUE(c.dynamic);
  EXPECT_TRUE(c.conserving);
  EXPECT_NEAR(c.energy_scale, 2.0 * kF * kF / kK, 1e-4);
  EXPECT_LE(std::abs(c.energy_change), 1e-12);
  // the per-increment energies of IncrementInfo are the frames'
  ASSERT_FALSE(r.increments.empty());
  ASSERT_TRUE(r.increments.back().energies.has_value());
  EXPECT_EQ(r.increments.back().energies->allke, r.frames.back().energies->allke);
}

TEST(VerificationDynamicEnergy, HhtOnlyDissipates) {
  const JobResult r = run_deck(sdof_deck(", DIRECT", kT / 40.0, 2.0 * kT));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const StepChecks& c = r.steps.at(0).checks;
  EXPECT_FALSE(c.conserving);
  EXPECT_LT(c.energy_change, 0.0);
  EXPECT_GT(c.energy_change, -0.05 * c.energy_scale);
  // never above its start (the trapezoidal works make HHT's ETOTAL oscillate within its fall)
  for (const IncrementInfo& i : r.increments)
    if (i.converged) EXPECT_LE(i.energies->etotal(), 1e-12);
  EXPECT_TRUE(r.run.warnings.empty() ||
              r.run.warnings.front().find("energy balance") == std::string::npos);
}

TEST(VerificationDynamicEnergy, AnInitialVelocityIsKineticEnergyKept) {
  const double v0 = 1.0;
  const JobResult r = run_deck(sdof_deck(", DIRECT, ALPHA=0.", kT / 40.0, kT,
                                         "*INITIAL CONDITIONS, TYPE=VELOCITY\n2, 1, 1.", 0.0));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const double e0 = 0.5 * kM * v0 * v0;
  for (const IncrementInfo& i : r.increments) {
    ASSERT_TRUE(i.energies.has_value());
    EXPECT_NEAR(i.energies->etotal(), e0, 1e-12);
    EXPECT_NEAR(i.energies->allke + i.energies->allie, e0, 1e-12);
  }
  EXPECT_NEAR(r.steps.at(0).checks.energy_change, 0.0, 1e-12);
}

TEST(VerificationDynamicEnergy, AnImpactsLostKineticEnergyIsReported) {
  // a GAPUNI from node 2 to the fixed node 3 closes at u = c = 0.02 = F/k under F = 10: the mass
  // hits the stop at its largest speed, 1/2 m v^2 = F c - 1/2 k c^2 = 0.2 - 0.1 = 0.1 (INITIAL=YES:
  // the model has a gap, whose default MODERATE DISSIPATION starts from zero accelerations)
  const std::string gap =
      "*ELEMENT, TYPE=GAPUNI, ELSET=G\n10, 2, 3\n*GAP, ELSET=G\n0.02, 1., 0., 0.";
  const JobResult r =
      run_deck(sdof_deck(", DIRECT, ALPHA=0., INITIAL=YES", kT / 200.0, kT / 2.0, gap, 10.0));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  double ke_before = -1.0;
  for (const IncrementInfo& i : r.increments)
    if (i.converged && i.energies->allkl == 0.0) ke_before = i.energies->allke;
  const Energies& e = *r.increments.back().energies;
  EXPECT_NEAR(ke_before, 0.1, 1e-4); // the trapezoidal rule reaches the stop at full speed
  // the plastic impact takes what is left of it after the closing increment's contact work
  // (which goes into ALLIE: a fraction of one increment's work, F v dt ~ 0.02)
  EXPECT_NEAR(e.allkl, 0.1, 0.005);
  EXPECT_NEAR(e.allie, 0.5 * kK * 0.02 * 0.02 + (0.1 - e.allkl), 1e-9);
  EXPECT_NEAR(e.allke, 0.0, 1e-12); // it stays at the stop
  EXPECT_NEAR(e.allwk, 10.0 * 0.02, 1e-12);
  EXPECT_LT(std::abs(r.steps.at(0).checks.energy_change), 1e-12);
}

TEST(VerificationDynamicEnergy, EnergiesAreWrittenToTheResultsFiles) {
  const JobResult r = run_deck(sdof_deck(", DIRECT, ALPHA=0.", kT / 10.0, kT), true);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto dir = test::test_dir();
  const std::string dat = test::slurp(dir / "job.dat");
  EXPECT_NE(dat.find("ALLKE (KINETIC ENERGY)"), std::string::npos);
  EXPECT_NE(dat.find("ENERGY BALANCE OVER THE STEP"), std::string::npos);
  const std::string sta = test::slurp(dir / "job.sta");
  EXPECT_NE(sta.find("ETOTAL="), std::string::npos);
  const auto j = nlohmann::json::parse(test::slurp(dir / "job.results.json"));
  const auto& step = j.at("steps").at(0);
  const auto& rows = step.at("history").at("energies").at("rows");
  EXPECT_EQ(rows.size(), 10u);
  EXPECT_EQ(step.at("history").at("energies").at("columns").at(3), "ALLKE");
  const auto& frame = step.at("frames").back();
  EXPECT_DOUBLE_EQ(frame.at("energies").at("ALLKE").get<double>(), rows.back().at(3).get<double>());
  EXPECT_TRUE(step.at("checks").at("energy_balance").at("conserving").get<bool>());
}

TEST(VerificationDynamicEnergy, HistoryOutputIsATimeSeriesOfTheRequestedValues) {
  // *OUTPUT, HISTORY: U and V of node 2 and the bar's axial force (SF) every increment, the
  // energies; the values are the frames' (node output) at the same increments
  const std::string history = "*OUTPUT, HISTORY, VARIABLE=PRESELECT\n*NODE OUTPUT, NSET=TIP\nU, V\n"
                              "*ELEMENT OUTPUT, ELSET=BAR\nSF";
  const JobResult r = run_deck(
      sdof_deck(", DIRECT, ALPHA=0.", kT / 10.0, kT, "*NSET, NSET=TIP\n2", kF, history), true);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto j = nlohmann::json::parse(test::slurp(test::test_dir() / "job.results.json"));
  const auto& values = j.at("steps").at(0).at("history").at("values");
  const auto& columns = values.at("columns");
  ASSERT_EQ(columns.size(), 3u + 3u + 3u + 1u);
  EXPECT_EQ(columns.at(3), "U1 at node 2");
  EXPECT_EQ(columns.at(6), "V1 at node 2");
  EXPECT_EQ(columns.at(9), "SF1 at element 1");
  const auto& rows = values.at("rows");
  ASSERT_EQ(rows.size(), 10u);
  std::size_t k = 0;
  for (const Frame& f : r.frames) {
    if (f.increment == 0) continue;
    const auto& row = rows.at(k++);
    const double u = test::U(r, f, 2)[0];
    EXPECT_EQ(row.at(0).get<double>(), f.increment);
    EXPECT_DOUBLE_EQ(row.at(3).get<double>(), u);
    EXPECT_DOUBLE_EQ(row.at(6).get<double>(),
                     f.nodes.V[static_cast<std::size_t>(JobResult::node(*r.model, 2))][0]);
    EXPECT_NEAR(row.at(9).get<double>(), kK * u, 1e-9); // the axial force k u
  }
  const std::string report = test::slurp(test::test_dir() / "job.report.html");
  EXPECT_NE(report.find("History output"), std::string::npos);
  EXPECT_NE(report.find("Energies"), std::string::npos);
}

TEST(VerificationDynamicEnergy, ADashpotsDissipationIsAllvd) {
  // free vibration from v0 = 1 with a DASHPOT1 c = 1 at the mass (zeta = c / (2 sqrt(k m)) =
  // 0.032): the trapezoidal rule balances exactly, ALLKE + ALLIE + ALLVD = 1/2 m v0^2 at every
  // increment (R(0) holds the dashpot's force c v0: INITIAL=YES starts from a0 = -c v0 / m, and
  // ALLVD's trapezoidal rule from c v0), ALLVD grows and after 2 periods holds most of it
  // (the amplitude decays as exp(-zeta w t): 1 - exp(-2 zeta w 2T) = 1 - exp(-8 pi zeta) = 0.55)
  const std::string dashpot = "*ELEMENT, TYPE=DASHPOT1, ELSET=D\n20, 2\n*DASHPOT, ELSET=D\n1\n1.\n"
                              "*INITIAL CONDITIONS, TYPE=VELOCITY\n2, 1, 1.";
  const JobResult r =
      run_deck(sdof_deck(", DIRECT, ALPHA=0., INITIAL=YES", kT / 100.0, 2.0 * kT, dashpot, 0.0));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const double e0 = 0.5 * kM;
  double vd = 0.0;
  for (const IncrementInfo& i : r.increments) {
    if (!i.converged) continue;
    const Energies& e = *i.energies;
    EXPECT_NEAR(e.allke + e.allie + e.allvd, e0, 1e-12 * e0) << "t = " << i.step_time;
    EXPECT_GE(e.allvd, vd - 1e-15); // dissipation never decreases
    vd = e.allvd;
  }
  const double zeta = 1.0 / (2.0 * std::sqrt(kK * kM));
  EXPECT_NEAR(vd / e0, 1.0 - std::exp(-8.0 * std::numbers::pi * zeta), 0.05);
}

TEST(VerificationDynamicEnergy, SlidingOnAFrictionalRestIsAllfd) {
  // a point mass m = 1 pressed onto a GAPUNI rest by N = 100 (static step 1: it sticks, LAGRANGE
  // friction mu = 0.3), then pushed along the rest by F = 100 t (*DYNAMIC's default ramp to 50
  // at t = 0.5, as Abaqus's): it sticks until F = mu N = 30 at t = 0.3, then slides with
  // a = F - mu N = 100 (t - 0.3): v = 50 (t - 0.3)^2, x = 50/3 (t - 0.3)^3. The friction force is
  // mu N all the slide: ALLFD = mu N x exactly; the trapezoidal rule balances every increment
  // (ETOTAL = ALLKE + ALLFD - ALLWK = 0 up to the Newton tolerance), and its x follows the cubic
  // within its O(dt^2) error (dt = 0.005: under 1 % of x at t = 0.5)
  const JobResult r = run_deck(R"(*HEADING
a mass sliding on a frictional rest
*NODE
10, 0., 0., 0.
12, 0., -1., 0.
*ELEMENT, TYPE=MASS, ELSET=M
1, 10
*MASS, ELSET=M
1.
*ELEMENT, TYPE=GAPUNI, ELSET=G
101, 10, 12
*GAP, ELSET=G
0., 0., -1., 0., 1.
*FRICTION, LAGRANGE
0.3
*BOUNDARY
12, 1, 3
10, 3, 3
*STEP
*STATIC
*CLOAD
10, 2, -100.
*END STEP
*STEP, INC=1000
*DYNAMIC, DIRECT, ALPHA=0.
0.005, 0.5
*CLOAD
10, 1, 50.
*NODE PRINT, FREQUENCY=1
U
*END STEP
)");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  int checked = 0;
  double x_end = 0.0;
  for (const Frame& f : r.frames) {
    if (f.step != 2 || f.increment == 0) continue;
    const double x = test::U(r, f, 10)[0];
    const Energies& e = *f.energies;
    EXPECT_NEAR(e.allfd, 30.0 * x, 1e-9) << "t = " << f.step_time;
    EXPECT_NEAR(e.etotal(), 0.0, 1e-9 * e.scale() + 1e-12);
    if (f.step_time < 0.3 - 1e-9) EXPECT_NEAR(x, 0.0, 1e-12); // sticking
    x_end = x;
    ++checked;
  }
  EXPECT_EQ(checked, 100);
  const double exact = 50.0 / 3.0 * 0.2 * 0.2 * 0.2;
  EXPECT_NEAR(x_end, exact, 0.01 * exact);
}

TEST(VerificationDynamicEnergy, ABaseDrivenMassAloneIsWorkIntoKineticEnergy) {
  // every DOF prescribed (no equations): a point mass m = 2 driven by an acceleration ramped to
  // a = 3 t (*BOUNDARY, TYPE=ACCELERATION, *DYNAMIC's default ramp over the step of 1): v = 1.5
  // t^2, ALLKE = 1/2 m v^2 = 2.25 at t = 1, done by the reaction m a: ALLWK = the integral of m a
  // dx = 9 t^4 / 4 = 2.25. The driven DOF's motion is the exact integral of the prescribed
  // acceleration, but the kernels see the integrator's rates there (docs/theory/dynamics.md, Base
  // motion: they differ by O(dt)): M v and the reaction M a are that close (dt = 0.01: measured
  // 3e-5 and 5e-3 of 2.25)
  const JobResult r = run_deck(R"(*HEADING
a mass driven alone
*NODE
1, 0., 0., 0.
*ELEMENT, TYPE=MASS, ELSET=M
1, 1
*MASS, ELSET=M
2.
*BOUNDARY
1, 2, 3
*STEP, INC=1000
*DYNAMIC, DIRECT
0.01, 1.
*BOUNDARY, TYPE=ACCELERATION
1, 1, 1, 3.
*END STEP
)");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Energies& e = *r.increments.back().energies;
  EXPECT_NEAR(e.allke, 2.25, 1e-4 * 2.25);
  EXPECT_NEAR(e.allwk, 2.25, 1e-2 * 2.25);
}

} // namespace
} // namespace gapfem
