// *BEAM ADDED INERTIA in a dynamic and a static step (docs/theory/dynamics.md §8, "Added
// inertia"): a water-filled steel pipe, a cantilever of 20 PIPE31 along x (L = 3000, r_o = 50,
// t = 5, E = 2e5, nu = 0.3, rho = 7.85e-9), clamped at node 1.
//
// Contents: water of density 1e-9 filling r_i = 45, m_c = 1e-9 pi 45^2 per length, given as added
// mass on the axis with the rotary inertia I11 = I22 = m_c (r_o^2 + r_i^2) / 4 (so that the pipe
// with contents has exactly the mass matrix of a wall of density rho + m_c / A: the section's
// own rotary inertia per length is rho I = rho A (r_o^2 + r_i^2) / 4 about each section axis).
//
// 1. Equivalence: the deck with contents and the deck whose wall density is rho + m_c / A (no
//    added inertia) have the same mass matrix, stiffness and increments, so the same history; the
//    tip deflection agrees to 1e-9 of its amplitude (round-off of 2000 trapezoidal steps). A wrong
//    rotary inertia of the added mass (e.g. none) changes the bending frequency by about
//    (r_g / L)^2 ~ 1e-4 and the history by far more than the tolerance.
// 2. Closed form: released from the static deflection of a tip load, the tip vibrates in the
//    first bending mode with the period of the Euler-Bernoulli cantilever
//        T1 = 2 pi / (1.8751^2 sqrt(E I / (m' L^4))),  m' = rho A + m_c.
//    Tolerance 1%: shear flexibility and rotary inertia (r_g / L)^2 ~ 1.3e-4 times a factor of
//    order 10, the lumped mass of 20 linear elements (a few 1e-3), the trapezoidal rule's period
//    elongation (w dt)^2 / 12 = 8e-5 at dt = T1 / 200, and the second mode in the released shape
//    (2.5% of the tip amplitude at 6.27 times the frequency: the period from the first and last of
//    20 zero crossings moves by at most 2 x 0.025 / (2 pi 10) = 8e-4). Without the contents the
//    period is sqrt(rho A / m') = 0.81 times as long: far outside.
// 3. ALPHA damps the added inertia: with the contents' mass proportional to the wall's (above),
//    C = ALPHA M_added = ALPHA f M with f = m_c / m', which is the material damping
//    *DAMPING, ALPHA = ALPHA f of the heavier wall: the same history to 1e-9 of the amplitude.
//    ALPHA = 6 gives the first mode zeta = ALPHA f / (2 w1) = 0.020. Mass-proportional damping
//    decays every mode at the same rate ALPHA f / 2, so the damped history is the undamped one
//    times exp(-ALPHA f t / 2) (up to the damped frequencies w sqrt(1 - zeta^2): a phase of
//    2 pi 10 zeta^2 / 2 = 0.013 rad after 10 periods, below 1e-3 of a peak): the peak near
//    t = 10 T1 over the undamped run's is exp(-ALPHA f t / 2) = 0.31 within 1% (measured 0.2%).
// 4. Gravity acts on the added mass: GRAV 9810 in -y gives the clamp the reaction
//    (rho A + m_c) g L exactly (static equilibrium of a linear model; 1e-9 for the solver's
//    residual).
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <numbers>

namespace gapfem {
namespace {

using test::run_deck_exact;

constexpr double kL = 3000.0, kRo = 50.0, kRi = 45.0, kE = 200000.0, kRho = 7.85e-9;
constexpr int kElements = 20;
const double kA = std::numbers::pi * (kRo * kRo - kRi * kRi);
const double kI = std::numbers::pi / 4.0 * (std::pow(kRo, 4) - std::pow(kRi, 4));
const double kMc = 1e-9 * std::numbers::pi * kRi * kRi;

/// The cantilever with `density` and `section_extra` after the section; `steps` at the end.
std::string pipe_deck(double density, const std::string& section_extra, const std::string& steps) {
  std::string nodes, elems;
  for (int i = 0; i <= kElements; ++i)
    nodes += fmt::format("{}, {:.17g}, 0., 0.\n", i + 1, kL * i / kElements);
  for (int e = 1; e <= kElements; ++e) elems += fmt::format("{}, {}, {}\n", e, e, e + 1);
  return fmt::format(R"(*HEADING
a water-filled pipe cantilever
*NODE, NSET=ALL
{}*ELEMENT, TYPE=PIPE31, ELSET=P
{}*BEAM SECTION, ELSET=P, MATERIAL=STEEL, SECTION=PIPE
50., 5.
0., 0., 1.
{}*MATERIAL, NAME=STEEL
*ELASTIC
200000., 0.3
*DENSITY
{:.17g}
*BOUNDARY
1, 1, 6
{})",
                     nodes, elems, section_extra, density, steps);
}

std::string contents(const std::string& params = "") {
  const double I = kMc * (kRo * kRo + kRi * kRi) / 4.0;
  return fmt::format("*BEAM ADDED INERTIA{}\n{:.17g}, 0., 0., 0., {:.17g}, {:.17g}, 0.\n", params,
                     kMc, I, I);
}

double period() {
  const double mp = kRho * kA + kMc;
  const double b = 1.8751040687;
  return 2.0 * std::numbers::pi / (b * b * std::sqrt(kE * kI / (mp * std::pow(kL, 4))));
}

/// Static tip load 1000 in y, then released for 10.5 periods at T1 / 200.
std::string release_steps() {
  const double T = period(), dt = T / 200.0;
  return fmt::format(R"(*STEP
*STATIC
1., 1.
*CLOAD
{}, 2, 1000.
*END STEP
*STEP, INC=100000, AMPLITUDE=STEP
*DYNAMIC, DIRECT, ALPHA=0.
{:.17g}, {:.17g}
*CLOAD, OP=NEW
*NODE PRINT, FREQUENCY=1
U
*END STEP
)",
                     kElements + 1, dt, 2100 * dt);
}

/// The tip's y deflection at each increment of the dynamic step, with its time.
std::vector<std::pair<double, double>> tip_history(const JobResult& r) {
  std::vector<std::pair<double, double>> h;
  for (const Frame& f : r.frames)
    if (f.step == 2 && f.increment > 0)
      h.emplace_back(f.step_time, test::U(r, f, kElements + 1)[1]);
  return h;
}

TEST(BeamAddedInertiaDeck, ContentsAreTheMassOfAHeavierWallAndGiveTheCantileverPeriod) {
  const JobResult with = run_deck_exact(pipe_deck(kRho, contents(), release_steps()), "with");
  ASSERT_EQ(with.exit_code, 0) << with.error;
  const JobResult heavy = run_deck_exact(pipe_deck(kRho + kMc / kA, "", release_steps()), "heavy");
  ASSERT_EQ(heavy.exit_code, 0) << heavy.error;
  const auto a = tip_history(with), b = tip_history(heavy);
  ASSERT_EQ(a.size(), 2100u);
  ASSERT_EQ(b.size(), a.size());
  double amp = 0.0;
  for (const auto& [t, u] : a) amp = std::max(amp, std::abs(u));
  ASSERT_GT(amp, 1.0);
  for (std::size_t n = 0; n < a.size(); ++n) EXPECT_NEAR(a[n].second, b[n].second, 1e-9 * amp) << n;

  // zero crossings (linear interpolation between increments): 21 of them in 10.5 periods
  std::vector<double> crossings;
  for (std::size_t n = 1; n < a.size(); ++n) {
    const auto [t0, u0] = a[n - 1];
    const auto [t1, u1] = a[n];
    if ((u0 > 0.0) != (u1 > 0.0)) crossings.push_back(t0 + (t1 - t0) * u0 / (u0 - u1));
  }
  ASSERT_GE(crossings.size(), 21u);
  const double measured = 2.0 * (crossings[20] - crossings[0]) / 20.0;
  EXPECT_NEAR(measured / period(), 1.0, 0.01) << measured << " vs " << period();
}

TEST(BeamAddedInertiaDeck, AlphaDampsTheContentsAsAMaterialAlphaOfTheirShare) {
  const double alpha = 6.0, f = kMc / (kRho * kA + kMc);
  const JobResult with =
      run_deck_exact(pipe_deck(kRho, contents(", ALPHA=6."), release_steps()), "with");
  ASSERT_EQ(with.exit_code, 0) << with.error;
  std::string heavy_deck = pipe_deck(kRho + kMc / kA, "", release_steps());
  const std::string density = "*DENSITY\n";
  heavy_deck.insert(heavy_deck.find(density), fmt::format("*DAMPING, ALPHA={:.17g}\n", alpha * f));
  const JobResult heavy = run_deck_exact(heavy_deck, "heavy");
  ASSERT_EQ(heavy.exit_code, 0) << heavy.error;
  const JobResult undamped = run_deck_exact(pipe_deck(kRho, contents(), release_steps()), "free");
  ASSERT_EQ(undamped.exit_code, 0) << undamped.error;
  const auto a = tip_history(with), b = tip_history(heavy), c = tip_history(undamped);
  ASSERT_EQ(a.size(), 2100u);
  ASSERT_EQ(b.size(), a.size());
  ASSERT_EQ(c.size(), a.size());
  double amp = 0.0;
  for (const auto& [t, u] : a) amp = std::max(amp, std::abs(u));
  for (std::size_t n = 0; n < a.size(); ++n) EXPECT_NEAR(a[n].second, b[n].second, 1e-9 * amp) << n;
  const double zeta = alpha * f / (2.0 * 2.0 * std::numbers::pi / period());
  EXPECT_NEAR(zeta, 0.02, 0.002);
  // the largest deflection of the last period, damped and undamped
  std::size_t i = 1900, j = 1900;
  for (std::size_t n = 1900; n < a.size(); ++n) {
    if (std::abs(a[n].second) > std::abs(a[i].second)) i = n;
    if (std::abs(c[n].second) > std::abs(c[j].second)) j = n;
  }
  const double decay = std::exp(-alpha * f / 2.0 * c[j].first);
  EXPECT_NEAR(std::abs(a[i].second) / std::abs(c[j].second) / decay, 1.0, 0.01)
      << std::abs(a[i].second) / std::abs(c[j].second) << " vs " << decay;
}

TEST(BeamAddedInertiaDeck, GravityWeighsTheContents) {
  const std::string steps = R"(*STEP
*STATIC
1., 1.
*DLOAD
P, GRAV, 9810., 0., -1., 0.
*NODE PRINT
RF
*END STEP
)";
  const JobResult r = run_deck_exact(pipe_deck(kRho, contents(), steps));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const double W = (kRho * kA + kMc) * 9810.0 * kL;
  EXPECT_NEAR(test::RF(r, test::last_frame(r), 1)[1], W, 1e-9 * W);
}

} // namespace
} // namespace gapfem
