#pragma once
/// @file nodal_average.hpp
/// Element output at the nodes: each continuum (or heat-transfer) element's integration-point
/// values are extrapolated to its nodes, then averaged over the elements that share a node, as
/// Abaqus does for POSITION=AVERAGED AT NODES and CalculiX for its .frd file.
///
/// Extrapolation: the least-squares fit of the point values by the element's linear (corner)
/// shape functions, evaluated at every node (a mid-side node gets the mean of its edge's corners).
/// It is the inverse of the point interpolation where the rule has one point per corner (C3D8,
/// C3D20R, C3D10, CPS4, CPS8R, CPS6), a least-squares fit where it has more (C3D20, C3D15, CPS8),
/// and the element's mean where it has fewer (C3D4, C3D6, CPS3, C3D8R, CPS4R): a linear field is
/// reproduced exactly at the nodes of every element of the first two groups.
#include "model/cell_shape.hpp"
#include "model/model.hpp"
#include "results/results.hpp"

#include <map>
#include <string_view>
#include <vector>

namespace gapfem::output {

/// One element variable at the nodes.
struct NodalField {
  /// component slots: S and E 11, 22, 33, 12, 13, 23 (6); HFL 1, 2, 3 (3)
  int width = 0;
  std::vector<double> values; ///< n_nodes x width (components an element lacks are 0)
  std::vector<int> count;     ///< per node: how many elements contributed (0: no value)
};

/// Slot of a component name ("S11" → 0, "E23" → 5, "HFL2" → 1) in a field of `width`, or -1.
int nodal_slot(std::string_view name, int width);

/// Rows: nodes of `shape`; columns: the points of the element's rule with `n_points` points.
/// Empty when no rule of the shape has that many points (the caller then uses the mean).
std::vector<double> extrapolation_matrix(Shape shape, int n_points);

class NodalAverager {
 public:
  /// `var` (S, E or HFL) of the elements with mask[e] != 0 (every element when `mask` is null),
  /// from `frame`'s element results. Elements without a cell or with no value are left out.
  NodalField average(const Model& model, const Frame& frame, ElemVar var,
                     const std::vector<char>* mask = nullptr);

 private:
  const std::vector<double>& matrix(Shape shape, int n_points);
  std::map<std::pair<int, int>, std::vector<double>> _cache;
};

} // namespace gapfem::output
