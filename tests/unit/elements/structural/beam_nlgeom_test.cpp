// Beams B21, B22, B31, B32, PIPE31 under NLGEOM and the new element layouts: exact tangent
// (central differences of the residual at large, committed rotations), zero strain under rigid
// motions of any size, rigid-mode count of the linear stiffness, NLGEOM = linear at the reference
// state, the follower load stiffness of P1/P2, and the section library (BOX, I, GENERAL).
#include "elements/structural/beam_section.hpp"
#include "elements/structural/rotation.hpp"
#include "structural_test_support.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <random>

namespace gapfem::structural_test {
namespace {

using Shape = BeamSection::Shape;
using rotation::Quat;
using rotation::V3;
constexpr double kE = 210e3, kNu = 0.3;

/// One beam element of a type, as a probe with its own start-of-increment values and committed
/// rotations (the probe's committed history: 4 quaternion components per node).
struct OneElement {
  TestModel tm;
  ElemId e = -1;
  KernelProbe p;
  int dpn = 6;

  OneElement(ElementType type, std::vector<Vec3> nodes, Shape shape, std::vector<double> dims,
             bool nlgeom)
      : p(probe_of(tm, e, type, nodes, shape, dims)) {
    dpn = static_cast<int>(p.kernel->node_dofs(0).size());
    p.ctx.nlgeom = nlgeom;
    p.ctx.model_size = 1.0;
  }
  static KernelProbe probe_of(TestModel& tm, ElemId& e, ElementType type,
                              const std::vector<Vec3>& nodes, Shape shape,
                              const std::vector<double>& dims) {
    std::vector<NodeId> ids;
    for (const Vec3& x : nodes) ids.push_back(tm.add_node(x));
    const Vec3 n1 =
        element_info(type).space == SpaceRequirement::Planar ? Vec3{0, 0, -1} : Vec3{0.3, 1.0, 0.2};
    e = tm.add_element(type, ids, tm.add_beam_section(tm.add_material(kE, kNu), shape, dims, n1));
    return tm.probe(e);
  }
  int rot0() const { return dpn == 3 ? 2 : 3; }
  const std::vector<Vec3>& X() const { return p.X; }
  KernelResult eval(const std::vector<double>& uu) {
    p.u = uu;
    return p.evaluate();
  }
  /// Gives node a the committed rotation vector v (start of the increment) and DOF values v.
  void commit_rotation(int a, const V3<double>& v) {
    const Quat<double> q = rotation::quat_exp(v);
    auto& q0 = p.state0;
    q0[4 * a] = q.w, q0[4 * a + 1] = q.x, q0[4 * a + 2] = q.y, q0[4 * a + 3] = q.z;
    p.state = p.state0;
    for (int i = 0; i < (dpn == 3 ? 1 : 3); ++i) {
      const double c = dpn == 3 ? v[2] : v[i];
      p.u0[a * dpn + rot0() + i] = c;
      p.u[a * dpn + rot0() + i] = c;
    }
  }
};

struct Layout {
  ElementType type;
  int nodes;
};
const Layout kLayouts[] = {{ElementType::B31, 2},
                           {ElementType::B32, 3},
                           {ElementType::B21, 2},
                           {ElementType::B22, 3},
                           {ElementType::PIPE31, 2}};

std::vector<Vec3> nodes_of(const Layout& l) {
  const bool planar = element_info(l.type).space == SpaceRequirement::Planar;
  const Vec3 a{0.1, 0.2, 0.0}, b = planar ? Vec3{1.1, 0.6, 0.0} : Vec3{1.0, 0.5, 0.3};
  if (l.nodes == 2) return {a, b};
  // a slightly curved three-node element (middle node off the chord)
  return {a, {0.5 * (a[0] + b[0]) + 0.05, 0.5 * (a[1] + b[1]) - 0.04, 0.5 * (a[2] + b[2])}, b};
}

Shape shape_of(ElementType t) {
  return t == ElementType::PIPE31 ? Shape::Pipe : Shape::Rect;
}
std::vector<double> dims_of(ElementType t) {
  return t == ElementType::PIPE31 ? std::vector<double>{0.08, 0.01}
                                  : std::vector<double>{0.06, 0.1};
}

TEST(StructuralBeamNlgeom, TangentIsExactAtLargeCommittedRotations) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (const Layout& l : kLayouts) {
    OneElement el(l.type, nodes_of(l), shape_of(l.type), dims_of(l.type), true);
    // committed rotations of about a radian, then a trial state well away from them
    for (int a = 0; a < l.nodes; ++a)
      el.commit_rotation(a, el.dpn == 3 ? V3<double>{0, 0, 0.9 + 0.2 * a}
                                        : V3<double>{0.5 * U(rng), 0.8 + 0.1 * a, 0.4 * U(rng)});
    for (double& v : el.p.u) v += 0.15 * U(rng);
    SCOPED_TRACE(element_info(l.type).name);
    expect_fd_tangent(el.p);
    expect_revert_is_exact(el.p);
  }
}

TEST(StructuralBeamNlgeom, TangentIsExactNearTheReferenceState) {
  // the series branches of the rotation functions (rotations below 0.2 rad)
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (const Layout& l : kLayouts) {
    OneElement el(l.type, nodes_of(l), shape_of(l.type), dims_of(l.type), true);
    for (double& v : el.p.u) v += 1e-3 * U(rng);
    SCOPED_TRACE(element_info(l.type).name);
    expect_fd_tangent(el.p);
  }
}

// A translation and a rotation of 0.3, 2 and 3 rad from the reference state store no energy; a
// small-strain beam at a deformed state is indifferent to a translation and an infinitesimal
// rotation.
TEST(StructuralBeamNlgeom, RigidMotionsOfAnySizeAreStrainFree) {
  for (const Layout& l : kLayouts) {
    SCOPED_TRACE(element_info(l.type).name);
    for (double angle : {0.3, 2.0, 3.0}) {
      OneElement el(l.type, nodes_of(l), shape_of(l.type), dims_of(l.type), true);
      expect_rigid_body_invariance(el.p, {.angle = angle});
    }
    OneElement lin(l.type, nodes_of(l), shape_of(l.type), dims_of(l.type), false);
    for (std::size_t i = 0; i < lin.p.u.size(); ++i) lin.p.u[i] = 0.01 * std::sin(1.0 + i);
    expect_rigid_body_invariance(lin.p);
  }
}

TEST(StructuralBeamNlgeom, LinearStiffnessHasOnlyTheRigidModesAndEqualsNlgeomAtRest) {
  for (const Layout& l : kLayouts) {
    OneElement lin(l.type, nodes_of(l), shape_of(l.type), dims_of(l.type), false);
    OneElement nl(l.type, nodes_of(l), shape_of(l.type), dims_of(l.type), true);
    const KernelResult a = lin.p.evaluate(), b = nl.p.evaluate();
    const auto n = static_cast<int>(a.n);
    Eigen::MatrixXd K(n, n);
    double kmax = 0.0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        K(i, j) = a.k(i, j);
        kmax = std::max(kmax, std::abs(K(i, j)));
        EXPECT_NEAR(a.k(i, j), b.k(i, j), 1e-10 * std::abs(a.k(i, j)) + 1e-12 * kmax);
      }
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues();
    const int rigid = lin.dpn == 3 ? 3 : 6;
    for (int i = 0; i < n; ++i) {
      if (i < rigid)
        EXPECT_LT(std::abs(ev(i)), 1e-9 * kmax) << element_info(l.type).name << " mode " << i;
      else
        EXPECT_GT(ev(i), 1e-9 * kmax) << element_info(l.type).name << " mode " << i;
    }
  }
}

/// The load stiffness of a load of `kind` on `face` against central differences (the harness).
void expect_face_load_stiffness(OneElement& el, DistLoadKind kind, int face, double magnitude) {
  SCOPED_TRACE(std::string(element_info(el.p.kernel->type()).name) + " face " +
               std::to_string(face));
  ASSERT_TRUE(el.p.kernel->supports_load(kind, face));
  expect_fd_load_stiffness(el.p, test::distributed_load(kind, face), magnitude);
}

TEST(StructuralBeamNlgeom, FollowerLineLoadStiffnessMatchesCentralDifferences) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (const Layout& l : kLayouts) {
    OneElement el(l.type, nodes_of(l), shape_of(l.type), dims_of(l.type), true);
    const bool planar = el.dpn == 3;
    for (int a = 0; a < l.nodes; ++a)
      el.commit_rotation(a, planar ? V3<double>{0, 0, 0.7} : V3<double>{0.2, 0.7, -0.3});
    for (double& v : el.p.u) v += 0.1 * U(rng);
    for (int face : {1, 2}) {
      if (planar && face == 1) continue;
      expect_face_load_stiffness(el, DistLoadKind::LineLoad, face, 2.5);
    }
  }
}

TEST(StructuralBeamNlgeom, PipePressureStiffnessMatchesCentralDifferences) {
  // PI/PE: f = F dl/dx, conservative, stiffness -F d2l/dx2; PIPE32 curved (nodes_of)
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (const Layout& l : {Layout{ElementType::PIPE31, 2}, Layout{ElementType::PIPE32, 3}}) {
    OneElement el(l.type, nodes_of(l), Shape::Pipe, {0.08, 0.01}, true);
    for (double& v : el.p.u) v += 0.1 * U(rng);
    for (int face : {1, 2}) {
      expect_face_load_stiffness(el, DistLoadKind::PipePressure, face, 3.0);
    }
  }
}

TEST(StructuralBeamSections, BoxIAndGeneralProperties) {
  BeamSection box;
  box.shape = Shape::Box;
  box.dims = {0.2, 0.3, 0.01, 0.02, 0.01, 0.02}; // thin walls: mid-line 0.19 x 0.28
  const auto b = beam_section_properties(box);
  const double w = 0.19, h = 0.28;
  EXPECT_NEAR(b.A, 2 * h * 0.01 + 2 * w * 0.02, 1e-14);
  // I11 = 2 (t h^3 / 12) [webs] + 2 (t_f w) (h/2)^2 [flanges]
  EXPECT_NEAR(b.I11, 2 * 0.01 * h * h * h / 12 + 2 * 0.02 * w * h * h / 4, 1e-14);
  EXPECT_NEAR(b.I22, 2 * 0.02 * w * w * w / 12 + 2 * 0.01 * h * w * w / 4, 1e-14);
  EXPECT_NEAR(b.Q1, 0.0, 1e-15);
  EXPECT_NEAR(b.Q2, 0.0, 1e-15);
  // Bredt: J = 4 A_m^2 / sum(L/t)
  EXPECT_NEAR(b.J, 4 * w * w * h * h / (2 * h / 0.01 + 2 * w / 0.02), 1e-14);
  EXPECT_DOUBLE_EQ(b.k, 0.44);

  BeamSection I;
  I.shape = Shape::I;
  // l = 0.1 from the bottom face, h = 0.3, flanges 0.2 and 0.1 wide, t 0.02, 0.01, web 0.008
  I.dims = {0.1, 0.3, 0.2, 0.1, 0.02, 0.01, 0.008};
  const auto p = beam_section_properties(I);
  const double yb = -0.1 + 0.01, yt = 0.3 - 0.1 - 0.005, Lw = yt - yb;
  const double Ab = 0.2 * 0.02, At = 0.1 * 0.01, Aw = Lw * 0.008;
  EXPECT_NEAR(p.A, Ab + At + Aw, 1e-15);
  EXPECT_NEAR(p.Q2, Ab * yb + At * yt + Aw * 0.5 * (yb + yt), 1e-15);
  EXPECT_NEAR(p.I11, Ab * yb * yb + At * yt * yt + 0.008 * (yt * yt * yt - yb * yb * yb) / 3,
              1e-15);
  EXPECT_NEAR(p.I22, 0.02 * std::pow(0.2, 3) / 12 + 0.01 * std::pow(0.1, 3) / 12, 1e-15);
  EXPECT_NEAR(p.J, (0.2 * 8e-6 + 0.1 * 1e-6 + Lw * std::pow(0.008, 3)) / 3, 1e-18);
  I.dims = {0.1, 0.02, 0.2, 0.1, 0.02, 0.01, 0.008}; // flanges thicker than the height
  EXPECT_THROW(beam_section_properties(I), InputError);

  BeamSection g;
  g.shape = Shape::General;
  g.dims = {2.5e-2, 1e-4, 2e-5, 1.5e-4, 3e-5};
  const auto q = beam_section_properties(g);
  EXPECT_EQ(q.A, 2.5e-2);
  EXPECT_EQ(q.I12, 2e-5);
  EXPECT_EQ(q.n_points, 0);
  g.dims = {2.5e-2, 1e-4, 2e-4, 1.5e-4, 3e-5}; // I12^2 > I11 I22
  EXPECT_THROW(beam_section_properties(g), InputError);
  g.dims = {2.5e-2, 1e-4};
  EXPECT_NO_THROW(beam_section_properties(g, true)); // planar: A, I11 suffice
  EXPECT_THROW(beam_section_properties(g, false), InputError);
}

/// Area, first and second moments of a simple polygon (counter-clockwise), about the origin.
struct PolygonMoments {
  double A = 0, Q1 = 0, Q2 = 0, I11 = 0, I22 = 0, I12 = 0;
};
PolygonMoments polygon(const std::vector<std::array<double, 2>>& v) {
  // by triangles fanned from the origin, each with its exact moments (Gauss rule of degree 2
  // on the mid-edge points is exact for quadratics)
  PolygonMoments m;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const auto& p = v[i];
    const auto& q = v[(i + 1) % v.size()];
    const double area = 0.5 * (p[0] * q[1] - q[0] * p[1]);
    const std::array<double, 2> mids[3] = {{0.5 * p[0], 0.5 * p[1]},
                                           {0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1])},
                                           {0.5 * q[0], 0.5 * q[1]}};
    m.A += area;
    for (const auto& x : mids) {
      m.Q1 += area / 3 * x[0];
      m.Q2 += area / 3 * x[1];
      m.I11 += area / 3 * x[1] * x[1];
      m.I22 += area / 3 * x[0] * x[0];
      m.I12 += area / 3 * x[0] * x[1];
    }
  }
  return m;
}

TEST(StructuralBeamSections, LSectionAboutItsCentroid) {
  // thin legs: the mid-line (thin-walled) properties approach the solid L's as (t/L)^2
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> size(0.05, 0.2), thin(0.002, 0.004);
  for (int trial = 0; trial < 20; ++trial) {
    const double a = size(rng), b = size(rng), t1 = thin(rng), t2 = thin(rng);
    BeamSection L;
    L.shape = Shape::L;
    L.dims = {a, b, t1, t2};
    const auto p = beam_section_properties(L);
    // the solid L with its outer corner at the origin: leg a along +1, leg b along +2
    const auto m = polygon({{0, 0}, {a, 0}, {a, t1}, {t2, t1}, {t2, b}, {0, b}});
    const double c1 = m.Q1 / m.A, c2 = m.Q2 / m.A;
    EXPECT_NEAR(p.A, m.A, 1e-15);
    EXPECT_NEAR(p.Q1, 0.0, 1e-15); // the origin is the centroid
    EXPECT_NEAR(p.Q2, 0.0, 1e-15);
    const double I11 = m.I11 - m.A * c2 * c2, I22 = m.I22 - m.A * c1 * c1;
    const double I12 = m.I12 - m.A * c1 * c2;
    const double tol = 3.0 * std::pow(std::max(t1, t2) / std::min(a, b), 2);
    EXPECT_NEAR(p.I11 / I11, 1.0, tol);
    EXPECT_NEAR(p.I22 / I22, 1.0, tol);
    EXPECT_LT(p.I12, 0.0); // an L opening to +1, +2: the legs lie in the 2nd/4th quadrants
    EXPECT_NEAR(p.I12 / I12, 1.0, tol);
    EXPECT_NEAR(p.J, ((a - t2 / 2) * t1 * t1 * t1 + (b - t1 / 2) * t2 * t2 * t2) / 3, 1e-18);
    ASSERT_EQ(p.n_points, 3);
    EXPECT_NEAR(p.points[1][0], -c1, 1e-3 * a); // the outer corner
    EXPECT_NEAR(p.points[1][1], -c2, 1e-3 * b);
  }
  BeamSection L;
  L.shape = Shape::L;
  L.dims = {0.1, 0.05, 0.06, 0.01}; // t1 >= b
  EXPECT_THROW(beam_section_properties(L), InputError);
}

TEST(StructuralBeamSections, TrapezoidRectangleTriangleAndOffset) {
  BeamSection t;
  t.shape = Shape::Trapezoid;
  t.dims = {0.3, 0.2, 0.3, 0.1}; // a rectangle 0.3 x 0.2 about its centre
  auto p = beam_section_properties(t);
  EXPECT_NEAR(p.A, 0.06, 1e-15);
  EXPECT_NEAR(p.I11, 0.3 * 0.008 / 12, 1e-15);
  EXPECT_NEAR(p.I22, 0.2 * 0.027 / 12, 1e-15);
  EXPECT_NEAR(p.J / rectangle_torsion_constant(0.3, 0.2), 1.0, 1e-5);
  // equilateral triangle of side s about its centroid: I = sqrt(3) s^4 / 96 and the exact
  // Saint-Venant constant J = sqrt(3) s^4 / 80 (Timoshenko & Goodier §112)
  const double s = 0.12, h = s * std::sqrt(3.0) / 2;
  t.dims = {s, h, 0.0, h / 3};
  p = beam_section_properties(t);
  EXPECT_NEAR(p.Q2, 0.0, 1e-16);
  EXPECT_NEAR(p.I11 / (std::sqrt(3.0) * std::pow(s, 4) / 96), 1.0, 1e-12);
  EXPECT_NEAR(p.I22 / (std::sqrt(3.0) * std::pow(s, 4) / 96), 1.0, 1e-12);
  EXPECT_NEAR(p.J / (std::sqrt(3.0) * std::pow(s, 4) / 80), 1.0, 1e-4);
  // a general trapezoid with its origin d above the bottom: I11 = I_base - 2 d Q_base + d^2 A
  const double a = 0.4, b = 0.25, c = 0.1, d = 0.05;
  t.dims = {a, b, c, d};
  p = beam_section_properties(t);
  const double A = 0.5 * (a + c) * b, Qb = b * b * (a + 2 * c) / 6,
               Ib = b * b * b * (a + 3 * c) / 12;
  EXPECT_NEAR(p.A, A, 1e-15);
  EXPECT_NEAR(p.Q2, Qb - d * A, 1e-15);
  EXPECT_NEAR(p.I11, Ib - 2 * d * Qb + d * d * A, 1e-15);
  EXPECT_NEAR(p.Q1, 0.0, 1e-16);
  EXPECT_NEAR(p.I12, 0.0, 1e-16);
  // J lies between the triangle's and the rectangle's of the same height (monotone in c)
  EXPECT_GT(p.J, trapezoid_torsion_constant(a, b, 0.0));
  EXPECT_LT(p.J, trapezoid_torsion_constant(a, b, a));
  ASSERT_EQ(p.n_points, 4);
  EXPECT_NEAR(p.points[0][1], b - d, 1e-15); // top corners first
  EXPECT_NEAR(p.points[2][1], -d, 1e-15);
  t.dims = {0.4, 0.0, 0.1, 0.0};
  EXPECT_THROW(beam_section_properties(t), InputError);
}

} // namespace
} // namespace gapfem::structural_test
