// Element-level physics of the continuum kernels: constant-strain patch tests (small strain and
// NLGEOM), a stress-free 90-degree rotation, thermal strain, B-bar dilatation, validate() and
// NLGEOM failures (the rigid-motion checks of every type: continuum_tangent_test.cpp).
#include "continuum_fixture.hpp"

#include <Eigen/Dense>
#include <fmt/format.h>

namespace gapfem::test {
namespace {

const std::vector<ElementType> kAllTypes = continuum_types();

std::string type_name(const ::testing::TestParamInfo<ElementType>& info) {
  return std::string(element_info(info.param).name);
}

PlaneKind plane_of(ElementType t) {
  return element_info(t).plane;
}

/// Voigt component (I, J) pairs in the output order of each kinematic class.
std::vector<std::pair<int, int>> components(ElementType t) {
  if (is_3d(t)) return {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
  if (plane_of(t) == PlaneKind::PlaneStress) return {{0, 0}, {1, 1}, {0, 1}};
  return {{0, 0}, {1, 1}, {2, 2}, {0, 1}};
}

/// Analytic stress tensor of isotropic elasticity for a strain tensor `e` (3x3, the out-of-plane
/// normal already set for plane strain / axisymmetric), thermal strain eth. Plane stress: e33 is
/// solved from sigma33 = 0.
Eigen::Matrix3d analytic_stress(ElementType t, Eigen::Matrix3d e, double eth,
                                const TestMaterial& m) {
  const double mu = m.E / (2 * (1 + m.nu)), lam = m.E * m.nu / ((1 + m.nu) * (1 - 2 * m.nu));
  if (plane_of(t) == PlaneKind::PlaneStress)
    e(2, 2) = eth - lam * (e(0, 0) + e(1, 1) - 2 * eth) / (lam + 2 * mu);
  const Eigen::Matrix3d ee = e - eth * Eigen::Matrix3d::Identity();
  return lam * ee.trace() * Eigen::Matrix3d::Identity() + 2 * mu * ee;
}

void expect_block(const ElementRecovery& rec, ElemVar var, ElementType t,
                  const Eigen::Matrix3d& want, bool engineering_shear, double tol,
                  const std::string& what) {
  const OutputBlock* b = rec.find(var);
  ASSERT_NE(b, nullptr);
  const auto comps = components(t);
  ASSERT_EQ(b->names.size(), comps.size());
  for (int q = 0; q < b->n_points; ++q)
    for (std::size_t c = 0; c < comps.size(); ++c) {
      const auto [I, J] = comps[c];
      const double v = want(I, J) * (engineering_shear && I != J ? 2.0 : 1.0);
      EXPECT_NEAR(b->values[q * comps.size() + c], v, tol)
          << what << " " << b->names[c] << " at point " << q + 1;
    }
}

/// A displacement gradient with a constant-strain field for every type. Axisymmetric elements
/// need u_r proportional to r (hoop strain u_r / r constant): du_r/dz = 0 and no r-translation.
Eigen::Matrix3d patch_gradient(ElementType t, double scale) {
  Eigen::Matrix3d A;
  A << 1.0, 0.4, -0.3, -0.6, 0.7, 0.2, 0.5, -0.25, -0.8;
  A *= scale;
  if (!is_3d(t)) {
    A.row(2).setZero();
    A.col(2).setZero();
  }
  if (plane_of(t) == PlaneKind::Axisymmetric) A(0, 1) = 0.0;
  return A;
}

class ContinuumPatch : public ::testing::TestWithParam<ElementType> {};

// Small strain: u = A X + c gives eps = sym(A) exactly at every point (isoparametric elements
// reproduce linear fields; B-bar leaves a constant dilatation unchanged), and sigma = C:(eps - eth
// I).
TEST_P(ContinuumPatch, LinearFieldGivesExactStressSmallStrain) {
  const ElementType t = GetParam();
  TestMaterial m;
  ElementHarness h(t, reference_nodes(t), m, 2.5);
  const Eigen::Matrix3d A = patch_gradient(t, 1e-3);
  double Ad[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) Ad[i][j] = A(i, j);
  const Vec3 c = plane_of(t) == PlaneKind::Axisymmetric ? Vec3{0, 0.3, 0} : Vec3{0.1, -0.2, 0.3};
  h.set_linear_field(Ad, c);
  for (bool thermal : {false, true}) {
    double eth = 0.0;
    if (thermal) {
      h.set_temperature(120.0, 20.0);
      eth = m.alpha * 100.0; // secant alpha with ZERO = 0 and T_init 20: alpha (T - T_init)
    }
    Eigen::Matrix3d e = 0.5 * (A + A.transpose());
    if (plane_of(t) == PlaneKind::Axisymmetric) e(2, 2) = A(0, 0); // hoop u_r / r
    const ElementRecovery rec = h.recover();
    const Eigen::Matrix3d s = analytic_stress(t, e, eth, m);
    // Stresses ~ 1e3 here; round-off in the element is ~1e-16 relative to E * |eps|.
    expect_block(rec, ElemVar::S, t, s, false, 1e-8 * m.E * 1e-3, thermal ? "thermal" : "");
    expect_block(rec, ElemVar::E, t, e, true, 1e-12, thermal ? "thermal" : "");
  }
}

// NLGEOM: u = A X gives the constant F = I + A; E = (F^T F - I)/2, S = C:(E - eth I) and the
// reported Cauchy stress is F S F^T / det F (plane stress: F33 = sqrt(1 + 2 E33)).
TEST_P(ContinuumPatch, LinearFieldGivesExactStressNlgeom) {
  const ElementType t = GetParam();
  TestMaterial m;
  ElementHarness h(t, reference_nodes(t), m);
  h.ctx.nlgeom = true;
  const Eigen::Matrix3d A = patch_gradient(t, 0.1);
  double Ad[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) Ad[i][j] = A(i, j);
  h.set_linear_field(Ad);
  h.set_temperature(70.0, 20.0);
  const double eth = m.alpha * 50.0;
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity() + A;
  if (plane_of(t) == PlaneKind::Axisymmetric) F(2, 2) = 1.0 + A(0, 0);
  Eigen::Matrix3d E = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());
  const Eigen::Matrix3d S = analytic_stress(t, E, eth, m);
  if (plane_of(t) == PlaneKind::PlaneStress) {
    const double mu = m.E / (2 * (1 + m.nu)), lam = m.E * m.nu / ((1 + m.nu) * (1 - 2 * m.nu));
    const double e33 = eth - lam * (E(0, 0) + E(1, 1) - 2 * eth) / (lam + 2 * mu);
    F(2, 2) = std::sqrt(1 + 2 * e33);
  }
  const Eigen::Matrix3d sigma = F * S * F.transpose() / F.determinant();
  const ElementRecovery rec = h.recover();
  expect_block(rec, ElemVar::S, t, sigma, false, 1e-9 * m.E, "cauchy");
  expect_block(rec, ElemVar::E, t, E, true, 1e-12, "green-lagrange");
}

// NLGEOM: a rigid rotation by 90 degrees is strain free (E_GL = 0), so the stress and the residual
// vanish. Axisymmetric elements admit no in-plane rotation and are excluded.
TEST(ContinuumRigidRotation, NinetyDegreesIsStressFreeNlgeom) {
  for (ElementType t : kAllTypes) {
    if (plane_of(t) == PlaneKind::Axisymmetric) continue; // no rigid in-plane rotation
    ElementHarness h(t, reference_nodes(t));
    h.ctx.nlgeom = true;
    std::vector<Eigen::Matrix3d> rotations;
    rotations.push_back(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix());
    if (is_3d(t))
      rotations.push_back(
          Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d(1, 2, -1).normalized()).toRotationMatrix());
    for (const Eigen::Matrix3d& R : rotations) {
      const Eigen::Matrix3d A = R - Eigen::Matrix3d::Identity();
      double Ad[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) Ad[i][j] = A(i, j);
      h.set_linear_field(Ad, {0.2, 0.1, -0.3});
      for (double v : h.evaluate(false).r) EXPECT_NEAR(v, 0.0, 1e-10 * 200000.0);
      const ElementRecovery rec = h.recover();
      for (double v : rec.find(ElemVar::S)->values) EXPECT_NEAR(v, 0.0, 1e-10 * 200000.0);
      for (double v : rec.find(ElemVar::E)->values) EXPECT_NEAR(v, 0.0, 1e-14);
    }
  }
}

// Thermal strain: a free element expanding with the thermal strain is stress free; a fully
// constrained one carries sigma = -E alpha dT / (1 - 2 nu) on every normal component (3-D, plane
// strain, axisymmetric) or -E alpha dT / (1 - nu) in plane (plane stress).
TEST_P(ContinuumPatch, ThermalStrainFreeAndConstrained) {
  const ElementType t = GetParam();
  TestMaterial m;
  const double dT = 80.0, eth = m.alpha * dT;
  for (bool nl : {false, true}) {
    ElementHarness h(t, reference_nodes(t), m);
    h.ctx.nlgeom = nl;
    h.set_temperature(20.0 + dT, 20.0);
    // Free: stretch so that the strain measure equals eth in every direction (small: e = eth;
    // NLGEOM: (lambda^2 - 1)/2 = eth). Plane strain cannot expand out of plane; it is checked
    // below.
    const double stretch = nl ? std::sqrt(1 + 2 * eth) - 1 : eth;
    double A[3][3] = {{stretch, 0, 0}, {0, stretch, 0}, {0, 0, stretch}};
    h.set_linear_field(A);
    if (plane_of(t) != PlaneKind::PlaneStrain) {
      for (double v : h.evaluate(false).r) EXPECT_NEAR(v, 0.0, 1e-9 * m.E * eth);
      const ElementRecovery free_rec = h.recover();
      for (double v : free_rec.find(ElemVar::S)->values) EXPECT_NEAR(v, 0.0, 1e-9 * m.E * eth);
    }
    std::fill(h.u.begin(), h.u.end(), 0.0);
    const ElementRecovery rec = h.recover();
    const OutputBlock* s = rec.find(ElemVar::S);
    const auto comps = components(t);
    double want = plane_of(t) == PlaneKind::PlaneStress ? -m.E * eth / (1 - m.nu)
                                                        : -m.E * eth / (1 - 2 * m.nu);
    if (nl && plane_of(t) == PlaneKind::PlaneStress) {
      // Cauchy = S / F33: the free thickness grows by F33 = sqrt(1 + 2 E33), E33 = eth (1 + nu) /
      // (1 - nu) from S33 = 0 with E11 = E22 = 0.
      want /= std::sqrt(1 + 2 * eth * (1 + m.nu) / (1 - m.nu));
    }
    for (int q = 0; q < s->n_points; ++q)
      for (std::size_t c = 0; c < comps.size(); ++c)
        EXPECT_NEAR(s->values[q * comps.size() + c], comps[c].first == comps[c].second ? want : 0.0,
                    1e-9 * m.E * eth)
            << s->names[c];
  }
}

// Plane strain, free in plane: sigma11 = sigma22 = 0 needs eps = (1 + nu) eth in plane, and then
// sigma33 = -E eth (the out-of-plane expansion is prevented).
TEST(ContinuumPlaneStrain, FreeInPlaneThermalExpansionLeavesOutOfPlaneStress) {
  TestMaterial m;
  const double eth = m.alpha * 50.0;
  for (ElementType t : {ElementType::CPE3, ElementType::CPE4}) {
    ElementHarness h(t, reference_nodes(t), m);
    h.set_temperature(70.0, 20.0);
    const double e = (1 + m.nu) * eth;
    double A[3][3] = {{e, 0, 0}, {0, e, 0}, {0, 0, 0}};
    h.set_linear_field(A);
    const ElementRecovery rec = h.recover();
    const OutputBlock* s = rec.find(ElemVar::S);
    for (int q = 0; q < s->n_points; ++q) {
      EXPECT_NEAR(s->values[q * 4 + 0], 0.0, 1e-9 * m.E * eth);
      EXPECT_NEAR(s->values[q * 4 + 1], 0.0, 1e-9 * m.E * eth);
      EXPECT_NEAR(s->values[q * 4 + 2], -m.E * eth, 1e-9 * m.E * eth);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Continuum, ContinuumPatch, ::testing::ValuesIn(kAllTypes), type_name);

// B-bar (C3D8, CPE4, CAX4): the volumetric strain (trace over the three normal components, hoop
// included) is the element mean at every integration point, for any displacement; the other
// fully integrated elements keep a pointwise trace. Small strain and NLGEOM.
TEST(ContinuumBbar, DilatationIsTheElementMean) {
  for (ElementType t : {ElementType::C3D8, ElementType::CPE4, ElementType::CAX4, ElementType::CPS4,
                        ElementType::C3D10}) {
    for (bool nl : {false, true}) {
      ElementHarness h(t, reference_nodes(t));
      h.ctx.nlgeom = nl;
      random_displacements(h.u, 0.02, 7u);
      const ElementRecovery rec = h.recover();
      const OutputBlock* e = rec.find(ElemVar::E);
      const int nc = static_cast<int>(e->names.size());
      const int nn = plane_of(t) == PlaneKind::PlaneStress ? 2 : 3;
      std::vector<double> tr;
      for (int q = 0; q < e->n_points; ++q) {
        double s = 0.0;
        for (int c = 0; c < nn; ++c) s += e->values[q * nc + c];
        tr.push_back(s);
      }
      const auto [lo, hi] = std::minmax_element(tr.begin(), tr.end());
      const bool bbar = t == ElementType::C3D8 || t == ElementType::CPE4 || t == ElementType::CAX4;
      if (bbar)
        EXPECT_NEAR(*hi - *lo, 0.0, 1e-14) << element_info(t).name;
      else
        EXPECT_GT(*hi - *lo, 1e-4) << element_info(t).name; // random field: O(0.02) variation
    }
  }
}

// B-bar prevents volumetric locking. In the mode u_x = c x y the pointwise dilatation c y varies
// through the element but its mean is 0, so with B-bar the energy is purely deviatoric and scales
// with the shear modulus: per unit mu it barely changes from nu = 0.3 to nu = 0.4999. A plain 2x2x2
// element would add lambda * (c y)^2 terms, a factor lambda/mu ~ 5000 larger at nu = 0.4999.
TEST(ContinuumBbar, NearlyIncompressibleBendingDoesNotLock) {
  auto energy = [](double nu) {
    TestMaterial m;
    m.nu = nu;
    ElementHarness h(ElementType::C3D8, reference_nodes(ElementType::C3D8, false), m);
    for (std::size_t a = 0; a < h.X.size(); ++a) h.u[3 * a] = 1e-3 * h.X[a][0] * h.X[a][1] * 4.0;
    const std::vector<double> r = h.evaluate(false).r;
    double w = 0.0; // linear: energy = u.r / 2
    for (std::size_t i = 0; i < r.size(); ++i) w += 0.5 * h.u[i] * r[i];
    return w / (m.E / (2 * (1 + nu))); // per shear modulus
  };
  const double w03 = energy(0.3), w49 = energy(0.4999);
  EXPECT_LT(w49, 2.0 * w03);
}

TEST(ContinuumValidate, CatchesInvertedElement) {
  for (ElementType t : kAllTypes) {
    auto X = reference_nodes(t);
    ElementHarness ok(t, X);
    EXPECT_EQ(ok.kernel->validate(ok.input()), "") << element_info(t).name;
    // Mirror the element: x -> -x for 3-D, y -> -y for 2-D (the node order is now left-handed).
    if (is_3d(t)) {
      for (auto& p : X) p[0] = -p[0];
    } else {
      for (auto& p : X) p[1] = -p[1]; // (r stays positive)
    }
    ElementHarness bad(t, X);
    const std::string msg = bad.kernel->validate(bad.input());
    EXPECT_NE(msg.find("element is inverted or degenerate (Jacobian <= 0 at integration point 1)"),
              std::string::npos)
        << element_info(t).name << ": " << msg;
    EXPECT_NE(msg.find("check the node order"), std::string::npos);
  }
}

TEST(ContinuumValidate, AxisymmetricElementLeftOfTheAxis) {
  auto X = reference_nodes(ElementType::CAX4);
  for (auto& p : X) p[0] -= 3.0;
  ElementHarness h(ElementType::CAX4, X);
  EXPECT_NE(h.kernel->validate(h.input()).find("r <= 0"), std::string::npos);
}

// NLGEOM: an element turned inside out (det F <= 0) is a recoverable failure naming the element.
TEST(ContinuumNlgeom, NonPositiveDetFThrowsConvergenceFailure) {
  for (ElementType t : kAllTypes) {
    ElementHarness h(t, reference_nodes(t));
    h.ctx.nlgeom = true;
    double A[3][3] = {{0, 0, 0}, {0, -2.0, 0}, {0, 0, 0}}; // F22 = -1
    h.set_linear_field(A);
    try {
      h.evaluate(false);
      ADD_FAILURE() << element_info(t).name << ": no exception";
    } catch (const ConvergenceFailure& e) {
      EXPECT_NE(std::string(e.what()).find("element 1"), std::string::npos) << e.what();
    }
    h.ctx.nlgeom = false; // small strain: no check, no exception
    EXPECT_NO_THROW(h.evaluate(false));
  }
}

} // namespace
} // namespace gapfem::test
