// Instantiations of the three-dimensional continuum kernels: C3D8 (B-bar), C3D4, C3D10, C3D20,
// C3D20R (2x2x2), C3D15 and C3D6 (plain full integration, as Abaqus's), C3D8I and C3D8R.
#include "elements/solid/continuum_factory.hpp"
#include "elements/solid/incompatible_kernel.hpp"
#include "elements/solid/reduced_kernel.hpp"

namespace gapfem {

std::unique_ptr<ElementKernel> make_continuum_3d(ElementType type, ContinuumSetup setup) {
  using K = Kinematics;
  switch (type) {
  case ElementType::C3D8:
    return std::make_unique<
        ContinuumKernel<ContinuumTraits<ElementType::C3D8, Shape::Hex8, K::ThreeD, true>>>(
        std::move(setup));
  case ElementType::C3D4:
    return std::make_unique<
        ContinuumKernel<ContinuumTraits<ElementType::C3D4, Shape::Tet4, K::ThreeD, false>>>(
        std::move(setup));
  case ElementType::C3D10:
    return std::make_unique<
        ContinuumKernel<ContinuumTraits<ElementType::C3D10, Shape::Tet10, K::ThreeD, false>>>(
        std::move(setup));
  case ElementType::C3D20:
    return std::make_unique<
        ContinuumKernel<ContinuumTraits<ElementType::C3D20, Shape::Hex20, K::ThreeD, false>>>(
        std::move(setup));
  case ElementType::C3D20R:
    return std::make_unique<ContinuumKernel<
        ContinuumTraits<ElementType::C3D20R, Shape::Hex20, K::ThreeD, false, true>>>(
        std::move(setup));
  case ElementType::C3D15:
    return std::make_unique<
        ContinuumKernel<ContinuumTraits<ElementType::C3D15, Shape::Wedge15, K::ThreeD, false>>>(
        std::move(setup));
  case ElementType::C3D6:
    return std::make_unique<
        ContinuumKernel<ContinuumTraits<ElementType::C3D6, Shape::Wedge6, K::ThreeD, false>>>(
        std::move(setup));
  case ElementType::C3D8R:
    return std::make_unique<ReducedKernel<ElementType::C3D8R, K::ThreeD>>(std::move(setup));
  case ElementType::C3D8I:
    return std::make_unique<IncompatibleKernel<ElementType::C3D8I, Shape::Hex8, K::ThreeD>>(
        std::move(setup));
  default:
    return nullptr;
  }
}

} // namespace gapfem
