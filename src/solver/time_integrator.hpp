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
/// Static steps have none (quasi-static: no rates, the weights of C and M are 0). A Newmark or HHT
/// integrator for *DYNAMIC is another class here whose rates carry history (v_n, a_n): the
/// solution state then keeps v, a and their committed copies (needs_rate_history()).
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

  /// The weights of K, C and M in the effective tangent: 1, dv/du, da/du.
  OperatorWeights weights() const;
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

/// The step's integrator from its context: backward Euler in transient heat-transfer and coupled
/// steps (StepContext::transient), none (quasi-static) otherwise.
std::unique_ptr<TimeIntegrator> make_time_integrator(const StepContext& ctx);

} // namespace gapfem
