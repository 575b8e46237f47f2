// *BEAM ADDED INERTIA in the beam kernels' mass and damping (elements/structural/beam_mass.hpp,
// docs/theory/dynamics.md §8, "Added inertia"). One element along x from 0 to L = 5, RECT
// 0.2 x 0.3 section of density 7.8e-9, n1 approximately z: in space t = x, n2 = t x n1 = -y,
// n1 = z; in the plane n1 = -z, n2 = y. Closed forms, each to 1e-12 of the block's scale
// (sums of a few products: round-off only):
// - the added part M(with) - M(section alone) of a mass m per length at d = x1 n1 + x2 n2 with
//   rotary inertia J about its centre of mass is, per unit length, the rigid-body block
//   [[m 1, -m [d x]], [m [d x], J + m (|d|^2 1 - d d^T)]] (kinetic energy of a rigid section),
//   lumped L/2 per node for two nodes, so the element's total mass is (rho A + m) L;
// - an inertia given in axes turned by 45 degrees (principal values a, b) is, in the section
//   axes, [[(a + b) / 2, (a - b) / 2], [(a - b) / 2, (a + b) / 2]] (the tensor e1 e1^T a +
//   e2 e2^T b with e1 = (n1 + n2) / sqrt 2);
// - several data lines add up; a planar beam couples u1 and ur3 through x2 only;
// - M with an offset, turned added inertia is symmetric and positive semi-definite (least
//   eigenvalue >= -1e-13 of the largest: round-off), and the residual and tangent are not
//   touched (the harness's central-difference check of the tangent at a deformed state);
// - ALPHA gives the damping block ALPHA times the added part of M; with a material *DAMPING
//   ALPHA_R as well, C = ALPHA_R M(section) + ALPHA M(added) (Abaqus damps the added inertia
//   with its own keyword's ALPHA only).
#include "io/inp/reader.hpp"
#include "unit/elements/kernel_harness.hpp"
#include "unit/elements/kernel_probe.hpp"

#include <Eigen/Dense>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <string>

namespace gapfem {
namespace {

using test::KernelProbe;

constexpr double kL = 5.0, kRho = 7.8e-9;

std::string deck(const std::string& type, const std::string& added, const std::string& damping = "",
                 int nodes = 2) {
  const bool planar = type[1] == '2';
  std::string s = nodes == 2 ? "*NODE\n1, 0., 0., 0.\n2, 5., 0., 0.\n"
                             : "*NODE\n1, 0., 0., 0.\n2, 2.5, 0., 0.\n3, 5., 0., 0.\n";
  s += fmt::format("*ELEMENT, TYPE={}, ELSET=E\n{}\n", type, nodes == 2 ? "1, 1, 2" : "1, 1, 2, 3");
  s += "*BEAM SECTION, ELSET=E, MATERIAL=M, SECTION=RECT\n0.2, 0.3\n";
  s += planar ? "0., 0., -1.\n" : "0., 0., 1.\n";
  s += added;
  return s + "*MATERIAL, NAME=M\n*ELASTIC\n2e5, 0.3\n*DENSITY\n7.8e-9\n" + damping;
}

struct Blocks {
  std::size_t n = 0;
  std::vector<double> M, C;
  double m(int a, int i, int b, int j, int dpn) const { return M[(dpn * a + i) * n + dpn * b + j]; }
};

Blocks blocks_of(const std::string& text) {
  auto model = std::make_shared<const Model>(read_deck_string(text, "added_inertia.inp"));
  KernelProbe p = KernelProbe::of(model);
  Blocks b;
  b.n = static_cast<std::size_t>(p.n());
  std::vector<double> r(b.n, 0.0);
  b.M.assign(b.n * b.n, 0.0);
  b.C.assign(b.n * b.n, 0.0);
  ElementOutput out;
  out.residual = r;
  out.want_tangent = false;
  out.mass = b.M;
  out.want_mass = true;
  out.damping = b.C;
  out.want_damping = p.kernel->has_damping();
  p.kernel->evaluate(p.input(), out);
  return b;
}

/// M(with) - M(without), entry by entry.
std::vector<double> added_part(const Blocks& with, const Blocks& without) {
  std::vector<double> d(with.M.size());
  for (std::size_t i = 0; i < d.size(); ++i) d[i] = with.M[i] - without.M[i];
  return d;
}

using Mat3 = std::array<std::array<double, 3>, 3>;

/// The rigid-body block per unit length of a mass m at d (global) with inertia J about it.
std::array<std::array<double, 6>, 6> rigid_block(double m, const Vec3& d, const Mat3& J) {
  std::array<std::array<double, 6>, 6> B{};
  const Mat3 dx = {{{0.0, -d[2], d[1]}, {d[2], 0.0, -d[0]}, {-d[1], d[0], 0.0}}};
  const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  for (int i = 0; i < 3; ++i) {
    B[i][i] = m;
    for (int j = 0; j < 3; ++j) {
      B[3 + i][j] = m * dx[i][j];
      B[i][3 + j] = -m * dx[i][j];
      B[3 + i][3 + j] = J[i][j] + m * ((i == j ? dd : 0.0) - d[i] * d[j]);
    }
  }
  return B;
}

TEST(BeamAddedInertia, OffsetMassIsTheRigidSectionBlockLumped) {
  // m = 4e-8 at x1 = 0.1, x2 = 0.25 (global d = 0.1 z - 0.25 y), I11 = 3e-10, I22 = 1e-10,
  // I12 = -5e-11 about its centre (section axes, angle 0): about global x the polar I11 + I22,
  // about z = n1 I11, about y = -n2 I22, the (n1, n2) entry I12 -> (z, y) entry -I12
  const double m = 4e-8, I11 = 3e-10, I22 = 1e-10, I12 = -5e-11;
  const Blocks without = blocks_of(deck("B31", ""));
  const Blocks with =
      blocks_of(deck("B31", fmt::format("*BEAM ADDED INERTIA\n{}, 0.1, 0.25, 0., {}, {}, {}\n", m,
                                        I11, I22, I12)));
  const std::vector<double> d = added_part(with, without);
  Mat3 J{};
  J[0][0] = I11 + I22;
  J[2][2] = I11;
  J[1][1] = I22;
  J[2][1] = J[1][2] = -I12;
  const auto B = rigid_block(m, {0.0, -0.25, 0.1}, J);
  const double tol = 1e-12 * m * kL;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j)
          EXPECT_NEAR(d[(6 * a + i) * 12 + 6 * b + j], a == b ? kL / 2 * B[i][j] : 0.0, tol)
              << a << " " << i << " " << b << " " << j;
  // the total translational mass along each direction: (rho A + m) L
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(with.m(0, i, 0, i, 6) + with.m(1, i, 1, i, 6), (kRho * 0.06 + m) * kL, tol);
}

TEST(BeamAddedInertia, QuadraticBeamKeepsItConsistent) {
  // B32: the added part is the consistent integral N_a N_b ds times the per-length block, e.g.
  // 2/15 L at the end node, 8/15 L at the middle, -1/30 L end to end; total (rho A + m) L
  const double m = 4e-8;
  const Blocks without = blocks_of(deck("B32", "", "", 3));
  const Blocks with = blocks_of(deck("B32", fmt::format("*BEAM ADDED INERTIA\n{}\n", m), "", 3));
  const std::vector<double> d = added_part(with, without);
  const double tol = 1e-12 * m * kL;
  EXPECT_NEAR(d[0], m * kL * 2 / 15, tol);
  EXPECT_NEAR(d[(6 + 1) * 18 + 6 + 1], m * kL * 8 / 15, tol);
  EXPECT_NEAR(d[2 * 18 + 12 + 2], -m * kL / 30, tol);
  double total = 0.0;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) total += with.M[(6 * a) * 18 + 6 * b];
  EXPECT_NEAR(total, (kRho * 0.06 + m) * kL, tol);
}

TEST(BeamAddedInertia, OrientationAngleTurnsTheRotaryInertia) {
  const double a = 3e-10, b = 1e-10;
  const Blocks without = blocks_of(deck("B31", ""));
  const Blocks with =
      blocks_of(deck("B31", fmt::format("*BEAM ADDED INERTIA\n0., 0., 0., 45., {}, {}\n", a, b)));
  const std::vector<double> d = added_part(with, without);
  auto at = [&](int i, int j) { return d[(3 + i) * 12 + 3 + j]; }; // node 1's rotations
  const double tol = 1e-12 * a * kL;
  EXPECT_NEAR(at(0, 0), kL / 2 * (a + b), tol);      // about the axis: the polar
  EXPECT_NEAR(at(2, 2), kL / 2 * (a + b) / 2, tol);  // about z = n1
  EXPECT_NEAR(at(1, 1), kL / 2 * (a + b) / 2, tol);  // about y = -n2
  EXPECT_NEAR(at(2, 1), -kL / 2 * (a - b) / 2, tol); // (n1, n2) entry (a - b)/2, n2 = -y
  // 90 degrees swaps I11 and I22
  const Blocks turned =
      blocks_of(deck("B31", fmt::format("*BEAM ADDED INERTIA\n0., 0., 0., 90., {}, {}\n", a, b)));
  const Blocks swapped =
      blocks_of(deck("B31", fmt::format("*BEAM ADDED INERTIA\n0., 0., 0., 0., {}, {}\n", b, a)));
  for (std::size_t i = 0; i < turned.M.size(); ++i)
    EXPECT_NEAR(turned.M[i], swapped.M[i], tol) << i;
}

TEST(BeamAddedInertia, DataLinesAddUp) {
  // two lines of m at x2 = +-0.25: no coupling, rotary 2 m 0.25^2 about z and about the axis
  const double m = 4e-8;
  const Blocks without = blocks_of(deck("B31", ""));
  const Blocks two = blocks_of(
      deck("B31", fmt::format("*BEAM ADDED INERTIA\n{0}, 0., 0.25\n{0}, 0., -0.25\n", m)));
  const Blocks once =
      blocks_of(deck("B31", fmt::format("*BEAM ADDED INERTIA\n{}, 0., 0., 0., {}, 0., 0.\n", 2 * m,
                                        2 * m * 0.0625)));
  const double tol = 1e-12 * m * kL;
  for (std::size_t i = 0; i < two.M.size(); ++i) EXPECT_NEAR(two.M[i], once.M[i], tol) << i;
  const std::vector<double> d = added_part(two, without);
  EXPECT_NEAR(d[5 * 12 + 5], kL / 2 * 2 * m * 0.0625, tol);
  EXPECT_NEAR(d[3 * 12 + 3], kL / 2 * 2 * m * 0.0625, tol);
}

TEST(BeamAddedInertia, PlanarBeamCouplesAxialAndRotationThroughX2) {
  // B21: d = x2 y (n2 = y); the velocity of the mass is u1' - x2 w3 along x: M(u1, ur3) = -m x2
  // per length; x1 (out of the plane) changes nothing in the plane
  const double m = 4e-8;
  const Blocks without = blocks_of(deck("B21", ""));
  const Blocks with =
      blocks_of(deck("B21", fmt::format("*BEAM ADDED INERTIA\n{}, 0.7, 0.25\n", m)));
  const std::vector<double> d = added_part(with, without);
  const double tol = 1e-12 * m * kL;
  EXPECT_NEAR(d[0 * 6 + 2], -kL / 2 * m * 0.25, tol);
  EXPECT_NEAR(d[2 * 6 + 0], -kL / 2 * m * 0.25, tol);
  EXPECT_NEAR(d[1 * 6 + 2], 0.0, tol);
  EXPECT_NEAR(d[2 * 6 + 2], kL / 2 * m * 0.0625, tol);
}

TEST(BeamAddedInertia, MassStaysSymmetricPositiveAndTheTangentUntouched) {
  const std::string added = "*BEAM ADDED INERTIA, ALPHA=2.\n4e-8, 0.1, 0.25, 30., 3e-10, 1e-10, "
                            "-5e-11\n2e-8, -0.3, 0.05\n";
  for (const auto& [type, nodes] :
       {std::pair{"B31", 2}, std::pair{"B32", 3}, std::pair{"B21", 2}, std::pair{"B22", 3}}) {
    SCOPED_TRACE(type);
    const std::string a =
        type[1] == '2' ? "*BEAM ADDED INERTIA\n4e-8, 0.1, 0.25, , 3e-10\n" : added;
    const Blocks b = blocks_of(deck(type, a, "", nodes));
    const auto n = static_cast<Eigen::Index>(b.n);
    const Eigen::MatrixXd M = Eigen::Map<const Eigen::MatrixXd>(b.M.data(), n, n);
    const double scale = M.cwiseAbs().maxCoeff();
    EXPECT_LE((M - M.transpose()).cwiseAbs().maxCoeff(), 1e-14 * scale);
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(M).eigenvalues();
    EXPECT_GE(ev.minCoeff(), -1e-13 * ev.maxCoeff());
    auto model =
        std::make_shared<const Model>(read_deck_string(deck(type, a, "", nodes), "fd.inp"));
    KernelProbe p = KernelProbe::of(model);
    for (std::size_t i = 0; i < p.u.size(); ++i) p.u[i] = 1e-3 * std::cos(0.7 * double(i));
    test::expect_fd_tangent(p);
  }
}

TEST(BeamAddedInertia, AlphaDampsTheAddedInertiaOnly) {
  const double m = 4e-8;
  const std::string added = fmt::format("*BEAM ADDED INERTIA, ALPHA=2.\n{}, 0.1, 0.25, 30., 3e-10, "
                                        "1e-10\n",
                                        m);
  const std::string plain =
      fmt::format("*BEAM ADDED INERTIA\n{}, 0.1, 0.25, 30., 3e-10, 1e-10\n", m);
  const Blocks without = blocks_of(deck("B31", ""));
  const Blocks with = blocks_of(deck("B31", added));
  const std::vector<double> d = added_part(with, without);
  const double tol = 1e-12 * m * kL;
  for (std::size_t i = 0; i < d.size(); ++i) EXPECT_NEAR(with.C[i], 2.0 * d[i], 2.0 * tol) << i;
  // no ALPHA: no damping block at all
  auto model = std::make_shared<const Model>(read_deck_string(deck("B31", plain), "a.inp"));
  EXPECT_FALSE(KernelProbe::of(model).kernel->has_damping());
  // with the material's *DAMPING, ALPHA=3: 3 M(section) + 2 M(added)
  const Blocks both = blocks_of(deck("B31", added, "*DAMPING, ALPHA=3.\n"));
  for (std::size_t i = 0; i < d.size(); ++i)
    EXPECT_NEAR(both.C[i], 3.0 * without.M[i] + 2.0 * d[i], 3.0 * tol) << i;
  // and with the material's damping alone the added inertia is not damped: 3 M(section)
  const Blocks material_only = blocks_of(deck("B31", plain, "*DAMPING, ALPHA=3.\n"));
  for (std::size_t i = 0; i < d.size(); ++i)
    EXPECT_NEAR(material_only.C[i], 3.0 * without.M[i], 3.0 * tol) << i;
}

} // namespace
} // namespace gapfem
