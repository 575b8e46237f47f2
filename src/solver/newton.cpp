#include "solver/newton.hpp"

#include "common/error.hpp"
#include "common/log.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <unordered_map>

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

/// The share of R_n a modified-Newton (stale-factor) iterate must meet (see the convergence
/// check).
constexpr double kStaleAcceptance = 1e-2;
/// Stale iterations at most past R_n on the way to kStaleAcceptance.
constexpr int kStaleRefinements = 2;

NewtonResult solve_increment(NonlinearProblem& p, ConstrainedSolver& solver,
                             const NewtonControls& c, const FluxHistory& history,
                             RunStatistics* stats) {
  NewtonResult res;
  std::unordered_map<ElemId, int> flips;
  std::vector<ElemId> last_changed; ///< sorted, by the evaluation before the last
  int turning_back = 0; ///< evaluations in a row that only turned back the one before's changes
  std::vector<double> du, dl;
  double previous_ratio = std::numeric_limits<double>::infinity();
  double residual_ratio_now = std::numeric_limits<double>::infinity(); ///< of the last evaluation
  int increases = 0, equilibrium_iterations = 0;
  bool last_stale = false, force_fresh = false;
  /// residual ratio over the last fresh-factor iteration (this increment's, or the step's before)
  double fresh_contraction = c.fresh_contraction;
  Evaluation ev;
  // Evaluate at the trial state; the tangent only where the solver will use it (with a kept
  // factor of a stiffness that has barely drifted, modified Newton needs the residual alone).
  // An increment's first evaluation always assembles it: the solver measures the drift there.
  auto evaluate = [&](bool tangent) {
    try {
      ev = p.evaluate(tangent);
      return true;
    } catch (const ConvergenceFailure& e) {
      res.reason = e.what();
      res.cause = FailureCause::Element;
      return false;
    }
  };
  auto tangent_wanted = [&] {
    return c.factor_reuse == FactorReuse::Never || !c.residual_only || !solver.matrix_optional();
  };
  // the tangent at the state of an evaluation made without it
  auto add_tangent = [&] {
    try {
      const Evaluation full = p.assemble_tangent();
      ev.symmetric = full.symmetric;
      ev.friction = full.friction;
      ev.tangent = true;
      return true;
    } catch (const ConvergenceFailure& e) {
      res.reason = e.what();
      res.cause = FailureCause::Element;
      return false;
    }
  };
  if (!evaluate(true)) return res;
  // The flux scale of the increment is the largest average flux seen in any of its evaluations
  // without contact status changes: a free thermal expansion has large thermal forces at the start
  // and none at convergence. An evaluation that changes status is transitional and may carry
  // forces no converged state has (a stick predicted after a slip reversal carries k_s e, far
  // beyond mu N); counted in the scale they would let a large residual pass as small.
  // an element that asks for a smaller increment ends the attempt at once (Abaqus's PNEWDT < 1)
  auto requested_cutback = [&] {
    res.dt_ratio = std::min(res.dt_ratio, ev.dt_ratio);
    if (!(ev.dt_ratio < 1.0)) return false;
    res.reason = fmt::format("an element asked for a {:.3g} times smaller time increment (PNEWDT "
                             "of its user subroutine)",
                             ev.dt_ratio);
    res.cause = FailureCause::Requested;
    return true;
  };
  if (requested_cutback()) return res;
  std::array<double, kNumFields> flux{};
  if (ev.status_changes == 0) flux = ev.flux;
  if (p.rhs().empty() && p.constraints().n_rows() == 0) {
    // every DOF is prescribed: nothing to solve, the evaluation gives the reactions
    res.converged = true;
    res.flux = flux;
    return res;
  }
  for (;;) {
    // ---- solve and update
    const auto& C = p.constraints();
    const auto b = p.rhs();
    du.assign(b.size(), 0.0);
    dl.assign(static_cast<std::size_t>(C.n_rows()), 0.0);
    KktOptions opt;
    opt.constraint_tolerance = 1e-3 * p.constraint_tolerance();
    opt.reuse = c.factor_reuse;
    opt.force_fresh = force_fresh;
    opt.relative_tolerance = forcing_term(c, res.iterations, residual_ratio_now, ev.status_changes,
                                          turning_back, ev.friction);
    if (force_fresh && !ev.tangent && !add_tangent()) return res;
    try {
      opt.matrix_current = ev.tangent;
      KktStatistics ks = solver.solve(p.matrix(), b, C, du, dl, ev.symmetric, opt, stats);
      if (ks.needs_matrix) {
        log::debug("  the solver needs the tangent: assembling it");
        if (!add_tangent()) return res;
        opt.matrix_current = true;
        ks = solver.solve(p.matrix(), b, C, du, dl, ev.symmetric, opt, stats);
      }
      last_stale = ks.stale_factor;
      force_fresh = false;
    } catch (const SingularSystem& e) {
      res.singular = true;
      res.singular_equations = e.equations();
      res.reason = "the system of equations is singular";
      res.cause = FailureCause::Singular;
      return res;
    }
    // line search: a frictional gap whose slip would reverse past its stick band stops the step
    // where its slip turns (the slip branch has no stiffness along the slip, so the full step
    // would jump over the whole band)
    const double alpha = p.step_limit(du, dl);
    if (alpha < 1.0) {
      for (double& v : du) v *= alpha;
      for (double& v : dl) v *= alpha;
      log::debug("  step limited to {:.3g} of the correction (slip reversal)", alpha);
    }
    p.apply(du, dl);
    ++res.iterations;
    if (stats) ++stats->iterations;
    std::array<double, kNumFields> cmax{};
    for (std::size_t i = 0; i < du.size(); ++i) {
      const int f = static_cast<int>(p.equation_field(static_cast<LocalIndex>(i)));
      cmax[f] = std::max(cmax[f], std::abs(du[i]));
    }
    // ---- evaluate at the new state (with the tangent after all where a status change altered
    // it: the solver must see the new matrix)
    if (!evaluate(tangent_wanted())) return res;
    if (!ev.tangent && ev.stiffness_changed && !add_tangent()) return res;
    if (requested_cutback()) return res;
    if (ev.status_changes == 0)
      for (int f = 0; f < kNumFields; ++f) flux[f] = std::max(flux[f], ev.flux[f]);
    if (ev.status_changes > 0) {
      ++res.severe_iterations;
      for (ElemId e : ev.changed)
        if (++flips[e] >= c.chatter_flips) res.chattering.push_back(e);
      std::vector<ElemId> changed = ev.changed;
      std::sort(changed.begin(), changed.end());
      turning_back =
          std::includes(last_changed.begin(), last_changed.end(), changed.begin(), changed.end())
              ? turning_back + 1
              : 0;
      last_changed = std::move(changed);
      if (!res.chattering.empty()) {
        std::sort(res.chattering.begin(), res.chattering.end());
        res.chattering.erase(std::unique(res.chattering.begin(), res.chattering.end()),
                             res.chattering.end());
        res.reason = "contact status is chattering";
        res.cause = FailureCause::Chattering;
        return res;
      }
    } else {
      ++equilibrium_iterations;
    }
    // ---- convergence check
    const auto inc = p.increment_max();
    bool converged = ev.status_changes == 0 && ev.constraint_max <= p.constraint_tolerance();
    bool within_stale_share = true; // every field also within kStaleAcceptance of its R_n
    double worst_ratio = 0.0;
    for (int f = 0; f < kNumFields; ++f) {
      if (!ev.has_field[f]) continue;
      const NewtonControls::Field& fc = c.field[f];
      const double qt =
          fc.user_flux > 0 ? fc.user_flux : (history.sum[f] + flux[f]) / (history.n + 1);
      const double r = ev.residual_max[f];
      // zero flux: a field whose time-averaged flux is below q~_0 (round-off heat in a coupled step
      // without heat load) is converged once its residual is below epsilon q~_0; it does not count
      // in the ratio
      if (qt < fc.initial_flux && r <= fc.zero_flux_ratio * fc.initial_flux) continue;
      // (no scale yet when every evaluation so far changed contact status: not converged)
      if (qt > 0) worst_ratio = std::max(worst_ratio, r / qt);
      if (!std::isfinite(r)) worst_ratio = std::numeric_limits<double>::infinity();
      bool ok;
      if (qt <= 0)
        ok = false;
      else if (r <= fc.linear_ratio * qt)
        ok = true;
      else
        ok = r <= fc.residual_ratio * qt && cmax[f] <= fc.correction_ratio * inc[f];
      converged &= ok;
      within_stale_share &=
          qt > 0 && r <= std::max(kStaleAcceptance * fc.residual_ratio, fc.linear_ratio) * qt;
    }
    // A modified-Newton iterate (from a stale factor) converges linearly: when it first meets R_n
    // its error is of the order of the tolerance, where full Newton's quadratic step lands far
    // below it. Such an iterate is accepted once it is also within kStaleAcceptance of R_n, or
    // after kStaleRefinements more (cheap, residual-only) stale iterations while they still
    // reduce the residual, so that the answer is about as converged as full Newton's.
    if (converged && last_stale && !within_stale_share && res.refinements < kStaleRefinements &&
        std::isfinite(previous_ratio) && worst_ratio < previous_ratio) {
      converged = false;
      ++res.refinements;
    }
    res.residual_history.push_back(worst_ratio);
    residual_ratio_now = worst_ratio;
    log::debug("  iteration {}: residual/flux {:.3e}, status changes {}{}, constraint {:.3e}",
               res.iterations, worst_ratio, ev.status_changes,
               ev.branch_changes > 0
                   ? fmt::format(" (force-law gaps opened or closed: {})", ev.branch_changes)
                   : std::string(),
               ev.constraint_max);
    if (converged) {
      const int augmented = p.augment();
      if (augmented == 0) {
        res.converged = true;
        res.flux = flux;
        return res;
      }
      // The augmented multipliers change the residual: re-evaluate and keep iterating.
      if (++res.augmentations > c.max_augmentations) {
        res.reason = fmt::format("augmented Lagrange did not reach its penetration tolerance in {} "
                                 "augmentations; increase the penalty stiffness",
                                 c.max_augmentations);
        res.cause = FailureCause::Augmentation;
        return res;
      }
      if (!evaluate(tangent_wanted())) return res;
      if (!ev.tangent && ev.stiffness_changed && !add_tangent()) return res;
      if (requested_cutback()) return res;
      equilibrium_iterations = 0;
      increases = 0;
      previous_ratio = std::numeric_limits<double>::infinity();
      continue;
    }
    if (!std::isfinite(worst_ratio)) {
      res.reason = "the residual is not finite";
      res.cause = FailureCause::NonFinite;
      return res;
    }
    // A stale factor that no longer contracts the residual well is replaced: "well" is 10x, or
    // half as well as a fresh factor did in this increment or the step's earlier ones when full
    // Newton itself contracts slowly (a penalty law's kinks), so that the stale step is not
    // blamed for the physics; a stale step that lets the residual grow is always replaced. (Not
    // blaming a stale iteration that crossed force-law kinks (Evaluation::branch_changes) was
    // tried: the forced fresh factor is what teaches this rule that the physics is slow, and
    // without it the penalty 11k block took 13 factorisations instead of 2.)
    if (std::isfinite(previous_ratio) && previous_ratio > 0 && ev.status_changes == 0) {
      const double contraction = worst_ratio / previous_ratio;
      if (!last_stale)
        fresh_contraction = res.fresh_contraction = contraction;
      else if (contraction > std::max(c.stale_contraction, std::min(2.0 * fresh_contraction, 1.0)))
        force_fresh = true;
    }
    if (ev.status_changes == 0) {
      if (worst_ratio > previous_ratio)
        ++increases;
      else
        increases = 0;
      if (equilibrium_iterations >= c.divergence_check_after && increases >= 2) {
        res.reason = fmt::format("the solution is diverging (residual/flux {:.3e})", worst_ratio);
        res.cause = FailureCause::Diverging;
        return res;
      }
    }
    previous_ratio = worst_ratio;
    if (equilibrium_iterations >= c.max_equilibrium_iterations) {
      res.reason = fmt::format("no convergence in {} equilibrium iterations (residual/flux {:.3e})",
                               equilibrium_iterations, worst_ratio);
      res.cause = FailureCause::Iterations;
      return res;
    }
    if (res.severe_iterations > c.max_severe_iterations) {
      res.reason =
          fmt::format("contact status did not settle in {} iterations", c.max_severe_iterations);
      res.cause = FailureCause::Status;
      return res;
    }
  }
}

} // namespace gapfem
