// *ORIENTATION as *SPRING / *DASHPOT, ORIENTATION= use it (io/inp/orientation.cpp): the local axes
// from points a, b (and the origin c), from node numbers, with the additional rotation of the
// second line; and the errors of a spring that refers to one it cannot use.
#include "unit/io/reader_test_util.hpp"

#include <cmath>
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

} // namespace
} // namespace gapfem
