// Waves and modes in *DYNAMIC steps against closed forms (docs/theory/dynamics.md, Verification):
// - A stress wave in a bar onto a stop: a T3D2 bar of length L = 1 (100 elements, E = 1000,
//   rho = 10: c = sqrt(E/rho) = 10), at rest against a GAPUNI stop at its right end (clearance 0),
//   its left end driven at v0 = 0.01 from t = 0 (*BOUNDARY, TYPE=VELOCITY, a step). The
//   compression wave sigma = rho c v0 = 1 runs to the stop in L/c = 0.1 and is reflected there
//   doubled: the stop's force rises from 0 to 2 rho c v0 A = 2 (A = 1) at t = L/c and holds it
//   until the reflection gets back to the driven end (t = 2 L/c = 0.2), after which the
//   stress doubles again at the stop at 3 L/c. Lumped mass and the trapezoidal rule with
//   c dt = 0.5 element: the front is spread over a few elements (Gibbs ringing around the
//   plateau), so the arrival (the force first above half the plateau) is checked within 3 % of
//   L/c and the plateau's mean over [1.2, 1.8] L/c within 3 % of 2.
// - A cantilever's first bending period: ten B32 elements (consistent mass with rotary
//   inertia) of a 10 x 0.2 x 0.2 beam (E = 2e5, rho = 1, I = a^4/12), released at once from
//   its static deflection under a tip load (AMPLITUDE=STEP: with the default ramp a removed load
//   is taken off over the step, as in Abaqus): T1 = 2 pi / (1.8751^2 sqrt(EI/(rho A L^4))) by
//   Euler-Bernoulli theory (slenderness 50: shear and rotary inertia lower the frequency by
//   under 0.1 %). The period is the mean spacing of the tip's upward zero crossings over six
//   periods with the trapezoidal rule at dt = T1/200 (period elongation (w dt)^2/12 = 8e-5;
//   the higher modes the static shape holds, 3 %, shift single crossings slightly): within
//   0.5 %.
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <numbers>

namespace gapfem {
namespace {

using test::run_deck;

TEST(VerificationDynamicWave, AStressWaveDoublesAtARigidStop) {
  constexpr int n = 100;
  constexpr double L = 1.0, E = 1000.0, rho = 10.0, v0 = 0.01;
  const double c = std::sqrt(E / rho), dt = 0.5 * (L / n) / c;
  std::string d = "*HEADING\na bar driven at one end onto a stop at the other\n*NODE\n";
  for (int i = 0; i <= n; ++i) d += fmt::format("{}, {}, 0., 0.\n", i + 1, L * i / n);
  d += fmt::format("{}, {}, 0., 0.\n*ELEMENT, TYPE=T3D2, ELSET=BAR\n", n + 2, L);
  for (int i = 1; i <= n; ++i) d += fmt::format("{}, {}, {}\n", i, i, i + 1);
  d += fmt::format("*NSET, NSET=ALL, GENERATE\n1, {}\n", n + 1);
  d += fmt::format("*ELEMENT, TYPE=GAPUNI, ELSET=STOP\n{}, {}, {}\n", n + 1, n + 1, n + 2);
  d += fmt::format(R"(*GAP, ELSET=STOP
0., 1., 0., 0., 1.
*MATERIAL, NAME=M
*ELASTIC
{}, 0.
*DENSITY
{}
*SOLID SECTION, ELSET=BAR, MATERIAL=M
1.
*BOUNDARY
ALL, 2, 3
{}, 1, 3
*STEP, INC=10000, AMPLITUDE=STEP
*DYNAMIC, DIRECT, ALPHA=0., INITIAL=YES
{}, {}
*BOUNDARY, TYPE=VELOCITY
1, 1, 1, {}
*EL PRINT, ELSET=STOP, FREQUENCY=1
S
*END STEP
)",
                   E, rho, n + 2, dt, 0.25, v0);
  const JobResult r = run_deck(d);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const double t_arrival = L / c, plateau = 2.0 * rho * c * v0;
  double first = -1.0, sum = 0.0;
  int count = 0;
  for (const Frame& f : r.frames) {
    if (f.increment == 0) continue;
    const double F = test::gap(r, f, n + 1).normal_force;
    if (first < 0.0 && F > 0.5 * plateau) first = f.step_time;
    if (f.step_time < 0.8 * t_arrival) EXPECT_NEAR(F, 0.0, 1e-3 * plateau) << f.step_time;
    if (f.step_time > 1.2 * t_arrival && f.step_time < 1.8 * t_arrival) {
      sum += F;
      ++count;
    }
  }
  EXPECT_NEAR(first, t_arrival, 0.03 * t_arrival);
  ASSERT_GT(count, 10);
  EXPECT_NEAR(sum / count, plateau, 0.03 * plateau);
}

TEST(VerificationDynamicWave, ACantileversFirstBendingPeriod) {
  constexpr int n = 10;
  constexpr double L = 10.0, a = 0.2, E = 2e5, rho = 1.0;
  const double A = a * a, I = a * a * a * a / 12.0;
  const double w1 = 1.8751 * 1.8751 * std::sqrt(E * I / (rho * A * L * L * L * L));
  const double T1 = 2.0 * std::numbers::pi / w1;
  std::string d = "*HEADING\na cantilever released from its static deflection\n*NODE\n";
  for (int i = 0; i <= 2 * n; ++i) d += fmt::format("{}, {}, 0., 0.\n", i + 1, L * i / (2 * n));
  d += "*ELEMENT, TYPE=B32, ELSET=BEAM\n";
  for (int e = 0; e < n; ++e)
    d += fmt::format("{}, {}, {}, {}\n", e + 1, 2 * e + 1, 2 * e + 2, 2 * e + 3);
  d += fmt::format(R"(*MATERIAL, NAME=S
*ELASTIC
{}, 0.3
*DENSITY
{}
*BEAM SECTION, ELSET=BEAM, MATERIAL=S, SECTION=RECT
{}, {}
0., 0., -1.
*BOUNDARY
1, 1, 6
*STEP
*STATIC
*CLOAD
{}, 2, -1.
*END STEP
*STEP, INC=10000, AMPLITUDE=STEP
*DYNAMIC, DIRECT, ALPHA=0., INITIAL=YES
{}, {}
*CLOAD, OP=NEW
*NODE PRINT, FREQUENCY=1
U
*END STEP
)",
                   E, rho, a, a, 2 * n + 1, T1 / 200.0, 6.2 * T1);
  const JobResult r = run_deck(d);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  std::vector<double> ups; // upward zero crossings of the tip's deflection, interpolated
  double t_prev = 0.0, u_prev = 0.0;
  bool started = false;
  for (const Frame& f : r.frames) {
    if (f.step != 2) continue;
    const double u = test::U(r, f, 2 * n + 1)[1];
    if (started && u_prev < 0.0 && u >= 0.0)
      ups.push_back(t_prev + (f.step_time - t_prev) * (-u_prev) / (u - u_prev));
    started = true;
    t_prev = f.step_time;
    u_prev = u;
  }
  ASSERT_GE(ups.size(), 5u);
  const double T = (ups.back() - ups.front()) / static_cast<double>(ups.size() - 1);
  EXPECT_NEAR(T, T1, 0.005 * T1);
}

} // namespace
} // namespace gapfem
