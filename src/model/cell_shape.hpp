#pragma once
/// @file cell_shape.hpp
/// The reference cells of the continuum and heat-transfer elements (the element type table names
/// each type's cell; fe/shape_functions.hpp defines their shape functions and node positions).
///
///   Line2/Line3    xi in [-1, 1]; the Line3 midside node is node 3
///   Tri3/Tri6      area coordinates (xi, eta), N1 = 1 - xi - eta; Tri6 midsides 4: 1-2, 5: 2-3,
///                  6: 3-1
///   Quad4/Quad8    [-1, 1]^2, corners counter-clockwise from (-1, -1); Quad8 midsides 5: 1-2,
///                  6: 2-3, 7: 3-4, 8: 4-1
///   Tet4/Tet10     volume coordinates (xi, eta, zeta), N1 = 1 - xi - eta - zeta; Tet10 midsides
///                  5..10 on edges 1-2, 2-3, 3-1, 1-4, 2-4, 3-4
///   Wedge6/Wedge15 triangle (xi, eta) x zeta in [-1, 1]; corners 1-3 at zeta = -1, 4-6 above;
///                  Wedge15 midsides 7: 1-2, 8: 2-3, 9: 3-1, 10: 4-5, 11: 5-6, 12: 6-4, 13: 1-4,
///                  14: 2-5, 15: 3-6
///   Hex8/Hex20     [-1, 1]^3, corners 1-4 on zeta = -1 counter-clockwise from (-1, -1), 5-8
///                  above; Hex20 midsides 9: 1-2, 10: 2-3, 11: 3-4, 12: 4-1, 13: 5-6, 14: 6-7,
///                  15: 7-8, 16: 8-5, 17: 1-5, 18: 2-6, 19: 3-7, 20: 4-8
/// (the Abaqus node orders of the element library).
#include <cstdint>
#include <string_view>

namespace gapfem {

enum class Shape : std::uint8_t {
  Line2,
  Line3,
  Tri3,
  Tri6,
  Quad4,
  Quad8,
  Tet4,
  Tet10,
  Wedge6,
  Wedge15,
  Hex8,
  Hex20
};

/// Number of nodes of a shape.
constexpr int shape_n_nodes(Shape s) {
  switch (s) {
  case Shape::Line2:
    return 2;
  case Shape::Line3:
    return 3;
  case Shape::Tri3:
    return 3;
  case Shape::Tri6:
    return 6;
  case Shape::Quad4:
    return 4;
  case Shape::Quad8:
    return 8;
  case Shape::Tet4:
    return 4;
  case Shape::Tet10:
    return 10;
  case Shape::Wedge6:
    return 6;
  case Shape::Wedge15:
    return 15;
  case Shape::Hex8:
    return 8;
  case Shape::Hex20:
    return 20;
  }
  return 0;
}
/// Parametric dimension of a shape.
constexpr int shape_dim(Shape s) {
  switch (s) {
  case Shape::Line2:
  case Shape::Line3:
    return 1;
  case Shape::Tri3:
  case Shape::Tri6:
  case Shape::Quad4:
  case Shape::Quad8:
    return 2;
  default:
    return 3;
  }
}
std::string_view shape_name(Shape s);
/// True for the quadratic (midside-node) shapes.
constexpr bool shape_quadratic(Shape s) {
  return s == Shape::Line3 || s == Shape::Tri6 || s == Shape::Quad8 || s == Shape::Tet10 ||
         s == Shape::Wedge15 || s == Shape::Hex20;
}

} // namespace gapfem
