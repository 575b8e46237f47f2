#pragma once
/// @file matrix_kernel.hpp
/// A constant linear element: residual K u and tangent K over the element's DOFs (node by node).
/// The kernel of LINEAR user elements (*USER ELEMENT, LINEAR with *MATRIX) and of substructures
/// (their reduced stiffness). Output: the element nodal forces NFORC = K u.
#include "elements/user/user_kernel_common.hpp"

namespace gapfem {

class MatrixKernel final : public ElementKernel {
 public:
  /// `K` (and `M`, the mass, or empty): n_dofs x n_dofs row-major over `dofs`' element order.
  MatrixKernel(ElementType type, NodeDofTable dofs, std::vector<double> K, bool unsymmetric,
               std::vector<double> M = {});

  ElementType type() const override { return _type; }
  int n_nodes() const override { return _dofs.n_nodes(); }
  std::span<const DofType> node_dofs(int local_node) const override {
    return _dofs.node(local_node);
  }
  void evaluate(const ElementInput& in, ElementOutput& out) const override;
  /// The deck's mass: a LINEAR user element's *MATRIX, TYPE=MASS (UserElementType::mass), or a
  /// substructure's reduced mass (generated with MASS MATRIX=YES), the block's own operator;
  /// without one, massless. Undamped (Abaqus's LINEAR user elements have no damping matrix).
  bool has_mass() const override { return !_M.empty(); }
  bool has_damping() const override { return false; }
  bool supports_output(ElemVar var) const override { return var == ElemVar::NFORC; }
  void recover(const ElementInput& in, ElementRecovery& out) const override;
  /// K u (element order).
  void internal_force(std::span<const double> u, std::span<double> f) const;

 private:
  ElementType _type;
  NodeDofTable _dofs;
  std::vector<double> _K, _M;
  bool _unsymmetric;
};

} // namespace gapfem
