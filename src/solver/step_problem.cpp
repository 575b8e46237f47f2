#include "solver/step_problem.hpp"

#include "model/model.hpp"

#include <algorithm>
#include <cmath>

namespace gapfem {

StepProblem::StepProblem(Discretization& disc, Assembler& assembler, const StepLoads& loads,
                         SolutionState& state, const StepContext& base,
                         std::shared_ptr<const SparsityPattern> pattern)
    : _disc(disc), _asm(assembler), _loads(loads), _s(state), _ctx(base),
      _integrator(make_time_integrator(base)), _K(std::move(pattern)), _Kin(_K),
      _rhs(static_cast<std::size_t>(loads.equations().n_eq()), 0.0),
      _constraint_tol(1e-10 * base.model_size) {}

void StepProblem::set_unsymmetric_loads(bool on) {
  _unsymmetric_loads = on;
}

void StepProblem::set_integrator(std::unique_ptr<TimeIntegrator> integrator) {
  _integrator = std::move(integrator);
}

void StepProblem::begin_rates(double dt) {
  _pseudo_time.begin_increment(dt);
  _ctx.rates = {};
  _weights = {};
  if (_integrator) {
    _integrator->begin_increment(dt);
    _ctx.rates = _integrator->coefficients();
    _weights = _integrator->weights();
  }
  if (_integrator && _integrator->needs_rate_history()) {
    const std::size_t n = _s.u.size();
    for (auto* r : {&_s.v, &_s.a, &_s.v_start, &_s.a_start})
      if (r->size() != n) r->assign(n, 0.0);
  } else {
    for (auto* r : {&_s.v, &_s.a, &_s.v_start, &_s.a_start}) r->clear();
  }
  if (!_integrator || !_integrator->second_order()) { // no inertia: no dynamic history
    _s.r_start.clear();
    _s.r_prev.clear();
    _f_dyn.clear();
  }
}

void StepProblem::begin_increment(double t0, double dt, int increment,
                                  std::span<const double> guess) {
  _ctx.increment = increment;
  _ctx.dt = dt;
  const OperatorWeights before = _weights;
  begin_rates(dt);
  // the same effective operators as the increment before (a dynamic step at an unchanged size):
  // Newton may keep the factor from the start (NonlinearProblem::operators_as_before)
  _operators_as_before = dt > 0.0 && _integrator && _integrator->second_order() &&
                         !_s.r_start.empty() && before == _weights;
  _ctx.step_time = t0 + dt;
  _ctx.total_time = _s.total_time + t0 + dt;
  std::copy(_s.u_start.begin(), _s.u_start.end(), _s.u.begin());
  FE_CHECK(guess.empty() || guess.size() == _s.u.size(), "guessed increment of the wrong size");
  if (!guess.empty()) // prescribed slots take their values below
    for (std::size_t k = 0; k < guess.size(); ++k) _s.u[k] += guess[k];
  _disc.reset_trial();
  _trial_saved = false;
  _loads.apply_prescribed(_ctx.step_time, _s.u);
  _loads.apply_prescribed_motion(t0, _ctx.step_time, _s.u_start, _s.v_start, _s.u);
  if (!_s.v.empty() && _loads.has_motion()) { // the elements see the prescribed trial rates
    if (_rate_given.size() != _s.u.size()) {
      _rate_given.assign(_s.u.size(), 0);
      _loads.mark_motion(_rate_given);
    }
    _loads.prescribed_rates(t0, _ctx.step_time, _s.v_start, _s.v, _s.a);
  }
  _loads.apply_local_bcs(t0, _ctx.step_time, _s.u_start, _s.v_start, _s.a_start,
                         _disc.constraints());
  if (_loads.has_temperature_field()) _loads.temperatures(_ctx.step_time, _s.T);
  if (_loads.has_temperature_gradients()) {
    _s.G.resize(2 * _s.T.size());
    _loads.temperature_gradients(_ctx.step_time, _s.G);
  } else {
    _s.G.clear();
  }
  _loads.interference(_ctx.step_time, _disc);
}

void StepProblem::set_stabilization(std::shared_ptr<const std::vector<double>> mass, double c) {
  _stab_mass = std::move(mass);
  _stab_c = _stab_mass ? c : 0.0;
  if (_stab_c <= 0.0) _f_stab.clear();
}

void StepProblem::commit() {
  // the trial rates of the converged increment (they become the committed below)
  if (!_s.v_start.empty()) _integrator->rates(_s.u, _s.u_start, _s.v_start, _s.a_start, _s.v, _s.a);
  _loads.prescribed_rates(_ctx.step_time - _ctx.dt, _ctx.step_time, _s.v_start, _s.v, _s.a);
  _loads.prescribed_local_rates(_ctx.step_time - _ctx.dt, _ctx.step_time, _s.v_start, _s.v, _s.a);
  account_energies();
  if (!_s.r_start.empty() && _ctx.rates.defined()) commit_rate_history();
  if (!_s.v_start.empty()) {
    _s.v_start = _s.v;
    _s.a_start = _s.a;
  }
  _s.u_start = _s.u;
  _s.T_start = _s.T;
  _s.v_damp.clear();
  _disc.commit();
}

FieldView StepProblem::fields() const {
  FieldView f;
  f.u = _s.u;
  f.u_start = _s.u_start;
  f.v_start = _s.v_start;
  f.a_start = _s.a_start;
  if (!_rate_given.empty() && !_s.v.empty()) {
    f.rate_given = _rate_given;
    f.v_given = _s.v;
    f.a_given = _s.a;
  }
  if (_loads.has_temperature_field()) {
    f.temperature = _s.T;
    f.temperature_start = _s.T_start;
    f.initial_temperature = _s.T_initial;
    f.temperature_gradient = _s.G;
  }
  return f;
}

Evaluation StepProblem::assemble_tangent() {
  FE_CHECK(_trial_saved, "assemble_tangent without an evaluation of the residual alone");
  _disc.restore_trial(_trial_before);
  return evaluate(true);
}

Evaluation StepProblem::evaluate(bool tangent) {
  ScopedTimer timer(_stats, TimeCategory::Assembly);
  _trial_saved = !tangent;
  if (!tangent) _disc.save_trial(_trial_before);
  if (_stats) {
    ++_stats->evaluations;
    if (tangent) ++_stats->tangent_assemblies;
  }
  const FieldView f = fields();
  MatrixInserter* K = tangent ? &_Kin : nullptr;
  const bool history = !_s.r_start.empty() && _ctx.rates.defined();
  RateForces rate_forces;
  if (history) {
    for (auto* v : {&_inertia, &_damping_forces, &_momentum}) v->resize(_s.u.size());
    rate_forces = {_inertia, _damping_forces, _momentum};
  }
  AssemblyResult ar = _asm.assemble(f, _ctx, _s.f_int, K, &_C, _weights, rate_forces);
  if (history) add_rate_history();
  if (_stats) { // gap elements are reported as "gap work", not assembly
    (*_stats)[TimeCategory::GapWork] += ar.gap_seconds;
    (*_stats)[TimeCategory::Assembly] -= ar.gap_seconds;
  }
  add_stabilization(ar, tangent);
  std::fill(_s.f_ext.begin(), _s.f_ext.end(), 0.0);
  _loads.add_nodal_loads(_ctx.step_time, _s.f_ext);
  _loads.distributed_loads(_ctx.step_time, _active);
  bool follower = false;
  if (!_active.empty()) {
    // load stiffness belongs to K: none when K's weight is 0 (M alone)
    _asm.assemble_loads(_active, f, _ctx, _s.f_ext, _weights.k != 0.0 ? K : nullptr,
                        !_unsymmetric_loads);
    for (const auto& a : _active)
      follower |= _unsymmetric_loads && _ctx.nlgeom &&
                  (a.load->kind == DistLoadKind::Pressure ||
                   (a.load->kind == DistLoadKind::LineLoad && a.load->face > 0));
  }
  Evaluation ev;
  ev.status_changes = ar.status_changes;
  ev.branch_changes = ar.branch_changes;
  ev.stiffness_changed = ar.stiffness_changed;
  ev.changed = std::move(ar.changed);
  ev.symmetric = !ar.unsymmetric && !follower;
  ev.friction = ar.friction;
  ev.dt_ratio = ar.dt_ratio;
  ev.tangent = tangent;
  const DofMap& dofs = _disc.dofs();
  const EquationMap& eqm = _loads.equations();
  for (LocalIndex i = 0; i < eqm.n_eq(); ++i) {
    const LocalIndex s = eqm.eq_slot[i];
    const double r = _s.f_int[s] - _s.f_ext[s];
    _rhs[i] = -r;
    const int fld = static_cast<int>(dofs.slot_field(s));
    ev.has_field[fld] = true;
    if (std::abs(r) > ev.residual_max[fld]) {
      ev.residual_max[fld] = std::abs(r);
      ev.residual_eq[fld] = i;
    }
  }
  std::array<double, kNumFields> sum = ar.flux_sum;
  std::array<long, kNumFields> cnt = ar.flux_count;
  for (LocalIndex s = 0; s < dofs.n_slots(); ++s)
    if (_s.f_ext[s] != 0.0) {
      const int fld = static_cast<int>(dofs.slot_field(s));
      sum[fld] += std::abs(_s.f_ext[s]);
      ++cnt[fld];
    }
  for (int fld = 0; fld < kNumFields; ++fld)
    ev.flux[fld] = cnt[fld] > 0 ? sum[fld] / cnt[fld] : 0.0;
  for (double g : _C.g) ev.constraint_max = std::max(ev.constraint_max, std::abs(g));
  return ev;
}

void StepProblem::add_stabilization(AssemblyResult& ar, bool tangent) {
  if (_stab_c <= 0.0 || !_pseudo_time.coefficients().defined()) {
    if (!_f_stab.empty()) std::fill(_f_stab.begin(), _f_stab.end(), 0.0);
    return;
  }
  const std::vector<double>& m = *_stab_mass;
  _f_stab.assign(_s.u.size(), 0.0);
  const EquationMap& eqm = _loads.equations();
  const DofMap& dofs = _disc.dofs();
  // C* v with backward Euler's v = (u - u_start) / dt: the weight c / dt times M* (u - u_start)
  const double k = _pseudo_time.damping_weight(_stab_c);
  for (LocalIndex i = 0; i < eqm.n_eq(); ++i) {
    const LocalIndex s = eqm.eq_slot[i];
    if (!(m[s] > 0.0)) continue;
    const double f = k * m[s] * (_s.u[s] - _s.u_start[s]);
    _f_stab[s] = f;
    _s.f_int[s] += f;
    if (tangent) _K.add(i, i, k * m[s]);
    if (f != 0.0) {
      const int fld = static_cast<int>(dofs.slot_field(s));
      ar.flux_sum[fld] += std::abs(f);
      ++ar.flux_count[fld];
    }
  }
}

void StepProblem::apply(std::span<const double> du, std::span<const double> dl) {
  _trial_saved = false;
  const EquationMap& eqm = _loads.equations();
  for (LocalIndex i = 0; i < eqm.n_eq(); ++i) _s.u[eqm.eq_slot[i]] += du[i];
  for (int r = 0; r < _C.n_rows(); ++r) _disc.multiplier_trial(_C.multiplier[r]) += dl[r];
}

double StepProblem::step_limit(std::span<const double> du, std::span<const double>) {
  if (!_disc.has_gaps()) return 1.0;
  const EquationMap& eqm = _loads.equations();
  _du_slots.assign(_s.u.size(), 0.0);
  for (LocalIndex i = 0; i < eqm.n_eq(); ++i) _du_slots[eqm.eq_slot[i]] = du[i];
  return _asm.step_limit(fields(), _ctx, _du_slots);
}

int StepProblem::augment() {
  if (!_disc.has_gaps()) return 0;
  return _asm.augment(fields(), _ctx);
}

void StepProblem::compute_stiffness_hints() {
  if (!_disc.has_gaps()) return;
  StepContext ctx = _ctx;
  if (ctx.dt <= 0) ctx.dt = ctx.step_period; // transient terms need a finite increment
  const std::vector<double> diag = _asm.diagonal_stiffness(fields(), ctx, /*skip_gaps=*/true);
  const DofMap& dofs = _disc.dofs();
  // A gap whose nodes carry no other element (a node joined to the model only by gaps) takes the
  // mean over the model's displacement DOFs; a model of gaps alone takes 1.
  double model_sum = 0.0;
  int model_n = 0;
  for (LocalIndex s = 0; s < dofs.n_slots(); ++s)
    if (dofs.slot_field(s) == Field::Displacement && diag[s] > 0) {
      model_sum += diag[s];
      ++model_n;
    }
  const double model_mean = model_n > 0 ? model_sum / model_n : 1.0;
  for (auto& b : _disc.blocks()) {
    if (b.stiffness_hint.empty()) continue;
    for (std::size_t i = 0; i < b.size(); ++i) {
      double sum = 0.0;
      int n = 0;
      for (LocalIndex s : b.element_slots(i))
        if (dofs.slot_field(s) == Field::Displacement && diag[s] > 0) {
          sum += diag[s];
          ++n;
        }
      b.stiffness_hint[i] = n > 0 ? sum / n : model_mean;
    }
  }
}

Field StepProblem::equation_field(LocalIndex eq) const {
  return _disc.dofs().slot_field(_loads.equations().eq_slot[eq]);
}

std::array<double, kNumFields> StepProblem::increment_max() const {
  std::array<double, kNumFields> m{};
  const DofMap& dofs = _disc.dofs();
  for (LocalIndex s = 0; s < dofs.n_slots(); ++s) {
    const int fld = static_cast<int>(dofs.slot_field(s));
    m[fld] = std::max(m[fld], std::abs(_s.u[s] - _s.u_start[s]));
  }
  return m;
}

std::vector<double> StepProblem::reactions() const {
  std::vector<double> r(_s.f_int.size(), 0.0);
  const auto presc = _loads.prescribed();
  // dynamic steps: the physical forces M a + I + C v - P at t + dt, not HHT's weighted
  // M a / (1 + alpha) and history term -alpha / (1 + alpha) R(t) of the residual
  const bool dynamic = _f_dyn.size() == r.size() && _inertia.size() == r.size();
  for (std::size_t s = 0; s < r.size(); ++s)
    if (presc[s]) r[s] = _s.f_int[s] - _s.f_ext[s] - (dynamic ? _f_dyn[s] - _inertia[s] : 0.0);
  return r;
}

std::vector<double> StepProblem::concentrated_loads() const {
  std::vector<double> f(_s.f_int.size(), 0.0);
  _loads.add_nodal_loads(_ctx.step_time, f);
  return f;
}

} // namespace gapfem
