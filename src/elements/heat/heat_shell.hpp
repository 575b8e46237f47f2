#pragma once
/// @file heat_shell.hpp
/// The heat-transfer shells DS3, DS4 and DS8 (docs/theory/thermal.md §7). Each node carries the
/// temperatures at the section points through the thickness: DOF 11 at the SNEG side, 12, … up to
/// DOF 10 + n at the SPOS side, n the number of points on *SHELL SECTION (odd, Simpson's rule; 1
/// for a shell without a gradient through its thickness).
///
/// Through the thickness the temperature is piecewise quadratic: the n points split the thickness
/// into (n - 1) / 2 layers of three points each, with Lagrange interpolation in each layer. In the
/// surface it is interpolated with the element's shape functions N_a, so that
///   T(xi, z) = sum_a N_a(xi) sum_k L_k(z) T_ak.
/// Conduction is integrated with the element's surface rule (DS3 1 point, DS4 2 x 2, DS8 3 x 3)
/// times Simpson's rule per layer: the through-thickness term (dL/dz)^2 is quadratic in each layer,
/// so Simpson integrates it exactly; the in-surface term becomes a sum over the section points,
/// each conducting along the surface with its Simpson weight. The heat capacity uses the same
/// weights through the thickness; DS3/DS4 integrate it at the nodes (lumped, as the first-order
/// heat-transfer elements), DS8 consistently. The thickness may vary (*NODAL THICKNESS); the shell
/// is treated as thin: the curvature of the surface does not change the volume through the
/// thickness, and an OFFSET moves the reference surface without changing the results.
///
/// Loads: BF per volume at every point (Simpson weights); SNEG/SPOS fluxes and FNEG/FPOS films
/// (and surface-based ones on SNEG/SPOS sides) at the first or last point, integrated at the nodes
/// for DS3/DS4 and consistently for DS8. Output HFL1, HFL2 (local surface directions 1, 2, the
/// Abaqus shell convention) and HFL3 (along the normal) at every integration and section point.
#include "elements/element_kernel.hpp"

#include <memory>

namespace gapfem {

/// DS3/DS4/DS8 kernel for a block; InputError for a missing *SHELL SECTION or thermal data.
std::unique_ptr<ElementKernel> make_heat_shell_kernel(const KernelContext& ctx);

} // namespace gapfem
