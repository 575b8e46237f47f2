// Instantiations of the plane and axisymmetric continuum kernels.
#include "elements/solid/continuum_factory.hpp"
#include "elements/solid/incompatible_kernel.hpp"
#include "elements/solid/reduced_kernel.hpp"

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
  case T::CPS8:
    return std::make_unique<
        ContinuumKernel<ContinuumTraits<T::CPS8, Shape::Quad8, K::PlaneStress, false>>>(
        std::move(setup));
  case T::CPS8R:
    return std::make_unique<
        ContinuumKernel<ContinuumTraits<T::CPS8R, Shape::Quad8, K::PlaneStress, false, true>>>(
        std::move(setup));
  case T::CPE8:
    return std::make_unique<
        ContinuumKernel<ContinuumTraits<T::CPE8, Shape::Quad8, K::PlaneStrain, false>>>(
        std::move(setup));
  case T::CPE8R:
    return std::make_unique<
        ContinuumKernel<ContinuumTraits<T::CPE8R, Shape::Quad8, K::PlaneStrain, false, true>>>(
        std::move(setup));
  case T::CAX8:
    return std::make_unique<
        ContinuumKernel<ContinuumTraits<T::CAX8, Shape::Quad8, K::Axisymmetric, false>>>(
        std::move(setup));
  case T::CAX8R:
    return std::make_unique<
        ContinuumKernel<ContinuumTraits<T::CAX8R, Shape::Quad8, K::Axisymmetric, false, true>>>(
        std::move(setup));
  case T::CPS6:
    return std::make_unique<
        ContinuumKernel<ContinuumTraits<T::CPS6, Shape::Tri6, K::PlaneStress, false>>>(
        std::move(setup));
  case T::CPE6:
    return std::make_unique<
        ContinuumKernel<ContinuumTraits<T::CPE6, Shape::Tri6, K::PlaneStrain, false>>>(
        std::move(setup));
  case T::CAX6:
    return std::make_unique<
        ContinuumKernel<ContinuumTraits<T::CAX6, Shape::Tri6, K::Axisymmetric, false>>>(
        std::move(setup));
  case T::CPS4R:
    return std::make_unique<ReducedKernel<T::CPS4R, K::PlaneStress>>(std::move(setup));
  case T::CPE4R:
    return std::make_unique<ReducedKernel<T::CPE4R, K::PlaneStrain>>(std::move(setup));
  case T::CAX4R:
    return std::make_unique<ReducedKernel<T::CAX4R, K::Axisymmetric>>(std::move(setup));
  case T::CPS4I:
    return std::make_unique<IncompatibleKernel<T::CPS4I, Shape::Quad4, K::PlaneStress>>(
        std::move(setup));
  case T::CPE4I:
    return std::make_unique<IncompatibleKernel<T::CPE4I, Shape::Quad4, K::PlaneStrain>>(
        std::move(setup));
  case T::CAX4I:
    return std::make_unique<IncompatibleKernel<T::CAX4I, Shape::Quad4, K::Axisymmetric>>(
        std::move(setup));
  default:
    return nullptr;
  }
}

} // namespace gapfem
