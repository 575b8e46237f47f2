#pragma once
/// @file continuum_factory.hpp
/// Internal: per-dimension constructors of the continuum kernels (instantiated in separate
/// translation units to keep compile times down). Used by make_continuum_kernel().
#include "elements/solid/continuum_kernel.hpp"

#include <memory>

namespace gapfem {

/// C3D8, C3D4, C3D10; nullptr for other types.
std::unique_ptr<ElementKernel> make_continuum_3d(ElementType type, ContinuumSetup setup);
/// CPS3, CPS4, CPE3, CPE4, CAX3, CAX4; nullptr for other types.
std::unique_ptr<ElementKernel> make_continuum_2d(ElementType type, ContinuumSetup setup);

} // namespace gapfem
