// The first-order reduced-integration elements (C3D8R, CPS4R, CPE4R, CAX4R) and their hourglass
// control (elements/solid/hourglass.hpp, reduced_kernel.hpp). The generic continuum suites
// (patch tests, rigid motions, thermal strain, finite-difference tangents with NLGEOM and with
// temperature-dependent elasticity for the T twins) cover them with the other types; here:
// - ENHANCED is the incompatible-mode element for small strain: the tangents of C3D8R and C3D8I
//   (CPS4R/CPS4I, CPE4R/CPE4I, CAX4R/CAX4I) agree to 1e-10 on a parallelepiped and on a
//   distorted element.
// - No spurious zero-energy modes: on a distorted element the stiffness has exactly the rigid
//   modes in its null space (6 in 3-D, 3 plane, 1 axisymmetric), with either approach.
// - The hourglass energy in closed form on the unit cube / square, u_x = a xi eta:
//   ENHANCED: the incompatible modes relieve the shear and free eps_yy (u_y ~ 1 - eta^2), so
//     eps_xx = 2 a eta with sigma_yy = 0: plane stress W = 1/2 E (2a)^2 <eta^2> V = 2/3 E a^2
//     (V = 1). In 3-D eps_zz cannot follow eta (the modes give eps_zz ~ zeta only), so
//     eps_zz = 0 and W = 2/3 E a^2 / (1 - nu^2);
//   STIFFNESS: W = 1/2 0.005 G V (b:b) |h|^2 a^2 with b:b = 3/2, |h|^2 = 8 (cube) and b:b = 2,
//     |h|^2 = 4 (square); the scaling factor multiplies it; the uniform strain carries nothing.
#include "continuum_fixture.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

using namespace gapfem;
using namespace gapfem::test;

namespace {

constexpr double kE = 200000.0, kNu = 0.3;

std::unique_ptr<ElementKernel> kernel_with(ElementType t, const std::vector<Vec3>& X,
                                           std::shared_ptr<Model>& model, HourglassControl mode,
                                           double scale) {
  TestMaterial m;
  m.E = kE;
  m.nu = kNu;
  model = one_element_model(t, X, m);
  SectionControls c;
  c.name = "EC-1";
  c.hourglass = mode;
  c.scale = scale;
  model->section_controls.push_back(c);
  model->solid_sections[0].controls = 0;
  static const std::vector<ElemId> elems{0};
  return make_element_kernel(KernelContext{*model, t, model->element_property[0], elems});
}

Eigen::MatrixXd tangent(const ElementKernel& k, const std::vector<Vec3>& X,
                        const std::vector<double>& u) {
  KernelProbe p(k, X);
  p.u = u;
  const KernelResult r = p.evaluate();
  const auto n = static_cast<Eigen::Index>(r.n);
  return Eigen::Map<const Eigen::Matrix<double, -1, -1, Eigen::RowMajor>>(r.K.data(), n, n);
}

double artificial_energy(const ElementKernel& k, const std::vector<Vec3>& X,
                         const std::vector<double>& u) {
  KernelProbe p(k, X);
  p.u = u;
  const ElementRecovery rec = p.recover();
  EXPECT_TRUE(rec.artificial_energy.has_value());
  return rec.artificial_energy.value_or(-1.0);
}

/// Corners of a parallelepiped: x = A xi + c (xi the cell's node coordinates).
std::vector<Vec3> parallelepiped(ElementType t) {
  const bool three = is_3d(t);
  const Eigen::Matrix3d A =
      three ? (Eigen::Matrix3d() << 0.9, 0.3, -0.1, 0.1, 0.6, 0.2, -0.2, 0.15, 0.7).finished()
            : (Eigen::Matrix3d() << 0.9, 0.35, 0, 0.15, 0.6, 0, 0, 0, 1).finished();
  std::vector<Vec3> X;
  for (const auto& xi : shape_node_coords(shape_of(t))) {
    const Eigen::Vector3d p = A * Eigen::Vector3d(xi[0], xi[1], three ? xi[2] : 0.0);
    X.push_back({p[0] + (three ? 0.0 : 2.0), p[1], three ? p[2] : 0.0});
  }
  return X;
}

} // namespace

TEST(ReducedIntegration, EnhancedEqualsIncompatibleModesOnParallelepiped) {
  for (auto [r, i] : {std::pair{ElementType::C3D8R, ElementType::C3D8I},
                      {ElementType::CPS4R, ElementType::CPS4I},
                      {ElementType::CPE4R, ElementType::CPE4I},
                      {ElementType::CAX4R, ElementType::CAX4I}}) {
    const std::vector<Vec3> X = parallelepiped(r);
    std::shared_ptr<Model> mr, mi;
    auto kr = kernel_with(r, X, mr, HourglassControl::Enhanced, 1.0);
    auto ki = kernel_with(i, X, mi, HourglassControl::Enhanced, 1.0);
    const std::vector<double> u(kr->n_dofs(), 0.0);
    const Eigen::MatrixXd Kr = tangent(*kr, X, u), Ki = tangent(*ki, X, u);
    EXPECT_LT((Kr - Ki).norm(), 1e-10 * Ki.norm()) << element_info(r).name;
    const std::vector<Vec3> Xd = reference_nodes(r);
    const Eigen::MatrixXd Kd = tangent(*ki, Xd, u);
    EXPECT_LT((tangent(*kr, Xd, u) - Kd).norm(), 1e-10 * Kd.norm()) << element_info(r).name;
  }
}

// The kernel harness with either hourglass control, small strain and NLGEOM: the tangent against
// central differences, revert-then-evaluate, and rigid motions. Under NLGEOM the hourglass forces
// K_hg u stay linear in u on the reference configuration (hourglass.hpp): a rigid rotation of the
// reference state is force free, but a rotated deformed state carries hourglass forces that do
// not turn with it when K_hg couples the components (ENHANCED); STIFFNESS penalises each
// component alike (K_hg = A x I) and turns with the body.
TEST(ReducedIntegration, KernelChecksWithEitherHourglassControl) {
  for (ElementType t :
       {ElementType::C3D8R, ElementType::CPS4R, ElementType::CPE4R, ElementType::CAX4R})
    for (HourglassControl mode : {HourglassControl::Enhanced, HourglassControl::Stiffness})
      for (bool nl : {false, true}) {
        SCOPED_TRACE(std::string(element_info(t).name) +
                     (mode == HourglassControl::Enhanced ? " ENHANCED" : " STIFFNESS") +
                     (nl ? " NLGEOM" : " small"));
        const std::vector<Vec3> X = reference_nodes(t);
        std::shared_ptr<Model> m;
        auto k = kernel_with(t, X, m, mode, 1.0);
        KernelProbe p(*k, X);
        p.ctx.nlgeom = nl;
        random_displacements(p.u, nl ? 0.05 : 0.01, 5u);
        expect_fd_tangent(p);
        expect_revert_is_exact(p);
        expect_rigid_body_invariance(p, {.from_reference = mode == HourglassControl::Enhanced});
      }
}

TEST(ReducedIntegration, OnlyRigidModesAreFree) {
  for (ElementType t :
       {ElementType::C3D8R, ElementType::CPS4R, ElementType::CPE4R, ElementType::CAX4R}) {
    const int rigid = is_3d(t) ? 6 : (element_info(t).plane == PlaneKind::Axisymmetric ? 1 : 3);
    for (HourglassControl mode : {HourglassControl::Enhanced, HourglassControl::Stiffness}) {
      const std::vector<Vec3> X = reference_nodes(t);
      std::shared_ptr<Model> m;
      auto k = kernel_with(t, X, m, mode, 1.0);
      const Eigen::MatrixXd K = tangent(*k, X, std::vector<double>(k->n_dofs(), 0.0));
      EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
      const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues();
      int zeros = 0;
      for (int j = 0; j < ev.size(); ++j) zeros += std::abs(ev[j]) < 1e-9 * ev.maxCoeff();
      EXPECT_EQ(zeros, rigid) << element_info(t).name
                              << (mode == HourglassControl::Enhanced ? " ENHANCED" : " STIFFNESS");
      // the smallest deformation mode is an hourglass mode: far from zero, even for STIFFNESS
      EXPECT_GT(ev[rigid], 1e-5 * ev.maxCoeff()) << element_info(t).name;
    }
  }
}

TEST(ReducedIntegration, HourglassEnergyInClosedForm) {
  const double a = 1e-3, G = kE / (2 * (1 + kNu));
  for (ElementType t : {ElementType::C3D8R, ElementType::CPS4R}) {
    const bool three = is_3d(t);
    std::vector<Vec3> X;
    for (const auto& xi : shape_node_coords(shape_of(t)))
      X.push_back({0.5 * (xi[0] + 1), 0.5 * (xi[1] + 1), three ? 0.5 * (xi[2] + 1) : 0.0});
    std::vector<double> u(X.size() * (three ? 3 : 2), 0.0);
    const auto xi = shape_node_coords(shape_of(t));
    for (std::size_t n = 0; n < X.size(); ++n) u[n * (three ? 3 : 2)] = a * xi[n][0] * xi[n][1];
    std::shared_ptr<Model> m;
    auto enhanced = kernel_with(t, X, m, HourglassControl::Enhanced, 1.0);
    const double w = 2.0 / 3.0 * kE * a * a / (three ? 1 - kNu * kNu : 1.0);
    EXPECT_NEAR(artificial_energy(*enhanced, X, u), w, 1e-12 * kE * a * a) << element_info(t).name;
    const double bb = three ? 1.5 : 2.0, hh = three ? 8.0 : 4.0;
    for (double s : {1.0, 2.0}) {
      auto stiff = kernel_with(t, X, m, HourglassControl::Stiffness, s);
      EXPECT_NEAR(artificial_energy(*stiff, X, u), 0.5 * s * 0.005 * G * bb * hh * a * a,
                  1e-12 * kE * a * a)
          << element_info(t).name;
      // the hourglass mode carries no uniform strain: the residual is the hourglass force alone
      const Eigen::MatrixXd K = tangent(*stiff, X, u);
      const Eigen::VectorXd uu = Eigen::Map<const Eigen::VectorXd>(u.data(), u.size());
      EXPECT_NEAR(0.5 * uu.dot(K * uu), 0.5 * s * 0.005 * G * bb * hh * a * a, 1e-12 * kE * a * a);
    }
  }
}
