#include "model/material.hpp"

#include <array>

namespace gapfem {

void Material::elastic_at(double temperature, double& E, double& nu) const {
  std::array<double, 2> v{};
  elastic.evaluate(temperature, v);
  E = v[0];
  nu = v[1];
}

double Material::thermal_strain(double temperature, double initial_temperature) const {
  if (expansion.empty()) return 0.0;
  // Abaqus: eps_th = alpha(T)(T - T0) - alpha(T_I)(T_I - T0), alpha the secant coefficient about
  // T0.
  const double a = expansion.value(temperature);
  const double ai = expansion.value(initial_temperature);
  return a * (temperature - expansion_zero) - ai * (initial_temperature - expansion_zero);
}

double Material::thermal_strain_derivative(double temperature) const {
  if (expansion.empty()) return 0.0;
  return expansion.value(temperature) +
         expansion.derivative(temperature) * (temperature - expansion_zero);
}

} // namespace gapfem
