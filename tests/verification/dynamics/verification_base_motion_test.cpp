// Base motion (*BOUNDARY, TYPE=VELOCITY|ACCELERATION; docs/theory/dynamics.md, "Base motion").
//
// The oscillator: a T3D2 bar (k = EA/L = 500) whose mass is lumped at its ends (m = 0.5 each,
// no coupling between them), node 1 the support, node 2 the mass; w = sqrt(k/m) = sqrt(1000).
//
// Harmonic base excitation from rest: the support's acceleration a_g = A cos(W t) (A = 2,
// W = 0.6 w), so its velocity is (A/W) sin(W t) and its displacement (A/W^2)(1 - cos(W t)).
// The relative displacement z = u2 - u1 obeys m z'' + k z = -m a_g, z(0) = z'(0) = 0:
//   z(t) = C (cos(W t) - cos(w t)),   C = -A / (w^2 - W^2)     (steady + transient).
// - The trapezoidal rule (ALPHA=0) is the trapezoidal rule on the first-order system, i.e. the
//   bilinear map s -> (2/dt) tan. It integrates the mass, m u2'' + k u2 = k u_g(t_n), with the
//   support's exact u_g = (A/W^2)(1 - cos W t) at the increment ends: the constant part gives
//   A/W^2, the cosine -(A/W^2) w^2/(w^2 - Wd^2) cos(W t_n), and u2(0) = 0 the free term
//   D cos(wd t_n) (the discrete velocity of every term is a sine, zero at t = 0); so exactly
//   z_n = u2_n - u_g(t_n) = Cd (cos(W t_n) - cos(wd t_n)),  Cd = -A (Wd/W)^2 / (w^2 - Wd^2),
//   wd = (2/dt) atan(w dt/2) (the period error), Wd = (2/dt) tan(W dt/2): to 1e-9 of |C|.
// - Against the continuous z(t): |z_n - z(t_n)| <= |Cd - C| 2 + |C| |wd - w| t_n (the period
//   error; cos is 1-Lipschitz); the test takes this bound (plus 1e-12).
// - TRANSIENT FIDELITY (HHT, alpha = -0.05) against the continuous z(t): the period error at most
//   twice the trapezoidal rule's (|alpha| small) and HHT's numerical damping ratio
//   -alpha w dt / 2 (Hilber, Hughes and Taylor 1977, small w dt) acting on the transient term:
//   tol = |C| (2 |wd - w| t + 2 |Cd - C| / |C| + |alpha| w dt w t / 2).
// - TYPE=VELOCITY with the velocity amplitude and TYPE=DISPLACEMENT with the displacement
//   amplitude (PERIODIC both) drive the same support motion: the histories agree to 1e-8 of |C|.
// Rigid motion: the support node with its lumped mass, driven by TYPE=ACCELERATION with a SMOOTH
// STEP from 0 to a1 over [0, T1] and held: u = a1 T1^2 S2(xi), v = a1 T1 S1(xi), a = a1 s(xi), xi =
// t/T1, with s = xi^3 (10 - 15 xi + 6 xi^2), S1 = xi^4 (5/2 - 3 xi + xi^2), S2 = xi^5 (1/2 - xi/2 +
// xi^2/7); after T1: a = a1, v = a1 (T1/2 + (t - T1)), u = a1 (T1^2/7 + T1 (t - T1)/2 + (t - T1)^2
// / 2). U, V and A of the node are these to 1e-12 (exact integration; rounding only).
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <numbers>

namespace gapfem {
namespace {

using test::run_deck;

constexpr double kK = 500.0, kM = 0.5, kA = 2.0;
const double kW = std::sqrt(kK / kM);
const double kWg = 0.6 * kW;
const double kT = 2.0 * std::numbers::pi / kW;

/// The oscillator with its support driven by `bc` (a *BOUNDARY block with its amplitude).
std::string base_deck(const std::string& amplitude, const std::string& bc, const std::string& dyn,
                      double dt, double period) {
  return fmt::format(R"(*HEADING
SDOF on a moving support
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
1, 2, 3
2, 2, 3
{}
*STEP, INC=100000
*DYNAMIC, DIRECT{}
{}, {}
{}
*NODE PRINT, FREQUENCY=1
U, V, A
*END STEP
)",
                     amplitude, dyn, dt, period, bc);
}

/// The support's motion as PERIODIC amplitudes (N = 1, omega = W, t0 = 0, A0; A1, B1).
std::string periodic(const char* name, double a0, double a1, double b1) {
  return fmt::format("*AMPLITUDE, NAME={}, DEFINITION=PERIODIC\n1, {:.17g}, 0., {:.17g}\n{:.17g}, "
                     "{:.17g}\n",
                     name, kWg, a0, a1, b1);
}
const std::string kAcc = periodic("ACC", 0.0, kA, 0.0);                              // A cos
const std::string kVel = periodic("VEL", 0.0, 0.0, kA / kWg);                        // (A/W) sin
const std::string kDisp = periodic("DIS", kA / (kWg * kWg), -kA / (kWg * kWg), 0.0); // 1 - cos

struct Sample {
  double t, z, u1, v1, a1;
};

std::vector<Sample> samples(const JobResult& r) {
  std::vector<Sample> out;
  for (const Frame& f : r.frames) {
    if (f.increment == 0) continue;
    const LocalIndex n1 = r.model->mesh.find_node(1);
    out.push_back({f.step_time, test::U(r, f, 2)[0] - test::U(r, f, 1)[0], f.nodes.U[n1][0],
                   f.nodes.V.at(n1)[0], f.nodes.A.at(n1)[0]});
  }
  return out;
}

const double kC = -kA / (kW * kW - kWg * kWg);
double z_exact(double t) {
  return kC * (std::cos(kWg * t) - std::cos(kW * t));
}

TEST(VerificationBaseMotion, HarmonicBaseAccelerationAsTheTrapezoidalClosedForm) {
  const double dt = kT / 100.0;
  const JobResult r =
      run_deck(base_deck(kAcc, "*BOUNDARY, TYPE=ACCELERATION, AMPLITUDE=ACC\n1, 1, 1, 1.",
                         ", ALPHA=0.", dt, 2.0 * kT));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto s = samples(r);
  ASSERT_EQ(s.size(), 200u);
  const double wd = 2.0 / dt * std::atan(kW * dt / 2.0), Wd = 2.0 / dt * std::tan(kWg * dt / 2.0);
  const double Cd = -kA * (Wd / kWg) * (Wd / kWg) / (kW * kW - Wd * Wd);
  double worst = 0.0;
  for (const Sample& x : s) {
    EXPECT_NEAR(x.z, Cd * (std::cos(kWg * x.t) - std::cos(wd * x.t)), 1e-9 * std::abs(kC)) << x.t;
    const double bound = 2.0 * std::abs(Cd - kC) + std::abs(kC) * std::abs(wd - kW) * x.t + 1e-12;
    EXPECT_NEAR(x.z, z_exact(x.t), bound) << x.t;
    worst = std::max(worst, std::abs(x.z - z_exact(x.t)) / std::abs(kC));
    // the support follows the exact integrals of its acceleration; V and A are the prescribed
    EXPECT_NEAR(x.u1, kA / (kWg * kWg) * (1.0 - std::cos(kWg * x.t)), 1e-12);
    EXPECT_NEAR(x.v1, kA / kWg * std::sin(kWg * x.t), 1e-12);
    EXPECT_NEAR(x.a1, kA * std::cos(kWg * x.t), 1e-12);
  }
  RecordProperty("worst_relative_error", fmt::format("{:.3e}", worst));
}

TEST(VerificationBaseMotion, TransientFidelityWithinHhtsPeriodErrorAndDamping) {
  const double dt = kT / 100.0, alpha = 0.05;
  const JobResult r = run_deck(base_deck(
      kAcc, "*BOUNDARY, TYPE=ACCELERATION, AMPLITUDE=ACC\n1, 1, 1, 1.", "", dt, 2.0 * kT));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const double wd = 2.0 / dt * std::atan(kW * dt / 2.0), Wd = 2.0 / dt * std::tan(kWg * dt / 2.0);
  const double Cd = -kA * (Wd / kWg) * (Wd / kWg) / (kW * kW - Wd * Wd);
  for (const Sample& x : samples(r)) {
    const double tol =
        std::abs(kC) * (2.0 * std::abs(wd - kW) * x.t + 2.0 * std::abs(Cd - kC) / std::abs(kC) +
                        alpha * kW * dt * kW * x.t / 2.0);
    EXPECT_NEAR(x.z, z_exact(x.t), tol) << x.t;
  }
}

TEST(VerificationBaseMotion, VelocityAndDisplacementOfTheSameMotionGiveTheSameHistory) {
  const double dt = kT / 50.0;
  const JobResult acc = run_deck(base_deck(
      kAcc, "*BOUNDARY, TYPE=ACCELERATION, AMPLITUDE=ACC\n1, 1, 1, 1.", "", dt, 1.5 * kT));
  const JobResult vel = run_deck(
      base_deck(kVel, "*BOUNDARY, TYPE=VELOCITY, AMPLITUDE=VEL\n1, 1, 1, 1.", "", dt, 1.5 * kT));
  const JobResult dis =
      run_deck(base_deck(kDisp, "*BOUNDARY, AMPLITUDE=DIS\n1, 1, 1, 1.", "", dt, 1.5 * kT));
  for (const JobResult* r : {&acc, &vel, &dis}) ASSERT_EQ(r->exit_code, 0) << r->error;
  const auto a = samples(acc), v = samples(vel), d = samples(dis);
  ASSERT_EQ(a.size(), 75u);
  ASSERT_EQ(v.size(), a.size());
  ASSERT_EQ(d.size(), a.size());
  for (std::size_t n = 0; n < a.size(); ++n) {
    EXPECT_NEAR(v[n].z, a[n].z, 1e-8 * std::abs(kC)) << n;
    EXPECT_NEAR(d[n].z, a[n].z, 1e-8 * std::abs(kC)) << n;
    EXPECT_NEAR(v[n].v1, a[n].v1, 1e-10) << n; // the prescribed velocity in both
  }
}

TEST(VerificationBaseMotion, RigidMassFollowsTheSmoothStepsIntegralsExactly) {
  const double a1 = 3.0, T1 = 0.4, dt = 0.025;
  // the support of the oscillator (its lumped mass 0.5 rides on it) driven alone
  const std::string deck = base_deck(
      fmt::format("*AMPLITUDE, NAME=SS, DEFINITION=SMOOTH STEP\n0., 0., {}, 1.", T1),
      fmt::format("*BOUNDARY, TYPE=ACCELERATION, AMPLITUDE=SS\n1, 1, 1, {}", a1), "", dt, 0.6);
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  int n = 0;
  for (const Frame& f : r.frames) {
    if (f.increment == 0) continue;
    ++n;
    const double t = f.step_time;
    double u, v, a;
    if (t <= T1) {
      const double xi = t / T1;
      a = a1 * xi * xi * xi * (10.0 - 15.0 * xi + 6.0 * xi * xi);
      v = a1 * T1 * std::pow(xi, 4) * (2.5 - 3.0 * xi + xi * xi);
      u = a1 * T1 * T1 * std::pow(xi, 5) * (0.5 - 0.5 * xi + xi * xi / 7.0);
    } else {
      const double s = t - T1;
      a = a1;
      v = a1 * (T1 / 2.0 + s);
      u = a1 * (T1 * T1 / 7.0 + T1 * s / 2.0 + s * s / 2.0);
    }
    EXPECT_NEAR(test::U(r, f, 1)[0], u, 1e-12) << t;
    const LocalIndex n1 = r.model->mesh.find_node(1);
    EXPECT_NEAR(f.nodes.V.at(n1)[0], v, 1e-12) << t;
    EXPECT_NEAR(f.nodes.A.at(n1)[0], a, 1e-12) << t;
  }
  EXPECT_EQ(n, 24);
}

// TYPE=VELOCITY in a static step (Abaqus: applied at once, a STEP variation, without an
// amplitude): the support moves by u = v t and carries the bar along without force.
TEST(VerificationBaseMotion, VelocityInAStaticStepMovesBySpeedTimesTime) {
  std::string deck = base_deck("", "*BOUNDARY, TYPE=VELOCITY\n1, 1, 1, 0.3", "", 0.5, 2.0);
  deck.replace(deck.find("*DYNAMIC, DIRECT"), 16, "*STATIC, DIRECT");
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  int n = 0;
  for (const Frame& f : r.frames) {
    if (f.increment == 0) continue;
    ++n;
    EXPECT_NEAR(test::U(r, f, 1)[0], 0.3 * f.step_time, 1e-14);
    EXPECT_NEAR(test::U(r, f, 2)[0], 0.3 * f.step_time, 1e-12);
    EXPECT_NEAR(test::RF(r, f, 1)[0], 0.0, 1e-9);
  }
  EXPECT_EQ(n, 4);
}

// Propagation: step 1 drives v = V0 sin(W t) over T1; step 2 carries the condition over
// unchanged and holds the velocity reached, v1 = V0 sin(W T1) (u grows by v1 per unit time);
// step 3 sets the velocity to 0 without an amplitude: with the step's RAMP default the velocity
// goes linearly from v1 to 0 (u gains v1 (t - t^2 / (2 T3))), with STEP it is 0 at once.
TEST(VerificationBaseMotion, APropagatedVelocityHoldsItsEndValueAndARampStartsFromIt) {
  const double T1 = 0.3, T2 = 0.2, T3 = 0.2, dt = 0.01, V0 = kA / kWg;
  std::string deck =
      base_deck(kVel, "*BOUNDARY, TYPE=VELOCITY, AMPLITUDE=VEL\n1, 1, 1, 1.", "", dt, T1);
  deck += fmt::format("*STEP, INC=1000\n*DYNAMIC, DIRECT\n{}, {}\n*END STEP\n"
                      "*STEP, INC=1000\n*DYNAMIC, DIRECT\n{}, {}\n*BOUNDARY, TYPE=VELOCITY\n"
                      "1, 1, 1, 0.\n*END STEP\n",
                      dt, T2, dt, T3);
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const bool ramp = r.model->steps.at(2).ramp_default;
  const double v1 = V0 * std::sin(kWg * T1);
  const double u1 = V0 / kWg * (1.0 - std::cos(kWg * T1)), u2 = u1 + v1 * T2;
  const LocalIndex n1 = r.model->mesh.find_node(1);
  int checked = 0;
  for (const Frame& f : r.frames) {
    if (f.increment == 0 || f.step == 1) continue;
    const double t = f.step_time;
    double u, v;
    if (f.step == 2) {
      u = u1 + v1 * t;
      v = v1;
    } else {
      u = ramp ? u2 + v1 * (t - t * t / (2.0 * T3)) : u2;
      v = ramp ? v1 * (1.0 - t / T3) : 0.0;
    }
    EXPECT_NEAR(test::U(r, f, 1)[0], u, 1e-12) << f.step << " " << t;
    EXPECT_NEAR(f.nodes.V.at(n1)[0], v, 1e-12) << f.step << " " << t;
    ++checked;
  }
  EXPECT_EQ(checked, 40);
}

// HAFTOL (automatic increments: repeated increments and the half-step state) with base motion:
// the support stays on its exact integrals whatever the increments (1e-12), and the relative
// motion follows the closed form within 5 % of |C| (HAFTOL = 0.005 of a force amplitude
// m A = 1; measured: see the property).
TEST(VerificationBaseMotion, AutomaticIncrementsKeepTheSupportExact) {
  std::string deck = base_deck(kAcc, "*BOUNDARY, TYPE=ACCELERATION, AMPLITUDE=ACC\n1, 1, 1, 1.",
                               ", HAFTOL=0.005", kT / 100.0, 2.0 * kT);
  deck.replace(deck.find("*DYNAMIC, DIRECT"), 16, "*DYNAMIC");
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  double worst = 0.0;
  const auto s = samples(r);
  ASSERT_GT(s.size(), 20u);
  for (const Sample& x : s) {
    EXPECT_NEAR(x.u1, kA / (kWg * kWg) * (1.0 - std::cos(kWg * x.t)), 1e-12) << x.t;
    EXPECT_NEAR(x.v1, kA / kWg * std::sin(kWg * x.t), 1e-12) << x.t;
    EXPECT_NEAR(x.z, z_exact(x.t), 0.05 * std::abs(kC)) << x.t;
    worst = std::max(worst, std::abs(x.z - z_exact(x.t)) / std::abs(kC));
  }
  RecordProperty("increments", static_cast<int>(s.size()));
  RecordProperty("worst_relative_error", fmt::format("{:.3e}", worst));
}

} // namespace
} // namespace gapfem
