#pragma once
/// @file constraints.hpp
/// Linear multi-point constraints of the model, as the input layer resolved them: every *EQUATION,
/// *MPC, *KINEMATIC COUPLING, *COUPLING and *TIE becomes a list of rows
///
///     sum_k c_k u(node_k, dof_k) = 0,
///
/// whose first term is the row's dependent DOF (the one Abaqus eliminates). The solver enforces
/// them exactly with Lagrange multipliers (fem/constraint_set.hpp); the dependent DOF is used for
/// the redundancy checks and for "a boundary condition wins over a tie" (yields_to_bc).
#include "common/error.hpp"
#include "common/types.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace gapfem {

/// Which keyword made a constraint (for messages and for the NLGEOM rule).
enum class ConstraintKind : std::uint8_t { Equation, Mpc, KinematicCoupling, Coupling, Tie };

struct ConstraintTerm {
  NodeId node = -1;
  DofType dof = DofType::U1;
  double coeff = 0.0;
  /// The DOF exists at the node even where no element carries it (a coupling's reference node,
  /// the rotations an MPC BEAM gives a solid node).
  bool activates = false;
};

struct LinearConstraint {
  std::vector<ConstraintTerm> terms; ///< terms[0]: the dependent DOF (coefficient != 0)
  ConstraintKind kind = ConstraintKind::Equation;
  /// How messages name it besides its location: "" (an *EQUATION, *MPC), "tie T1", "coupling C1".
  std::string name;
  SourceLocation loc; ///< the data line (or keyword line) that defined it (its dependent term's)
  /// Per term, the data line that gave it (an *EQUATION spans lines); empty: `loc` for every term.
  std::vector<SourceLocation> term_loc;
  /// Where term k was given.
  const SourceLocation& loc_of(std::size_t k) const {
    return k < term_loc.size() ? term_loc[k] : loc;
  }
  /// "node 12" prefixed by the constraint's name ("tie T1: node 12").
  std::string entity(const std::string& node) const {
    return name.empty() ? "node " + node : name + ": node " + node;
  }
  /// "tie T1 at deck.inp:40 (*TIE)" or "deck.inp:40 (*EQUATION)".
  std::string where() const { return name.empty() ? loc.str() : name + " at " + loc.str(); }
  /// A term on a DOF its node does not carry (and does not activate) drops the row instead of
  /// being an error: "every active DOF" of MPC TIE, the rotations of a kinematic coupling's
  /// nodes that have none.
  bool drop_if_missing = false;
  /// The first term is a dependent DOF Abaqus eliminates (one constraint per dependent DOF, no
  /// boundary condition on it). A distributing coupling eliminates nothing (Abaqus enforces it
  /// with multipliers): boundary conditions may hold any of its DOFs.
  bool eliminates = true;
  /// The terms' DOFs 1-6 at nodes with a *TRANSFORM are in the local system (*EQUATION).
  bool local_dofs = false;
  /// In a step whose boundary conditions prescribe the dependent DOF, the row is not applied
  /// (ties and couplings: the boundary condition holds the node, as Abaqus resolves it); otherwise
  /// such a boundary condition is an input error.
  bool yields_to_bc = false;
  /// The row is the small-rotation (linearised) form of a constraint that is nonlinear in the
  /// rotations (MPC BEAM/LINK, kinematic coupling): a step with NLGEOM rejects it.
  bool small_rotation = false;
};

/// *TRANSFORM: a local coordinate system at nodes. Boundary conditions, concentrated loads,
/// *EQUATION terms and nodal output (U, RF, CF, UR, RM, CM) at these nodes refer to its axes.
struct NodeTransform {
  enum class Type : std::uint8_t { Rectangular, Cylindrical };
  Type type = Type::Rectangular;
  Vec3 a{}, b{}; ///< R: a on local x, b in the local x-y plane; C: two points on the z axis
  SourceLocation loc;
};

/// The local axes at a node at X: rows e1, e2, e3 (row-major 3 x 3, orthonormal); nullopt where
/// the points do not define a system. A node on the axis of a cylindrical system gets a radial
/// direction chosen normal to the axis (see on_cylinder_axis).
std::optional<std::array<double, 9>> local_axes(const NodeTransform& t, const Vec3& X);
/// True for a node on the axis of a cylindrical system, where the radial and tangential
/// directions are arbitrary: only uses that treat local 1 and 2 alike are unambiguous.
bool on_cylinder_axis(const NodeTransform& t, const Vec3& X);

} // namespace gapfem
