// The mass operator of every continuum kernel (elements/solid/continuum_mass.hpp): stress/
// displacement and coupled types, full, reduced (full rule for the mass) and incompatible-mode
// elements, plane (thickness), axisymmetric (2 pi r) and 3-D. The consistent mass sums, per
// direction, to rho x volume (the reference volume of continuum_loads, an independent
// integration); a rigid translation's kinetic energy is exact; the block is symmetric, carries
// nothing on a coupled element's NT DOFs, follows rho(T), and is zero without *DENSITY while the
// kernel still says it has a mass.
#include "elements/solid/continuum_loads.hpp"
#include "unit/elements/solid/continuum_fixture.hpp"

#include <algorithm>
#include <cmath>

namespace gapfem::test {
namespace {

std::vector<ElementType> every_continuum_type() {
  std::vector<ElementType> out;
  for (const ElementTypeInfo& info : all_element_types())
    if (info.family == ElementFamily::Continuum) out.push_back(info.type);
  return out;
}

Kinematics kinematics_of(ElementType t) {
  if (is_3d(t)) return Kinematics::ThreeD;
  switch (element_info(t).plane) {
  case PlaneKind::PlaneStress:
    return Kinematics::PlaneStress;
  case PlaneKind::Axisymmetric:
    return Kinematics::Axisymmetric;
  default:
    return Kinematics::PlaneStrain;
  }
}

constexpr double kThickness = 0.5; ///< plane elements

/// A probe of type t at a uniform temperature of 100 whose density is `density` (at 0 and 200
/// when `varying`; none when 0).
KernelProbe probe(ElementType t, double density, bool varying = false) {
  TestMaterial tm;
  tm.density = 0.0;
  auto model = one_element_model(t, reference_nodes(t), tm, kThickness);
  Material& mat = model->materials[0];
  if (density > 0.0) {
    mat.density.n_values = 1;
    mat.density.values =
        varying ? std::vector<double>{density, 0.5 * density} : std::vector<double>{density};
    if (varying) mat.density.keys = {0.0, 200.0};
  }
  if (element_info(t).temperature) {
    mat.conductivity.n_values = 1;
    mat.conductivity.values = {45.0};
  }
  KernelProbe p = KernelProbe::of(std::shared_ptr<const Model>(std::move(model)));
  const int per_node = p.n() / static_cast<int>(p.X.size());
  if (element_info(t).temperature)
    for (std::size_t a = 0; a < p.X.size(); ++a) p.u[a * per_node + per_node - 1] = 100.0;
  else
    p.T.assign(p.X.size(), 100.0);
  return p;
}

/// The mass block of the probe's element (n x n row-major).
std::vector<double> mass(KernelProbe& p) {
  const auto n = static_cast<std::size_t>(p.n());
  std::vector<double> r(n, 0.0), M(n * n, 0.0);
  ElementOutput out;
  out.residual = r;
  out.want_tangent = false;
  out.mass = M;
  out.want_mass = true;
  p.kernel->evaluate(p.input(), out);
  return M;
}

double reference_volume(const KernelProbe& p, ElementType t) {
  const int nd = is_3d(t) ? 3 : 2;
  const bool plane = !is_3d(t) && element_info(t).plane != PlaneKind::Axisymmetric;
  LoadGeometry g{kinematics_of(t), shape_of(t), p.X, p.u, nd, plane ? kThickness : 1.0};
  return continuum_reference_volume(g);
}

TEST(ContinuumMass, SumsToRhoTimesVolumeAndMovesRigidlyInEveryContinuumKernel) {
  const double rho = 7.85e-9;
  for (ElementType t : every_continuum_type()) {
    SCOPED_TRACE(std::string(element_info(t).name));
    KernelProbe p = probe(t, rho);
    EXPECT_TRUE(p.kernel->has_mass());
    const std::vector<double> M = mass(p);
    const int n = p.n(), nn = static_cast<int>(p.X.size()), per_node = n / nn;
    const int nd = is_3d(t) ? 3 : 2;
    const double m_total = rho * reference_volume(p, t);
    ASSERT_GT(m_total, 0.0);
    for (int i = 0; i < per_node; ++i) { // each direction; NT rows carry nothing
      double sum = 0.0;
      for (int a = 0; a < nn; ++a)
        for (int j = 0; j < n; ++j) sum += M[(a * per_node + i) * n + j];
      EXPECT_NEAR(sum, i < nd ? m_total : 0.0, 1e-12 * m_total) << "direction " << i;
    }
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) EXPECT_EQ(M[i * n + j], M[j * n + i]);
    // a rigid translation v = (1, -2, 3): kinetic energy 1/2 |v|^2 rho V
    const double vel[3] = {1.0, -2.0, 3.0};
    std::vector<double> v(static_cast<std::size_t>(n), 0.0);
    for (int a = 0; a < nn; ++a)
      for (int i = 0; i < nd; ++i) v[a * per_node + i] = vel[i];
    double ke = 0.0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) ke += 0.5 * v[i] * M[i * n + j] * v[j];
    double v2 = 0.0;
    for (int i = 0; i < nd; ++i) v2 += vel[i] * vel[i];
    EXPECT_NEAR(ke, 0.5 * v2 * m_total, 1e-12 * v2 * m_total);
  }
}

TEST(ContinuumMass, DensityAtThePointTemperatureAndNoneWithoutDensity) {
  for (ElementType t : every_continuum_type()) {
    SCOPED_TRACE(std::string(element_info(t).name));
    KernelProbe warm = probe(t, 8e-9, true), plain = probe(t, 6e-9); // rho(100) = 6e-9
    const std::vector<double> a = mass(warm), b = mass(plain);
    const double scale = *std::max_element(b.begin(), b.end());
    for (std::size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(a[k], b[k], 1e-12 * scale);
    KernelProbe none = probe(t, 0.0);
    EXPECT_TRUE(none.kernel->has_mass());
    const std::vector<double> z = mass(none);
    EXPECT_EQ(std::count(z.begin(), z.end(), 0.0), static_cast<long>(z.size()));
  }
}

// The mass is an addition: asking for it leaves residual and tangent as they are.
TEST(ContinuumMass, AskingForTheMassChangesNothingElse) {
  for (ElementType t : every_continuum_type()) {
    SCOPED_TRACE(std::string(element_info(t).name));
    KernelProbe p = probe(t, 7.85e-9);
    random_displacements(p.u, 0.01, 5u + static_cast<unsigned>(t));
    const KernelResult plain = p.evaluate();
    const auto n = static_cast<std::size_t>(p.n());
    std::vector<double> r(n, 0.0), K(n * n, 0.0), M(n * n, 0.0);
    ElementOutput out;
    out.residual = r;
    out.tangent = K;
    out.mass = M;
    out.want_mass = true;
    p.kernel->evaluate(p.input(), out);
    EXPECT_EQ(r, plain.r);
    EXPECT_EQ(K, plain.K);
  }
}

} // namespace
} // namespace gapfem::test
