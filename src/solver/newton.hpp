#pragma once
/// @file newton.hpp
/// Newton–Raphson for one increment with Abaqus/Standard's default criteria (per field):
///   residual:   r_max <= R_n * q~   (R_n = 0.005), with q~ the time-averaged flux of the step
///   correction: c_max <= C_n * du_max (C_n = 0.01), du_max the largest increment of the field
///   a field whose r_max <= 1e-8 q~ is converged regardless of the correction (linear increments)
/// plus, with contact, no status change in the last evaluation and every closed gap within the
/// clearance tolerance. Contact status changes make "severe discontinuity" iterations.
#include "common/timer.hpp"
#include "linalg/constrained_solver.hpp"
#include "solver/nonlinear_problem.hpp"

#include <span>
#include <string>
#include <unordered_map>
#include <vector>

namespace gapfem {

struct NewtonControls {
  /// Convergence criteria of one field (Abaqus *CONTROLS, PARAMETERS=FIELD).
  struct Field {
    double residual_ratio = 0.005;  ///< R_n
    double correction_ratio = 0.01; ///< C_n
    double linear_ratio = 1e-8;     ///< epsilon_l
    /// Zero flux (Abaqus epsilon^alpha and q~_0^alpha): a field whose time-averaged flux is below
    /// initial_flux is also converged when its residual is below zero_flux_ratio * initial_flux. A
    /// coupled step with no heat load (uniform temperature) thus converges on its displacements.
    double zero_flux_ratio = 1e-5;
    double initial_flux = 1e-2;
    double user_flux = 0.0; ///< q~_u: when > 0, replaces the time-averaged flux
  };
  std::array<Field, kNumFields> field{};
  int max_equilibrium_iterations = 16; ///< I_C
  int divergence_check_after = 4;      ///< I_0
  int max_severe_iterations = 12;      ///< contact status iterations per attempt
  int chatter_flips = 8;               ///< one element flipping this often is chattering
  int max_augmentations = 25;          ///< augmented-Lagrange updates per increment
  /// factor reuse across iterations and increments (modified Newton with exact contact rows);
  /// a stale-factor iteration that reduces the residual by less than stale_contraction (or, when
  /// a fresh factor contracted less than that in this increment, by less than half as much as it)
  /// forces a fresh factor on the next one
  FactorReuse factor_reuse = FactorReuse::Auto;
  double stale_contraction = 0.1;
  /// While the solver keeps a factor it can reuse (ConstrainedSolver::matrix_optional), evaluate
  /// the residual alone: the tangent's values would not be used. An increment's first evaluation
  /// and any that precedes a fresh factorisation assemble it.
  bool residual_only = true;
  /// The last converged increment of the step took more than one iteration: the step is not
  /// linear, so the first system of the next increment is solved to Newton's looser forcing term
  /// (an iterative backend) rather than in full. Set by the step driver.
  bool nonlinear_step = false;
  /// The residual contraction of the last fresh-factor iteration in the step's earlier
  /// increments (0: none; set by the step driver). The stale-factor check starts from it: where
  /// full Newton itself contracts slowly (a penalty law's kinks), a stale factor is not blamed.
  double fresh_contraction = 0.0;
};

struct FluxHistory {
  std::array<double, kNumFields> sum{}; ///< sum of converged increments' flux in this step
  int n = 0;
};

/// Why an increment attempt failed, for the diagnosis of a step that cannot go on.
enum class FailureCause : std::uint8_t {
  None,
  Element,      ///< an element could not be evaluated (turned inside out, non-finite force)
  Singular,     ///< the Newton system is singular
  Chattering,   ///< contact status flips back and forth
  Status,       ///< contact status did not settle
  Augmentation, ///< augmented Lagrange did not reach its tolerance
  Diverging,    ///< the residual grows
  Iterations,   ///< too many equilibrium iterations
  NonFinite,    ///< the residual is not finite
  Requested     ///< an element asked for a smaller increment (a UEL's PNEWDT < 1)
};

struct NewtonResult {
  bool converged = false;
  int iterations = 0;        ///< linear solves of the Newton system
  int severe_iterations = 0; ///< iterations that changed contact status
  /// stale iterations taken past R_n toward full Newton's accuracy (not counted by automatic
  /// incrementation: they say nothing of how hard the increment was)
  int refinements = 0;
  int augmentations = 0;                 ///< augmented-Lagrange updates
  std::array<double, kNumFields> flux{}; ///< flux of the converged state (for the time average)
  std::string reason;                    ///< why it did not converge
  FailureCause cause = FailureCause::None;
  std::vector<ElemId> chattering;
  std::vector<double> residual_history; ///< worst residual/flux ratio after each iteration
  double fresh_contraction = 0.0;       ///< of the attempt's last fresh-factor iteration (0: none)
  bool singular = false;
  std::vector<LocalIndex> singular_equations;
  /// The elements' time-increment request over the attempt's evaluations (ElementOutput::
  /// dt_ratio): the cut-back ratio of a Requested failure, the growth bound of a converged one
  double dt_ratio = std::numeric_limits<double>::infinity();
};

/// The share of R_n a modified-Newton (stale-factor) iterate must meet (check_convergence).
inline constexpr double kStaleAcceptance = 1e-2;
/// Stale iterations at most past R_n on the way to kStaleAcceptance.
inline constexpr int kStaleRefinements = 2;

/// Abaqus's criteria on one field after an iteration: `flux` the field's time-averaged flux q~,
/// `residual` its largest residual r_max, `correction` its largest correction c_max, `increment`
/// its largest increment du_max.
struct FieldCheck {
  /// false: zero flux (q~ < q~_0 and r_max <= epsilon q~_0), the field neither converges the
  /// iteration nor fails it and is left out of the residual ratio
  bool counted = true;
  bool converged = false;    ///< linear rule (r_max <= epsilon_l q~), or residual and correction
  bool within_stale = false; ///< r_max within kStaleAcceptance of R_n (a stale iterate's bar)
  double ratio = 0.0;        ///< r_max / q~ (0 without a flux scale yet, inf when not finite)
};
FieldCheck check_field(const NewtonControls::Field& controls, double flux, double residual,
                       double correction, double increment);

/// One increment attempt's Newton–Raphson iteration, one method per stage. run() calls them in
/// this order until the attempt converges or fails:
///
///   start                 the first evaluation (with the tangent); nothing to solve, a cut-back
///   solve_system          the Newton system through ConstrainedSolver (residual-only
///                         evaluations while it keeps a factor; a fresh factor when asked)
///   limit_step            line search: the problem's step limit scales the correction
///   apply_correction      u += du; the correction's largest entry per field
///   evaluate_state        the residual at the new state (the tangent where the solver needs it)
///   widen_flux_scale      the increment's flux scale from evaluations without status changes
///   track_status_changes  severe discontinuity iterations, chattering elements
///   check_convergence     Abaqus's criteria per field; a stale iterate's extra refinements
///   augment               at a converged state: augmented Lagrange, or the attempt converged
///   check_finite          a residual that is not finite ends the attempt
///   choose_factor         a stale factor that contracts too slowly is replaced next iteration
///   check_divergence      the residual grew twice in a row past I_0 iterations
///   check_iteration_limits  I_C equilibrium iterations, the severe iterations allowed
///
/// Every stage that returns bool returns false when the attempt is over; result() tells whether
/// it converged and why not. The iteration's state lives in members, so that a procedure that
/// needs another stage (dynamics: the integrator's velocities and accelerations after a
/// correction) adds a method and a call in run() rather than a branch in a loop. Tests drive the
/// stages one by one.
class NewtonIteration {
 public:
  /// `problem`, `solver` and `stats` (may be null) must outlive the object: one attempt.
  NewtonIteration(NonlinearProblem& problem, ConstrainedSolver& solver,
                  const NewtonControls& controls, const FluxHistory& history, RunStatistics* stats);

  /// Iterate to convergence or failure (the stages in order).
  NewtonResult run();

  bool start();
  bool solve_system();
  void limit_step();
  void apply_correction();
  bool evaluate_state();
  void widen_flux_scale();
  bool track_status_changes();
  /// true: the iterate meets the criteria (then augment() decides whether it is final).
  bool check_convergence();
  bool augment();
  bool check_finite();
  void choose_factor();
  bool check_divergence();
  bool check_iteration_limits();

  const NewtonResult& result() const { return _res; }
  const Evaluation& evaluation() const { return _ev; }
  /// The correction of the last solve (after limit_step: the part applied).
  std::span<const double> correction() const { return _du; }
  /// The worst residual/flux ratio of the last convergence check.
  double residual_ratio() const { return _residual_ratio_now; }
  /// The next solve factorises afresh (choose_factor found the stale factor too slow).
  bool fresh_factor_next() const { return _force_fresh; }

 private:
  bool evaluate(bool tangent);
  bool add_tangent();
  bool tangent_wanted() const;
  bool requested_cutback();
  double time_averaged_flux(int field) const;

  NonlinearProblem& _p;
  ConstrainedSolver& _solver;
  NewtonControls _c;
  FluxHistory _history;
  RunStatistics* _stats;
  NewtonResult _res;
  Evaluation _ev; ///< the last evaluation
  std::vector<double> _du, _dl;
  std::array<double, kNumFields> _flux{}; ///< the increment's flux scale so far
  std::array<double, kNumFields> _cmax{}; ///< the last correction's largest entry per field
  std::unordered_map<ElemId, int> _flips; ///< status changes per element
  std::vector<ElemId> _last_changed;      ///< sorted, by the evaluation before the last
  int _turning_back = 0; ///< evaluations in a row that only turned back the one before's changes
  int _increases = 0;    ///< convergence checks in a row whose residual ratio grew
  int _equilibrium_iterations = 0;
  double _worst_ratio = 0.0;                                        ///< of the last check
  double _previous_ratio = std::numeric_limits<double>::infinity(); ///< of the check before
  double _residual_ratio_now = std::numeric_limits<double>::infinity();
  bool _last_stale = false;  ///< the last solve used a stale factor
  bool _force_fresh = false; ///< the next solve factorises afresh
  /// residual ratio over the last fresh-factor iteration (this increment's, or the step's before)
  double _fresh_contraction = 0.0;
};

/// One increment attempt: NewtonIteration(...).run().
NewtonResult solve_increment(NonlinearProblem& problem, ConstrainedSolver& solver,
                             const NewtonControls& c, const FluxHistory& history,
                             RunStatistics* stats);

} // namespace gapfem
