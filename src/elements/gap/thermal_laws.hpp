#pragma once
/// @file thermal_laws.hpp
/// Thermal interaction laws of the gap elements GAPUNIT and DGAP (spec gap-elements.md §4, §0b),
/// as small immutable objects used by the gap kernels. Every law returns its value together with
/// the partial derivatives the kernels need for a consistent tangent.
///
///   conduction  q = k(x, Tbar) (T_A - T_B),  Tbar = (T_A + T_B) / 2,  x = clearance h, or the
///               contact pressure p with *GAP CONDUCTANCE, PRESSURE
///   radiation   q = C(h) [(T_A - T_Z)^4 - (T_B - T_Z)^4],  C = F(h) sigma / (1/eps_A + 1/eps_B -
///   1) friction    a dissipation rate r is split into f eta r (node 1) and (1 - f) eta r (node 2)
///
/// q is a flux per unit area, positive from side A (gap node 1) to side B (gap node 2).
#include "common/error.hpp"

#include <vector>

namespace gapfem {

struct GapConductanceSpec;
struct GapRadiationSpec;
struct GapHeatGenerationSpec;
struct PhysicalConstants;

/// Conductance and its partial derivatives.
struct ConductanceValue {
  double k = 0.0;     ///< conductance (flux per area per degree)
  double dk_dx = 0.0; ///< d k / d clearance (or pressure)
  double dk_dT = 0.0; ///< d k / d mean temperature
};

/// A gap flux per area and its partial derivatives.
struct GapFluxValue {
  double q = 0.0;      ///< flux per area from node 1 (A) to node 2 (B)
  double dq_dTa = 0.0; ///< d q / d T_A
  double dq_dTb = 0.0; ///< d q / d T_B
  double dq_dx = 0.0;  ///< d q / d clearance (conduction with PRESSURE: d q / d pressure)
};

/// *GAP CONDUCTANCE: k(x, Tbar), piecewise linear in x and in the mean temperature. The data lines
/// are grouped by temperature, as Abaqus tabulates them (all x values of the lowest temperature
/// first); between the groups k is interpolated linearly in temperature, outside them it is the
/// nearest group's. Within a group: below the first x the first conductance holds; beyond the last
/// x a clearance table drops to zero ("zero conductance just past the last clearance point"),
/// a pressure table keeps the last conductance.
class GapConductanceLaw {
 public:
  /// Throws InputError (at the keyword) when the temperature groups are not in ascending order.
  explicit GapConductanceLaw(const GapConductanceSpec& spec);

  /// True with *GAP CONDUCTANCE, PRESSURE: x is the contact pressure.
  bool pressure_dependent() const { return _pressure; }
  /// k(x, Tbar) with its partial derivatives (zero across the drop past the last clearance).
  ConductanceValue evaluate(double x, double mean_temperature) const;
  /// Conduction flux q = k(x, (T_A + T_B)/2) (T_A - T_B) with its partial derivatives.
  GapFluxValue conduction(double Ta, double Tb, double x) const;

 private:
  struct Group {
    double temperature = 0.0;
    std::vector<double> x, k;
  };
  void group_value(const Group& g, double x, double& k, double& dk_dx) const;

  std::vector<Group> _groups;
  bool _pressure = false;
};

/// *GAP RADIATION with *PHYSICAL CONSTANTS: q = C(h) [(T_A - T_Z)^4 - (T_B - T_Z)^4]. The view
/// factor F(h) is piecewise linear in the clearance with constant values outside the table.
class GapRadiationLaw {
 public:
  /// Throws InputError (at *GAP RADIATION) when ABSOLUTE ZERO or STEFAN BOLTZMANN is missing.
  GapRadiationLaw(const GapRadiationSpec& spec, const PhysicalConstants& constants);

  /// C(h) = F(h) sigma / (1/eps_A + 1/eps_B - 1); optionally dC/dh.
  double coefficient(double h, double* dC_dh = nullptr) const;
  /// Radiation flux from node 1 (A) to node 2 (B) across clearance h, with its derivatives.
  GapFluxValue evaluate(double Ta, double Tb, double h) const;
  double absolute_zero() const { return _zero; }

 private:
  std::vector<double> _h, _F;
  double _factor = 0.0; ///< sigma / (1/eps_A + 1/eps_B - 1)
  double _zero = 0.0;
};

/// Heat of one gap node from frictional dissipation.
struct HeatSplit {
  double node1 = 0.0; ///< f eta r
  double node2 = 0.0; ///< (1 - f) eta r
};

/// *GAP HEAT GENERATION: node 1 (slave side) receives f eta r, node 2 (1 - f) eta r (spec §0b).
class GapHeatGeneration {
 public:
  explicit GapHeatGeneration(const GapHeatGenerationSpec& spec);
  GapHeatGeneration(double eta, double fraction) : _eta(eta), _f(fraction) {}
  /// Split of the dissipation rate r (the split is linear: d node_i / d r = node_i(1)).
  HeatSplit split(double dissipation_rate) const {
    return {_f * _eta * dissipation_rate, (1.0 - _f) * _eta * dissipation_rate};
  }
  double eta() const { return _eta; }
  double fraction() const { return _f; }

 private:
  double _eta = 1.0, _f = 0.5;
};

} // namespace gapfem
