// Instantiations of the plane and axisymmetric continuum kernels.
#include "elements/solid/continuum_factory.hpp"

namespace gapfem {

std::unique_ptr<ElementKernel> make_continuum_2d(ElementType type, ContinuumSetup setup) {
  using K = Kinematics;
  using T = ElementType;
  switch (type) {
  case T::CPS3:
    return std::make_unique<
        ContinuumKernel<ContinuumTraits<T::CPS3, Shape::Tri3, K::PlaneStress, false>>>(
        std::move(setup));
  case T::CPS4: // plane stress: plain full integration (no volumetric locking)
    return std::make_unique<
        ContinuumKernel<ContinuumTraits<T::CPS4, Shape::Quad4, K::PlaneStress, false>>>(
        std::move(setup));
  case T::CPE3:
    return std::make_unique<
        ContinuumKernel<ContinuumTraits<T::CPE3, Shape::Tri3, K::PlaneStrain, false>>>(
        std::move(setup));
  case T::CPE4:
    return std::make_unique<
        ContinuumKernel<ContinuumTraits<T::CPE4, Shape::Quad4, K::PlaneStrain, true>>>(
        std::move(setup));
  case T::CAX3:
    return std::make_unique<
        ContinuumKernel<ContinuumTraits<T::CAX3, Shape::Tri3, K::Axisymmetric, false>>>(
        std::move(setup));
  case T::CAX4:
    return std::make_unique<
        ContinuumKernel<ContinuumTraits<T::CAX4, Shape::Quad4, K::Axisymmetric, true>>>(
        std::move(setup));
  default:
    return nullptr;
  }
}

} // namespace gapfem
