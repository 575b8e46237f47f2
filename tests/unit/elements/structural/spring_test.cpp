// SPRING1 / SPRING2 / SPRINGA kernels: forces, signs, NLGEOM kinematics, tangents, temperature
// dependence and the factory's DOF checks.
#include "structural_test_support.hpp"

#include <cmath>

namespace gapfem::structural_test {
namespace {

TEST(StructuralSpring, Spring1ForceIsStiffnessTimesDisplacement) {
  TestModel tm;
  const NodeId n = tm.add_node({0, 0, 0});
  const ElemId e = tm.add_element(ElementType::SPRING1, {n}, tm.add_spring(2, 0, {{250.0, 0.0}}));
  KernelProbe el = tm.probe(e);
  const auto& k = el.kernel;
  ASSERT_EQ(k->n_dofs(), 1);
  EXPECT_EQ(k->node_dofs(0)[0], DofType::U2);
  el.u[0] = 0.02;
  const KernelResult ev = el.evaluate();
  EXPECT_DOUBLE_EQ(ev.r[0], 5.0); // 250 * 0.02
  EXPECT_DOUBLE_EQ(ev.k(0, 0), 250.0);
  const ElementRecovery rec = el.recover();
  EXPECT_DOUBLE_EQ(rec.find(ElemVar::S)->values[0], 5.0);
  EXPECT_DOUBLE_EQ(rec.find(ElemVar::E)->values[0], 0.02);
}

TEST(StructuralSpring, Spring2UsesItsOwnDofAtEachNodeAndAbaqusSign) {
  TestModel tm;
  const NodeId a = tm.add_node({0, 0, 0}), b = tm.add_node({1, 0, 0});
  const ElemId e = tm.add_element(ElementType::SPRING2, {a, b}, tm.add_spring(2, 3, {{100.0, 0}}));
  KernelProbe el = tm.probe(e);
  const auto& k = el.kernel;
  ASSERT_EQ(k->n_dofs(), 2);
  EXPECT_EQ(k->node_dofs(0)[0], DofType::U2);
  EXPECT_EQ(k->node_dofs(1)[0], DofType::U3);
  el.u = {0.3, 0.1};
  // Abaqus: du = u_i(node 1) - u_j(node 2) = 0.2, F = 20; internal force +F on node 1, -F on 2.
  const KernelResult ev = el.evaluate();
  EXPECT_NEAR(ev.r[0], 20.0, 1e-12);
  EXPECT_NEAR(ev.r[1], -20.0, 1e-12);
  EXPECT_DOUBLE_EQ(ev.k(0, 1), -100.0);
  EXPECT_DOUBLE_EQ(ev.k(1, 1), 100.0);
  const ElementRecovery rec = el.recover();
  EXPECT_NEAR(rec.find(ElemVar::S)->values[0], 20.0, 1e-12);
  EXPECT_NEAR(rec.find(ElemVar::E)->values[0], 0.2, 1e-15);
}

TEST(StructuralSpring, SpringAActsAlongInitialLineWithoutNlgeom) {
  TestModel tm;
  const NodeId a = tm.add_node({0, 0, 0}), b = tm.add_node({3, 4, 0});
  const ElemId e = tm.add_element(ElementType::SPRINGA, {a, b}, tm.add_spring(0, 0, {{10.0, 0}}));
  KernelProbe el = tm.probe(e);
  const auto& k = el.kernel;
  ASSERT_EQ(k->n_dofs(), 6);
  el.u = {0, 0, 0, 0.1, 0.2, 0.5};
  // n0 = (0.6, 0.8, 0): du = 0.06 + 0.16 = 0.22 (the z motion is transverse), F = 2.2.
  const KernelResult ev = el.evaluate();
  const double F = 2.2, n0[3] = {0.6, 0.8, 0.0};
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(ev.r[i], -F * n0[i], 1e-12);
    EXPECT_NEAR(ev.r[3 + i], F * n0[i], 1e-12);
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(ev.k(3 + i, 3 + j), 10.0 * n0[i] * n0[j], 1e-12);
  }
  EXPECT_NEAR(el.recover().find(ElemVar::E)->values[0], 0.22, 1e-14);
}

TEST(StructuralSpring, SpringAWithNlgeomFollowsTheCurrentLine) {
  TestModel tm;
  const NodeId a = tm.add_node({0, 0, 0}), b = tm.add_node({2, 0, 0});
  const ElemId e = tm.add_element(ElementType::SPRINGA, {a, b}, tm.add_spring(0, 0, {{10.0, 0}}));
  KernelProbe el = tm.probe(e);
  el.ctx.nlgeom = true;
  // Rigid rotation by 90 degrees about z: node 2 goes to (0, 2, 0): no force.
  el.u = {0, 0, 0, -2, 2, 0};
  for (double r : el.evaluate().r) EXPECT_NEAR(r, 0.0, 1e-12);
  // Rotation plus stretch to length 3: F = k (3 - 2) = 10 along the current line (0, 1, 0).
  el.u = {0, 0, 0, -2, 3, 0};
  const KernelResult ev = el.evaluate();
  EXPECT_NEAR(ev.r[1], -10.0, 1e-12);
  EXPECT_NEAR(ev.r[4], 10.0, 1e-12);
  EXPECT_NEAR(ev.r[3], 0.0, 1e-12);
  // Geometric stiffness: transverse stiffness F / l = 10 / 3 at node 2 in x.
  EXPECT_NEAR(ev.k(3, 3), 10.0 / 3.0, 1e-12);
}

// SPRINGA: the tangent by central differences, revert-then-evaluate, and rigid motions (small:
// an infinitesimal rotation; NLGEOM: the spring follows its line, the force turns with it).
TEST(StructuralSpring, SpringAKernelChecks) {
  for (bool nlgeom : {false, true}) {
    SCOPED_TRACE(nlgeom ? "NLGEOM" : "small");
    TestModel tm;
    const NodeId a = tm.add_node({0.1, -0.2, 0.3}), b = tm.add_node({1.2, 0.7, -0.4});
    const ElemId e = tm.add_element(ElementType::SPRINGA, {a, b}, tm.add_spring(0, 0, {{7.0, 0}}));
    KernelProbe el = tm.probe(e);
    el.ctx.nlgeom = nlgeom;
    el.u = {0.05, -0.3, 0.2, 0.4, 0.1, -0.25};
    expect_fd_tangent(el);
    expect_revert_is_exact(el);
    expect_rigid_body_invariance(el);
  }
}

// SPRING1 is grounded (no rigid motion); SPRING2 between the same DOF of its two nodes moves
// rigidly along that DOF, between different DOFs it does not.
TEST(StructuralSpring, Spring1AndSpring2KernelChecks) {
  TestModel tm;
  const NodeId a = tm.add_node({0, 0, 0}), b = tm.add_node({1, 0, 0});
  const ElemId e1 = tm.add_element(ElementType::SPRING1, {a}, tm.add_spring(5, 0, {{3.0, 0}}));
  const ElemId e2 = tm.add_element(ElementType::SPRING2, {a, b}, tm.add_spring(1, 2, {{5.0, 0}}));
  const ElemId e3 = tm.add_element(ElementType::SPRING2, {a, b}, tm.add_spring(2, 2, {{5.0, 0}}));
  for (ElemId e : {e1, e2, e3}) {
    KernelProbe el = tm.probe(e);
    for (std::size_t i = 0; i < el.u.size(); ++i) el.u[i] = 0.1 * (i + 1);
    expect_fd_tangent(el);
    expect_revert_is_exact(el);
  }
  KernelProbe same = tm.probe(e3);
  same.u = {0.3, 0.1};
  expect_rigid_body_invariance(same, {.rotate = false});
}

TEST(StructuralSpring, SpringAInPlanarModelUsesDofsOneAndTwo) {
  TestModel tm;
  tm.model.space = ModelSpace::Planar;
  const NodeId a = tm.add_node({0, 0, 0}), b = tm.add_node({1, 1, 0});
  const ElemId e = tm.add_element(ElementType::SPRINGA, {a, b}, tm.add_spring(0, 0, {{4.0, 0}}));
  KernelProbe el = tm.probe(e);
  const auto& k = el.kernel;
  ASSERT_EQ(k->n_dofs(), 4);
  EXPECT_EQ(k->node_dofs(1)[1], DofType::U2);
  el.ctx.nlgeom = true;
  el.u = {0, 0, 0.3, -0.1};
  expect_fd_tangent(el);
  expect_revert_is_exact(el);
  expect_rigid_body_invariance(el); // in plane, about z
}

TEST(StructuralSpring, StiffnessInterpolatedAtAverageTemperature) {
  TestModel tm;
  const NodeId a = tm.add_node({0, 0, 0}), b = tm.add_node({1, 0, 0});
  const ElemId e =
      tm.add_element(ElementType::SPRING2, {a, b}, tm.add_spring(1, 1, {{100, 0}, {200, 100}}));
  KernelProbe el = tm.probe(e);
  const auto& k = el.kernel;
  EXPECT_TRUE(k->uses_temperature_field());
  el.u = {0.01, 0.0};
  // Without a temperature field: first row, k = 100.
  EXPECT_NEAR(el.evaluate().r[0], 1.0, 1e-12);
  // Nodes at 40 and 60: average 50, k = 150 by linear interpolation.
  el.T = {40.0, 60.0};
  el.Ti = {0.0, 0.0};
  EXPECT_NEAR(el.evaluate().r[0], 1.5, 1e-12);
}

TEST(StructuralSpring, DofThreeOrRotationInPlanarModelIsInputErrorAtTheSpringLine) {
  for (int dof : {3, 4, 6}) {
    TestModel tm;
    tm.model.space = ModelSpace::Planar;
    const NodeId n = tm.add_node({0, 0, 0});
    const ElemId e = tm.add_element(ElementType::SPRING1, {n}, tm.add_spring(dof, 0, {{1.0, 0}}));
    try {
      tm.kernel(e);
      ADD_FAILURE() << "DOF " << dof << " accepted in a planar model";
    } catch (const InputError& err) {
      EXPECT_EQ(err.location().keyword, "*SPRING");
      EXPECT_EQ(err.location().line, 7);
      EXPECT_NE(std::string(err.what()).find("does not exist"), std::string::npos) << err.what();
    }
  }
  // The same DOFs are fine in a 3-D model; DOF 11 is not a spring DOF anywhere.
  TestModel tm;
  const NodeId a = tm.add_node({0, 0, 0}), b = tm.add_node({1, 0, 0});
  EXPECT_NO_THROW(
      tm.kernel(tm.add_element(ElementType::SPRING2, {a, b}, tm.add_spring(3, 6, {{1, 0}}))));
  EXPECT_THROW(tm.kernel(tm.add_element(ElementType::SPRING1, {a}, tm.add_spring(11, 0, {{1, 0}}))),
               InputError);
}

TEST(StructuralSpring, CoincidentSpringANodesFailValidation) {
  TestModel tm;
  const NodeId a = tm.add_node({1, 1, 1}), b = tm.add_node({1, 1, 1});
  const ElemId e = tm.add_element(ElementType::SPRINGA, {a, b}, tm.add_spring(0, 0, {{1, 0}}));
  KernelProbe el = tm.probe(e);
  EXPECT_NE(el.kernel->validate(el.input()).find("coincide"), std::string::npos);
}

TEST(StructuralSpring, MissingSpringPropertyIsInputError) {
  TestModel tm;
  const NodeId n = tm.add_node({0, 0, 0});
  const ElemId e = tm.add_element(ElementType::SPRING1, {n}, PropertyRef{});
  EXPECT_THROW(tm.kernel(e), InputError);
}

} // namespace
} // namespace gapfem::structural_test
