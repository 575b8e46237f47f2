// SPRING1/2 and DASHPOT1/2 with ORIENTATION= (local DOFs: spring.hpp, FixedAction), and the
// NONLINEAR spring: the DOFs an oriented element takes, its force along the local axis, the
// tangent and the dashpot's damping block against central differences (kernel_harness.hpp).
#include "structural_test_support.hpp"
#include "unit/elements/kernel_harness.hpp"

#include <cmath>
#include <numbers>

namespace gapfem::structural_test {
namespace {

/// Local axes turned by 30 degrees about z, then tilted: a general orthonormal frame.
std::array<Vec3, 3> frame() {
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  // e1 = (c, s, 0) turned about x by 0.4 rad; e3 = e1 x e2
  const double cx = std::cos(0.4), sx = std::sin(0.4);
  const Vec3 e1{c, s * cx, s * sx}, e2{-s, c * cx, c * sx}, e3{0.0, -sx, cx};
  return {e1, e2, e3};
}

/// A spring (or dashpot) property on local DOFs dof1 (dof2) of `axes`; linear k or the table
/// (force, relative displacement / velocity).
PropertyRef add_oriented(TestModel& tm, bool dashpot, int dof1, int dof2, double k,
                         const std::array<Vec3, 3>& axes,
                         std::vector<std::pair<double, double>> table = {}) {
  SpringSection s;
  s.elset = "S";
  s.dashpot = dashpot;
  s.dof1 = dof1;
  s.dof2 = dof2;
  s.stiffness.n_values = 1;
  s.stiffness.values.push_back(k);
  s.nonlinear = !table.empty();
  for (auto [F, x] : table) {
    s.force.push_back(F);
    s.relative.push_back(x);
  }
  s.orientation = "OR";
  s.axes = axes;
  s.loc = {"test.inp", 7, dashpot ? "*DASHPOT" : "*SPRING"};
  tm.model.spring_sections.push_back(s);
  return {PropertyRef::Kind::Spring,
          static_cast<std::int32_t>(tm.model.spring_sections.size() - 1)};
}

double dot(const Vec3& a, const double* u) {
  return a[0] * u[0] + a[1] * u[1] + a[2] * u[2];
}

TEST(OrientedSpring, Spring1ActsAlongTheLocalAxisOnAllThreeTranslations) {
  TestModel tm;
  const auto e = frame();
  const NodeId n = tm.add_node({0, 0, 0});
  const ElemId el =
      tm.add_element(ElementType::SPRING1, {n}, add_oriented(tm, false, 2, 0, 50.0, e));
  KernelProbe p = tm.probe(el);
  ASSERT_EQ(p.kernel->n_dofs(), 3);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(p.kernel->node_dofs(0)[k], static_cast<DofType>(k));
  p.u = {0.01, -0.02, 0.03};
  // du = e2 . u, r = k du e2, K = k e2 e2^T
  const double du = dot(e[1], p.u.data());
  const KernelResult r = p.evaluate();
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(r.r[i], 50.0 * du * e[1][i], 1e-15);
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(r.k(i, j), 50.0 * e[1][i] * e[1][j], 1e-13);
  }
  EXPECT_NEAR(p.recover().find(ElemVar::E)->values[0], du, 1e-17);
  EXPECT_NEAR(p.recover().find(ElemVar::S)->values[0], 50.0 * du, 1e-15);
  // a motion normal to the local axis loads nothing
  p.u = {e[0][0] - e[2][0], e[0][1] - e[2][1], e[0][2] - e[2][2]};
  for (double f : p.evaluate().r) EXPECT_NEAR(f, 0.0, 1e-13);
  expect_fd_tangent(p);
}

TEST(OrientedSpring, Spring2UsesItsLocalDofAtEachNodeAndRotations) {
  TestModel tm;
  const auto e = frame();
  const NodeId a = tm.add_node({0, 0, 0}), b = tm.add_node({1, 0, 0});
  // local DOF 1 at node 1 against local rotation 6 (about e3) at node 2: mixed, as Abaqus allows
  const ElemId el =
      tm.add_element(ElementType::SPRING2, {a, b}, add_oriented(tm, false, 1, 6, 7.0, e));
  KernelProbe p = tm.probe(el);
  ASSERT_EQ(p.kernel->n_dofs(), 6);
  EXPECT_EQ(p.kernel->node_dofs(0)[0], DofType::U1);
  EXPECT_EQ(p.kernel->node_dofs(1)[0], DofType::UR1);
  EXPECT_EQ(p.kernel->node_dofs(1)[2], DofType::UR3);
  p.u = {0.1, 0.2, -0.1, 0.05, -0.03, 0.02};
  // du = e1 . u(1) - e3 . phi(2); r = k du [e1, -e3]
  const double du = dot(e[0], p.u.data()) - dot(e[2], p.u.data() + 3);
  const KernelResult r = p.evaluate();
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(r.r[i], 7.0 * du * e[0][i], 1e-14);
    EXPECT_NEAR(r.r[3 + i], -7.0 * du * e[2][i], 1e-14);
  }
  expect_fd_tangent(p);
  expect_revert_is_exact(p);
}

TEST(OrientedSpring, NonlinearSpringAlongTheLocalAxis) {
  TestModel tm;
  const auto e = frame();
  const NodeId a = tm.add_node({0, 0, 0}), b = tm.add_node({1, 0, 0});
  const std::vector<std::pair<double, double>> table = {
      {-2.0, -0.1}, {0.0, 0.0}, {1.0, 0.05}, {1.5, 0.2}};
  const ElemId el =
      tm.add_element(ElementType::SPRING2, {a, b}, add_oriented(tm, false, 3, 3, 0.0, e, table));
  KernelProbe p = tm.probe(el);
  // du = e3 . (u(1) - u(2)) = 0.1: between (0.05, 1) and (0.2, 1.5): F = 1 + 0.05/0.15 * 0.5
  const Vec3 d{0.1 * e[2][0], 0.1 * e[2][1], 0.1 * e[2][2]};
  p.u = {d[0] + 0.3, d[1] - 0.1, d[2], 0.3, -0.1, 0.0}; // u(1) = d + q, u(2) = q
  const double du = dot(e[2], p.u.data()) - dot(e[2], p.u.data() + 3);
  ASSERT_NEAR(du, 0.1, 1e-15);
  const double F = 1.0 + (0.1 - 0.05) / 0.15 * 0.5;
  const KernelResult r = p.evaluate();
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(r.r[i], F * e[2][i], 1e-14);
  EXPECT_NEAR(p.recover().find(ElemVar::S)->values[0], F, 1e-14);
  expect_fd_tangent(p);
  // beyond the table: the last force, no stiffness (constant extrapolation)
  for (double& x : p.u) x *= 10.0;
  const KernelResult far = p.evaluate();
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(far.r[i], 1.5 * e[2][i], 1e-14);
  for (double k : far.K) EXPECT_EQ(k, 0.0);
}

TEST(OrientedSpring, PlanarSpringTakesTheInPlaneTranslations) {
  TestModel tm;
  tm.model.space = ModelSpace::Planar;
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  const std::array<Vec3, 3> e{Vec3{c, s, 0}, Vec3{-s, c, 0}, Vec3{0, 0, 1}};
  const NodeId n = tm.add_node({0, 0, 0});
  const ElemId el =
      tm.add_element(ElementType::SPRING1, {n}, add_oriented(tm, false, 1, 0, 4.0, e));
  KernelProbe p = tm.probe(el);
  ASSERT_EQ(p.kernel->n_dofs(), 2);
  p.u = {0.2, 0.1};
  const KernelResult r = p.evaluate();
  EXPECT_NEAR(r.r[0], 4.0 * (0.2 * c + 0.1 * s) * c, 1e-15);
  expect_fd_tangent(p);
  // a local axis out of the plane is an error at the *SPRING line
  TestModel bad;
  bad.model.space = ModelSpace::Planar;
  const NodeId m = bad.add_node({0, 0, 0});
  const ElemId be =
      bad.add_element(ElementType::SPRING1, {m}, add_oriented(bad, false, 1, 0, 4.0, frame()));
  try {
    (void)bad.kernel(be);
    ADD_FAILURE() << "an out-of-plane local axis was accepted";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("leaves the plane"), std::string::npos) << err.what();
  }
}

/// The dashpot's damping block C = c B B^T against differences of the force c (B . v) B in v: the
/// kernel's force at velocities v in a static step (v = (u - u_start) / dt with dt = 1) is the
/// damping force, so its tangent is C; and the block the kernel returns equals that tangent.
TEST(OrientedSpring, Dashpot2DampingBlockAndTangent) {
  for (const bool nonlinear : {false, true}) {
    TestModel tm;
    const auto e = frame();
    const NodeId a = tm.add_node({0, 0, 0}), b = tm.add_node({1, 0, 0});
    const std::vector<std::pair<double, double>> table = {
        {-3.0, -2.0}, {-1.0, -0.5}, {0.0, 0.0}, {0.5, 1.0}, {1.2, 3.0}};
    const ElemId el =
        tm.add_element(ElementType::DASHPOT2, {a, b},
                       add_oriented(tm, true, 2, 1, 3.0, e, nonlinear ? table : decltype(table){}));
    KernelProbe p = tm.probe(el);
    ASSERT_EQ(p.kernel->n_dofs(), 6);
    p.ctx.procedure = Procedure::Static;
    p.ctx.dt = 1.0;
    p.u = {0.03, -0.04, 0.01, 0.21, 0.13, -0.05};
    SCOPED_TRACE(::testing::Message() << "nonlinear " << nonlinear);
    expect_fd_tangent(p);
    expect_revert_is_exact(p);
    // the damping block at the same velocity is the static tangent (dt = 1)
    const auto n = static_cast<std::size_t>(p.n());
    std::vector<double> r(n, 0.0), K(n * n, 0.0), C(n * n, 0.0);
    ElementOutput out;
    out.residual = r;
    out.tangent = K;
    out.damping = C;
    out.want_damping = true;
    p.kernel->evaluate(p.input(), out);
    for (std::size_t i = 0; i < n * n; ++i) EXPECT_NEAR(C[i], K[i], 1e-14) << i;
    // w = e2 . v(1) - e1 . v(2); the force F(w) along [e2, -e1]
    const double w = dot(e[1], p.u.data()) - dot(e[0], p.u.data() + 3);
    // the table between (w, F) = (-0.5, -1), (0, 0) and (1, 0.5)
    ASSERT_GT(w, -0.5);
    ASSERT_LT(w, 1.0);
    const double F = !nonlinear ? 3.0 * w : w < 0.0 ? 2.0 * w : 0.5 * w;
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(r[i], F * e[1][i], 1e-14);
      EXPECT_NEAR(r[3 + i], -F * e[0][i], 1e-14);
    }
  }
}

/// In a step with rates (the operator path): what the assembler forms, the kernel's residual + C v
/// and tangent + v_du C, with v from the Newmark map of (u - u_start, v_start); its tangent against
/// central differences, linear and NONLINEAR, for an oriented DASHPOT2.
TEST(OrientedSpring, Dashpot2WithTheIntegratorsRates) {
  for (const bool nonlinear : {false, true}) {
    TestModel tm;
    const auto e = frame();
    const NodeId a = tm.add_node({0, 0, 0}), b = tm.add_node({1, 0, 0});
    const std::vector<std::pair<double, double>> table = {
        {-3.0, -2.0}, {-1.0, -0.5}, {0.0, 0.0}, {0.5, 1.0}, {1.2, 3.0}};
    const ElemId el =
        tm.add_element(ElementType::DASHPOT2, {a, b},
                       add_oriented(tm, true, 3, 2, 3.0, e, nonlinear ? table : decltype(table){}));
    KernelProbe p = tm.probe(el);
    p.ctx.procedure = Procedure::Dynamic;
    p.ctx.rates.first_order = p.ctx.rates.second_order = true;
    p.ctx.rates.v_du = 20.0; // Newmark (beta = 1/4, gamma = 1/2) over h = 0.1: v = 2/h du - v0
    p.ctx.rates.v_v = -1.0;
    p.u0 = {0.01, 0.02, -0.03, 0.05, -0.01, 0.02};
    p.u = {0.03, -0.04, 0.01, 0.08, 0.03, -0.05};
    const std::vector<double> v0 = {0.1, -0.3, 0.2, 0.4, 0.1, -0.2}, a0(6, 0.0);
    SCOPED_TRACE(::testing::Message() << "nonlinear " << nonlinear);
    const RateCoefficients& c = p.ctx.rates;
    auto total = [&](std::vector<double>& r, std::vector<double>& K) {
      std::vector<double> v(6), C(36, 0.0);
      for (std::size_t k = 0; k < 6; ++k) v[k] = c.velocity(p.u[k] - p.u0[k], v0[k], a0[k]);
      r.assign(6, 0.0);
      K.assign(36, 0.0);
      ElementOutput out;
      out.residual = r;
      out.tangent = K;
      out.damping = C;
      out.want_damping = true;
      ElementInput in = p.input();
      in.v = v;
      in.v_start = v0;
      in.a_start = a0;
      p.kernel->evaluate(in, out);
      for (std::size_t i = 0; i < 6; ++i)
        for (std::size_t j = 0; j < 6; ++j) {
          r[i] += C[i * 6 + j] * v[j];
          K[i * 6 + j] += c.v_du * C[i * 6 + j];
        }
      return v;
    };
    std::vector<double> r, K;
    const std::vector<double> v = total(r, K);
    // the force F(w) along [e3, -e2], w = e3 . v(1) - e2 . v(2)
    const double w = dot(e[2], v.data()) - dot(e[1], v.data() + 3);
    double F = 3.0 * w;
    if (nonlinear) { // the table between its rows (w, F)
      const double ws[] = {-2.0, -0.5, 0.0, 1.0, 3.0}, Fs[] = {-3.0, -1.0, 0.0, 0.5, 1.2};
      ASSERT_GT(w, ws[0]);
      ASSERT_LT(w, ws[4]);
      int k = 0;
      while (w > ws[k + 1]) ++k;
      F = Fs[k] + (w - ws[k]) / (ws[k + 1] - ws[k]) * (Fs[k + 1] - Fs[k]);
    }
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(r[i], F * e[2][i], 1e-13);
      EXPECT_NEAR(r[3 + i], -F * e[1][i], 1e-13);
    }
    const std::vector<double> keep = p.u;
    const double h = 1e-6;
    double worst = 0.0, scale = 0.0;
    for (double k : K) scale = std::max(scale, std::abs(k));
    for (std::size_t j = 0; j < 6; ++j) {
      std::vector<double> rp, rm, Kx;
      p.u = keep;
      p.u[j] += h;
      total(rp, Kx);
      p.u[j] = keep[j] - h;
      total(rm, Kx);
      for (std::size_t i = 0; i < 6; ++i)
        worst = std::max(worst, std::abs((rp[i] - rm[i]) / (2 * h) - K[i * 6 + j]));
    }
    p.u = keep;
    // piecewise linear in u away from the table's kinks: central differences exact to round-off
    // ~ eps |r| / h
    EXPECT_LT(worst, 1e-7 * scale);
  }
}

} // namespace
} // namespace gapfem::structural_test
