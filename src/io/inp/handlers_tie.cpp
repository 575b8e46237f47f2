// *TIE: TYPE=SURFACE TO SURFACE (the default) ties the surfaces in the mortar sense
// (fem/mortar.hpp: int N_s (u_slave - u_master) dA = 0 per slave node, exact for linear fields
// whichever side is the slave); TYPE=NODE TO SURFACE (and a node-based slave surface) ties every
// slave node to the closest point of the master surface,
//   u(s, i) - sum_k N_k(xi) u(m_k, i) = 0.
// Both act on the translations and, where both sides carry it, the temperature DOF 11 (Abaqus ties
// every DOF active on both surfaces). The search and the rows wait for the end of the model data
// (deferred, before the other constraints: ADJUST=YES moves the slave nodes onto the master
// surface, a stress-free initial adjustment). A slave node beyond the position tolerance is an
// input error; a slave node that is also a master node is not tied (it already belongs to both).
#include "fem/mortar.hpp"
#include "fem/surface_geometry.hpp"
#include "io/inp/constraint_rows.hpp"
#include "io/inp/handlers.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <map>
#include <set>

namespace gapfem::inp {
namespace {

struct TieDef {
  std::string name;
  SourceLocation loc;
  std::string slave, master;
  std::optional<double> tolerance;
  bool adjust = true;
  bool surface_to_surface = true; ///< TYPE=SURFACE TO SURFACE (the default): mortar integrals
};

struct Box {
  Vec3 lo, hi;
  double distance(const Vec3& p) const {
    double d2 = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double d = std::max({lo[i] - p[i], 0.0, p[i] - hi[i]});
      d2 += d * d;
    }
    return std::sqrt(d2);
  }
};

/// One row per DOF: u(s) + sum_k c_k u(k) = 0 for the terms (node, c), s first with c = 1.
void add_rows(Model& m, const RowOrigin& o, const std::vector<int>& dofs,
              const std::vector<std::pair<NodeId, double>>& terms) {
  for (int d : dofs) {
    LinearConstraint c = new_row(o);
    c.drop_if_missing = true;
    for (const auto& [n, coeff] : terms) c.terms.push_back({n, dof_of(d), coeff, false});
    m.constraints.push_back(std::move(c));
  }
}

void build_tie(BuildState& st, const TieDef& t) {
  Model& m = st.model;
  const Surface& slave = m.surfaces.at(t.slave);
  const Surface& master = m.surfaces.at(t.master);
  const std::vector<SurfaceFacet> facets = surface_facets(m, master);
  if (facets.empty() && st.incomplete_surfaces.count(t.master))
    return; // its elements failed to be defined (reported there)
  if (facets.empty())
    throw InputError(t.loc, fmt::format("tie {}", t.name),
                     fmt::format("the master surface {} has no element faces", t.master));
  std::vector<Box> boxes;
  std::set<NodeId> master_nodes;
  double size_sum = 0.0;
  for (const SurfaceFacet& f : facets) {
    Box b{m.mesh.coords[f.nodes[0]], m.mesh.coords[f.nodes[0]]};
    for (int a = 0; a < f.n_nodes; ++a) {
      master_nodes.insert(f.nodes[a]);
      for (int i = 0; i < 3; ++i) {
        b.lo[i] = std::min(b.lo[i], m.mesh.coords[f.nodes[a]][i]);
        b.hi[i] = std::max(b.hi[i], m.mesh.coords[f.nodes[a]][i]);
      }
    }
    boxes.push_back(b);
    size_sum += facet_size(m, f);
  }
  // Abaqus's default position tolerance: 5% of a typical master facet
  const double tol = t.tolerance.value_or(0.05 * size_sum / static_cast<double>(facets.size()));
  // every slave node must find the master surface within the tolerance (ADJUST moves it there)
  std::map<NodeId, FacetPoint> closest;
  std::map<NodeId, std::size_t> closest_facet;
  int outside = 0;
  NodeId first_out = -1;
  double first_distance = 0.0;
  for (NodeId n : surface_nodes(m, slave)) {
    if (master_nodes.count(n)) continue; // on both surfaces: already one node
    const Vec3 x = m.mesh.coords[n];
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < facets.size(); ++k) {
      if (boxes[k].distance(x) >= best) continue;
      const FacetPoint p = closest_point(m, facets[k], x);
      if (p.distance < best) {
        best = p.distance;
        closest[n] = p;
        closest_facet[n] = k;
      }
    }
    if (best > tol && outside++ == 0) {
      first_out = n;
      first_distance = best;
    }
  }
  if (outside > 0)
    throw InputError(t.loc, fmt::format("tie {}", t.name),
                     fmt::format("{} slave node(s) of surface {} find no face of the master "
                                 "surface {} within the position tolerance {:.4g} (the first: "
                                 "node {} at a distance of {:.4g}); raise POSITION TOLERANCE, or "
                                 "leave those nodes out of the slave surface",
                                 outside, t.slave, t.master, tol, m.node_label(first_out),
                                 first_distance));
  if (t.adjust)
    for (const auto& [n, p] : closest) m.mesh.coords[n] = p.point;

  const RowOrigin o{ConstraintKind::Tie, "tie " + t.name, t.loc, true};
  std::vector<int> dofs = space_dofs(m.space).translations;
  dofs.push_back(11); // where both sides carry the temperature
  std::set<NodeId> done;
  if (t.surface_to_surface && !slave.node_based) {
    const std::vector<SurfaceFacet> slave_facets = surface_facets(m, slave);
    for (const MortarRow& row :
         mortar_rows(m, slave_facets, facets, tol + 1e-12, m.space != ModelSpace::ThreeD)) {
      std::vector<std::pair<NodeId, double>> terms = row.slave_terms;
      for (const auto& [n, c] : row.master_terms) terms.emplace_back(n, -c);
      add_rows(m, o, dofs, terms);
      done.insert(row.slave);
    }
  }
  // node to surface (and slave nodes the mortar integrals do not reach): u_s = sum N_k u_k
  for (const auto& [n, p] : closest) {
    if (done.count(n)) continue;
    const SurfaceFacet& f = facets[closest_facet[n]];
    std::vector<std::pair<NodeId, double>> terms{{n, 1.0}};
    for (int a = 0; a < f.n_nodes; ++a)
      if (std::abs(p.N[a]) > 1e-14) terms.emplace_back(f.nodes[a], -p.N[a]);
    add_rows(m, o, dofs, terms);
  }
}

const Surface& tie_surface(BuildState& s, const FieldReader& r, std::size_t field,
                           const char* role) {
  const std::string name = s.set_name(to_upper(r.text(field)));
  std::string key = to_upper(r.text(field));
  if (key.find('.') == std::string::npos) key = name;
  const auto it = s.model.surfaces.find(key);
  if (it == s.model.surfaces.end())
    r.fail(fmt::format("{} surface {}", role, key),
           undefined_name(s, key, NameKind::Surface, "*TIE", "a surface",
                          "define it with *SURFACE before the tie"));
  return it->second;
}

} // namespace

void handle_tie(BuildState& s, const Keyword& kw) {
  TieDef t;
  t.name = name_param(kw, "NAME", true);
  t.loc = kw.loc;
  t.tolerance = real_param(kw, "POSITION TOLERANCE");
  if (t.tolerance && !(*t.tolerance >= 0))
    throw InputError(kw.loc, param_text(kw, "POSITION TOLERANCE"),
                     "the position tolerance must not be negative");
  t.adjust = yes_no_param(kw, "ADJUST", true);
  const int type = enum_param(kw, "TYPE", {"SURFACE TO SURFACE", "NODE TO SURFACE"}, 0);
  bool read = false;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(2, "slave surface, master surface");
    if (read)
      r.fail("data", "a *TIE takes one line (slave surface, master surface); write "
                     "another *TIE for another pair");
    read = true;
    const Surface& slave = tie_surface(s, r, 0, "slave");
    const Surface& master = tie_surface(s, r, 1, "master");
    if (master.node_based && !kw.has("CYCLIC SYMMETRY")) // a cyclic master's nodes are met
      r.fail(fmt::format("surface {}", master.name),
             "the master surface of a tie must be element-based (its faces interpolate the slave "
             "nodes)");
    t.slave = slave.name;
    t.master = master.name;
  });
  if (!read)
    throw InputError(kw.loc, fmt::format("tie {}", t.name),
                     "the tie needs a data line: slave surface, master surface");
  if (t.slave.empty()) return; // the data line was reported
  t.surface_to_surface = type == 0;
  if (kw.has("CYCLIC SYMMETRY")) { // the sector's sides: handlers_cyclic.cpp
    const CyclicTie c{t.name, t.slave, t.master, t.loc, t.tolerance, t.adjust};
    s.cyclic_ties.emplace_back(t.name, t.loc);
    s.deferred_constraints.push_back({0, [c](BuildState& st) { build_cyclic_tie(st, c); }});
    return;
  }
  s.deferred_constraints.push_back({0, [t](BuildState& st) { build_tie(st, t); }});
}

} // namespace gapfem::inp
