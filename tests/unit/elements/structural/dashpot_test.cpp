// DASHPOT1 / DASHPOT2 / DASHPOTA kernels and the ALPHA damping of MASS elements: forces and signs,
// the damping block, the tangent against central differences in both of the dashpot's paths
// (static step: v = (u - u_start) / dt, the kernel's own; steps with rates: the assembler's C v
// plus the kernel's rest), NONLINEAR tables and their constant extrapolation.
#include "elements/structural/point_inertia.hpp"
#include "structural_test_support.hpp"

#include <cmath>

namespace gapfem::structural_test {
namespace {

/// A dashpot property: linear c, or (nonlinear) the table (force, velocity).
PropertyRef add_dashpot(TestModel& tm, int dof1, int dof2, double c,
                        std::vector<std::pair<double, double>> table = {}) {
  SpringSection s;
  s.elset = "D";
  s.dashpot = true;
  s.dof1 = dof1;
  s.dof2 = dof2;
  s.stiffness.n_values = 1;
  s.stiffness.values.push_back(c);
  s.nonlinear = !table.empty();
  for (auto [F, w] : table) {
    s.force.push_back(F);
    s.relative.push_back(w);
  }
  s.loc = {"test.inp", 7, "*DASHPOT"};
  tm.model.spring_sections.push_back(s);
  return {PropertyRef::Kind::Spring,
          static_cast<std::int32_t>(tm.model.spring_sections.size() - 1)};
}

const std::vector<std::pair<double, double>> kTable = {
    {-3.0, -2.0}, {-1.0, -0.5}, {0.0, 0.0}, {0.5, 1.0}, {1.2, 3.0}};

/// The static-step context: fixed increment dt, no rates.
void static_step(KernelProbe& p, double dt) {
  p.ctx.procedure = Procedure::Static;
  p.ctx.dt = dt;
}

TEST(StructuralDashpot, Dashpot2InAStaticStepUsesTheIncrementOverDt) {
  TestModel tm;
  const NodeId a = tm.add_node({0, 0, 0}), b = tm.add_node({1, 0, 0});
  const ElemId e = tm.add_element(ElementType::DASHPOT2, {a, b}, add_dashpot(tm, 2, 3, 4.0));
  KernelProbe p = tm.probe(e);
  ASSERT_EQ(p.kernel->n_dofs(), 2);
  EXPECT_TRUE(p.kernel->has_damping());
  EXPECT_FALSE(p.kernel->has_mass());
  EXPECT_EQ(p.kernel->node_dofs(1)[0], DofType::U3);
  static_step(p, 0.5);
  p.u0 = {0.1, 0.0};
  p.u = {0.3, 0.1};
  // w = (0.2 - 0.1) / 0.5 = 0.2, F = 0.8: +F on node 1, -F on node 2; K = c/dt [1 -1; -1 1]
  const KernelResult r = p.evaluate();
  EXPECT_NEAR(r.r[0], 0.8, 1e-14);
  EXPECT_NEAR(r.r[1], -0.8, 1e-14);
  EXPECT_NEAR(r.k(0, 0), 8.0, 1e-14);
  EXPECT_NEAR(r.k(0, 1), -8.0, 1e-14);
  EXPECT_NEAR(p.recover().find(ElemVar::S)->values[0], 0.8, 1e-14);
  EXPECT_NEAR(p.recover().find(ElemVar::E)->values[0], 0.2, 1e-15);
  expect_fd_tangent(p);
  // a dynamic step that gives no velocity (an operator-less evaluation): no force
  p.ctx.procedure = Procedure::Dynamic;
  for (double f : p.evaluate().r) EXPECT_EQ(f, 0.0);
}

TEST(StructuralDashpot, TangentsAgainstDifferencesInStaticSteps) {
  for (const bool nonlinear : {false, true})
    for (const bool nlgeom : {false, true}) {
      TestModel tm;
      const NodeId a = tm.add_node({0.1, -0.2, 0.3}), b = tm.add_node({1.2, 0.7, -0.4});
      const ElemId e =
          tm.add_element(ElementType::DASHPOTA, {a, b},
                         add_dashpot(tm, 0, 0, 3.0, nonlinear ? kTable : decltype(kTable){}));
      KernelProbe p = tm.probe(e);
      static_step(p, 0.2);
      p.ctx.nlgeom = nlgeom;
      p.u0 = {0.01, 0.02, -0.03, 0.05, -0.01, 0.02};
      p.u = {0.03, -0.04, 0.01, 0.21, 0.13, -0.05};
      SCOPED_TRACE(::testing::Message() << "nonlinear " << nonlinear << " nlgeom " << nlgeom);
      expect_fd_tangent(p);
      expect_revert_is_exact(p);
    }
}

/// The whole damping force of a kernel in a step with rates: what the assembler forms from the
/// kernel's output (its residual + C v, its tangent + v_du C) at the trial u, v from the rates'
/// map of (u - u_start, v_start, a_start).
struct Total {
  std::vector<double> r, K;
};
Total with_rates(KernelProbe& p, const std::vector<double>& v0, const std::vector<double>& a0) {
  const auto n = static_cast<std::size_t>(p.n());
  const RateCoefficients& c = p.ctx.rates;
  std::vector<double> v(n), C(n * n, 0.0);
  for (std::size_t k = 0; k < n; ++k) v[k] = c.velocity(p.u[k] - p.u0[k], v0[k], a0[k]);
  Total t{std::vector<double>(n, 0.0), std::vector<double>(n * n, 0.0)};
  ElementOutput out;
  out.residual = t.r;
  out.tangent = t.K;
  out.damping = C;
  out.want_damping = true;
  ElementInput in = p.input();
  in.v = v;
  in.v_start = v0;
  in.a_start = a0;
  p.kernel->evaluate(in, out);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      t.r[i] += C[i * n + j] * v[j];
      t.K[i * n + j] += c.v_du * C[i * n + j];
    }
  return t;
}

TEST(StructuralDashpot, TangentsAgainstDifferencesWithTheIntegratorsRates) {
  for (const bool nonlinear : {false, true})
    for (const bool nlgeom : {false, true}) {
      TestModel tm;
      const NodeId a = tm.add_node({0.1, -0.2, 0.3}), b = tm.add_node({1.2, 0.7, -0.4});
      const ElemId e =
          tm.add_element(ElementType::DASHPOTA, {a, b},
                         add_dashpot(tm, 0, 0, 3.0, nonlinear ? kTable : decltype(kTable){}));
      KernelProbe p = tm.probe(e);
      p.ctx.procedure = Procedure::Dynamic;
      p.ctx.nlgeom = nlgeom;
      // Newmark (beta = 1/4, gamma = 1/2) over h = 0.1: v = 2/h du - v0
      p.ctx.rates.first_order = p.ctx.rates.second_order = true;
      p.ctx.rates.v_du = 20.0;
      p.ctx.rates.v_v = -1.0;
      p.u0 = {0.01, 0.02, -0.03, 0.05, -0.01, 0.02};
      p.u = {0.03, -0.04, 0.01, 0.08, 0.03, -0.05};
      const std::vector<double> v0 = {0.1, -0.3, 0.2, 0.4, 0.1, -0.2}, a0(6, 0.0);
      SCOPED_TRACE(::testing::Message() << "nonlinear " << nonlinear << " nlgeom " << nlgeom);
      const Total base = with_rates(p, v0, a0);
      const std::vector<double> keep = p.u;
      const double h = 1e-6;
      double worst = 0.0, scale = 0.0;
      for (double k : base.K) scale = std::max(scale, std::abs(k));
      for (std::size_t j = 0; j < 6; ++j) {
        p.u = keep;
        p.u[j] += h;
        const Total plus = with_rates(p, v0, a0);
        p.u[j] = keep[j] - h;
        const Total minus = with_rates(p, v0, a0);
        for (std::size_t i = 0; i < 6; ++i)
          worst = std::max(worst, std::abs((plus.r[i] - minus.r[i]) / (2 * h) - base.K[i * 6 + j]));
      }
      p.u = keep;
      // central differences of a smooth residual: truncation ~ h^2 F''' and round-off ~ eps F / h
      EXPECT_LT(worst, 1e-6 * scale);
    }
}

TEST(StructuralDashpot, NonlinearTableForceAndConstantExtrapolation) {
  TestModel tm;
  const NodeId a = tm.add_node({0, 0, 0});
  const ElemId e = tm.add_element(ElementType::DASHPOT1, {a}, add_dashpot(tm, 1, 0, 0.0, kTable));
  KernelProbe p = tm.probe(e);
  static_step(p, 1.0);
  // inside: w = 2 between (1, 0.5) and (3, 1.2): F = 0.5 + 0.35 = 0.85, dF/dw = 0.35
  p.u = {2.0};
  KernelResult r = p.evaluate();
  EXPECT_NEAR(r.r[0], 0.85, 1e-14);
  EXPECT_NEAR(r.k(0, 0), 0.35, 1e-14);
  // beyond the table: the last force, no slope (Abaqus/Standard's constant extrapolation)
  p.u = {5.0};
  r = p.evaluate();
  EXPECT_NEAR(r.r[0], 1.2, 1e-14);
  EXPECT_EQ(r.k(0, 0), 0.0);
  p.u = {-4.0};
  EXPECT_NEAR(p.evaluate().r[0], -3.0, 1e-14);
}

TEST(StructuralDashpot, LinearTableIsTheLinearDashpot) {
  TestModel tm;
  const NodeId a = tm.add_node({0, 0, 0}), b = tm.add_node({0.6, 0.8, 0});
  const ElemId lin = tm.add_element(ElementType::DASHPOTA, {a, b}, add_dashpot(tm, 0, 0, 2.5));
  const ElemId tab = tm.add_element(ElementType::DASHPOTA, {a, b},
                                    add_dashpot(tm, 0, 0, 0.0, {{-25.0, -10.0}, {25.0, 10.0}}));
  for (const bool nlgeom : {false, true}) {
    KernelProbe p = tm.probe(lin), q = tm.probe(tab);
    for (KernelProbe* k : {&p, &q}) {
      static_step(*k, 0.1);
      k->ctx.nlgeom = nlgeom;
      k->u = {0.01, -0.02, 0.03, 0.04, 0.05, -0.01};
    }
    const KernelResult rp = p.evaluate(), rq = q.evaluate();
    for (std::size_t i = 0; i < rp.r.size(); ++i) EXPECT_NEAR(rq.r[i], rp.r[i], 1e-12);
    for (std::size_t i = 0; i < rp.K.size(); ++i) EXPECT_NEAR(rq.K[i], rp.K[i], 1e-12);
  }
}

TEST(StructuralDashpot, MassAlphaGivesTheDampingBlockAlphaM) {
  MassSection s;
  s.mass = 2.0;
  s.alpha = 0.3;
  const PointInertiaKernel k(ElementType::MASS, s, ModelSpace::ThreeD);
  EXPECT_TRUE(k.has_damping());
  std::vector<double> r(3), K(9), M(9), C(9);
  ElementOutput out;
  out.residual = r;
  out.tangent = K;
  out.mass = M;
  out.want_mass = true;
  out.damping = C;
  out.want_damping = true;
  std::vector<Vec3> X = {{0, 0, 0}};
  std::vector<double> u(3, 0.0);
  ElementInput in;
  in.X = X;
  in.u = u;
  in.u_start = u;
  k.evaluate(in, out);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_DOUBLE_EQ(C[i * 3 + j], i == j ? 0.6 : 0.0);
  s.alpha = 0.0;
  EXPECT_FALSE(PointInertiaKernel(ElementType::MASS, s, ModelSpace::ThreeD).has_damping());
}

} // namespace
} // namespace gapfem::structural_test
