#pragma once
/// @file shell_geometry.hpp
/// Reference geometry of the shells S3/S3R, S4/S4R and S8R: shape functions on the element's
/// natural coordinates, the integration points, the local material directions of Abaqus's shell
/// convention and the nodal directors (docs/theory/structural.md §4).
///
/// Local directions at a point: n the unit surface normal (dX/dxi x dX/deta, node numbering
/// counter-clockwise seen from the positive side); 1 the projection of the global x-axis onto the
/// surface, or of the global z-axis when x is within 0.1 degree of the normal; 2 = n x 1.
#include "common/types.hpp"

#include <array>
#include <span>
#include <string>

namespace gapfem::shell {

/// Largest node count of a shell (S8R).
inline constexpr int kMaxNodes = 8;

/// Shape functions and their natural derivatives at (r, s) for 3 (r, s in the unit triangle),
/// 4 or 8 (r, s in [-1, 1]^2) nodes in Abaqus numbering.
struct Shape {
  std::array<double, kMaxNodes> N{}, dr{}, ds{};
};
Shape shape_at(int n_nodes, double r, double s);
/// Natural coordinates of node a.
std::array<double, 2> node_coordinates(int n_nodes, int a);

/// Reference geometry of one point of the mid-surface.
struct SurfacePoint {
  Shape sh;
  double r = 0.0, s = 0.0;
  double dA = 0.0; ///< |A1 x A2| times the quadrature weight (area element)
  Vec3 A1{}, A2{}; ///< covariant tangents dX/dr, dX/ds of the reference surface
  Vec3 n{};        ///< unit normal
  Vec3 e1{}, e2{}; ///< local directions 1 and 2
  /// T[alpha][i] = A^alpha . e_i: covariant components -> local components
  std::array<std::array<double, 2>, 2> T{};
  Vec3 D{}, Dr{}, Ds{}; ///< interpolated director and its natural derivatives
  double thickness = 0.0;
};

/// The surface point at (r, s) with quadrature weight w; `directors` and `thickness` per node.
/// Returns false when the surface is degenerate there (zero area element).
bool surface_point(std::span<const Vec3> X, std::span<const Vec3> directors,
                   std::span<const double> thickness, double r, double s, double w,
                   SurfacePoint& p);

/// Local directions 1, 2 of a surface with unit normal n (Abaqus's default).
void local_directions(const Vec3& n, Vec3& e1, Vec3& e2);

/// Unit normal of the element's own surface at node a (for the nodal directors); zero vector when
/// the surface is degenerate there.
Vec3 element_normal_at_node(std::span<const Vec3> X, int a);

/// Integration rule of an element: in-plane points and weights.
struct Rule {
  int n = 0;
  std::array<std::array<double, 3>, 9> pts{}; ///< r, s, weight
};
/// Full rule: 2x2 Gauss for quadrilaterals, the centroid for triangles.
Rule full_rule(int n_nodes);
/// 3x3 Gauss (S8, CalculiX's fully integrated eight-node shell).
Rule gauss3x3_rule();
/// The centre point (r, s, weight = reference area in natural coordinates).
std::array<double, 3> centre_point(int n_nodes);

/// An empty string when the element's geometry is usable; otherwise a sentence for the user.
std::string check_geometry(std::span<const Vec3> X, std::span<const Vec3> directors,
                           std::span<const double> thickness, double model_size);

} // namespace gapfem::shell
