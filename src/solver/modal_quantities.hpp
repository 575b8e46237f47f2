#pragma once
/// @file modal_quantities.hpp
/// What Abaqus reports of each eigenmode (Theory Guide, "Variables associated with the natural
/// modes of a model"; docs/theory/frequency.md): the normalisation of the mode shapes, the
/// generalized mass m = phi^T M phi, the participation factors Gamma_i = phi^T M T_i / m and the
/// effective masses Gamma_i^2 m, T_i the rigid-body motion of direction i (translations along X,
/// Y, Z; rotations about the X, Y, Z axes through the global origin) over the free equations.
#include "fem/dof_map.hpp"
#include "linalg/csr_matrix.hpp"
#include "linalg/eigen_solver.hpp"
#include "model/mesh.hpp"
#include "results/results.hpp"

namespace gapfem {

/// The index of the entry of largest magnitude among the displacements and rotations of the
/// equation vector phi.
std::size_t largest_entry(std::span<const double> phi, const DofMap& dofs, const EquationMap& eqm);

/// Normalises pairs.vectors in place (largest entry +1, or unit generalized mass with its largest
/// entry positive) and returns the modes' quantities.
EigenSummary modal_summary(const Mesh& mesh, const DofMap& dofs, const EquationMap& eqm,
                           const CsrMatrix& M, EigenPairs& pairs, bool mass_normalized);

} // namespace gapfem
