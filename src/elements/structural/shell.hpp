#pragma once
/// @file shell.hpp
/// Shear-flexible (Reissner-Mindlin) shells S3/S3R, S4/S4R and S8R with DOFs 1-6 per node
/// (Abaqus Analysis User's Guide, "Shell element library"; docs/theory/structural.md §4).
///
/// Degenerated-continuum kinematics: x(r, s, z) = x_r(r, s) + z d(r, s) with the reference surface
/// x_r interpolated from the nodal displacements and the director d from nodal directors d_a,
/// the averaged nodal normals of the reference mesh rotated by the nodal rotations (d_a = D_a +
/// theta_a x D_a without NLGEOM; d_a = R_a D_a with NLGEOM, R_a updated multiplicatively from the
/// start of each increment, one quaternion per node of history). The membrane, bending and
/// transverse shear strains are the first-order terms in z of the Green-Lagrange strain (their
/// linearisation without NLGEOM), in the local directions of Abaqus's shell convention.
///
/// One energy per element, written once for any scalar: residual and tangent are its gradient and
/// Hessian by forward automatic differentiation (common/jet.hpp), exact and symmetric with and
/// without NLGEOM. Integration: S4/S4R 2x2 for the normal strains and the centre for the in-plane
/// shear strains (selective integration: no hourglass modes, no in-plane shear locking), MITC4
/// transverse shear; S3/S3R three points with MITC3 transverse shear; S8R 2x2. The rotation about
/// the normal (drilling) is tied to the in-plane rotation of the surface by a small penalty
/// (10^-3 G t per area) at the nodes, objective under NLGEOM.
///
/// The section is homogeneous elastic: its resultants come from Simpson's rule through the
/// thickness, which is exact for the linear through-thickness strain, so the section stiffness is
/// integrated in closed form; stresses are reported at the n section points (1 = SNEG ... n =
/// SPOS). OFFSET moves the reference surface by offset * thickness from the mid-surface.
#include "elements/element_kernel.hpp"

namespace gapfem {

/// Factory for S3, S3R, S4, S4R and S8R blocks: section, material and nodal directors.
std::unique_ptr<ElementKernel> make_shell_kernel(const KernelContext& ctx);

} // namespace gapfem
