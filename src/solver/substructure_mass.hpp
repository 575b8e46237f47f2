#pragma once
/// @file substructure_mass.hpp
/// The reduced mass of a substructure (*SUBSTRUCTURE GENERATE, MASS MATRIX=YES): the model's mass
/// projected on the same static (Guyan) modes as the stiffness, T = [1; -K_II^-1 K_IR] over
/// (retained; internal) DOFs,
///     M_red = T^T M T = M_RR - M_RI X - X^T M_IR + X^T M_II X,   X = K_II^-1 K_IR,
/// exact for the motions the static modes describe (every internal DOF following the retained
/// ones statically: a massless interior, or a rigid-body motion) and an approximation otherwise
/// (docs/substructures.md; Abaqus Analysis User's Guide, "Defining substructures").
#include "linalg/constrained_solver.hpp"
#include "linalg/csr_matrix.hpp"

#include <span>
#include <vector>

namespace gapfem {

struct SubstructureRecovery;

/// M_red (nR x nR row-major, exactly symmetric) from the model's mass M over its equations, the
/// retained equations in their order, the per-equation retained/internal indices (-1 when not),
/// K_IR in `rec` (ir_ptr/ir_col/ir_val, rows internal, columns retained) and the factor of K_II
/// (null when nothing is internal). X is formed whole: nI x nR doubles.
std::vector<double> reduce_mass(const CsrMatrix& M, std::span<const LocalIndex> retained_eq,
                                std::span<const LocalIndex> internal_eq,
                                std::span<const LocalIndex> ret_index,
                                std::span<const LocalIndex> int_index,
                                const SubstructureRecovery& rec, ConstrainedFactor* Kii);

} // namespace gapfem
