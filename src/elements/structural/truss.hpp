#pragma once
/// @file truss.hpp
/// Two-node linear elastic trusses T2D2 (planar, DOFs 1-2) and T3D2 (DOFs 1-3), Abaqus Analysis
/// User's Manual, "Truss elements": constant axial strain, cross-section area from
/// *SOLID SECTION (default 1), thermal strain from the predefined temperature field.
///
///   small strain (no NLGEOM): eps = n0 . (u2 - u1) / L along the initial axis n0,
///                             N = E A (eps - eps_th).
///   NLGEOM: exact large rotations; logarithmic strain eps = ln(l/L), true stress
///           sigma = E (eps - eps_th), N = sigma A with A held constant (docs/theory/structural.md
///           explains this choice); consistent tangent K = (EA/l) n n^T + (N/l)(I - n n^T).
///
/// Loads: GRAV (rho A g per unit length) and BX/BY/BZ (force per volume times A), lumped half to
/// each node (exact for a straight member with linear interpolation).
/// Output: S11 (true stress), E11 (total strain; logarithmic with NLGEOM), SF1 (axial force).
/// Mass (with *DENSITY): lumped, rho A L / 2 per node and direction (Abaqus's first-order
/// elements lump their mass), rho at the element's mean temperature; no damping operator.
#include "elements/element_kernel.hpp"
#include "model/material.hpp"

namespace gapfem {

/// T2D2 / T3D2 kernel. Immutable; thread-safe.
class TrussKernel final : public ElementKernel {
 public:
  TrussKernel(ElementType type, Material material, double area);

  ElementType type() const override { return _type; }
  std::span<const DofType> node_dofs(int local_node) const override;
  bool uses_temperature_field() const override;
  std::string validate(const ElementInput& in) const override;
  void evaluate(const ElementInput& in, ElementOutput& out) const override;
  /// dN / l (I - n n^T), dN = E A / l times the stretch along du (log strain, as the NLGEOM
  /// tangent).
  bool stress_stiffness(const ElementInput& in, std::span<const double> du,
                        std::span<double> K) const override;
  bool has_mass() const override { return !_material.density.empty(); }
  bool has_damping() const override { return false; }
  bool supports_load(DistLoadKind kind, int face) const override;
  void load(const ElementInput& in, const DistributedLoad& load, double magnitude,
            double sink_temperature, std::span<double> f_ext,
            std::span<double> tangent) const override;
  bool supports_output(ElemVar var) const override;
  void recover(const ElementInput& in, ElementRecovery& out) const override;

  /// Axial response at the input state.
  struct Axial {
    double strain = 0.0; ///< total strain (logarithmic with NLGEOM)
    double stress = 0.0; ///< E (strain - thermal strain)
    double force = 0.0;  ///< stress * area
    double dN_dl = 0.0;  ///< d force / d length
  };
  Axial axial(const ElementInput& in) const;

 private:
  ElementType _type;
  Material _material;
  double _area;
  int _ndim;
};

/// Factory for T2D2/T3D2 blocks (InputError for a missing *SOLID SECTION, material or *ELASTIC).
std::unique_ptr<ElementKernel> make_truss_kernel(const KernelContext& ctx);

} // namespace gapfem
