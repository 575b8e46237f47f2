// GAPUNIT and DGAP kernels: heat flow across the gap from the thermal laws, and the kernel
// harness: central differences of every coupled tangent term (temperature blocks, d q / d
// clearance, d q / d pressure through the normal multiplier's column when contact is exact,
// frictional heating), revert-then-evaluate and translations.
#include "elements/gap/mechanical_gap.hpp"
#include "gap_test_util.hpp"

#include <gtest/gtest.h>

using namespace gapfem;
using namespace gapfem::test;

namespace {
GapSection thermal_gapunit(bool pressure) {
  GapSection s;
  s.d = 0.0;
  s.direction = {0, -1, 0};
  s.direction_given = true;
  s.area = 2.0;
  s.area_given = true;
  s.conductance.given = true;
  s.conductance.pressure = pressure;
  if (pressure)
    s.conductance.rows = {{5.0, 0.0, 0, 0}, {25.0, 100.0, 0, 0}}; // k(p)
  else
    s.conductance.rows = {{10.0, 0.0, 0, 0}, {2.0, 0.01, 0, 0}}; // k(h)
  return s;
}
} // namespace

TEST(GapThermal, GapunitConductanceTangentOpenAndClosed) {
  for (bool pressure : {false, true}) {
    SCOPED_TRACE(pressure ? "pressure-dependent" : "clearance-dependent");
    GapSection s = thermal_gapunit(pressure);
    s.d = pressure ? 0.0 : 0.005;
    Model m = two_node_gap_model(ElementType::GAPUNIT, {0, 0, 0}, {0, -1, 0}, s);
    KernelProbe el = gap_probe(m);
    ASSERT_EQ(el.u.size(), 8u);
    el.u = {0, 0.001, 0, 130.0, 0, 0, 0, 70.0};
    if (pressure) {
      el.state[GapStateLayout::status] = static_cast<double>(ContactStatus::Closed);
      el.state0 = el.state;
      el.mult[0] = 80.0; // p = 40 → k = 5 + 20 * 0.4 = 13
    }
    const KernelResult ev = el.evaluate();
    const GapRecord g = gap_record(el);
    // h = d + n.(u2 - u1) = 0.005 + 0.001 (node 1 moves away along -n)
    const double k = pressure ? 13.0 : 10.0 + (2.0 - 10.0) * 0.006 / 0.01;
    EXPECT_NEAR(g.conductance, k, 1e-12);
    EXPECT_NEAR(g.heat_flux, k * 60.0, 1e-9);
    EXPECT_NEAR(ev.r[3], 2.0 * k * 60.0, 1e-9) << "node 1 loses A q";
    // displacement steps ~6e-9 (length 0.001, within the 0.006 clearance); the temperatures'
    // steps scale with their values (~1e-3 on 100), so the former 1e-5 round-off allowance of
    // steps ~1e-8 on temperatures is no longer needed: the harness's own tolerance applies
    expect_fd_tangent(el, {.length = 0.001});
  }
}

TEST(GapThermal, GapunitFrictionalHeatingTangent) {
  GapSection s = thermal_gapunit(false);
  s.friction.given = true;
  s.friction.rows = {{0.3, 0, 0, 0}};
  s.friction.elastic_slip = 1e-4;
  s.heat_generation.given = true;
  s.heat_generation.eta = 0.9;
  s.heat_generation.fraction = 0.25;
  s.behavior.given = true;
  s.behavior.law = PressureOverclosure::Linear;
  s.behavior.slope = 1e4;
  Model m = two_node_gap_model(ElementType::GAPUNIT, {0, 0, 0}, {0, -1, 0}, s);
  KernelProbe el = gap_probe(m);
  el.ctx.dt = 0.5;
  el.u = {0.01, -0.005, 0.002, 100.0, 0, 0, 0, 20.0}; // slipping, normal force 2 * 1e4 * 0.005
  el.evaluate();
  const GapRecord g = gap_record(el);
  ASSERT_EQ(g.status, ContactStatus::Slip);
  expect_fd_tangent(el, {.length = 1e-4});
  // the slip, dissipation and heat of an abandoned attempt leave no trace; a translation of
  // both nodes changes nothing (temperatures unchanged)
  expect_revert_is_exact(el);
  expect_rigid_body_invariance(el, {.rotate = false});
}

TEST(GapThermal, DgapUsesTheConstantClearance) {
  GapSection s;
  s.d = 0.5;
  s.area = 1.0;
  s.conductance.given = true;
  s.conductance.rows = {{10.0, 0.0, 0, 0}, {10.0, 1.0, 0, 0}};
  Model m = two_node_gap_model(ElementType::DGAP, {0, 0, 0}, {1, 0, 0}, s);
  KernelProbe el = gap_probe(m);
  el.u = {100.0, 50.0};
  const KernelResult ev = el.evaluate();
  EXPECT_NEAR(ev.r[0], 500.0, 1e-12); // T1 of the spec: q = 10 * 50
  EXPECT_NEAR(ev.r[1], -500.0, 1e-12);
  EXPECT_NEAR(gap_record(el).heat_flux, 500.0, 1e-12);
  expect_fd_tangent(el);
  expect_revert_is_exact(el);
  expect_rigid_body_invariance(el, {.frame = true}); // conducts the same wherever it is
  s.d = 2.0; // beyond the last clearance point: no conductance (spec T3)
  Model m3 = two_node_gap_model(ElementType::DGAP, {0, 0, 0}, {1, 0, 0}, s);
  KernelProbe e3 = gap_probe(m3);
  e3.u = {100.0, 50.0};
  EXPECT_EQ(e3.evaluate().r[0], 0.0);
}
