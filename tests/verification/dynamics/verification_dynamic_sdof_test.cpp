// *DYNAMIC on a single degree of freedom with closed forms (docs/theory/dynamics.md): a T3D2 bar
// of stiffness k = EA/L = 500 and lumped mass m = rho A L / 2 = 0.5 at its free end
// (w = sqrt(k/m) = sqrt(1000), T = 2 pi / w = 0.19869), loaded at t = 0 by a constant force
// F = 5 (an amplitude that is 1 from the step start). Exact response from rest:
//   u(t) = F/k (1 - cos w t),  F/k = 0.01,  a(0) = F/m (INITIAL=YES computes it).
// - ALPHA=0 (the trapezoidal rule) has no amplitude error; its discrete solution is exactly
//   u_n = F/k (1 - cos(n theta)), theta = 2 atan(w dt / 2) (its period elongation): to 1e-9.
// - TRANSIENT FIDELITY (HHT, alpha = -0.05) against the same recurrence advanced by hand from
//   Hilber, Hughes and Taylor's equations (an oracle independent of the assembler, the mass and
//   the initial accelerations) to 1e-9, and against the continuous u(t) within 1.5 % of F/k over
//   a period at dt = T/100 (HHT's period error and numerical damping at w dt = 0.063).
// - QUASI-STATIC (backward Euler) damps the motion out: u -> F/k.
// - A linear dynamic increment takes one Newton iteration.
// - HAFTOL sizes the increments from the half-increment residual: they vary, each accepted one
//   is within the tolerance; HAFTOL = 0.05 (1 % of F) keeps the answer within 12 % of F/k of the
//   closed form over two periods (about 23 increments a period; measured 8.9 %), HAFTOL = 0.005
//   within 2 % (measured 1.3 %) with more than twice the increments.
#include "test_util.hpp"

#include <cmath>
#include <cstdio>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <numbers>

namespace gapfem {
namespace {

using test::run_deck;

constexpr double kK = 500.0, kM = 0.5, kF = 5.0;
const double kW = std::sqrt(kK / kM);
const double kT = 2.0 * std::numbers::pi / kW;

std::string sdof_deck(const std::string& dynamic, double dt, double period,
                      const std::string& print = "U") {
  return fmt::format(R"(*HEADING
SDOF: a bar with its mass lumped at the free end, a constant force from t = 0
*NODE
1, 0., 0., 0.
2, 1., 0., 0.
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
*AMPLITUDE, NAME=CONST
0., 1., 1000., 1.
*STEP, INC=100000
*DYNAMIC{}
{}, {}
*CLOAD, AMPLITUDE=CONST
2, 1, 5.
*NODE PRINT, FREQUENCY=1
{}
*END STEP
)",
                     dynamic, dt, period, print);
}

/// u of node 2 at the end of every increment, with its step time.
std::vector<std::pair<double, double>> history(const JobResult& r) {
  std::vector<std::pair<double, double>> h;
  for (const Frame& f : r.frames)
    if (f.increment > 0) h.emplace_back(f.step_time, test::U(r, f, 2)[0]);
  return h;
}

TEST(VerificationDynamicSdof, TrapezoidalRuleIsExactUpToItsPeriodElongation) {
  const double dt = kT / 40.0;
  const JobResult r = run_deck(sdof_deck(", DIRECT, ALPHA=0.", dt, 2.0 * kT));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto h = history(r);
  ASSERT_EQ(h.size(), 80u);
  const double theta = 2.0 * std::atan(kW * dt / 2.0);
  for (std::size_t n = 0; n < h.size(); ++n)
    EXPECT_NEAR(h[n].second, kF / kK * (1.0 - std::cos((n + 1) * theta)), 1e-9 * kF / kK)
        << "increment " << n + 1;
  for (const IncrementInfo& i : r.increments) EXPECT_EQ(i.iterations, 1); // linear
}

/// Displacement, velocity and acceleration at the end of an increment.
struct Motion {
  double u = 0.0, v = 0.0, a = 0.0;
};

/// HHT on m a + k u = F by hand: M a / (1 + alpha) + R - alpha / (1 + alpha) R_n = 0,
/// R = k u - F, Newmark's u and v updates; from rest with a(0) = F/m.
std::vector<Motion> hht_motion_by_hand(double alpha, double dt, int n) {
  const double beta = 0.25 * (1.0 - alpha) * (1.0 - alpha), gamma = 0.5 - alpha;
  double u = 0.0, v = 0.0, a = kF / kM, R = -kF;
  std::vector<Motion> out;
  for (int i = 0; i < n; ++i) {
    // a_new = (du - dt v - dt^2 (1/2 - beta) a) / (beta dt^2), linear in du: solve for du
    const double c = 1.0 / (beta * dt * dt);
    const double a0 = -(v * dt + dt * dt * (0.5 - beta) * a) * c; // a_new at du = 0
    // kM (a0 + c du) / (1 + alpha) + kK (u + du) - kF - alpha / (1 + alpha) R = 0
    const double du = -(kM * a0 / (1.0 + alpha) + kK * u - kF - alpha / (1.0 + alpha) * R) /
                      (kM * c / (1.0 + alpha) + kK);
    const double an = a0 + c * du;
    v += dt * ((1.0 - gamma) * a + gamma * an);
    a = an;
    u += du;
    R = kK * u - kF;
    out.push_back({u, v, a});
  }
  return out;
}

/// The displacements of hht_motion_by_hand.
std::vector<double> hht_by_hand(double alpha, double dt, int n) {
  std::vector<double> u;
  for (const Motion& m : hht_motion_by_hand(alpha, dt, n)) u.push_back(m.u);
  return u;
}

TEST(VerificationDynamicSdof, TransientFidelityFollowsHhtAndTheClosedForm) {
  const double dt = kT / 100.0;
  const JobResult r = run_deck(sdof_deck(", DIRECT", dt, kT));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto h = history(r);
  ASSERT_EQ(h.size(), 100u);
  const auto oracle = hht_by_hand(-0.05, dt, 100);
  double worst = 0.0;
  for (std::size_t n = 0; n < h.size(); ++n) {
    EXPECT_NEAR(h[n].second, oracle[n], 1e-9 * kF / kK) << "increment " << n + 1;
    worst = std::max(worst, std::abs(h[n].second - kF / kK * (1.0 - std::cos(kW * h[n].first))));
  }
  EXPECT_LT(worst, 0.015 * kF / kK);
  EXPECT_GT(worst, 1e-5 * kF / kK); // HHT is not exact: the test would notice a wrong oracle
}

TEST(VerificationDynamicSdof, QuasiStaticApplicationDampsTheMotionOut) {
  const JobResult r =
      run_deck(sdof_deck(", DIRECT, APPLICATION=QUASI-STATIC", kT / 4.0, 10.0 * kT));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto h = history(r);
  EXPECT_NEAR(h.back().second, kF / kK, 1e-4 * kF / kK);
}

TEST(VerificationDynamicSdof, AutomaticIncrementsWithoutDirectReachTheEnd) {
  const JobResult r = run_deck(sdof_deck("", kT / 50.0, kT));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto h = history(r);
  ASSERT_FALSE(h.empty());
  EXPECT_NEAR(h.back().first, kT, 1e-12);
}

// *INITIAL CONDITIONS, TYPE=VELOCITY: free vibration from u = 0, v = v0 (no load). The
// trapezoidal rule's discrete solution is u_n = (v0 / w) sin(n theta), theta = 2 atan(w dt / 2)
// (u_1 = dt v0 / (1 + (w dt / 2)^2) = (v0 / w) sin theta), and conserves the energy.
TEST(VerificationDynamicSdof, InitialVelocityStartsAFreeVibration) {
  std::string d = sdof_deck(", DIRECT, ALPHA=0.", kT / 40.0, kT);
  d.insert(d.find("*STEP"), "*INITIAL CONDITIONS, TYPE=VELOCITY\n2, 1, 0.3\n");
  d.replace(d.find("2, 1, 5."), 8, "2, 1, 0.");
  const JobResult r = run_deck(d);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto h = history(r);
  ASSERT_EQ(h.size(), 40u);
  const double theta = 2.0 * std::atan(kW * kT / 80.0);
  for (std::size_t n = 0; n < h.size(); ++n)
    EXPECT_NEAR(h[n].second, 0.3 / kW * std::sin((n + 1) * theta), 1e-12) << n + 1;
}

/// The largest error against the continuous closed form over a history.
double worst_error(const std::vector<std::pair<double, double>>& h) {
  double worst = 0.0;
  for (const auto& [t, u] : h)
    worst = std::max(worst, std::abs(u - kF / kK * (1.0 - std::cos(kW * t))));
  return worst;
}

TEST(VerificationDynamicSdof, HaftolSizesTheIncrements) {
  const JobResult loose = run_deck(sdof_deck(", HAFTOL=0.05", 0.01, 2.0 * kT));
  const JobResult tight = run_deck(sdof_deck(", HAFTOL=0.005", 0.01, 2.0 * kT));
  ASSERT_EQ(loose.exit_code, 0) << loose.error;
  ASSERT_EQ(tight.exit_code, 0) << tight.error;
  const auto hl = history(loose), ht = history(tight);
  EXPECT_NEAR(hl.back().first, 2.0 * kT, 1e-12);
  EXPECT_NEAR(ht.back().first, 2.0 * kT, 1e-12);
  double dt_min = 1e9, dt_max = 0.0;
  for (const IncrementInfo& i : loose.increments)
    if (i.converged) {
      dt_min = std::min(dt_min, i.dt);
      dt_max = std::max(dt_max, i.dt);
    }
  EXPECT_GT(dt_max, 1.2 * dt_min); // the increments adapt
  int repeated = 0;
  for (const IncrementInfo& i : loose.increments) repeated += i.deltmx_exceeded;
  EXPECT_GT(repeated, 0);
  EXPECT_GT(ht.size(), 2 * hl.size());
  std::printf("HAFTOL 0.05: %zu increments, worst %.4g; 0.005: %zu, worst %.4g\n", hl.size(),
              worst_error(hl), ht.size(), worst_error(ht));
  EXPECT_LT(worst_error(hl), 0.12 * kF / kK);
  EXPECT_LT(worst_error(ht), 0.02 * kF / kK);
}

/// The SDOF in two dynamic steps (the second continues the motion), restart data written.
std::string two_steps(const std::string& restart, bool model) {
  std::string d = sdof_deck(", DIRECT", kT / 40.0, kT / 2.0);
  d.insert(d.find("*STEP"), restart + "\n");
  d += "*STEP\n*DYNAMIC, DIRECT\n" + std::to_string(kT / 40.0) + ", " + std::to_string(kT) +
       "\n*NODE PRINT, FREQUENCY=1\nU\n*END STEP\n";
  if (model) return d;
  return "*HEADING\ncontinued\n*RESTART, READ, STEP=1\n" + d.substr(d.rfind("*STEP"));
}

// A restart record carries the velocities, accelerations and HHT's history: resuming after step 1
// gives step 2 to the last digit of the uninterrupted run.
TEST(VerificationDynamicSdof, RestartCarriesTheMotion) {
  const JobResult whole = run_deck(two_steps("*RESTART, WRITE, FREQUENCY=1", true), true, "old");
  ASSERT_EQ(whole.exit_code, 0) << whole.error;
  JobOptions o;
  o.deck = test::write_deck(two_steps("", false), "new");
  o.oldjob = (o.deck.parent_path() / "old.res").string();
  o.quiet = true;
  const JobResult resumed = run_job(o);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.error;
  const double a = test::U(whole, test::last_frame(whole, 2), 2)[0];
  const double b = test::U(resumed, test::last_frame(resumed, 2), 2)[0];
  EXPECT_NE(a, 0.0);
  EXPECT_EQ(a, b);
}

// V and A as node output (*NODE PRINT U, V, A): the frames hold the increment's end values.
// The trapezoidal rule's discrete solution by hand, from rest with a_0 = F/m: the equation of
// motion holds at every t_n, so a_n = (F - k u_n) / m = F/m cos(n theta). With v_n = C sin(n theta)
// Newmark's velocity update v_{n+1} - v_n = dt/2 (a_n + a_{n+1}) reads
//   2 C cos((n + 1/2) theta) sin(theta/2) = dt F/m cos((n + 1/2) theta) cos(theta/2),
// so C = (F/m) (dt/2) / tan(theta/2) = F / (m w) = (F/k) w, as tan(theta/2) = w dt / 2; the
// displacement update u_{n+1} - u_n = dt/2 (v_n + v_{n+1}) gives the same C, and v_0 = 0:
//   v_n = (F/k) w sin(n theta),   a_n = (F/m) cos(n theta).
TEST(VerificationDynamicSdof, VelocityAndAccelerationOutputAsTheTrapezoidalClosedForm) {
  const double dt = kT / 40.0;
  const JobResult r = run_deck(sdof_deck(", DIRECT, ALPHA=0.", dt, kT, "U, V, A"), true);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const double theta = 2.0 * std::atan(kW * dt / 2.0);
  const NodeId tip = r.model->mesh.find_node(2);
  int n = 0;
  for (const Frame& f : r.frames) {
    if (f.increment == 0) continue;
    ++n;
    ASSERT_EQ(f.nodes.V.size(), f.nodes.U.size());
    ASSERT_EQ(f.nodes.A.size(), f.nodes.U.size());
    EXPECT_NEAR(f.nodes.V[tip][0], kF / kK * kW * std::sin(n * theta), 1e-9 * kF / kK * kW)
        << "increment " << n;
    EXPECT_NEAR(f.nodes.A[tip][0], kF / kM * std::cos(n * theta), 1e-9 * kF / kM)
        << "increment " << n;
    for (int c : {1, 2}) {
      EXPECT_EQ(f.nodes.V[tip][c], 0.0);
      EXPECT_EQ(f.nodes.A[tip][c], 0.0);
    }
  }
  EXPECT_EQ(n, 40);
  // job.dat: a V and an A table after U's, Abaqus's column names
  const std::string dat = test::slurp(test::test_dir() / "job.dat");
  EXPECT_NE(dat.find("NODE FOOT-   V1          V2          V3"), std::string::npos);
  EXPECT_NE(dat.find("NODE FOOT-   A1          A2          A3"), std::string::npos);
  // the JSON frames carry them beside U
  const std::string json = test::slurp(test::test_dir() / "job.results.json");
  EXPECT_NE(json.find("\"V\":["), std::string::npos);
  EXPECT_NE(json.find("\"A\":["), std::string::npos);
}

TEST(VerificationDynamicSdof, VelocityAndAccelerationOutputFollowHht) {
  const double dt = kT / 50.0;
  const JobResult r = run_deck(sdof_deck(", DIRECT", dt, kT, "V, A"));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto oracle = hht_motion_by_hand(-0.05, dt, 50);
  const NodeId tip = r.model->mesh.find_node(2);
  std::size_t n = 0;
  for (const Frame& f : r.frames) {
    if (f.increment == 0) continue;
    ASSERT_LT(n, oracle.size());
    EXPECT_NEAR(f.nodes.V[tip][0], oracle[n].v, 1e-9 * kF / kK * kW) << "increment " << n + 1;
    EXPECT_NEAR(f.nodes.A[tip][0], oracle[n].a, 1e-9 * kF / kM) << "increment " << n + 1;
    ++n;
  }
  EXPECT_EQ(n, oracle.size());
}

TEST(VerificationDynamicSdof, VelocityRequestedInAStaticStepIsAWarning) {
  // the same bar loaded statically: V and A are not there; one warning, nothing written for them
  std::string deck = sdof_deck(", DIRECT, ALPHA=0.", 0.5, 1.0, "U, V, A");
  deck.replace(deck.find("*DYNAMIC, DIRECT, ALPHA=0."), 26, "*STATIC, DIRECT");
  deck.replace(deck.find("*END STEP"), 9,
               "*NODE FILE\nU, V\n*OUTPUT, FIELD\n*NODE OUTPUT\nU, A\n*END STEP");
  const JobResult r = run_deck(deck, true);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  int warned = 0;
  for (const std::string& w : r.model->warnings)
    if (w.find("output of dynamic steps") != std::string::npos) {
      ++warned;
      EXPECT_NE(w.find("V, A are output of dynamic steps; step 1 is *STATIC: not written"),
                std::string::npos)
          << w;
    }
  EXPECT_EQ(warned, 1);
  const Frame& f = test::last_frame(r);
  EXPECT_TRUE(f.nodes.V.empty());
  EXPECT_TRUE(f.nodes.A.empty());
  EXPECT_NEAR(test::U(r, f, 2)[0], kF / kK, 1e-12);
  const std::string dat = test::slurp(test::test_dir() / "job.dat");
  EXPECT_NE(dat.find("U1"), std::string::npos);
  EXPECT_EQ(dat.find("V1"), std::string::npos);
  EXPECT_EQ(dat.find("A1"), std::string::npos);
  EXPECT_EQ(dat.find("NOTHING TO PRINT"), std::string::npos);
  const std::string frd = test::slurp(test::test_dir() / "job.frd");
  EXPECT_NE(frd.find("DISP"), std::string::npos);
  EXPECT_EQ(frd.find("VELO"), std::string::npos);
  const std::string vtu = test::slurp(test::test_dir() / "job_1_2.vtu");
  EXPECT_NE(vtu.find("Name=\"U\""), std::string::npos);
  EXPECT_EQ(vtu.find("Name=\"A\""), std::string::npos);
}

} // namespace
} // namespace gapfem
