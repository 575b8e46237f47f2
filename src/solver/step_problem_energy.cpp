// The energies of the step problem (results.hpp, Energies; docs/theory/dynamics.md, "Energies"):
// each force's work by the trapezoidal rule over the increment, W += 1/2 (f_n + f_n+1) . du, which
// the trapezoidal rule of time integration makes exact (M a's work then equals the change of 1/2
// v.M v, so ETOTAL stays constant to the Newton tolerance); the kinetic energy 1/2 v.M v at each
// commit.
#include "fem/constraint_set.hpp"
#include "solver/step_problem.hpp"

namespace gapfem {

void StepProblem::account_energies() {
  _etotal_before = _s.energies().etotal();
  const std::size_t n = _s.u.size();
  for (auto* f : {&_s.f_elem_start, &_s.f_damp_start, &_s.f_ext_start, &_s.f_other_start})
    if (f->size() != n) f->assign(n, 0.0);
  // a dynamic step's evaluation gave M a, C v and M v alone (StepProblem::evaluate)
  const bool dynamic = !_s.r_start.empty() && _ctx.rates.defined() && _inertia.size() == n &&
                       _damping_forces.size() == n && _momentum.size() == n;
  const double wh = dynamic ? _integrator->history_weight() : 0.0;
  const double wi = dynamic ? _integrator->inertia_weight() : 1.0;
  const auto prescribed = _loads.prescribed();
  const bool rates = _s.v.size() == n;
  std::vector<std::uint8_t> held;
  const std::vector<double> f_bc = local_bc_forces(held);
  double ke = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double du = _s.u[k] - _s.u_start[k];
    const double fs = _f_stab.empty() ? 0.0 : _f_stab[k];
    double fe = _s.f_int[k] - fs; // the element forces (all of f_int but stabilization)
    double fi = 0.0, fd = 0.0;
    if (dynamic) { // f_int = wi M a + I + C v + HHT's history (+ stabilization)
      fi = _inertia[k];
      fd = _damping_forces[k];
      fe -= wi * fi + fd + wh * _s.r_start[k];
      if (rates) ke += 0.5 * _s.v[k] * _momentum[k];
    }
    const double fx = _s.f_ext[k];
    // a slot a boundary condition in a local system holds is a prescribed one for the books: its
    // row's force is the reaction (ALLWK), not an element's
    const bool local = !held.empty() && held[k];
    if (local) fe -= f_bc[k];
    const bool fixed = local || (k < prescribed.size() && prescribed[k]);
    // a prescribed slot's reaction (the physical forces there), a free slot's constraint forces
    const double other = fixed ? fi + fe + fd - fx : fx - _s.f_int[k];
    _s.allie += 0.5 * (_s.f_elem_start[k] + fe) * du;
    _s.allsd += fs * du;
    _s.allvd += 0.5 * (_s.f_damp_start[k] + fd) * du;
    _s.allwk += 0.5 * (_s.f_ext_start[k] + fx) * du;
    (fixed ? _s.allwk : _s.allcw) += 0.5 * (_s.f_other_start[k] + other) * du;
    _s.f_elem_start[k] = fe;
    _s.f_damp_start[k] = fd;
    _s.f_ext_start[k] = fx;
    _s.f_other_start[k] = other;
  }
  _s.allke = ke;
}

std::vector<double> StepProblem::local_bc_forces(std::vector<std::uint8_t>& held) const {
  const ConstraintSet& rows = _disc.constraints();
  std::vector<double> f;
  held.clear();
  for (const auto& [node, dof] : _loads.local_bcs()) {
    const int r = rows.bc_row(node, dof);
    if (r < 0 || !rows.active(r)) continue;
    if (f.empty()) {
      f.assign(_s.u.size(), 0.0);
      held.assign(_s.u.size(), 0);
    }
    const auto slots = rows.row_slots(r);
    const auto coeffs = rows.row_coeffs(r);
    for (std::size_t k = 0; k < slots.size(); ++k) {
      f[slots[k]] += coeffs[k] * rows.mult_trial[static_cast<std::size_t>(r)];
      held[slots[k]] = 1;
    }
  }
  return f;
}

void StepProblem::reset_energy_start_forces(std::span<const double> v_before) {
  const std::size_t n = _s.u.size();
  if (_s.f_other_start.size() != n || _s.f_damp_start.size() != n) return; // no increment yet
  std::vector<double> f(n), Ma(n, 0.0), Cv(n, 0.0);
  FieldView fv = fields();
  fv.v_start = v_before; // the damping forces the accelerations were solved with
  assemble_at_rates(fv, OperatorWeights{1.0, 1.0, 1.0, 1.0}, f, Ma, Cv);
  const auto prescribed = _loads.prescribed();
  std::vector<std::uint8_t> held;
  const std::vector<double> f_bc = local_bc_forces(held);
  for (std::size_t k = 0; k < n; ++k) {
    const bool fixed = k < prescribed.size() && prescribed[k];
    const double fx = _s.f_ext[k];
    const bool local = !held.empty() && held[k];
    _s.f_elem_start[k] = f[k] - Ma[k] - Cv[k] - (local ? f_bc[k] : 0.0);
    _s.f_damp_start[k] = Cv[k];
    _s.f_other_start[k] = fixed || local ? f[k] - (local ? f_bc[k] : 0.0) - fx : fx - f[k];
  }
}

} // namespace gapfem
