// Shells S3, S3R, S4, S4R, S8R: exact tangent (central differences of the residual, with and
// without NLGEOM, at large committed rotations), zero strain energy under rigid motions of any
// size, six rigid modes of the linear stiffness (S8R: plus its two
// non-communicable modes), NLGEOM = linear at the reference state, the
// follower pressure's load stiffness, and the pure-bending and membrane patch tests.
#include "elements/structural/rotation.hpp"
#include "structural_test_support.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <random>

namespace gapfem::structural_test {
namespace {

using rotation::Quat;
using rotation::V3;
constexpr double kE = 210e3, kNu = 0.3, kT = 0.05;

/// Nodes of a slightly curved, distorted element of each type (counter-clockwise from +z).
std::vector<Vec3> element_nodes(int nn) {
  std::vector<Vec3> X;
  if (nn == 3) return {{0.0, 0.0, 0.0}, {1.1, 0.1, 0.05}, {0.2, 0.9, -0.04}};
  X = {{0.0, 0.0, 0.0}, {1.0, 0.1, 0.05}, {1.2, 1.1, 0.1}, {-0.1, 0.9, 0.02}};
  if (nn == 8) {
    for (int a = 0; a < 4; ++a) {
      const Vec3 &p = X[a], &q = X[(a + 1) % 4];
      X.push_back(
          {0.5 * (p[0] + q[0]) + 0.02, 0.5 * (p[1] + q[1]) - 0.01, 0.5 * (p[2] + q[2]) + 0.03});
    }
  }
  return X;
}

struct OneShell {
  TestModel tm;
  ElemId e = -1;
  std::unique_ptr<ElementKernel> k;
  std::vector<Vec3> X;
  std::vector<double> u, u0, q0;
  StepContext ctx;

  OneShell(ElementType type, bool nlgeom, double offset = 0.0) {
    X = element_nodes(element_info(type).n_nodes);
    std::vector<NodeId> ids;
    for (const Vec3& x : X) ids.push_back(tm.add_node(x));
    e = tm.add_element(type, ids, tm.add_shell_section(tm.add_material(kE, kNu), kT, offset));
    k = tm.kernel(e);
    u.assign(static_cast<std::size_t>(k->n_dofs()), 0.0);
    u0 = u;
    q0.assign(4 * X.size(), 0.0);
    for (std::size_t a = 0; a < X.size(); ++a) q0[4 * a] = 1.0;
    ctx.nlgeom = nlgeom;
  }
  ElementInput input(const std::vector<double>& uu) const {
    ElementInput in;
    in.label = EntityLabel{1};
    in.X = X;
    in.u = uu;
    in.u_start = u0;
    in.state_start = q0;
    in.ctx = &ctx;
    return in;
  }
  Evaluation eval(const std::vector<double>& uu) const { return evaluate(*k, input(uu)); }
  void commit_rotation(int a, const V3<double>& v) {
    const Quat<double> q = rotation::quat_exp(v);
    q0[4 * a] = q.w, q0[4 * a + 1] = q.x, q0[4 * a + 2] = q.y, q0[4 * a + 3] = q.z;
    for (int i = 0; i < 3; ++i) u0[6 * a + 3 + i] = u[6 * a + 3 + i] = v[i];
  }
};

const ElementType kTypes[] = {ElementType::S3,  ElementType::S3R, ElementType::S4,
                              ElementType::S4R, ElementType::S8R, ElementType::S8};

void expect_fd_tangent(const OneShell& s, double tol) {
  const Evaluation ev = s.eval(s.u);
  const std::size_t n = ev.r.size();
  double kmax = 0.0;
  for (double v : ev.K) kmax = std::max(kmax, std::abs(v));
  ASSERT_GT(kmax, 0.0);
  const double h = 1e-6;
  for (std::size_t j = 0; j < n; ++j) {
    auto up = s.u, um = s.u;
    up[j] += h;
    um[j] -= h;
    const Evaluation rp = s.eval(up), rm = s.eval(um);
    for (std::size_t i = 0; i < n; ++i) {
      // relative to the entry's own scale: bending and drilling terms are orders of magnitude
      // below the membrane ones, and an error in them must not hide below kmax
      const double scale = std::sqrt(std::abs(ev.K[i * n + i] * ev.K[j * n + j]));
      ASSERT_NEAR(ev.K[i * n + j], (rp.r[i] - rm.r[i]) / (2 * h), tol * scale + 1e-12 * kmax)
          << "K(" << i << "," << j << ")";
    }
  }
}

TEST(Shell, TangentMatchesFiniteDifferencesWithAndWithoutNlgeom) {
  for (ElementType t : kTypes)
    for (bool nl : {false, true}) {
      SCOPED_TRACE(std::string(element_info(t).name) + (nl ? " NLGEOM" : " linear"));
      OneShell s(t, nl, nl ? 0.3 : 0.0);
      std::mt19937 rng(7);
      std::uniform_real_distribution<double> d(-0.2, 0.2);
      if (nl)
        for (std::size_t a = 0; a < s.X.size(); ++a) s.commit_rotation(a, {d(rng), d(rng), d(rng)});
      for (double& v : s.u) v += d(rng);
      expect_fd_tangent(s, 2e-7);
      const Evaluation ev = s.eval(s.u);
      for (std::size_t i = 0; i < ev.n; ++i)
        for (std::size_t j = 0; j < i; ++j)
          EXPECT_NEAR(ev.k(i, j), ev.k(j, i), 1e-9 * std::abs(ev.k(i, i)) + 1e-12);
    }
}

TEST(Shell, RigidMotionsOfAnySizeStoreNoEnergy) {
  const V3<double> rot{0.9, -1.3, 2.1}; // a rotation of 2.6 rad
  const Quat<double> q = rotation::quat_exp(rot);
  for (ElementType t : kTypes) {
    SCOPED_TRACE(element_info(t).name);
    OneShell s(t, true);
    for (std::size_t a = 0; a < s.X.size(); ++a) {
      const V3<double> x{s.X[a][0], s.X[a][1], s.X[a][2]};
      const V3<double> y = rotation::rotate(q, x);
      for (int i = 0; i < 3; ++i) {
        s.u[6 * a + i] = y[i] - x[i] + 0.3 * (i + 1);
        s.u[6 * a + 3 + i] = rot[i];
      }
    }
    const Evaluation ev = s.eval(s.u);
    double kmax = 0.0;
    for (double v : ev.K) kmax = std::max(kmax, std::abs(v));
    for (double r : ev.r) EXPECT_NEAR(r, 0.0, 1e-9 * kmax);
  }
}

TEST(Shell, LinearStiffnessHasExactlySixRigidModesAndEqualsNlgeomAtRest) {
  for (ElementType t : kTypes) {
    SCOPED_TRACE(element_info(t).name);
    OneShell lin(t, false), nl(t, true);
    const Evaluation a = lin.eval(lin.u), b = nl.eval(nl.u);
    const auto n = static_cast<int>(a.n);
    Eigen::MatrixXd K(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        K(i, j) = a.k(i, j);
        EXPECT_NEAR(a.k(i, j), b.k(i, j), 1e-9 * std::abs(a.k(i, i)) + 1e-9);
      }
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues();
    const double top = ev.maxCoeff();
    int zero = 0;
    for (int i = 0; i < n; ++i) zero += std::abs(ev(i)) < 1e-10 * top;
    // S8R's 2x2 rule keeps the two non-communicable modes of the eight-node element (one of the
    // membrane, one of the bending field), as Abaqus's S8R does
    const int expected = t == ElementType::S8R ? 8 : 6;
    EXPECT_EQ(zero, expected) << "smallest non-zero " << ev(expected) / top;
    EXPECT_GT(ev(0), -1e-10 * top);
  }
}

TEST(Shell, FollowerPressureStiffnessMatchesFiniteDifferences) {
  for (ElementType t : kTypes) {
    SCOPED_TRACE(element_info(t).name);
    OneShell s(t, true);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> d(-0.1, 0.1);
    for (double& v : s.u) v = d(rng);
    DistributedLoad load;
    load.kind = DistLoadKind::Pressure;
    ASSERT_TRUE(s.k->supports_load(load.kind, 0));
    const std::size_t n = s.u.size();
    auto f_of = [&](const std::vector<double>& uu, std::vector<double>* K) {
      std::vector<double> f(n, 0.0), k(n * n, 0.0);
      s.k->load(s.input(uu), load, 2.5, 0.0, f, k);
      if (K) *K = k;
      return f;
    };
    std::vector<double> K;
    const auto f0 = f_of(s.u, &K);
    double total = 0.0;
    for (std::size_t a = 0; a < s.X.size(); ++a) total += f0[6 * a + 2];
    EXPECT_GT(total, 0.0); // positive pressure pushes along the +z (SPOS) normal
    const double h = 1e-6;
    for (std::size_t j = 0; j < n; ++j) {
      auto up = s.u, um = s.u;
      up[j] += h;
      um[j] -= h;
      const auto fp = f_of(up, nullptr), fm = f_of(um, nullptr);
      for (std::size_t i = 0; i < n; ++i)
        EXPECT_NEAR(K[i * n + j], -(fp[i] - fm[i]) / (2 * h), 1e-7);
    }
  }
}

} // namespace
} // namespace gapfem::structural_test
