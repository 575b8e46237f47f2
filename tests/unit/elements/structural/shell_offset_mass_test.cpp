// The mass of a shell with a reference surface OFFSET (shell.cpp, add_mass; docs/theory/dynamics.md
// §8): the section's material lies at z in [zm - t/2, zm + t/2] along the normal from the
// reference surface (the nodes), zm = -offset t. Per unit area, integrating rho through the
// thickness in closed form:
//   mass               rho t                          (unchanged by the offset)
//   first moment       S = rho t zm                   (couples u and the rotations:
//                                                      the kinetic energy S u'.(w x n))
//   rotary inertia     rho (t^3/12 + t zm^2)          (about the reference surface)
// For a flat element in the x-y plane (n = e_z) w x n = (w_y, -w_x, 0), so M couples u_x with
// w_y by +S and u_y with w_x by -S; summed over the element: times the area A. Quadrature of
// these polynomials is exact, so the sums hold to round-off (1e-12 relative).
#include "structural_test_support.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace gapfem::structural_test {
namespace {

constexpr double kRho = 7800.0, kT = 0.02;

/// M of a flat 2 x 3 rectangle (S4R, S4: lumped; S8R: consistent) or the triangle of half of it.
std::vector<double> mass(ElementType type, double offset, int& n_nodes, double& area) {
  TestModel tm;
  const int mat = tm.add_material(2.1e11, 0.3, 0.0, kRho);
  const std::vector<Vec3> X = {{0, 0, 0}, {2, 0, 0},   {2, 3, 0}, {0, 3, 0},
                               {1, 0, 0}, {2, 1.5, 0}, {1, 3, 0}, {0, 1.5, 0}};
  n_nodes = element_info(type).n_nodes;
  area = n_nodes == 3 ? 3.0 : 6.0;
  std::vector<NodeId> nodes;
  for (int a = 0; a < n_nodes; ++a) nodes.push_back(tm.add_node(X[a]));
  const ElemId e = tm.add_element(type, nodes, tm.add_shell_section(mat, kT, offset));
  KernelProbe p = tm.probe(e);
  EXPECT_TRUE(p.kernel->has_mass());
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

TEST(ShellOffsetMass, InertiaAboutTheReferenceSurfaceAndTheCoupling) {
  for (const ElementType type :
       {ElementType::S3R, ElementType::S4R, ElementType::S4, ElementType::S8R})
    for (const double offset : {0.0, 0.5, -0.5, 1.3}) {
      SCOPED_TRACE(::testing::Message() << element_info(type).name << " offset " << offset);
      int nn = 0;
      double A = 0.0;
      const std::vector<double> M = mass(type, offset, nn, A);
      const int n = 6 * nn;
      const double zm = -offset * kT;
      const double m = kRho * kT * A, S = kRho * kT * zm * A;
      const double I = kRho * (kT * kT * kT / 12.0 + kT * zm * zm) * A;
      // sums over all node pairs of one DOF against another
      auto sum = [&](int i, int j) {
        double s = 0.0;
        for (int a = 0; a < nn; ++a)
          for (int b = 0; b < nn; ++b) s += M[(6 * a + i) * n + 6 * b + j];
        return s;
      };
      for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(sum(i, i), m, 1e-12 * m);
        EXPECT_NEAR(sum(3 + i, 3 + i), I, 1e-12 * I);
      }
      const double tol = 1e-12 * m * kT;
      EXPECT_NEAR(sum(0, 4), S, tol); // u_x with w_y
      EXPECT_NEAR(sum(4, 0), S, tol);
      EXPECT_NEAR(sum(1, 3), -S, tol); // u_y with w_x
      EXPECT_NEAR(sum(3, 1), -S, tol);
      EXPECT_NEAR(sum(2, 3), 0.0, tol); // nothing with the normal translation
      EXPECT_NEAR(sum(2, 4), 0.0, tol);
      EXPECT_NEAR(sum(0, 5), 0.0, tol); // nor with the drilling rotation
      // symmetric, and positive semi-definite (the section's own inertia t^3/12 keeps the 2 x 2
      // blocks [rho t, S; S, rho (t^3/12 + t zm^2)] positive: determinant rho^2 t^4 / 12)
      Eigen::MatrixXd Mm(n, n);
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          Mm(i, j) = M[i * n + j];
          EXPECT_EQ(M[i * n + j], M[j * n + i]) << i << ", " << j;
        }
      const double least = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Mm).eigenvalues()(0);
      EXPECT_GE(least, -1e-13 * Mm.norm());
      // first order: lumped per node (no entry between two different nodes)
      if (nn < 8)
        for (int a = 0; a < nn; ++a)
          for (int b = 0; b < nn; ++b)
            for (int i = 0; i < 6 && a != b; ++i)
              for (int j = 0; j < 6; ++j) EXPECT_EQ(M[(6 * a + i) * n + 6 * b + j], 0.0);
    }
}

// A rigid motion of the lumped S4R (nodal velocities V + w x X_a, rotations w): what the offset
// adds to the kinetic energy 1/2 q^T M q is, from the per-node lumps (a quarter of the element's
// each, the rectangle's row sums), S (V + w x Xc).(w x n) + rho t zm^2 A |w|^2 / 2, Xc the
// centroid (the coupling is linear in the nodal velocity, whose mean is that of the centroid).
TEST(ShellOffsetMass, RigidTiltKineticEnergyOfTheOffsetTerms) {
  int nn = 0;
  double A = 0.0;
  const std::vector<double> M0 = mass(ElementType::S4R, 0.0, nn, A);
  const std::vector<double> M1 = mass(ElementType::S4R, 0.5, nn, A);
  const int n = 6 * nn;
  const std::vector<Vec3> X = {{0, 0, 0}, {2, 0, 0}, {2, 3, 0}, {0, 3, 0}};
  const Vec3 V{0.3, -0.2, 0.1}, w{0.7, 0.4, 0.0};
  std::vector<double> q(n);
  for (int a = 0; a < nn; ++a) {
    const Vec3 wx{w[1] * X[a][2] - w[2] * X[a][1], w[2] * X[a][0] - w[0] * X[a][2],
                  w[0] * X[a][1] - w[1] * X[a][0]};
    for (int i = 0; i < 3; ++i) {
      q[6 * a + i] = V[i] + wx[i];
      q[6 * a + 3 + i] = w[i];
    }
  }
  auto energy = [&](const std::vector<double>& M) {
    double e = 0.0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) e += 0.5 * q[i] * M[i * n + j] * q[j];
    return e;
  };
  const double zm = -0.5 * kT, S = kRho * kT * zm * A;
  const Vec3 wn{w[1], -w[0], 0.0};
  const Vec3 Xc{1.0, 1.5, 0.0};
  const Vec3 wXc{w[1] * Xc[2] - w[2] * Xc[1], w[2] * Xc[0] - w[0] * Xc[2],
                 w[0] * Xc[1] - w[1] * Xc[0]};
  double Vwn = 0.0;
  for (int i = 0; i < 3; ++i) Vwn += (V[i] + wXc[i]) * wn[i];
  const double w2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
  const double dE = S * Vwn + 0.5 * kRho * kT * zm * zm * A * w2;
  EXPECT_NEAR(energy(M1) - energy(M0), dE, 1e-12 * energy(M0));
}

} // namespace
} // namespace gapfem::structural_test
