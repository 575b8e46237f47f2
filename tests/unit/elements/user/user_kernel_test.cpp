// The kernels of the deck's own element types under the kernel harness: a LINEAR user element
// (MatrixKernel, the stiffness of a bar) and a nonlinear one (UelKernel calling an element plugin
// defined here: an elastic-plastic bar with kinematic hardening along its current axis, the
// plastic elongation and back force as SVARS). Tangent against central differences (elastic and
// plastic, small strain and NLGEOM), revert-then-evaluate (the SVARS of an abandoned attempt leave
// no trace) and rigid motions.
#include "elements/user/matrix_kernel.hpp"
#include "elements/user/uel_kernel.hpp"
#include "elements/user/user_code.hpp"
#include "unit/elements/kernel_harness.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace gapfem::test {
namespace {

/// U1: NODES=2, DOFs 1-3 at both, PROPERTIES = k, Fy, h; VARIABLES = the plastic elongation dp
/// and the back force b. Force F = k (d - dp) with d the elongation (NLGEOM: l - L along the
/// current axis; else n0 . (u2 - u1)), inside |F - b| <= Fy, b = h dp.
int bar_plugin(gapfem_element_call* call) {
  plugin::Element e{*call};
  const double k = e.properties()[0], fy = e.properties()[1], hard = e.properties()[2];
  const auto X = e.coords();
  const auto u = e.u();
  Eigen::Vector3d D0, D;
  for (int i = 0; i < 3; ++i) {
    D0[i] = X[3 + i] - X[i];
    D[i] = D0[i] + u[3 + i] - u[i];
  }
  const double L = D0.norm(), l = D.norm();
  const Eigen::Vector3d e0 = D0 / L;
  const bool nl = call->nlgeom != 0;
  const Eigen::Vector3d n = nl ? Eigen::Vector3d(D / l) : e0;
  const double d = nl ? l - L : e0.dot(D - D0);
  double dp = e.state_start()[0], b = e.state_start()[1];
  double f = k * (d - dp), kt = k;
  const double excess = std::abs(f - b) - fy;
  if (excess > 0) {
    const double sign = f - b > 0 ? 1.0 : -1.0, dgam = excess / (k + hard);
    dp += dgam * sign;
    b += hard * dgam * sign;
    f = k * (d - dp);
    kt = k * hard / (k + hard);
  }
  e.state()[0] = dp;
  e.state()[1] = b;
  e.energy()[1] = 0.5 * f * f / k;
  Eigen::Matrix3d A = kt * n * n.transpose();
  if (nl) A += f / l * (Eigen::Matrix3d::Identity() - n * n.transpose());
  for (int i = 0; i < 3; ++i) {
    e.residual()[i] = -f * n[i];
    e.residual()[3 + i] = f * n[i];
    for (int j = 0; j < 3; ++j) {
      e.tangent(i, j) = e.tangent(3 + i, 3 + j) = A(i, j);
      e.tangent(i, 3 + j) = e.tangent(3 + i, j) = -A(i, j);
    }
  }
  return 0;
}

const std::vector<Vec3> kNodes{{0.1, 0.2, -0.1}, {1.3, 0.7, 0.5}};

UserElementType bar_type() {
  UserElementType t;
  t.name = "U1";
  t.number = 1;
  t.n_nodes = 2;
  t.n_coords = 3;
  t.n_properties = 3;
  t.n_variables = 2;
  t.node_dofs = {{1, 2, 3}, {1, 2, 3}};
  return t;
}

KernelProbe plugin_bar(bool nlgeom) {
  UelProperty props;
  props.properties = {2000.0, 30.0, 400.0};
  auto code = std::make_shared<const UserCode>(nullptr, &bar_plugin, "bar_plugin (unit test)");
  KernelProbe p(std::make_shared<UelKernel>(bar_type(), &props, code, false), kNodes);
  p.ctx.nlgeom = nlgeom;
  p.ctx.dt = 0.1;
  return p;
}

/// Elongates the bar by `stretch` along its axis plus a small transverse motion.
void stretch(KernelProbe& p, double by) {
  Eigen::Vector3d D(kNodes[1][0] - kNodes[0][0], kNodes[1][1] - kNodes[0][1],
                    kNodes[1][2] - kNodes[0][2]);
  D.normalize();
  for (int i = 0; i < 3; ++i) {
    p.u[i] = 0.002 * std::sin(1.0 + i);
    p.u[3 + i] = p.u[i] + by * D[i] + 0.003 * std::cos(2.0 + i);
  }
}

// Elastic (F = 2000 * 0.005 = 10 < 30) and plastic (from a committed plastic state, loaded
// further), small strain and NLGEOM.
TEST(UserElementPlugin, KernelChecks) {
  for (bool nl : {false, true})
    for (bool plastic : {false, true}) {
      SCOPED_TRACE(std::string(nl ? "NLGEOM" : "small") + (plastic ? " plastic" : " elastic"));
      KernelProbe p = plugin_bar(nl);
      if (plastic) {
        stretch(p, 0.03); // F = 60 > Fy: yields
        p.evaluate();
        ASSERT_GT(p.state[0], 0.0);
        p.commit();
      }
      stretch(p, plastic ? 0.04 : 0.005);
      expect_fd_tangent(p);
      expect_revert_is_exact(p);
      expect_rigid_body_invariance(p);
    }
}

// A LINEAR user element: K = k [n n^T, -n n^T; -n n^T, n n^T] of a bar along n.
TEST(UserElementMatrix, KernelChecks) {
  Eigen::Vector3d n(kNodes[1][0] - kNodes[0][0], kNodes[1][1] - kNodes[0][1],
                    kNodes[1][2] - kNodes[0][2]);
  n.normalize();
  std::vector<double> K(36, 0.0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double v = 1500.0 * n[i] * n[j];
      K[i * 6 + j] = K[(3 + i) * 6 + 3 + j] = v;
      K[i * 6 + 3 + j] = K[(3 + i) * 6 + j] = -v;
    }
  KernelProbe p(std::make_shared<MatrixKernel>(ElementType::USER,
                                               NodeDofTable({{1, 2, 3}, {1, 2, 3}}), K, false),
                kNodes);
  stretch(p, 0.01);
  expect_fd_tangent(p);
  expect_revert_is_exact(p);
  expect_rigid_body_invariance(p);
}

// *MATRIX, TYPE=MASS of a LINEAR user element is the kernel's mass operator, given back exactly
// when asked for; without it the element is massless.
TEST(UserElementMatrix, MassMatrixIsTheDecksOwn) {
  std::vector<double> K(36, 0.0), M(36, 0.0);
  for (int i = 0; i < 6; ++i) {
    K[i * 6 + i] = 10.0;
    M[i * 6 + i] = 2.0 + i;                                 // a lumped mass ...
    if (i < 3) M[i * 6 + 3 + i] = M[(3 + i) * 6 + i] = 0.5; // ... with a coupling term
  }
  const MatrixKernel plain(ElementType::USER, NodeDofTable({{1, 2, 3}, {1, 2, 3}}), K, false);
  EXPECT_FALSE(plain.has_mass());
  const MatrixKernel massive(ElementType::USER, NodeDofTable({{1, 2, 3}, {1, 2, 3}}), K, false, M);
  ASSERT_TRUE(massive.has_mass());
  EXPECT_FALSE(massive.has_damping());
  std::vector<double> u(6, 0.0), r(6, 0.0), T(36, 0.0), Me(36, 0.0);
  std::vector<Vec3> X(kNodes.begin(), kNodes.end());
  ElementInput in;
  in.X = X;
  in.u = u;
  in.u_start = u;
  ElementOutput out;
  out.residual = r;
  out.tangent = T;
  out.mass = Me;
  out.want_mass = true;
  massive.evaluate(in, out);
  EXPECT_EQ(Me, M);
  EXPECT_EQ(T, K);
}

} // namespace
} // namespace gapfem::test
