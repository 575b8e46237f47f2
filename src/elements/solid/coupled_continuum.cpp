// Instantiations of the coupled temperature-displacement continuum kernels.
#include "elements/solid/coupled_continuum.hpp"

#include "elements/heat/heat_kernel.hpp"
#include "elements/solid/reduced_kernel.hpp"
#include "model/model.hpp"

namespace gapfem {

InitialTemperatures block_initial_temperatures(const KernelContext& ctx) {
  InitialTemperatures it;
  const Model& m = ctx.model;
  it.n_nodes = element_info(ctx.type).n_nodes;
  bool any = false;
  for (double t : m.initial_temperature) any |= t != 0.0;
  if (!any) return it;
  it.values.reserve(ctx.elements.size() * static_cast<std::size_t>(it.n_nodes));
  for (ElemId e : ctx.elements)
    for (NodeId n : m.mesh.element_nodes(e)) it.values.push_back(m.initial_temperature[n]);
  return it;
}

namespace {

template <ElementType Base, Shape S, Kinematics K, bool BBar, HeatGeometry G, bool Reduced = false>
std::unique_ptr<ElementKernel> make(const KernelContext& ctx, ContinuumSetup setup,
                                    HeatMaterial heat, double thickness) {
  return std::make_unique<
      CoupledContinuumKernel<ContinuumKernel<ContinuumTraits<Base, S, K, BBar, Reduced>>, G>>(
      ctx.type, std::move(setup), std::move(heat), thickness, block_initial_temperatures(ctx));
}

template <ElementType Base, Kinematics K, HeatGeometry G>
std::unique_ptr<ElementKernel> make_reduced(const KernelContext& ctx, ContinuumSetup setup,
                                            HeatMaterial heat, double thickness) {
  return std::make_unique<CoupledContinuumKernel<ReducedKernel<Base, K>, G>>(
      ctx.type, std::move(setup), std::move(heat), thickness, block_initial_temperatures(ctx));
}

} // namespace

std::unique_ptr<ElementKernel>
make_coupled_continuum_kernel(const KernelContext& ctx, ContinuumSetup setup, double thickness) {
  HeatMaterial heat = heat_material_for(ctx, setup.material);
  setup.needs_temperature = true; // the thermal strain comes from the NT DOFs
  using T = ElementType;
  using K = Kinematics;
  using HG = HeatGeometry;
  // The mechanics of each type is that of its stress/displacement counterpart (continuum_2d.cpp,
  // continuum_3d.cpp): B-bar for the fully integrated first-order plane-strain, axisymmetric and
  // brick elements.
  switch (ctx.type) {
  case T::CPS4T:
    return make<T::CPS4, Shape::Quad4, K::PlaneStress, false, HG::Planar>(
        ctx, std::move(setup), std::move(heat), thickness);
  case T::CPE4T:
    return make<T::CPE4, Shape::Quad4, K::PlaneStrain, true, HG::Planar>(
        ctx, std::move(setup), std::move(heat), thickness);
  case T::CAX4T:
    return make<T::CAX4, Shape::Quad4, K::Axisymmetric, true, HG::Axisymmetric>(
        ctx, std::move(setup), std::move(heat), 1.0);
  case T::C3D4T:
    return make<T::C3D4, Shape::Tet4, K::ThreeD, false, HG::Solid>(ctx, std::move(setup),
                                                                   std::move(heat), 1.0);
  case T::C3D8T:
    return make<T::C3D8, Shape::Hex8, K::ThreeD, true, HG::Solid>(ctx, std::move(setup),
                                                                  std::move(heat), 1.0);
  case T::C3D8RT:
    return make_reduced<T::C3D8R, K::ThreeD, HG::Solid>(ctx, std::move(setup), std::move(heat),
                                                        1.0);
  case T::CPS4RT:
    return make_reduced<T::CPS4R, K::PlaneStress, HG::Planar>(ctx, std::move(setup),
                                                              std::move(heat), thickness);
  case T::CPE4RT:
    return make_reduced<T::CPE4R, K::PlaneStrain, HG::Planar>(ctx, std::move(setup),
                                                              std::move(heat), thickness);
  case T::CAX4RT:
    return make_reduced<T::CAX4R, K::Axisymmetric, HG::Axisymmetric>(ctx, std::move(setup),
                                                                     std::move(heat), 1.0);
  case T::C3D20T:
    return make<T::C3D20, Shape::Hex20, K::ThreeD, false, HG::Solid>(ctx, std::move(setup),
                                                                     std::move(heat), 1.0);
  case T::C3D20RT:
    return make<T::C3D20R, Shape::Hex20, K::ThreeD, false, HG::Solid, true>(ctx, std::move(setup),
                                                                            std::move(heat), 1.0);
  case T::C3D6T:
    return make<T::C3D6, Shape::Wedge6, K::ThreeD, false, HG::Solid>(ctx, std::move(setup),
                                                                     std::move(heat), 1.0);
  case T::CPS8T:
    return make<T::CPS8, Shape::Quad8, K::PlaneStress, false, HG::Planar>(
        ctx, std::move(setup), std::move(heat), thickness);
  case T::CPS8RT:
    return make<T::CPS8R, Shape::Quad8, K::PlaneStress, false, HG::Planar, true>(
        ctx, std::move(setup), std::move(heat), thickness);
  case T::CPE8T:
    return make<T::CPE8, Shape::Quad8, K::PlaneStrain, false, HG::Planar>(
        ctx, std::move(setup), std::move(heat), thickness);
  case T::CPE8RT:
    return make<T::CPE8R, Shape::Quad8, K::PlaneStrain, false, HG::Planar, true>(
        ctx, std::move(setup), std::move(heat), thickness);
  case T::CAX8T:
    return make<T::CAX8, Shape::Quad8, K::Axisymmetric, false, HG::Axisymmetric>(
        ctx, std::move(setup), std::move(heat), 1.0);
  case T::CAX8RT:
    return make<T::CAX8R, Shape::Quad8, K::Axisymmetric, false, HG::Axisymmetric, true>(
        ctx, std::move(setup), std::move(heat), 1.0);
  default:
    return nullptr;
  }
}

} // namespace gapfem
