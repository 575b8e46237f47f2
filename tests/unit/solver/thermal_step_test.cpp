// The thermal step rules (solver/thermal_step.hpp) and the accuracy retry of the increment
// controller: Abaqus's DELTMX rule, fixed transient increments, the largest free temperature
// change, initial temperatures and the procedure checks.
#include "fem/dof_map.hpp"
#include "model/model.hpp"
#include "solver/increment_control.hpp"
#include "solver/thermal_step.hpp"

#include <gtest/gtest.h>

namespace gapfem::test {
namespace {

// dT_max > DELTMX: redo with 0.85 DELTMX / dT_max (Abaqus's D_F = 0.85); otherwise the next
// increment may grow by DELTMX / dT_max, at most 2 (W_M of diffusion-dominated procedures).
TEST(ThermalStep, DeltmxRule) {
  const TemperatureAccuracy over = deltmx_rule(20.0, 5.0);
  EXPECT_TRUE(over.redo);
  EXPECT_DOUBLE_EQ(over.ratio, 0.85 * 5.0 / 20.0);
  const TemperatureAccuracy under = deltmx_rule(4.0, 5.0);
  EXPECT_FALSE(under.redo);
  EXPECT_DOUBLE_EQ(under.ratio, 1.25);
  EXPECT_DOUBLE_EQ(deltmx_rule(1.0, 5.0).ratio, 2.0);
  EXPECT_DOUBLE_EQ(deltmx_rule(0.0, 5.0).ratio, 2.0);
  EXPECT_FALSE(deltmx_rule(5.0, 5.0).redo); // exactly at the limit is accepted
}

TEST(ThermalStep, RetrySmallerRepeatsTheIncrementWithinTheLimits) {
  Incrementation inc;
  inc.initial = 0.1;
  inc.period = 1.0;
  inc.minimum = 0.01;
  IncrementController c(inc, 100);
  EXPECT_TRUE(c.retry_smaller(0.5));
  EXPECT_DOUBLE_EQ(c.next(), 0.05);
  EXPECT_EQ(c.attempt(), 1);
  EXPECT_DOUBLE_EQ(c.step_time(), 0.0);
  // Not below the minimum: 0.05 * 0.1 is clamped to 0.01, then no smaller size is possible.
  EXPECT_TRUE(c.retry_smaller(0.1));
  EXPECT_DOUBLE_EQ(c.next(), 0.01);
  EXPECT_FALSE(c.retry_smaller(0.5));
  EXPECT_DOUBLE_EQ(c.next(), 0.01);
  // Accepting with a growth suggestion of 2: the convergence rules allow no growth yet (one easy
  // increment), so the size stays.
  c.accept(1, 2.0);
  EXPECT_DOUBLE_EQ(c.step_time(), 0.01);
  EXPECT_DOUBLE_EQ(c.next(), 0.01);
  // A ratio below one shrinks the next increment.
  c.accept(1, 0.5);
  EXPECT_DOUBLE_EQ(c.next(), 0.01); // clamped to the minimum
  // DIRECT incrementation never retries.
  inc.direct = true;
  IncrementController d(inc, 100);
  EXPECT_FALSE(d.retry_smaller(0.5));
}

TEST(ThermalStep, RetryStopsAfterTheAttemptsOfAnIncrement) {
  Incrementation inc;
  inc.initial = 1.0;
  inc.period = 1.0;
  inc.minimum = 1e-9;
  IncrementController c(inc, 100);
  int retries = 0;
  while (c.retry_smaller(0.5)) ++retries;
  EXPECT_EQ(retries, IncrementRules{}.max_attempts - 1);
}

TEST(ThermalStep, FixedIncrementsForTransientStepsWithoutDeltmx) {
  Step s;
  s.procedure = Procedure::HeatTransfer;
  s.inc.steady_state = false;
  EXPECT_TRUE(fixed_transient_increments(s));
  s.inc.deltmx = 2.0;
  EXPECT_FALSE(fixed_transient_increments(s));
  s.inc.deltmx = 0.0;
  s.inc.steady_state = true;
  EXPECT_FALSE(fixed_transient_increments(s));
  s.procedure = Procedure::Static;
  s.inc.steady_state = false;
  EXPECT_FALSE(fixed_transient_increments(s));
}

// Two nodes: node 0 carries U1 and NT, node 1 NT only. Slots: (0, U1), (0, NT), (1, NT).
TEST(ThermalStep, TemperatureChangeAndInitialTemperatures) {
  const DofMap dofs({dof_bit(DofType::U1) | dof_bit(DofType::NT), dof_bit(DofType::NT)});
  ASSERT_EQ(dofs.n_slots(), 3);
  Model m;
  m.initial_temperature = {15.0, 25.0};
  std::vector<double> u(3, 0.0);
  set_initial_temperatures(m, dofs, u);
  EXPECT_EQ(u[0], 0.0);
  EXPECT_EQ(u[1], 15.0);
  EXPECT_EQ(u[2], 25.0);
  // Node 1's temperature is prescribed: only node 0's change (3) counts, not the displacement (9).
  const std::vector<std::uint8_t> prescribed{0, 0, 1};
  const EquationMap eqs = EquationMap::build(prescribed);
  const std::vector<double> now{9.0, 18.0, 125.0};
  EXPECT_DOUBLE_EQ(max_free_temperature_change(dofs, eqs, now, u), 3.0);
}

// Heat-transfer shells: DOFs 11, 12, 13 at node 0 (a 3-point shell), 11 at node 1 (a solid).
// Slots follow the DOF numbers; every temperature starts at the node's initial value, and a
// change of any of them counts for DELTMX.
TEST(ThermalStep, TemperaturesThroughAShellsThickness) {
  DofType d{};
  ASSERT_TRUE(dof_from_abaqus(13, d));
  EXPECT_TRUE(is_temperature(d));
  EXPECT_EQ(temperature_index(d), 2);
  EXPECT_EQ(abaqus_number(d), 13);
  EXPECT_EQ(field_of(d), Field::Temperature);
  ASSERT_TRUE(dof_from_abaqus(kMaxAbaqusDof, d));
  EXPECT_EQ(abaqus_number(d), 25);
  EXPECT_FALSE(dof_from_abaqus(26, d));
  EXPECT_FALSE(dof_from_abaqus(7, d));
  EXPECT_FALSE(is_temperature(DofType::UR3));
  const DofMap dofs(
      {dof_bit(DofType::NT) | dof_bit(temperature_dof(1)) | dof_bit(temperature_dof(2)),
       dof_bit(DofType::NT)});
  ASSERT_EQ(dofs.n_slots(), 4);
  EXPECT_EQ(dofs.max_temperature_points(), 3);
  EXPECT_EQ(dofs.slot(0, temperature_dof(2)), 2);
  EXPECT_EQ(dofs.slot(1, DofType::NT), 3);
  EXPECT_EQ(dofs.slot(1, temperature_dof(1)), -1);
  Model m;
  m.initial_temperature = {15.0, 25.0};
  std::vector<double> u(4, 0.0);
  set_initial_temperatures(m, dofs, u);
  EXPECT_EQ(u, (std::vector<double>{15.0, 15.0, 15.0, 25.0}));
  const std::vector<std::uint8_t> prescribed{0, 0, 0, 0};
  const EquationMap eqs = EquationMap::build(prescribed);
  const std::vector<double> now{15.0, 15.0, 22.0, 26.0};
  EXPECT_DOUBLE_EQ(max_free_temperature_change(dofs, eqs, now, u), 7.0);
}

} // namespace
} // namespace gapfem::test
