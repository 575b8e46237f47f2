#pragma once
/// @file coupled_truss.hpp
/// The coupled temperature-displacement trusses T2D2T (DOFs 1, 2, 11) and T3D2T (1, 2, 3, 11).
/// Mechanics: the T2D2/T3D2 kernel (truss.hpp) with the thermal strain and the temperature of
/// *ELASTIC taken from the average of the two NT DOFs; heat: conduction along the member and
/// lumped capacity with the section area (HeatCore of a two-node link, heat_core.hpp).
///
/// Coupling block: the axial force N = E(Tm) A (eps - eps_th(Tm)), Tm = (T1 + T2)/2, gives
///   d r_u / d T_b = 1/2 A [E'(Tm) (eps - eps_th) - E(Tm) eps_th'(Tm)] [-n; n].
/// The heat equation does not depend on the displacements (reference length).
/// Operators: the truss's lumped mass on the displacements (with *DENSITY), the heat capacity as
/// the damping operator of the temperatures (integrated by the kernel: damping_in_residual).
#include "elements/heat/heat_core.hpp"
#include "elements/solid/coupled_continuum.hpp"
#include "elements/structural/truss.hpp"

namespace gapfem {

class CoupledTrussKernel final : public ElementKernel {
 public:
  CoupledTrussKernel(ElementType type, const Material& material, double area, HeatMaterial heat,
                     InitialTemperatures initial);

  ElementType type() const override { return _type; }
  std::span<const DofType> node_dofs(int local_node) const override;
  std::string validate(const ElementInput& in) const override;
  void evaluate(const ElementInput& in, ElementOutput& out) const override;
  double stored_heat(const ElementInput& in) const override;
  bool has_mass() const override { return _mech.has_mass(); }
  bool has_damping() const override { return _heat.material().has_capacity(); }
  bool damping_in_residual() const override { return true; }
  bool supports_load(DistLoadKind kind, int face) const override;
  void load(const ElementInput& in, const DistributedLoad& load, double magnitude,
            double sink_temperature, std::span<double> f_ext,
            std::span<double> tangent) const override;
  bool supports_output(ElemVar var) const override;
  void recover(const ElementInput& in, ElementRecovery& out) const override;

 private:
  using Heat = HeatCore<Shape::Line2, HeatGeometry::Line>;
  struct Local {
    ElementInput in;
    std::array<double, 6> u{}, u0{};
    Heat::Temps T{}, T0{};
    std::array<double, 2> zeros{};
  };
  void split(const ElementInput& in, Local& l) const;
  int slot(int i) const { return (i / _ndim) * (_ndim + 1) + i % _ndim; }
  HeatLayout layout() const { return {_ndim + 1, _ndim, 2 * (_ndim + 1)}; }

  ElementType _type;
  int _ndim;
  Material _material;
  double _area;
  TrussKernel _mech;
  Heat _heat;
  InitialTemperatures _initial;
};

/// Factory for T2D2T/T3D2T blocks (same section rules as T2D2/T3D2, plus *CONDUCTIVITY).
std::unique_ptr<ElementKernel> make_coupled_truss_kernel(const KernelContext& ctx);

} // namespace gapfem
