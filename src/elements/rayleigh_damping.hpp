#pragma once
/// @file rayleigh_damping.hpp
/// Material Rayleigh damping (*DAMPING, ALPHA=, BETA= in a *MATERIAL) as a kernel decorator: the
/// wrapped kernel's residual, tangent, mass, history, rows and output unchanged, plus the damping
/// block
///
///     C_e = alpha_R M_e + beta_R K_e(u)
///
/// with M_e the kernel's mass block and K_e its tangent at the trial state (docs/theory/
/// dynamics.md, "Rayleigh damping", for why the tangent and what that means under NLGEOM). The
/// assembler adds C_e v to the residual and c C_e to the effective tangent; d(C_e)/du v is left
/// out of the tangent (it vanishes for a linear element; Newton still converges on the residual).
///
/// When the assembler asks for the damping block but not for the tangent or the mass (a
/// residual-only pass), the decorator asks the inner kernel for them into stack scratch of at
/// most kMaxDofs^2 entries: no allocation per evaluation, no mutable state (thread-safe).
#include "elements/element_kernel.hpp"

#include <memory>

namespace gapfem {

struct Material;

/// The decorator. Only kernels whose own evaluate() leaves the damping to the assembler
/// (damping_in_residual() false) and with at most kMaxDofs DOFs can be wrapped.
class RayleighDampingKernel final : public ElementKernel {
 public:
  /// largest element wrapped: C3D20 has 60 DOFs, S8R 48
  static constexpr int kMaxDofs = 64;

  RayleighDampingKernel(std::unique_ptr<ElementKernel> inner, double alpha, double beta);

  const ElementKernel& inner() const { return *_inner; }
  double alpha() const { return _alpha; }
  double beta() const { return _beta; }

  ElementType type() const override { return _inner->type(); }
  int n_nodes() const override { return _inner->n_nodes(); }
  std::span<const DofType> node_dofs(int local_node) const override {
    return _inner->node_dofs(local_node);
  }
  int n_state() const override { return _inner->n_state(); }
  int n_multipliers() const override { return _inner->n_multipliers(); }
  bool has_mass() const override { return _inner->has_mass(); }
  /// beta non-zero, or alpha non-zero on a kernel with mass (alpha M of a massless kernel is 0)
  bool has_damping() const override { return _has_damping; }
  bool damping_in_residual() const override { return false; }
  bool has_artificial_energy() const override { return _inner->has_artificial_energy(); }
  bool uses_temperature_field() const override { return _inner->uses_temperature_field(); }
  std::string validate(const ElementInput& in) const override { return _inner->validate(in); }
  void initialize(const ElementInput& in) const override { _inner->initialize(in); }
  void evaluate(const ElementInput& in, ElementOutput& out) const override;
  bool augment(const ElementInput& in) const override { return _inner->augment(in); }
  bool limits_steps() const override { return _inner->limits_steps(); }
  double step_limit(const ElementInput& in, std::span<const double> du) const override {
    return _inner->step_limit(in, du);
  }
  bool supports_load(DistLoadKind kind, int face) const override {
    return _inner->supports_load(kind, face);
  }
  void load(const ElementInput& in, const DistributedLoad& load, double magnitude,
            double sink_temperature, std::span<double> f_ext,
            std::span<double> tangent) const override {
    _inner->load(in, load, magnitude, sink_temperature, f_ext, tangent);
  }
  double stored_heat(const ElementInput& in) const override { return _inner->stored_heat(in); }
  bool supports_output(ElemVar var) const override { return _inner->supports_output(var); }
  void recover(const ElementInput& in, ElementRecovery& out) const override {
    _inner->recover(in, out);
  }

 private:
  std::unique_ptr<ElementKernel> _inner;
  double _alpha = 0.0, _beta = 0.0;
  bool _has_damping = false;
};

/// The material of a block's property (solid, beam or shell section), or nullptr (springs, gaps,
/// point inertias, user elements, substructures, *BEAM GENERAL SECTION).
const Material* property_material(const KernelContext& ctx);

/// `kernel` wrapped in a RayleighDampingKernel when the block's material has *DAMPING with a
/// non-zero ALPHA or BETA; returned unchanged otherwise (bit for bit the same results). A kernel
/// that integrates its own damping (coupled temperature-displacement elements) cannot be wrapped:
/// InputError when the model has a *DYNAMIC step.
std::unique_ptr<ElementKernel> with_material_damping(const KernelContext& ctx,
                                                     std::unique_ptr<ElementKernel> kernel);

} // namespace gapfem
