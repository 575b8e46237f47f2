// T2D2 / T3D2 kernels: axial force, rigid motions (small and NLGEOM), logarithmic strain, thermal
// strain, tangents, GRAV/body-force loads and factory errors.
#include "structural_test_support.hpp"

#include <cmath>
#include <numeric>

namespace gapfem::structural_test {
namespace {

constexpr double kE = 200e3, kNu = 0.3, kA = 3.0;

struct Truss {
  TestModel tm;
  ElemId e = -1;
  std::unique_ptr<ElementKernel> k;
  Truss(ElementType type, Vec3 X1, Vec3 X2, double alpha = 0.0, std::optional<double> rho = {}) {
    if (type == ElementType::T2D2) tm.model.space = ModelSpace::Planar;
    const NodeId a = tm.add_node(X1), b = tm.add_node(X2);
    e = tm.add_element(type, {a, b},
                       tm.add_solid_section(tm.add_material(kE, kNu, alpha, rho), kA));
    k = tm.kernel(e);
  }
  KernelProbe local() const { return tm.probe(e, *k); }
};

TEST(StructuralTruss, AxialForceIsEAOverLTimesElongation) {
  // Oblique T3D2, L = |(2, 3, 6)| = 7, n = (2, 3, 6)/7.
  Truss t(ElementType::T3D2, {0, 0, 0}, {2, 3, 6});
  KernelProbe el = t.local();
  const Vec3 n{2.0 / 7, 3.0 / 7, 6.0 / 7};
  const Vec3 transverse{3.0 / 7, -2.0 / 7, 0.0}; // orthogonal to n: no small-strain force
  for (int i = 0; i < 3; ++i) el.u[3 + i] = 0.014 * n[i] + 0.05 * transverse[i];
  const KernelResult ev = el.evaluate();
  const double N = kE * kA / 7.0 * 0.014; // = 1200
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(ev.r[i], -N * n[i], 1e-9);
    EXPECT_NEAR(ev.r[3 + i], N * n[i], 1e-9);
  }
  const ElementRecovery rec = el.recover();
  EXPECT_NEAR(rec.find(ElemVar::SF)->values[0], N, 1e-9);
  EXPECT_NEAR(rec.find(ElemVar::S)->values[0], N / kA, 1e-9);
  EXPECT_NEAR(rec.find(ElemVar::E)->values[0], 0.002, 1e-15);
}

TEST(StructuralTruss, SmallStrainRigidTranslationAndInfinitesimalRotationGiveNoForce) {
  Truss t(ElementType::T3D2, {1, 2, 3}, {4, -2, 3});
  KernelProbe el = t.local();
  // u = c + w x X with an arbitrary w: exact zero along the initial axis (linear kinematics).
  const Vec3 c{0.3, -0.2, 0.7}, w{0.01, -0.02, 0.03};
  for (int a = 0; a < 2; ++a) {
    const Vec3& X = el.X[a];
    const Vec3 wx{w[1] * X[2] - w[2] * X[1], w[2] * X[0] - w[0] * X[2], w[0] * X[1] - w[1] * X[0]};
    for (int i = 0; i < 3; ++i) el.u[3 * a + i] = c[i] + wx[i];
  }
  for (double r : el.evaluate().r) EXPECT_NEAR(r, 0.0, 1e-9);
}

TEST(StructuralTruss, NlgeomNinetyDegreeRigidRotationGivesNoForce) {
  for (ElementType type : {ElementType::T2D2, ElementType::T3D2}) {
    Truss t(type, {1, 1, 0}, {4, 1, 0});
    KernelProbe el = t.local();
    el.ctx.nlgeom = true;
    const int nd = type == ElementType::T2D2 ? 2 : 3;
    // Node 2 from (4, 1) to (1, 4): rotation by 90 degrees about node 1, plus a translation.
    el.u[0] = 0.5, el.u[1] = -0.25;
    el.u[nd] = -3.0 + 0.5, el.u[nd + 1] = 3.0 - 0.25;
    for (double r : el.evaluate().r) EXPECT_NEAR(r, 0.0, 1e-9);
    // Without NLGEOM the same motion is read as a shortening of 3 along the initial axis.
    el.ctx.nlgeom = false;
    EXPECT_NEAR(el.evaluate().r[nd], -kE * kA * 3.0 / 3.0, 1e-6);
  }
}

TEST(StructuralTruss, NlgeomForceUsesLogarithmicStrainAndConstantArea) {
  Truss t(ElementType::T3D2, {0, 0, 0}, {2, 0, 0});
  KernelProbe el = t.local();
  el.ctx.nlgeom = true;
  // Rotate to the z axis and stretch to l = 2.4: strain ln(1.2), N = E A ln(1.2) along +z.
  el.u = {0, 0, 0, -2.0, 0.0, 2.4};
  const double eps = std::log(1.2), N = kE * kA * eps;
  const KernelResult ev = el.evaluate();
  EXPECT_NEAR(ev.r[5], N, 1e-9 * N);
  EXPECT_NEAR(ev.r[2], -N, 1e-9 * N);
  EXPECT_NEAR(ev.r[3], 0.0, 1e-9);
  // Material tangent EA/l along the bar, geometric N/l across it.
  EXPECT_NEAR(ev.k(5, 5), kE * kA / 2.4, 1e-9);
  EXPECT_NEAR(ev.k(3, 3), N / 2.4, 1e-9);
  const ElementRecovery rec = el.recover();
  EXPECT_NEAR(rec.find(ElemVar::E)->values[0], eps, 1e-14);
  EXPECT_NEAR(rec.find(ElemVar::S)->values[0], kE * eps, 1e-9);
  EXPECT_NEAR(rec.find(ElemVar::SF)->values[0], N, 1e-9 * N);
}

// The tangent by central differences (thermal strain included), revert-then-evaluate, and rigid
// motions of a deformed, heated bar (small: an infinitesimal rotation; NLGEOM: a finite one).
TEST(StructuralTruss, KernelChecks) {
  for (ElementType type : {ElementType::T2D2, ElementType::T3D2})
    for (bool nlgeom : {false, true}) {
      Truss t(type, {0.2, -0.1, 0}, {1.1, 0.8, type == ElementType::T3D2 ? 0.5 : 0.0}, 1e-5);
      KernelProbe el = t.local();
      el.ctx.nlgeom = nlgeom;
      for (std::size_t i = 0; i < el.u.size(); ++i) el.u[i] = 0.05 * std::sin(1.0 + 2.0 * i);
      el.T = {150.0, 90.0};
      el.Ti = {20.0, 20.0};
      SCOPED_TRACE(std::string(element_info(type).name) + (nlgeom ? " NLGEOM" : ""));
      expect_fd_tangent(el);
      expect_revert_is_exact(el);
      expect_rigid_body_invariance(el);
    }
}

TEST(StructuralTruss, ConstrainedThermalExpansionGivesCompression) {
  const double alpha = 1.2e-5;
  Truss t(ElementType::T3D2, {0, 0, 0}, {0, 5, 0}, alpha);
  EXPECT_TRUE(t.k->uses_temperature_field());
  KernelProbe el = t.local();
  el.T = {120.0, 120.0};
  el.Ti = {20.0, 20.0};
  // Both ends held: eps = 0, sigma = -E alpha dT = -200e3 * 1.2e-5 * 100 = -240, N = -720.
  const KernelResult ev = el.evaluate();
  EXPECT_NEAR(ev.r[4], -720.0, 1e-9);
  EXPECT_NEAR(ev.r[1], 720.0, 1e-9);
  // Free expansion: u = alpha dT L = 0.006 at node 2 gives no force.
  el.u[4] = alpha * 100.0 * 5.0;
  EXPECT_NEAR(el.evaluate().r[4], 0.0, 1e-9);
}

TEST(StructuralTruss, GravityAndBodyForceLoadsSumToTheTotalForce) {
  const double rho = 7.85e-9, g = 9810.0;
  Truss t(ElementType::T3D2, {0, 0, 0}, {3, 4, 12}, 0.0, rho); // L = 13
  ASSERT_TRUE(t.k->supports_load(DistLoadKind::Gravity, 0));
  KernelProbe el = t.local();
  DistributedLoad grav;
  grav.kind = DistLoadKind::Gravity;
  grav.magnitude = g;
  grav.direction = {0.0, 0.0, -1.0};
  std::vector<double> f = el.load(grav, g, 0.0);
  const double W = rho * kA * 13.0 * g; // weight of the bar
  EXPECT_NEAR(f[2] + f[5], -W, 1e-12 * W);
  EXPECT_NEAR(f[2], f[5], 1e-15);
  EXPECT_EQ(f[0], 0.0);
  DistributedLoad by;
  by.kind = DistLoadKind::BodyForce;
  by.direction = {0.0, 1.0, 0.0};
  f = el.load(by, 2.0, 0.0);
  EXPECT_NEAR(f[1] + f[4], 2.0 * kA * 13.0, 1e-12); // force per volume * volume
}

TEST(StructuralTruss, GravityWithoutDensityIsInputError) {
  // At factory time when a step applies GRAV to the element …
  TestModel tm;
  const NodeId a = tm.add_node({0, 0, 0}), b = tm.add_node({1, 0, 0});
  const ElemId e =
      tm.add_element(ElementType::T3D2, {a, b}, tm.add_solid_section(tm.add_material(kE, kNu), kA));
  Step step;
  DistributedLoad grav;
  grav.elem = e;
  grav.kind = DistLoadKind::Gravity;
  grav.loc = {"test.inp", 42, "*DLOAD"};
  step.dloads.push_back(grav);
  tm.model.steps.push_back(step);
  try {
    tm.kernel(e);
    ADD_FAILURE() << "GRAV without *DENSITY accepted";
  } catch (const InputError& err) {
    EXPECT_EQ(err.location().line, 42);
    EXPECT_NE(err.message().find("*DENSITY"), std::string::npos);
  }
  // … and from load() when the factory could not know.
  tm.model.steps.clear();
  KernelProbe el = tm.probe(e);
  EXPECT_THROW(el.load(grav, 9.81, 0.0), InputError);
}

TEST(StructuralTruss, FactoryAndValidationErrors) {
  TestModel tm;
  const NodeId a = tm.add_node({0, 0, 0}), b = tm.add_node({0, 0, 0});
  // No *SOLID SECTION.
  EXPECT_THROW(tm.kernel(tm.add_element(ElementType::T3D2, {a, b}, PropertyRef{})), InputError);
  // Material without *ELASTIC.
  const int m = tm.add_material(kE, kNu);
  tm.model.materials[m].elastic = PropertyTable{};
  EXPECT_THROW(tm.kernel(tm.add_element(ElementType::T3D2, {a, b}, tm.add_solid_section(m, 1.0))),
               InputError);
  // Zero length.
  const ElemId e = tm.add_element(ElementType::T3D2, {a, b},
                                  tm.add_solid_section(tm.add_material(kE, kNu), 1.0));
  KernelProbe el = tm.probe(e);
  EXPECT_NE(el.kernel->validate(el.input()).find("no length"), std::string::npos);
}

} // namespace
} // namespace gapfem::structural_test
