#include "fem/constraint_set.hpp"

#include "common/error.hpp"
#include "fem/dof_map.hpp"
#include "model/model.hpp"

#include <cmath>
#include <fmt/format.h>
#include <map>
#include <set>

namespace gapfem {

namespace {

/// The sentence for a DOF that two constraints make dependent: what it means for the keywords
/// that made them (a tie's slave node, a coupling's node, an equation's first term).
std::string dependent_twice(const LinearConstraint& lc, const LinearConstraint& other, int dof) {
  const bool tie = lc.kind == ConstraintKind::Tie && other.kind == ConstraintKind::Tie;
  if (tie)
    return fmt::format("DOF {} of this slave node is already tied by {}; a node can be the slave "
                       "of one tie only: remove one of the ties, or take the node out of one "
                       "slave surface",
                       dof, other.where());
  const bool equations = lc.kind != ConstraintKind::Tie && other.kind != ConstraintKind::Tie &&
                         lc.kind != ConstraintKind::Coupling &&
                         other.kind != ConstraintKind::Coupling &&
                         lc.kind != ConstraintKind::KinematicCoupling &&
                         other.kind != ConstraintKind::KinematicCoupling;
  return fmt::format("DOF {} is already the dependent DOF of the constraint at {}; a DOF can be "
                     "the dependent (first) DOF of one constraint only: {}",
                     dof, other.where(),
                     equations ? "remove one of them, or write one of them with another DOF as "
                                 "its first term"
                               : "remove one of them");
}

/// The global DOFs (slots) and coefficients of c u(node, dof): one slot, or for a DOF of a node
/// with a *TRANSFORM (terms written in its local system) the three global components.
bool expand_term(const Model& model, const DofMap& dofs, const ConstraintTerm& t, bool local,
                 std::vector<LocalIndex>& slots, std::vector<double>& coeffs) {
  const int d = static_cast<int>(t.dof);
  if (local && d < 6) {
    if (const auto Q = model.node_axes(t.node)) {
      const int base = d < 3 ? 0 : 3, row = d - base;
      for (int j = 0; j < 3; ++j) {
        const double q = (*Q)[3 * row + j];
        if (std::abs(q) < 1e-15) continue;
        const LocalIndex s = dofs.slot(t.node, static_cast<DofType>(base + j));
        if (s < 0) return false;
        slots.push_back(s);
        coeffs.push_back(t.coeff * q);
      }
      return true;
    }
  }
  const LocalIndex s = dofs.slot(t.node, t.dof);
  if (s < 0) return false;
  slots.push_back(s);
  coeffs.push_back(t.coeff);
  return true;
}
} // namespace

ConstraintSet::ConstraintSet(const Model& model, const DofMap& dofs) {
  std::map<std::pair<NodeId, int>, int> dependent; // dependent DOF -> constraint
  for (std::size_t c = 0; c < model.constraints.size(); ++c) {
    const LinearConstraint& lc = model.constraints[c];
    const auto start = _slot.size();
    bool dropped = false;
    for (std::size_t k = 0; k < lc.terms.size(); ++k) {
      const ConstraintTerm& t = lc.terms[k];
      if (expand_term(model, dofs, t, lc.local_dofs, _slot, _coeff)) continue;
      if (lc.drop_if_missing) {
        dropped = true;
        break;
      }
      throw InputError(lc.loc_of(k), lc.entity(model.node_label(t.node).str()),
                       fmt::format("no element at this node has DOF {}, so the constraint "
                                   "cannot act on it; constrain a DOF the node's elements use",
                                   abaqus_number(t.dof)));
    }
    if (dropped || _slot.size() == start) {
      _slot.resize(start);
      _coeff.resize(start);
      continue;
    }
    // a DOF is the dependent DOF of one constraint only (Abaqus eliminates it once)
    const ConstraintTerm& t = lc.terms.front();
    const auto [it, fresh] =
        lc.eliminates
            ? dependent.try_emplace({t.node, static_cast<int>(t.dof)}, static_cast<int>(c))
            : std::pair{dependent.end(), true};
    if (!fresh) {
      const LinearConstraint& other = model.constraints[it->second];
      throw InputError(lc.loc_of(0), lc.entity(model.node_label(t.node).str()),
                       dependent_twice(lc, other, abaqus_number(t.dof)));
    }
    _ptr.push_back(static_cast<LocalIndex>(_slot.size()));
    _value.push_back(0.0);
    _source.push_back(static_cast<int>(c));
  }
  // boundary conditions in local systems: e_d . u(node) = value, one potential row per local DOF
  for (NodeId n = 0; n < static_cast<NodeId>(model.node_transform.size()); ++n) {
    const auto Q = model.node_axes(n);
    if (!Q) continue;
    for (int base : {0, 3})
      for (int d = 0; d < 3; ++d) {
        // the row of local DOF d uses the global DOFs of its group the node carries; a row that
        // would need a DOF the node lacks (local 3 of a planar node) does not exist
        const auto start = _slot.size();
        bool representable = true;
        for (int j = 0; j < 3; ++j) {
          const double c = (*Q)[3 * d + j];
          if (std::abs(c) < 1e-15) continue;
          const LocalIndex sl = dofs.slot(n, static_cast<DofType>(base + j));
          if (sl < 0) {
            representable = false;
            break;
          }
          _slot.push_back(sl);
          _coeff.push_back(c);
        }
        if (!representable || _slot.size() == start) {
          _slot.resize(start);
          _coeff.resize(start);
          continue;
        }
        _ptr.push_back(static_cast<LocalIndex>(_slot.size()));
        _value.push_back(0.0);
        _source.push_back(-1);
        _bc_row[{n, base + d + 1}] = n_rows() - 1;
      }
  }
  _eq.assign(_slot.size(), -1);
  _active.assign(_value.size(), 0);
  mult_committed.assign(_value.size(), 0.0);
  mult_trial = mult_committed;
}

int ConstraintSet::bc_row(NodeId node, int dof) const {
  const auto it = _bc_row.find({node, dof});
  return it == _bc_row.end() ? -1 : it->second;
}

void ConstraintSet::set_equations(const Model& model, const EquationMap& eqmap,
                                  std::span<const std::pair<NodeId, int>> local_bcs) {
  for (std::size_t k = 0; k < _slot.size(); ++k) _eq[k] = eqmap.slot_eq[_slot[k]];
  std::vector<std::uint8_t> bc_active(_value.size(), 0);
  std::set<NodeId> held_nodes;
  for (const auto& [n, d] : local_bcs) {
    held_nodes.insert(n);
    const int r = bc_row(n, d);
    FE_CHECK(r >= 0, "boundary condition in a local system without its row");
    bc_active[r] = 1;
  }
  for (int r = 0; r < n_rows(); ++r) {
    bool on = true;
    if (_source[r] < 0) {
      on = bc_active[r] != 0;
    } else {
      const LinearConstraint& lc = model.constraints[_source[r]];
      on = _eq[_ptr[r]] >= 0 || !lc.eliminates;
      // a tie or coupling at a node held in its local system yields to those conditions too
      if (on && lc.yields_to_bc && held_nodes.count(lc.terms.front().node)) on = false;
      if (!on && !lc.yields_to_bc) {
        const ConstraintTerm& t = lc.terms.front();
        throw InputError(lc.loc, lc.entity(model.node_label(t.node).str()),
                         fmt::format("DOF {} is the constraint's dependent DOF and also has a "
                                     "boundary condition; remove one of them",
                                     abaqus_number(t.dof)));
      }
    }
    _active[r] = on ? 1 : 0;
    if (!on) mult_committed[r] = mult_trial[r] = 0.0;
  }
}

void ConstraintSet::assemble(std::span<const double> u, std::span<double> f_int, ConstraintBlock* C,
                             std::int64_t first_multiplier, const DofMap& dofs,
                             std::array<double, kNumFields>& flux_sum,
                             std::array<long, kNumFields>& flux_count,
                             const ConstraintBlock::GivenFields& given) const {
  for (int r = 0; r < n_rows(); ++r) {
    if (!_active[r]) continue;
    const auto slots = row_slots(r);
    const auto coeffs = row_coeffs(r);
    const double lambda = mult_trial[r];
    double g = -_value[r];
    for (std::size_t k = 0; k < slots.size(); ++k) {
      g += coeffs[k] * u[slots[k]];
      const double f = coeffs[k] * lambda;
      if (f == 0.0) continue;
      f_int[slots[k]] += f;
      const int fld = static_cast<int>(dofs.slot_field(slots[k]));
      flux_sum[fld] += std::abs(f);
      ++flux_count[fld];
    }
    if (C && C->add_row(row_eqs(r), coeffs, g, first_multiplier + r) && !given.v.empty()) {
      C->add_given(row_eqs(r), slots, coeffs, given); // dynamic: prescribed rates
      if (!_rate.empty()) { // the right-hand side's own rates: C v - rate_v = 0
        C->given_v.back() -= _rate[2 * static_cast<std::size_t>(r)];
        C->given_a.back() -= _rate[2 * static_cast<std::size_t>(r) + 1];
      }
    }
  }
}

} // namespace gapfem
