#pragma once
/// @file mortar.hpp
/// The surface-to-surface (mortar) tie of two element-based surfaces: for every slave node s,
///
///     sum_s' M_ss' u_s' - sum_m D_sm u_m = 0,
///     M_ss' = int_Gamma N_s N_s' dA,   D_sm = int_Gamma N_s N_m dA,
///
/// integrated over the part Gamma of the slave surface that the master surface covers, segment by
/// segment: each slave facet is clipped against the master facets projected onto its plane, the
/// pieces are triangulated, and both sides' shape functions are evaluated at the triangles'
/// quadrature points. The constraint reproduces every linear field exactly (the patch test) for
/// either side as slave, matching or not.
#include "fem/surface_geometry.hpp"

#include <map>
#include <vector>

namespace gapfem {

/// The mortar row of one slave node, scaled by its covered area int_Gamma N_s dA.
struct MortarRow {
  NodeId slave = -1;
  std::vector<std::pair<NodeId, double>> slave_terms;  ///< (s', M_ss' / a_s), s' = s first
  std::vector<std::pair<NodeId, double>> master_terms; ///< (m, D_sm / a_s)
  double covered = 0.0; ///< a_s / int_slave N_s dA: 1 when the master covers the node's support
};

/// Rows for the slave facets against the master facets. `gap` bounds the normal distance between
/// a slave facet and a master facet that take part. Slave nodes that are also master nodes get no
/// row. `space_2d`: facets are edges in the x-y plane.
std::vector<MortarRow> mortar_rows(const Model& model, const std::vector<SurfaceFacet>& slave,
                                   const std::vector<SurfaceFacet>& master, double gap,
                                   bool space_2d);

} // namespace gapfem
