#pragma once
/// @file beam.hpp
/// Shear-flexible (Timoshenko) beams: B31 and PIPE31 (two nodes, one integration point), B32 and
/// PIPE32 (three nodes end-middle-end, two points), in space with DOFs 1-6; B21 and B22 in the
/// x-y plane with DOFs 1, 2, 6 (Abaqus Analysis User's Guide, "Beam element library").
///
/// One energy, written once for any scalar (beam_kinematics.hpp): the residual is its gradient and
/// the tangent its Hessian, both from forward automatic differentiation (common/jet.hpp), so the
/// tangent is the exact consistent one with and without NLGEOM. Small-displacement steps use the
/// linear strains; NLGEOM uses the geometrically exact strains with the objective rotation
/// interpolation of Crisfield & Jelenic, and the nodal rotations are updated multiplicatively
/// from the start of each increment (state: one unit quaternion per node).
///
/// Two-node elements use the shear stiffness K = kGA / (1 + kGA L^2 / (12 E I)) per bending
/// plane, which makes them exact for end-loaded prismatic beams (docs/theory/structural.md §3.2).
///
/// Local axes (Abaqus "Beam element cross-section orientation"): t the reference tangent,
/// n2 = t x n1a / |.| with n1a the approximate n1 of the section (default (0,0,-1), always
/// (0,0,-1) for planar beams), n1 = n2 x t. Output per integration point: SF1 axial force, SF2/SF3
/// shear forces along n2/n1, SM1/SM2 bending moments about n1/n2, SM3 twisting moment (planar:
/// SF1, SF2, SM1); S11/S12 and E11/E12 at the section points.
#include "elements/element_kernel.hpp"
#include "elements/structural/beam_section.hpp"
#include "model/material.hpp"

#include <array>

namespace gapfem {

/// Factory for beam blocks: section and material checks.
std::unique_ptr<ElementKernel> make_beam_kernel(const KernelContext& ctx);

} // namespace gapfem
