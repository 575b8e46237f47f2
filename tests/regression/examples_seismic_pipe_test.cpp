// Regression tests of examples/05_seismic_pipe (README.md there): the example deck and its three
// companion decks, run in-process as shipped, against the closed forms the README states.
//
// Smooth step 0 -> A over [0, T1] (Abaqus *AMPLITUDE, DEFINITION=SMOOTH STEP), xi = t/T1:
//   a = A s(xi), s = xi^3 (10 - 15 xi + 6 xi^2); its integrals from rest
//   v = A T1 S1(xi), S1 = xi^4 (5/2 - 3 xi + xi^2);  u = A T1^2 S2(xi), S2 = xi^5 (1/2 - xi/2 +
//   xi^2/7) and after T1: a = A, v = A (T1/2 + q), u = A (T1^2/7 + T1 q/2 + q^2/2), q = t - T1.
//
// Sliding threshold (sliding_threshold.inp): a mass m on a rest with Coulomb friction mu under
// gravity, the ground accelerated horizontally by a(t) (smooth step 0 -> 0.6 g over 2 s). While it
// sticks the mass moves with the ground, so the friction force is m a(t); it can give at most
// mu N = mu m g, so slip starts when a(t) = mu g: s(xi) = 1/2, xi = 1/2 (s is odd about 1/2),
// t* = 1 s. From then the friction force is mu m g (forward), the mass accelerates at mu g, and
// the slip (ground minus mass) is
//   delta(t) = u(t) - u(t*) - v(t*) (t - t*) - mu g (t - t*)^2 / 2.
// Lift-off (lift_off.inp): the ground accelerated vertically by a_z(t) (0 -> -1.5 g). In contact
// the mass rides with the ground: N = m (g + a_z), zero when a_z = -g: s(xi_L) = 2/3, t_L =
// 1.18174 s. Then the mass flies freely from the ground's position and velocity at t_L and the
// clearance is z_mass - z_ground = u_z(t_L) + v_z(t_L)(t - t_L) - g (t - t_L)^2/2 - u_z(t).
#include "test_util.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

using namespace gapfem;
using namespace gapfem::test;

namespace {

constexpr double kG = 9.81;

JobResult run_example05(const std::string& deck) {
  JobOptions o;
  o.deck = std::filesystem::path(GAPFEM_SOURCE_DIR) / "examples/05_seismic_pipe" / deck;
  o.write_files = false;
  o.quiet = true;
  JobResult r = run_job(o);
  EXPECT_TRUE(r.run.warnings.empty()) << deck << ": " << r.run.warnings.front();
  return r;
}

struct Motion {
  double u, v, a;
};
/// The smooth step 0 -> A over [0, T1] and its integrals from rest (header comment).
Motion smooth_step(double A, double T1, double t) {
  if (t >= T1) {
    const double q = t - T1;
    return {A * (T1 * T1 / 7 + T1 * q / 2 + q * q / 2), A * (T1 / 2 + q), A};
  }
  const double x = t / T1;
  return {A * T1 * T1 * std::pow(x, 5) * (0.5 - x / 2 + x * x / 7),
          A * T1 * std::pow(x, 4) * (2.5 - 3 * x + x * x),
          A * x * x * x * (10 - 15 * x + 6 * x * x)};
}

/// The value of history column `name` in increment `i` (NaN when absent).
double hist(const IncrementInfo& i, const std::string& name) {
  if (!i.history_columns) return std::nan("");
  for (std::size_t k = 0; k < i.history_columns->size(); ++k)
    if ((*i.history_columns)[k] == name) return i.history[k];
  return std::nan("");
}

/// The increments of step `step` with history output.
std::vector<const IncrementInfo*> history_of(const JobResult& r, int step) {
  std::vector<const IncrementInfo*> out;
  for (const IncrementInfo& i : r.increments)
    if (i.step == step && i.converged && i.history_columns) out.push_back(&i);
  return out;
}

/// The force a gap exerts on its first node (the pipe), in global components: the normal force
/// against the closing direction, and the friction force (GapRecord::friction_force is the
/// force on the second node, the ground, in t1, t2: the pipe takes its opposite).
Vec3 force_on_pipe(const GapRecord& g) {
  Vec3 f{};
  for (int k = 0; k < 3; ++k)
    f[k] = -g.normal_force * g.direction[k] - g.friction_force[0] * g.t1[k] -
           g.friction_force[1] * g.t2[k];
  return f;
}

// The pipe: 4-inch (114.3 x 6.02 mm), rho = 7850; the centreline of the L (8 m, an elbow of four
// chords of R = 0.1524, 6 m) as make_deck.py builds it.
double pipe_weight() {
  const double ro = 0.1143 / 2, ri = ro - 0.00602, R = 0.1524, pi = std::numbers::pi;
  const double L = (8.0 - R) + 4 * 2 * R * std::sin(pi / 16) + (6.0 - R);
  return 7850.0 * kG * pi * (ro * ro - ri * ri) * L;
}

/// The exact double integral of a piecewise-linear record sampled every dt from rest.
Motion integrate_record(const std::filesystem::path& file, double dt, double t_end) {
  std::ifstream in(file);
  std::vector<double> a;
  std::string line;
  while (std::getline(in, line)) {
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream ss(line);
    for (double x; ss >> x;) a.push_back(x);
  }
  double u = 0, v = 0;
  for (std::size_t i = 0; i + 1 < a.size() && (i + 1) * dt <= t_end + 1e-12; ++i) {
    u += v * dt + dt * dt * (a[i] / 3 + a[i + 1] / 6);
    v += dt * (a[i] + a[i + 1]) / 2;
  }
  const double t_rec = (a.size() - 1) * dt; // the record holds its last value (zero) after it
  if (t_end > t_rec) u += v * (t_end - t_rec) + a.back() * (t_end - t_rec) * (t_end - t_rec) / 2;
  return {u, v, a.back()};
}

} // namespace

// The example: gravity, then the three-component accelerogram as base motion.
TEST(RegressionExamples, SeismicPipeWeightBaseMotionAndHistories) {
  const JobResult r = run_example05("seismic_pipe.inp");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  ASSERT_EQ(r.steps.size(), 2u);
  const double W = pipe_weight();
  ASSERT_NEAR(W, 2197.25, 0.01);

  // WEIGHT: rests (gap forces) and anchors (RF) carry the weight: the step's reaction sum equals
  // rho g A L to 1e-9 (the static step is linear: hard gaps are exact rows; measured 1e-13).
  const Frame& f1 = last_frame(r, 1);
  EXPECT_NEAR(r.steps[0].checks.reaction_sum[2], W, 1e-9 * W);
  double carried = 0.0;
  for (Label e = 201; e <= 206; ++e) {
    EXPECT_NE(gap(r, f1, e).status, ContactStatus::Open) << e;
    carried += gap(r, f1, e).normal_force;
  }
  EXPECT_NEAR(carried + RF(r, f1, 1)[2] + RF(r, f1, 33)[2], W, 1e-9 * W);
  for (Label e = 301; e <= 303; ++e) EXPECT_EQ(gap(r, f1, e).status, ContactStatus::Open) << e;

  // EARTHQUAKE: every increment converged (2000 of 0.0025 s); the ground (a support's ground
  // node) is where the exact integrals of the piecewise-linear record put it, to rounding.
  EXPECT_TRUE(r.steps[1].converged);
  EXPECT_EQ(r.steps[1].increments, 2000);
  const Frame& f2 = last_frame(r, 2);
  const auto dir = std::filesystem::path(GAPFEM_SOURCE_DIR) / "examples/05_seismic_pipe";
  const char* comps[] = {"accelerogram_x.txt", "accelerogram_y.txt", "accelerogram_z.txt"};
  for (int k = 0; k < 3; ++k) {
    const Motion m = integrate_record(dir / comps[k], 0.01, 5.0);
    EXPECT_NEAR(U(r, f2, 101)[k], m.u, 1e-9 * (1 + std::abs(m.u))) << k;
    // baseline-corrected: the ground ends at rest (samples rounded to 1e-6 m/s^2: 400 of them
    // over 0.01 s leave at most 4e-6 m/s; measured 5e-8)
    EXPECT_NEAR(m.v, 0.0, 4e-6);
  }
  // History output: U at the elbow's middle node, S of rest 204 and of the three guides (15
  // curves: the report draws up to 16), every fourth increment and the last; energies every
  // increment.
  const auto h = history_of(r, 2);
  ASSERT_EQ(h.size(), 500u);
  ASSERT_EQ(h.back()->history_columns->size(), 15u);
  EXPECT_FALSE(std::isnan(hist(*h.back(), "U1 at node 17")));
  double max_rest = 0.0, min_rest = 1e300, max_guide = 0.0;
  int guide_contacts = 0;
  for (const IncrementInfo* i : h) {
    max_rest = std::max(max_rest, hist(*i, "S11 at element 204"));
    min_rest = std::min(min_rest, hist(*i, "S11 at element 204"));
    for (int e : {301, 302, 303}) {
      const double s = hist(*i, "S11 at element " + std::to_string(e));
      max_guide = std::max(max_guide, s);
      guide_contacts += s > 0.0;
    }
  }
  // the vertical shaking (0.3 g) varies the rest's force about its static value, and it stays in
  // contact (the vertical ground acceleration never reaches -g)
  EXPECT_GT(max_rest * 0.01, 1.2 * gap(r, f1, 204).normal_force);
  EXPECT_GT(min_rest, 0.0);
  // the pipe hits its 1 mm guides (PTFE rests let it move): impacts, each a plastic one whose
  // kinetic energy loss is ALLKL (docs/theory/dynamics.md §5); a guide's force at an impact is
  // of the order of the pipe's weight or more (measured peak 1.2 kN)
  EXPECT_GT(guide_contacts, 10);
  EXPECT_GT(max_guide * 0.01, 0.1 * W);
  // HHT (MODERATE DISSIPATION) never gains energy: ETOTAL falls from 0; the impacts' loss is
  // reported (ALLKL > 0)
  ASSERT_TRUE(r.increments.back().energies.has_value());
  double e_scale = 0.0;
  for (const IncrementInfo& i : r.increments)
    if (i.step == 2 && i.energies) e_scale = std::max(e_scale, i.energies->scale());
  const Energies& e = *r.increments.back().energies;
  EXPECT_LE(e.etotal(), 1e-9 * e_scale);
  EXPECT_GT(e.allkl, 0.01 * e_scale);
  EXPECT_GT(e_scale, 1.0);
}

// Rigid shake: the L without anchors on its rests, the ground accelerated in x by a smooth step to
// a0 = 0.1 g (< mu g: the rests stick) over 1 s, then held. Newton's second law for the whole pipe
// (it moves with the ground once the smooth step is over): the supports' forces on the pipe sum
// to (m a0, 0, W). The residual vibration of the pipe on its rests' stick springs after the step
// is the only deviation: measured 2.6e-3 m a0 in x and 2.5e-4 m a0 in y at t >= 1.5 s; tolerance
// 5e-3 m a0 (twice that), 1e-6 W vertically. A wrong mass or support force is off by far more
// (the reactions at the driven DOFs are off by a factor 1.7: the disabled test below).
TEST(RegressionExamples, SeismicPipeRigidShakeSupportsCarryMassTimesAcceleration) {
  const JobResult r = run_example05("rigid_shake.inp");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const double W = pipe_weight(), m = W / kG, a0 = 0.1 * kG;
  int checked = 0;
  for (const Frame& f : r.frames) {
    if (f.step != 2 || f.step_time < 1.5) continue;
    Vec3 sum{};
    for (Label e : {201, 202, 203, 204, 205, 206, 301, 302, 303}) {
      const GapRecord& g = gap(r, f, e);
      EXPECT_NE(g.status, ContactStatus::Slip) << e;
      const Vec3 fe = force_on_pipe(g);
      for (int k = 0; k < 3; ++k) sum[k] += fe[k];
    }
    EXPECT_NEAR(sum[0], m * a0, 5e-3 * m * a0) << f.step_time;
    EXPECT_NEAR(sum[1], 0.0, 5e-3 * m * a0) << f.step_time;
    EXPECT_NEAR(sum[2], W, 1e-6 * W) << f.step_time;
    ++checked;
  }
  EXPECT_GE(checked, 3);
}

// The same through the reactions at the driven DOFs (the ground nodes are massless: the reactions
// are the gap forces; they were reported scaled by 1/(1 + alpha) in HHT steps, 1.7071 m a0 with
// MODERATE DISSIPATION, until StepProblem::reactions took HHT's weights out); the step end's
// leftover vibration as above.
TEST(RegressionExamples, SeismicPipeRigidShakeReactionsSumToMassTimesAcceleration) {
  const JobResult r = run_example05("rigid_shake.inp");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const double W = pipe_weight(), m = W / kG, a0 = 0.1 * kG;
  EXPECT_NEAR(r.steps[1].checks.reaction_sum[0], m * a0, 5e-3 * m * a0);
  EXPECT_NEAR(r.steps[1].checks.reaction_sum[2], W, 1e-6 * W);
}

// Sliding threshold: closed forms in the header comment (m = 50, mu = 0.3, A = 0.6 g, T1 = 2).
TEST(RegressionExamples, SeismicPipeSlidingStartsWhenGroundAccelerationExceedsMuG) {
  const JobResult r = run_example05("sliding_threshold.inp");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const double m = 50.0, mu = 0.3, A = 0.6 * kG, T1 = 2.0, ts = 1.0, area = 0.01;
  const Motion at_s = smooth_step(A, T1, ts);
  double first_slip = -1.0;
  int n = 0;
  for (const IncrementInfo* i : history_of(r, 2)) {
    const double t = i->step_time;
    const Motion g = smooth_step(A, T1, t);
    const double N = hist(*i, "S11 at element 11") * area;
    const double F = -hist(*i, "S12 at element 11") * area; // forward on the mass
    EXPECT_NEAR(N, m * kG, 1e-9 * m * kG) << t;
    // the ground's A output is the prescribed acceleration
    EXPECT_NEAR(hist(*i, "A1 at node 2"), g.a, 1e-12) << t;
    const bool slipping = F >= mu * N * (1 - 1e-9);
    if (slipping && first_slip < 0) first_slip = t;
    if (std::abs(t - ts) < 1e-9) continue; // a(t*) = mu g exactly: either status
    if (t < ts) {
      // stick: friction = m a(t); the stick spring's transient (measured 3.3e-3 N, 2.2e-5 of
      // mu m g) within 5e-5 mu m g
      EXPECT_FALSE(slipping) << t;
      EXPECT_NEAR(F, m * g.a, 5e-5 * mu * m * kG) << t;
    } else {
      // slip: friction = mu N, the slip as the closed form; the onset inside an increment of
      // 0.005 s and the stick spring's elastic slip (5e-6 m) bound the error: 1e-4 m
      // (measured 5e-5 m over 2.14 m)
      EXPECT_TRUE(slipping) << t;
      const double q = t - ts;
      const double delta = g.u - at_s.u - at_s.v * q - mu * kG * q * q / 2;
      EXPECT_NEAR(-hist(*i, "E12 at element 11"), delta, 1e-4) << t;
    }
    ++n;
  }
  EXPECT_EQ(n, 499); // 500 increments less the one at t*
  EXPECT_NEAR(first_slip, ts + 0.005, 1e-9) << "the first increment end after t* = 1 s";
}

// Lift-off: closed forms in the header comment (m = 50, A = -1.5 g, T1 = 2).
TEST(RegressionExamples, SeismicPipeLiftOffWhenGroundFallsFasterThanG) {
  const JobResult r = run_example05("lift_off.inp");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const double m = 50.0, A = -1.5 * kG, T1 = 2.0, area = 0.01;
  double lo = 0, hi = 1; // s(xi) = 2/3 by bisection
  for (int k = 0; k < 100; ++k) {
    const double mid = (lo + hi) / 2;
    (smooth_step(A, T1, mid * T1).a > -kG ? lo : hi) = mid;
  }
  const double tl = lo * T1;
  ASSERT_NEAR(tl, 1.18174, 1e-5);
  const Motion at_l = smooth_step(A, T1, tl);
  double first_open = -1.0;
  for (const IncrementInfo* i : history_of(r, 2)) {
    const double t = i->step_time;
    const Motion g = smooth_step(A, T1, t);
    const double N = hist(*i, "S11 at element 11") * area, h = hist(*i, "E11 at element 11");
    if (N == 0.0 && first_open < 0) first_open = t;
    if (t < tl) {
      // N = m (g + a_z): measured 7e-3 N of 490 N (HHT's start transient); 1e-4 m g
      EXPECT_NEAR(N, m * (kG + g.a), 1e-4 * m * kG) << t;
      EXPECT_NEAR(h, 0.0, 1e-12) << t;
    } else {
      EXPECT_EQ(N, 0.0) << t;
      const double q = t - tl;
      const double z = at_l.u + at_l.v * q - kG * q * q / 2 - g.u;
      // the lift-off inside an increment of 0.005 s: measured 1.2e-4 m over 2.9 m; 1e-3 m
      EXPECT_NEAR(h, z, 1e-3) << t;
    }
  }
  EXPECT_NEAR(first_open, 1.185, 1e-9) << "the first increment end after t_L";
}
