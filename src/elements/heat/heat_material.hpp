#pragma once
/// @file heat_material.hpp
/// Thermal properties of one material for the heat-transfer and coupled elements: the isotropic
/// conductivity k(T) with dk/dT, and the volumetric heat capacity C(T) = rho(T) c(T) with its
/// internal energy per unit volume E(T) = integral of C from a reference temperature.
///
/// The capacity term of the heat equation is written with the internal energy, as in the Abaqus
/// Theory Guide ("Uncoupled heat transfer analysis": rho dU/dt): backward Euler gives the rate
/// (E(T) - E(T_start)) / dt, whose derivative is C(T) / dt. For a constant C this is the familiar
/// C (T - T_start) / dt; with temperature-dependent data it stores exactly the heat E(T) -
/// E(T_start), so the heat balance of a step closes without a time-discretisation error.
///
/// Tables are piecewise linear with constant extrapolation (model/table.hpp); rho c is then
/// piecewise quadratic between the merged breakpoints of both tables, and E is integrated exactly
/// (Simpson's rule on each interval).
#include "model/material.hpp"

#include <vector>

namespace gapfem {

class HeatMaterial {
 public:
  /// Copies the tables of `m`. *CONDUCTIVITY must be present (the reader checks it).
  explicit HeatMaterial(const Material& m);

  const std::string& name() const { return _name; }
  /// Both *DENSITY and *SPECIFIC HEAT are given (needed by transient steps).
  bool has_capacity() const { return !_rho.empty() && !_c.empty(); }
  /// The conductivity depends on temperature (the conduction tangent is then unsymmetric).
  bool conductivity_varies() const { return _k.n_rows() > 1; }
  /// k(T) and dk/dT.
  void conductivity(double T, double& k, double& dk_dT) const {
    _k.evaluate(T, {&k, 1}, {&dk_dT, 1});
  }
  /// Volumetric heat capacity rho(T) c(T).
  double capacity(double T) const;
  /// Internal energy per unit volume E(T) (reference: the lowest table temperature).
  double energy(double T) const;

 private:
  std::string _name;
  PropertyTable _k, _rho, _c;
  std::vector<double> _T; ///< merged breakpoints of density and specific heat (ascending)
  std::vector<double> _E; ///< E at the breakpoints
};

} // namespace gapfem
