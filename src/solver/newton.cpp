#include "solver/newton.hpp"

#include "common/error.hpp"
#include "common/log.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace gapfem {

namespace {
/// How accurately an iterative backend need solve the Newton system (inexact Newton). In full:
/// the first system of a step that may be linear (a linear problem must meet the linear
/// criterion, 1e-8 of the flux, in one iteration) and, with friction, any system after a contact
/// status change (stick/slip decisions follow the step, and an inexact one makes gaps chatter).
/// Otherwise until the residual is 1e-3 of what Newton tolerates (R_n x the flux, given the
/// residual ratio now), never looser than 1e-6. Direct backends ignore it. `turning_back`: the
/// evaluations in a row whose status changes only turned back elements changed by the one before.
double forcing_term(const NewtonControls& c, int iterations, double residual_ratio,
                    int status_changes, int turning_back, bool friction) {
  constexpr double kFull = 1e-10, kLoosest = 1e-6;
  // Without friction an open/closed decision follows a gap's value, which the next iteration
  // corrects anyway: the system after status changes is solved to 1e-3, the first system of an
  // increment once the step has shown itself nonlinear to 1e-4 (it usually brings the status
  // changes). Measured on bench's slab-40k with --solver iterative: 398 -> 309 Krylov iterations
  // for 16 -> 17 Newton iterations; 1e-2 after status changes took 19 Newton iterations, 1e-3 for
  // the first system one more. When the only changes turn back what the last iteration turned,
  // the inexact step may be what turns them (a gap at the brink, as in the fuel pin example,
  // chattered to a cut-back with 1e-3): each such iteration in a row solves ten times more
  // accurately.
  constexpr double kAfterStatusChanges = 1e-3, kFirstOfNonlinearStep = 1e-4;
  if (iterations == 0) return c.nonlinear_step && !friction ? kFirstOfNonlinearStep : kFull;
  if (!std::isfinite(residual_ratio) || residual_ratio <= 0) return kFull;
  if (status_changes > 0)
    return friction ? kFull : std::max(kFull, kAfterStatusChanges * std::pow(10.0, -turning_back));
  double rn = std::numeric_limits<double>::infinity();
  for (const NewtonControls::Field& f : c.field) rn = std::min(rn, f.residual_ratio);
  return std::clamp(1e-3 * rn / residual_ratio, kFull, kLoosest);
}
} // namespace

FieldCheck check_field(const NewtonControls::Field& fc, double qt, double r, double correction,
                       double increment) {
  FieldCheck check;
  // zero flux: a field whose time-averaged flux is below q~_0 (round-off heat in a coupled step
  // without heat load) is converged once its residual is below epsilon q~_0; it does not count
  // in the ratio
  if (qt < fc.initial_flux && r <= fc.zero_flux_ratio * fc.initial_flux) {
    check.counted = false;
    return check;
  }
  // (no scale yet when every evaluation so far changed contact status: not converged)
  if (qt > 0) check.ratio = r / qt;
  if (!std::isfinite(r)) check.ratio = std::numeric_limits<double>::infinity();
  if (qt <= 0)
    check.converged = false;
  else if (r <= fc.linear_ratio * qt)
    check.converged = true;
  else
    check.converged = r <= fc.residual_ratio * qt && correction <= fc.correction_ratio * increment;
  check.within_stale =
      qt > 0 && r <= std::max(kStaleAcceptance * fc.residual_ratio, fc.linear_ratio) * qt;
  return check;
}

NewtonIteration::NewtonIteration(NonlinearProblem& problem, ConstrainedSolver& solver,
                                 const NewtonControls& controls, const FluxHistory& history,
                                 RunStatistics* stats)
    : _p(problem), _solver(solver), _c(controls), _history(history), _stats(stats),
      _fresh_contraction(controls.fresh_contraction) {}

NewtonResult NewtonIteration::run() {
  if (start()) {
    while (solve_system()) {
      limit_step();
      apply_correction();
      if (!evaluate_state()) break;
      widen_flux_scale();
      if (!track_status_changes()) break;
      if (check_convergence()) {
        if (augment()) continue;
        break;
      }
      if (!check_finite()) break;
      choose_factor();
      if (!check_divergence() || !check_iteration_limits()) break;
    }
  }
  return std::move(_res);
}

// Evaluate at the trial state; the tangent only where the solver will use it (with a kept factor
// of a stiffness that has barely drifted, modified Newton needs the residual alone). An
// increment's first evaluation always assembles it: the solver measures the drift there.
bool NewtonIteration::evaluate(bool tangent) {
  try {
    _ev = _p.evaluate(tangent);
    return true;
  } catch (const ConvergenceFailure& e) {
    _res.reason = e.what();
    _res.cause = FailureCause::Element;
    return false;
  }
}

bool NewtonIteration::tangent_wanted() const {
  return _c.factor_reuse == FactorReuse::Never || !_c.residual_only || !_solver.matrix_optional();
}

// the tangent at the state of an evaluation made without it
bool NewtonIteration::add_tangent() {
  try {
    const Evaluation full = _p.assemble_tangent();
    _ev.symmetric = full.symmetric;
    _ev.friction = full.friction;
    _ev.tangent = true;
    return true;
  } catch (const ConvergenceFailure& e) {
    _res.reason = e.what();
    _res.cause = FailureCause::Element;
    return false;
  }
}

// an element that asks for a smaller increment ends the attempt at once (Abaqus's PNEWDT < 1)
bool NewtonIteration::requested_cutback() {
  _res.dt_ratio = std::min(_res.dt_ratio, _ev.dt_ratio);
  if (!(_ev.dt_ratio < 1.0)) return false;
  _res.reason = fmt::format("an element asked for a {:.3g} times smaller time increment (PNEWDT "
                            "of its user subroutine)",
                            _ev.dt_ratio);
  _res.cause = FailureCause::Requested;
  return true;
}

bool NewtonIteration::start() {
  // the tangent, unless the increment's operators are the last increment's (a dynamic step at an
  // unchanged size) and the solver may keep its factor: the residual alone, as later iterations
  const bool tangent = tangent_wanted() || !_p.operators_as_before();
  if (!evaluate(tangent)) return false;
  if (!_ev.tangent && _ev.stiffness_changed && !add_tangent()) return false;
  if (requested_cutback()) return false;
  // The flux scale of the increment is the largest average flux seen in any of its evaluations
  // without contact status changes: a free thermal expansion has large thermal forces at the
  // start and none at convergence. An evaluation that changes status is transitional and may
  // carry forces no converged state has (a stick predicted after a slip reversal carries k_s e,
  // far beyond mu N); counted in the scale they would let a large residual pass as small.
  if (_ev.status_changes == 0) _flux = _ev.flux;
  if (_p.rhs().empty() && _p.constraints().n_rows() == 0) {
    // every DOF is prescribed: nothing to solve, the evaluation gives the reactions
    _res.converged = true;
    _res.flux = _flux;
    return false;
  }
  return true;
}

bool NewtonIteration::solve_system() {
  const auto& C = _p.constraints();
  const auto b = _p.rhs();
  _du.assign(b.size(), 0.0);
  _dl.assign(static_cast<std::size_t>(C.n_rows()), 0.0);
  KktOptions opt;
  opt.constraint_tolerance = 1e-3 * _p.constraint_tolerance();
  opt.reuse = _c.factor_reuse;
  opt.force_fresh = _force_fresh;
  opt.relative_tolerance = forcing_term(_c, _res.iterations, _residual_ratio_now,
                                        _ev.status_changes, _turning_back, _ev.friction);
  if (_force_fresh && !_ev.tangent && !add_tangent()) return false;
  try {
    opt.matrix_current = _ev.tangent;
    KktStatistics ks = _solver.solve(_p.matrix(), b, C, _du, _dl, _ev.symmetric, opt, _stats);
    if (ks.needs_matrix) {
      log::debug("  the solver needs the tangent: assembling it");
      if (!add_tangent()) return false;
      opt.matrix_current = true;
      ks = _solver.solve(_p.matrix(), b, C, _du, _dl, _ev.symmetric, opt, _stats);
    }
    _last_stale = ks.stale_factor;
    _force_fresh = false;
  } catch (const SingularSystem& e) {
    _res.singular = true;
    _res.singular_equations = e.equations();
    _res.reason = "the system of equations is singular";
    _res.cause = FailureCause::Singular;
    return false;
  }
  return true;
}

// line search: a frictional gap whose slip would reverse past its stick band stops the step where
// its slip turns (the slip branch has no stiffness along the slip, so the full step would jump
// over the whole band)
void NewtonIteration::limit_step() {
  const double alpha = _p.step_limit(_du, _dl);
  if (alpha < 1.0) {
    for (double& v : _du) v *= alpha;
    for (double& v : _dl) v *= alpha;
    log::debug("  step limited to {:.3g} of the correction (slip reversal)", alpha);
  }
}

void NewtonIteration::apply_correction() {
  _p.apply(_du, _dl);
  ++_res.iterations;
  if (_stats) ++_stats->iterations;
  _cmax = {};
  for (std::size_t i = 0; i < _du.size(); ++i) {
    const int f = static_cast<int>(_p.equation_field(static_cast<LocalIndex>(i)));
    _cmax[f] = std::max(_cmax[f], std::abs(_du[i]));
  }
}

// Evaluate at the new state (with the tangent after all where a status change altered it: the
// solver must see the new matrix).
bool NewtonIteration::evaluate_state() {
  if (!evaluate(tangent_wanted())) return false;
  if (!_ev.tangent && _ev.stiffness_changed && !add_tangent()) return false;
  return !requested_cutback();
}

void NewtonIteration::widen_flux_scale() {
  if (_ev.status_changes == 0)
    for (int f = 0; f < kNumFields; ++f) _flux[f] = std::max(_flux[f], _ev.flux[f]);
}

bool NewtonIteration::track_status_changes() {
  if (_ev.status_changes == 0) {
    ++_equilibrium_iterations;
    return true;
  }
  ++_res.severe_iterations;
  for (ElemId e : _ev.changed)
    if (++_flips[e] >= _c.chatter_flips) _res.chattering.push_back(e);
  std::vector<ElemId> changed = _ev.changed;
  std::sort(changed.begin(), changed.end());
  _turning_back =
      std::includes(_last_changed.begin(), _last_changed.end(), changed.begin(), changed.end())
          ? _turning_back + 1
          : 0;
  _last_changed = std::move(changed);
  if (_res.chattering.empty()) return true;
  std::sort(_res.chattering.begin(), _res.chattering.end());
  _res.chattering.erase(std::unique(_res.chattering.begin(), _res.chattering.end()),
                        _res.chattering.end());
  _res.reason = "contact status is chattering";
  _res.cause = FailureCause::Chattering;
  return false;
}

double NewtonIteration::time_averaged_flux(int f) const {
  const NewtonControls::Field& fc = _c.field[f];
  return fc.user_flux > 0 ? fc.user_flux : (_history.sum[f] + _flux[f]) / (_history.n + 1);
}

bool NewtonIteration::check_convergence() {
  const auto inc = _p.increment_max();
  bool converged = _ev.status_changes == 0 && _ev.constraint_max <= _p.constraint_tolerance();
  bool within_stale_share = true; // every field also within kStaleAcceptance of its R_n
  _worst_ratio = 0.0;
  for (int f = 0; f < kNumFields; ++f) {
    if (!_ev.has_field[f]) continue;
    const FieldCheck fc =
        check_field(_c.field[f], time_averaged_flux(f), _ev.residual_max[f], _cmax[f], inc[f]);
    if (!fc.counted) continue;
    _worst_ratio = std::max(_worst_ratio, fc.ratio);
    converged &= fc.converged;
    within_stale_share &= fc.within_stale;
  }
  // A modified-Newton iterate (from a stale factor) converges linearly: when it first meets R_n
  // its error is of the order of the tolerance, where full Newton's quadratic step lands far
  // below it. Such an iterate is accepted once it is also within kStaleAcceptance of R_n, or
  // after kStaleRefinements more (cheap, residual-only) stale iterations while they still
  // reduce the residual, so that the answer is about as converged as full Newton's.
  if (converged && _last_stale && !within_stale_share && _res.refinements < kStaleRefinements &&
      std::isfinite(_previous_ratio) && _worst_ratio < _previous_ratio) {
    converged = false;
    ++_res.refinements;
  }
  _res.residual_history.push_back(_worst_ratio);
  _residual_ratio_now = _worst_ratio;
  log::debug("  iteration {}: residual/flux {:.3e}, status changes {}{}, constraint {:.3e}",
             _res.iterations, _worst_ratio, _ev.status_changes,
             _ev.branch_changes > 0
                 ? fmt::format(" (force-law gaps opened or closed: {})", _ev.branch_changes)
                 : std::string(),
             _ev.constraint_max);
  return converged;
}

bool NewtonIteration::augment() {
  if (_p.augment() == 0) {
    _res.converged = true;
    _res.flux = _flux;
    return false;
  }
  // The augmented multipliers change the residual: re-evaluate and keep iterating.
  if (++_res.augmentations > _c.max_augmentations) {
    _res.reason = fmt::format("augmented Lagrange did not reach its penetration tolerance in {} "
                              "augmentations; increase the penalty stiffness",
                              _c.max_augmentations);
    _res.cause = FailureCause::Augmentation;
    return false;
  }
  if (!evaluate_state()) return false;
  _equilibrium_iterations = 0;
  _increases = 0;
  _previous_ratio = std::numeric_limits<double>::infinity();
  return true;
}

bool NewtonIteration::check_finite() {
  if (std::isfinite(_worst_ratio)) return true;
  _res.reason = "the residual is not finite";
  _res.cause = FailureCause::NonFinite;
  return false;
}

// A stale factor that no longer contracts the residual well is replaced: "well" is 10x, or half
// as well as a fresh factor did in this increment or the step's earlier ones when full Newton
// itself contracts slowly (a penalty law's kinks), so that the stale step is not blamed for the
// physics; a stale step that lets the residual grow is always replaced. (Not blaming a stale
// iteration that crossed force-law kinks (Evaluation::branch_changes) was tried: the forced fresh
// factor is what teaches this rule that the physics is slow, and without it the penalty 11k block
// took 13 factorisations instead of 2.)
void NewtonIteration::choose_factor() {
  if (!std::isfinite(_previous_ratio) || !(_previous_ratio > 0) || _ev.status_changes != 0) return;
  const double contraction = _worst_ratio / _previous_ratio;
  if (!_last_stale)
    _fresh_contraction = _res.fresh_contraction = contraction;
  else if (contraction > std::max(_c.stale_contraction, std::min(2.0 * _fresh_contraction, 1.0)))
    _force_fresh = true;
}

bool NewtonIteration::check_divergence() {
  if (_ev.status_changes == 0) {
    if (_worst_ratio > _previous_ratio)
      ++_increases;
    else
      _increases = 0;
    if (_equilibrium_iterations >= _c.divergence_check_after && _increases >= 2) {
      _res.reason = fmt::format("the solution is diverging (residual/flux {:.3e})", _worst_ratio);
      _res.cause = FailureCause::Diverging;
      return false;
    }
  }
  _previous_ratio = _worst_ratio;
  return true;
}

bool NewtonIteration::check_iteration_limits() {
  if (_equilibrium_iterations >= _c.max_equilibrium_iterations) {
    _res.reason = fmt::format("no convergence in {} equilibrium iterations (residual/flux {:.3e})",
                              _equilibrium_iterations, _worst_ratio);
    _res.cause = FailureCause::Iterations;
    return false;
  }
  if (_res.severe_iterations > _c.max_severe_iterations) {
    _res.reason =
        fmt::format("contact status did not settle in {} iterations", _c.max_severe_iterations);
    _res.cause = FailureCause::Status;
    return false;
  }
  return true;
}

NewtonResult solve_increment(NonlinearProblem& p, ConstrainedSolver& solver,
                             const NewtonControls& c, const FluxHistory& history,
                             RunStatistics* stats) {
  return NewtonIteration(p, solver, c, history, stats).run();
}

} // namespace gapfem
