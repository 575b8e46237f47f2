#pragma once
/// @file spring.hpp
/// Spring elements with Abaqus semantics (Abaqus Analysis User's Manual 6.6, §26.1.1
/// "Springs" and §26.1.2 "Spring element library"):
///   SPRING1  one node, DOF i to ground:           relative displacement du = u_i
///   SPRING2  node 1 DOF i to node 2 DOF j:         du = u_i(1) - u_j(2)
///   SPRINGA  axial spring along the line joining the nodes; du = change of length. Without NLGEOM
///            the line of action is the initial line, with NLGEOM the current one ("this line of
///            action may rotate in large-displacement analysis").
/// With *SPRING, ORIENTATION= (SPRING1/2 only) the DOFs i, j are local: u_i is n_i . u with n_i
/// the orientation's local axis i (the rotation vector for 4-6), the same axes at both nodes, fixed
/// through the analysis ("acting in a fixed direction"); docs/theory/dynamics.md §9.
/// Force F = k(T) du, with k from *SPRING (temperature-dependent rows interpolated at the element's
/// average predefined temperature), or F(du) from a NONLINEAR table (piecewise linear, constant
/// outside). Output: S11 = F, E11 = du.
#include "elements/element_kernel.hpp"
#include "model/section.hpp"
#include "model/table.hpp"

#include <array>

namespace gapfem {

/// The action of a SPRING1/2 or DASHPOT1/2 ("acting in a fixed direction"): the DOFs it uses at
/// each node and B, so that the relative displacement (velocity) is B . u (B . v). Global DOFs:
/// one DOF per node, B = [1] or [1, -1]. With an orientation: the three translations (rotations)
/// of each node, two translations in planar models, B = [n_i] or [n_i, -n_j].
struct FixedAction {
  std::array<DofType, 3> dofs0{}, dofs1{};
  int n0 = 0, n1 = 0;
  std::array<double, 6> B{};
  int n_dofs() const { return n0 + n1; }
};
/// The FixedAction of a SPRING1/2 or DASHPOT1/2 property whose DOFs (and orientation) have been
/// checked (make_spring_kernel).
FixedAction fixed_action(ElementType type, const SpringSection& section, ModelSpace space);

/// SPRING1 / SPRING2 / SPRINGA kernel. Immutable; thread-safe.
class SpringKernel final : public ElementKernel {
 public:
  /// `space` decides the DOFs of SPRINGA (1-2 in 2-D models, 1-3 in 3-D). The DOFs of
  /// SPRING1/SPRING2 must have been checked against the space by the caller (the factory).
  SpringKernel(ElementType type, const SpringSection& section, ModelSpace space);

  ElementType type() const override { return _type; }
  std::span<const DofType> node_dofs(int local_node) const override;
  bool uses_temperature_field() const override { return !_nonlinear && _stiffness.n_rows() > 1; }
  std::string validate(const ElementInput& in) const override;
  void evaluate(const ElementInput& in, ElementOutput& out) const override;
  /// SPRINGA: dF / l (I - n n^T), dF the force's change along du (its slope at the base state
  /// times the stretch); SPRING1/SPRING2 act along fixed directions: nothing.
  bool stress_stiffness(const ElementInput& in, std::span<const double> du,
                        std::span<double> K) const override;
  /// Springs are massless and undamped (Abaqus's SPRING elements: *SPRING has no damping; a
  /// damped spring is a SPRING and a DASHPOT on the same nodes, a point mass is a MASS element).
  bool has_mass() const override { return false; }
  bool has_damping() const override { return false; }
  bool supports_output(ElemVar var) const override;
  void recover(const ElementInput& in, ElementRecovery& out) const override;

  /// Force F and stiffness dF/du at relative displacement du (linear: k at the element's
  /// temperature, the first table row without a temperature field).
  void force(const ElementInput& in, double du, double& F, double& dF) const;

 private:
  /// Relative displacement du (see the table above).
  double relative_displacement(const ElementInput& in) const;

  ElementType _type;
  PropertyTable _stiffness;
  bool _nonlinear = false;
  Curve _table;     ///< NONLINEAR: F(du)
  int _ndim = 3;    ///< SPRINGA: translational DOFs per node
  FixedAction _act; ///< SPRING1/2; SPRINGA: its translations in dofs0/dofs1
};

/// Factory for SPRING1/SPRING2/SPRINGA and DASHPOT1/DASHPOT2/DASHPOTA blocks (dashpot.hpp): checks
/// the *SPRING / *DASHPOT property (the right keyword, stiffness or coefficient given, DOFs valid
/// in the model space) and throws InputError naming its line otherwise.
std::unique_ptr<ElementKernel> make_spring_kernel(const KernelContext& ctx);

} // namespace gapfem
