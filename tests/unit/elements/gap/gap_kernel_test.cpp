// Unit tests of the mechanical gap kernels: clearance formulas, status logic, and central
// finite-difference checks of the residual/tangent and of the constraint row (spec §1.2-1.4).
#include "elements/gap/mechanical_gap.hpp"
#include "gap_test_util.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <random>

using namespace gapfem;
using gapfem::test::SingleElement;
using gapfem::test::two_node_gap_model;

namespace {

GapSection section(double d, Vec3 dir = {0, 0, 0}, double area = 1.0) {
  GapSection s;
  s.d = d;
  s.direction = dir;
  s.direction_given = dir[0] != 0 || dir[1] != 0 || dir[2] != 0;
  s.area = area;
  return s;
}

const std::vector<ElemId> kOnlyElement{0};
std::unique_ptr<ElementKernel> kernel_for(const Model& m) {
  return make_gap_kernel(
      KernelContext{m, m.mesh.elem_types[0], m.element_property[0], kOnlyElement});
}

// Central differences of the residual (multiplier fixed) and of g against the tangent and the
// constraint row. h = cbrt(eps) * scale gives a truncation error O(h^2) ~ 1e-11 relative.
void check_tangent(SingleElement& el, double scale) {
  el.evaluate();
  ASSERT_EQ(el.n_constraints, 1);
  const auto K = el.K;
  const auto c = el.ccoef;
  const auto nd = el.u.size();
  const double h = std::cbrt(2.2e-16) * scale;
  const auto state = el.state;
  for (std::size_t j = 0; j < nd; ++j) {
    const double keep = el.u[j];
    el.u[j] = keep + h;
    el.state = state;
    el.evaluate();
    const auto rp = el.r;
    const double gp = el.cval[0];
    el.u[j] = keep - h;
    el.state = state;
    el.evaluate();
    const auto rm = el.r;
    const double gm = el.cval[0];
    el.u[j] = keep;
    el.state = state;
    EXPECT_NEAR((gp - gm) / (2 * h), c[j], 1e-7) << "dg/du column " << j;
    for (std::size_t i = 0; i < nd; ++i)
      EXPECT_NEAR((rp[i] - rm[i]) / (2 * h), K[i * nd + j], 1e-6 * (1 + std::abs(K[i * nd + j])))
          << "K(" << i << "," << j << ")";
  }
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
  SingleElement el(m, kernel_for(m));
  el.u = {0, -0.4, 0, 0, 0, 0}; // node 1 moves down 0.4 towards node 2: h = 0.5 + n.(u2-u1) = 0.1
  EXPECT_NEAR(el.record().clearance, 0.1, 1e-15);
  el.evaluate();
  EXPECT_EQ(el.n_constraints, 0) << "open gap has no constraint";
  el.u[1] = -0.6; // h = -0.1 → closes
  el.evaluate();
  EXPECT_EQ(el.status_changes, 1);
  EXPECT_EQ(el.n_constraints, 1);
  EXPECT_NEAR(el.cval[0], 0.1, 1e-15) << "g = -(h) = overclosure";
}

TEST(GapKernel, GivenDirectionPointingAwayNeverCloses) {
  Model m = two_node_gap_model(ElementType::GAPUNI, {0, 0, 0}, {0, -1, 0}, section(0.5, {0, 1, 0}));
  SingleElement el(m, kernel_for(m));
  el.u = {0, -1.0, 0, 0, 0, 0};
  EXPECT_NEAR(el.record().clearance, 1.5, 1e-15); // h = 0.5 + (0,1,0).(0 - (0,-1,0)) = 1.5
}

TEST(GapKernel, ComputedDirectionIsIndependentOfNodeOrder) {
  for (bool reversed : {false, true}) {
    Vec3 a{0, 0, 0}, b{0, -1, 0};
    Model m = reversed ? two_node_gap_model(ElementType::GAPUNI, b, a, section(0.5))
                       : two_node_gap_model(ElementType::GAPUNI, a, b, section(0.5));
    SingleElement el(m, kernel_for(m));
    // the node at the origin moves down by 0.4 (towards the other node)
    el.u = {0, 0, 0, 0, 0, 0};
    el.u[reversed ? 4 : 1] = -0.4;
    EXPECT_NEAR(el.record().clearance, 0.1, 1e-15) << (reversed ? "reversed" : "forward");
  }
}

TEST(GapKernel, CoincidentNodesWithoutDirectionAreRejected) {
  Model m = two_node_gap_model(ElementType::GAPUNI, {1, 1, 1}, {1, 1, 1}, section(0.5));
  SingleElement el(m, kernel_for(m));
  EXPECT_NE(el.kernel->validate(el.input()).find("direction"), std::string::npos);
}

TEST(GapKernel, CylinderAndSphereClearance) {
  // GAPCYL d>0 about the x axis: h = d - |P(x1-x2)|; axial motion does not count.
  Model m =
      two_node_gap_model(ElementType::GAPCYL, {0, 0, 0}, {0, 0, 0}, section(0.0208, {1, 0, 0}));
  SingleElement el(m, kernel_for(m));
  el.u = {5.0, 0.0115378, 0.0173066, 0, 0, 0};
  EXPECT_NEAR(el.record().clearance, 0.0208 - std::hypot(0.0115378, 0.0173066), 1e-12);
  // GAPCYL d<0: h = |P r| + d
  Model m2 =
      two_node_gap_model(ElementType::GAPCYL, {0, 2, 0}, {0, 0, 0}, section(-1.0, {1, 0, 0}));
  SingleElement e2(m2, kernel_for(m2));
  e2.u = {3.0, -0.5, 0, 0, 0, 0};
  EXPECT_NEAR(e2.record().clearance, 1.5 - 1.0, 1e-14);
  // GAPSPHER d>0: h = d - |x1 - x2|
  Model m3 = two_node_gap_model(ElementType::GAPSPHER, {0, 0, 0}, {0, 0, 0}, section(0.208));
  SingleElement e3(m3, kernel_for(m3));
  e3.u = {0.1, 0.1, 0.1, 0, 0, 0};
  EXPECT_NEAR(e3.record().clearance, 0.208 - std::sqrt(0.03), 1e-14);
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
    SingleElement el(m, kernel_for(m));
    for (auto& v : el.u) v = U(rng);
    if (c.type != ElementType::GAPUNI) el.u[1] += 0.08; // move node 1 off the axis/centre
    el.state[GapStateLayout::status] = static_cast<double>(ContactStatus::Closed);
    el.mult[0] = 37.0; // a compressive contact force
    check_tangent(el, 0.05);
  }
}

TEST(GapKernel, TensionOpensAClosedGap) {
  Model m =
      two_node_gap_model(ElementType::GAPUNI, {0, 0, 0}, {0, -1, 0}, section(0.0, {0, -1, 0}));
  SingleElement el(m, kernel_for(m));
  el.evaluate();
  EXPECT_EQ(el.n_constraints, 1) << "d = 0 starts closed";
  el.mult[0] = -1.0; // the solve produced tension
  el.evaluate();
  EXPECT_EQ(el.status_changes, 1);
  EXPECT_EQ(el.n_constraints, 0);
  EXPECT_EQ(el.mult[0], 0.0);
  for (double v : el.r) EXPECT_EQ(v, 0.0);
}

TEST(GapKernel, CcxPenaltyLawMatchesItsFormula) {
  Model m = ccx_penalty_gap_model();
  SingleElement el(m, kernel_for(m));
  el.u = {0, -1e-4, 0, 0, 0, 0}; // overclosure g = 1e-4
  const double eps = 3.141592653589793 * 1e-3 / 1e7;
  const double F = 1e7 * 1e-4 * (0.5 + std::atan(1e-4 / eps) / 3.141592653589793);
  EXPECT_NEAR(el.record().normal_force, F, 1e-9 * F);
}

TEST(GapKernel, PenaltyGapOpeningOrClosingIsABranchChangeNotAStatusChange) {
  // A force law's gap that opens or closes changes no severe-discontinuity status (Abaqus counts
  // none for softened or penalty contact), but reports the kink it crossed (printed by -v: why
  // such decks converge linearly while gaps still open and close).
  Model m = ccx_penalty_gap_model();
  SingleElement el(m, kernel_for(m));
  el.u = {0, 1e-4, 0, 0, 0, 0}; // open by 1e-4 (the zero clearance starts it closed)
  el.evaluate();
  el.evaluate();
  EXPECT_EQ(el.status_changes, 0);
  EXPECT_EQ(el.branch_changes, 0) << "open before, open now";
  el.u[1] = -1e-4; // overclosed by 1e-4: closes
  el.evaluate();
  EXPECT_EQ(el.status_changes, 0);
  EXPECT_EQ(el.branch_changes, 1);
  el.u[1] = -2e-4; // closed before, closed now
  el.evaluate();
  EXPECT_EQ(el.branch_changes, 0);
  el.u[1] = 1e-4; // opens again
  el.evaluate();
  EXPECT_EQ(el.status_changes, 0);
  EXPECT_EQ(el.branch_changes, 1);
}
