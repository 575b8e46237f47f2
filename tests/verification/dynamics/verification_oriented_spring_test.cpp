// SPRING1 and DASHPOT1 with *SPRING / *DASHPOT, ORIENTATION= (local DOFs: Keywords Reference
// *SPRING, *DASHPOT; docs/theory/dynamics.md §9), with closed forms.
//
// The model: a MASS m on node 1 in the x-y plane (z held), two SPRING1 on the local DOFs 1 (k1)
// and 2 (k2) of the orientation OR, whose local 1-axis is n1 = (cos a, sin a, 0) (a = 30 degrees)
// and local 2-axis n2 = (-sin a, cos a, 0). The stiffness is K = k1 n1 n1^T + k2 n2 n2^T, so
//   static:  u = (F . n1 / k1) n1 + (F . n2 / k2) n2  (K^-1 F in the principal axes);
//   dynamic: a force F n1 applied suddenly and held moves the mass along n1 only (n1 is an
//            eigenvector of K), x = u . n1 - F/k1 oscillates with the period T = 2 pi sqrt(m/k1),
//            and u . n2 stays zero.
// With ALPHA=0 the HHT operator is the trapezoidal rule, whose period is T (1 + (w h)^2 / 12) to
// leading order (verification_dashpot_test.cpp derives it); the test allows twice that.
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <numbers>
#include <vector>

namespace gapfem {
namespace {

using test::run_deck;

constexpr double kM = 0.5, kK1 = 500.0, kK2 = 2000.0, kC = 1.5, kF = 5.0;
const double kAngle = std::numbers::pi / 6.0;
const double kCos = std::cos(kAngle), kSin = std::sin(kAngle);

/// The deck: `oriented` puts the springs (and dashpot) on OR's local DOFs; otherwise on the
/// global DOFs 1 and 2 (the same model turned back by a). `extra` adds elements; `step` is the
/// step's procedure and load lines.
std::string deck(bool oriented, const std::string& extra, const std::string& step) {
  const std::string o = oriented ? ", ORIENTATION=OR" : "";
  return fmt::format(R"(*HEADING
a mass on two springs in the axes of an orientation
*NODE
1, 0., 0., 0.
*ORIENTATION, NAME=OR
{:.17g}, {:.17g}, 0., {:.17g}, {:.17g}, 0.
*ELEMENT, TYPE=MASS, ELSET=M
1, 1
*MASS, ELSET=M
{}
*ELEMENT, TYPE=SPRING1, ELSET=S1
2, 1
*SPRING, ELSET=S1{}
1
{}
*ELEMENT, TYPE=SPRING1, ELSET=S2
3, 1
*SPRING, ELSET=S2{}
2
{}
{}*BOUNDARY
1, 3, 3
*AMPLITUDE, NAME=CONST
0., 1., 1000., 1.
*STEP, INC=100000
{}*NODE PRINT, FREQUENCY=1
U
*END STEP
)",
                     kCos, kSin, -kSin, kCos, kM, o, kK1, o, kK2, extra, step);
}

/// The displacement of node 1 along n1 and n2 at the end of every increment.
std::vector<std::array<double, 2>> history(const JobResult& r) {
  std::vector<std::array<double, 2>> h;
  for (const Frame& f : r.frames) {
    if (f.increment <= 0) continue;
    const Vec3& u = f.nodes.U.at(r.model->mesh.find_node(1));
    h.push_back({kCos * u[0] + kSin * u[1], -kSin * u[0] + kCos * u[1]});
  }
  return h;
}

TEST(VerificationOrientedSpring, StaticDisplacementIsTheLoadProjectedOnTheLocalAxes) {
  // F = (Fx, Fy) = (5, 2): u = (F.n1/k1) n1 + (F.n2/k2) n2; linear, so one solve: round-off only
  const double Fx = 5.0, Fy = 2.0;
  const JobResult r =
      run_deck(deck(true, "", fmt::format("*STATIC\n*CLOAD\n1, 1, {}\n1, 2, {}\n", Fx, Fy)));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const double f1 = Fx * kCos + Fy * kSin, f2 = -Fx * kSin + Fy * kCos;
  const double ux = f1 / kK1 * kCos - f2 / kK2 * kSin, uy = f1 / kK1 * kSin + f2 / kK2 * kCos;
  const Vec3& u = test::U(r, test::last_frame(r), 1);
  EXPECT_NEAR(u[0], ux, 1e-12 * std::abs(ux));
  EXPECT_NEAR(u[1], uy, 1e-12 * std::abs(uy));
  // the global springs of the same stiffness numbers give another answer: the axes matter
  const JobResult g =
      run_deck(deck(false, "", fmt::format("*STATIC\n*CLOAD\n1, 1, {}\n1, 2, {}\n", Fx, Fy)));
  ASSERT_EQ(g.exit_code, 0) << g.error;
  EXPECT_GT(std::abs(test::U(g, test::last_frame(g), 1)[0] - ux), 0.03 * std::abs(ux));
}

TEST(VerificationOrientedSpring, NonlinearSpringAlongItsLocalAxis) {
  // local 1 follows the table (F, du) = (0, 0), (1, 0.01), (1.5, 0.03); a load 1.25 along n1
  // lands in the second segment: du = 0.01 + 0.25 / 25 = 0.02 (piecewise linear: Newton ends
  // exactly there, so only round-off remains), nothing along n2
  std::string text = deck(
      true, "",
      fmt::format("*STATIC\n*CLOAD\n1, 1, {:.17g}\n1, 2, {:.17g}\n", 1.25 * kCos, 1.25 * kSin));
  const std::string linear = fmt::format("*SPRING, ELSET=S1, ORIENTATION=OR\n1\n{}\n", kK1);
  ASSERT_NE(text.find(linear), std::string::npos);
  text.replace(text.find(linear), linear.size(),
               "*SPRING, ELSET=S1, ORIENTATION=OR, NONLINEAR\n1\n0., 0.\n1., 0.01\n1.5, 0.03\n");
  const JobResult r = run_deck(text);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto h = history(r);
  ASSERT_FALSE(h.empty());
  EXPECT_NEAR(h.back()[0], 0.02, 1e-12);
  EXPECT_NEAR(h.back()[1], 0.0, 1e-14);
}

TEST(VerificationOrientedSpring, FreeVibrationAlongTheLocalAxisHasThePeriodOfK1) {
  const double w = std::sqrt(kK1 / kM), T = 2.0 * std::numbers::pi / w, dt = T / 100.0;
  const std::string step =
      fmt::format("*DYNAMIC, DIRECT, ALPHA=0.\n{:.17g}, {:.17g}\n*CLOAD, AMPLITUDE=CONST\n"
                  "1, 1, {:.17g}\n1, 2, {:.17g}\n",
                  dt, 5.0 * T, kF * kCos, kF * kSin);
  const JobResult r = run_deck(deck(true, "", step));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto h = history(r);
  ASSERT_EQ(h.size(), 500u);
  std::vector<double> t; // upward zero crossings of x = u.n1 - F/k1 (sample n at (n + 1) dt)
  double amplitude = 0.0, off_axis = 0.0;
  for (std::size_t n = 0; n < h.size(); ++n) {
    const double x = h[n][0] - kF / kK1;
    amplitude = std::max(amplitude, std::abs(x));
    off_axis = std::max(off_axis, std::abs(h[n][1]));
    if (n > 0) {
      const double xp = h[n - 1][0] - kF / kK1;
      if (xp < 0.0 && x >= 0.0) t.push_back(dt * (static_cast<double>(n) + xp / (xp - x)));
    }
  }
  // the amplitude of the step response is F/k1 (no damping: the trapezoidal rule keeps it)
  EXPECT_NEAR(amplitude, kF / kK1, 0.01 * kF / kK1);
  EXPECT_LT(off_axis, 1e-12 * kF / kK1) << "the mass left its axis n1";
  ASSERT_GE(t.size(), 4u);
  const double period = (t.back() - t.front()) / static_cast<double>(t.size() - 1);
  EXPECT_NEAR(period / T, 1.0, 2.0 * w * w * dt * dt / 12.0) << "measured period " << period;
}

TEST(VerificationOrientedSpring, OrientedDashpotDampsAsTheGlobalOneTurnedBack) {
  // the same damped oscillator twice: along the global x axis, and along n1 through OR; the
  // motions along their own axes agree to the round-off of the projections (1e-10 of F/k1)
  const double T = 2.0 * std::numbers::pi * std::sqrt(kM / kK1), dt = T / 50.0;
  auto run = [&](bool oriented) {
    const std::string dashpot =
        fmt::format("*ELEMENT, TYPE=DASHPOT1, ELSET=D\n4, 1\n*DASHPOT, ELSET=D{}\n1\n{}\n",
                    oriented ? ", ORIENTATION=OR" : "", kC);
    const double fx = oriented ? kF * kCos : kF, fy = oriented ? kF * kSin : 0.0;
    const std::string step =
        fmt::format("*DYNAMIC, DIRECT, ALPHA=0.\n{:.17g}, {:.17g}\n*CLOAD, AMPLITUDE=CONST\n"
                    "1, 1, {:.17g}\n1, 2, {:.17g}\n",
                    dt, 2.0 * T, fx, fy);
    return run_deck(deck(oriented, dashpot, step));
  };
  const JobResult g = run(false), o = run(true);
  ASSERT_EQ(g.exit_code, 0) << g.error;
  ASSERT_EQ(o.exit_code, 0) << o.error;
  std::vector<std::array<double, 2>> hg;
  for (const Frame& f : g.frames)
    if (f.increment > 0) {
      const Vec3& u = f.nodes.U.at(g.model->mesh.find_node(1));
      hg.push_back({u[0], u[1]});
    }
  const auto ho = history(o);
  ASSERT_EQ(ho.size(), hg.size());
  ASSERT_EQ(ho.size(), 100u);
  double peak = 0.0;
  for (std::size_t n = 0; n < ho.size(); ++n) {
    EXPECT_NEAR(ho[n][0], hg[n][0], 1e-10 * kF / kK1) << n + 1;
    EXPECT_NEAR(ho[n][1], hg[n][1], 1e-10 * kF / kK1) << n + 1;
    peak = std::max(peak, ho[n][0]);
  }
  // and it is damped: the overshoot of the undamped 2 F/k1 is cut
  EXPECT_LT(peak, 1.95 * kF / kK1);
}

} // namespace
} // namespace gapfem
