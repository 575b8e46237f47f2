// Unit tests of the heat-transfer shells DS3, DS4 and DS8 (elements/heat/heat_shell.hpp): the
// kernel harness (the tangent against central differences with temperature-dependent
// conductivity and capacity, films; revert-then-evaluate; the element moved in space),
// exact fluxes of a field linear along the surface and through the thickness, conservation, the
// stored heat of a uniform rise and the totals of the thermal loads.
#include "elements/element_kernel.hpp"
#include "model/model.hpp"
#include "unit/elements/kernel_harness.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace gapfem::test {
namespace {

constexpr double kK = 20.0, kRho = 7000.0, kC = 500.0;

/// Corner and mid-side nodes of a flat square [0, 1.2] x [0, 0.8] (triangle: its lower half),
/// mildly distorted, then rotated into a tilted plane (and optionally warped out of it).
std::vector<Vec3> shell_nodes(ElementType t, bool warped) {
  std::vector<std::array<double, 2>> p;
  if (t == ElementType::DS3)
    p = {{0.0, 0.0}, {1.2, 0.1}, {0.2, 0.8}};
  else
    p = {{0.0, 0.0}, {1.2, 0.1}, {1.1, 0.9}, {-0.1, 0.8}};
  if (t == ElementType::DS8)
    for (int a = 0; a < 4; ++a) {
      const auto& A = p[a];
      const auto& B = p[(a + 1) % 4];
      p.push_back({0.5 * (A[0] + B[0]) + 0.03, 0.5 * (A[1] + B[1]) - 0.02});
    }
  // rotation: x' = R x with columns e1 = (c, 0, s), e2 = (0, 1, 0) tilted by 30 degrees
  const double c = std::cos(0.5236), s = std::sin(0.5236);
  std::vector<Vec3> X;
  for (std::size_t a = 0; a < p.size(); ++a) {
    const double w = warped ? 0.05 * ((a % 2) ? 1.0 : -1.0) : 0.0;
    X.push_back({c * p[a][0] - s * w, p[a][1], s * p[a][0] + c * w});
  }
  return X;
}

/// One heat-transfer shell with `points` temperatures through the thickness, as a kernel probe.
struct ShellHarness : KernelProbe {
  int P = 1;

  ShellHarness(ElementType t, int points, bool varying, bool warped, bool nodal_thickness = false)
      : KernelProbe(KernelProbe::of(model_of(t, points, varying, warped, nodal_thickness))),
        P(points) {
    ctx.procedure = Procedure::HeatTransfer;
  }
  static std::shared_ptr<const Model> model_of(ElementType t, int points, bool varying, bool warped,
                                               bool nodal_thickness) {
    auto model = std::make_shared<Model>();
    const std::vector<Vec3> X = shell_nodes(t, warped);
    add_lone_element(*model, t, X);
    model->source_files.push_back("test.inp");
    Material m;
    m.name = "M";
    auto table = [&](double v, double factor) {
      PropertyTable tb;
      tb.n_values = 1;
      tb.values = varying ? std::vector<double>{v, factor * v} : std::vector<double>{v};
      if (varying) tb.keys = {0.0, 200.0};
      return tb;
    };
    m.conductivity = table(kK, 1.6);
    m.density = table(kRho, 0.9);
    m.specific_heat = table(kC, 1.3);
    model->materials.push_back(m);
    ShellSection sec;
    sec.elset = "SHELL";
    sec.material = 0;
    sec.thickness = 0.05;
    sec.n_points = points;
    sec.nodal_thickness = nodal_thickness;
    if (nodal_thickness)
      for (std::size_t a = 0; a < X.size(); ++a) model->nodal_thickness.push_back(0.04 + 0.01 * a);
    model->shell_sections.push_back(sec);
    model->element_property.push_back({PropertyRef::Kind::Shell, 0});
    return model;
  }
  using KernelProbe::load;
  /// f_ext and -d f_ext / dT of one distributed load.
  void load(DistLoadKind kind, int face, double magnitude, double sink, std::vector<double>& f,
            std::vector<double>& K) {
    f = load(distributed_load(kind, face, magnitude, sink), magnitude, sink, &K);
  }
  double area() { // of the flat, undistorted reference: from the kernel's own BF totals
    std::vector<double> f, K;
    load(DistLoadKind::SurfaceFlux, 2, 1.0, 0.0, f, K);
    double A = 0.0;
    for (double v : f) A += v;
    return A;
  }
};

std::string name_of(ElementType t) {
  return std::string(element_info(t).name);
}

struct Case {
  ElementType type;
  int points;
};
std::vector<Case> all_cases() {
  std::vector<Case> c;
  for (ElementType t : {ElementType::DS3, ElementType::DS4, ElementType::DS8})
    for (int p : {1, 3, 5}) c.push_back({t, p});
  return c;
}
std::string case_name(const ::testing::TestParamInfo<Case>& i) {
  return name_of(i.param.type) + "_" + std::to_string(i.param.points);
}

class HeatShell : public ::testing::TestWithParam<Case> {};

// The tangent (conduction with k(T), capacity with rho c (T) in a transient step) against central
// differences of the residual at random temperatures, on a warped element with nodal thickness;
// revert-then-evaluate; the element moved and turned in space conducts the same.
TEST_P(HeatShell, TangentMatchesCentralDifferences) {
  ShellHarness h(GetParam().type, GetParam().points, true, true, true);
  h.ctx.transient = true;
  h.ctx.dt = 0.7;
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> T(20.0, 180.0);
  for (int i = 0; i < h.n(); ++i) {
    h.u[i] = T(gen);
    h.u0[i] = T(gen);
  }
  EXPECT_TRUE(h.evaluate().unsymmetric); // k depends on T
  expect_fd_tangent(h);
  expect_revert_is_exact(h);
  expect_rigid_body_invariance(h, {.frame = true});
}

// The film on either side: -d f / dT against central differences, and only that side's DOFs.
TEST_P(HeatShell, FilmTangentMatchesCentralDifferences) {
  ShellHarness h(GetParam().type, GetParam().points, false, true);
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> T(20.0, 180.0);
  for (double& v : h.u) v = T(gen);
  for (int face : {1, 2}) {
    SCOPED_TRACE("face " + std::to_string(face));
    const std::vector<double> f =
        h.load(distributed_load(DistLoadKind::Film, face, 300.0, 50.0), 300.0, 50.0);
    const int k = face == 1 ? 0 : h.P - 1;
    for (int i = 0; i < h.n(); ++i)
      if (i % h.P != k) EXPECT_EQ(f[i], 0.0) << i;
    expect_fd_load_stiffness(h, distributed_load(DistLoadKind::Film, face, 300.0, 50.0), 300.0,
                             50.0);
  }
}

// T = T0 + g . X + c z on a flat (tilted) element, z measured from the mid-surface along the
// normal: the section points sit at z_k = -t/2 + k t / (n - 1), and the element reproduces the
// field exactly, so at every point HFL1 = -k g . e1, HFL2 = -k g . e2 and HFL3 = -k c (c = 0 for
// one point). The residual of any field sums to zero (steady conduction conserves heat), and a
// uniform field leaves no residual.
TEST_P(HeatShell, LinearFieldGivesExactFluxesAndConservesHeat) {
  ShellHarness h(GetParam().type, GetParam().points, false, false);
  const int P = h.P;
  const double t = 0.05, c = P > 1 ? 400.0 : 0.0;
  const double tilt = 0.5236;
  const Vec3 n{-std::sin(tilt), 0.0, std::cos(tilt)}; // normal of the tilted plane (e1 x e2)
  const Vec3 g{30.0 * std::cos(tilt), -12.0, 30.0 * std::sin(tilt)}; // in the plane
  for (std::size_t a = 0; a < h.X.size(); ++a)
    for (int k = 0; k < P; ++k) {
      const double z = P > 1 ? -0.5 * t + k * t / (P - 1) : 0.0;
      h.u[a * P + k] = 100.0 + g[0] * h.X[a][0] + g[1] * h.X[a][1] + g[2] * h.X[a][2] + c * z;
    }
  const ElementRecovery rec = h.recover();
  const OutputBlock* b = rec.find(ElemVar::HFL);
  ASSERT_NE(b, nullptr);
  ASSERT_EQ(b->section_points, P);
  // local direction 1: the projection of global x on the surface, 2 = n x 1
  Vec3 e1{std::cos(tilt), 0.0, std::sin(tilt)};
  const Vec3 e2{n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2],
                n[0] * e1[1] - n[1] * e1[0]};
  const double g1 = g[0] * e1[0] + g[1] * e1[1] + g[2] * e1[2];
  const double g2 = g[0] * e2[0] + g[1] * e2[1] + g[2] * e2[2];
  for (int p = 0; p < b->n_points; ++p) {
    EXPECT_NEAR(b->values[3 * p], -kK * g1, 1e-9 * kK * 30.0) << p;
    EXPECT_NEAR(b->values[3 * p + 1], -kK * g2, 1e-9 * kK * 30.0) << p;
    EXPECT_NEAR(b->values[3 * p + 2], -kK * c, 1e-9 * kK * 400.0) << p;
  }
  std::vector<double> r = h.evaluate().r;
  double sum = 0.0, scale = 0.0;
  for (double v : r) {
    sum += v;
    scale += std::abs(v);
  }
  EXPECT_GT(scale, 0.0);
  EXPECT_NEAR(sum, 0.0, 1e-12 * scale);
  std::fill(h.u.begin(), h.u.end(), 37.0);
  r = h.evaluate().r;
  for (double v : r) EXPECT_NEAR(v, 0.0, 1e-9);
}

// A uniform rise dT of the whole element stores rho c A t dT (Simpson's weights sum to the
// thickness; the lumped and consistent capacities both integrate a constant exactly), and the
// capacity residual sums to that heat over dt.
TEST_P(HeatShell, UniformRiseStoresRhoCVdT) {
  ShellHarness h(GetParam().type, GetParam().points, false, false);
  h.ctx.transient = true;
  h.ctx.dt = 2.0;
  std::fill(h.u0.begin(), h.u0.end(), 20.0);
  std::fill(h.u.begin(), h.u.end(), 25.0);
  const double V = h.area() * 0.05;
  EXPECT_NEAR(h.kernel->stored_heat(h.input()), kRho * kC * V * 5.0, 1e-9 * kRho * kC * V * 5.0);
  double sum = 0.0;
  for (double v : h.evaluate().r) sum += v;
  EXPECT_NEAR(sum, kRho * kC * V * 5.0 / 2.0, 1e-9 * kRho * kC * V * 5.0);
}

// Totals of the loads: BF gives r A t over all DOFs (each section point its Simpson share), a
// surface flux q A on one side's DOFs only, a film h A (T_sink - T) at a uniform T.
TEST_P(HeatShell, LoadTotals) {
  ShellHarness h(GetParam().type, GetParam().points, false, true);
  const int P = h.P;
  const double A = h.area();
  EXPECT_GT(A, 0.4); // the triangle is half the square
  std::vector<double> f, K;
  h.load(DistLoadKind::BodyFlux, 0, 1e5, 0.0, f, K);
  double total = 0.0, side = 0.0;
  for (double v : f) total += v;
  EXPECT_NEAR(total, 1e5 * A * 0.05, 1e-9 * 1e5 * A);
  h.load(DistLoadKind::SurfaceFlux, 1, 700.0, 0.0, f, K);
  total = 0.0;
  for (int i = 0; i < h.n(); ++i) {
    total += f[i];
    if (i % P == 0) side += f[i];
  }
  EXPECT_NEAR(total, 700.0 * A, 1e-9 * 700.0 * A);
  EXPECT_NEAR(side, total, 1e-12 * 700.0 * A);
  std::fill(h.u.begin(), h.u.end(), 80.0);
  h.load(DistLoadKind::Film, 2, 25.0, 30.0, f, K);
  total = 0.0;
  for (double v : f) total += v;
  EXPECT_NEAR(total, 25.0 * A * (30.0 - 80.0), 1e-9 * 25.0 * A * 50.0);
  EXPECT_TRUE(h.kernel->supports_load(DistLoadKind::Film, 1));
  EXPECT_FALSE(h.kernel->supports_load(DistLoadKind::Film, 3));
  EXPECT_FALSE(h.kernel->supports_load(DistLoadKind::Pressure, 1));
}

INSTANTIATE_TEST_SUITE_P(Heat, HeatShell, ::testing::ValuesIn(all_cases()), case_name);

// Each node carries DOFs 11, 12, ..., 10 + n.
TEST(HeatShellDofs, OneTemperaturePerSectionPoint) {
  ShellHarness h(ElementType::DS4, 7, false, false);
  const auto d = h.kernel->node_dofs(2);
  ASSERT_EQ(d.size(), 7u);
  for (int k = 0; k < 7; ++k) EXPECT_EQ(abaqus_number(d[k]), 11 + k);
}

} // namespace
} // namespace gapfem::test
