// Dashpots (elements/structural/dashpot.hpp) and the ALPHA damping of point masses, with closed
// forms. The oscillator: a MASS element (m) on node 1, a SPRING1 (k) and a DASHPOT1 (c) to
// ground on DOF 1, the node's other translations held, started from rest by a force F applied
// suddenly and held (a step response: the decaying oscillation x = u - F/k around the static
// F/k is the free vibration from x = -F/k, x' = 0), integrated by the trapezoidal rule
// (*DYNAMIC, ALPHA=0: HHT's alpha set to zero, beta = 1/4, gamma = 1/2, so that HHT's own
// dissipation does not blur the damping being checked). (From rest, because the start of a
// dynamic step evaluates R(0) without the damping forces C v0: an initial velocity would give an
// inconsistent a0; see the report of issue 46.)
//
// Closed forms used below (m x'' + c x' + k x = 0):
//   w = sqrt(k/m), zeta = c / (2 m w), wd = w sqrt(1 - zeta^2), damped period Td = 2 pi / wd,
//   logarithmic decrement delta = ln(u_peak(i) / u_peak(i+1)) = 2 pi zeta / sqrt(1 - zeta^2).
// The trapezoidal rule on the first-order system y = (u, v), y' = A y, advances y_{n+1} =
// (I - h A/2)^{-1} (I + h A/2) y_n exactly (Newmark's average acceleration with consistent
// accelerations is that rule): each eigenvalue lambda = w (-zeta +- i sqrt(1-zeta^2)) of A goes to
// mu = (1 + h lambda/2) / (1 - h lambda/2), i.e. the discrete lambda_h = (2/h) atanh(h lambda/2)
// = lambda (1 + (h lambda)^2 / 12 + O(h^4)). So the discrete motion's period is Td (1 + (w h)^2
// / 12) and its decrement delta (1 - (w h)^2 / 6) to leading order (zeta small: Re(lambda^3) =
// 3 zeta w^3, Im(lambda^3) = -w^3 to first order in zeta). The tests allow twice these errors
// for the period and the decrement measured from the history; the recurrence itself, advanced
// by hand, must match to 1e-9 (the solver's linear-solve round-off over ~200 increments).
#include "test_util.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <numbers>
#include <vector>

namespace gapfem {
namespace {

using test::run_deck;

constexpr double kM = 0.5, kK = 500.0, kC = 1.5, kF = 5.0; // zeta = 1.5 / (2 0.5 31.62) = 0.047

double omega() {
  return std::sqrt(kK / kM);
}
double zeta() {
  return kC / (2.0 * kM * omega());
}
double damped_period() {
  return 2.0 * std::numbers::pi / (omega() * std::sqrt(1.0 - zeta() * zeta()));
}

/// The oscillator deck; `damper` is the element (and property) lines that damp node 1.
std::string oscillator(const std::string& damper, double dt, double period) {
  return fmt::format(R"(*HEADING
mass, spring and damper to ground
*NODE
1, 0., 0., 0.
*ELEMENT, TYPE=MASS, ELSET=M
1, 1
*MASS, ELSET=M{}
{}
*ELEMENT, TYPE=SPRING1, ELSET=S
2, 1
*SPRING, ELSET=S
1
{}
{}*BOUNDARY
1, 2, 3
*AMPLITUDE, NAME=CONST
0., 1., 1000., 1.
*STEP, INC=100000
*DYNAMIC, DIRECT, ALPHA=0.
{}, {}
*CLOAD, AMPLITUDE=CONST
1, 1, {}
*NODE PRINT, FREQUENCY=1
U, V
*END STEP
)",
                     damper.rfind("ALPHA", 0) == 0 ? ", " + damper : "", kM, kK,
                     damper.rfind("ALPHA", 0) == 0 ? "" : damper, dt, period, kF);
}

const std::string kDashpot1 =
    fmt::format("*ELEMENT, TYPE=DASHPOT1, ELSET=D\n3, 1\n*DASHPOT, ELSET=D\n1\n{}\n", kC);

/// u (DOF `dof` of node `node`) at the end of every increment.
std::vector<double> history(const JobResult& r, Label node = 1, int dof = 1,
                            bool velocity = false) {
  std::vector<double> h;
  const NodeId n = r.model->mesh.find_node(node);
  for (const Frame& f : r.frames) {
    if (f.increment <= 0) continue;
    h.push_back((velocity ? f.nodes.V : f.nodes.U).at(n)[dof - 1]);
  }
  return h;
}

/// The trapezoidal recurrence by hand: x_n = u_n - F/k for n = 1..count, from x = -F/k, x' = 0.
std::vector<double> trapezoidal(double m, double c, double k, double F, double h, int count) {
  Eigen::Matrix2d A;
  A << 0.0, 1.0, -k / m, -c / m;
  const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
  const Eigen::Matrix2d S = (I - 0.5 * h * A).inverse() * (I + 0.5 * h * A);
  Eigen::Vector2d y(-F / k, 0.0);
  std::vector<double> u;
  for (int n = 0; n < count; ++n) {
    y = S * y;
    u.push_back(y[0]);
  }
  return u;
}

/// Upward zero crossings of the sampled history (linear interpolation), in time.
std::vector<double> upward_crossings(const std::vector<double>& x, double h) {
  std::vector<double> t;
  for (std::size_t n = 1; n < x.size(); ++n)
    if (x[n - 1] < 0.0 && x[n] >= 0.0) // sample n is at (n+1) h
      t.push_back(h * (static_cast<double>(n) + x[n - 1] / (x[n - 1] - x[n])));
  return t;
}

/// x = u - F/k.
std::vector<double> deviation(std::vector<double> u) {
  for (double& v : u) v -= kF / kK;
  return u;
}

/// Peak values (local maxima), each refined by the parabola through its three samples.
std::vector<double> peaks(const std::vector<double>& u) {
  std::vector<double> p;
  for (std::size_t n = 1; n + 1 < u.size(); ++n)
    if (u[n] > u[n - 1] && u[n] >= u[n + 1]) {
      const double a = u[n - 1], b = u[n], c = u[n + 1];
      p.push_back(b + (c - a) * (c - a) / (8.0 * (2.0 * b - a - c)));
    }
  return p;
}

TEST(VerificationDashpot, DampedFreeVibrationHasTheClosedFormPeriodAndDecrement) {
  const double Td = damped_period(), dt = Td / 100.0;
  const JobResult r = run_deck(oscillator(kDashpot1, dt, 5.0 * Td));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto u = deviation(history(r));
  ASSERT_EQ(u.size(), 500u);
  // the recurrence, by hand
  const auto ref = trapezoidal(kM, kC, kK, kF, dt, 500);
  const double scale = kF / kK;
  for (std::size_t n = 0; n < u.size(); ++n) ASSERT_NEAR(u[n], ref[n], 1e-9 * scale) << n + 1;
  // period and decrement against the continuous closed form
  const double wh2 = omega() * omega() * dt * dt;
  const auto t = upward_crossings(u, dt);
  ASSERT_GE(t.size(), 4u);
  const double T = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
  EXPECT_NEAR(T / Td, 1.0, 2.0 * wh2 / 12.0) << "measured damped period " << T;
  const auto p = peaks(u);
  ASSERT_GE(p.size(), 4u);
  const double delta = std::log(p.front() / p.back()) / static_cast<double>(p.size() - 1);
  const double delta_exact = 2.0 * std::numbers::pi * zeta() / std::sqrt(1.0 - zeta() * zeta());
  EXPECT_NEAR(delta / delta_exact, 1.0, 2.0 * wh2 / 6.0) << "measured decrement " << delta;
}

// *MASS, ALPHA = c / m damps the mass as the dashpot c does (C = alpha M = c): the same histories
// up to the round-off of forming alpha and alpha m.
TEST(VerificationDashpot, MassAlphaDampsLikeTheDashpot) {
  const double Td = damped_period(), dt = Td / 50.0;
  const JobResult a = run_deck(oscillator(kDashpot1, dt, 2.0 * Td));
  const JobResult b = run_deck(oscillator(fmt::format("ALPHA={:.17g}", kC / kM), dt, 2.0 * Td));
  ASSERT_EQ(a.exit_code, 0) << a.error;
  ASSERT_EQ(b.exit_code, 0) << b.error;
  const auto ua = history(a), ub = history(b);
  ASSERT_EQ(ua.size(), ub.size());
  ASSERT_EQ(ua.size(), 100u);
  for (std::size_t n = 0; n < ua.size(); ++n) EXPECT_NEAR(ub[n], ua[n], 1e-12 * kF / kK) << n + 1;
  // and ALPHA does damp: the last peak is below the undamped amplitude
  const JobResult c = run_deck(oscillator("ALPHA=0.", dt, 2.0 * Td));
  ASSERT_EQ(c.exit_code, 0) << c.error;
  const auto p = peaks(deviation(ub)), q = peaks(deviation(history(c)));
  ASSERT_FALSE(p.empty());
  ASSERT_FALSE(q.empty());
  EXPECT_LT(p.back(), 0.9 * q.back());
}

// A nonlinear dashpot whose table is the line F = c w over the velocities the mass reaches gives
// the linear dashpot's histories: the element force is the same number (c w from the table
// interpolates to within round-off) and the tangent the same c.
TEST(VerificationDashpot, NonlinearDashpotWithALinearTableIsTheLinearOne) {
  const double Td = damped_period(), dt = Td / 50.0;
  const std::string table =
      fmt::format("*ELEMENT, TYPE=DASHPOT1, ELSET=D\n3, 1\n*DASHPOT, ELSET=D, NONLINEAR\n1\n"
                  "{}, -10.\n0., 0.\n{}, 10.\n",
                  -10.0 * kC, 10.0 * kC);
  const JobResult a = run_deck(oscillator(kDashpot1, dt, 2.0 * Td));
  const JobResult b = run_deck(oscillator(table, dt, 2.0 * Td));
  ASSERT_EQ(a.exit_code, 0) << a.error;
  ASSERT_EQ(b.exit_code, 0) << b.error;
  const auto ua = history(a), ub = history(b);
  ASSERT_EQ(ua.size(), ub.size());
  for (std::size_t n = 0; n < ua.size(); ++n) EXPECT_NEAR(ub[n], ua[n], 1e-12 * kF / kK) << n + 1;
}

/// Node 1 held at the origin, node 2 (the mass) at distance 1 along (cos a, sin a, 0); a spring
/// and a dashpot between them, a force F along the axis applied suddenly and held. `axial`: SPRINGA
/// and DASHPOTA; otherwise SPRING2 and DASHPOT2 on DOF 1 with the axis along x (a = 0).
std::string two_node(bool axial, double a, double dt, double period, bool nlgeom) {
  const double cx = std::cos(a), cy = std::sin(a);
  const std::string dofs = axial ? "" : "1, 1";
  return fmt::format(R"(*NODE
1, 0., 0., 0.
2, {:.17g}, {:.17g}, 0.
*ELEMENT, TYPE=MASS, ELSET=M
1, 2
*MASS, ELSET=M
{}
*ELEMENT, TYPE={}, ELSET=S
2, 1, 2
*SPRING, ELSET=S
{}
{}
*ELEMENT, TYPE={}, ELSET=D
3, 1, 2
*DASHPOT, ELSET=D
{}
{}
*BOUNDARY
1, 1, 3
2, 3, 3
{}*AMPLITUDE, NAME=CONST
0., 1., 1000., 1.
*STEP, INC=100000{}
*DYNAMIC, DIRECT, ALPHA=0.
{}, {}
*CLOAD, AMPLITUDE=CONST
2, 1, {:.17g}
2, 2, {:.17g}
*NODE PRINT, FREQUENCY=1
U
*END STEP
)",
                     cx, cy, kM, axial ? "SPRINGA" : "SPRING2", dofs, kK,
                     axial ? "DASHPOTA" : "DASHPOT2", dofs, kC, axial ? "" : "2, 2, 2\n",
                     nlgeom ? ", NLGEOM" : "", dt, period, kF * cx, kF * cy);
}

// DASHPOTA (and SPRINGA) along an axis turned by 30 degrees moves the mass along the axis exactly
// as DASHPOT2 (SPRING2) on DOF 1 along x: the projections agree to round-off (1e-12 of the
// amplitude); under NLGEOM the line does not turn (the motion is along it), so the same holds up
// to the Newton tolerance.
TEST(VerificationDashpot, DashpotAAlongATurnedAxisIsDashpot2AlongTheAxis) {
  const double Td = damped_period(), dt = Td / 50.0, a = std::numbers::pi / 6.0;
  const JobResult ref = run_deck(two_node(false, 0.0, dt, 2.0 * Td, false));
  ASSERT_EQ(ref.exit_code, 0) << ref.error;
  const auto u = history(ref, 2, 1);
  ASSERT_EQ(u.size(), 100u);
  for (const bool nlgeom : {false, true}) {
    const JobResult r = run_deck(two_node(true, a, dt, 2.0 * Td, nlgeom));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    const auto ux = history(r, 2, 1), uy = history(r, 2, 2);
    ASSERT_EQ(ux.size(), u.size());
    const double tol = (nlgeom ? 1e-7 : 1e-12) * kF / kK;
    for (std::size_t n = 0; n < u.size(); ++n) {
      EXPECT_NEAR(ux[n] * std::cos(a) + uy[n] * std::sin(a), u[n], tol) << n + 1 << " " << nlgeom;
      EXPECT_NEAR(-ux[n] * std::sin(a) + uy[n] * std::cos(a), 0.0, tol) << n + 1 << " " << nlgeom;
    }
  }
}

// A mass on a dashpot alone under a constant force F: m v' + c v = F, v -> F/c. The trapezoidal
// rule advances v exactly as v_{n+1} = mu v_n + (1 - mu) F/c with mu = (1 - h c/2m)/(1 + h c/2m),
// so v_n = F/c (1 - mu^n) (INITIAL=YES gives a_0 = F/m, the consistent start); after 60
// increments of h = m/c, mu^60 = 3^-60: v = F/c to round-off.
TEST(VerificationDashpot, MassOnADashpotReachesTheTerminalVelocity) {
  const double F = 3.0, h = kM / kC;
  const std::string deck = fmt::format(R"(*NODE
1, 0., 0., 0.
*ELEMENT, TYPE=MASS, ELSET=M
1, 1
*MASS, ELSET=M
{}
*ELEMENT, TYPE=DASHPOT1, ELSET=D
3, 1
*DASHPOT, ELSET=D
1
{}
*BOUNDARY
1, 2, 3
*AMPLITUDE, NAME=CONST
0., 1., 1000., 1.
*STEP, INC=1000
*DYNAMIC, DIRECT, ALPHA=0.
{}, {}
*CLOAD, AMPLITUDE=CONST
1, 1, {}
*NODE PRINT, FREQUENCY=1
U, V
*END STEP
)",
                                       kM, kC, h, 60.0 * h, F);
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto v = history(r, 1, 1, true);
  ASSERT_EQ(v.size(), 60u);
  const double mu = (1.0 - h * kC / (2.0 * kM)) / (1.0 + h * kC / (2.0 * kM));
  for (std::size_t n = 0; n < v.size(); ++n)
    EXPECT_NEAR(v[n], F / kC * (1.0 - std::pow(mu, n + 1.0)), 1e-10 * F / kC) << n + 1;
  EXPECT_NEAR(v.back(), F / kC, 1e-10 * F / kC);
}

// A dashpot in a static step: Abaqus takes the velocity as the displacement increment over the
// time increment ("Dashpots": "in quasi-static analysis ... by dividing the displacement
// increments by the time increment"). With a spring k in parallel and a force F held over
// fixed increments dt: c (u_n - u_{n-1}) / dt + k u_n = F, so u_n = F/k (1 - rho^n) with
// rho = c / (c + k dt) (backward Euler's creep towards F/k), to the Newton tolerance.
TEST(VerificationDashpot, StaticStepTakesTheVelocityFromTheIncrement) {
  const double F = 5.0, dt = 0.001;
  const std::string deck = fmt::format(R"(*NODE
1, 0., 0., 0.
*ELEMENT, TYPE=SPRING1, ELSET=S
2, 1
*SPRING, ELSET=S
1
{}
*ELEMENT, TYPE=DASHPOT1, ELSET=D
3, 1
*DASHPOT, ELSET=D
1
{}
*BOUNDARY
1, 2, 3
*AMPLITUDE, NAME=CONST
0., 1., 1000., 1.
*STEP, INC=1000
*STATIC, DIRECT
{}, {}
*CLOAD, AMPLITUDE=CONST
1, 1, {}
*NODE PRINT, FREQUENCY=1
U
*EL PRINT, ELSET=D
S
*END STEP
)",
                                       kK, kC, dt, 10.0 * dt, F);
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto u = history(r);
  ASSERT_EQ(u.size(), 10u);
  const double rho = kC / (kC + kK * dt);
  for (std::size_t n = 0; n < u.size(); ++n)
    EXPECT_NEAR(u[n], F / kK * (1.0 - std::pow(rho, n + 1.0)), 1e-9 * F / kK) << n + 1;
}

/// The message of a deck that must fail (exit 1).
std::string failure(const std::string& damper) {
  const JobResult r = run_deck(oscillator(damper, 0.01, 0.1));
  EXPECT_EQ(r.exit_code, 1) << damper;
  return r.error;
}

TEST(VerificationDashpot, InputErrors) {
  const std::string el = "*ELEMENT, TYPE=DASHPOT1, ELSET=D\n3, 1\n";
  EXPECT_NE(failure(el + "*DASHPOT, ELSET=D\n1\n-1.5\n").find("must not be negative"),
            std::string::npos);
  EXPECT_NE(failure(el + "*DASHPOT, ELSET=D\n").find("data lines are missing"), std::string::npos);
  EXPECT_NE(failure(el + "*DASHPOT, ELSET=D\n1\n").find("coefficient is missing"),
            std::string::npos);
  EXPECT_NE(failure(el + "*DASHPOT, ELSET=D, NONLINEAR\n1\n0., 0.\n1., 1.\n2., 1.\n")
                .find("must increase"),
            std::string::npos);
  EXPECT_NE(failure(el + "*DASHPOT, ELSET=D, NONLINEAR\n1\n0., 0.\n").find("at least two"),
            std::string::npos);
  EXPECT_NE(failure(el + "*DASHPOT, ELSET=D\n1\n1.5, 10.\n").find("frequency"), std::string::npos);
  EXPECT_NE(failure(el + "*DASHPOT, ELSET=D, ORIENTATION=OR\n1\n1.5\n").find("ORIENTATION"),
            std::string::npos);
  EXPECT_NE(failure(el + "*SPRING, ELSET=D\n1\n1.5\n").find("DASHPOT1 elements take *DASHPOT"),
            std::string::npos);
  EXPECT_NE(failure(el).find("*DASHPOT"), std::string::npos);
  EXPECT_NE(failure("ALPHA=-1.").find("ALPHA must not be negative"), std::string::npos);
}

} // namespace
} // namespace gapfem
