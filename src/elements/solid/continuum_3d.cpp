// Instantiations of the three-dimensional continuum kernels.
#include "elements/solid/continuum_factory.hpp"

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
  default:
    return nullptr;
  }
}

} // namespace gapfem
