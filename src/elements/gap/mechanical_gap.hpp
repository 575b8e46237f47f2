#pragma once
/// @file mechanical_gap.hpp
/// GAPUNI, GAPCYL and GAPSPHER (and the mechanical part of GAPUNIT): kinematics from
/// gap_kinematics, the normal behaviour either as exact hard contact (a Lagrange multiplier and an
/// active-set status decided at every evaluation) or as a force law (normal_law.hpp).
#include "elements/element_kernel.hpp"
#include "elements/gap/gap_kinematics.hpp"
#include "elements/gap/normal_law.hpp"

#include <array>
#include <vector>

namespace gapfem {

/// History layout of a mechanical gap (doubles per element).
struct GapStateLayout {
  static constexpr int status = 0;    ///< ContactStatus as a number
  static constexpr int direction = 1; ///< last well-defined closure direction (3)
  static constexpr int size = 4;
};

class MechanicalGapKernel final : public ElementKernel {
public:
  MechanicalGapKernel(const KernelContext& ctx);

  ElementType type() const override { return _type; }
  std::span<const DofType> node_dofs(int) const override { return _dofs; }
  int n_state() const override { return GapStateLayout::size; }
  int n_multipliers() const override { return 3; }
  std::string validate(const ElementInput& in) const override;
  void initialize(const ElementInput& in) const override;
  void evaluate(const ElementInput& in, ElementOutput& out) const override;
  bool supports_output(ElemVar v) const override { return v == ElemVar::S || v == ElemVar::E; }
  void recover(const ElementInput& in, ElementRecovery& out) const override;

private:
  struct Local {
    GapGeometry geom;
    Eigen::Vector3d u1, u2;
    GapGeometryParams params;
  };
  void kinematics(const ElementInput& in, Local& out) const;
  GapGeometryParams params_for(const ElementInput& in) const;

  ElementType _type;
  const GapSection& _section;
  GapGeometryParams _base;
  bool _computed_direction = false;
  int _dim = 3;               ///< displacement components per node (2 in planar/axisymmetric models)
  int _per_node = 3;          ///< local DOFs per node
  std::vector<DofType> _dofs;
  std::unique_ptr<NormalForceLaw> _law; ///< null: exact hard contact
  double _length_scale = 1.0;
};

} // namespace gapfem
