#pragma once
/// @file nonlinear_problem.hpp
/// What Newton knows about the physics: evaluate at the trial state (residual, tangent, active
/// constraints), apply a correction, and a few measures for the convergence criteria.
#include "common/types.hpp"
#include "linalg/constraint_block.hpp"
#include "linalg/csr_matrix.hpp"

#include <array>
#include <limits>
#include <span>
#include <vector>

namespace gapfem {

/// Result of one evaluation at the trial state.
struct Evaluation {
  std::array<double, kNumFields> residual_max{}; ///< max |r| over the free equations of each field
  std::array<LocalIndex, kNumFields> residual_eq{-1, -1, -1};
  std::array<double, kNumFields> flux{};    ///< average force/flux magnitude this iteration
  std::array<bool, kNumFields> has_field{}; ///< the field has free equations
  double constraint_max = 0.0;              ///< max |g| of the active constraint rows
  int status_changes = 0;
  int branch_changes = 0; ///< force-law gaps that opened or closed (AssemblyResult)
  /// a status change altered the tangent itself (ElementOutput::stiffness_changed)
  bool stiffness_changed = false;
  std::vector<ElemId> changed; ///< elements whose contact status changed
  bool symmetric = true;
  bool friction = false; ///< some closed gap has friction
  /// the elements' time-increment request (AssemblyResult::dt_ratio); infinity: none
  double dt_ratio = std::numeric_limits<double>::infinity();
  /// matrix() holds the tangent at this state (false: an evaluation of the residual alone)
  bool tangent = true;
};

class NonlinearProblem {
 public:
  virtual ~NonlinearProblem() = default;
  /// Assemble residual and constraints at the trial state, and the tangent when `tangent` (else
  /// matrix() keeps whatever an earlier evaluation or the solver left in it: Newton asks for the
  /// residual alone while the solver reuses a kept factor). May throw ConvergenceFailure.
  virtual Evaluation evaluate(bool tangent) = 0;
  /// The tangent at the state of the last evaluation, which was made without it: the elements see
  /// the history that evaluation saw, so its residual, constraints and status changes stand
  /// (Evaluation::symmetric and friction of the tangent's assembly are returned). May throw
  /// ConvergenceFailure.
  virtual Evaluation assemble_tangent() = 0;
  /// The tangent over the free equations (valid after evaluate; the solver may overwrite it).
  virtual CsrMatrix& matrix() = 0;
  /// -residual over the free equations.
  virtual std::span<const double> rhs() const = 0;
  virtual const ConstraintBlock& constraints() const = 0;
  /// u += du on the free equations; multipliers of the active rows += dl.
  virtual void apply(std::span<const double> du, std::span<const double> dl) = 0;
  virtual Field equation_field(LocalIndex eq) const = 0;
  /// max |u - u_start| per field over all slots (the increment so far).
  virtual std::array<double, kNumFields> increment_max() const = 0;
  /// Closed-gap clearance tolerance (length).
  virtual double constraint_tolerance() const = 0;
  /// Augmented Lagrange: at a converged state, update multiplier estimates that do not yet meet
  /// their tolerance. Returns how many changed (0: the state is final).
  virtual int augment() { return 0; }
  /// The increment's operators (the integrator's weights of K, C and M) are those of the
  /// increment before, in a step whose rates carry history (a dynamic step at an unchanged
  /// increment size): Newton may then start from the residual alone and the kept factor, as it
  /// continues (a linear increment: one back-substitution). False: start with the tangent.
  virtual bool operators_as_before() const { return false; }
  /// Line search: the fraction (0, 1] of the correction (du over the free equations, dl over the
  /// active rows) to apply.
  virtual double step_limit(std::span<const double> du, std::span<const double> dl) { return 1.0; }
};

} // namespace gapfem
