// CENTRIF on every continuum element type (continuum_loads.cpp): the nodal forces add up to
// rho omega^2 times the integral of the distance vector from the axis (checked against the
// element's own mass-weighted integral through the body-force routine: for a linear field
// r(x), sum N_a r(x) dV = sum_a (integral of N_a) r(x_a) is exact), and with NLGEOM the load
// stiffness is minus the derivative of the nodal forces, checked by central differences of the
// forces themselves (the finite-difference check of every tangent).
#include "continuum_fixture.hpp"

#include <cmath>
#include <numbers>

namespace gapfem::test {
namespace {

constexpr double kRho = 7.85e-9, kOmega2 = 1.0e6;

/// The axis a type can take: the symmetry axis (axisymmetric), the normal of the plane (plane),
/// an oblique axis off the origin (3-D).
DistributedLoad centrifugal(ElementType t) {
  DistributedLoad ld;
  ld.kind = DistLoadKind::Centrifugal;
  ld.face = 0;
  if (element_info(t).plane == PlaneKind::Axisymmetric) {
    ld.direction = {0.0, 1.0, 0.0};
  } else if (!is_3d(t)) {
    ld.point = {0.3, -0.2, 0.0};
    ld.direction = {0.0, 0.0, 1.0};
  } else {
    const double n = std::sqrt(1.0 + 4.0 + 9.0);
    ld.point = {0.5, -1.0, 0.25};
    ld.direction = {1.0 / n, 2.0 / n, 3.0 / n};
  }
  return ld;
}

/// rho omega^2 (x - p)_perp at x.
Vec3 force_density(const DistributedLoad& ld, const Vec3& x) {
  Vec3 d{x[0] - ld.point[0], x[1] - ld.point[1], x[2] - ld.point[2]};
  const double along = d[0] * ld.direction[0] + d[1] * ld.direction[1] + d[2] * ld.direction[2];
  for (int i = 0; i < 3; ++i) d[i] = kRho * kOmega2 * (d[i] - along * ld.direction[i]);
  return d;
}

TEST(CentrifugalLoad, ResultantIsTheMassWeightedDistanceFromTheAxis) {
  for (ElementType type : continuum_types()) {
    SCOPED_TRACE(element_info(type).name);
    ElementHarness h(type, reference_nodes(type));
    const DistributedLoad ld = centrifugal(type);
    const int nd = dofs_per_node(type);
    const std::vector<double> f = h.load(ld, kOmega2, 0.0);
    // the same integral through GRAV-like unit body forces per component: sum_a F_a(e_i) r(x_a)
    // is exact because r is linear in x and sum_a N_a x_a = x (isoparametric)
    double want[3] = {0.0, 0.0, 0.0}, got[3] = {0.0, 0.0, 0.0};
    for (int i = 0; i < nd; ++i) {
      DistributedLoad unit;
      unit.kind = DistLoadKind::BodyForce;
      unit.direction[i] = 1.0;
      const std::vector<double> w = h.load(unit, 1.0, 0.0); // integral of N_a per node
      for (std::size_t a = 0; a < h.X.size(); ++a) {
        want[i] += w[a * nd + i] * force_density(ld, h.X[a])[i];
        got[i] += f[a * nd + i];
      }
    }
    for (int i = 0; i < nd; ++i) EXPECT_NEAR(got[i], want[i], 1e-12 * (std::abs(want[i]) + 1e-6));
    double size = 0.0;
    for (int i = 0; i < nd; ++i) size += std::abs(got[i]);
    EXPECT_GT(size, 0.0);
  }
}

TEST(CentrifugalLoad, NlgeomLoadStiffnessIsMinusTheForcesDerivative) {
  for (ElementType type : continuum_types()) {
    SCOPED_TRACE(element_info(type).name);
    ElementHarness h(type, reference_nodes(type));
    h.ctx.nlgeom = true;
    const DistributedLoad ld = centrifugal(type);
    const std::size_t n = h.u.size();
    for (std::size_t k = 0; k < n; ++k)
      h.u[k] = 0.01 * std::sin(1.0 + 0.7 * static_cast<double>(k));
    std::vector<double> K;
    h.load(ld, kOmega2, 0.0, &K);
    const double eps = 1e-6;
    double scale = 0.0;
    for (double v : K) scale = std::max(scale, std::abs(v));
    ASSERT_GT(scale, 0.0);
    for (std::size_t j = 0; j < n; ++j) {
      const double keep = h.u[j];
      h.u[j] = keep + eps;
      const std::vector<double> fp = h.load(ld, kOmega2, 0.0);
      h.u[j] = keep - eps;
      const std::vector<double> fm = h.load(ld, kOmega2, 0.0);
      h.u[j] = keep;
      for (std::size_t i = 0; i < n; ++i)
        EXPECT_NEAR(K[i * n + j], -(fp[i] - fm[i]) / (2 * eps), 1e-7 * scale) << i << ", " << j;
    }
    // without NLGEOM the load is the reference one: no stiffness, no change with u
    h.ctx.nlgeom = false;
    std::vector<double> K0;
    h.load(ld, kOmega2, 0.0, &K0);
    for (double v : K0) EXPECT_EQ(v, 0.0);
  }
}

} // namespace
} // namespace gapfem::test
