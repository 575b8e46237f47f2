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

#include <string>

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

NewtonResult solve_increment(NonlinearProblem& problem, ConstrainedSolver& solver,
                             const NewtonControls& c, const FluxHistory& history,
                             RunStatistics* stats);

} // namespace gapfem
