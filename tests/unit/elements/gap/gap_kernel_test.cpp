// Unit tests of the mechanical gap kernels: clearance formulas, status logic, and the kernel
// harness: central differences of the residual/tangent and of the constraint row (spec
// §1.2-1.4), revert-then-evaluate and translations.
#include "elements/gap/mechanical_gap.hpp"
#include "gap_test_util.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <random>

using namespace gapfem;
using namespace gapfem::test;

namespace {

GapSection section(double d, Vec3 dir = {0, 0, 0}, double area = 1.0) {
  GapSection s;
  s.d = d;
  s.direction = dir;
  s.direction_given = dir[0] != 0 || dir[1] != 0 || dir[2] != 0;
  s.area = area;
  return s;
}

/// A GAPUNI of zero clearance closing along -y with CalculiX's penalty law, k = 1e7, f_inf = 1e-3.
Model ccx_penalty_gap_model() {
  GapSection s = section(0.0, {0, -1, 0});
  s.ccx_penalty = true;
  s.ccx_stiffness = 1e7;
  s.ccx_tension = 1e-3;
  return two_node_gap_model(ElementType::GAPUNI, {0, 0, 0}, {0, -1, 0}, s);
}

} // namespace

TEST(GapKernel, GapuniClearanceAndSign) {
  // M1 geometry: node 1 at origin, node 2 at (0,-1,0), d = 0.5, n = (0,-1,0).
  Model m =
      two_node_gap_model(ElementType::GAPUNI, {0, 0, 0}, {0, -1, 0}, section(0.5, {0, -1, 0}));
  KernelProbe el = gap_probe(m);
  el.u = {0, -0.4, 0, 0, 0, 0}; // node 1 moves down 0.4 towards node 2: h = 0.5 + n.(u2-u1) = 0.1
  EXPECT_NEAR(gap_record(el).clearance, 0.1, 1e-15);
  EXPECT_EQ(el.evaluate().n_constraints, 0) << "open gap has no constraint";
  el.u[1] = -0.6; // h = -0.1 → closes
  const KernelResult ev = el.evaluate();
  EXPECT_EQ(ev.status_changes, 1);
  EXPECT_EQ(ev.n_constraints, 1);
  EXPECT_NEAR(ev.g[0], 0.1, 1e-15) << "g = -(h) = overclosure";
}

TEST(GapKernel, GivenDirectionPointingAwayNeverCloses) {
  Model m = two_node_gap_model(ElementType::GAPUNI, {0, 0, 0}, {0, -1, 0}, section(0.5, {0, 1, 0}));
  KernelProbe el = gap_probe(m);
  el.u = {0, -1.0, 0, 0, 0, 0};
  EXPECT_NEAR(gap_record(el).clearance, 1.5, 1e-15); // h = 0.5 + (0,1,0).(0 - (0,-1,0)) = 1.5
}

TEST(GapKernel, ComputedDirectionIsIndependentOfNodeOrder) {
  for (bool reversed : {false, true}) {
    Vec3 a{0, 0, 0}, b{0, -1, 0};
    Model m = reversed ? two_node_gap_model(ElementType::GAPUNI, b, a, section(0.5))
                       : two_node_gap_model(ElementType::GAPUNI, a, b, section(0.5));
    KernelProbe el = gap_probe(m);
    // the node at the origin moves down by 0.4 (towards the other node)
    el.u = {0, 0, 0, 0, 0, 0};
    el.u[reversed ? 4 : 1] = -0.4;
    EXPECT_NEAR(gap_record(el).clearance, 0.1, 1e-15) << (reversed ? "reversed" : "forward");
  }
}

TEST(GapKernel, CoincidentNodesWithoutDirectionAreRejected) {
  Model m = two_node_gap_model(ElementType::GAPUNI, {1, 1, 1}, {1, 1, 1}, section(0.5));
  KernelProbe el = gap_probe(m);
  EXPECT_NE(el.kernel->validate(el.input()).find("direction"), std::string::npos);
}

TEST(GapKernel, CylinderAndSphereClearance) {
  // GAPCYL d>0 about the x axis: h = d - |P(x1-x2)|; axial motion does not count.
  Model m =
      two_node_gap_model(ElementType::GAPCYL, {0, 0, 0}, {0, 0, 0}, section(0.0208, {1, 0, 0}));
  KernelProbe el = gap_probe(m);
  el.u = {5.0, 0.0115378, 0.0173066, 0, 0, 0};
  EXPECT_NEAR(gap_record(el).clearance, 0.0208 - std::hypot(0.0115378, 0.0173066), 1e-12);
  // GAPCYL d<0: h = |P r| + d
  Model m2 =
      two_node_gap_model(ElementType::GAPCYL, {0, 2, 0}, {0, 0, 0}, section(-1.0, {1, 0, 0}));
  KernelProbe e2 = gap_probe(m2);
  e2.u = {3.0, -0.5, 0, 0, 0, 0};
  EXPECT_NEAR(gap_record(e2).clearance, 1.5 - 1.0, 1e-14);
  // GAPSPHER d>0: h = d - |x1 - x2|
  Model m3 = two_node_gap_model(ElementType::GAPSPHER, {0, 0, 0}, {0, 0, 0}, section(0.208));
  KernelProbe e3 = gap_probe(m3);
  e3.u = {0.1, 0.1, 0.1, 0, 0, 0};
  EXPECT_NEAR(gap_record(e3).clearance, 0.208 - std::sqrt(0.03), 1e-14);
}

TEST(GapKernel, ClosedStateTangentMatchesFiniteDifferences) {
  struct Case {
    ElementType type;
    Vec3 X1, X2;
    GapSection sec;
  };
  const std::vector<Case> cases = {
      {ElementType::GAPUNI, {0, 0, 0}, {0.3, -1, 0.2}, section(0.0, {0.2, -1, 0.1})},
      {ElementType::GAPUNI, {0, 0, 0}, {0.3, -1, 0.2}, section(0.0)},
      {ElementType::GAPCYL, {0, 0, 0}, {0, 0, 0}, section(0.02, {1, 0.2, 0})},
      {ElementType::GAPCYL, {0.1, 1.0, 0.2}, {0, 0, 0}, section(-1.0, {1, 0, 0.3})},
      {ElementType::GAPSPHER, {0, 0, 0}, {0, 0, 0}, section(0.2)},
      {ElementType::GAPSPHER, {0.1, 1.0, 0.2}, {0, 0, 0}, section(-1.0)},
  };
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-0.05, 0.05);
  for (const auto& c : cases) {
    SCOPED_TRACE(element_info(c.type).name);
    Model m = two_node_gap_model(c.type, c.X1, c.X2, c.sec);
    KernelProbe el = gap_probe(m);
    for (auto& v : el.u) v = U(rng);
    if (c.type != ElementType::GAPUNI) el.u[1] += 0.08; // move node 1 off the axis/centre
    el.state[GapStateLayout::status] = static_cast<double>(ContactStatus::Closed);
    el.mult[0] = 37.0; // a compressive contact force
    EXPECT_EQ(expect_fd_tangent(el, {.length = 0.05}).base.n_constraints, 1);
  }
}

/// A closed gap of each type with elastic-slip friction: overclosed by 0.01 and slid sideways a
/// little (stick), closed by a multiplier or, with `force_law`, by a linear pressure law.
struct ClosedGap {
  Model model;
  std::vector<double> u;
};
ClosedGap closed_gap(ElementType type, bool force_law) {
  const bool uni = type == ElementType::GAPUNI;
  GapSection s = section(uni ? 0.0 : 0.5, uni                           ? Vec3{0, -1, 0}
                                          : type == ElementType::GAPCYL ? Vec3{1, 0, 0}
                                                                        : Vec3{0, 0, 0});
  s.friction.given = true;
  s.friction.rows = {{0.3, 0, 0, 0}};
  s.friction.elastic_slip = 1e-3;
  if (force_law) {
    s.behavior.given = true;
    s.behavior.law = PressureOverclosure::Linear;
    s.behavior.slope = 2e4;
  }
  // GAPUNI: node 2 below node 1, closing along -y; the others about coincident nodes, node 1
  // pushed 0.01 past the cylinder or sphere of radius 0.5 along +y
  ClosedGap c{two_node_gap_model(type, {0, 0, 0}, {0, uni ? -1.0 : 0.0, 0}, s), {}};
  c.u = {0.0004, uni ? -0.01 : 0.51, 0.0002, 0, 0, 0};
  return c;
}
/// The probe of a closed gap; coincident nodes get the closure direction +y as history.
KernelProbe closed_probe(const ClosedGap& c) {
  KernelProbe el = gap_probe(c.model);
  if (c.model.mesh.elem_types[0] != ElementType::GAPUNI)
    el.state[GapStateLayout::direction + 1] = el.state0[GapStateLayout::direction + 1] = 1.0;
  el.u = c.u;
  return el;
}

/// Runs `check` on the probe of every closed gap: each type, closed by a multiplier or a force law.
template <class Check>
void for_each_closed_gap(Check check) {
  for (ElementType type : {ElementType::GAPUNI, ElementType::GAPCYL, ElementType::GAPSPHER})
    for (bool force_law : {false, true}) {
      SCOPED_TRACE(std::string(element_info(type).name) + (force_law ? " force law" : " exact"));
      const ClosedGap c = closed_gap(type, force_law);
      KernelProbe el = closed_probe(c);
      check(el);
    }
}

// A cut-back discards an attempt exactly: the status, direction, slip and multipliers of an
// abandoned attempt leave no trace (an increment that slides the gap further from a committed
// closed state).
TEST(GapKernel, RevertIsExact) {
  for_each_closed_gap([](KernelProbe& el) {
    el.mult0[0] = 50.0;
    el.revert();
    ASSERT_GT(el.evaluate().n_constraints, 0);
    el.commit();
    el.u[0] += 0.003;
    el.u[2] -= 0.001;
    expect_revert_is_exact(el);
  });
}

// Moving both nodes alike changes nothing: clearance, status, forces, rows. A gap admits no
// rotation: a given direction stays fixed in space, a computed one is history.
TEST(GapKernel, TranslationChangesNothing) {
  for_each_closed_gap([](KernelProbe& el) {
    el.mult[0] = 40.0;
    expect_rigid_body_invariance(el, {.rotate = false});
  });
}

TEST(GapKernel, TensionOpensAClosedGap) {
  Model m =
      two_node_gap_model(ElementType::GAPUNI, {0, 0, 0}, {0, -1, 0}, section(0.0, {0, -1, 0}));
  KernelProbe el = gap_probe(m);
  EXPECT_EQ(el.evaluate().n_constraints, 1) << "d = 0 starts closed";
  el.mult[0] = -1.0; // the solve produced tension
  const KernelResult ev = el.evaluate();
  EXPECT_EQ(ev.status_changes, 1);
  EXPECT_EQ(ev.n_constraints, 0);
  EXPECT_EQ(el.mult[0], 0.0);
  for (double v : ev.r) EXPECT_EQ(v, 0.0);
}

TEST(GapKernel, CcxPenaltyLawMatchesItsFormula) {
  Model m = ccx_penalty_gap_model();
  KernelProbe el = gap_probe(m);
  el.u = {0, -1e-4, 0, 0, 0, 0}; // overclosure g = 1e-4
  const double eps = 3.141592653589793 * 1e-3 / 1e7;
  const double F = 1e7 * 1e-4 * (0.5 + std::atan(1e-4 / eps) / 3.141592653589793);
  EXPECT_NEAR(gap_record(el).normal_force, F, 1e-9 * F);
}

TEST(GapKernel, PenaltyGapOpeningOrClosingIsABranchChangeNotAStatusChange) {
  // A force law's gap that opens or closes changes no severe-discontinuity status (Abaqus counts
  // none for softened or penalty contact), but reports the kink it crossed (printed by -v: why
  // such decks converge linearly while gaps still open and close).
  Model m = ccx_penalty_gap_model();
  KernelProbe el = gap_probe(m);
  el.u = {0, 1e-4, 0, 0, 0, 0}; // open by 1e-4 (the zero clearance starts it closed)
  el.evaluate();
  KernelResult ev = el.evaluate();
  EXPECT_EQ(ev.status_changes, 0);
  EXPECT_EQ(ev.branch_changes, 0) << "open before, open now";
  el.u[1] = -1e-4; // overclosed by 1e-4: closes
  ev = el.evaluate();
  EXPECT_EQ(ev.status_changes, 0);
  EXPECT_EQ(ev.branch_changes, 1);
  el.u[1] = -2e-4; // closed before, closed now
  EXPECT_EQ(el.evaluate().branch_changes, 0);
  el.u[1] = 1e-4; // opens again
  ev = el.evaluate();
  EXPECT_EQ(ev.status_changes, 0);
  EXPECT_EQ(ev.branch_changes, 1);
}
