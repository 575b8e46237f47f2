#include "io/inp/constraint_rows.hpp"

#include "fem/surface_geometry.hpp"

#include <cmath>
#include <set>

namespace gapfem::inp {

SpaceDofs space_dofs(ModelSpace space) {
  if (space == ModelSpace::ThreeD) return {{1, 2, 3}, {4, 5, 6}};
  return {{1, 2}, {6}};
}

LinearConstraint new_row(const RowOrigin& o) {
  LinearConstraint c;
  c.kind = o.kind;
  c.name = o.name;
  c.loc = o.loc;
  c.yields_to_bc = o.yields_to_bc;
  return c;
}

DofType dof_of(int abaqus_number) {
  DofType d{};
  dof_from_abaqus(abaqus_number, d);
  return d;
}

LinearConstraint equal_row(const RowOrigin& o, NodeId a, NodeId b, int dof, bool activate_a,
                           bool activate_b) {
  LinearConstraint c = new_row(o);
  c.terms.push_back({a, dof_of(dof), 1.0, activate_a});
  c.terms.push_back({b, dof_of(dof), -1.0, activate_b});
  return c;
}

LinearConstraint rigid_row(const RowOrigin& o, ModelSpace space, NodeId a, NodeId b, int dof,
                           const Vec3& d, bool activate_a) {
  LinearConstraint c = new_row(o);
  c.terms.push_back({a, dof_of(dof), 1.0, activate_a});
  c.terms.push_back({b, dof_of(dof), -1.0, true});
  // -(theta x d)_i: (theta x d) = (t2 d3 - t3 d2, t3 d1 - t1 d3, t1 d2 - t2 d1)
  const int i = dof - 1;
  const int j = (i + 1) % 3, k = (i + 2) % 3; // (theta x d)_i = t_j d_k - t_k d_j
  auto add = [&](int rot, double coeff) {
    if (coeff == 0.0) return;
    if (space != ModelSpace::ThreeD && rot != 6) return; // planar: theta = (0, 0, t3)
    c.terms.push_back({b, dof_of(rot), coeff, true});
    c.small_rotation = true;
  };
  add(4 + j, -d[k]);
  add(4 + k, d[j]);
  return c;
}

std::vector<NodeId> surface_nodes(const Model& m, const Surface& s) {
  std::set<NodeId> nodes;
  if (s.node_based)
    for (const auto& wn : s.nodes) nodes.insert(wn.node);
  else
    for (const SurfaceFacet& f : surface_facets(m, s))
      for (int a = 0; a < f.n_nodes; ++a) nodes.insert(f.nodes[a]);
  return {nodes.begin(), nodes.end()};
}

int dominant_translation(ModelSpace space, const Vec3& v) {
  const int n = space == ModelSpace::ThreeD ? 3 : 2;
  int best = 0;
  for (int i = 1; i < n; ++i)
    if (std::abs(v[i]) > std::abs(v[best])) best = i;
  return best + 1;
}

} // namespace gapfem::inp
