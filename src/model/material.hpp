#pragma once
/// @file material.hpp
/// Material property records (*MATERIAL and its sub-options), temperature tables interpolated
/// linearly with constant extrapolation.
#include "common/error.hpp"
#include "model/table.hpp"

#include <optional>
#include <string>

namespace gapfem {

struct Material {
  std::string name;
  SourceLocation loc;
  PropertyTable elastic; ///< *ELASTIC (ISOTROPIC): values E, nu; key temperature
  PropertyTable density; ///< *DENSITY: rho; key temperature
  PropertyTable
      expansion; ///< *EXPANSION (ISO): alpha (secant, from `expansion_zero`); key temperature
  double expansion_zero = 0.0; ///< *EXPANSION, ZERO= reference temperature of the secant alpha
  PropertyTable conductivity;  ///< *CONDUCTIVITY (ISO): k; key temperature
  PropertyTable specific_heat; ///< *SPECIFIC HEAT: c; key temperature

  bool has_elastic() const { return !elastic.empty(); }
  /// Young's modulus and Poisson's ratio at temperature T.
  void elastic_at(double temperature, double& E, double& nu) const;
  /// Thermal strain alpha(T)(T - T0) - alpha(T_init)(T_init - T0) with Abaqus's secant definition.
  double thermal_strain(double temperature, double initial_temperature) const;
  /// d(thermal strain)/dT at T.
  double thermal_strain_derivative(double temperature) const;
};

} // namespace gapfem
