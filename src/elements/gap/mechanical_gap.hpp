#pragma once
/// @file mechanical_gap.hpp
/// GAPUNI, GAPCYL and GAPSPHER (and the mechanical part of GAPUNIT): kinematics from
/// gap_kinematics, the normal behaviour either as exact hard contact (a Lagrange multiplier with an
/// active-set status decided at every evaluation), augmented Lagrange, or a force law
/// (normal_law.hpp); Coulomb friction (friction.hpp) with an elastic-slip stick or exact (LAGRANGE,
/// ROUGH) stick multipliers; contact damping. docs/theory/gap_elements.md has the equations.
#include "elements/element_kernel.hpp"
#include "elements/gap/friction.hpp"
#include "elements/gap/gap_kinematics.hpp"
#include "elements/gap/gap_thermal.hpp"
#include "elements/gap/normal_law.hpp"

#include <array>
#include <optional>
#include <vector>

namespace gapfem {

/// History layout of a mechanical gap (doubles per element).
struct GapStateLayout {
  static constexpr int status = 0;      ///< ContactStatus as a number
  static constexpr int direction = 1;   ///< closure direction (3): the increment's slip basis
  static constexpr int slip = 4;        ///< accumulated slip in t1, t2 (E12, E13)
  static constexpr int plastic = 6;     ///< plastic slip / stick point in t1, t2
  static constexpr int dissipation = 8; ///< accumulated frictional dissipation
  static constexpr int lambda_aug = 9;  ///< augmented-Lagrange multiplier estimate
  static constexpr int slip_dir = 10;   ///< slip direction (Lagrange friction), 2
  static constexpr int damping = 12;    ///< damping forces of the increment: normal, t1, t2
  /// augmented Lagrange: the previous augmentation of this increment (multiplier estimate,
  /// overclosure, 1 when valid) for the secant update
  static constexpr int aug_previous = 15;
  static constexpr int damping_work = 18; ///< accumulated work of the damping forces (ALLSE)
  static constexpr int size = 19;
};

class MechanicalGapKernel final : public ElementKernel {
 public:
  explicit MechanicalGapKernel(const KernelContext& ctx);

  ElementType type() const override { return _type; }
  std::span<const DofType> node_dofs(int) const override { return _dofs; }
  int n_state() const override { return GapStateLayout::size; }
  int n_multipliers() const override { return 3; }
  std::string validate(const ElementInput& in) const override;
  void initialize(const ElementInput& in) const override;
  void evaluate(const ElementInput& in, ElementOutput& out) const override;
  /// Gaps are massless. *CONTACT DAMPING is not a damping operator: its viscous force is computed
  /// by the kernel from the increment (gap_response.cpp, damping(): the closing rate du / dt)
  /// with its tangent in K, so the gap reports no damping block.
  bool has_mass() const override { return false; }
  bool has_damping() const override { return false; }
  bool augment(const ElementInput& in) const override;
  bool limits_steps() const override { return _penalty_friction; }
  double step_limit(const ElementInput& in, std::span<const double> du) const override;
  bool supports_output(ElemVar v) const override {
    return v == ElemVar::S || v == ElemVar::E || (v == ElemVar::HFL && _thermal.has_value());
  }
  void recover(const ElementInput& in, ElementRecovery& out) const override;

  /// Characteristic length of element `block_index` (attached elements' mean size).
  double characteristic_length(LocalIndex block_index) const { return _lc[block_index]; }

 private:
  enum class NormalMode { Direct, Force, Augmented };
  struct Response; // what one evaluation computes for output and augmentation (gap_response.hpp)
  struct Local;    // its intermediate quantities, stage to stage
  /// One evaluation (gap_response.cpp): with `out`, writes the trial state and multipliers and
  /// assembles; without, only computes R.
  void respond(const ElementInput& in, std::span<double> state, std::span<double> mult,
               ElementOutput* out, Response& r) const;
  // the stages of respond()
  void setup(const ElementInput& in, std::span<const double> st, Response& R, Local& L) const;
  void normal(const ElementInput& in, std::span<double> st, std::span<double> mult, Response& R,
              Local& L) const;
  void friction(const ElementInput& in, std::span<double> st, std::span<double> mult,
                ElementOutput* out, Response& R, Local& L) const;
  void friction_lagrange(const ElementInput& in, std::span<double> st, std::span<double> mult,
                         ElementOutput* out, Response& R, Local& L) const;
  void friction_penalty(const ElementInput& in, std::span<double> st, Response& R, Local& L) const;
  /// Elastic-slip friction's stiffness as compliant rows (slots 1 and 2) instead of tangent terms.
  void slip_rows(const ElementInput& in, std::span<double> mult, const Response& R, Local& L) const;
  void damping(const ElementInput& in, Response& R, Local& L) const;
  void heat(const ElementInput& in, Response& R, Local& L) const;
  void store(const ElementInput& in, std::span<double> st, ElementOutput& out, Response& R,
             const Local& L) const;
  void assemble(const ElementInput& in, ElementOutput& out, const Response& R,
                const Local& L) const;
  void assemble_heat(ElementOutput& out, const Response& R, const Local& L) const;
  /// Can the solver enforce a row with these coefficients (does it touch a free DOF)?
  bool enforceable(const ElementInput& in, const Local& L,
                   const Eigen::Matrix<double, 8, 1>& row) const;
  GapGeometry geometry(const ElementInput& in, std::span<const double> u,
                       std::span<const double> state) const;
  GapGeometryParams params_for(const ElementInput& in) const;
  const FrictionLaw* friction_for(const ElementInput& in) const;
  double augmented_stiffness(const ElementInput& in) const;

  ElementType _type;
  const GapSection& _section;
  GapGeometryParams _base;
  bool _computed_direction = false;
  int _dim = 3;      ///< displacement components per node (2 in planar/axisymmetric models)
  int _per_node = 3; ///< local DOFs per node
  std::vector<DofType> _dofs;
  NormalMode _mode = NormalMode::Direct;
  bool _no_separation = false;
  std::unique_ptr<NormalForceLaw> _law;
  /// Force laws: a gap whose slope is at least kRowFraction of the law's stiffness scale carries
  /// it as a compliant constraint row (GAPFEM_PENALTY_ROWS=0 keeps it in the tangent)
  bool _compliant_rows = true;
  /// Elastic-slip friction on a fixed direction carries its stick and slip stiffness as compliant
  /// rows along the eigenvectors of its slip tangent (GAPFEM_FRICTION_ROWS=0: in the tangent), so
  /// that stick/slip changes and the stick stiffness's dependence on the normal force change rows,
  /// not the matrix the solver factorises (docs/theory/gap_elements.md §4).
  bool _slip_rows = true;
  static constexpr double kRowFraction = 1e-9;
  double _augmented_k = 0.0;          ///< 0: automatic
  std::vector<FrictionLaw> _friction; ///< [0] the section's (if any), then *CHANGE FRICTION
  std::vector<std::vector<std::pair<int, int>>> _friction_schedule; ///< per element: (step, law)
  int _section_friction = -1;
  bool _penalty_friction = false; ///< a rotating gap with an elastic-slip friction law (step_limit)
  std::vector<double> _lc;        ///< per element of the block
  double _length_scale = 1.0;
  std::optional<GapThermalModel> _thermal; ///< GAPUNIT: conductance, radiation, heat generation
};

} // namespace gapfem
