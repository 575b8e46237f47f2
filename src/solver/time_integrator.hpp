#pragma once
/// @file time_integrator.hpp
/// The time-integrator seam (OpenSees's TransientIntegrator, MFEM's ODESolver): owned by the step
/// problem, it maps (u; u_n, v_n, a_n, dt) to the trial rates (v, a) and gives the weights of K, C
/// and M in the effective tangent, k K + c C + m M with k = 1, c = dv/du, m = da/du
/// (fem/assembler.hpp, OperatorWeights). Element kernels never see it nor dt: they get its
/// coefficients (elements/rate_coefficients.hpp) through StepContext::rates.
///
/// Backward Euler is the first integrator: the transient heat-transfer and coupled steps' capacity
/// and the automatic stabilization's viscous forces of static steps (in the step's pseudo-time).
/// Static steps have none (quasi-static: no rates, the weights of C and M are 0). *DYNAMIC has
/// Hilber-Hughes-Taylor (HHT) and second-order backward Euler (APPLICATION=QUASI-STATIC), whose
/// rates carry history (v_n, a_n): the solution state then keeps v, a and their committed copies
/// (needs_rate_history()).
///
/// HHT's equation at t + dt, M a + (1 + alpha) R(t + dt) - alpha R(t) = 0 with R = I - P + L
/// everything but inertia (internal, damping, external and constraint forces), is solved divided
/// by 1 + alpha so that the constraint forces are the physical ones at t + dt:
///   M a / (1 + alpha) + R(t + dt) - alpha / (1 + alpha) R(t) = 0,
/// hence inertia_weight() = 1 / (1 + alpha) on M a (and on M in the tangent) and
/// history_weight() = -alpha / (1 + alpha) on the committed R(t) (StepProblem keeps it).
#include "elements/rate_coefficients.hpp"
#include "fem/assembler.hpp"

#include <memory>
#include <span>
#include <string_view>

namespace gapfem {

class TimeIntegrator {
 public:
  virtual ~TimeIntegrator() = default;
  virtual std::string_view name() const = 0;
  /// Start (an attempt of) an increment of size dt.
  virtual void begin_increment(double dt) = 0;
  /// The affine maps of the current increment from (u - u_n, v_n, a_n) to (v, a).
  virtual RateCoefficients coefficients() const = 0;
  /// The weight in the effective tangent of a damping operator scaled by `damping`, that is
  /// damping * dv/du, formed as the integrator forms it (backward Euler: damping / dt).
  virtual double damping_weight(double damping) const = 0;

  /// The factor of the inertia forces M a in the residual (HHT: 1 / (1 + alpha)).
  virtual double inertia_weight() const { return 1.0; }
  /// The factor of the committed non-inertial residual R(t) in the residual (HHT: -alpha / (1 +
  /// alpha)); 0: none is kept.
  virtual double history_weight() const { return 0.0; }

  /// The state halfway through the increment of size dt that ends at u (for the half-increment
  /// residual of automatic incrementation): writes u_mid per slot and returns true, or false
  /// when the integrator has no such rule (then u_mid is untouched).
  virtual bool midpoint(double dt, std::span<const double> u, std::span<const double> u_n,
                        std::span<const double> v_n, std::span<const double> a_n,
                        std::span<double> u_mid) const {
    return false;
  }

  /// The weights of K, C and M in the effective tangent: 1, dv/du, inertia_weight() da/du; the
  /// residual's factor of M a (OperatorWeights::inertia).
  OperatorWeights weights() const;
  /// Does the integrator solve a second-order problem (its rates always carry history, also
  /// before the first increment sets dt)?
  virtual bool second_order() const { return false; }
  /// Do the trial rates depend on the committed ones (the solution state must then keep them)?
  bool needs_rate_history() const;
  /// The trial rates per slot from the trial u and the committed u_n, v_n, a_n (v_n, a_n may be
  /// empty: zero); `a` is left alone in a first-order integration.
  void rates(std::span<const double> u, std::span<const double> u_n, std::span<const double> v_n,
             std::span<const double> a_n, std::span<double> v, std::span<double> a) const;
};

/// Backward Euler, first order: v = (u - u_n) / dt, no accelerations.
class BackwardEuler final : public TimeIntegrator {
 public:
  std::string_view name() const override { return "backward Euler"; }
  void begin_increment(double dt) override { _dt = dt; }
  RateCoefficients coefficients() const override { return RateCoefficients::backward_euler(_dt); }
  double damping_weight(double damping) const override { return _dt > 0.0 ? damping / _dt : 0.0; }

 private:
  double _dt = 0.0;
};

/// Newmark's parameters with Hilber-Hughes-Taylor's alpha (-1/2 <= alpha <= 0): from u = u_n + du,
///   a = du / (beta dt^2) - v_n / (beta dt) - (1 / (2 beta) - 1) a_n,
///   v = v_n + dt ((1 - gamma) a_n + gamma a).
/// alpha = 0, beta = 1/4, gamma = 1/2 is the trapezoidal rule.
class HilberHughesTaylor final : public TimeIntegrator {
 public:
  HilberHughesTaylor(double alpha, double beta, double gamma)
      : _alpha(alpha), _beta(beta), _gamma(gamma) {}
  /// beta = (1 - alpha)^2 / 4 and gamma = 1/2 - alpha: second order, unconditionally stable.
  static HilberHughesTaylor with_alpha(double alpha) {
    return {alpha, 0.25 * (1.0 - alpha) * (1.0 - alpha), 0.5 - alpha};
  }
  std::string_view name() const override { return "Hilber-Hughes-Taylor"; }
  void begin_increment(double dt) override { _dt = dt; }
  RateCoefficients coefficients() const override;
  double damping_weight(double damping) const override { return damping * coefficients().v_du; }
  double inertia_weight() const override { return 1.0 / (1.0 + _alpha); }
  double history_weight() const override { return -_alpha / (1.0 + _alpha); }
  bool second_order() const override { return true; }
  /// Newmark's displacement over dt/2 with the acceleration's mean a_mid = (a_n + a) / 2 (a the
  /// acceleration at the end): u_mid = u_n + h v_n + h^2 ((1/2 - beta) a_n + beta a_mid), h = dt/2
  /// (Hibbitt and Karlsson's half-step state).
  bool midpoint(double dt, std::span<const double> u, std::span<const double> u_n,
                std::span<const double> v_n, std::span<const double> a_n,
                std::span<double> u_mid) const override;
  double alpha() const { return _alpha; }
  double beta() const { return _beta; }
  double gamma() const { return _gamma; }

 private:
  double _alpha, _beta, _gamma;
  double _dt = 0.0;
};

/// Backward Euler for second-order problems (*DYNAMIC, APPLICATION=QUASI-STATIC):
///   v = du / dt,  a = (v - v_n) / dt = du / dt^2 - v_n / dt.
class BackwardEulerDynamic final : public TimeIntegrator {
 public:
  std::string_view name() const override { return "backward Euler (dynamic)"; }
  bool second_order() const override { return true; }
  void begin_increment(double dt) override { _dt = dt; }
  RateCoefficients coefficients() const override;
  double damping_weight(double damping) const override { return _dt > 0.0 ? damping / _dt : 0.0; }

 private:
  double _dt = 0.0;
};

/// The step's integrator from its context: backward Euler in transient heat-transfer and coupled
/// steps (StepContext::transient), none (quasi-static) otherwise.
std::unique_ptr<TimeIntegrator> make_time_integrator(const StepContext& ctx);

} // namespace gapfem
