// The mass of every element type gapfem registers (docs/theory/dynamics.md, "Mass of each element
// type"), looping over the type table: for each stress/displacement type of the continuum, truss,
// beam and shell families a one-element model with *DENSITY, and
// - the mass summed over each translational direction is rho x volume, the volume from the
//   element's geometry in closed form (box, tetrahedron, wedge, polygon; 2 pi r_c A for
//   axisymmetric elements; A L for lines; t A for shells) to 1e-12 (quadrature of polynomials:
//   exact but for round-off);
// - the rotary inertia, where the type has it, sums about each global axis to its closed form:
//   beams rho L (I11 + I22) about the axis, rho L I11 and rho L I22 about the section axes n1, n2
//   (Abaqus's exact rotary inertia, planar beams rho L I11); shells rho t^3/12 A about each axis;
// - M is symmetric and positive semi-definite (its least eigenvalue >= -1e-13 of its largest);
// - where Abaqus lumps (trusses, two-node beams, first-order shells) M is block-diagonal over the
//   nodes and each node carries the row sum of the consistent matrix, here in closed form (L/2 per
//   node of a line, A/4 per node of a rectangle, A/3 of a triangle).
// Families without mass (springs, dashpots, gaps, heat transfer) are covered by
// operators_test.cpp (MasslessKernelsSaySo); point inertias by verification_point_inertia_test;
// user elements and substructures, whose mass the deck defines, by their deck tests.
// Also: a temperature-dependent *DENSITY is read at the element's mean temperature.
#include "io/inp/reader.hpp"
#include "unit/elements/kernel_probe.hpp"
#include "unit/elements/solid/continuum_fixture.hpp"

#include <Eigen/Dense>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <numbers>
#include <optional>
#include <string>

namespace gapfem {
namespace {

using test::KernelProbe;

constexpr double kRho = 7.8e-9;
constexpr double kTol = 1e-12;

std::shared_ptr<const Model> model_of(const std::string& text) {
  return std::make_shared<const Model>(read_deck_string(text, "element_mass.inp"));
}

std::string material(bool heat) {
  std::string s = "*MATERIAL, NAME=M\n*ELASTIC\n2e5, 0.3\n*DENSITY\n7.8e-9\n";
  if (heat) s += "*CONDUCTIVITY\n45.\n*SPECIFIC HEAT\n4.6e8\n*EXPANSION\n1e-5\n";
  return s;
}

/// What one type's mass must be.
struct Expected {
  double mass = 0.0; ///< per translational direction
  int ndir = 3;
  /// rotary inertia about the global x, y, z axes (summed over the element), when the type has
  /// rotations; the axes a planar element lacks are ignored
  std::optional<std::array<double, 3>> rotary;
  /// lumped: every node's share of the mass per direction (closed-form row sums); empty when
  /// Abaqus keeps the matrix consistent
  std::vector<double> node_mass;
};

struct Case {
  KernelProbe probe;
  Expected want;
};

std::vector<DofType> dof_list(const KernelProbe& p) {
  std::vector<DofType> dof;
  for (int a = 0; a < p.kernel->n_nodes(); ++a)
    for (DofType t : p.kernel->node_dofs(a)) dof.push_back(t);
  return dof;
}

std::vector<double> mass_of(KernelProbe& p) {
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

// ------------------------------------------------------------------------ the cases by family

/// Lines along x from 0 to L = 5 (three nodes: the middle at 2.5).
constexpr double kL = 5.0;
std::string line_nodes(int nodes) {
  return nodes == 2 ? "*NODE\n1, 0., 0., 0.\n2, 5., 0., 0.\n"
                    : "*NODE\n1, 0., 0., 0.\n2, 2.5, 0., 0.\n3, 5., 0., 0.\n";
}
std::string connectivity(int nodes) {
  std::string s = "1";
  for (int a = 1; a <= nodes; ++a) s += fmt::format(", {}", a);
  return s + "\n";
}

Case truss_case(const ElementTypeInfo& info) {
  const double A = 0.25;
  const std::string deck = line_nodes(2) + fmt::format("*ELEMENT, TYPE={}, ELSET=E\n", info.name) +
                           connectivity(2) + "*SOLID SECTION, ELSET=E, MATERIAL=M\n0.25\n" +
                           material(info.temperature);
  Expected e{kRho * A * kL, info.space == SpaceRequirement::Planar ? 2 : 3};
  e.node_mass.assign(2, kRho * A * kL / 2.0);
  return {KernelProbe::of(model_of(deck)), e};
}

/// RECT 0.2 (x1) x 0.3 (x2), or PIPE r = 0.5, t = 0.05; n1 approximately z (in space: t = x,
/// n2 = t x n1a = -y, n1 = z) or -z (planar: n1 = -z, rotation about z is about -n1).
Case beam_case(const ElementTypeInfo& info) {
  const bool pipe = info.name.starts_with("PIPE");
  const bool planar = info.space == SpaceRequirement::Planar;
  const int nodes = info.n_nodes;
  double A = 0.0, I11 = 0.0, I22 = 0.0;
  std::string section;
  if (pipe) {
    const double ro = 0.5, ri = 0.45;
    A = std::numbers::pi * (ro * ro - ri * ri);
    I11 = I22 = std::numbers::pi * (std::pow(ro, 4) - std::pow(ri, 4)) / 4.0;
    section = "*BEAM SECTION, ELSET=E, MATERIAL=M, SECTION=PIPE\n0.5, 0.05\n";
  } else {
    const double a = 0.2, b = 0.3;
    A = a * b;
    I11 = a * b * b * b / 12.0;
    I22 = b * a * a * a / 12.0;
    section = "*BEAM SECTION, ELSET=E, MATERIAL=M, SECTION=RECT\n0.2, 0.3\n";
  }
  section += planar ? "0., 0., -1.\n" : "0., 0., 1.\n";
  const std::string deck = line_nodes(nodes) +
                           fmt::format("*ELEMENT, TYPE={}, ELSET=E\n", info.name) +
                           connectivity(nodes) + section + material(false);
  Expected e{kRho * A * kL, planar ? 2 : 3};
  // about x (the axis): the polar I11 + I22; about y (-n2): I22; about z (n1 or -n1): I11
  e.rotary = std::array<double, 3>{kRho * kL * (I11 + I22), kRho * kL * I22, kRho * kL * I11};
  if (nodes == 2) e.node_mass.assign(2, kRho * A * kL / 2.0);
  return {KernelProbe::of(model_of(deck)), e};
}

/// A flat 2 x 3 rectangle (or the triangle of half of it) at z = 0, t = 0.02.
Case shell_case(const ElementTypeInfo& info) {
  const std::string nodes = "*NODE\n1, 0., 0., 0.\n2, 2., 0., 0.\n3, 2., 3., 0.\n4, 0., 3., 0.\n"
                            "5, 1., 0., 0.\n6, 2., 1.5, 0.\n7, 1., 3., 0.\n8, 0., 1.5, 0.\n";
  const int n = info.n_nodes;
  const double t = 0.02, A = n == 3 ? 3.0 : 6.0;
  const std::string deck = nodes + fmt::format("*ELEMENT, TYPE={}, ELSET=E\n", info.name) +
                           connectivity(n) + "*SHELL SECTION, ELSET=E, MATERIAL=M\n0.02\n" +
                           material(info.temperature);
  Expected e{kRho * t * A, 3};
  const double eta = kRho * t * t * t / 12.0 * A;
  e.rotary = std::array<double, 3>{eta, eta, eta};
  if (n < 8) e.node_mass.assign(static_cast<std::size_t>(n), kRho * t * A / n);
  return {KernelProbe::of(model_of(deck)), e};
}

/// The volume of an undistorted reference element from its corner nodes in closed form.
double closed_form_volume(ElementType type, const std::vector<Vec3>& X) {
  const ElementTypeInfo& info = element_info(type);
  const Shape s = test::shape_of(type);
  auto polygon = [&](int corners, double* rc) { // shoelace area and centroid x
    double a = 0.0, cx = 0.0;
    for (int i = 0; i < corners; ++i) {
      const Vec3 &p = X[i], &q = X[(i + 1) % corners];
      const double c = p[0] * q[1] - q[0] * p[1];
      a += c / 2.0;
      cx += (p[0] + q[0]) * c / 6.0;
    }
    *rc = cx / a;
    return std::abs(a);
  };
  double rc = 0.0;
  switch (s) {
  case Shape::Tri3:
  case Shape::Tri6:
  case Shape::Quad4:
  case Shape::Quad8: {
    const double A = polygon(s == Shape::Tri3 || s == Shape::Tri6 ? 3 : 4, &rc);
    return info.plane == PlaneKind::Axisymmetric ? 2.0 * std::numbers::pi * rc * A : A;
  }
  case Shape::Hex8:
  case Shape::Hex20: { // an axis-aligned box
    Vec3 lo = X[0], hi = X[0];
    for (int a = 0; a < 8; ++a)
      for (int i = 0; i < 3; ++i)
        lo[i] = std::min(lo[i], X[a][i]), hi[i] = std::max(hi[i], X[a][i]);
    return (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
  }
  case Shape::Tet4:
  case Shape::Tet10: {
    Eigen::Matrix3d J;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) J(k, i) = X[i + 1][k] - X[0][k];
    return std::abs(J.determinant()) / 6.0;
  }
  case Shape::Wedge6:
  case Shape::Wedge15: { // a right prism: the triangle 1-2-3 times the height to node 4
    const double A = polygon(3, &rc);
    return A * std::abs(X[3][2] - X[0][2]);
  }
  default:
    ADD_FAILURE() << "no closed-form volume for " << info.name;
    return 0.0;
  }
}

Case continuum_case(const ElementTypeInfo& info) {
  const std::vector<Vec3> X = test::reference_nodes(info.type, false);
  test::TestMaterial m;
  m.density = kRho;
  std::shared_ptr<Model> model = test::one_element_model(info.type, X, m);
  if (info.temperature) { // the coupled types need the thermal constants too
    Material& mat = model->materials[0];
    mat.conductivity.n_values = 1;
    mat.conductivity.values = {45.0};
    mat.specific_heat.n_values = 1;
    mat.specific_heat.values = {4.6e8};
  }
  Expected e{kRho * closed_form_volume(info.type, X), test::is_3d(info.type) ? 3 : 2};
  return {KernelProbe::of(std::shared_ptr<const Model>(model)), e};
}

/// The case of a type, or nullopt for the families whose mass is checked elsewhere.
std::optional<Case> case_of(const ElementTypeInfo& info) {
  switch (info.family) {
  case ElementFamily::Truss:
    return truss_case(info);
  case ElementFamily::Beam:
    return beam_case(info);
  case ElementFamily::Shell:
    if (!info.displacement) return std::nullopt; // DS3/DS4/DS8: heat transfer, massless
    return shell_case(info);
  case ElementFamily::Continuum:
    return continuum_case(info);
  case ElementFamily::Spring:
  case ElementFamily::Gap:
  case ElementFamily::HeatTransfer:
  case ElementFamily::Mass:
  case ElementFamily::User:
  case ElementFamily::Substructure:
    return std::nullopt;
  }
  ADD_FAILURE() << info.name << ": a family this test does not know; add its mass case";
  return std::nullopt;
}

// ------------------------------------------------------------------------------ the checks

void check(Case& c) {
  KernelProbe& p = c.probe;
  const Expected& w = c.want;
  ASSERT_TRUE(p.kernel->has_mass());
  const std::vector<double> M = mass_of(p);
  const std::vector<DofType> dof = dof_list(p);
  const std::size_t n = dof.size();
  double scale = 0.0;
  for (double v : M) scale = std::max(scale, std::abs(v));
  ASSERT_GT(scale, 0.0);
  // translations: the total per direction
  const DofType trans[3] = {DofType::U1, DofType::U2, DofType::U3};
  for (int d = 0; d < w.ndir; ++d) {
    double s = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
        if (dof[i] == trans[d] && dof[j] == trans[d]) s += M[i * n + j];
    EXPECT_NEAR(s, w.mass, kTol * w.mass) << "direction " << d + 1;
  }
  // rotations: the inertia about each global axis
  const DofType rot[3] = {DofType::UR1, DofType::UR2, DofType::UR3};
  for (int d = 0; d < 3; ++d) {
    double s = 0.0;
    bool present = false;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
        if (dof[i] == rot[d] && dof[j] == rot[d]) s += M[i * n + j], present = true;
    if (!present) continue;
    ASSERT_TRUE(w.rotary) << "rotations without an expected rotary inertia";
    EXPECT_NEAR(s, (*w.rotary)[d], kTol * (*w.rotary)[d]) << "rotation about axis " << d + 1;
  }
  // symmetric, positive semi-definite
  Eigen::MatrixXd E(n, n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      EXPECT_EQ(M[i * n + j], M[j * n + i]) << i << ", " << j;
      E(i, j) = M[i * n + j];
    }
  const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(E).eigenvalues();
  EXPECT_GE(ev.minCoeff(), -1e-13 * ev.maxCoeff());
  // lumped: nothing joins two nodes, and each node's translations carry its row sum
  if (w.node_mass.empty()) return;
  std::vector<int> node_of;
  for (int a = 0; a < p.kernel->n_nodes(); ++a)
    for (std::size_t k = 0; k < p.kernel->node_dofs(a).size(); ++k) node_of.push_back(a);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      if (node_of[i] != node_of[j]) EXPECT_EQ(M[i * n + j], 0.0) << i << ", " << j;
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < w.ndir; ++d)
      if (dof[i] == trans[d])
        EXPECT_NEAR(M[i * n + i], w.node_mass[node_of[i]], kTol * w.mass) << "DOF " << i;
}

TEST(ElementMass, EveryRegisteredTypeIntegratesTheDensity) {
  int checked = 0;
  for (const ElementTypeInfo& info : all_element_types()) {
    SCOPED_TRACE(std::string(info.name));
    std::optional<Case> c = case_of(info);
    if (!c) continue;
    check(*c);
    ++checked;
  }
  // the continuum (C3D…, CPS/CPE/CAX…, their T twins), truss, beam and shell types
  EXPECT_GE(checked, 50);
}

// The beams' mass matrix by hand: a B31 along x lumps rho A L / 2 and rho L I / 2 on each node's
// diagonal; a B32 keeps the consistent integral N_a N_b: L (2/15, 1/15, -1/30 | 8/15) times the
// per-length block, so its end-to-end term is -rho A L / 30.
TEST(ElementMass, BeamConsistentAndLumpedByHand) {
  const double A = 0.06, I11 = 0.2 * 0.027 / 12.0, I22 = 0.3 * 0.008 / 12.0;
  for (int nodes : {2, 3}) {
    const ElementTypeInfo& info = element_info(nodes == 2 ? ElementType::B31 : ElementType::B32);
    Case c = beam_case(info);
    const std::vector<double> M = mass_of(c.probe);
    const auto n = static_cast<std::size_t>(6 * nodes);
    auto m = [&](int a, int i, int b, int j) { return M[(6 * a + i) * n + 6 * b + j]; };
    if (nodes == 2) {
      EXPECT_NEAR(m(0, 0, 0, 0), kRho * A * kL / 2, kTol * kRho * A * kL);
      EXPECT_NEAR(m(1, 3, 1, 3), kRho * (I11 + I22) * kL / 2, kTol * kRho * I11 * kL);
      EXPECT_NEAR(m(0, 5, 0, 5), kRho * I11 * kL / 2, kTol * kRho * I11 * kL);
      EXPECT_NEAR(m(0, 4, 0, 4), kRho * I22 * kL / 2, kTol * kRho * I11 * kL);
    } else {
      EXPECT_NEAR(m(0, 0, 0, 0), kRho * A * kL * 2 / 15, kTol * kRho * A * kL);
      EXPECT_NEAR(m(1, 1, 1, 1), kRho * A * kL * 8 / 15, kTol * kRho * A * kL);
      EXPECT_NEAR(m(0, 2, 2, 2), -kRho * A * kL / 30, kTol * kRho * A * kL);
      EXPECT_NEAR(m(0, 3, 1, 3), kRho * (I11 + I22) * kL / 15, kTol * kRho * I11 * kL);
    }
    // a symmetric section about its node: no coupling of translations and rotations
    for (int a = 0; a < nodes; ++a)
      for (int b = 0; b < nodes; ++b)
        for (int i = 0; i < 3; ++i)
          for (int j = 3; j < 6; ++j) EXPECT_EQ(m(a, i, b, j), 0.0);
  }
}

// A temperature-dependent density (7.8e-9 at 0, 7.0e-9 at 100) at nodal temperatures 40 and 80:
// the element's mean temperature 60 gives 7.32e-9 (linear interpolation), for a truss and a beam.
TEST(ElementMass, TemperatureDependentDensity) {
  const std::string mat = "*MATERIAL, NAME=M\n*ELASTIC\n2e5, 0.3\n*DENSITY\n7.8e-9, 0.\n"
                          "7.0e-9, 100.\n";
  const double rho = 7.8e-9 + 0.6 * (7.0e-9 - 7.8e-9);
  const std::pair<std::string, double> cases[] = {
      {"*ELEMENT, TYPE=T3D2, ELSET=E\n1, 1, 2\n*SOLID SECTION, ELSET=E, MATERIAL=M\n0.25\n", 0.25},
      {"*ELEMENT, TYPE=B31, ELSET=E\n1, 1, 2\n*BEAM SECTION, ELSET=E, MATERIAL=M, "
       "SECTION=RECT\n0.2, 0.3\n0., 0., 1.\n",
       0.06}};
  for (const auto& [elements, A] : cases) {
    auto p = KernelProbe::of(model_of(line_nodes(2) + elements + mat));
    p.T = {40.0, 80.0};
    p.T0 = p.T;
    const std::vector<double> M = mass_of(p);
    const auto n = static_cast<std::size_t>(p.n());
    EXPECT_NEAR(M[0], rho * A * kL / 2, 1e-12 * rho * A * kL) << elements;
    EXPECT_NEAR(M[n + 1], rho * A * kL / 2, 1e-12 * rho * A * kL) << elements;
  }
}

} // namespace
} // namespace gapfem
