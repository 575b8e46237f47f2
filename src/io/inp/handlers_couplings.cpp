// *MPC (BEAM, TIE, PIN, LINK), *KINEMATIC COUPLING, and *COUPLING with *KINEMATIC or
// *DISTRIBUTING. Nodes and sets are resolved where the keyword is read (its scope); the rows are
// built at the end of the model data (BuildState::deferred_constraints), when the model space and
// the final coordinates are known. Abaqus references: Analysis User's Guide "General multi-point
// constraints", "Kinematic coupling constraints", "Coupling constraints"; Theory Guide
// "Distributing coupling constraints" (the load distribution and its linearised constraint).
#include "fem/surface_geometry.hpp"
#include "io/inp/constraint_rows.hpp"
#include "io/inp/handlers.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace gapfem::inp {
namespace {

Vec3 sub(const Vec3& a, const Vec3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
double norm(const Vec3& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

/// DOF ranges of *KINEMATIC COUPLING / *KINEMATIC / *DISTRIBUTING data: first[, last]; blank
/// first = all of 1-6.
std::vector<int> dof_range(const FieldReader& r, std::size_t first_field) {
  if (r.blank(first_field)) return {1, 2, 3, 4, 5, 6};
  constexpr std::string_view rule = "DOF {}: give DOFs within 1-6, the first not above the last";
  const long long a = r.integer(first_field, "first DOF", 1, 6, rule);
  const long long b = r.integer_or(first_field + 1, a, "last DOF", 1, 6, rule);
  if (b < a)
    r.fail(fmt::format("DOFs {}-{}", a, b), "give DOFs within 1-6, the first not above the last");
  std::vector<int> out;
  for (long long d = a; d <= b; ++d) out.push_back(static_cast<int>(d));
  return out;
}

bool contains(const std::vector<int>& v, int x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

/// The local axes (rows e1, e2, e3) of a coupling's ORIENTATION= at x; the identity without one;
/// nullopt for a point on a cylindrical system's axis when `on_axis_ok` (else an error).
std::optional<Eigen::Matrix3d> coupling_axes(const BuildState& s, const RowOrigin& o,
                                             const std::string& orientation, const Vec3& x,
                                             bool on_axis_ok = false) {
  if (orientation.empty()) return Eigen::Matrix3d::Identity();
  const auto it = s.orientations.find(orientation);
  if (it == s.orientations.end())
    throw InputError(o.loc, o.name,
                     fmt::format("ORIENTATION={}: no *ORIENTATION of this name is defined; define "
                                 "it or correct the name",
                                 orientation));
  if (s.model.space != ModelSpace::ThreeD)
    throw InputError(o.loc, o.name,
                     fmt::format("ORIENTATION={}: a coupling in a local system needs a "
                                 "three-dimensional model",
                                 orientation));
  std::string why;
  bool on_axis = false;
  const auto axes = orientation_axes_at(s, it->second, x, why, &on_axis);
  if (!axes && on_axis && on_axis_ok) return std::nullopt;
  if (!axes) throw InputError(o.loc, o.name, fmt::format("ORIENTATION={}: {}", orientation, why));
  Eigen::Matrix3d A;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) A(i, j) = (*axes)[static_cast<std::size_t>(i)][j];
  return A;
}

/// e . (field of node a) - e . (field of node b) [- (d x e) . theta(b)]: one row along the local
/// direction e, the largest component of a's the dependent DOF; `first` the field's first DOF
/// (1 translations, 4 rotations); `d` given: a's translation follows b's rigid motion.
LinearConstraint local_row(const RowOrigin& o, NodeId a, NodeId b, int first,
                           const Eigen::Vector3d& e, const Eigen::Vector3d* d) {
  LinearConstraint c = new_row(o);
  int big = 0;
  e.cwiseAbs().maxCoeff(&big);
  c.terms.push_back({a, dof_of(first + big), e[big], false});
  for (int j = 0; j < 3; ++j)
    if (j != big && std::abs(e[j]) > 1e-14) c.terms.push_back({a, dof_of(first + j), e[j], false});
  for (int j = 0; j < 3; ++j)
    if (std::abs(e[j]) > 1e-14) c.terms.push_back({b, dof_of(first + j), -e[j], true});
  if (d) { // e . (theta x d) = theta . (d x e)
    const Eigen::Vector3d m = d->cross(e);
    for (int k = 0; k < 3; ++k)
      if (std::abs(m[k]) > 1e-14 * std::max(1.0, d->norm())) {
        c.terms.push_back({b, dof_of(4 + k), -m[k], true});
        c.small_rotation = true;
      }
  }
  return c;
}

// ------------------------------------------------------------------ kinematic coupling rows
/// Coupling nodes follow the rigid motion of the reference node in the selected DOFs:
/// translations through rigid links, rotations equal (only at nodes that carry rotations); with
/// ORIENTATION= the DOFs are those of its local axes at each coupling node.
void kinematic_rows(BuildState& s, const RowOrigin& o, NodeId ref, const std::vector<NodeId>& nodes,
                    const std::vector<int>& dofs, const std::string& orientation = {}) {
  if (!orientation.empty()) {
    const Vec3& XR = s.model.mesh.coords[ref];
    int on_axis = 0;
    for (NodeId n : nodes) {
      if (n == ref) continue;
      const auto axes = coupling_axes(s, o, orientation, s.model.mesh.coords[n], true);
      if (!axes) { // no radial or tangential direction there: the node takes no part
        ++on_axis;
        continue;
      }
      const Eigen::Matrix3d& A = *axes;
      const Vec3 dv = sub(s.model.mesh.coords[n], XR);
      const Eigen::Vector3d d(dv[0], dv[1], dv[2]);
      for (int i = 1; i <= 3; ++i)
        if (contains(dofs, i))
          s.model.constraints.push_back(local_row(o, n, ref, 1, A.row(i - 1).transpose(), &d));
      for (int i = 4; i <= 6; ++i)
        if (contains(dofs, i)) {
          LinearConstraint c = local_row(o, n, ref, 4, A.row(i - 4).transpose(), nullptr);
          c.drop_if_missing = true;
          s.model.constraints.push_back(std::move(c));
        }
    }
    if (on_axis > 0)
      s.warn(o.loc, fmt::format("{}: {} coupling node(s) lie on the axis of the cylindrical "
                                "ORIENTATION={}, where its local directions are undefined; they "
                                "are left out of the coupling",
                                o.name, on_axis, orientation));
    return;
  }
  const SpaceDofs sd = space_dofs(s.model.space);
  const Vec3& XR = s.model.mesh.coords[ref];
  for (NodeId n : nodes) {
    if (n == ref) continue;
    const Vec3 d = sub(s.model.mesh.coords[n], XR);
    for (int i : sd.translations)
      if (contains(dofs, i))
        s.model.constraints.push_back(rigid_row(o, s.model.space, n, ref, i, d, false));
    for (int i : sd.rotations)
      if (contains(dofs, i)) {
        LinearConstraint c = equal_row(o, n, ref, i, false, true);
        c.drop_if_missing = true;
        s.model.constraints.push_back(std::move(c));
      }
  }
}

// ------------------------------------------------------------------ distributing coupling rows
enum class Weighting { Uniform, Linear, Quadratic, Cubic };

double weight_factor(Weighting w, double r, double r0) {
  const double x = r0 > 0 ? std::min(r / r0, 1.0) : 0.0;
  switch (w) {
  case Weighting::Uniform:
    return 1.0;
  case Weighting::Linear:
    return 1.0 - x;
  case Weighting::Quadratic:
    return 1.0 - x * x;
  case Weighting::Cubic:
    return 1.0 - 3.0 * x * x + 2.0 * x * x * x;
  }
  return 1.0;
}

/// The reference node moves with the coupling nodes "in an average sense" (Abaqus Theory Guide,
/// "Distributing coupling constraints"): with normalised weights w_n, centroid xbar = sum w_n x_n,
/// r_n = x_n - xbar and the arrangement inertia T = sum w_n (|r_n|^2 I - r_n r_n^T),
///   theta_R = T^-1 sum w_n r_n x u_n,   u_R = sum w_n u_n + theta_R x (x_R - xbar),
/// which is the constraint whose reaction distributes a force and moment at the reference node as
/// F_n = w_n (F_R + (T^-1 M^_R) x r_n). Translations are always constrained, rotations as given.
void distributing_rows(BuildState& s, const RowOrigin& o, const BuildState::CouplingDef& c,
                       Weighting method, double r0, const std::vector<int>& dofs) {
  const Mesh& mesh = s.model.mesh;
  const bool three_d = s.model.space == ModelSpace::ThreeD;
  const SpaceDofs sd = space_dofs(s.model.space);
  const Vec3& XR = mesh.coords[c.ref];
  std::vector<std::pair<NodeId, double>> w;
  double total = 0.0;
  for (const auto& [n, area] : c.nodes) {
    if (n == c.ref) continue;
    const double wn = area * weight_factor(method, norm(sub(mesh.coords[n], XR)), r0);
    if (wn <= 0.0) continue;
    w.emplace_back(n, wn);
    total += wn;
  }
  if (w.empty() || !(total > 0))
    throw InputError(o.loc, o.name,
                     "the distributing coupling has no coupling node with a positive weight; "
                     "check the surface and the influence radius");
  for (auto& [n, wn] : w) wn /= total;
  Vec3 xbar{};
  for (const auto& [n, wn] : w)
    for (int i = 0; i < 3; ++i) xbar[i] += wn * mesh.coords[n][i];
  const Vec3 rR = sub(XR, xbar);
  // rotation operator: theta = G u, G (3 x 3n) = T^-1 [w_n [r_n]x]
  Eigen::Matrix3d T = Eigen::Matrix3d::Zero();
  for (const auto& [n, wn] : w) {
    const Vec3 r = sub(mesh.coords[n], xbar);
    const Eigen::Vector3d rv(r[0], r[1], r[2]);
    T += wn * (rv.squaredNorm() * Eigen::Matrix3d::Identity() - rv * rv.transpose());
  }
  const bool need_rotation = norm(rR) > 1e-12 * std::max(1.0, s.model.model_size()) ||
                             std::any_of(sd.rotations.begin(), sd.rotations.end(),
                                         [&](int d) { return contains(dofs, d); });
  Eigen::Matrix3d Tinv = Eigen::Matrix3d::Zero();
  if (need_rotation) {
    if (three_d) {
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(T);
      const double lmax = eig.eigenvalues().maxCoeff();
      if (!(eig.eigenvalues().minCoeff() > 1e-10 * lmax))
        throw InputError(o.loc, o.name,
                         "the coupling nodes lie on one line (or are one point), so they do not "
                         "define the reference node's rotation about it; couple more nodes, put "
                         "the reference node on that line and release the rotations (DOFs 4-6)");
      Tinv = T.inverse();
    } else {
      if (!(T(2, 2) > 0))
        throw InputError(o.loc, o.name,
                         "the coupling nodes are one point, so they do not define the reference "
                         "node's rotation; couple more nodes or release DOF 6");
      Tinv(2, 2) = 1.0 / T(2, 2);
    }
  }
  // coefficients of theta_R (3 rows) on each coupling node translation: G_n = T^-1 w_n [r_n]x
  auto G = [&](const Vec3& r, double wn) {
    Eigen::Matrix3d rx;
    rx << 0, -r[2], r[1], r[2], 0, -r[0], -r[1], r[0], 0;
    return Eigen::Matrix3d(Tinv * (wn * rx));
  };
  const Eigen::Vector3d rRv(rR[0], rR[1], rR[2]);
  Eigen::Matrix3d rRx;
  rRx << 0, -rR[2], rR[1], rR[2], 0, -rR[0], -rR[1], rR[0], 0;
  // translation rows: u_R - sum_n [w_n I - [r_R]x G_n] u_n = 0  (theta x r_R = -[r_R]x theta)
  for (int i : sd.translations) {
    LinearConstraint row = new_row(o);
    row.eliminates = false;
    row.terms.push_back({c.ref, dof_of(i), 1.0, true});
    for (const auto& [n, wn] : w) {
      const Eigen::Matrix3d Gn = G(sub(mesh.coords[n], xbar), wn);
      const Eigen::Matrix3d A = wn * Eigen::Matrix3d::Identity() - rRx * Gn;
      for (int j : sd.translations) {
        const double a = A(i - 1, j - 1);
        if (std::abs(a) > 1e-14) row.terms.push_back({n, dof_of(j), -a, false});
      }
    }
    s.model.constraints.push_back(std::move(row));
  }
  // rotation rows along the global axes, or the local ones of ORIENTATION= at the reference node:
  // e . theta_R - e . (sum_n G_n u_n) = 0
  const Eigen::Matrix3d A = *coupling_axes(s, o, c.orientation, XR);
  for (int i : sd.rotations) {
    if (!contains(dofs, i)) continue;
    const Eigen::Vector3d e =
        three_d ? Eigen::Vector3d(A.row(i - 4).transpose()) : Eigen::Vector3d::Unit(i - 4);
    LinearConstraint row = new_row(o);
    row.eliminates = false;
    int big = 0;
    e.cwiseAbs().maxCoeff(&big);
    row.terms.push_back({c.ref, dof_of(4 + big), e[big], true});
    for (int j = 0; j < 3; ++j)
      if (j != big && std::abs(e[j]) > 1e-14)
        row.terms.push_back({c.ref, dof_of(4 + j), e[j], true});
    for (const auto& [n, wn] : w) {
      const Eigen::RowVector3d g = e.transpose() * G(sub(mesh.coords[n], xbar), wn);
      for (int j : sd.translations) {
        const double a = g[j - 1];
        if (std::abs(a) > 1e-14) row.terms.push_back({n, dof_of(j), -a, false});
      }
    }
    s.model.constraints.push_back(std::move(row));
  }
}

// ------------------------------------------------------------------ *MPC
enum class MpcType { Beam, Tie, Pin, Link };

void mpc_rows(BuildState& s, MpcType type, const SourceLocation& loc, NodeId a, NodeId b) {
  RowOrigin o{ConstraintKind::Mpc, "", loc, false};
  const SpaceDofs sd = space_dofs(s.model.space);
  const Vec3 d = sub(s.model.mesh.coords[a], s.model.mesh.coords[b]);
  switch (type) {
  case MpcType::Pin: // an MPC gives its nodes the DOFs it constrains (e.g. a node without elements)
    for (int i : sd.translations) s.model.constraints.push_back(equal_row(o, a, b, i, true, true));
    break;
  case MpcType::Tie: // every active DOF: the rows of DOFs the nodes do not both carry are dropped
    for (int i : {1, 2, 3, 4, 5, 6, 11}) {
      if (s.model.space != ModelSpace::ThreeD && (i == 3 || i == 4 || i == 5)) continue;
      LinearConstraint c = equal_row(o, a, b, i, false, false);
      c.drop_if_missing = true;
      s.model.constraints.push_back(std::move(c));
    }
    break;
  case MpcType::Beam:
    for (int i : sd.translations)
      s.model.constraints.push_back(rigid_row(o, s.model.space, a, b, i, d, true));
    for (int i : sd.rotations) s.model.constraints.push_back(equal_row(o, a, b, i, true, true));
    break;
  case MpcType::Link: {
    if (!(norm(d) > 0))
      throw InputError(loc, fmt::format("node {}", s.model.node_label(a)),
                       "the two nodes of an MPC LINK coincide, so the link has no direction; use "
                       "MPC PIN for coincident nodes");
    // (X_a - X_b) . (u_a - u_b) = 0, eliminating the largest component of node a
    const int dep = dominant_translation(s.model.space, d);
    LinearConstraint c = new_row(o);
    c.small_rotation = true; // a fixed distance is nonlinear in large displacements
    c.terms.push_back({a, dof_of(dep), d[dep - 1], true});
    for (int i : sd.translations)
      if (i != dep && d[i - 1] != 0.0) c.terms.push_back({a, dof_of(i), d[i - 1], true});
    for (int i : sd.translations)
      if (d[i - 1] != 0.0) c.terms.push_back({b, dof_of(i), -d[i - 1], true});
    s.model.constraints.push_back(std::move(c));
    break;
  }
  }
}

} // namespace

void handle_mpc(BuildState& s, const Keyword& kw) {
  if (kw.has("USER")) reject_param(kw, "USER", "user MPCs (MPC subroutines) are not available");
  if (kw.has("MODE") && enum_param(kw, "MODE", {"NODE", "DOF"}, 0) == 1)
    throw InputError(kw.loc, "MODE=DOF",
                     "gapfem reads MPCs in the default node mode (MODE=NODE); write the MPC "
                     "types BEAM, TIE, PIN or LINK with their nodes");
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    const std::string t = canonical(r.text(0));
    MpcType type{};
    if (t == "BEAM")
      type = MpcType::Beam;
    else if (t == "TIE")
      type = MpcType::Tie;
    else if (t == "PIN")
      type = MpcType::Pin;
    else if (t == "LINK")
      type = MpcType::Link;
    else
      r.fail(fmt::format("MPC type {}", r.text(0)),
             "this MPC type is not supported by gapfem; supported are BEAM, TIE, PIN and LINK "
             "(write others with *EQUATION)");
    r.at_most(3, "MPC type, first node (or set), second node (or set)");
    std::vector<NodeId> a = resolve_nodes(s, r, 1);
    std::vector<NodeId> b = resolve_nodes(s, r, 2);
    if (a.empty() || b.empty()) return;
    auto by_label = [&](std::vector<NodeId>& v) {
      std::sort(v.begin(), v.end(), [&](NodeId x, NodeId y) {
        return s.model.mesh.node_labels[x] < s.model.mesh.node_labels[y];
      });
    };
    by_label(a);
    by_label(b);
    if (b.size() != 1 && b.size() != a.size())
      r.fail(fmt::format("node set {}", r.text(2)),
             fmt::format("the second set must hold one node or as many as the first ({} vs {}); "
                         "the n-th nodes of the sets (by label) are joined",
                         b.size(), a.size()));
    const SourceLocation at = r.loc();
    for (std::size_t i = 0; i < a.size(); ++i) {
      const NodeId na = a[i], nb = b.size() == 1 ? b[0] : b[i];
      if (na == nb)
        r.fail(fmt::format("node {}", s.model.node_label(na)),
               "an MPC joins two different nodes; this node is both");
      s.deferred_constraints.push_back(
          {1, [type, at, na, nb](BuildState& st) { mpc_rows(st, type, at, na, nb); }});
    }
  });
}

void handle_kinematic_coupling(BuildState& s, const Keyword& kw) {
  const NodeId ref = param_node(s, kw, "REF NODE");
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(3, "node or node set, first DOF, last DOF");
    const std::vector<NodeId> nodes = resolve_nodes(s, r, 0);
    const std::vector<int> dofs = dof_range(r, 1);
    const RowOrigin o{ConstraintKind::KinematicCoupling,
                      fmt::format("kinematic coupling to node {}", s.model.node_label(ref)),
                      r.loc(), true};
    s.deferred_constraints.push_back(
        {1, [o, ref, nodes, dofs](BuildState& st) { kinematic_rows(st, o, ref, nodes, dofs); }});
  });
}

void handle_coupling(BuildState& s, const Keyword& kw) {
  // the block is open even when the coupling fails: its *KINEMATIC / *DISTRIBUTING are then
  // skipped without a second message
  s.couplings.emplace_back();
  s.couplings.back().failed = true;
  BuildState::CouplingDef c;
  c.name = name_param(kw, "CONSTRAINT NAME", true);
  c.orientation = name_param(kw, "ORIENTATION", false);
  c.loc = kw.loc;
  c.ref = param_node(s, kw, "REF NODE");
  const std::string surf = set_param(s, kw, "SURFACE", true);
  const auto it = s.model.surfaces.find(surf);
  if (it == s.model.surfaces.end())
    throw InputError(kw.loc, fmt::format("SURFACE={}", surf),
                     undefined_name(s, surf, NameKind::Surface, kw.name, "a surface",
                                    "define it with *SURFACE before the coupling"));
  const std::optional<double> radius = real_param(kw, "INFLUENCE RADIUS");
  if (radius && !(*radius > 0))
    throw InputError(kw.loc, param_text(kw, "INFLUENCE RADIUS"),
                     "the influence radius must be positive");
  c.radius = radius.value_or(0.0);
  // coupling nodes and their tributary areas (node-based surfaces: the given areas)
  std::map<NodeId, double> area;
  if (it->second.node_based)
    for (const auto& wn : it->second.nodes) area[wn.node] += wn.area;
  else
    for (const SurfaceFacet& f : surface_facets(s.model, it->second))
      add_tributary_areas(s.model, f, area);
  const Vec3& XR = s.model.mesh.coords[c.ref];
  for (const auto& [n, a] : area)
    if (!radius || norm(sub(s.model.mesh.coords[n], XR)) <= *radius) c.nodes.emplace_back(n, a);
  if (c.nodes.empty() && s.incomplete_surfaces.count(surf)) return; // reported at its elements
  if (c.nodes.empty())
    throw InputError(kw.loc, fmt::format("coupling {}", c.name),
                     radius ? "no node of the surface lies within the influence radius of the "
                              "reference node; raise INFLUENCE RADIUS"
                            : "the surface has no nodes");
  s.couplings.back() = std::move(c);
}

namespace {
/// The coupling the sub-option belongs to; nullptr when that *COUPLING failed (reported).
BuildState::CouplingDef* current_coupling(BuildState& s, const Keyword& kw) {
  if (s.couplings.empty()) return nullptr; // (the parser checks the parent block)
  BuildState::CouplingDef& c = s.couplings.back();
  if (c.failed) return nullptr;
  if (c.defined)
    throw InputError(kw.loc, fmt::format("coupling {}", c.name),
                     "the coupling already has its *KINEMATIC or *DISTRIBUTING; start another "
                     "*COUPLING for a second one");
  c.defined = true;
  return &c;
}
std::vector<int> all_dof_lines(BuildState& s, const Keyword& kw) {
  std::vector<int> dofs;
  bool any = false;
  for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    r.at_most(2, "first DOF, last DOF");
    for (int d : dof_range(r, 0))
      if (!contains(dofs, d)) dofs.push_back(d);
    any = true;
  });
  if (!any) dofs = {1, 2, 3, 4, 5, 6};
  return dofs;
}
} // namespace

void handle_kinematic(BuildState& s, const Keyword& kw) {
  const BuildState::CouplingDef* cp = current_coupling(s, kw);
  if (!cp) return;
  const BuildState::CouplingDef& c = *cp;
  const std::vector<int> dofs = all_dof_lines(s, kw);
  const RowOrigin o{ConstraintKind::Coupling, "coupling " + c.name, c.loc, true};
  std::vector<NodeId> nodes;
  for (const auto& [n, a] : c.nodes) nodes.push_back(n);
  const NodeId ref = c.ref;
  const std::string orientation = c.orientation;
  s.deferred_constraints.push_back({1, [o, ref, nodes, dofs, orientation](BuildState& st) {
                                      kinematic_rows(st, o, ref, nodes, dofs, orientation);
                                    }});
}

void handle_distributing(BuildState& s, const Keyword& kw) {
  const BuildState::CouplingDef* cp = current_coupling(s, kw);
  if (!cp) return;
  const BuildState::CouplingDef& c = *cp;
  const auto method = static_cast<Weighting>(
      enum_param(kw, "WEIGHTING METHOD", {"UNIFORM", "LINEAR", "QUADRATIC", "CUBIC"}, 0));
  if (enum_param(kw, "COUPLING", {"CONTINUUM", "STRUCTURAL"}, 0) == 1)
    throw InputError(kw.loc, "COUPLING=STRUCTURAL",
                     "structural distributing coupling (the coupling nodes' rotations take part) "
                     "is not available; use COUPLING=CONTINUUM (the default)");
  enum_param(kw, "ROTATIONAL COUPLING", {"CONTINUUM", "STRUCTURAL"}, 1); // no rotations at
  // coupling nodes of solids: both give the continuum form
  enum_param(kw, "FREE NODES", {"ALLOW", "ERROR", "REMOVE"}, 0);
  const std::vector<int> dofs = all_dof_lines(s, kw);
  const RowOrigin o{ConstraintKind::Coupling, "coupling " + c.name, c.loc, false};
  const BuildState::CouplingDef def = c;
  s.deferred_constraints.push_back({1, [o, def, method, dofs](BuildState& st) {
                                      // r0: the influence radius, else the farthest coupling node
                                      double r0 = def.radius;
                                      const Vec3& XR = st.model.mesh.coords[def.ref];
                                      if (!(r0 > 0))
                                        for (const auto& [n, a] : def.nodes)
                                          r0 = std::max(r0, norm(sub(st.model.mesh.coords[n], XR)));
                                      distributing_rows(st, o, def, method, r0, dofs);
                                    }});
}

} // namespace gapfem::inp
