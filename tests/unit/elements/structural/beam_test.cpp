// B31 kernel: section properties, stiffness structure (symmetry, rigid modes), closed-form
// cantilevers assembled here with Eigen, consistent GRAV loads, thermal strain, output, errors.
#include "elements/structural/beam.hpp"
#include "elements/structural/beam_section.hpp"
#include "structural_test_support.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <numbers>

namespace gapfem::structural_test {
namespace {

constexpr double kE = 210e3, kNu = 0.3, kG = kE / (2.0 * (1.0 + kNu));
using Shape = BeamSection::Shape;

TEST(StructuralBeam, SectionPropertiesOfRectCircPipe) {
  BeamSection rect;
  rect.shape = Shape::Rect;
  rect.dims = {2.0, 1.0}; // a = 2 along local 1, b = 1 along local 2
  const auto r = beam_section_properties(rect);
  EXPECT_DOUBLE_EQ(r.A, 2.0);
  EXPECT_DOUBLE_EQ(r.I11, 2.0 / 12.0); // a b^3 / 12
  EXPECT_DOUBLE_EQ(r.I22, 8.0 / 12.0); // b a^3 / 12
  // Timoshenko & Goodier table for a/b = 2: J = 0.229 a b^3 (3 digits given there).
  EXPECT_NEAR(r.J / (2.0 * 1.0), 0.229, 5e-4);
  EXPECT_DOUBLE_EQ(r.k, 0.85);
  // Square: J = 0.1406 a^4 (Roark, Table 10.7 case 4, also T&G: 0.141).
  EXPECT_NEAR(rectangle_torsion_constant(1.0, 1.0), 0.1406, 1e-4);
  // Very thin strip: J -> a b^3 / 3 (1 - 0.630 b / a).
  EXPECT_NEAR(rectangle_torsion_constant(1.0, 0.01) / (1e-6 / 3.0), 1.0 - 0.630 * 0.01, 1e-5);

  BeamSection circ;
  circ.shape = Shape::Circ;
  circ.dims = {0.5};
  const auto c = beam_section_properties(circ);
  const double pi = std::numbers::pi;
  EXPECT_DOUBLE_EQ(c.A, pi * 0.25);
  EXPECT_DOUBLE_EQ(c.I11, pi * 0.0625 / 4.0);
  EXPECT_DOUBLE_EQ(c.J, pi * 0.0625 / 2.0);
  EXPECT_DOUBLE_EQ(c.k, 0.89);

  BeamSection pipe;
  pipe.shape = Shape::Pipe;
  pipe.dims = {1.0, 0.25};
  const auto p = beam_section_properties(pipe);
  EXPECT_DOUBLE_EQ(p.A, pi * (1.0 - 0.5625));
  EXPECT_DOUBLE_EQ(p.J, pi * (1.0 - std::pow(0.75, 4)) / 2.0);
  EXPECT_DOUBLE_EQ(p.k, 0.53);

  pipe.dims = {1.0, 1.5}; // wall thicker than the radius
  EXPECT_THROW(beam_section_properties(pipe), InputError);
  rect.dims = {1.0};
  EXPECT_THROW(beam_section_properties(rect), InputError);
}

/// One B31 element in a fresh model.
struct OneBeam {
  TestModel tm;
  ElemId e = -1;
  std::unique_ptr<ElementKernel> k;
  OneBeam(Vec3 X1, Vec3 X2, Shape shape, std::vector<double> dims, std::optional<Vec3> n1 = {},
          double alpha = 0.0, std::optional<double> rho = {}) {
    const NodeId a = tm.add_node(X1), b = tm.add_node(X2);
    e = tm.add_element(ElementType::B31, {a, b},
                       tm.add_beam_section(tm.add_material(kE, kNu, alpha, rho), shape, dims, n1));
    k = tm.kernel(e);
  }
  KernelProbe local() const { return tm.probe(e, *k); }
};

TEST(StructuralBeam, StiffnessIsSymmetricPositiveSemidefiniteWithSixRigidModes) {
  OneBeam b({0.3, -0.2, 0.1}, {1.1, 0.5, 0.9}, Shape::Rect, {0.1, 0.25}, Vec3{0.0, 1.0, 0.0});
  KernelProbe el = b.local();
  ASSERT_EQ(b.k->validate(el.input()), "");
  const KernelResult ev = el.evaluate();
  Eigen::Matrix<double, 12, 12> K;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) K(i, j) = ev.k(i, j);
  EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 12, 12>> eig(K);
  const auto& lambda = eig.eigenvalues(); // ascending
  const double lmax = lambda(11);
  // Rigid modes: zero up to round-off of the entries (~1e-16 relative per product term).
  for (int i = 0; i < 6; ++i) EXPECT_LT(std::abs(lambda(i)), 1e-10 * lmax) << "mode " << i;
  // Deformation modes (axial, torsion, 2 bending, 2 shear) have finite stiffness.
  for (int i = 6; i < 12; ++i) EXPECT_GT(lambda(i), 1e-8 * lmax) << "mode " << i;
}

// The tangent by central differences (a heated pipe), revert-then-evaluate, and rigid motions of
// the deformed state: a translation and an infinitesimal rotation u = c + w x X, rotations += w.
TEST(StructuralBeam, KernelChecks) {
  OneBeam b({0.0, 0.1, 0.2}, {0.9, -0.3, 0.6}, Shape::Pipe, {0.08, 0.01}, Vec3{1.0, 1.0, 0.0},
            1e-5);
  KernelProbe el = b.local();
  for (int i = 0; i < 12; ++i) el.u[i] = 1e-3 * std::cos(0.7 * i);
  el.T = {80.0, 20.0};
  el.Ti = {20.0, 20.0};
  expect_fd_tangent(el);
  expect_revert_is_exact(el);
  expect_rigid_body_invariance(el);
}

/// A straight cantilever of n equal B31 elements from the origin along `axis`, clamped at node 0;
/// solves K u = f for the given tip load (6 components) and optional element loads.
struct Cantilever {
  TestModel tm;
  std::vector<ElemId> elems;
  std::unique_ptr<ElementKernel> k;
  int n;
  Cantilever(int n_elems, Vec3 axis, double L, Shape shape, std::vector<double> dims,
             std::optional<Vec3> n1 = {}, std::optional<double> rho = {})
      : n(n_elems) {
    const PropertyRef prop =
        tm.add_beam_section(tm.add_material(kE, kNu, 0.0, rho), shape, dims, n1);
    for (int i = 0; i <= n; ++i) {
      const double s = L * i / n;
      tm.add_node({s * axis[0], s * axis[1], s * axis[2]});
    }
    for (int i = 0; i < n; ++i) elems.push_back(tm.add_element(ElementType::B31, {i, i + 1}, prop));
    const ElemId all[1] = {elems[0]};
    k = make_element_kernel(KernelContext{tm.model, ElementType::B31, prop, {all, 1}});
  }
  Eigen::VectorXd solve(const std::array<double, 6>& tip, const DistributedLoad* dload = nullptr,
                        double dload_magnitude = 0.0) {
    const int N = 6 * (n + 1);
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(N, N);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(N);
    for (int i = 0; i < 6; ++i) f(6 * n + i) = tip[i];
    for (int el = 0; el < n; ++el) {
      KernelProbe loc = tm.probe(elems[el], *k);
      const KernelResult ev = loc.evaluate();
      for (int a = 0; a < 12; ++a)
        for (int b = 0; b < 12; ++b) K(6 * el + a, 6 * el + b) += ev.k(a, b);
      if (dload) {
        const std::vector<double> fe = loc.load(*dload, dload_magnitude, 0.0);
        for (int a = 0; a < 12; ++a) f(6 * el + a) += fe[a];
      }
    }
    Eigen::VectorXd u = Eigen::VectorXd::Zero(N);
    u.tail(N - 6) = K.bottomRightCorner(N - 6, N - 6).ldlt().solve(f.tail(N - 6));
    return u;
  }
};

struct SectionCase {
  Shape shape;
  std::vector<double> dims;
};

TEST(StructuralBeam, CantileverTipLoadIsExactIncludingShearForAnyMesh) {
  // Short, deep beams so that the shear term P L/(k G A) is 5-40 % of the bending term.
  const double L = 1.0, P = 1000.0;
  const std::vector<SectionCase> cases = {
      {Shape::Rect, {0.12, 0.3}}, {Shape::Circ, {0.15}}, {Shape::Pipe, {0.2, 0.03}}};
  for (const auto& sc : cases) {
    BeamSection bs;
    bs.shape = sc.shape;
    bs.dims = sc.dims;
    const BeamSectionProperties s = beam_section_properties(bs);
    for (int n = 1; n <= 4; ++n) {
      // Axis along global x, default n1 = (0,0,-1): t = x, n2 = t x n1 = +y, n1 = n2 x t = -z.
      Cantilever c(n, {1, 0, 0}, L, sc.shape, sc.dims);
      SCOPED_TRACE(::testing::Message() << "shape " << static_cast<int>(sc.shape) << ", n = " << n);
      // Load along +y (local n2): bending about n1 with I11.
      Eigen::VectorXd u = c.solve({0, P, 0, 0, 0, 0});
      const double v_y = P * L * L * L / (3 * kE * s.I11) + P * L / (s.k * kG * s.A);
      const double rot = P * L * L / (2 * kE * s.I11); // about +z (counter-clockwise)
      EXPECT_NEAR(u(6 * n + 1), v_y, 1e-10 * v_y);
      EXPECT_NEAR(u(6 * n + 5), rot, 1e-10 * rot);
      // Load along +z (local -n1): bending about n2 with I22.
      u = c.solve({0, 0, P, 0, 0, 0});
      const double v_z = P * L * L * L / (3 * kE * s.I22) + P * L / (s.k * kG * s.A);
      EXPECT_NEAR(u(6 * n + 2), v_z, 1e-10 * v_z);
      EXPECT_NEAR(u(6 * n + 4), -P * L * L / (2 * kE * s.I22), 1e-10 * v_z / L);
      // Axial force and torque: u = P L/(E A), twist = T L/(G J).
      u = c.solve({P, 0, 0, 30.0, 0, 0});
      EXPECT_NEAR(u(6 * n), P * L / (kE * s.A), 1e-12);
      EXPECT_NEAR(u(6 * n + 3), 30.0 * L / (kG * s.J), 1e-12);
    }
  }
}

TEST(StructuralBeam, ObliqueCantileverMatchesTheAxisAlignedOne) {
  // Same RECT cantilever along a skew axis with n1 given: tip deflection along n2 is unchanged.
  const double L = 2.0, P = 50.0;
  const Vec3 t{2.0 / 3, 1.0 / 3, 2.0 / 3}; // unit
  const Vec3 n1a{0.0, 0.0, 1.0};
  Cantilever c(3, t, L, Shape::Rect, {0.1, 0.2}, n1a);
  // Local axes as Abaqus builds them: n2 = t x n1a / |.|.
  Vec3 n2{t[1] * n1a[2] - t[2] * n1a[1], t[2] * n1a[0] - t[0] * n1a[2],
          t[0] * n1a[1] - t[1] * n1a[0]};
  const double len = std::sqrt(n2[0] * n2[0] + n2[1] * n2[1] + n2[2] * n2[2]);
  for (double& x : n2) x /= len;
  const Eigen::VectorXd u = c.solve({P * n2[0], P * n2[1], P * n2[2], 0, 0, 0});
  const double I11 = 0.1 * 0.008 / 12.0, A = 0.02;
  const double expected = P * L * L * L / (3 * kE * I11) + P * L / (0.85 * kG * A);
  const double along_n2 = u(18) * n2[0] + u(19) * n2[1] + u(20) * n2[2];
  EXPECT_NEAR(along_n2, expected, 1e-9 * expected);
  const double along_t = u(18) * t[0] + u(19) * t[1] + u(20) * t[2];
  EXPECT_NEAR(along_t, 0.0, 1e-9 * expected);
}

TEST(StructuralBeam, UniformGravityOnCantileverIsNodallyExact) {
  // Consistent loads (q L/2, q L^2/12) with the exact element stiffness give the exact nodal
  // deflections of a Timoshenko cantilever: w(L) = q L^4/(8 E I) + q L^2/(2 k G A).
  const double L = 1.5, rho = 7.8e-9, g = 9810.0;
  const double a = 0.1, b = 0.2, A = a * b, I11 = a * b * b * b / 12.0;
  DistributedLoad grav;
  grav.kind = DistLoadKind::Gravity;
  grav.direction = {0.0, -1.0, 0.0};
  for (int n : {1, 2, 5}) {
    Cantilever c(n, {1, 0, 0}, L, Shape::Rect, {a, b}, {}, rho);
    const Eigen::VectorXd u = c.solve({0, 0, 0, 0, 0, 0}, &grav, g);
    const double q = rho * A * g;
    const double w = q * std::pow(L, 4) / (8 * kE * I11) + q * L * L / (2 * 0.85 * kG * A);
    EXPECT_NEAR(u(6 * n + 1), -w, 1e-10 * w) << n << " elements";
    // Tip rotation of the uniformly loaded cantilever: q L^3/(6 E I), clockwise.
    EXPECT_NEAR(u(6 * n + 5), -q * std::pow(L, 3) / (6 * kE * I11), 1e-10 * w / L);
  }
}

TEST(StructuralBeam, GravityLoadsSumToWeightWithFixedEndMoments) {
  const double rho = 2.7e-9, g = 9810.0;
  OneBeam b({0, 0, 0}, {3, 0, 4}, Shape::Circ, {0.1}, {}, 0.0, rho); // L = 5
  KernelProbe el = b.local();
  DistributedLoad grav;
  grav.kind = DistLoadKind::Gravity;
  grav.direction = {0.0, 0.0, -1.0};
  const std::vector<double> f = el.load(grav, g, 0.0);
  const double A = std::numbers::pi * 0.01, W = rho * A * 5.0 * g;
  EXPECT_NEAR(f[2] + f[8], -W, 1e-12 * W);
  EXPECT_NEAR(f[0] + f[6], 0.0, 1e-15 * W);
  // Fixed-end moments q_perp L^2/12 with q_perp = (W/L) * 3/5 (the part normal to the axis),
  // about the horizontal axis normal to the beam (global y): opposite at the two ends.
  const double m = (W / 5.0) * 0.6 * 25.0 / 12.0;
  EXPECT_NEAR(std::abs(f[4]), m, 1e-12 * m);
  EXPECT_NEAR(f[4] + f[10], 0.0, 1e-15 * m);
  // Moment balance about node 1: node 2 at (3, 0, 4) with force (0, 0, f8) and the two
  // moments must equal the moment of the distributed weight, resultant at (1.5, 0, 2).
  const double My = -3.0 * f[8] + f[4] + f[10];
  EXPECT_NEAR(My, -1.5 * (-W), 1e-12 * W);
}

TEST(StructuralBeam, ThermalStrainFreeAndClamped) {
  const double alpha = 1e-5;
  OneBeam b({0, 0, 0}, {0, 2, 0}, Shape::Rect, {0.1, 0.2}, {}, alpha);
  EXPECT_TRUE(b.k->uses_temperature_field());
  KernelProbe el = b.local();
  el.T = {70.0, 70.0};
  el.Ti = {20.0, 20.0};
  // Clamped: N = -E A alpha dT = -210e3 * 0.02 * 5e-4 = -2.1, pushing the nodes outward.
  KernelResult ev = el.evaluate();
  EXPECT_NEAR(ev.r[7], -2.1, 1e-12);
  EXPECT_NEAR(ev.r[1], 2.1, 1e-12);
  // Free expansion along the axis: no force.
  el.u[7] = alpha * 50.0 * 2.0;
  ev = el.evaluate();
  for (double r : ev.r) EXPECT_NEAR(r, 0.0, 1e-12);
}

TEST(StructuralBeam, SectionForcesAndFibreStressesOfACantilever) {
  // Two-element RECT cantilever along x with a tip load P along +y: element 1 (root half) has
  // SF2 = P, mid-length moment about n1 = -z ... recover and compare with statics.
  const double L = 2.0, P = 100.0, a = 0.1, b = 0.2;
  Cantilever c(2, {1, 0, 0}, L, Shape::Rect, {a, b});
  const Eigen::VectorXd u = c.solve({0, P, 0, 0, 0, 0});
  KernelProbe el = c.tm.probe(c.elems[0], *c.k);
  for (int i = 0; i < 12; ++i) el.u[i] = u(i);
  const ElementRecovery rec = el.recover();
  const OutputBlock* sf = rec.find(ElemVar::SF);
  ASSERT_NE(sf, nullptr);
  ASSERT_EQ(sf->names.size(), 6u);
  EXPECT_EQ(sf->names[3], "SM1");
  // Shear force on the positive face equals the tip load; no axial force or torsion.
  EXPECT_NEAR(sf->values[0], 0.0, 1e-9);
  EXPECT_NEAR(sf->values[1], P, 1e-9);
  EXPECT_NEAR(sf->values[2], 0.0, 1e-9);
  EXPECT_NEAR(sf->values[5], 0.0, 1e-9);
  // Moment at the integration point x = 0.5: magnitude P (L - 0.5) = 150. The beam bends towards
  // +y, so curvature about +z is positive, i.e. about n1 = -z negative: SM1 = -150.
  EXPECT_NEAR(sf->values[3], -150.0, 1e-8);
  EXPECT_NEAR(sf->values[4], 0.0, 1e-9);
  // Fibre stress S11 = M1 x2 / I11 at the corners (x2 = +-b/2): top (+n2 = +y) in compression.
  const double I11 = a * b * b * b / 12.0, smax = 150.0 * (b / 2) / I11;
  const OutputBlock* s = rec.find(ElemVar::S);
  ASSERT_EQ(s->n_points, 4);
  EXPECT_NEAR(s->values[0], -smax, 1e-9 * smax); // point (+a/2, +b/2)
  EXPECT_NEAR(s->values[4], smax, 1e-9 * smax);  // point (-a/2, -b/2)
  const OutputBlock* e = rec.find(ElemVar::E);
  EXPECT_NEAR(e->values[0], -smax / kE, 1e-9 * smax / kE);
}

TEST(StructuralBeam, TorsionShearStressOnCircleIsTrOverJ) {
  const double r = 0.05, T = 20.0, L = 1.0;
  Cantilever c(1, {0, 1, 0}, L, Shape::Circ, {r});
  const Eigen::VectorXd u = c.solve({0, 0, 0, 0, T, 0}); // torque about the axis (+y)
  KernelProbe el = c.tm.probe(c.elems[0], *c.k);
  for (int i = 0; i < 12; ++i) el.u[i] = u(i);
  const ElementRecovery rec = el.recover();
  const double J = std::numbers::pi * std::pow(r, 4) / 2;
  EXPECT_NEAR(rec.find(ElemVar::SF)->values[5], T, 1e-9);
  for (int p = 0; p < 4; ++p) EXPECT_NEAR(rec.find(ElemVar::S)->values[2 * p + 1], T * r / J, 1e-6);
}

TEST(StructuralBeam, N1ParallelToTheAxisFailsValidation) {
  // Beam along z with the default n1 = (0, 0, -1).
  OneBeam b({0, 0, 0}, {0, 0, 1}, Shape::Circ, {0.1});
  KernelProbe el = b.local();
  const std::string msg = b.k->validate(el.input());
  EXPECT_NE(msg.find("different n1"), std::string::npos) << msg;
  // A beam along x with the same section is fine.
  OneBeam ok({0, 0, 0}, {1, 0, 0}, Shape::Circ, {0.1});
  EXPECT_EQ(ok.k->validate(ok.local().input()), "");
}

} // namespace
} // namespace gapfem::structural_test
