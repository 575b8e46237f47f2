#pragma once
/// @file surface_geometry.hpp
/// Geometry of element-based surfaces in the reference configuration, for the constraints built
/// on surfaces: the facets (element faces in 3-D, edges in 2-D) with their global nodes, the
/// tributary area of each surface node (distributing couplings), and the closest point of a
/// facet to a point (the slave-node search of *TIE).
#include "common/types.hpp"
#include "fe/element_faces.hpp"
#include "model/element_types.hpp"

#include <array>
#include <map>
#include <optional>
#include <vector>

namespace gapfem {

struct Model;
struct Surface;

/// The reference cell of a continuum or heat-transfer element type (nullopt: no faces).
std::optional<Shape> cell_shape(ElementType type);

/// One face (edge) of a surface with the global nodes on it.
struct SurfaceFacet {
  ElemId elem = -1;
  int face = 0; ///< 1-based
  Shape shape = Shape::Tri3;
  int n_nodes = 0;
  std::array<NodeId, 8> nodes{};
};

/// The facets of an element-based surface (faces whose element type has none are skipped).
std::vector<SurfaceFacet> surface_facets(const Model& model, const Surface& surface);

/// Adds the tributary area of each node of the facet: the integral of its shape function over
/// the facet for linear facets, area / n for quadratic ones (whose corner integrals can vanish).
/// Edges of 2-D models give their length.
void add_tributary_areas(const Model& model, const SurfaceFacet& facet,
                         std::map<NodeId, double>& area);

/// Closest point of a facet to a point.
struct FacetPoint {
  std::array<double, 2> xi{}; ///< facet coordinates
  std::array<double, 8> N{};  ///< shape functions of the facet nodes at xi
  Vec3 point{};
  double distance = 0.0;
};
FacetPoint closest_point(const Model& model, const SurfaceFacet& facet, const Vec3& x);

/// Largest distance between two corner nodes of the facet (its "size").
double facet_size(const Model& model, const SurfaceFacet& facet);

} // namespace gapfem
