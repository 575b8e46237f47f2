// Cyclic symmetry: *CYCLIC SYMMETRY MODEL (N sectors in 360 degrees about the axis from a to b)
// and *TIE, CYCLIC SYMMETRY (slave surface, master surface). The datum sector's slave surface is
// its master surface turned by 360 / N about the axis; every slave node is tied to the point of
// the master surface it came from, with the displacements (and rotations) turned the same way:
//   u(s) = R sum_k N_k u(m_k),   theta(s) = R sum_k N_k theta(m_k),   T(s) = sum_k N_k T(m_k),
// R the rotation by the sector angle. The rows are exact for any displacement (X_s = R X_m), so
// they hold under NLGEOM too; they carry the cyclic symmetric response (nodal diameter 0), the
// one a static, heat-transfer or dynamic step of a sector computes. Nodes on both surfaces lie on
// the axis: their components across the axis are zero. Abaqus references: Keywords Reference
// *CYCLIC SYMMETRY MODEL, *TIE; Analysis User's Guide "Analysis of models that exhibit cyclic
// symmetry" (docs/keywords.md).
#include "fem/surface_geometry.hpp"
#include "io/inp/constraint_rows.hpp"
#include "io/inp/handlers.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <map>
#include <numbers>
#include <set>

namespace gapfem::inp {
namespace {

Eigen::Vector3d vec(const Vec3& v) {
  return {v[0], v[1], v[2]};
}

/// The rotation by `angle` about the unit axis e (right-hand rule).
Eigen::Matrix3d rotation(const Eigen::Vector3d& e, double angle) {
  Eigen::Matrix3d K;
  K << 0, -e.z(), e.y(), e.z(), 0, -e.x(), -e.y(), e.x(), 0;
  return std::cos(angle) * Eigen::Matrix3d::Identity() + std::sin(angle) * K +
         (1 - std::cos(angle)) * e * e.transpose();
}

/// The master surface's facets with their bounding boxes, for the closest-point search. A
/// node-based master (CalculiX's cyclic decks) has one-node facets: its nodes, which the turned
/// slave nodes must meet.
struct MasterSearch {
  std::vector<SurfaceFacet> facets;
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> boxes;
  double mean_size = 0.0; ///< facets: their mean size; nodes: the mean nearest-node distance
  std::set<NodeId> nodes;

  MasterSearch(const Model& m, const Surface& master) {
    if (master.node_based) {
      for (const auto& wn : master.nodes) nodes.insert(wn.node);
      for (NodeId n : nodes) {
        SurfaceFacet f;
        f.n_nodes = 1;
        f.nodes[0] = n;
        facets.push_back(f);
      }
    } else {
      facets = surface_facets(m, master);
    }
    for (const SurfaceFacet& f : facets) {
      Eigen::Vector3d lo = vec(m.mesh.coords[f.nodes[0]]), hi = lo;
      for (int a = 0; a < f.n_nodes; ++a) {
        nodes.insert(f.nodes[a]);
        lo = lo.cwiseMin(vec(m.mesh.coords[f.nodes[a]]));
        hi = hi.cwiseMax(vec(m.mesh.coords[f.nodes[a]]));
      }
      boxes.emplace_back(lo, hi);
      if (!master.node_based) mean_size += facet_size(m, f) / static_cast<double>(facets.size());
    }
    if (master.node_based) mean_size = mean_node_spacing(m);
  }

  /// The mean distance from each master node to its nearest neighbour (all pairs: a sector's
  /// side has a few thousand nodes at most).
  double mean_node_spacing(const Model& m) const {
    if (facets.size() < 2) return 0.0;
    double sum = 0.0;
    for (const SurfaceFacet& a : facets) {
      double best = std::numeric_limits<double>::infinity();
      for (const SurfaceFacet& b : facets)
        if (a.nodes[0] != b.nodes[0])
          best = std::min(best,
                          (vec(m.mesh.coords[a.nodes[0]]) - vec(m.mesh.coords[b.nodes[0]])).norm());
      sum += best;
    }
    return sum / static_cast<double>(facets.size());
  }

  /// The closest point of the surface to x and its facet.
  std::pair<FacetPoint, std::size_t> closest(const Model& m, const Eigen::Vector3d& x) const {
    FacetPoint best;
    best.distance = std::numeric_limits<double>::infinity();
    std::size_t at = 0;
    for (std::size_t k = 0; k < facets.size(); ++k) {
      const Eigen::Vector3d d =
          (boxes[k].first - x).cwiseMax(Eigen::Vector3d::Zero()).cwiseMax(x - boxes[k].second);
      if (d.norm() >= best.distance) continue;
      const FacetPoint p = point_of(m, facets[k], x);
      if (p.distance < best.distance) {
        best = p;
        at = k;
      }
    }
    return {best, at};
  }

  static FacetPoint point_of(const Model& m, const SurfaceFacet& f, const Eigen::Vector3d& x) {
    if (f.n_nodes > 1) return closest_point(m, f, {x.x(), x.y(), x.z()});
    FacetPoint p; // a node of a node-based master
    p.N[0] = 1.0;
    p.point = m.mesh.coords[f.nodes[0]];
    p.distance = (vec(p.point) - x).norm();
    return p;
  }
};

/// Where each slave node comes from on the master surface, for a sector turned by `angle`.
struct Match {
  std::map<NodeId, std::pair<FacetPoint, std::size_t>> points;
  int outside = 0;
  NodeId first_out = -1;
  double first_distance = 0.0;
};

Match match(const Model& m, const MasterSearch& ms, const std::vector<NodeId>& slaves,
            const Eigen::Vector3d& a, const Eigen::Matrix3d& back, double tol) {
  Match out;
  for (NodeId n : slaves) {
    if (ms.nodes.count(n)) continue; // on both surfaces: on the axis (axis_rows)
    const Eigen::Vector3d x = a + back * (vec(m.mesh.coords[n]) - a);
    const auto found = ms.closest(m, x);
    out.points[n] = found;
    if (found.first.distance > tol && out.outside++ == 0) {
      out.first_out = n;
      out.first_distance = found.first.distance;
    }
  }
  return out;
}

/// sum_i p_i u(n, dofs[i]) = 0 for two directions p across the axis e (each row eliminating its
/// largest component, the second free of the first's).
void axis_rows(Model& m, const RowOrigin& o, NodeId n, const Eigen::Vector3d& e,
               const std::array<int, 3>& dofs) {
  Eigen::Vector3d p1 = e.unitOrthogonal(), p2 = e.cross(p1);
  int d1 = 0, d2 = 0;
  p1.cwiseAbs().maxCoeff(&d1);
  p2 -= p2[d1] / p1[d1] * p1;
  p2.cwiseAbs().maxCoeff(&d2);
  for (const auto& [p, d] : {std::pair{p1, d1}, std::pair{p2, d2}}) {
    LinearConstraint c = new_row(o);
    c.drop_if_missing = true;
    c.terms.push_back({n, dof_of(dofs[static_cast<std::size_t>(d)]), p[d], false});
    for (int j = 0; j < 3; ++j)
      if (j != d && std::abs(p[j]) > 1e-14 * p.cwiseAbs().maxCoeff())
        c.terms.push_back({n, dof_of(dofs[static_cast<std::size_t>(j)]), p[j], false});
    m.constraints.push_back(std::move(c));
  }
}

/// u(s, dofs) = R sum_k N_k u(m_k, dofs) for a vector field (translations or rotations).
void vector_rows(Model& m, const RowOrigin& o, NodeId s, const SurfaceFacet& f, const FacetPoint& p,
                 const Eigen::Matrix3d& R, const std::array<int, 3>& dofs) {
  for (int i = 0; i < 3; ++i) {
    LinearConstraint c = new_row(o);
    c.drop_if_missing = true;
    c.terms.push_back({s, dof_of(dofs[static_cast<std::size_t>(i)]), 1.0, false});
    for (int a = 0; a < f.n_nodes; ++a)
      for (int j = 0; j < 3; ++j) {
        const double coeff = -p.N[a] * R(i, j);
        if (std::abs(coeff) > 1e-14)
          c.terms.push_back({f.nodes[a], dof_of(dofs[static_cast<std::size_t>(j)]), coeff, false});
      }
    m.constraints.push_back(std::move(c));
  }
}

} // namespace

void handle_cyclic_symmetry_model(BuildState& s, const Keyword& kw) {
  BuildState::CyclicModelDef def;
  def.loc = kw.loc;
  const auto n = real_param(kw, "N");
  if (!n) throw InputError(kw.loc, "", "give N=<the number of sectors in 360 degrees>");
  if (!(*n > 1.0) || *n > 1e6)
    throw InputError(kw.loc, param_text(kw, "N"),
                     "N is the number of sectors in 360 degrees: more than 1");
  if (*n != std::round(*n))
    s.warn(kw.loc, fmt::format("N={} is not a whole number (CalculiX allows it): the sector angle "
                               "is 360/N = {:.6g} degrees and the structure does not close",
                               *n, 360.0 / *n));
  def.n = *n;
  def.tie = name_param(kw, "TIE", false);
  for (const BuildState::CyclicModelDef& other : s.cyclic_models)
    if (other.tie == def.tie)
      throw InputError(kw.loc, def.tie.empty() ? "" : param_text(kw, "TIE"),
                       fmt::format("{} has a *CYCLIC SYMMETRY MODEL already ({}); give each "
                                   "sector's its TIE= (one model per cyclic tie)",
                                   def.tie.empty() ? "the model" : "this tie", other.loc.str()));
  for (const char* p : {"NGRAPH", "ELSET"})
    if (kw.has(p))
      s.warn(kw.loc, fmt::format("{}= (CalculiX's expansion of the results to further sectors): "
                                 "gapfem writes the results of the datum sector",
                                 p));
  if (kw.has("CHECK") && !yes_no_param(kw, "CHECK", true))
    s.warn(kw.loc, "CHECK=NO (CalculiX): gapfem always checks that the slave surface is the "
                   "master surface turned by 360/N degrees");
  bool read = false;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    if (read && r.size() == 1 && !r.blank(0) && !parse_real(r.text(0))) {
      s.warn(r.loc(), fmt::format("{}: a set name after the axis (older CalculiX decks) is not "
                                  "used",
                                  r.text(0)));
      return;
    }
    r.at_most(6, "the axis: x, y, z of point a, x, y, z of point b");
    if (read) r.fail("data", "the axis takes one data line: two points, a and b");
    read = true;
    for (std::size_t i = 0; i < 3; ++i) {
      def.a[i] = r.real(i, fmt::format("{} of point a", "xyz"[i]));
      def.b[i] = r.real(i + 3, fmt::format("{} of point b", "xyz"[i]));
    }
    if ((vec(def.b) - vec(def.a)).norm() == 0.0)
      r.fail("axis", "points a and b coincide: give two distinct points of the symmetry axis");
  });
  if (!read)
    throw InputError(kw.loc, "",
                     "give the symmetry axis on a data line: x, y, z of point a, "
                     "x, y, z of point b");
  s.cyclic_models.push_back(def);
}

void build_cyclic_tie(BuildState& st, const CyclicTie& t) {
  Model& m = st.model;
  const std::string entity = "tie " + t.name;
  // its model: the one naming it (TIE=), else the one naming no tie
  const BuildState::CyclicModelDef* model = nullptr;
  for (const BuildState::CyclicModelDef& c : st.cyclic_models)
    if (c.tie == t.name || (c.tie.empty() && !model)) model = &c;
  if (!model)
    throw InputError(t.loc, entity,
                     st.cyclic_models.empty()
                         ? "a tie with CYCLIC SYMMETRY needs *CYCLIC SYMMETRY MODEL, N=<sectors> "
                           "with the symmetry axis in the model data"
                         : fmt::format("no *CYCLIC SYMMETRY MODEL belongs to this tie: every one "
                                       "names another TIE=; give this sector's with TIE={}",
                                       t.name));
  const BuildState::CyclicModelDef& cm = *model;
  if (m.space != ModelSpace::ThreeD)
    throw InputError(t.loc, entity, "cyclic symmetry needs a three-dimensional model");
  const Surface& slave = m.surfaces.at(t.slave);
  const Surface& master = m.surfaces.at(t.master);
  const MasterSearch ms(m, master);
  if (ms.facets.empty() && st.incomplete_surfaces.count(t.master)) return;
  if (ms.facets.empty())
    throw InputError(t.loc, entity,
                     fmt::format("the master surface {} has no element faces or nodes", t.master));
  const double tol = t.tolerance.value_or(0.05 * ms.mean_size);
  const Eigen::Vector3d a = vec(cm.a), e = (vec(cm.b) - a).normalized();
  const double alpha = 2 * std::numbers::pi / cm.n;
  const std::vector<NodeId> slaves = surface_nodes(m, slave);
  // the slave side is the master turned by +alpha about a -> b (or by -alpha: whichever
  // brings every slave node onto the master surface)
  double sign = 1.0;
  Match found = match(m, ms, slaves, a, rotation(e, -alpha), tol);
  if (found.outside > 0) {
    Match other = match(m, ms, slaves, a, rotation(e, alpha), tol);
    if (other.outside < found.outside) {
      found = std::move(other);
      sign = -1.0;
    }
  }
  if (found.outside > 0)
    throw InputError(t.loc, entity,
                     fmt::format("{} slave node(s) of surface {} are not on the master surface {} "
                                 "turned by 360/N = {:.6g} degrees about the axis (the first: node "
                                 "{}, {:.4g} away, beyond the position tolerance {:.4g}); check N "
                                 "and the axis of *CYCLIC SYMMETRY MODEL, or raise POSITION "
                                 "TOLERANCE",
                                 found.outside, t.slave, t.master, 360.0 / cm.n,
                                 m.node_label(found.first_out), found.first_distance, tol));
  const Eigen::Matrix3d R = rotation(e, sign * alpha);
  const RowOrigin o{ConstraintKind::Tie, entity, t.loc, true};
  constexpr std::array<int, 3> kTranslations{1, 2, 3}, kRotations{4, 5, 6};
  for (NodeId n : slaves) {
    if (!ms.nodes.count(n)) continue;
    const Eigen::Vector3d x = vec(m.mesh.coords[n]) - a;
    if ((x - x.dot(e) * e).norm() > tol)
      throw InputError(t.loc, fmt::format("{}: node {}", entity, m.node_label(n).str()),
                       "this node is on both the slave and the master surface but not on the "
                       "symmetry axis; a sector's two sides meet on the axis only");
    axis_rows(m, o, n, e, kTranslations);
    axis_rows(m, o, n, e, kRotations);
  }
  for (const auto& [n, pf] : found.points) {
    const auto& [p, k] = pf;
    if (t.adjust) {
      const Eigen::Vector3d x = a + R * (vec(p.point) - a);
      m.mesh.coords[n] = {x.x(), x.y(), x.z()};
    }
    const SurfaceFacet& f = ms.facets[k];
    vector_rows(m, o, n, f, p, R, kTranslations);
    vector_rows(m, o, n, f, p, R, kRotations);
    LinearConstraint c = new_row(o); // the temperature where both sides carry it
    c.drop_if_missing = true;
    c.terms.push_back({n, dof_of(11), 1.0, false});
    for (int j = 0; j < f.n_nodes; ++j)
      if (std::abs(p.N[j]) > 1e-14) c.terms.push_back({f.nodes[j], dof_of(11), -p.N[j], false});
    m.constraints.push_back(std::move(c));
  }
}

void check_cyclic_symmetry(BuildState& s) {
  if (s.cyclic_ties.empty()) {
    if (!s.cyclic_models.empty())
      s.warn(s.cyclic_models.front().loc, "*CYCLIC SYMMETRY MODEL without a *TIE, CYCLIC "
                                          "SYMMETRY: the model is analysed as it is, without "
                                          "cyclic constraints");
    return;
  }
  for (const BuildState::CyclicModelDef& cm : s.cyclic_models)
    if (!cm.tie.empty() && std::none_of(s.cyclic_ties.begin(), s.cyclic_ties.end(),
                                        [&](const auto& t) { return t.first == cm.tie; }))
      s.error(cm.loc, fmt::format("TIE={}", cm.tie),
              "no *TIE, CYCLIC SYMMETRY has this name; name the cyclic tie of the sector");
  for (const Step& step : s.model.steps)
    if (is_perturbation(step.procedure) || is_mode_based(step.procedure))
      s.error(step.loc, fmt::format("step {}", step.number),
              fmt::format("{} in a cyclic symmetric model: gapfem's cyclic tie holds the cyclic "
                          "symmetric response (nodal diameter 0) only, and the modes of the other "
                          "nodal diameters (*SELECT CYCLIC SYMMETRY MODES) are not available; "
                          "model the whole structure for this step",
                          procedure_name(step.procedure)));
}

} // namespace gapfem::inp
