// ElementKernel::stress_stiffness (eigenvalue buckling's initial-stress matrix,
// docs/theory/buckling.md §2) of the continuum kernels, against an independent oracle: the
// change of the kernel's own NLGEOM tangent along the perturbation du, whose quadratic form
// v^T dK v = v^T (K_sigma + K_u) v loses the initial-displacement part K_u for a rigid rotation v
// (K_u[v, v] = 2 E_lin(v) : D : E_nl''(du, v) and E_lin(v) = 0). So for an infinitesimal rotation
// v about z both must give the same number, for every 3-D and plane type that provides the
// matrix; the matrix is symmetric, and a rigid translation du (no stress) gives zero.
#include "unit/elements/solid/continuum_fixture.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace gapfem::test {
namespace {

double quadratic_form(const std::vector<double>& K, const std::vector<double>& v) {
  const std::size_t n = v.size();
  double q = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) q += v[i] * K[i * n + j] * v[j];
  return q;
}

TEST(StressStiffness, RigidRotationFormEqualsTheTangentsChange) {
  int provided = 0;
  for (ElementType t : continuum_types()) {
    if (element_info(t).plane == PlaneKind::Axisymmetric) continue; // no rigid rotation in r-z
    SCOPED_TRACE(element_info(t).name);
    ElementHarness h(t, reference_nodes(t));
    h.ctx.nlgeom = true;
    const int nd = dofs_per_node(t);
    const std::size_t n = static_cast<std::size_t>(h.n());
    // du: a uniaxial stretch and a shear, v: a rotation about z
    const double A[3][3] = {{1e-3, 2e-4, 0.0}, {0.0, -3e-4, 0.0}, {0.0, 0.0, 5e-4}};
    std::vector<double> du(n, 0.0), v(n, 0.0);
    for (std::size_t a = 0; a < h.X.size(); ++a)
      for (int i = 0; i < nd; ++i) {
        for (int j = 0; j < nd; ++j) du[a * nd + i] += A[i][j] * h.X[a][j];
        v[a * nd + i] = i == 0 ? -h.X[a][1] : i == 1 ? h.X[a][0] : 0.0;
      }
    std::vector<double> Ks(n * n, 0.0);
    const ElementInput in = h.input();
    if (!h.kernel->stress_stiffness(in, du, Ks)) continue;
    ++provided;
    // the oracle: (K(h du) - K(-h du)) / (2 h) of the kernel's NLGEOM tangent
    const double step = 1e-3;
    std::vector<double> dK(n * n, 0.0);
    for (const double sign : {1.0, -1.0}) {
      for (std::size_t k = 0; k < n; ++k) h.u[k] = sign * step * du[k];
      const KernelResult res = h.evaluate(true);
      for (std::size_t k = 0; k < n * n; ++k) dK[k] += sign * res.K[k] / (2.0 * step);
    }
    const double want = quadratic_form(dK, v), got = quadratic_form(Ks, v);
    EXPECT_NEAR(got, want, 1e-6 * std::abs(want) + 1e-9);
    EXPECT_GT(std::abs(want), 0.0);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < i; ++j)
        EXPECT_NEAR(Ks[i * n + j], Ks[j * n + i], 1e-9 * (std::abs(Ks[i * n + j]) + 1.0));
    // a rigid translation stresses nothing
    std::vector<double> shift(n, 0.0), K0(n * n, 0.0);
    for (std::size_t a = 0; a < h.X.size(); ++a) shift[a * nd] = 1e-3;
    h.u.assign(n, 0.0);
    ASSERT_TRUE(h.kernel->stress_stiffness(h.input(), shift, K0));
    double biggest = 0.0;
    for (double x : K0) biggest = std::max(biggest, std::abs(x));
    EXPECT_LT(biggest, 1e-6 * std::abs(want));
  }
  EXPECT_GT(provided, 10); // the fully integrated and reduced-rule bricks, plane types
}

} // namespace
} // namespace gapfem::test
