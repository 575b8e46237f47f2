#pragma once
/// @file point_inertia.hpp
/// Point inertias with Abaqus semantics (Abaqus Analysis User's Guide, "Point masses" and
/// "Rotary inertia"): MASS carries the mass m of *MASS on the translational DOFs of its node
/// (1-3; 1-2 in planar models), ROTARYI the inertia tensor of *ROTARY INERTIA (I11, I22, I33, I12,
/// I13, I23 about the node, global axes) on its rotational DOFs (4-6; 6 alone in planar models).
/// They have no stiffness: their residual and tangent are zero, their mass block is m I or the
/// tensor (docs/conventions.md, "Mass and damping"); GRAV loads a MASS element with m g. Under
/// NLGEOM the rotary inertia stays in global axes (it does not rotate with the node). ALPHA gives
/// the element the damping block alpha M (Rayleigh mass-proportional damping).
#include "elements/element_kernel.hpp"
#include "model/section.hpp"

#include <array>

namespace gapfem {

class PointInertiaKernel final : public ElementKernel {
 public:
  PointInertiaKernel(ElementType type, const MassSection& section, ModelSpace space);

  ElementType type() const override { return _type; }
  std::span<const DofType> node_dofs(int) const override {
    return std::span<const DofType>(_dofs.data(), _n);
  }
  void evaluate(const ElementInput& in, ElementOutput& out) const override;
  bool has_mass() const override { return true; }
  /// ALPHA on *MASS / *ROTARY INERTIA: mass-proportional damping C = alpha M (Abaqus applies it
  /// in direct-integration dynamics; the assembler adds C v in every step with rates)
  bool has_damping() const override { return _alpha != 0.0; }
  bool supports_load(DistLoadKind kind, int face) const override {
    return _type == ElementType::MASS && kind == DistLoadKind::Gravity && face == 0;
  }
  void load(const ElementInput& in, const DistributedLoad& load, double magnitude, double sink,
            std::span<double> f_ext, std::span<double> tangent) const override;

 private:
  ElementType _type;
  std::array<DofType, 3> _dofs{};
  int _n = 0;
  std::array<double, 9> _M{}; ///< the _n x _n mass block
  double _alpha = 0.0;        ///< ALPHA: C = alpha M
};

/// Factory for MASS and ROTARYI blocks: the block's *MASS / *ROTARY INERTIA (InputError naming the
/// element and the keyword it needs otherwise).
std::unique_ptr<ElementKernel> make_point_inertia_kernel(const KernelContext& ctx);

} // namespace gapfem
