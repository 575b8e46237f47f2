// Linear constraints: *EQUATION, and the checks every constraint keyword shares (a DOF is the
// dependent DOF of one constraint only; a boundary condition on it is an error unless the
// constraint yields to it). The rows go to Model::constraints (model/constraints.hpp).
#include "io/inp/handlers.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>

namespace gapfem::inp {
namespace {

/// Nodes of a field in the order Abaqus pairs node sets in an equation: by label.
std::vector<NodeId> nodes_by_label(BuildState& s, const FieldReader& r, std::size_t field) {
  std::vector<NodeId> nodes = resolve_nodes(s, r, field);
  const auto& labels = s.model.mesh.node_labels;
  std::sort(nodes.begin(), nodes.end(), [&](NodeId a, NodeId b) { return labels[a] < labels[b]; });
  return nodes;
}

DofType equation_dof(const FieldReader& r, std::size_t field) {
  DofType d{};
  dof_from_abaqus(dof_number(r, field, "degree of freedom"), d);
  return d;
}

/// One term of an equation as written: the nodes (one, or a node set's), the DOF, coefficient.
struct TermSpec {
  std::vector<NodeId> nodes;
  DofType dof{};
  double coeff = 0.0;
  SourceLocation loc;
  std::string text;
};

/// Makes the equations of one *EQUATION block entry: one per node of the node sets.
void add_equations(BuildState& s, const std::vector<TermSpec>& terms) {
  std::size_t count = 1;
  for (const TermSpec& t : terms) {
    if (t.nodes.empty()) return; // a failed set (already reported)
    if (t.nodes.size() == 1) continue;
    if (count != 1 && t.nodes.size() != count)
      throw InputError(t.loc, fmt::format("term {}", t.text),
                       fmt::format("node set terms of one equation must hold the same number of "
                                   "nodes (this one has {}, another {}); the n-th equation uses "
                                   "the n-th node of every set, ordered by label",
                                   t.nodes.size(), count));
    count = t.nodes.size();
  }
  for (std::size_t i = 0; i < count; ++i) {
    LinearConstraint c;
    c.kind = ConstraintKind::Equation;
    c.local_dofs = true;
    c.loc = terms.front().loc; // the line of its dependent (first) term
    for (const TermSpec& t : terms) {
      c.term_loc.push_back(t.loc);
      const NodeId n = t.nodes.size() == 1 ? t.nodes[0] : t.nodes[i];
      for (const ConstraintTerm& prev : c.terms)
        if (prev.node == n && prev.dof == t.dof)
          throw InputError(t.loc, fmt::format("node {}", s.model.node_label(n)),
                           fmt::format("DOF {} appears twice in one equation; combine the two "
                                       "terms into one coefficient",
                                       abaqus_number(t.dof)));
      c.terms.push_back({n, t.dof, t.coeff});
    }
    s.model.constraints.push_back(std::move(c));
  }
}

} // namespace

void handle_equation(BuildState& s, const Keyword& kw) {
  // Data: a line with the number of terms N, then N terms (node or node set, DOF, coefficient),
  // at most four per line; then the next equation.
  std::size_t i = 0;
  const auto& lines = kw.data;
  while (i < lines.size()) {
    if (lines[i].empty()) {
      ++i;
      continue;
    }
    const FieldReader head = s.reader(kw, lines[i]);
    ++i;
    long long n = 0;
    try {
      head.at_most(1, "number of terms");
      n = head.integer(0, "number of terms", 1, 10000,
                       "{} terms is out of range: an equation has 1 to 10000 terms, and the first "
                       "line of each equation gives their number");
    } catch (const InputError& e) {
      s.diag.error(e);
      kw.mark_read(); // the rest of the block cannot be read reliably
      return;
    }
    std::vector<TermSpec> terms;
    try {
      while (static_cast<long long>(terms.size()) < n) {
        if (i >= lines.size())
          head.fail("equation",
                    fmt::format("the equation has {} terms but the data ends after {}; make the "
                                "first line the number of terms that follow (node, DOF, "
                                "coefficient; up to four terms per line)",
                                n, terms.size()));
        const DataLine& line = lines[i++];
        if (line.empty()) continue;
        const FieldReader r = s.reader(kw, line);
        if (r.size() % 3 != 0 || r.size() > 12)
          r.fail("terms", "write up to four terms per line, each as node (or node set), DOF, "
                          "coefficient");
        for (std::size_t f = 0; f < r.size(); f += 3) {
          if (static_cast<long long>(terms.size()) == n)
            r.fail("terms",
                   fmt::format("the equation has {} terms; this line holds more. Raise the "
                               "number of terms, or start the next equation with its "
                               "own line of the number of terms",
                               n));
          TermSpec t;
          t.nodes = nodes_by_label(s, r, f);
          t.dof = equation_dof(r, f + 1);
          t.coeff = r.real(f + 2, "coefficient");
          t.loc = r.loc();
          t.text = r.text(f);
          if (terms.empty() && t.coeff == 0.0)
            r.fail(fmt::format("field {} (coefficient)", f + 3),
                   "the first term's coefficient must not be zero: its DOF is the one the "
                   "equation eliminates");
          terms.push_back(std::move(t));
        }
      }
      add_equations(s, terms);
    } catch (const InputError& e) {
      s.diag.error(e);
    }
  }
}

namespace {
/// Rows in their small-rotation form are exact under NLGEOM only while the rotations they use
/// stay zero: every rotation term must be held at zero by a boundary condition of the step.
void check_nlgeom_rows(BuildState& s) {
  const Model& m = s.model;
  for (const Step& step : m.steps) {
    if (!step.nlgeom) continue;
    std::map<std::pair<NodeId, int>, bool> held; // (node, dof) -> prescribed to zero
    for (const BoundaryEntry& bc : step.boundary)
      held[{bc.node, static_cast<int>(bc.dof)}] = bc.value == 0.0 && !bc.fixed;
    for (const LinearConstraint& c : m.constraints) {
      if (!c.small_rotation) continue;
      bool exact = true, has_rotation = false; // an MPC LINK row has no rotation terms
      for (std::size_t k = 1; k < c.terms.size(); ++k) {
        const ConstraintTerm& t = c.terms[k];
        if (field_of(t.dof) != Field::Rotation) continue;
        has_rotation = true;
        const auto it = held.find({t.node, static_cast<int>(t.dof)});
        if (it == held.end() || !it->second) exact = false;
      }
      if (has_rotation && exact) continue;
      s.error(c.loc, c.name.empty() ? "" : c.name,
              fmt::format("step {} has NLGEOM, but this constraint is linear in the rotations "
                          "(its small-rotation form{}); gapfem does not have its large-rotation "
                          "form: run the step without NLGEOM, or hold the reference node's "
                          "rotations with *BOUNDARY (then the form is exact)",
                          step.number, has_rotation ? "" : ": MPC LINK keeps a distance"));
      return; // one message
    }
  }
}
} // namespace

void build_deferred_constraints(BuildState& s) {
  if (!s.model.node_transform.empty())
    s.model.node_transform.resize(static_cast<std::size_t>(s.model.mesh.n_nodes()), -1);
  std::stable_sort(s.deferred_constraints.begin(), s.deferred_constraints.end(),
                   [](const auto& a, const auto& b) { return a.order < b.order; });
  for (const auto& d : s.deferred_constraints) {
    try {
      d.build(s);
    } catch (const InputError& e) {
      s.diag.error(e);
    }
  }
  s.deferred_constraints.clear();
}

void handle_transform(BuildState& s, const Keyword& kw) {
  const std::string nset = set_param(s, kw, "NSET", true);
  const int type = enum_param(kw, "TYPE", {"R", "C", "S"}, 0);
  if (type == 2)
    throw InputError(kw.loc, "TYPE=S",
                     "spherical transforms are not available; use TYPE=R (rectangular) or TYPE=C "
                     "(cylindrical)");
  const std::vector<NodeId>* set = find_nset(s, nset);
  if (!set) {
    if (s.bad_sets.count(nset)) return;
    throw InputError(kw.loc, fmt::format("NSET={}", nset),
                     undefined_name(s, nset, NameKind::NodeSet, kw.name, "a node set",
                                    "define it with *NSET before *TRANSFORM"));
  }
  const std::vector<NodeId> members = *set;
  NodeTransform t;
  t.type = type == 0 ? NodeTransform::Type::Rectangular : NodeTransform::Type::Cylindrical;
  t.loc = kw.loc;
  bool read = false;
  const int failed = for_each_line(s, kw, [&](const DataLine& line) {
    const FieldReader r = s.reader(kw, line);
    if (read) r.fail("data", "a *TRANSFORM takes one data line");
    r.at_most(6, "a_x, a_y, a_z, b_x, b_y, b_z");
    for (int i = 0; i < 3; ++i) {
      t.a[i] = r.real(i, "coordinate of point a");
      t.b[i] = r.real(3 + i, "coordinate of point b");
    }
    read = true;
    // the system depends on a and b alone (a node on a cylinder's axis gets a direction)
    if (!local_axes(t, Vec3{}))
      r.fail(fmt::format("a = ({}, {}, {}), b = ({}, {}, {})", r.text(0), r.text(1), r.text(2),
                         r.text(3), r.text(4), r.text(5)),
             t.type == NodeTransform::Type::Cylindrical
                 ? "the two points of the cylindrical system's axis coincide; give two distinct "
                   "points on its axis"
             : t.a == Vec3{} ? "a is the origin, so it gives no local x direction; give a point "
                               "on the local x axis as a"
                             : "b lies on the line of a (or at the origin), so a and b span no "
                               "local x-y plane; give b in the local x-y plane, off the x axis");
  });
  if (failed > 0) return; // (reported)
  if (!read)
    throw InputError(kw.loc, "", "*TRANSFORM needs a data line: a_x, a_y, a_z, b_x, b_y, b_z");
  Model& m = s.model;
  if (m.node_transform.empty())
    m.node_transform.assign(static_cast<std::size_t>(m.mesh.n_nodes()), -1);
  m.node_transform.resize(static_cast<std::size_t>(m.mesh.n_nodes()), -1);
  const int index = static_cast<int>(m.transforms.size());
  for (NodeId n : members) {
    if (m.node_transform[n] >= 0)
      throw InputError(kw.loc, fmt::format("node {}", m.node_label(n)),
                       fmt::format("the node already has a local system (*TRANSFORM at {}); give "
                                   "each node one *TRANSFORM",
                                   m.transforms[m.node_transform[n]].loc.str()));
  }
  m.transforms.push_back(t);
  for (NodeId n : members) m.node_transform[n] = index;
  const std::vector<NodeId> nodes = members;
  s.deferred_constraints.push_back(
      {1, [nodes, t](BuildState& st) {
         if (st.model.space == ModelSpace::ThreeD) return;
         for (NodeId n : nodes) {
           const auto q = st.model.node_axes(n);
           if (q && std::abs(std::abs((*q)[8]) - 1.0) > 1e-12)
             throw InputError(t.loc, fmt::format("node {}", st.model.node_label(n)),
                              "in a planar or axisymmetric model the local system must keep the z "
                              "axis; give a and b in the x-y plane");
         }
       }});
}

namespace {
/// Nodes on the axis of a cylindrical *TRANSFORM have an arbitrary radial direction (CalculiX takes
/// one as well): allowed when nothing depends on it, i.e. local DOFs 1 and 2 (and 4 and 5) are held
/// together at zero or left free, carry no load and appear in no equation.
void check_axis_nodes(BuildState& s) {
  Model& m = s.model;
  if (m.transforms.empty()) return;
  auto on_axis = [&](NodeId n) {
    return n >= 0 && n < static_cast<NodeId>(m.node_transform.size()) && m.node_transform[n] >= 0 &&
           on_cylinder_axis(m.transforms[m.node_transform[n]], m.mesh.coords[n]);
  };
  auto pair_of = [](DofType d) -> int {
    const int k = abaqus_number(d);
    return k == 1 || k == 2 ? 0 : (k == 4 || k == 5 ? 1 : -1);
  };
  const std::string remedy =
      "the node lies on the axis of its cylindrical *TRANSFORM (at {}), where the radial and "
      "tangential directions are undefined; {}: hold local DOFs {} and {} together at zero, or "
      "give "
      "the node a rectangular *TRANSFORM of its own";
  auto fail = [&](const SourceLocation& loc, NodeId n, int pair, std::string_view what) {
    s.error(loc, fmt::format("node {}", m.node_label(n)),
            fmt::format(fmt::runtime(remedy), m.transforms[m.node_transform[n]].loc.str(), what,
                        pair == 0 ? 1 : 4, pair == 0 ? 2 : 5));
  };
  for (const Step& step : m.steps) {
    std::map<std::pair<NodeId, int>, std::array<const BoundaryEntry*, 2>> held;
    for (const BoundaryEntry& bc : step.boundary) {
      const int pr = pair_of(bc.dof);
      if (pr < 0 || !on_axis(bc.node)) continue;
      const int k = abaqus_number(bc.dof);
      held[{bc.node, pr}][(k - 1) % 3] = &bc;
    }
    for (const auto& [key, pair] : held) {
      const BoundaryEntry* one = pair[0] ? pair[0] : pair[1];
      if (!pair[0] || !pair[1])
        fail(one->loc, key.first, key.second, "a boundary condition on one of them depends on it");
      else if (pair[0]->value != 0.0 || pair[1]->value != 0.0)
        fail(one->loc, key.first, key.second, "a non-zero prescribed value depends on it");
    }
    for (const NodalLoad& ld : step.cloads)
      if (pair_of(ld.dof) >= 0 && ld.value != 0.0 && on_axis(ld.node))
        fail(ld.loc, ld.node, pair_of(ld.dof), "a load along them depends on it");
  }
  for (const LinearConstraint& lc : m.constraints) {
    if (!lc.local_dofs) continue;
    for (const ConstraintTerm& t : lc.terms)
      if (pair_of(t.dof) >= 0 && on_axis(t.node)) {
        fail(lc.loc, t.node, pair_of(t.dof), "an equation term along them depends on it");
        break;
      }
  }
}
} // namespace

void check_constraints(BuildState& s) {
  check_axis_nodes(s);
  Model& m = s.model;
  // the first row per dependent DOF (a DOF that is the dependent DOF of two constraints is an
  // error reported by the solver's constraint set, which knows which DOFs exist)
  std::map<std::pair<NodeId, int>, std::size_t> dependent;
  for (std::size_t c = 0; c < m.constraints.size(); ++c) {
    if (!m.constraints[c].eliminates) continue;
    const ConstraintTerm& t = m.constraints[c].terms.front();
    dependent.try_emplace({t.node, static_cast<int>(t.dof)}, c);
  }
  // boundary conditions on dependent DOFs
  std::map<std::size_t, int> yielded; // constraint → steps in which a BC holds its dependent DOF
  for (const Step& step : m.steps)
    for (const BoundaryEntry& bc : step.boundary) {
      const auto it = dependent.find({bc.node, static_cast<int>(bc.dof)});
      if (it == dependent.end()) continue;
      const LinearConstraint& lc = m.constraints[it->second];
      if (lc.yields_to_bc) {
        ++yielded[it->second];
        continue;
      }
      s.error(bc.loc, fmt::format("node {}", m.node_label(bc.node)),
              fmt::format(
                  "DOF {} has a boundary condition and is the dependent (first) DOF of the "
                  "constraint at {}; a constraint's dependent DOF cannot be prescribed: move the "
                  "boundary condition to another DOF of the constraint or reorder its "
                  "terms",
                  abaqus_number(bc.dof), lc.where()));
      dependent.erase(it); // one message per DOF
    }
  check_nlgeom_rows(s);
  std::map<std::string, std::pair<std::size_t, int>> per_constraint; // where -> (first row, DOFs)
  for (const auto& [c, n] : yielded) {
    auto& e = per_constraint.try_emplace(m.constraints[c].where(), c, 0).first->second;
    ++e.second;
  }
  for (const auto& [where, e] : per_constraint) {
    const LinearConstraint& lc = m.constraints[e.first];
    s.warn(lc.loc, fmt::format("{}{} constrained DOF(s) also have boundary conditions; in those "
                               "steps the boundary condition holds the node and the constraint is "
                               "not applied to that DOF",
                               lc.name.empty() ? "" : lc.name + ": ", e.second));
  }
}

} // namespace gapfem::inp
