#pragma once
/// @file quadrature.hpp
/// Integration rules on the reference cells of the supported continuum and heat-transfer elements.
/// Points are listed in Abaqus integration-point order (first parametric coordinate fastest for the
/// Gauss product rules). Weights sum to the measure of the reference cell: 2 (line), 4 (quad),
/// 8 (hex), 1/2 (triangle), 1/6 (tetrahedron), 1 (wedge).
#include "fe/shape_functions.hpp"

#include <array>
#include <span>

namespace gapfem {

/// One integration point: parametric coordinates (unused ones are 0) and weight.
struct QuadraturePoint {
  std::array<double, 3> xi{};
  double weight = 0.0;
};

namespace quadrature_detail {
inline constexpr double kG2 = 0.57735026918962576451; // 1/sqrt(3)
inline constexpr double kG3 = 0.77459666924148337704; // sqrt(3/5)
inline constexpr double kW3a = 5.0 / 9.0, kW3b = 8.0 / 9.0;
// 4-point tetrahedron rule (degree 2): a = (5 + 3 sqrt 5)/20, b = (5 - sqrt 5)/20.
inline constexpr double kTa = 0.58541019662496845446, kTb = 0.13819660112501051518;
// 6-point triangle rule (degree 4, Dunavant/Strang-Fix): two orbits of (a, a, 1-2a).
inline constexpr double kT6a = 0.44594849091596488632, kT6wa = 0.22338158967801146570 / 2.0;
inline constexpr double kT6b = 0.09157621350977074346, kT6wb = 0.10995174365532186764 / 2.0;
// 3-point triangle rule (degree 2, interior points).
inline constexpr double kT3 = 1.0 / 6.0;
} // namespace quadrature_detail

/// 1-, 2- and 3-point Gauss rules on [-1, 1].
inline constexpr std::array<QuadraturePoint, 1> kGaussLine1{{{{0.0, 0, 0}, 2.0}}};
inline constexpr std::array<QuadraturePoint, 2> kGaussLine2{
    {{{-quadrature_detail::kG2, 0, 0}, 1.0}, {{quadrature_detail::kG2, 0, 0}, 1.0}}};
inline constexpr std::array<QuadraturePoint, 3> kGaussLine3{
    {{{-quadrature_detail::kG3, 0, 0}, quadrature_detail::kW3a},
     {{0.0, 0, 0}, quadrature_detail::kW3b},
     {{quadrature_detail::kG3, 0, 0}, quadrature_detail::kW3a}}};

/// Quadrilateral: centroid and 2x2 Gauss (Abaqus order: (-,-), (+,-), (-,+), (+,+)).
inline constexpr std::array<QuadraturePoint, 1> kGaussQuad1{{{{0.0, 0.0, 0}, 4.0}}};
inline constexpr std::array<QuadraturePoint, 4> kGaussQuad4{
    {{{-quadrature_detail::kG2, -quadrature_detail::kG2, 0}, 1.0},
     {{quadrature_detail::kG2, -quadrature_detail::kG2, 0}, 1.0},
     {{-quadrature_detail::kG2, quadrature_detail::kG2, 0}, 1.0},
     {{quadrature_detail::kG2, quadrature_detail::kG2, 0}, 1.0}}};

/// Quadrilateral 3x3 Gauss (Abaqus order, xi fastest).
inline constexpr std::array<QuadraturePoint, 9> kGaussQuad9 = [] {
  using namespace quadrature_detail;
  std::array<QuadraturePoint, 9> q{};
  constexpr double x[3] = {-kG3, 0.0, kG3}, w[3] = {kW3a, kW3b, kW3a};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) q[3 * j + i] = {{x[i], x[j], 0}, w[i] * w[j]};
  return q;
}();

/// Hexahedron 3x3x3 Gauss (Abaqus order, xi fastest, then eta, then zeta).
inline constexpr std::array<QuadraturePoint, 27> kGaussHex27 = [] {
  using namespace quadrature_detail;
  std::array<QuadraturePoint, 27> q{};
  constexpr double x[3] = {-kG3, 0.0, kG3}, w[3] = {kW3a, kW3b, kW3a};
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) q[9 * k + 3 * j + i] = {{x[i], x[j], x[k]}, w[i] * w[j] * w[k]};
  return q;
}();

/// Hexahedron: centroid and 2x2x2 Gauss (Abaqus order, xi fastest, then eta, then zeta).
inline constexpr std::array<QuadraturePoint, 1> kGaussHex1{{{{0.0, 0.0, 0.0}, 8.0}}};
inline constexpr std::array<QuadraturePoint, 8> kGaussHex8 = [] {
  std::array<QuadraturePoint, 8> q{};
  const double g = quadrature_detail::kG2;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        q[4 * k + 2 * j + i] = {{i ? g : -g, j ? g : -g, k ? g : -g}, 1.0};
  return q;
}();

/// Triangle (area coordinates xi, eta): centroid, 3-point (degree 2) and 6-point (degree 4).
inline constexpr std::array<QuadraturePoint, 1> kTri1{{{{1.0 / 3.0, 1.0 / 3.0, 0}, 0.5}}};
inline constexpr std::array<QuadraturePoint, 3> kTri3{
    {{{quadrature_detail::kT3, quadrature_detail::kT3, 0}, 1.0 / 6.0},
     {{1.0 - 2.0 * quadrature_detail::kT3, quadrature_detail::kT3, 0}, 1.0 / 6.0},
     {{quadrature_detail::kT3, 1.0 - 2.0 * quadrature_detail::kT3, 0}, 1.0 / 6.0}}};
inline constexpr std::array<QuadraturePoint, 6> kTri6 = [] {
  using namespace quadrature_detail;
  return std::array<QuadraturePoint, 6>{{{{kT6a, kT6a, 0}, kT6wa},
                                         {{1.0 - 2.0 * kT6a, kT6a, 0}, kT6wa},
                                         {{kT6a, 1.0 - 2.0 * kT6a, 0}, kT6wa},
                                         {{kT6b, kT6b, 0}, kT6wb},
                                         {{1.0 - 2.0 * kT6b, kT6b, 0}, kT6wb},
                                         {{kT6b, 1.0 - 2.0 * kT6b, 0}, kT6wb}}};
}();

/// Tetrahedron: centroid and 4-point (degree 2) rule.
inline constexpr std::array<QuadraturePoint, 1> kTet1{{{{0.25, 0.25, 0.25}, 1.0 / 6.0}}};
inline constexpr std::array<QuadraturePoint, 4> kTet4{
    {{{quadrature_detail::kTb, quadrature_detail::kTb, quadrature_detail::kTb}, 1.0 / 24.0},
     {{quadrature_detail::kTa, quadrature_detail::kTb, quadrature_detail::kTb}, 1.0 / 24.0},
     {{quadrature_detail::kTb, quadrature_detail::kTa, quadrature_detail::kTb}, 1.0 / 24.0},
     {{quadrature_detail::kTb, quadrature_detail::kTb, quadrature_detail::kTa}, 1.0 / 24.0}}};

/// Wedge (triangle x line): the triangle centroid x 2 Gauss points (C3D6, Abaqus's 2 points) and
/// the 3-point triangle rule x 3 Gauss points (C3D15, 9 points); the triangle points run fastest.
inline constexpr std::array<QuadraturePoint, 2> kWedge2{
    {{{1.0 / 3.0, 1.0 / 3.0, -quadrature_detail::kG2}, 0.5},
     {{1.0 / 3.0, 1.0 / 3.0, quadrature_detail::kG2}, 0.5}}};
inline constexpr std::array<QuadraturePoint, 9> kWedge9 = [] {
  using namespace quadrature_detail;
  std::array<QuadraturePoint, 9> q{};
  constexpr double z[3] = {-kG3, 0.0, kG3}, w[3] = {kW3a, kW3b, kW3a};
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i)
      q[3 * k + i] = {{kTri3[i].xi[0], kTri3[i].xi[1], z[k]}, kTri3[i].weight * w[k]};
  return q;
}();
/// A 6-point wedge rule exact for N_a N_b of Wedge6 (3-point triangle x 2 Gauss points), for
/// capacities and nodal volumes.
inline constexpr std::array<QuadraturePoint, 6> kWedge6 = [] {
  using namespace quadrature_detail;
  std::array<QuadraturePoint, 6> q{};
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < 3; ++i)
      q[3 * k + i] = {{kTri3[i].xi[0], kTri3[i].xi[1], k ? kG2 : -kG2}, kTri3[i].weight};
  return q;
}();

/// The standard ("full") stiffness rule of a shape: 2x2(x2) Gauss for quads and hexes, the centroid
/// for linear simplices, 4 points for the quadratic tetrahedron, 3 points for the quadratic
/// triangle, 2 (3) Gauss points for linear (quadratic) lines.
/// Quad8 and Hex20 use 3x3(x3) Gauss, the wedges 2 (Wedge6) and 9 (Wedge15) points.
std::span<const QuadraturePoint> full_integration_rule(Shape shape);
/// The reduced rule of the R element types: the centroid for Quad4/Hex8, 2x2(x2) Gauss for
/// Quad8/Hex20; the full rule for the other shapes.
std::span<const QuadraturePoint> reduced_integration_rule(Shape shape);
/// A rule that integrates the surface-load integrand of a face of this shape accurately enough
/// for follower loads on distorted faces (2x2 Gauss on quads, 3 / 6 points on linear / quadratic
/// triangles, 2 / 3 Gauss points on lines).
std::span<const QuadraturePoint> face_load_rule(Shape face_shape);

} // namespace gapfem
