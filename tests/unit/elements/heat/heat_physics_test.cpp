// Physics of the heat-transfer and coupled element kernels: patch tests (a linear temperature
// field gives the exact constant flux), conservation, lumped capacity and stored heat, the internal
// energy of temperature-dependent capacity, thermal loads, free thermal expansion of the coupled
// elements, output layout and factory errors.
#include "elements/heat/heat_material.hpp"
#include "heat_fixture.hpp"

#include <fmt/format.h>
#include <numbers>

namespace gapfem::test::heat {
namespace {

const std::vector<ElementType> kAllTypes = all_heat_types();

std::string type_name(const ::testing::TestParamInfo<ElementType>& info) {
  return std::string(element_info(info.param).name);
}

int dim_of(ElementType t) {
  return shape_dim(shape_of(t));
}

/// Unit vector of a link from node 1 to node 2.
Vec3 axis(const std::vector<Vec3>& X) {
  Vec3 d{X[1][0] - X[0][0], X[1][1] - X[0][1], X[1][2] - X[0][2]};
  const double L = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  return {d[0] / L, d[1] / L, d[2] / L};
}

class HeatPatch : public ::testing::TestWithParam<ElementType> {};

// Patch test: T = 30 + g . x is reproduced exactly by every (distorted) isoparametric element, so
// the heat flux is q = -k g at every integration point (round-off only: 1e-10 relative), and the
// internal flux vector sums to zero (conduction only moves heat inside the element).
TEST_P(HeatPatch, LinearTemperatureGivesExactConstantFlux) {
  const ElementType t = GetParam();
  Harness h(t, nodes_of(t));
  const Vec3 g{3.0, -2.0, 1.5};
  const int d = dim_of(t);
  Vec3 gg = g;
  for (int i = d; i < 3; ++i) gg[i] = 0.0;
  if (d == 1) gg = g; // links: the field varies along the axis through g . x
  if (t == ElementType::T2D2T) gg[2] = 0.0;
  h.set_linear_temperature(30.0, gg);
  const ElementRecovery rec = h.recover();
  const OutputBlock* hfl = rec.find(ElemVar::HFL);
  ASSERT_NE(hfl, nullptr);
  ASSERT_EQ(static_cast<int>(hfl->names.size()), d);
  EXPECT_EQ(hfl->names[0], "HFL1");
  const double k = Props{}.k;
  std::vector<double> expected(d);
  if (d == 1) {
    const Vec3 n = axis(h.X);
    expected[0] = -k * (gg[0] * n[0] + gg[1] * n[1] + gg[2] * n[2]);
  } else {
    for (int i = 0; i < d; ++i) expected[i] = -k * gg[i];
  }
  for (int q = 0; q < hfl->n_points; ++q)
    for (int i = 0; i < d; ++i)
      EXPECT_NEAR(hfl->values[q * d + i], expected[i], 1e-10 * k * 4.0) << "point " << q + 1;
  std::vector<double> r = h.evaluate(false).r;
  double sum = 0.0, mag = 0.0;
  for (int a = 0; a < static_cast<int>(h.X.size()); ++a) {
    sum += r[h.nt(a)];
    mag += std::abs(r[h.nt(a)]);
  }
  EXPECT_GT(mag, 0.0);
  EXPECT_NEAR(sum, 0.0, 1e-12 * mag);
}

INSTANTIATE_TEST_SUITE_P(Heat, HeatPatch, ::testing::ValuesIn(kAllTypes), type_name);

/// Volume of the undistorted element of each type with section 0.8 (links: area x length, planar:
/// thickness x area, axisymmetric: 2 pi r_c x area with the centroid radius, which is exact).
double volume(ElementType t, const std::vector<Vec3>& X) {
  const Shape s = shape_of(t);
  if (s == Shape::Line2) {
    double L2 = 0.0;
    for (int i = 0; i < 3; ++i) L2 += (X[1][i] - X[0][i]) * (X[1][i] - X[0][i]);
    return 0.8 * std::sqrt(L2);
  }
  const bool axi = element_info(t).plane == PlaneKind::Axisymmetric;
  if (s == Shape::Quad4 || s == Shape::Quad8)
    return (axi ? 2.0 * std::numbers::pi * 1.5 : 0.8) * 1.0; // 1 x 1 at x_c = 1.5
  if (s == Shape::Tri3 || s == Shape::Tri6)
    return (axi ? 2.0 * std::numbers::pi * (1.5 + 1.0 / 3.0) : 0.8) * 0.5;
  if (s == Shape::Hex8 || s == Shape::Hex20) return 1.0;
  if (s == Shape::Wedge6 || s == Shape::Wedge15) return 1.0; // triangle 1/2 x height 2
  return 1.0 / 6.0;                                          // unit tetrahedra
}

class HeatCapacity : public ::testing::TestWithParam<ElementType> {};

// A uniform temperature rise dT over dt stores rho c V dT (exact for constant properties), the
// capacity residual carries it as a rate, and first-order elements lump it at the nodes: every
// nodal term is positive, and on the undistorted brick/quad each node gets an equal share.
TEST_P(HeatCapacity, UniformRiseStoresRhoCVdT) {
  const ElementType t = GetParam();
  const Props p;
  Harness h(t, nodes_of(t, false), p, 0.8);
  h.set_transient(4.0);
  for (int a = 0; a < static_cast<int>(h.X.size()); ++a) {
    h.u0[h.nt(a)] = 20.0;
    h.u[h.nt(a)] = 26.0;
  }
  const double V = volume(t, h.X);
  const double expected = p.rho * p.c * V * 6.0;
  EXPECT_NEAR(h.stored_heat(), expected, 1e-12 * expected);
  std::vector<double> r = h.evaluate(false).r;
  double sum = 0.0;
  for (int a = 0; a < static_cast<int>(h.X.size()); ++a) {
    sum += r[h.nt(a)];
    if (!shape_quadratic(shape_of(t))) EXPECT_GT(r[h.nt(a)], 0.0) << "node " << a + 1;
  }
  EXPECT_NEAR(sum, expected / 4.0, 1e-12 * expected);
  if (shape_of(t) == Shape::Hex8 ||
      (shape_of(t) == Shape::Quad4 && !(element_info(t).plane == PlaneKind::Axisymmetric)))
    for (int a = 1; a < static_cast<int>(h.X.size()); ++a)
      EXPECT_NEAR(r[h.nt(a)], r[h.nt(0)], 1e-12 * expected);
  // Steady-state steps have no capacity: a uniform field gives no residual.
  h.ctx.transient = false;
  r = h.evaluate(false).r;
  for (int a = 0; a < static_cast<int>(h.X.size()); ++a) EXPECT_NEAR(r[h.nt(a)], 0.0, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Heat, HeatCapacity, ::testing::ValuesIn(kAllTypes), type_name);

// DC3D10 integrates the capacity consistently and exactly: for a field changing by dT = a + b . x
// (linear) the stored heat is rho c integral(dT) dV = rho c V dT(centroid).
TEST(HeatCapacityQuadraticTet, ConsistentCapacityIsExactForLinearChange) {
  const Props p;
  Harness h(ElementType::DC3D10, nodes_of(ElementType::DC3D10));
  h.set_transient(1.0);
  h.set_linear_temperature(0.0, {0.0, 0.0, 0.0});
  h.set_linear_temperature(5.0, {2.0, -1.0, 3.0}, true);
  Vec3 c{};
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i) c[i] += 0.25 * h.X[a][i];
  // Volume of the distorted tetrahedron from its corners.
  auto sub = [&](int a) {
    return Vec3{h.X[a][0] - h.X[0][0], h.X[a][1] - h.X[0][1], h.X[a][2] - h.X[0][2]};
  };
  const Vec3 e1 = sub(1), e2 = sub(2), e3 = sub(3);
  const double V =
      (e1[0] * (e2[1] * e3[2] - e2[2] * e3[1]) - e1[1] * (e2[0] * e3[2] - e2[2] * e3[0]) +
       e1[2] * (e2[0] * e3[1] - e2[1] * e3[0])) /
      6.0;
  const double dTc = 5.0 + 2.0 * c[0] - c[1] + 3.0 * c[2];
  EXPECT_NEAR(h.stored_heat(), p.rho * p.c * V * dTc, 1e-11 * p.rho * p.c * V * dTc);
}

// E(T) = integral of rho(T) c(T): dE/dT = rho c (central differences; E is piecewise cubic, so the
// error is h^2 |E'''| / 6 ~ 1e-6 relative with h = 0.01), exact energies of the tables, and
// additivity over consecutive increments (the heat balance telescopes).
TEST(HeatMaterialEnergy, DerivativeIsCapacityAndEnergyTelescopes) {
  Material m;
  m.conductivity.n_values = 1;
  m.conductivity.values = {1.0};
  m.density = table(2.0, true, 0.5);       // 2 -> 1 on [0, 200]
  m.specific_heat = table(3.0, true, 2.0); // 3 -> 6 on [0, 200]
  const HeatMaterial hm(m);
  for (double T : {-50.0, 10.0, 99.0, 150.0, 250.0}) {
    const double h = 0.01;
    const double fd = (hm.energy(T + h) - hm.energy(T - h)) / (2.0 * h);
    EXPECT_NEAR(fd, hm.capacity(T), 1e-6 * hm.capacity(T)) << "T = " << T;
  }
  // rho c = (2 - T/200)(3 + 3 T/200): integral over [0, 200] = 200 * int_0^1 (2 - s)(3 + 3 s) ds
  // = 200 * (6 + 3/2 - 1) = 1300; constant rho c = 6 below 0.
  EXPECT_NEAR(hm.energy(200.0) - hm.energy(0.0), 1300.0, 1e-9);
  EXPECT_NEAR(hm.energy(0.0) - hm.energy(-10.0), 60.0, 1e-9);
  EXPECT_NEAR((hm.energy(80.0) - hm.energy(30.0)) + (hm.energy(170.0) - hm.energy(80.0)),
              hm.energy(170.0) - hm.energy(30.0), 1e-9);
}

// Body flux r per volume: the nodal heats sum to r V. Surface flux q on face 1 of the undistorted
// brick (area 1): q per node 1/4 of the face. Films on a uniform temperature: h A (T_sink - T).
TEST(HeatLoads, BodyFluxSurfaceFluxAndFilmTotals) {
  Harness h(ElementType::DC3D8, nodes_of(ElementType::DC3D8, false));
  std::vector<double> f;
  h.load(DistLoadKind::BodyFlux, 0, 7.0, 0.0, f);
  double sum = 0.0;
  for (double v : f) sum += v;
  EXPECT_NEAR(sum, 7.0, 1e-12);
  h.load(DistLoadKind::SurfaceFlux, 1, 3.0, 0.0, f);
  for (int a = 0; a < 8; ++a) EXPECT_NEAR(f[a], a < 4 ? 0.75 : 0.0, 1e-12); // face S1: nodes 1-4
  for (int a = 0; a < 8; ++a) h.u[a] = 40.0;
  std::vector<double> K;
  h.load(DistLoadKind::Film, 2, 5.0, 100.0, f, &K);
  for (int a = 0; a < 8; ++a) EXPECT_NEAR(f[a], a >= 4 ? 5.0 * 0.25 * 60.0 : 0.0, 1e-12); // S2: 5-8
  for (int a = 0; a < 8; ++a) EXPECT_NEAR(K[a * 8 + a], a >= 4 ? 5.0 * 0.25 : 0.0, 1e-12);
  // DC1D2 "faces" are its ends, carrying the section area.
  Harness link(ElementType::DC1D2, nodes_of(ElementType::DC1D2), {}, 0.8);
  link.load(DistLoadKind::SurfaceFlux, 2, 10.0, 0.0, f);
  EXPECT_NEAR(f[0], 0.0, 1e-15);
  EXPECT_NEAR(f[1], 8.0, 1e-12);
  // Axisymmetric edge: the total over the circumference, q 2 pi r L (edge 4-1 at r = 1).
  Harness axi(ElementType::DCAX4, nodes_of(ElementType::DCAX4, false));
  axi.load(DistLoadKind::SurfaceFlux, 4, 1.0, 0.0, f);
  EXPECT_NEAR(f[0] + f[3], 2.0 * std::numbers::pi * 1.0 * 1.0, 1e-12);
}

class CoupledFreeExpansion : public ::testing::TestWithParam<ElementType> {};

// A free body heated uniformly from the initial temperature 20 to 120 with u = alpha dT x
// ((1 + nu) alpha dT x in plane strain) has no stress: the mechanical residual vanishes (round-off
// of E eps: 1e-13 E alpha dT allows for the volumes up to 2 pi r of the axisymmetric elements).
TEST_P(CoupledFreeExpansion, UniformHeatingOfFreeBodyIsStressFree) {
  const ElementType t = GetParam();
  Props p;
  Harness h(t, nodes_of(t), p, 1.0, 20.0);
  const int npn = h.per_node();
  // Plane strain holds eps33 = 0: the in-plane stress-free strain is (1 + nu) alpha dT.
  const double strain =
      p.alpha * 100.0 * (element_info(t).plane == PlaneKind::PlaneStrain ? 1.0 + p.nu : 1.0);
  for (int a = 0; a < static_cast<int>(h.X.size()); ++a) {
    for (int i = 0; i < npn - 1; ++i) h.u[a * npn + i] = strain * h.X[a][i];
    h.u[h.nt(a)] = 120.0;
  }
  h.u0 = h.u;
  std::vector<double> r = h.evaluate(false).r;
  for (int i = 0; i < h.n(); ++i)
    if (!h.is_nt(i)) EXPECT_NEAR(r[i], 0.0, 1e-13 * p.E * strain) << "dof " << i;
  // Held at zero displacement the same heating gives thermal forces of order E alpha dT A.
  for (int i = 0; i < h.n(); ++i)
    if (!h.is_nt(i)) h.u[i] = 0.0;
  r = h.evaluate(false).r;
  double fmax = 0.0;
  for (int i = 0; i < h.n(); ++i)
    if (!h.is_nt(i)) fmax = std::max(fmax, std::abs(r[i]));
  EXPECT_GT(fmax, 1e-3 * p.E * strain);
  // S and E output come from the mechanical kernel, HFL from the thermal part.
  const ElementRecovery rec = h.recover();
  EXPECT_NE(rec.find(ElemVar::S), nullptr);
  EXPECT_NE(rec.find(ElemVar::E), nullptr);
  EXPECT_NE(rec.find(ElemVar::HFL), nullptr);
  EXPECT_TRUE(h.kernel->supports_output(ElemVar::HFL));
  EXPECT_EQ(h.kernel->node_dofs(0).back(), DofType::NT);
}

INSTANTIATE_TEST_SUITE_P(Heat, CoupledFreeExpansion, ::testing::ValuesIn(heat_types(true)),
                         type_name);

TEST(HeatFactory, TransientStepNeedsDensityAndSpecificHeat) {
  Props p;
  p.capacity = false;
  auto model = model_of(ElementType::DC3D8, nodes_of(ElementType::DC3D8), p);
  std::vector<ElemId> elems{0};
  // Steady state only: fine without capacity data.
  Step steady;
  steady.number = 1;
  steady.procedure = Procedure::HeatTransfer;
  model->steps.push_back(steady);
  EXPECT_NO_THROW(make_element_kernel(
      KernelContext{*model, ElementType::DC3D8, model->element_property[0], elems}));
  Step transient = steady;
  transient.number = 2;
  transient.inc.steady_state = false;
  model->steps.push_back(transient);
  try {
    make_element_kernel(
        KernelContext{*model, ElementType::DC3D8, model->element_property[0], elems});
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("add *DENSITY and *SPECIFIC HEAT to the material"),
              std::string::npos)
        << e.what();
    EXPECT_NE(e.message().find("step 2"), std::string::npos) << e.what();
  }
}

TEST(HeatFactory, InvalidGeometryIsReported) {
  // Axisymmetric element with integration points at r < 0.
  std::vector<Vec3> X = nodes_of(ElementType::DCAX4, false);
  for (auto& x : X) x[0] -= 3.0;
  Harness h(ElementType::DCAX4, X);
  ElementInput in = h.input();
  EXPECT_NE(h.kernel->validate(in).find("r <= 0"), std::string::npos);
  // Coincident link nodes.
  Harness link(ElementType::DC1D2, {{0, 0, 0}, {0, 0, 0}});
  in = link.input();
  EXPECT_FALSE(link.kernel->validate(in).empty());
  // Inverted brick.
  std::vector<Vec3> Y = nodes_of(ElementType::DC3D8);
  std::swap(Y[1], Y[3]);
  std::swap(Y[5], Y[7]);
  Harness brick(ElementType::DC3D8, Y);
  in = brick.input();
  EXPECT_NE(brick.kernel->validate(in).find("inverted"), std::string::npos);
}

} // namespace
} // namespace gapfem::test::heat
