// The dynamic parts of the step problem (step_problem.hpp): HHT's history term and the start of
// a dynamic step (initial accelerations). Theory: docs/theory/dynamics.md.
#include "common/log.hpp"
#include "solver/step_problem.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace gapfem {

void StepProblem::add_rate_history() {
  const double wh = _integrator ? _integrator->history_weight() : 0.0;
  const double wi = _integrator ? _integrator->inertia_weight() : 1.0;
  _f_dyn.resize(_s.f_int.size());
  for (std::size_t s = 0; s < _s.f_int.size(); ++s) {
    const double h = wh * _s.r_start[s];
    _s.f_int[s] += h;
    _f_dyn[s] = wi * _inertia[s] + h;
  }
}

void StepProblem::commit_rate_history() {
  const double wh = _integrator ? _integrator->history_weight() : 0.0;
  const double wi = _integrator ? _integrator->inertia_weight() : 1.0;
  const bool inertia = _inertia.size() == _s.u.size();
  _s.r_prev = _s.r_start;
  for (std::size_t s = 0; s < _s.r_start.size(); ++s)
    _s.r_start[s] =
        _s.f_int[s] - _s.f_ext[s] - wh * _s.r_start[s] - (inertia ? wi * _inertia[s] : 0.0);
}

namespace {

/// The rows of a constraint block that `keep` says (all when empty) and that are exact (compliant
/// rows are forces of the displacements: they hold no acceleration).
ConstraintBlock exact_rows(const ConstraintBlock& C, const std::vector<bool>& keep = {}) {
  ConstraintBlock out;
  const bool columns = C.has_columns();
  for (int r = 0; r < C.n_rows(); ++r) {
    if (C.compliance[r] != 0.0 || (!keep.empty() && !keep[static_cast<std::size_t>(r)])) continue;
    const auto b = C.row_ptr[r], e = C.row_ptr[r + 1];
    out.col.insert(out.col.end(), C.col.begin() + b, C.col.begin() + e);
    out.val.insert(out.val.end(), C.val.begin() + b, C.val.begin() + e);
    if (columns) out.dval.insert(out.dval.end(), C.dval.begin() + b, C.dval.begin() + e);
    out.row_ptr.push_back(static_cast<LocalIndex>(out.col.size()));
    out.g.push_back(0.0);
    out.compliance.push_back(0.0);
    out.multiplier.push_back(C.multiplier[r]);
    out.given_v.push_back(C.given_v.empty() ? 0.0 : C.given_v[r]);
    out.given_a.push_back(C.given_a.empty() ? 0.0 : C.given_a[r]);
    out.travel.push_back(C.travel.empty() ? 0.0 : C.travel[r]);
  }
  return out;
}

/// 1/2 v.M v over the equations (M assembled over them).
double kinetic_energy(const CsrMatrix& M, const EquationMap& eqm, std::span<const double> v_slot) {
  const LocalIndex n = eqm.n_eq();
  std::vector<double> v(static_cast<std::size_t>(n)), Mv(v.size());
  for (LocalIndex i = 0; i < n; ++i) v[i] = v_slot[eqm.eq_slot[i]];
  M.multiply(v, Mv);
  double ke = 0.0;
  for (LocalIndex i = 0; i < n; ++i) ke += 0.5 * v[i] * Mv[i];
  return ke;
}

} // namespace

ConstraintBlock StepProblem::select_rows(const ConstraintBlock& C, const std::vector<bool>& keep) {
  return exact_rows(C, keep);
}

double StepProblem::start_dynamic_step(ConstrainedSolver& solver, bool initial_accelerations) {
  _s.r_start.clear();
  _f_dyn.clear();
  if (_s.a_start.size() != _s.u.size()) _s.a_start.assign(_s.u.size(), 0.0);
  if (_s.v_start.size() != _s.u.size()) _s.v_start.assign(_s.u.size(), 0.0);
  _loads.prescribed_rates(0.0, 0.0, _s.v_start, _s.v_start, _s.a_start); // base motion at t = 0
  _loads.prescribed_local_rates(0.0, 0.0, _s.v_start, _s.v_start, _s.a_start);
  // a velocity prescribed in a local system (a *TRANSFORM node's row) starts compatible with it
  const DynamicRestart r =
      restart_dynamics(solver, 0.0, initial_accelerations, _loads.has_local_motion(), false);
  _s.f_ext_start = _s.f_ext; // the step's loads at its start (ALLWK)
  _s.allke = r.kinetic_energy;
  return r.amax;
}

DynamicRestart StepProblem::restart_dynamics(ConstrainedSolver& solver, double t,
                                             bool accelerations, bool project_velocities,
                                             bool impact, std::span<const std::int64_t> released) {
  DynamicRestart out;
  // R(t): the residual at the committed state and the step's loads at t, no rates (dt = 0)
  begin_increment(t, 0.0);
  evaluate(false);
  _s.r_start.resize(_s.u.size());
  for (std::size_t s = 0; s < _s.u.size(); ++s) _s.r_start[s] = _s.f_int[s] - _s.f_ext[s];
  _s.r_prev.clear(); // a fresh start: no earlier increment to lag behind
  const bool moving =
      std::any_of(_s.v_start.begin(), _s.v_start.end(), [](double v) { return v != 0.0; });
  if (!accelerations && !project_velocities && !moving) {
    _driven_inertia.clear();
    return out;
  }
  const OperatorWeights keep = _weights;
  // M alone (the weights of K and C zero) with the active exact constraint rows
  _weights = {0.0, 0.0, 1.0, 1.0};
  evaluate(true);
  _weights = keep;
  const EquationMap& eqm = _loads.equations();
  const LocalIndex n = eqm.n_eq();
  out.kinetic_energy = kinetic_energy(_K, eqm, _s.v_start);
  if (!accelerations && !project_velocities) {
    add_rate_forces();
    return out;
  }
  if (n == 0) return out; // every DOF prescribed: nothing moves freely
  // a massless DOF (a stop on a spring, a node of springs and gaps only) gets a token mass,
  // 1e-8 of the largest: its right side is zero (a = 0 unless a row ties it to a mass) and an
  // impact's projection moves it almost for free, as a massless point moves with what it touches
  // (a mass hitting a massless spring-supported stop loses no kinetic energy)
  std::vector<bool> massive(static_cast<std::size_t>(n));
  double largest = 0.0;
  for (LocalIndex i = 0; i < n; ++i) largest = std::max(largest, _K.diagonal(i));
  const double token = largest > 0.0 ? 1e-8 * largest : 1.0;
  for (LocalIndex i = 0; i < n; ++i) {
    massive[i] = _K.diagonal(i) > 0.0;
    if (!massive[i]) _K.add(i, i, token);
  }
  std::vector<bool> rows; // every exact row but the released ones (still closed at the state)
  if (!released.empty())
    for (int r = 0; r < _C.n_rows(); ++r)
      rows.push_back(!std::binary_search(released.begin(), released.end(), _C.multiplier[r]));
  const ConstraintBlock C = exact_rows(_C, rows);
  const auto factor = solver.factorize(_K, C, true, _stats);
  for (LocalIndex i = 0; i < n; ++i)
    if (!massive[i]) _K.add(i, i, -token); // M again (energies)
  // the forces of the instant: an impact's damping forces are those of the velocities before
  // it (the velocity field it projects is discontinuous: a stiffness-proportional damping of its
  // jumps, kept in R(t), kicked the next increments through HHT's a_n terms, unstable)
  add_rate_forces();
  if (project_velocities) {
    out.energy_lost = project_velocities_onto(*factor, C, massive, out.support_work);
    out.kinetic_energy = kinetic_energy(_K, eqm, _s.v_start);
  }
  std::vector<double> l;
  if (accelerations)
    out.amax = impact ? impact_accelerations(solver, *factor, C, massive, token)
                      : consistent_accelerations(*factor, C, massive, l);
  return out;
}

void StepProblem::assemble_at_rates(FieldView fv, const OperatorWeights& w, std::vector<double>& f,
                                    std::vector<double>& Ma, std::vector<double>& Cv) {
  const StepContext keep = _ctx;
  _ctx.rates = RateCoefficients{};
  _ctx.rates.first_order = _ctx.rates.second_order = true;
  _ctx.rates.v_v = 1.0;
  _ctx.rates.a_a = 1.0;
  fv.rate_given = {};
  _asm.assemble(fv, _ctx, f, nullptr, nullptr, w, RateForces{Ma, Cv, {}});
  _ctx = keep;
}

bool StepProblem::add_rate_forces() {
  // one residual assembly whose rate maps are v = v_start and a = a_start, the accelerations
  // kept at driven DOFs only: every element sees the committed velocities (at a driven DOF the
  // prescribed one), so R(t) gets the damping forces of operators and of kernels damping in their
  // residual (nonlinear dashpots, contact damping), and the free DOFs' couplings to driven ones,
  // C v and a consistent mass's M a_p (_driven_inertia), which the accelerations' solve needs
  const std::size_t n = _s.u.size();
  std::vector<double> a(n, 0.0);
  bool driven = false;
  for (std::size_t s = 0; s < _rate_given.size() && s < _s.a_start.size(); ++s)
    if (_rate_given[s] && _s.a_start[s] != 0.0) {
      a[s] = _s.a_start[s];
      driven = true;
    }
  const bool moving =
      std::any_of(_s.v_start.begin(), _s.v_start.end(), [](double v) { return v != 0.0; });
  _driven_inertia.clear();
  if (!moving && !driven) return false;
  std::vector<double> f(n), Cv(n, 0.0), Ma(n, 0.0);
  FieldView fv = fields();
  fv.v_start = damped_velocities();
  fv.a_start = a;
  assemble_at_rates(fv, OperatorWeights{1.0, 1.0, driven ? 1.0 : 0.0, 1.0}, f, Ma, Cv);
  _s.f_damp_start = Cv; // ALLVD's trapezoidal rule starts from the operators' forces
  for (std::size_t s = 0; s < n; ++s) _s.r_start[s] += f[s] - Ma[s] - _s.f_int[s];
  if (driven) _driven_inertia = std::move(Ma);
  return true;
}

double StepProblem::project_velocities_onto(ConstrainedFactor& factor, const ConstraintBlock& C,
                                            const std::vector<bool>& massive,
                                            double& support_work) {
  // [M C^T; C 0] [dv; mu] = [0; -C v]: the least change of kinetic energy that makes the
  // velocities compatible with the rows (a fully plastic impact); C v includes the rows'
  // prescribed DOFs (given_v: a stop on a moving support takes the support's velocity)
  const EquationMap& eqm = _loads.equations();
  const LocalIndex n = eqm.n_eq();
  std::vector<double> v(static_cast<std::size_t>(n)), b(v.size(), 0.0), dv(v.size());
  for (LocalIndex i = 0; i < n; ++i) v[i] = _s.v_start[eqm.eq_slot[i]];
  std::vector<double> g(static_cast<std::size_t>(C.n_rows())), mu(g.size());
  for (int r = 0; r < C.n_rows(); ++r) {
    double cv = 0.0;
    for (auto k = C.row_ptr[r]; k < C.row_ptr[r + 1]; ++k) cv += C.val[k] * v[C.col[k]];
    g[r] = cv + C.given_v[r]; // the solver drives C dv + g to 0
  }
  factor.solve(b, g, dv, mu);
  // M dv = -C_f^T mu: the rows' impulse on the prescribed DOFs is -C_p^T mu, which their
  // supports balance with +C_p^T mu, working on v_p: mu . given_v (the loss stays 1/2 dv.M dv)
  support_work = 0.0;
  for (int r = 0; r < C.n_rows(); ++r) support_work += mu[r] * C.given_v[r];
  std::vector<double> Mdv(v.size());
  _K.multiply(dv, Mdv);
  double lost = 0.0;
  for (LocalIndex i = 0; i < n; ++i) {
    _s.v_start[eqm.eq_slot[i]] += dv[i];
    if (massive[i]) lost += 0.5 * dv[i] * Mdv[i];
  }
  return lost;
}

double StepProblem::consistent_accelerations(ConstrainedFactor& factor, const ConstraintBlock& C,
                                             const std::vector<bool>& massive,
                                             std::vector<double>& l,
                                             std::span<const double> released) {
  // M a + R = 0 on the DOFs with mass, C a + given_a = 0; then R there is -M a (the constraint
  // forces that hold C a = 0 included); a massless DOF keeps its R and a = 0
  const EquationMap& eqm = _loads.equations();
  const LocalIndex n = eqm.n_eq();
  std::vector<double> b(static_cast<std::size_t>(n)), a(b.size()), Ma(b.size());
  // a consistent mass coupling a free DOF to a driven one: M_ff a_f = -R_f - M_fp a_p
  const auto coupling = [&](LocalIndex s) {
    return _driven_inertia.empty() ? 0.0 : _driven_inertia[s];
  };
  for (LocalIndex i = 0; i < n; ++i) {
    const LocalIndex s = eqm.eq_slot[i];
    b[i] = massive[i] ? -_s.r_start[s] - coupling(s) + (released.empty() ? 0.0 : released[i]) : 0.0;
  }
  // C a + given_a = 0: accelerations compatible with the rows' prescribed DOFs too
  std::vector<double> g(C.given_a.begin(), C.given_a.end());
  g.resize(static_cast<std::size_t>(C.n_rows()), 0.0);
  l.assign(g.size(), 0.0);
  factor.solve(b, g, a, l);
  for (LocalIndex i = 0; i < n; ++i)
    if (!massive[i]) a[i] = 0.0;
  _K.multiply(a, Ma);
  double amax = 0.0;
  for (LocalIndex i = 0; i < n; ++i) {
    const LocalIndex s = eqm.eq_slot[i];
    _s.a_start[s] = a[i];
    if (massive[i])
      _s.r_start[s] = -Ma[i] - coupling(s);
    else if (!released.empty()) // a massless DOF's R without the released rows' forces
      _s.r_start[s] -= released[i];
    amax = std::max(amax, std::abs(a[i]));
  }
  return amax;
}

double StepProblem::impact_accelerations(ConstrainedSolver& solver, ConstrainedFactor& factor,
                                         const ConstraintBlock& C, const std::vector<bool>& massive,
                                         double token) {
  // The accelerations after an impact with the contacts unilateral: a gap whose force would pull
  // (normal multiplier < 0) separates at the impact's instant ("the points that acquire the same
  // velocity sometimes separate just after the impact", Theory Guide, "Intermittent
  // contact/impact"): its force, in R as the increment left it, is taken out and its row
  // dropped, and the rest solved again (a few passes: each drops at least one row). Holding
  // such a row kept a pull in a(t) that the next increment's trapezoid spent as it opened.
  const EquationMap& eqm = _loads.equations();
  const LocalIndex n = eqm.n_eq();
  const std::vector<double> r_start = _s.r_start;
  ConstraintBlock rows = C;
  std::unique_ptr<ConstrainedFactor> own;
  ConstrainedFactor* f = &factor;
  std::vector<double> released(static_cast<std::size_t>(n), 0.0), l;
  for (int pass = 0;; ++pass) {
    _s.r_start = r_start;
    const double amax = consistent_accelerations(*f, rows, massive, l, released);
    std::vector<std::int64_t> separate; // the normal rows of gaps whose force would pull
    for (int r = 0; r < rows.n_rows() && pass < 8; ++r) {
      const std::int64_t m = rows.multiplier[r];
      if (_disc.is_contact_normal(m) && _disc.multiplier_committed(m) + l[r] < 0.0)
        separate.push_back(m);
    }
    if (separate.empty()) { // the rows' forces that hold the contacts from now on: R + C^T l
      for (int r = 0; r < rows.n_rows(); ++r) {
        _disc.multiplier_committed(rows.multiplier[r]) += l[r];
        _disc.multiplier_trial(rows.multiplier[r]) += l[r];
      }
      return amax;
    }
    log::debug("  impact: {} contact(s) separate at once", separate.size());
    std::sort(separate.begin(), separate.end());
    std::vector<bool> keep(static_cast<std::size_t>(rows.n_rows()), true);
    for (int r = 0; r < rows.n_rows(); ++r) { // a separating gap's friction rows go with it
      const std::int64_t m = rows.multiplier[r];
      if (!std::binary_search(separate.begin(), separate.end(), _disc.contact_normal_of(m)))
        continue;
      for (auto k = rows.row_ptr[r]; k < rows.row_ptr[r + 1]; ++k)
        released[rows.col[k]] += _disc.multiplier_committed(m) * rows.val[k];
      _disc.multiplier_committed(m) = _disc.multiplier_trial(m) = 0.0;
      keep[r] = false;
    }
    rows = select_rows(rows, keep);
    for (LocalIndex i = 0; i < n; ++i)
      if (!massive[i]) _K.add(i, i, token);
    own = solver.factorize(_K, rows, true, _stats);
    for (LocalIndex i = 0; i < n; ++i)
      if (!massive[i]) _K.add(i, i, -token);
    f = own.get();
  }
}

void StepProblem::release_contacts(ConstrainedSolver& solver, double t,
                                   std::span<const std::int64_t> rows) {
  // the forces fall to 0 at t: R(t) is evaluated without them, and no trapezoid works on them
  for (const std::int64_t m : rows) _disc.multiplier_committed(m) = 0.0;
  restart_dynamics(solver, t, true, false, true, rows);
  reset_energy_start_forces(damped_velocities());
}

double StepProblem::impact(ConstrainedSolver& solver, double t,
                           std::span<const std::int64_t> new_rows) {
  // the work of the rows that closed in the increment over their travel (the gap's force rising
  // from 0 to the one that stopped the approach): kinetic energy the increment's own solution
  // gave up at the impact, which the trapezoid put into the gap's internal energy
  double absorbed = 0.0;
  for (int r = 0; r < _C.n_rows(); ++r)
    if (_C.compliance[r] == 0.0 && r < static_cast<int>(_C.travel.size()) &&
        std::binary_search(new_rows.begin(), new_rows.end(), _C.multiplier[r]))
      absorbed += 0.5 * _disc.multiplier_committed(_C.multiplier[r]) * _C.travel[r];
  // the increment's own imbalance: 0 to rounding for the trapezoidal rule; HHT's weights make
  // the trapezoid of an impulsive force inexact (a few percent of the impact's loss, either
  // sign): it is the impact's too
  const double gained = _s.energies().etotal() - _etotal_before;
  // keep the converged increment's forces for its frame and the step's checks
  const std::vector<double> f_int = _s.f_int, f_ext = _s.f_ext, f_dyn = _f_dyn;
  const std::vector<double> v_before = _s.v_start;
  const DynamicRestart r = restart_dynamics(solver, t, true, true, true);
  _s.f_int = f_int;
  _s.f_ext = f_ext;
  _f_dyn = f_dyn;
  reset_energy_start_forces(v_before);
  _s.v_damp = v_before; // a release at the next increment's start keeps these damping forces
  // ALLKL: what the impact took; a moving support's impulse works on what it hits (ALLWK)
  _s.allke = std::max(0.0, _s.allke + r.support_work - r.energy_lost);
  _s.allie -= absorbed;
  _s.allkl += r.energy_lost + absorbed - gained;
  _s.allwk += r.support_work;
  return r.energy_lost + absorbed - gained;
}

double StepProblem::book_release() {
  const double gained = _s.energies().etotal() - _etotal_before;
  _s.allkl -= gained;
  return gained;
}

double StepProblem::half_increment_residual(double t0, double dt) {
  std::vector<double> u_mid(_s.u.size());
  if (!_integrator || !_integrator->midpoint(dt, _s.u, _s.u_start, _s.v_start, _s.a_start, u_mid))
    return -1.0;
  // keep what the commit reads: the end state, its forces and the elements' trial history
  const std::vector<double> u_end = _s.u, f_int = _s.f_int, f_ext = _s.f_ext, inertia = _inertia,
                            f_dyn = _f_dyn, damping = _damping_forces, momentum = _momentum;
  const std::vector<double> T_end = _s.T, G_end = _s.G, rhs = _rhs;
  std::vector<double> trial;
  _disc.save_trial(trial);
  const StepContext ctx = _ctx;
  const ConstraintBlock C = _C;
  const double h = 0.5 * dt;
  _ctx.dt = h;
  _ctx.step_time = t0 + h;
  _ctx.total_time = _s.total_time + t0 + h;
  begin_rates(h); // the rates of u_mid over h are the midpoint's (Newmark's maps)
  _s.u = u_mid;
  _loads.apply_prescribed(_ctx.step_time, _s.u);
  _loads.apply_prescribed_motion(t0, _ctx.step_time, _s.u_start, _s.v_start, _s.u);
  if (_loads.has_temperature_field()) _loads.temperatures(_ctx.step_time, _s.T);
  evaluate(false);
  // f_int - f_ext = R_mid + wi M a + wh R(t0): take R_mid out and form the half-step residual
  const double wh = _integrator->history_weight(), wi = _integrator->inertia_weight();
  const double alpha = 1.0 / wi - 1.0;
  const EquationMap& eqm = _loads.equations();
  const bool prev = _s.r_prev.size() == _s.r_start.size();
  double r = 0.0;
  for (LocalIndex i = 0; i < eqm.n_eq(); ++i) {
    const LocalIndex s = eqm.eq_slot[i];
    const double Ma = _inertia.size() == _s.u.size() ? _inertia[s] : 0.0;
    const double R0 = _s.r_start[s], R1 = prev ? _s.r_prev[s] : R0;
    const double R_mid = -_rhs[i] - wi * Ma - wh * R0;
    r = std::max(r, std::abs(Ma + (1.0 + alpha) * R_mid - 0.5 * alpha * (R0 + R1)));
  }
  _s.u = u_end;
  _s.f_int = f_int;
  _s.f_ext = f_ext;
  _inertia = inertia;
  _f_dyn = f_dyn;
  _damping_forces = damping;
  _momentum = momentum;
  _s.T = T_end;
  _s.G = G_end;
  _rhs = rhs;
  _C = C;
  _disc.restore_trial(trial);
  _ctx = ctx;
  begin_rates(dt);
  return r;
}

} // namespace gapfem
