#pragma once
/// @file uel_kernel.hpp
/// Nonlinear user elements: the kernel calls the user's code, an Abaqus UEL subroutine or a gapfem
/// element plugin, with Abaqus's meanings (docs/user-elements.md). The element's history holds the
/// UEL's SVARS and ENERGY as committed/trial state, so every call of an increment attempt starts
/// from the values at the start of the increment and a cut-back discards the attempt exactly.
#include "elements/user/user_kernel_common.hpp"
#include "model/user_element.hpp"

#include <atomic>
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
  /// SVARS, the ENERGY values, the internal force of the last call (for NFORC), then what is known
  /// of the element's damping in a step (damping_slot()).
  int n_state() const override { return _type.n_variables + kEnergies + _dofs.n_dofs() + 1; }
  bool uses_temperature_field() const override { return _temperatures; }
  void evaluate(const ElementInput& in, ElementOutput& out) const override;
  /// A UEL in a model with a *DYNAMIC step has the mass its subroutine returns when called with
  /// LFLAGS(3) = 4 (AMATRX = M) and, in *DYNAMIC steps, the damping matrix it returns for
  /// LFLAGS(3) = 3 (AMATRX = C; the residual and stiffness calls of a dynamic step say
  /// LFLAGS(1) = 1: gapfem applies inertia, damping and the integrator itself,
  /// docs/theory/dynamics.md §8). An element whose C is zero at its first evaluation in a step is
  /// undamped for the rest of the step (no further call). Otherwise, and for element plugins
  /// (whose interface has no mass or damping request), massless and undamped.
  bool has_mass() const override { return _mass; }
  bool has_damping() const override { return _mass; }
  bool supports_output(ElemVar var) const override { return var == ElemVar::NFORC; }
  /// NFORC (the internal force at the converged state) and ENERGY(2), the elastic strain energy
  /// (reported where the output reports strain energies).
  void recover(const ElementInput& in, ElementRecovery& out) const override;

 private:
  /// Calls the code at the trial state: residual (gapfem's sign) and, when wanted, the tangent
  /// (row-major); writes the trial SVARS and ENERGY; returns the PNEWDT request.
  double call(const ElementInput& in, std::span<double> residual, std::span<double> tangent) const;
  /// The matrix the UEL returns for LFLAGS(3) = `what` (2 stiffness, 3 damping, 4 mass) at the
  /// trial state, on copies of SVARS and ENERGY (row-major, not yet symmetrized); an error naming
  /// the element when an entry is not finite.
  void operator_matrix(const ElementInput& in, int what, std::span<double> A) const;
  /// The damping block of a *DYNAMIC step into `C` (zeroed by the caller); returns the value of the
  /// damping slot after it: +KSTEP when the element is undamped in this step, -KSTEP when damped.
  /// `known` is the slot's value before the evaluation.
  double damping(const ElementInput& in, double known, std::span<double> C) const;
  /// Where the history keeps what is known of the damping in a step: +KSTEP (found undamped in
  /// step KSTEP: not asked again), -KSTEP (damped: asked at every evaluation), else unknown.
  std::size_t damping_slot() const {
    return static_cast<std::size_t>(_type.n_variables + kEnergies + _dofs.n_dofs());
  }

  UserElementType _type;
  NodeDofTable _dofs;
  std::vector<double> _props;
  std::vector<int> _jprops;
  std::shared_ptr<const UserCode> _code;
  bool _temperatures;
  bool _mass = false; ///< the model has a *DYNAMIC step and the code is a UEL
  /// one warning per element type for a UEL that returns its stiffness as its damping matrix
  mutable std::atomic<bool> _warned_stiffness_as_damping{false};
};

/// The kernel of a user element type that is not LINEAR: InputError when no user code was given
/// (gapfem --user) or the code has neither a UEL nor a plugin entry.
std::unique_ptr<ElementKernel> make_uel_kernel(const Model& model, const UserElementType& type,
                                               const UelProperty* properties);

} // namespace gapfem
