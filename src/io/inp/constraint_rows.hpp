#pragma once
/// @file constraint_rows.hpp
/// Rows of the kinematic constraints shared by *MPC, *KINEMATIC COUPLING, *COUPLING and *TIE, in
/// their small-rotation (linear) form (model/constraints.hpp):
///   equal DOFs            u(a, i) - u(b, i) = 0
///   rigid link            u(a, i) - u(b, i) - (theta(b) x (X_a - X_b))_i = 0
///   distance (MPC LINK)   (X_a - X_b) . (u_a - u_b) = 0
///   surface interpolation u(s, i) - sum_k N_k u(m_k, i) = 0
/// In planar and axisymmetric models the translations are 1, 2 and the rotation is 6.
#include "model/model.hpp"

#include <vector>

namespace gapfem::inp {

/// Translational and rotational DOF numbers of the model space.
struct SpaceDofs {
  std::vector<int> translations, rotations;
};
SpaceDofs space_dofs(ModelSpace space);

/// What every row of one constraint definition shares.
struct RowOrigin {
  ConstraintKind kind = ConstraintKind::Mpc;
  std::string name; ///< see LinearConstraint::name
  SourceLocation loc;
  bool yields_to_bc = false;
};

LinearConstraint new_row(const RowOrigin& o);
DofType dof_of(int abaqus_number);

/// u(a, dof) = u(b, dof); `activate`: both DOFs exist even where no element carries them.
LinearConstraint equal_row(const RowOrigin& o, NodeId a, NodeId b, int dof, bool activate_a,
                           bool activate_b);
/// Translation `dof` of node a follows the rigid motion of node b (b's rotations are activated):
/// u(a) = u(b) + theta(b) x d, d = X_a - X_b.
LinearConstraint rigid_row(const RowOrigin& o, ModelSpace space, NodeId a, NodeId b, int dof,
                           const Vec3& d, bool activate_a);

/// The nodes of a surface (node-based: its nodes; element-based: those of its faces), ascending.
std::vector<NodeId> surface_nodes(const Model& m, const Surface& s);

/// Largest-magnitude component of v among the model space's translations (1-based DOF).
int dominant_translation(ModelSpace space, const Vec3& v);

} // namespace gapfem::inp
