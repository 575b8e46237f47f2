// Thermal gap laws (elements/gap/thermal_laws.hpp): table rules, finite-difference checks of every
// derivative, and the spec's thermal test numbers T1-T4 (gap-elements.md §6.3) at the law level.
#include "elements/gap/thermal_laws.hpp"
#include "model/model.hpp"

#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <limits>

namespace gapfem::test {
namespace {

GapConductanceSpec conductance(std::vector<GapConductanceSpec::Row> rows, bool pressure = false) {
  GapConductanceSpec s;
  s.given = true;
  s.pressure = pressure;
  s.rows = std::move(rows);
  return s;
}

/// k = 10 at clearance 0 and 1 (the spec's T1-T3 table).
GapConductanceSpec constant_table() {
  return conductance({{10.0, 0.0, 0.0, 0.0}, {10.0, 1.0, 0.0, 0.0}});
}

/// Two temperature groups: at T = 0: k = 8 - 4x on x in [0, 1]; at T = 100: k = 12 - 2x on
/// x in [0, 2]. Between them linear in T.
GapConductanceSpec two_groups(bool pressure = false) {
  return conductance({{8.0, 0.0, 0.0, 0.0},
                      {4.0, 1.0, 0.0, 0.0},
                      {12.0, 0.0, 100.0, 0.0},
                      {10.0, 1.0, 100.0, 0.0},
                      {8.0, 2.0, 100.0, 0.0}},
                     pressure);
}

PhysicalConstants constants(double zero, double sigma) {
  PhysicalConstants c;
  c.absolute_zero = zero;
  c.stefan_boltzmann = sigma;
  return c;
}

GapRadiationSpec radiation(double eps, std::vector<double> F, std::vector<double> h) {
  GapRadiationSpec r;
  r.given = true;
  r.emissivity_a = r.emissivity_b = eps;
  r.view_factor = std::move(F);
  r.clearance = std::move(h);
  return r;
}

/// Central difference of f at x with step h.
double central(const std::function<double(double)>& f, double x, double h) {
  return (f(x + h) - f(x - h)) / (2.0 * h);
}

// ------------------------------------------------------------------------- conductance tables

TEST(GapThermalLaws, ConductanceInterpolatesClearanceAndTemperature) {
  const GapConductanceLaw law(two_groups());
  // T = 0 group at x = 0.25: 8 - 4 * 0.25 = 7.
  EXPECT_DOUBLE_EQ(law.evaluate(0.25, 0.0).k, 7.0);
  EXPECT_DOUBLE_EQ(law.evaluate(0.25, 0.0).dk_dx, -4.0);
  // T = 100 group at x = 1.5: 10 - 2 * 0.5 = 9.
  EXPECT_DOUBLE_EQ(law.evaluate(1.5, 100.0).k, 9.0);
  // T = 25 (w = 0.25) at x = 0.5: groups give 6 and 11 -> 6 + 0.25 * 5 = 7.25; dk/dT = 5 / 100.
  const ConductanceValue v = law.evaluate(0.5, 25.0);
  EXPECT_DOUBLE_EQ(v.k, 7.25);
  EXPECT_DOUBLE_EQ(v.dk_dx, -4.0 + 0.25 * (-2.0 + 4.0));
  EXPECT_DOUBLE_EQ(v.dk_dT, 0.05);
  // Outside the temperature range the nearest group holds, with no temperature slope.
  EXPECT_DOUBLE_EQ(law.evaluate(0.5, -50.0).k, 6.0);
  EXPECT_DOUBLE_EQ(law.evaluate(0.5, -50.0).dk_dT, 0.0);
  EXPECT_DOUBLE_EQ(law.evaluate(0.5, 300.0).k, 11.0);
}

TEST(GapThermalLaws, ClearanceTableDropsToZeroPastItsLastPoint) {
  const GapConductanceLaw law(two_groups());
  // Below the first clearance (penetration): the first conductance.
  EXPECT_DOUBLE_EQ(law.evaluate(-0.3, 0.0).k, 8.0);
  // At the last clearance the table value, just past it zero (spec §4.1).
  EXPECT_DOUBLE_EQ(law.evaluate(1.0, 0.0).k, 4.0);
  EXPECT_DOUBLE_EQ(law.evaluate(1.0 + 1e-9, 0.0).k, 0.0);
  EXPECT_DOUBLE_EQ(law.evaluate(1.0 + 1e-9, 0.0).dk_dx, 0.0);
  // Each temperature group drops past its own last clearance: at T = 50 and x = 1.5 only the
  // T = 100 group conducts (9), weight 0.5 -> 4.5.
  EXPECT_DOUBLE_EQ(law.evaluate(1.5, 50.0).k, 4.5);
}

TEST(GapThermalLaws, PressureTableIsConstantBeyondBothEnds) {
  const GapConductanceLaw law(two_groups(true));
  EXPECT_TRUE(law.pressure_dependent());
  EXPECT_DOUBLE_EQ(law.evaluate(5.0, 0.0).k, 4.0);
  EXPECT_DOUBLE_EQ(law.evaluate(5.0, 0.0).dk_dx, 0.0);
  EXPECT_DOUBLE_EQ(law.evaluate(-1.0, 100.0).k, 12.0);
}

TEST(GapThermalLaws, ConductanceRejectsUnsortedTemperatureGroups) {
  const auto spec =
      conductance({{1.0, 0.0, 100.0, 0.0}, {1.0, 1.0, 100.0, 0.0}, {2.0, 0.0, 50.0, 0.0}});
  EXPECT_THROW(GapConductanceLaw{spec}, InputError);
}

// Conduction flux derivatives against central differences, away from table kinks (x = 0.5,
// Tbar = 37.5 lies inside one interval of each variable). q is quadratic in the temperatures and
// linear in x there, so the central differences are exact up to round-off ~ eps |q| / h ~ 1e-10;
// the tolerance 1e-7 leaves room for that and still catches a missing dk/dT term (~ 0.6 here).
TEST(GapThermalLaws, ConductionDerivativesMatchCentralDifferences) {
  const GapConductanceLaw law(two_groups());
  const double Ta = 50.0, Tb = 25.0, x = 0.5;
  const GapFluxValue f = law.conduction(Ta, Tb, x);
  const double h = 1e-4;
  EXPECT_NEAR(f.dq_dTa, central([&](double t) { return law.conduction(t, Tb, x).q; }, Ta, h), 1e-7);
  EXPECT_NEAR(f.dq_dTb, central([&](double t) { return law.conduction(Ta, t, x).q; }, Tb, h), 1e-7);
  EXPECT_NEAR(f.dq_dx, central([&](double s) { return law.conduction(Ta, Tb, s).q; }, x, h), 1e-7);
  EXPECT_GT(std::abs(f.dq_dTa - law.evaluate(x, 37.5).k), 0.1); // the dk/dT term is present
}

// ------------------------------------------------------------------------- radiation

TEST(GapThermalLaws, RadiationNeedsPhysicalConstants) {
  const auto spec = radiation(0.5, {1.0}, {0.0});
  PhysicalConstants none;
  EXPECT_THROW(GapRadiationLaw(spec, none), InputError);
  PhysicalConstants only_zero;
  only_zero.absolute_zero = -273.15;
  try {
    GapRadiationLaw law(spec, only_zero);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("STEFAN BOLTZMANN"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("*PHYSICAL CONSTANTS"), std::string::npos) << e.what();
  }
}

// Spec §4.2 / §6.3 T4: eps = 0.45167 on both sides, F = 1, sigma = 0.1714e-8 gives
// C = sigma / (2 / 0.45167 - 1) = 4.99998e-10.
TEST(GapThermalLaws, RadiationCoefficientOfSpecT4) {
  const GapRadiationLaw law(radiation(0.45167, {1.0, 1.0}, {0.0, 1.0}),
                            constants(-460.0, 0.1714e-8));
  EXPECT_NEAR(law.coefficient(0.0), 4.99998e-10, 1e-15);
  EXPECT_NEAR(law.coefficient(0.0), 5.0e-10, 1e-14);
}

// Radiation derivatives with a view factor that varies with the clearance (F = 0.8 - 0.3 h on
// [0, 1]): q is a polynomial in T_A, T_B and linear in h inside the interval; relative tolerance
// 1e-8 against central differences with h = 1e-3 (truncation of the quartic: h^2 |q'''| / 6
// relative ~ 1e-9).
TEST(GapThermalLaws, RadiationDerivativesMatchCentralDifferences) {
  const GapRadiationLaw law(radiation(0.6, {0.8, 0.5}, {0.0, 1.0}), constants(-273.15, 5.67e-8));
  const double Ta = 500.0, Tb = 300.0, h = 0.4;
  const GapFluxValue f = law.evaluate(Ta, Tb, h);
  const double step = 1e-3;
  auto rel = [](double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); };
  EXPECT_LT(rel(f.dq_dTa, central([&](double t) { return law.evaluate(t, Tb, h).q; }, Ta, step)),
            1e-8);
  EXPECT_LT(rel(f.dq_dTb, central([&](double t) { return law.evaluate(Ta, t, h).q; }, Tb, step)),
            1e-8);
  EXPECT_LT(rel(f.dq_dx, central([&](double s) { return law.evaluate(Ta, Tb, s).q; }, h, step)),
            1e-8);
  // q = C [(T_A - T_Z)^4 - (T_B - T_Z)^4], C = (0.8 - 0.12) 5.67e-8 / (2/0.6 - 1).
  const double C = 0.68 * 5.67e-8 / (2.0 / 0.6 - 1.0);
  EXPECT_NEAR(f.q, C * (std::pow(773.15, 4) - std::pow(573.15, 4)), 1e-9 * std::abs(f.q));
  // Outside the view-factor table F is constant: no clearance derivative.
  EXPECT_EQ(law.evaluate(Ta, Tb, 2.0).dq_dx, 0.0);
}

// ------------------------------------------------------------------------- heat generation

TEST(GapThermalLaws, HeatGenerationSplitsTheDissipation) {
  GapHeatGenerationSpec spec;
  spec.eta = 0.9;
  spec.fraction = 0.25;
  const GapHeatGeneration g(spec);
  // Spec §0b: node 1 gets f eta r, node 2 (1 - f) eta r.
  const HeatSplit s = g.split(40.0);
  EXPECT_DOUBLE_EQ(s.node1, 0.25 * 0.9 * 40.0);
  EXPECT_DOUBLE_EQ(s.node2, 0.75 * 0.9 * 40.0);
  // Spec T5: N = 100, mu = 0.3, speed v -> r = 30 v; f = 0.5, eta = 1: 15 v to each node.
  const HeatSplit t5 = GapHeatGeneration(1.0, 0.5).split(30.0 * 2.0);
  EXPECT_DOUBLE_EQ(t5.node1, 30.0);
  EXPECT_DOUBLE_EQ(t5.node2, 30.0);
}

// ------------------------------------------------------------------------- spec §6.3 T1-T4

// T1: DGAP alone between 100 and 50, d = 0, k = 10: heat flux 500.
TEST(GapThermalLaws, SpecT1ConductionAcrossClosedGap) {
  const GapConductanceLaw law(constant_table());
  EXPECT_DOUBLE_EQ(law.conduction(100.0, 50.0, 0.0).q, 500.0);
}

/// Temperature of the node between a conductor (k = 1, A = 1, L = 0.95) held at 100 and a gap to
/// 50: the root of (100 - T_B) / 0.95 = q_gap(T_B, 50), found by bisection (q_gap increases with
/// T_B, the conductor flux decreases).
double series_temperature(const std::function<double(double)>& q_gap) {
  double lo = 50.0, hi = 100.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    ((100.0 - mid) / 0.95 > q_gap(mid) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// T2: conductor then gap conductance 10: q = 50 / (0.95 + 0.1) = 47.619, T_B = 54.762.
TEST(GapThermalLaws, SpecT2ConductorInSeriesWithGap) {
  const GapConductanceLaw law(constant_table());
  const double TB = series_temperature([&](double t) { return law.conduction(t, 50.0, 0.0).q; });
  EXPECT_NEAR(TB, 50.0 + 50.0 / (0.95 + 0.1) / 10.0, 1e-9); // T_B = 50 + q / k_gap
  EXPECT_NEAR(TB, 54.762, 5e-4);
  EXPECT_NEAR(law.conduction(TB, 50.0, 0.0).q, 47.619, 5e-4);
}

// T3: clearance 2 lies past the last table clearance 1: no conduction, q = 0, T_B = 100.
TEST(GapThermalLaws, SpecT3OpenGapBeyondTableConductsNothing) {
  const GapConductanceLaw law(constant_table());
  EXPECT_EQ(law.conduction(100.0, 50.0, 2.0).q, 0.0);
  const double TB = series_temperature([&](double t) { return law.conduction(t, 50.0, 2.0).q; });
  EXPECT_NEAR(TB, 100.0, 1e-9);
}

// T4: conductor then gap radiation with C = 5e-10, T_Z = -460: T_B = 88.988, q = 11.591 (spec).
TEST(GapThermalLaws, SpecT4ConductorInSeriesWithGapRadiation) {
  const GapRadiationLaw law(radiation(0.45167, {1.0, 1.0}, {0.0, 1.0}),
                            constants(-460.0, 0.1714e-8));
  const double TB = series_temperature([&](double t) { return law.evaluate(t, 50.0, 0.0).q; });
  EXPECT_NEAR(TB, 88.988, 5e-4);
  EXPECT_NEAR(law.evaluate(TB, 50.0, 0.0).q, 11.591, 5e-4);
  EXPECT_NEAR((100.0 - TB) / 0.95, law.evaluate(TB, 50.0, 0.0).q, 1e-9);
}

} // namespace
} // namespace gapfem::test
