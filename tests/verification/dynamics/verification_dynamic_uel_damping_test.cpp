// A UEL's damping in a dynamic step (elements/user/uel_kernel.cpp, docs/theory/dynamics.md §8):
// the user element of uel/uel_spring_dashpot.f, a spring k and a dashpot c in parallel along x
// carrying the mass m at its free node (K for LFLAGS(3) = 1, 2; C = c [1 -1; -1 1] for
// LFLAGS(3) = 3; M = diag(0, m) for LFLAGS(3) = 4), node 1 fixed, released at x = 0 with the
// initial velocity v0 (*INITIAL CONDITIONS, TYPE=VELOCITY).
//
// Closed form (m x'' + c x' + k x = 0, x(0) = 0, x'(0) = v0): w = sqrt(k/m), zeta = c/(2 m w),
// wd = w sqrt(1 - zeta^2), x(t) = v0/wd exp(-zeta w t) sin(wd t).
// The trapezoidal rule (ALPHA=0: beta = 1/4, gamma = 1/2) applied to a linear system is the
// trapezoidal rule of the first-order form y' = A y, y = (x, x'), A = [0 1; -k/m -c/m]:
// y_n+1 = (I - h A/2)^-1 (I + h A/2) y_n, provided the start acceleration is the consistent
// a0 = -c v0 / m (INITIAL=YES with the damping force C v0 in R(0)). gapfem's history must equal
// this recurrence, advanced here by hand, to rounding: 1e-9 of the amplitude v0/w (one Newton
// iteration per linear increment, residual tolerance far below that). Against the continuous
// solution the rule's only error is its phase and decay error: its eigenvalues z = (1 + s h/2) /
// (1 - s h/2) have ln z = s h + (s h)^3/12 + ..., a relative error (w h)^2/12 in both the
// frequency and the decay rate, so |x_n - x(t_n)| <= 2 (w t_n)(w h)^2/12 v0/wd (phase error
// times amplitude, doubled for the decay-rate error of the same size); at h = T/100 over three
// periods that is 2.5 % of v0/wd.
// The effective tangent K + gamma/(beta h) C + M/(beta h^2) is the linear system's exact
// Jacobian, so each increment converges in one Newton iteration: a tangent without the UEL's
// damping would not (its residual after the first correction would be c v-sized).
// Energies (ALPHA=0, docs/theory/dynamics.md "Energies"): ETOTAL = ALLKE + ALLIE + ALLVD is
// constant = 1/2 m v0^2; ALLVD, the work of C v, equals the mechanical energy lost,
// 1/2 m v0^2 - ALLKE - ALLIE, to 1e-6 of the largest energy (measured ~1e-15), and grows.
// A UEL whose damping is zero (c = 0) follows the undamped recurrence, and one returning an
// infinite damping entry stops the run with one message naming the element and LFLAGS(3) = 3.
#include "test_util.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <numbers>

namespace gapfem {
namespace {

namespace fs = std::filesystem;

const fs::path kUelDir = fs::path(GAPFEM_TEST_DIR) / "verification" / "user" / "uel";

constexpr double kK = 500.0, kM = 0.5, kV0 = 1.0, kZeta = 0.05;
const double kW = std::sqrt(kK / kM);
const double kC = 2.0 * kZeta * kM * kW;
const double kT = 2.0 * std::numbers::pi / kW;

std::string deck(double c, double dt, double period, double bad = 0.0) {
  return fmt::format(R"(*HEADING
spring-dashpot UEL carrying a mass, released with an initial velocity
*NODE
1, 0., 0., 0.
2, 1., 0., 0.
*USER ELEMENT, TYPE=U5, NODES=2, COORDINATES=1, PROPERTIES=4, VARIABLES=1
1
*ELEMENT, TYPE=U5, ELSET=SD
1, 1, 2
*UEL PROPERTY, ELSET=SD
{}, {}, {}, {}
*BOUNDARY
1, 1
*INITIAL CONDITIONS, TYPE=VELOCITY
2, 1, {}
*STEP, INC=100000
*DYNAMIC, DIRECT, ALPHA=0.
{}, {}
*NODE PRINT, FREQUENCY=1
U, V
*END STEP
)",
                     kK, c, kM, bad, kV0, dt, period);
}

JobResult run(const std::string& text, const std::string& name) {
  JobOptions o;
  o.deck = test::write_deck(text, name);
  o.write_files = false;
  o.quiet = true;
  o.user_code = kUelDir / "uel_spring_dashpot.f";
  return run_job(o);
}

/// U1 of node 2 at the end of every increment.
std::vector<double> history(const JobResult& r) {
  std::vector<double> h;
  const NodeId n = r.model->mesh.find_node(2);
  for (const Frame& f : r.frames)
    if (f.increment > 0) h.push_back(f.nodes.U.at(n)[0]);
  return h;
}

/// The trapezoidal recurrence by hand from x = 0, x' = v0.
std::vector<double> trapezoidal(double c, double h, std::size_t count) {
  Eigen::Matrix2d A;
  A << 0.0, 1.0, -kK / kM, -c / kM;
  const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
  const Eigen::Matrix2d S = (I - 0.5 * h * A).inverse() * (I + 0.5 * h * A);
  Eigen::Vector2d y(0.0, kV0);
  std::vector<double> x;
  for (std::size_t n = 0; n < count; ++n) {
    y = S * y;
    x.push_back(y[0]);
  }
  return x;
}

TEST(DynamicUelDamping, FreeDecayFollowsTheDampedClosedForm) {
  const double h = kT / 100.0;
  const JobResult r = run(deck(kC, h, 3.0 * kT), "uel_damped");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto x = history(r);
  ASSERT_EQ(x.size(), 300u);
  const auto ref = trapezoidal(kC, h, x.size());
  const double amplitude = kV0 / kW, wd = kW * std::sqrt(1.0 - kZeta * kZeta);
  double worst = 0.0;
  for (std::size_t n = 0; n < x.size(); ++n) {
    EXPECT_NEAR(x[n], ref[n], 1e-9 * amplitude) << n;
    const double t = h * static_cast<double>(n + 1);
    const double exact = kV0 / wd * std::exp(-kZeta * kW * t) * std::sin(wd * t);
    const double bound = 2.0 * kW * t * (kW * h) * (kW * h) / 12.0 * kV0 / wd;
    EXPECT_LE(std::abs(x[n] - exact), bound) << n;
    worst = std::max(worst, std::abs(x[n] - exact) / (kV0 / wd));
  }
  // the damping acts: the third period's peak, near t = 2.25 T, is exp(-zeta w 2.25 T) = 0.49 of
  // the undamped amplitude (0.494 v0/wd; 1 without damping)
  double last_peak = 0.0;
  for (std::size_t n = 200; n < x.size(); ++n) last_peak = std::max(last_peak, std::abs(x[n]));
  EXPECT_GT(last_peak, 0.47 * kV0 / wd);
  EXPECT_LT(last_peak, 0.51 * kV0 / wd);
  for (const IncrementInfo& i : r.increments) EXPECT_EQ(i.iterations, 1) << i.increment;
  std::printf("largest deviation from the continuous solution: %.3g of v0/wd\n", worst);
}

TEST(DynamicUelDamping, ViscousDissipationIsTheMechanicalEnergyLost) {
  const double h = kT / 100.0;
  const JobResult r = run(deck(kC, h, 3.0 * kT), "uel_energy");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const double e0 = 0.5 * kM * kV0 * kV0;
  double largest = 0.0, previous = 0.0, worst = 0.0;
  int frames = 0;
  for (const Frame& f : r.frames) {
    if (f.increment <= 0 || !f.energies) continue;
    largest = std::max(largest, f.energies->scale());
  }
  ASSERT_GT(largest, 0.0);
  for (const Frame& f : r.frames) {
    if (f.increment <= 0 || !f.energies) continue;
    const Energies& e = *f.energies;
    const double lost = e0 - e.allke - e.allie;
    EXPECT_NEAR(e.allvd, lost, 1e-6 * largest) << f.increment;
    EXPECT_GE(e.allvd, previous) << f.increment;
    previous = e.allvd;
    worst = std::max(worst, std::abs(e.allvd - lost) / largest);
    ++frames;
  }
  EXPECT_EQ(frames, 300);
  // three periods at zeta = 0.05 dissipate 1 - exp(-2 zeta w 3T) = 85 % of the energy
  EXPECT_GT(previous, 0.8 * e0);
  std::printf("largest |ALLVD - energy lost| / largest energy: %.3g\n", worst);
}

TEST(DynamicUelDamping, ZeroDampingIsTheUndampedOscillator) {
  const double h = kT / 100.0;
  const JobResult r = run(deck(0.0, h, kT), "uel_undamped");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto x = history(r);
  ASSERT_EQ(x.size(), 100u);
  const auto ref = trapezoidal(0.0, h, x.size());
  for (std::size_t n = 0; n < x.size(); ++n) EXPECT_NEAR(x[n], ref[n], 1e-9 * kV0 / kW) << n;
}

TEST(DynamicUelDamping, NonFiniteDampingIsOneErrorNamingTheElement) {
  const JobResult r = run(deck(kC, kT / 100.0, kT, 1.0), "uel_bad_damping");
  // an AnalysisError, like a non-finite RHS or mass (the user code's numbers, not the deck's)
  EXPECT_EQ(r.exit_code, kExitNoConvergence);
  EXPECT_NE(r.error.find("element 1 (U5)"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("LFLAGS(3) = 3"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("damping"), std::string::npos) << r.error;
}

} // namespace
} // namespace gapfem
