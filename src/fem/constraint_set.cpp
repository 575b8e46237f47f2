#include "fem/constraint_set.hpp"

#include "common/error.hpp"
#include "fem/dof_map.hpp"
#include "model/model.hpp"

#include <cmath>
#include <fmt/format.h>
#include <map>

namespace gapfem {

ConstraintSet::ConstraintSet(const Model& model, const DofMap& dofs) {
  std::map<LocalIndex, int> dependent; // dependent slot -> constraint
  for (std::size_t c = 0; c < model.constraints.size(); ++c) {
    const LinearConstraint& lc = model.constraints[c];
    const auto start = _slot.size();
    bool dropped = false;
    for (const ConstraintTerm& t : lc.terms) {
      const LocalIndex s = dofs.slot(t.node, t.dof);
      if (s < 0 && lc.drop_if_missing) {
        dropped = true;
        break;
      }
      if (s < 0)
        throw InputError(lc.loc, lc.entity(model.node_label(t.node).str()),
                         fmt::format("no element at this node has DOF {}, so the constraint "
                                     "cannot act on it; constrain a DOF the node's elements use",
                                     abaqus_number(t.dof)));
      _slot.push_back(s);
      _coeff.push_back(t.coeff);
    }
    if (dropped) {
      _slot.resize(start);
      _coeff.resize(start);
      continue;
    }
    // a DOF is the dependent DOF of one constraint only (Abaqus eliminates it once)
    const auto [it, fresh] = lc.eliminates
                                 ? dependent.try_emplace(_slot[start], static_cast<int>(c))
                                 : std::pair{dependent.end(), true};
    if (!fresh) {
      const LinearConstraint& other = model.constraints[it->second];
      const ConstraintTerm& t = lc.terms.front();
      throw InputError(lc.loc, lc.entity(model.node_label(t.node).str()),
                       fmt::format("DOF {} is already the dependent DOF of the constraint at {}; a "
                                   "DOF can be the dependent (first) DOF of one constraint only: "
                                   "remove one of them or reorder the terms",
                                   abaqus_number(t.dof), other.where()));
    }
    _ptr.push_back(static_cast<LocalIndex>(_slot.size()));
    _value.push_back(0.0);
    _source.push_back(static_cast<int>(c));
  }
  _eq.assign(_slot.size(), -1);
  _active.assign(_value.size(), 0);
  mult_committed.assign(_value.size(), 0.0);
  mult_trial = mult_committed;
}

void ConstraintSet::set_equations(const Model& model, const EquationMap& eqmap) {
  for (std::size_t k = 0; k < _slot.size(); ++k) _eq[k] = eqmap.slot_eq[_slot[k]];
  for (int r = 0; r < n_rows(); ++r) {
    const LinearConstraint& lc = model.constraints[_source[r]];
    const bool dependent_free = _eq[_ptr[r]] >= 0 || !lc.eliminates;
    if (!dependent_free && !lc.yields_to_bc) {
      const ConstraintTerm& t = lc.terms.front();
      throw InputError(lc.loc, lc.entity(model.node_label(t.node).str()),
                       fmt::format("DOF {} is the constraint's dependent DOF and also has a "
                                   "boundary condition; remove one of them",
                                   abaqus_number(t.dof)));
    }
    _active[r] = dependent_free ? 1 : 0;
    if (!dependent_free) mult_committed[r] = mult_trial[r] = 0.0;
  }
}

void ConstraintSet::assemble(std::span<const double> u, std::span<double> f_int, ConstraintBlock* C,
                             std::int64_t first_multiplier, const DofMap& dofs,
                             std::array<double, kNumFields>& flux_sum,
                             std::array<long, kNumFields>& flux_count) const {
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
    if (C) C->add_row(row_eqs(r), coeffs, g, first_multiplier + r);
  }
}

} // namespace gapfem
