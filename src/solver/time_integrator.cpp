#include "solver/time_integrator.hpp"

namespace gapfem {

OperatorWeights TimeIntegrator::weights() const {
  const RateCoefficients c = coefficients();
  return {1.0, c.v_du, c.a_du};
}

bool TimeIntegrator::needs_rate_history() const {
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

std::unique_ptr<TimeIntegrator> make_time_integrator(const StepContext& ctx) {
  if (ctx.transient) return std::make_unique<BackwardEuler>();
  return nullptr;
}

} // namespace gapfem
