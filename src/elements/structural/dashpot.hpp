#pragma once
/// @file dashpot.hpp
/// Dashpot elements with Abaqus semantics (Abaqus Analysis User's Guide, "Dashpots",
/// https://abaqus-docs.mit.edu/2017/English/SIMACAEELMRefMap/simaelm-c-dashpot.htm):
///   DASHPOT1  one node, DOF i to ground:    relative velocity w = v_i
///   DASHPOT2  node 1 DOF i, node 2 DOF j:   w = v_i(1) - v_j(2)
///   DASHPOTA  along the line of the nodes:  w = n . (v(2) - v(1)), n the initial line without
///             NLGEOM, the current one with it (as SPRINGA)
/// With *DASHPOT, ORIENTATION= (DASHPOT1/2 only) i and j are local DOFs, as for SPRING1/2
/// (spring.hpp, FixedAction): w = n_i . v(1) - n_j . v(2), fixed directions.
/// The force is F = c(T) w (*DASHPOT) or F(w) from the *DASHPOT, NONLINEAR table (piecewise linear,
/// constant outside the table); on the nodes r = F B with B = [1], [1, -1] or [-n, n], so that
/// for DASHPOT1/2 the force resists u_i(1) - u_j(2) growing like the SPRING's.
///
/// Where the velocity comes from (docs/theory/dynamics.md, "Dashpots and point-element damping"):
/// - a step whose integrator defines rates (*DYNAMIC, transient coupled steps): the kernel has a
///   damping operator C = F'(w) B B^T (has_damping); the assembler adds C v to the residual and
///   dv/du C to the tangent. A nonlinear table adds the rest itself: (F(w) - F'(w) w) B, so the
///   residual is F(w) B exactly. With NLGEOM the turning line adds its own tangent terms.
/// - a static step: Abaqus takes "the velocities ... by dividing the displacement increments by
///   the time increment"; the kernel does that, w from (u - u_start) / dt, force and tangent its
///   own (F'(w) / dt B B^T).
/// - otherwise (no velocity known) no force.
/// Output: S11 = F (its history slot, the force of the last evaluation with a velocity), E11 = the
/// relative displacement (as SPRING).
#include "elements/element_kernel.hpp"
#include "elements/structural/spring.hpp"
#include "model/section.hpp"
#include "model/table.hpp"

#include <array>

namespace gapfem {

/// DASHPOT1 / DASHPOT2 / DASHPOTA kernel. Immutable; thread-safe.
class DashpotKernel final : public ElementKernel {
 public:
  /// `space` decides the DOFs of DASHPOTA; the DOFs of DASHPOT1/2 are checked by the factory.
  DashpotKernel(ElementType type, const SpringSection& section, ModelSpace space);

  ElementType type() const override { return _type; }
  std::span<const DofType> node_dofs(int local_node) const override;
  int n_state() const override { return 1; } ///< the force, for output
  bool uses_temperature_field() const override { return !_nonlinear && _c.n_rows() > 1; }
  std::string validate(const ElementInput& in) const override;
  void evaluate(const ElementInput& in, ElementOutput& out) const override;
  /// Massless; a damping operator in every step with rates (added by the assembler).
  bool has_mass() const override { return false; }
  bool has_damping() const override { return true; }
  bool supports_output(ElemVar var) const override;
  void recover(const ElementInput& in, ElementRecovery& out) const override;

  /// Force and dF/dw at relative velocity w.
  void force(const ElementInput& in, double w, double& F, double& dF) const;

 private:
  /// B (n_dofs) and, for DASHPOTA, the current line: returns the number of DOFs.
  struct Line {
    std::array<double, 6> B{};
    std::array<double, 3> n{};
    double l = 0.0; ///< current length (DASHPOTA)
    int nd = 0;
  };
  Line line(const ElementInput& in) const;
  bool nlgeom_line(const ElementInput& in) const;
  /// NLGEOM DASHPOTA: d(F B)/du at fixed velocity (the line turning), into the tangent.
  void add_turning(const Line& ln, std::span<const double> dv, double F, double dF,
                   ElementOutput& out) const;

  ElementType _type;
  PropertyTable _c;
  bool _nonlinear = false;
  Curve _table; ///< NONLINEAR: F(w)
  int _ndim = 3;
  FixedAction _act; ///< DASHPOT1/2; DASHPOTA: its translations in dofs0/dofs1
};

} // namespace gapfem
