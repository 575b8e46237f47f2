#pragma once
/// @file gap_thermal.hpp
/// The thermal behaviour of a gap property (*GAP CONDUCTANCE, *GAP RADIATION, *GAP HEAT
/// GENERATION) combined into one flux law, and the DGAP kernel (heat transfer across a gap of
/// constant clearance d). GAPUNIT uses the same law inside the mechanical gap kernel.
#include "elements/element_kernel.hpp"
#include "elements/gap/thermal_laws.hpp"

#include <optional>

namespace gapfem {

struct GapSection;
struct PhysicalConstants;

/// q = q_conduction(h or p, Tbar) + q_radiation(h), per area, positive from node 1 to node 2.
class GapThermalModel {
 public:
  GapThermalModel(const GapSection& section, const PhysicalConstants& constants);
  bool conducts() const { return _conductance.has_value() || _radiation.has_value(); }
  const std::optional<GapHeatGeneration>& heat_generation() const { return _heat; }

  struct Flux {
    double q = 0.0, dq_dTa = 0.0, dq_dTb = 0.0;
    double dq_dh = 0.0; ///< through clearance-dependent conductance and view factor
    double dq_dp = 0.0; ///< through pressure-dependent conductance
    double conductance = 0.0;
  };
  /// Flux across a gap of clearance h carrying contact pressure p. With both a clearance and a
  /// pressure table, the pressure table applies while the gap is closed, the clearance table while
  /// it is open.
  Flux flux(double Ta, double Tb, double h, double p, bool closed) const;

 private:
  std::optional<GapConductanceLaw> _conductance;
  std::optional<GapConductanceLaw> _conductance_closed; ///< pressure table used while closed
  std::optional<GapRadiationLaw> _radiation;
  std::optional<GapHeatGeneration> _heat;
};

/// DGAP: heat transfer only (DOF 11), h = d constant, direction ignored (spec §1.5).
class DgapKernel final : public ElementKernel {
 public:
  explicit DgapKernel(const KernelContext& ctx);
  ElementType type() const override { return ElementType::DGAP; }
  std::span<const DofType> node_dofs(int) const override { return _dofs; }
  void evaluate(const ElementInput& in, ElementOutput& out) const override;
  /// A thermal gap stores no heat (no capacity) and has no inertia.
  bool has_mass() const override { return false; }
  bool has_damping() const override { return false; }
  bool supports_output(ElemVar v) const override { return v == ElemVar::HFL; }
  void recover(const ElementInput& in, ElementRecovery& out) const override;

 private:
  const GapSection& _section;
  GapThermalModel _thermal;
  std::array<DofType, 1> _dofs{DofType::NT};
};

} // namespace gapfem
