// Extrapolation of integration-point values to the nodes (output/nodal_average.hpp), checked
// against the field it must reproduce: a random linear field a + b . xi sampled at the points of
// each element's rule comes back exactly at every node (corners and mid-side nodes) wherever the
// rule has at least one point per corner; with fewer points the element's mean is used.
#include "fe/quadrature.hpp"
#include "fe/shape_functions.hpp"
#include "output/nodal_average.hpp"

#include <gtest/gtest.h>
#include <random>

namespace gapfem::output {
namespace {

struct Case {
  Shape shape;
  bool reduced;
};

TEST(NodalAverage, LinearFieldsComeBackExactlyAtTheNodes) {
  const Case cases[] = {{Shape::Hex8, false},  {Shape::Hex20, false},   {Shape::Hex20, true},
                        {Shape::Tet10, false}, {Shape::Wedge15, false}, {Shape::Quad4, false},
                        {Shape::Quad8, false}, {Shape::Quad8, true},    {Shape::Tri6, false}};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coef(-3.0, 3.0);
  for (const Case& c : cases) {
    const auto rule =
        c.reduced ? reduced_integration_rule(c.shape) : full_integration_rule(c.shape);
    const int np = static_cast<int>(rule.size());
    const std::vector<double> E = extrapolation_matrix(c.shape, np);
    const auto nodes = shape_node_coords(c.shape);
    ASSERT_EQ(E.size(), nodes.size() * rule.size()) << shape_name(c.shape) << " " << np;
    for (int trial = 0; trial < 20; ++trial) {
      const double a = coef(rng), b[3] = {coef(rng), coef(rng), coef(rng)};
      auto field = [&](const std::array<double, 3>& x) {
        return a + b[0] * x[0] + b[1] * x[1] + b[2] * x[2];
      };
      for (std::size_t n = 0; n < nodes.size(); ++n) {
        double v = 0.0;
        for (int p = 0; p < np; ++p) v += E[n * np + p] * field(rule[p].xi);
        EXPECT_NEAR(v, field(nodes[n]), 1e-12)
            << shape_name(c.shape) << " (" << np << " points) node " << n + 1;
      }
    }
  }
}

TEST(NodalAverage, TrilinearFieldOfC3D8IsReproduced) {
  // 8 points, 8 corners: the fit is the inverse of the interpolation, so any trilinear field
  // (xi eta zeta terms included) is exact at the corners
  const auto rule = full_integration_rule(Shape::Hex8);
  const std::vector<double> E = extrapolation_matrix(Shape::Hex8, 8);
  const auto nodes = shape_node_coords(Shape::Hex8);
  auto field = [](const std::array<double, 3>& x) {
    return 1.0 + 2.0 * x[0] * x[1] - 0.5 * x[1] * x[2] + 3.0 * x[0] * x[1] * x[2];
  };
  for (int n = 0; n < 8; ++n) {
    double v = 0.0;
    for (int p = 0; p < 8; ++p) v += E[n * 8 + p] * field(rule[p].xi);
    EXPECT_NEAR(v, field(nodes[n]), 1e-12) << "corner " << n + 1;
  }
}

TEST(NodalAverage, RulesWithFewerPointsThanCornersUseTheMean) {
  for (const Case c :
       {Case{Shape::Tet4, false}, Case{Shape::Wedge6, false}, Case{Shape::Tri3, false},
        Case{Shape::Hex8, true}, Case{Shape::Quad4, true}}) {
    const auto rule =
        c.reduced ? reduced_integration_rule(c.shape) : full_integration_rule(c.shape);
    EXPECT_TRUE(extrapolation_matrix(c.shape, static_cast<int>(rule.size())).empty())
        << shape_name(c.shape);
  }
  EXPECT_TRUE(extrapolation_matrix(Shape::Hex8, 5).empty()); // no rule with 5 points
}

TEST(NodalAverage, ComponentSlots) {
  EXPECT_EQ(nodal_slot("S11", 6), 0);
  EXPECT_EQ(nodal_slot("E33", 6), 2);
  EXPECT_EQ(nodal_slot("S12", 6), 3);
  EXPECT_EQ(nodal_slot("S13", 6), 4);
  EXPECT_EQ(nodal_slot("S23", 6), 5);
  EXPECT_EQ(nodal_slot("HFL1", 3), 0);
  EXPECT_EQ(nodal_slot("HFL3", 3), 2);
  EXPECT_EQ(nodal_slot("HFL4", 3), -1);
  EXPECT_EQ(nodal_slot("S11", 3), -1);
}

} // namespace
} // namespace gapfem::output
