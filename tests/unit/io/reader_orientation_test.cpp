// *ORIENTATION as *SPRING / *DASHPOT, ORIENTATION= use it (io/inp/orientation.cpp): the local axes
// from points a, b (and the origin c), from node numbers, with the additional rotation of the
// second line; and the errors of a spring that refers to one it cannot use.
#include "unit/io/reader_test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace gapfem {
namespace {

using test::error_text;
using test::read;

/// Nodes 1 (0, 0, 0), 2 (1, 1, 0), 3 (-1, 1, 0), 4 (1, 1, 5); SPRING1 element 10 on node 1, its
/// *SPRING on local DOF 1 with ORIENTATION=OR; `orientation` the *ORIENTATION keyword and lines.
std::string deck(const std::string& orientation, const std::string& type = "SPRING1") {
  const bool axial = type == "SPRINGA";
  return "*NODE\n1, 0., 0., 0.\n2, 1., 1., 0.\n3, -1., 1., 0.\n4, 1., 1., 5.\n" + orientation +
         "*ELEMENT, TYPE=" + type + ", ELSET=S\n10, 1" + (axial ? ", 2" : "") +
         "\n*SPRING, ELSET=S, ORIENTATION=OR\n" + (axial ? "" : "1") + "\n100.\n";
}

void expect_axes(const Model& m, const std::array<Vec3, 3>& want) {
  ASSERT_EQ(m.spring_sections.size(), 1u);
  ASSERT_TRUE(m.spring_sections[0].axes.has_value());
  const auto& e = *m.spring_sections[0].axes;
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(e[k][i], want[k][i], 1e-15) << k << ", " << i;
}

const double kR = 1.0 / std::sqrt(2.0);

TEST(ReaderOrientation, CoordinatesNodesAndOriginGiveTheSameAxes) {
  // local 1 along a, local 3 normal to a and b (right-handed), local 2 = 3 x 1
  const std::array<Vec3, 3> want{Vec3{kR, kR, 0}, Vec3{-kR, kR, 0}, Vec3{0, 0, 1}};
  expect_axes(read(deck("*ORIENTATION, NAME=OR\n1., 1., 0., -1., 1., 0.\n")), want);
  expect_axes(read(deck("*ORIENTATION, NAME=OR, DEFINITION=NODES\n2, 3\n")), want);
  // the origin c moved: the same directions from shifted points
  expect_axes(read(deck("*ORIENTATION, NAME=OR\n2., 3., 4., 0., 3., 4., 1., 2., 4.\n")), want);
  // the origin c given as a node (node 1, at the global origin)
  expect_axes(read(deck("*ORIENTATION, NAME=OR, DEFINITION=NODES\n2, 3, 1\n")), want);
}

TEST(ReaderOrientation, AdditionalRotationTurnsTheOtherTwoAxes) {
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  // about local 3 by 30 degrees: e1 = (c, s, 0), e2 = (-s, c, 0)
  expect_axes(read(deck("*ORIENTATION, NAME=OR\n1., 0., 0., 0., 1., 0.\n3, 30.\n")),
              {Vec3{c, s, 0}, Vec3{-s, c, 0}, Vec3{0, 0, 1}});
  // about local 1 (the default direction) by 30 degrees: e2 = (0, c, s), e3 = (0, -s, c)
  expect_axes(read(deck("*ORIENTATION, NAME=OR\n1., 0., 0., 0., 1., 0.\n, 30.\n")),
              {Vec3{1, 0, 0}, Vec3{0, c, s}, Vec3{0, -s, c}});
  // about local 2: e3 = (s, 0, c), e1 = (c, 0, -s)
  expect_axes(read(deck("*ORIENTATION, NAME=OR\n1., 0., 0., 0., 1., 0.\n2, 30.\n")),
              {Vec3{c, 0, -s}, Vec3{0, 1, 0}, Vec3{s, 0, c}});
}

TEST(ReaderOrientation, UnusedOrientationsAreOnlyRead) {
  // a cylindrical one nothing uses is no error; a spring without ORIENTATION stays global
  const Model m = read("*NODE\n1\n*ORIENTATION, NAME=CYL, SYSTEM=CYLINDRICAL\n0., 0., 0., 0., 0., "
                       "1.\n*ELEMENT, TYPE=SPRING1, ELSET=S\n10, 1\n*SPRING, ELSET=S\n1\n100.\n");
  ASSERT_EQ(m.spring_sections.size(), 1u);
  EXPECT_FALSE(m.spring_sections[0].axes.has_value());
}

TEST(ReaderOrientation, SpringsReferringToWhatTheyCannotUseAreErrors) {
  EXPECT_CONTAINS(error_text(deck("")), "ORIENTATION=OR: no *ORIENTATION, NAME=OR is defined");
  EXPECT_CONTAINS(
      error_text(deck("*ORIENTATION, NAME=OR, SYSTEM=CYLINDRICAL\n0., 0., 0., 0., 0., 1.\n")),
      "not SYSTEM=CYLINDRICAL");
  EXPECT_CONTAINS(error_text(deck("*ORIENTATION, NAME=OR\n1., 0., 0., 2., 0., 0.\n")),
                  "span no plane");
  EXPECT_CONTAINS(error_text(deck("*ORIENTATION, NAME=OR, DEFINITION=NODES\n2, 99\n")),
                  "node 99 of its first data line is not defined");
  EXPECT_CONTAINS(error_text(deck("*ORIENTATION, NAME=OR\n1., 0., 0., 0., 1., 0.\n", "SPRINGA")),
                  "ORIENTATION applies to SPRING1 and SPRING2 elements only");
  EXPECT_CONTAINS(error_text(deck("*ORIENTATION, NAME=OR\n1., 0., 0., 0., 1., 0.\n"
                                  "*ORIENTATION, NAME=OR\n1., 0., 0., 0., 1., 0.\n")),
                  "the orientation OR is already defined");
}

/// *ROTARY INERTIA, ORIENTATION=: the data line is the tensor in the local axes; the model holds
/// it in global ones, I = R I_local R^T (R's columns the local axes; gapfem's ROTARYI takes the
/// six values as the symmetric matrix's entries).
/// Local 1 = global y, local 2 = -global x, local 3 = z; I_local = [[1, .5, 0], [.5, 2, 0],
/// [0, 0, 3]]: I_xx = e2x^2 * 2 = 2, I_yy = e1y^2 * 1 = 1, I_xy = e2x L21 e1y = -0.5, I_zz = 3.
/// A 30-degree orientation about z keeps the trace and the z row (closed form below).
std::string rotary_deck(const std::string& orientation) {
  return "*NODE\n1, 0., 0., 0.\n" + orientation +
         "*ELEMENT, TYPE=ROTARYI, ELSET=R\n10, 1\n*ROTARY INERTIA, ELSET=R, ORIENTATION=OR\n"
         "1., 2., 3., 0.5, 0., 0.\n";
}

TEST(ReaderOrientation, RotaryInertiaIsTurnedToGlobalAxes) {
  {
    const Model m = read(rotary_deck("*ORIENTATION, NAME=OR\n0., 1., 0., -1., 0., 0.\n"));
    ASSERT_EQ(m.mass_sections.size(), 1u);
    const auto& I = m.mass_sections[0].inertia;
    const std::array<double, 6> want{2.0, 1.0, 3.0, -0.5, 0.0, 0.0};
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(I[k], want[k], 1e-15) << k;
  }
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  const Model m = read(
      rotary_deck(fmt::format("*ORIENTATION, NAME=OR\n{}, {}, 0., {}, {}, 0.\n", c, s, -s, c)));
  const auto& I = m.mass_sections[0].inertia;
  // e1 = (c, s, 0), e2 = (-s, c, 0): I_xx = c^2 + 2 s^2 - 2 c s (0.5), I_yy = s^2 + 2 c^2 + c s,
  // I_xy = c s - 2 s c + 0.5 (c^2 - s^2)
  EXPECT_NEAR(I[0], c * c + 2 * s * s - c * s, 1e-14);
  EXPECT_NEAR(I[1], s * s + 2 * c * c + c * s, 1e-14);
  EXPECT_NEAR(I[2], 3.0, 1e-15);
  EXPECT_NEAR(I[3], c * s - 2 * s * c + 0.5 * (c * c - s * s), 1e-14);
  EXPECT_NEAR(I[4], 0.0, 1e-15);
  EXPECT_NEAR(I[5], 0.0, 1e-15);
}

TEST(ReaderOrientation, RotaryInertiaErrors) {
  EXPECT_NE(error_text(rotary_deck("")).find("no *ORIENTATION, NAME=OR is defined"),
            std::string::npos);
  EXPECT_NE(error_text(rotary_deck("*ORIENTATION, NAME=OR, DEFINITION=OFFSET TO NODES\n1, 1\n"))
                .find("not taken for a rotary inertia"),
            std::string::npos)
      << error_text(rotary_deck("*ORIENTATION, NAME=OR, DEFINITION=OFFSET TO NODES\n1, 1\n"));
}

} // namespace
} // namespace gapfem
