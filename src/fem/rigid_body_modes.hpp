#pragma once
/// @file rigid_body_modes.hpp
/// The rigid-body modes of the free equations (translations, and rotations about the origin of
/// the reference coordinates), with a constant mode for temperatures: the near null space that an
/// algebraic multigrid needs to coarsen elasticity well (PETSc's GAMG, `--solver iterative`).
#include "common/types.hpp"
#include "fem/dof_map.hpp"
#include "linalg/constrained_solver.hpp"

#include <span>

namespace gapfem {

/// Modes over the equations of `eqs`: 3 in 2-D (two translations, the in-plane rotation), 6 in
/// 3-D, plus one for temperature DOFs when there are any. Rotational DOFs take their share of the
/// rotation modes; each mode is scaled to unit maximum.
NearNullSpace rigid_body_modes(const DofMap& dofs, const EquationMap& eqs,
                               std::span<const Vec3> coords, bool two_d);

} // namespace gapfem
