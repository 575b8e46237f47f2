#pragma once
/// @file normal_law.hpp
/// Normal contact laws that give the contact force directly as a function of the overclosure
/// g = -(h + v) (positive when the gap would penetrate). Hard contact enforced exactly (DIRECT) is
/// not a force law: the gap kernel imposes it with a Lagrange multiplier.
#include <memory>

namespace gapfem {

struct GapSection;

class NormalForceLaw {
public:
  virtual ~NormalForceLaw() = default;
  /// Compressive contact force F(g) and dF/dg.
  virtual void force(double g, double& F, double& dF_dg) const = 0;
  /// True when the law never lets the gap open once closed (bilateral).
  virtual bool bilateral() const { return false; }
};

/// CalculiX's GAPUNI law (fields 6-7 of *GAP): F = k g (1/2 + atan(g/eps)/pi), eps = pi f_inf / k;
/// a stiff penalty spring that carries a tension of at most f_inf when open.
class CcxPenaltyLaw final : public NormalForceLaw {
public:
  CcxPenaltyLaw(double stiffness, double tension) : _k(stiffness), _eps(3.141592653589793 * tension / stiffness) {}
  void force(double g, double& F, double& dF_dg) const override;

private:
  double _k, _eps;
};

/// The force law of a gap section, or nullptr for hard contact enforced with a multiplier.
std::unique_ptr<NormalForceLaw> make_normal_law(const GapSection& section);

} // namespace gapfem
