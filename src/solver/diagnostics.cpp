#include "solver/diagnostics.hpp"

#include "fem/assembler.hpp"
#include "model/model.hpp"
#include "solver/step_problem.hpp"

#include <algorithm>
#include <deque>
#include <fmt/format.h>
#include <set>

namespace gapfem {
namespace {

/// Node or element keys, sorted by the caller, as the deck names them.
std::string list_labels(const Model& model, const std::vector<Label>& labels,
                        std::size_t max_count = 12) {
  std::string out;
  for (std::size_t i = 0; i < labels.size() && i < max_count; ++i)
    out += (i ? ", " : "") + model.label_of_key(labels[i]).str();
  if (labels.size() > max_count) out += fmt::format(", … ({} in all)", labels.size());
  return out;
}

/// The singular equations as the deck names them: their nodes, and "node 12 DOF 3, … (and n
/// more)".
struct SingularDofs {
  std::set<NodeId> nodes;
  std::string at;
};

SingularDofs singular_dofs(const Model& model, const DofMap& dofs, const EquationMap& eqm,
                           std::span<const LocalIndex> equations) {
  SingularDofs out;
  std::vector<std::string> where;
  for (LocalIndex eq : equations) {
    if (eq < 0 || eq >= eqm.n_eq()) continue;
    const LocalIndex s = eqm.eq_slot[eq];
    out.nodes.insert(dofs.slot_node(s));
    if (where.size() < 8)
      where.push_back(fmt::format("node {} DOF {}", model.node_label(dofs.slot_node(s)),
                                  abaqus_number(dofs.slot_dof(s))));
  }
  if (out.nodes.empty()) return out;
  out.at = where.front();
  for (std::size_t i = 1; i < where.size(); ++i) out.at += ", " + where[i];
  if (equations.size() > where.size())
    out.at += fmt::format(" (and {} more)", equations.size() - where.size());
  return out;
}

/// Rotations that only a constraint gives a node (MPC BEAM, couplings at solid nodes) and that
/// nothing holds, such as the rotation about the line of a BEAM MPC: every singular equation is
/// such a rotation.
bool only_orphan_rotations(const Mesh& mesh, const DofMap& dofs, const EquationMap& eqm,
                           const std::vector<std::vector<ElemId>>& node_elems,
                           std::span<const LocalIndex> equations) {
  return std::all_of(equations.begin(), equations.end(), [&](LocalIndex eq) {
    if (eq < 0 || eq >= eqm.n_eq()) return true;
    const LocalIndex s = eqm.eq_slot[eq];
    const int d = abaqus_number(dofs.slot_dof(s));
    if (d < 4 || d > 6) return false;
    for (ElemId e : node_elems[dofs.slot_node(s)]) {
      const ElementFamily f = element_info(mesh.elem_types[e]).family;
      if (f == ElementFamily::Beam || f == ElementFamily::Shell || f == ElementFamily::Spring)
        return false;
    }
    return true;
  });
}

/// The body around a node: nodes connected through elements (open gaps excluded) and through
/// the linear constraints that apply in the step; the open gaps met on its boundary.
struct Body {
  std::vector<Label> nodes; ///< sorted
  std::set<ElemId> open_gaps;
};

Body body_around(NodeId start, const Model& model, Discretization& disc, Assembler& assembler,
                 StepProblem& prob, const std::vector<std::vector<ElemId>>& node_elems) {
  const Mesh& mesh = model.mesh;
  const DofMap& dofs = disc.dofs();
  const ConstraintSet& cs = disc.constraints();
  std::vector<std::vector<int>> node_rows(static_cast<std::size_t>(mesh.n_nodes()));
  for (int r = 0; r < cs.n_rows(); ++r)
    if (cs.active(r))
      for (LocalIndex sl : cs.row_slots(r)) node_rows[dofs.slot_node(sl)].push_back(r);
  const FieldView fields = prob.fields();
  ElementRecovery rec;
  auto is_open_gap = [&](ElemId e) {
    if (element_info(mesh.elem_types[e]).family != ElementFamily::Gap) return false;
    assembler.recover(e, fields, prob.context(), rec);
    return rec.gap && rec.gap->status == ContactStatus::Open;
  };
  std::vector<char> in_body(static_cast<std::size_t>(mesh.n_nodes()), 0);
  auto reach = [&](std::deque<NodeId>& queue, NodeId m) {
    if (in_body[m]) return;
    in_body[m] = 1;
    queue.push_back(m);
  };
  Body body;
  std::deque<NodeId> queue{start};
  in_body[start] = 1;
  while (!queue.empty()) {
    const NodeId n = queue.front();
    queue.pop_front();
    body.nodes.push_back(model.node_label(n).key);
    for (int r : node_rows[n])
      for (LocalIndex sl : cs.row_slots(r)) reach(queue, dofs.slot_node(sl));
    for (ElemId e : node_elems[n]) {
      if (is_open_gap(e)) {
        body.open_gaps.insert(e);
        continue;
      }
      for (NodeId m : mesh.element_nodes(e)) reach(queue, m);
    }
  }
  std::sort(body.nodes.begin(), body.nodes.end());
  return body;
}

/// The reduced-integration element types at the singular nodes ("C3D20R, CPS8R"), whose
/// zero-energy modes are the other candidate.
std::string reduced_types_at(const Mesh& mesh, const std::set<NodeId>& nodes,
                             const std::vector<std::vector<ElemId>>& node_elems) {
  std::string reduced;
  for (NodeId n : nodes)
    for (ElemId e : node_elems[n]) {
      const ElementTypeInfo& info = element_info(mesh.elem_types[e]);
      if (!info_reduced(info) || reduced.find(info.name) != std::string::npos) continue;
      reduced += (reduced.empty() ? "" : ", ") + std::string(info.name);
    }
  return reduced;
}

/// The sentence for a body that is not held by open gaps: a free temperature level, a limit
/// load, zero-energy modes or a missing support.
std::string unheld_body_message(const Model& model, const SingularDofs& sing,
                                const std::vector<Label>& body, bool temperature, bool supported,
                                const std::vector<std::vector<ElemId>>& node_elems) {
  const std::string& at = sing.at;
  if (temperature)
    return fmt::format(
        "the system is singular at {}: nothing fixes the temperature level of the part made of "
        "nodes {} (in a steady-state step it exchanges no heat with its surroundings). Prescribe "
        "a temperature there (*BOUNDARY, DOF 11) or add a film condition (*FILM, *SFILM)",
        at, list_labels(model, body));
  if (supported)
    return fmt::format(
        "the stiffness became singular at {} in the course of the increment, although the model "
        "is supported (its stiffness at the last converged state is not singular): the part made "
        "of nodes {} has reached a limit load (collapse or snap-through under a prescribed load) "
        "or an element has been crushed flat. Reduce the load, apply it as a prescribed "
        "displacement (*BOUNDARY) to follow the response past the limit, or refine the mesh "
        "where it is crushed",
        at, list_labels(model, body));
  // reduced-integration elements at the singular DOFs (C3D20R has spurious modes that propagate
  // along a row one element wide)
  const std::string reduced = reduced_types_at(model.mesh, sing.nodes, node_elems);
  if (!reduced.empty())
    return fmt::format(
        "the system is singular at {}: the part made of nodes {} can move as a rigid body or "
        "mechanism in that direction, or its reduced-integration elements ({}) deform in a "
        "zero-energy mode (the 2x2x2 rule of C3D20R leaves modes that a row of elements one "
        "element across in two directions does not hold). Add boundary conditions (*BOUNDARY) if "
        "the part is free; "
        "otherwise use the fully integrated type (C3D20, CPS8, ...) or at least two elements "
        "across the section",
        at, list_labels(model, body), reduced);
  return fmt::format(
      "the system is singular at {}: the part made of nodes {} can move as a rigid body or "
      "mechanism in that direction. Add boundary conditions (*BOUNDARY) or elements that "
      "constrain it",
      at, list_labels(model, body));
}

} // namespace

std::string describe_singularity(const Model& model, Discretization& disc, Assembler& assembler,
                                 StepProblem& prob, std::span<const LocalIndex> equations,
                                 bool supported) {
  const DofMap& dofs = disc.dofs();
  const EquationMap& eqm = prob.equations();
  const SingularDofs sing = singular_dofs(model, dofs, eqm, equations);
  if (sing.nodes.empty()) return "the system of equations is singular";
  const Mesh& mesh = model.mesh;
  std::vector<std::vector<ElemId>> node_elems(static_cast<std::size_t>(mesh.n_nodes()));
  for (ElemId e = 0; e < mesh.n_elements(); ++e)
    for (NodeId n : mesh.element_nodes(e)) node_elems[n].push_back(e);
  if (only_orphan_rotations(mesh, dofs, eqm, node_elems, equations))
    return fmt::format(
        "the system is singular at {}: no element gives these nodes rotations; they have them "
        "only through a constraint (*MPC BEAM, *KINEMATIC COUPLING, *COUPLING), which leaves "
        "some rotation free (e.g. the rotation about the line of a BEAM MPC between solid "
        "nodes). Hold it with *BOUNDARY (node, DOF) or use an MPC that needs no rotations (PIN, "
        "TIE, LINK)",
        sing.at);
  // the body around the first singular node
  const Body body = body_around(*sing.nodes.begin(), model, disc, assembler, prob, node_elems);
  if (!body.open_gaps.empty()) {
    std::vector<Label> gaps;
    for (ElemId e : body.open_gaps) gaps.push_back(model.element_label(e).key);
    std::sort(gaps.begin(), gaps.end());
    return fmt::format(
        "the system is singular at {}: the body made of nodes {} is held only by open gap "
        "elements {}, so nothing resists its rigid-body motion. Remedies: start at least one of "
        "these gaps closed (d = 0), add a soft spring (SPRING1/SPRING2) from the body to ground, "
        "add *CONTACT DAMPING after *GAP, or stabilize the step (*STATIC, STABILIZE), so the "
        "body is held while the gaps close",
        sing.at, list_labels(model, body.nodes), list_labels(model, gaps));
  }
  const bool temperature = std::any_of(equations.begin(), equations.end(), [&](LocalIndex eq) {
    return eq >= 0 && eq < eqm.n_eq() && dofs.slot_is_temperature(eqm.eq_slot[eq]);
  });
  return unheld_body_message(model, sing, body.nodes, temperature, supported, node_elems);
}

std::string describe_chattering(const Model& model, std::span<const ElemId> elements) {
  std::vector<Label> labels;
  for (ElemId e : elements) labels.push_back(model.element_label(e).key);
  std::sort(labels.begin(), labels.end());
  return fmt::format("the contact status of gap element(s) {} keeps switching (open/closed or "
                     "stick/slip) within the increment; a smaller increment, a larger elastic "
                     "slip or *CONTACT DAMPING may let it settle",
                     list_labels(model, labels));
}

void AttemptLog::add(int increment, int attempt, std::string kind, std::string text,
                     bool structural) {
  if (structural) _structural = {kind, text, {increment}};
  _last_kind = kind;
  for (Entry& e : _entries)
    if (e.kind == kind) {
      e.text = std::move(text);
      e.attempts.push_back(attempt);
      return;
    }
  _entries.push_back({std::move(kind), std::move(text), {attempt}});
}

std::string AttemptLog::summary() const {
  std::string last, earlier;
  for (const Entry& e : _entries) {
    if (e.kind == _last_kind) {
      last = e.text;
      continue;
    }
    std::string attempts;
    for (std::size_t i = 0; i < e.attempts.size(); ++i)
      attempts += (i ? ", " : "") + std::to_string(e.attempts[i]);
    earlier += fmt::format("{}{} (attempt{} {})", earlier.empty() ? "" : "; ", e.text,
                           e.attempts.size() > 1 ? "s" : "", attempts);
  }
  std::string out = "Last problem: " + last;
  if (!earlier.empty()) out += ". Earlier attempts of this increment: " + earlier;
  const bool seen = std::any_of(_entries.begin(), _entries.end(),
                                [&](const Entry& e) { return e.kind == _structural.kind; });
  if (!_structural.kind.empty() && !seen)
    out += fmt::format(". Earlier in the step (increment {}): {}", _structural.attempts.front(),
                       _structural.text);
  return out;
}

} // namespace gapfem
