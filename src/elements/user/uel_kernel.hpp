#pragma once
/// @file uel_kernel.hpp
/// Nonlinear user elements: the kernel calls the user's code, an Abaqus UEL subroutine or a gapfem
/// element plugin, with Abaqus's meanings (docs/user-elements.md). The element's history holds the
/// UEL's SVARS and ENERGY as committed/trial state, so every call of an increment attempt starts
/// from the values at the start of the increment and a cut-back discards the attempt exactly.
#include "elements/user/user_kernel_common.hpp"
#include "model/user_element.hpp"

#include <memory>

namespace gapfem {

class UserCode;
struct Model;

class UelKernel final : public ElementKernel {
 public:
  UelKernel(const UserElementType& type, const UelProperty* properties,
            std::shared_ptr<const UserCode> code, bool temperatures, bool dynamic = false);

  ElementType type() const override { return ElementType::USER; }
  int n_nodes() const override { return _dofs.n_nodes(); }
  std::span<const DofType> node_dofs(int local_node) const override {
    return _dofs.node(local_node);
  }
  static constexpr int kEnergies = 8; ///< Abaqus's ENERGY array
  /// SVARS, the ENERGY values, then the internal force of the last call (for NFORC).
  int n_state() const override { return _type.n_variables + kEnergies + _dofs.n_dofs(); }
  bool uses_temperature_field() const override { return _temperatures; }
  void evaluate(const ElementInput& in, ElementOutput& out) const override;
  /// A UEL in a model with a *DYNAMIC step has the mass its subroutine returns when called with
  /// LFLAGS(3) = 4 (AMATRX = M; the residual and stiffness calls of a dynamic step then say
  /// LFLAGS(1) = 1: gapfem applies the inertia itself, docs/theory/dynamics.md). Otherwise, and
  /// for element plugins (whose interface has no mass request), massless; never damped (the
  /// damping matrix, LFLAGS(3) = 3, is not asked for).
  bool has_mass() const override { return _mass; }
  bool has_damping() const override { return false; }
  bool supports_output(ElemVar var) const override { return var == ElemVar::NFORC; }
  /// NFORC (the internal force at the converged state) and ENERGY(2), the elastic strain energy
  /// (reported where the output reports strain energies).
  void recover(const ElementInput& in, ElementRecovery& out) const override;

 private:
  /// Calls the code at the trial state: residual (gapfem's sign) and, when wanted, the tangent
  /// (row-major); writes the trial SVARS and ENERGY; returns the PNEWDT request.
  double call(const ElementInput& in, std::span<double> residual, std::span<double> tangent) const;
  /// The user's mass matrix at the trial state (row-major, not yet symmetrized).
  void mass(const ElementInput& in, std::span<double> M) const;

  UserElementType _type;
  NodeDofTable _dofs;
  std::vector<double> _props;
  std::vector<int> _jprops;
  std::shared_ptr<const UserCode> _code;
  bool _temperatures;
  bool _mass = false; ///< the model has a *DYNAMIC step and the code is a UEL
};

/// The kernel of a user element type that is not LINEAR: InputError when no user code was given
/// (gapfem --user) or the code has neither a UEL nor a plugin entry.
std::unique_ptr<ElementKernel> make_uel_kernel(const Model& model, const UserElementType& type,
                                               const UelProperty* properties);

} // namespace gapfem
