#pragma once
/// @file material.hpp
/// Material property records (*MATERIAL and its sub-options), temperature tables interpolated
/// linearly with constant extrapolation.
#include "common/error.hpp"
#include "model/table.hpp"

#include <optional>
#include <string>

namespace gapfem {

/// *DAMPING in a material (docs/theory/dynamics.md, "Rayleigh damping"): the Rayleigh factors of
/// direct-integration dynamics, C_e = alpha M_e + beta K_e per element of the material, and the
/// factors Abaqus uses only in mode-based and frequency-domain procedures (kept for messages).
struct RayleighDamping {
  double alpha = 0.0;      ///< ALPHA: mass-proportional factor alpha_R (1/time), >= 0
  double beta = 0.0;       ///< BETA: stiffness-proportional factor beta_R (time), >= 0
  double structural = 0.0; ///< STRUCTURAL: frequency-domain procedures only (not used)
  double composite = 0.0;  ///< COMPOSITE: modal procedures only (not used)
  SourceLocation loc;      ///< the (first) *DAMPING line
  unsigned given = 0;      ///< parameters given: ALPHA 1, BETA 2, STRUCTURAL 4, COMPOSITE 8
  /// alpha or beta non-zero: the material's elements get a damping block in *DYNAMIC steps
  bool viscous() const { return alpha != 0.0 || beta != 0.0; }
};

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
  std::optional<RayleighDamping> damping; ///< *DAMPING, when given

  bool has_elastic() const { return !elastic.empty(); }
  /// Young's modulus and Poisson's ratio at temperature T.
  void elastic_at(double temperature, double& E, double& nu) const;
  /// Thermal strain alpha(T)(T - T0) - alpha(T_init)(T_init - T0) with Abaqus's secant definition.
  double thermal_strain(double temperature, double initial_temperature) const;
  /// d(thermal strain)/dT at T.
  double thermal_strain_derivative(double temperature) const;
};

} // namespace gapfem
