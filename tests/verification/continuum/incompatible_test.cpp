// Incompatible-mode elements (issue 13): pure bending is exact on a regular mesh one element deep.
// - CPS4I, 4 x 1 elements, L = 4, h = 1, plane stress, end moment M as the consistent forces
//   -+M/h of the linear bending stress at the tip's bottom and top nodes. Exact (up to round-off):
//   u_x = M x y / (E I), u_y = -M (x^2 + nu y^2) / (2 E I) + nu M h^2 / (8 E I) (y from the axis,
//   the bottom-left node held in y); CPS4 on the same mesh is far too stiff (shear locking).
// - C3D8I, 4 x 1 x 1 elements, the section [-1/2, 1/2]^2: sigma_xx = E kappa z gives
//   u_x = kappa x z, u_y = -nu kappa y z, u_z = -kappa (x^2 + nu (z^2 - y^2)) / 2; u_x = 0 on
//   x = 0 and three components at two nodes of that face fix the rigid motion with their exact
//   values; the tip face carries the consistent forces E kappa sign(z) / 24 per node.
// - Both are linear problems: one Newton iteration.
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>

using namespace gapfem;
using namespace gapfem::test;

namespace {
constexpr double kE = 1000.0, kNu = 0.3;

std::string plane_bending(const std::string& type, double M) {
  // nodes 1..5 bottom (y = -1/2), 6..10 top, x = 0..4
  std::string d = "*HEADING\npure bending " + type + "\n*NODE\n";
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i <= 4; ++i) d += fmt::format("{}, {}, {}\n", 1 + i + 5 * j, i, j - 0.5);
  d += fmt::format("*ELEMENT, TYPE={}, ELSET=ALL\n", type);
  for (int i = 0; i < 4; ++i)
    d += fmt::format("{}, {}, {}, {}, {}\n", i + 1, i + 1, i + 2, i + 7, i + 6);
  d += fmt::format(
      "*MATERIAL, NAME=M\n*ELASTIC\n{}, {}\n*SOLID SECTION, ELSET=ALL, MATERIAL=M\n1.\n", kE, kNu);
  d += fmt::format("*STEP\n*STATIC\n*BOUNDARY\n1, 1, 2\n6, 1, 1\n*CLOAD\n5, 1, {}\n10, 1, {}\n"
                   "*END STEP\n",
                   -M, M);
  return d;
}

} // namespace

TEST(Incompatible, Cps4iBendsExactly) {
  const double M = 2.0, I = 1.0 / 12.0;
  const JobResult r = run_deck(plane_bending("CPS4I", M), false, "cps4i");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  const double scale = M * 16.0 / (2 * kE * I);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i <= 4; ++i) {
      const double x = i, y = j - 0.5;
      const double ux = M * x * y / (kE * I);
      const double uy = -M * (x * x + kNu * y * y) / (2 * kE * I) + kNu * M / (8 * kE * I);
      EXPECT_NEAR(U(r, f, 1 + i + 5 * j)[0], ux, 1e-10 * scale);
      EXPECT_NEAR(U(r, f, 1 + i + 5 * j)[1], uy, 1e-10 * scale);
    }
  for (const IncrementInfo& inc : r.increments) EXPECT_EQ(inc.iterations, 1);
  // the compatible element locks: its tip deflection is well below the exact one
  const JobResult c = run_deck(plane_bending("CPS4", M), false, "cps4");
  ASSERT_EQ(c.exit_code, 0) << c.error;
  EXPECT_LT(std::abs(U(c, last_frame(c), 10)[1]), 0.8 * M * 16.0 / (2 * kE * I));
}

TEST(Incompatible, C3d8iBendsExactly) {
  const double kappa = 1e-3;
  auto label = [](int i, int j, int k) { return 1 + i + 5 * (j + 2 * k); };
  auto exact = [&](double x, double y, double z) {
    return Vec3{kappa * x * z, -kNu * kappa * y * z, -kappa * (x * x + kNu * (z * z - y * y)) / 2};
  };
  std::string d = "*HEADING\npure bending C3D8I\n*NODE\n";
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i <= 4; ++i)
        d += fmt::format("{}, {}, {}, {}\n", label(i, j, k), i, j - 0.5, k - 0.5);
  d += "*ELEMENT, TYPE=C3D8I, ELSET=ALL\n";
  for (int i = 0; i < 4; ++i)
    d += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", i + 1, label(i, 0, 0),
                     label(i + 1, 0, 0), label(i + 1, 1, 0), label(i, 1, 0), label(i, 0, 1),
                     label(i + 1, 0, 1), label(i + 1, 1, 1), label(i, 1, 1));
  d += fmt::format("*MATERIAL, NAME=M\n*ELASTIC\n{}, {}\n*SOLID SECTION, ELSET=ALL, MATERIAL=M\n\n",
                   kE, kNu);
  d += "*STEP\n*STATIC\n*BOUNDARY\n";
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j) d += fmt::format("{}, 1, 1\n", label(0, j, k));
  const Vec3 a = exact(0, -0.5, -0.5), b = exact(0, 0.5, -0.5);
  d += fmt::format("{}, 2, 2, {:.17g}\n{}, 3, 3, {:.17g}\n{}, 3, 3, {:.17g}\n", label(0, 0, 0),
                   a[1], label(0, 0, 0), a[2], label(0, 1, 0), b[2]);
  d += "*CLOAD\n";
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      d += fmt::format("{}, 1, {:.17g}\n", label(4, j, k), kE * kappa * (k ? 1.0 : -1.0) / 24.0);
  d += "*END STEP\n";
  const JobResult r = run_deck(d);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  const double scale = kappa * 16.0 / 2;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i <= 4; ++i) {
        const Vec3 want = exact(i, j - 0.5, k - 0.5);
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(U(r, f, label(i, j, k))[c], want[c], 1e-10 * scale) << i << j << k << c;
      }
  for (const IncrementInfo& inc : r.increments) EXPECT_EQ(inc.iterations, 1);
}
