#pragma once
/// @file heat_kernel.hpp
/// The heat-transfer element kernels DC1D2, DC2D3, DC2D4, DCAX3, DCAX4, DC3D4, DC3D8 and DC3D10
/// (DOF 11 only) as one template over the shape and the geometry of the section. The physics is
/// in HeatCore (heat_core.hpp); theory in docs/theory/thermal.md.
///
/// Output: HFL (heat flux vector -k grad T at the integration points): HFL1 HFL2 HFL3 in 3-D,
/// HFL1 HFL2 (x, y or r, z) in 2-D, HFL1 along the link from node 1 to node 2 for DC1D2. The
/// magnitude (Abaqus HFLM) is not part of HFL, as Abaqus's HFL stands for the components.
#include "elements/heat/heat_core.hpp"

#include <memory>

namespace gapfem {

namespace heat_detail {
inline constexpr std::array<DofType, 1> kNtDof{DofType::NT};
} // namespace heat_detail

template <ElementType Type, Shape S, HeatGeometry G>
class HeatKernel final : public ElementKernel {
 public:
  using Core = HeatCore<S, G>;
  static constexpr int NN = Core::NN;

  /// `section`: cross-section area (DC1D2) or thickness (DC2D3/DC2D4).
  HeatKernel(HeatMaterial material, double section) : _core(std::move(material), section) {}

  ElementType type() const override { return Type; }
  std::span<const DofType> node_dofs(int) const override { return heat_detail::kNtDof; }
  std::string validate(const ElementInput& in) const override { return _core.validate(in.X); }

  void evaluate(const ElementInput& in, ElementOutput& out) const override {
    typename Core::Temps T, T0;
    gather(in, T, T0);
    const bool want_K = out.want_tangent && out.tangent.size() == NN * NN;
    out.unsymmetric |= _core.add_internal(in.X, T, T0, in.ctx, layout(), out.residual,
                                          want_K ? out.tangent : std::span<double>{});
    if (out.want_damping) _core.add_capacity_block(in.X, T, layout(), out.damping);
  }

  /// No inertia (heat has none); the heat capacity is the damping operator, whose flux the
  /// kernel integrates itself (E(T) is nonlinear): damping_in_residual.
  bool has_mass() const override { return false; }
  bool has_damping() const override { return _core.material().has_capacity(); }
  bool damping_in_residual() const override { return true; }

  double stored_heat(const ElementInput& in) const override {
    typename Core::Temps T, T0;
    gather(in, T, T0);
    return _core.stored_heat(in.X, T, T0);
  }

  bool supports_load(DistLoadKind kind, int face) const override {
    return _core.supports_load(kind, face);
  }
  void load(const ElementInput& in, const DistributedLoad& ld, double magnitude, double sink,
            std::span<double> f_ext, std::span<double> tangent) const override {
    typename Core::Temps T, T0;
    gather(in, T, T0);
    _core.add_load(in.X, T, ld, magnitude, sink, layout(), f_ext,
                   tangent.size() == NN * NN ? tangent : std::span<double>{});
  }

  bool supports_output(ElemVar var) const override { return var == ElemVar::HFL; }
  void recover(const ElementInput& in, ElementRecovery& out) const override {
    typename Core::Temps T, T0;
    gather(in, T, T0);
    OutputBlock b;
    b.var = ElemVar::HFL;
    b.names = Core::flux_names();
    b.n_points = Core::NQ;
    b.values.resize(static_cast<std::size_t>(Core::NQ * Core::D));
    _core.heat_flux(in.X, T, b.values);
    out.blocks.push_back(std::move(b));
  }

  const Core& core() const { return _core; }

 private:
  static HeatLayout layout() { return {1, 0, NN}; }
  static void gather(const ElementInput& in, typename Core::Temps& T, typename Core::Temps& T0) {
    for (int a = 0; a < NN; ++a) {
      T[a] = in.u[a];
      T0[a] = in.u_start.empty() ? in.u[a] : in.u_start[a];
    }
  }

  Core _core;
};

struct KernelContext;

/// The thermal material of a block with the checks every element with temperature DOFs needs:
/// *CONDUCTIVITY, and *DENSITY with *SPECIFIC HEAT when the model has a transient heat transfer
/// or coupled step (InputError naming the material otherwise).
HeatMaterial heat_material_for(const KernelContext& ctx, const Material& material);

} // namespace gapfem
