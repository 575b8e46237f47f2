#include "solver/time_integrator.hpp"

namespace gapfem {

OperatorWeights TimeIntegrator::weights() const {
  const RateCoefficients c = coefficients();
  const double w = inertia_weight();
  return {1.0, c.v_du, w * c.a_du, w};
}

bool TimeIntegrator::needs_rate_history() const {
  if (second_order()) return true;
  const RateCoefficients c = coefficients();
  return c.velocity_has_history() || c.acceleration_has_history();
}

void TimeIntegrator::rates(std::span<const double> u, std::span<const double> u_n,
                           std::span<const double> v_n, std::span<const double> a_n,
                           std::span<double> v, std::span<double> a) const {
  const RateCoefficients c = coefficients();
  for (std::size_t k = 0; k < u.size(); ++k) {
    const double du = u[k] - u_n[k];
    const double v0 = v_n.empty() ? 0.0 : v_n[k];
    const double a0 = a_n.empty() ? 0.0 : a_n[k];
    v[k] = c.velocity(du, v0, a0);
    if (c.second_order) a[k] = c.acceleration(du, v0, a0);
  }
}

RateCoefficients HilberHughesTaylor::coefficients() const {
  RateCoefficients c;
  if (!(_dt > 0.0)) return c;
  const double b = _beta, g = _gamma, h = _dt;
  c.first_order = c.second_order = true;
  c.a_du = 1.0 / (b * h * h);
  c.a_v = -1.0 / (b * h);
  c.a_a = -(0.5 / b - 1.0);
  c.v_du = g / (b * h);
  c.v_v = 1.0 - g / b;
  c.v_a = h * (1.0 - 0.5 * g / b);
  return c;
}

bool HilberHughesTaylor::midpoint(double dt, std::span<const double> u, std::span<const double> u_n,
                                  std::span<const double> v_n, std::span<const double> a_n,
                                  std::span<double> u_mid) const {
  const double b = _beta, h = 0.5 * dt;
  for (std::size_t k = 0; k < u.size(); ++k) {
    const double v0 = v_n.empty() ? 0.0 : v_n[k], a0 = a_n.empty() ? 0.0 : a_n[k];
    const double du = u[k] - u_n[k];
    const double a = (du - dt * v0 - dt * dt * (0.5 - b) * a0) / (b * dt * dt);
    u_mid[k] = u_n[k] + h * v0 + h * h * ((0.5 - b) * a0 + b * 0.5 * (a0 + a));
  }
  return true;
}

RateCoefficients BackwardEulerDynamic::coefficients() const {
  RateCoefficients c;
  if (!(_dt > 0.0)) return c;
  c.first_order = c.second_order = true;
  c.v_du = 1.0 / _dt;
  c.a_du = 1.0 / (_dt * _dt);
  c.a_v = -1.0 / _dt;
  return c;
}

std::unique_ptr<TimeIntegrator> make_time_integrator(const StepContext& ctx) {
  if (ctx.transient) return std::make_unique<BackwardEuler>();
  return nullptr;
}

} // namespace gapfem
