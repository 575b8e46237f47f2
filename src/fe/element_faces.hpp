#pragma once
/// @file element_faces.hpp
/// Face (3-D) and edge (2-D) definitions of the reference cells in Abaqus numbering, used for
/// distributed surface loads (Pn, Sn, Fn) by the continuum and heat-transfer elements.
///
/// Abaqus / CalculiX face numbering (CalculiX User's Manual, *DLOAD, which follows the Abaqus
/// element library):
///   Hex8   S1 1-2-3-4  S2 5-8-7-6  S3 1-5-6-2  S4 2-6-7-3  S5 3-7-8-4  S6 4-8-5-1
///   Tet    S1 1-2-3    S2 1-4-2    S3 2-4-3    S4 3-4-1   (Tet10 adds the midside nodes)
///   Quad4  S1 1-2  S2 2-3  S3 3-4  S4 4-1;   Tri3  S1 1-2  S2 2-3  S3 3-1
/// With these orderings the face parametrisation x(xi, eta) has dx/dxi x dx/deta pointing INTO the
/// element (3-D), and for a counter-clockwise 2-D element the edge tangent rotated by +90 degrees,
/// (-dy/dxi, dx/dxi), points into the element.
#include "fe/shape_functions.hpp"

#include <array>
#include <span>

namespace gapfem {

/// One face or edge: its shape and the (0-based) local node numbers of the element on it.
struct FaceDef {
  Shape shape = Shape::Tri3;
  int n_nodes = 0;
  std::array<int, 8> nodes{};
};

/// Faces of a volume shape (Hex8, Tet4, Tet10) or edges of an area shape (Quad4, Tri3, Tri6),
/// in Abaqus order (index 0 is face S1). Empty for lines.
std::span<const FaceDef> element_faces(Shape cell);

} // namespace gapfem
