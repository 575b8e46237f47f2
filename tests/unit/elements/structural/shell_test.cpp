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

/// One shell element as a probe with its own start-of-increment values and committed rotations
/// (the probe's committed history: 4 quaternion components per node).
struct OneShell {
  TestModel tm;
  KernelProbe p;

  OneShell(ElementType type, bool nlgeom, double offset = 0.0) : p(probe_of(tm, type, offset)) {
    p.ctx.nlgeom = nlgeom;
  }
  static KernelProbe probe_of(TestModel& tm, ElementType type, double offset) {
    std::vector<NodeId> ids;
    for (const Vec3& x : element_nodes(element_info(type).n_nodes)) ids.push_back(tm.add_node(x));
    return tm.probe(
        tm.add_element(type, ids, tm.add_shell_section(tm.add_material(kE, kNu), kT, offset)));
  }
  const std::vector<Vec3>& X() const { return p.X; }
  void commit_rotation(int a, const V3<double>& v) {
    const Quat<double> q = rotation::quat_exp(v);
    auto& q0 = p.state0;
    q0[4 * a] = q.w, q0[4 * a + 1] = q.x, q0[4 * a + 2] = q.y, q0[4 * a + 3] = q.z;
    p.state = p.state0;
    for (int i = 0; i < 3; ++i) p.u0[6 * a + 3 + i] = p.u[6 * a + 3 + i] = v[i];
  }
};

const ElementType kTypes[] = {ElementType::S3,  ElementType::S3R, ElementType::S4,
                              ElementType::S4R, ElementType::S8R, ElementType::S8};

// The tangent by central differences (NLGEOM: an offset section at large committed rotations),
// symmetric (the kernel does not call it unsymmetric), and revert-then-evaluate.
TEST(Shell, TangentMatchesFiniteDifferencesWithAndWithoutNlgeom) {
  for (ElementType t : kTypes)
    for (bool nl : {false, true}) {
      SCOPED_TRACE(std::string(element_info(t).name) + (nl ? " NLGEOM" : " linear"));
      OneShell s(t, nl, nl ? 0.3 : 0.0);
      std::mt19937 rng(7);
      std::uniform_real_distribution<double> d(-0.2, 0.2);
      if (nl)
        for (std::size_t a = 0; a < s.X().size(); ++a)
          s.commit_rotation(a, {d(rng), d(rng), d(rng)});
      for (double& v : s.p.u) v += d(rng);
      expect_fd_tangent(s.p);
      expect_revert_is_exact(s.p);
    }
}

// Rigid motions: from the reference state a translation and a rotation of 2.6 rad (NLGEOM) store
// no energy; at a deformed state a translation and an infinitesimal rotation (small strain)
// change nothing.
TEST(Shell, RigidMotionsOfAnySizeStoreNoEnergy) {
  for (ElementType t : kTypes) {
    SCOPED_TRACE(element_info(t).name);
    OneShell s(t, true);
    expect_rigid_body_invariance(s.p, {.angle = 2.6, .axis = {0.9, -1.3, 2.1}});
    OneShell lin(t, false);
    for (std::size_t i = 0; i < lin.p.u.size(); ++i) lin.p.u[i] = 0.01 * std::sin(1.0 + i);
    expect_rigid_body_invariance(lin.p);
  }
}

TEST(Shell, LinearStiffnessHasExactlySixRigidModesAndEqualsNlgeomAtRest) {
  for (ElementType t : kTypes) {
    SCOPED_TRACE(element_info(t).name);
    OneShell lin(t, false), nl(t, true);
    const KernelResult a = lin.p.evaluate(), b = nl.p.evaluate();
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
    for (double& v : s.p.u) v = d(rng);
    DistributedLoad load;
    load.kind = DistLoadKind::Pressure;
    ASSERT_TRUE(s.p.kernel->supports_load(load.kind, 0));
    const std::vector<double> f0 = s.p.load(load, 2.5, 0.0);
    double total = 0.0;
    for (std::size_t a = 0; a < s.X().size(); ++a) total += f0[6 * a + 2];
    EXPECT_GT(total, 0.0); // positive pressure pushes along the +z (SPOS) normal
    expect_fd_load_stiffness(s.p, load, 2.5);
  }
}

} // namespace
} // namespace gapfem::structural_test
