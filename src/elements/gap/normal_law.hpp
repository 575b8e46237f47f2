#pragma once
/// @file normal_law.hpp
/// Normal contact laws that give the contact force directly as a function of the overclosure
/// g = -(h + v) (positive when the gap would penetrate): softened laws (*SURFACE BEHAVIOR,
/// PRESSURE-OVERCLOSURE=LINEAR | EXPONENTIAL | TABULAR), the penalty method for hard contact and
/// CalculiX's GAPUNI law. Pressures are per the gap's area: F = A p(g) (A = 1 when no area is
/// given, so "pressure" is a force). Hard contact enforced exactly (DIRECT) and augmented Lagrange
/// are handled by the gap kernel with multipliers.
#include <memory>
#include <vector>

namespace gapfem {

struct GapSection;

class NormalForceLaw {
 public:
  virtual ~NormalForceLaw() = default;
  /// Compressive contact force F(g) and dF/dg. `stiffness_hint` is the representative stiffness of
  /// the elements connected to the gap (for automatic penalty stiffnesses).
  virtual void force(double g, double stiffness_hint, double& F, double& dF_dg) const = 0;
  /// The law's stiffness scale (its penalty, or its steepest slope): below kRowFraction of it a
  /// slope is too soft to be worth a compliant row (MechanicalGapKernel).
  virtual double stiffness_scale(double stiffness_hint) const = 0;
};

/// CalculiX's GAPUNI law (fields 6-7 of *GAP): F = k g (1/2 + atan(g/eps)/pi), eps = pi f_inf / k.
class CcxPenaltyLaw final : public NormalForceLaw {
 public:
  CcxPenaltyLaw(double stiffness, double tension)
      : _k(stiffness), _eps(3.141592653589793 * tension / stiffness) {}
  void force(double g, double, double& F, double& dF_dg) const override;
  double stiffness_scale(double) const override { return _k; }

 private:
  double _k, _eps;
};

/// PRESSURE-OVERCLOSURE=LINEAR: p = k g for g > 0.
class LinearLaw final : public NormalForceLaw {
 public:
  LinearLaw(double slope, double area) : _k(slope * area) {}
  void force(double g, double, double& F, double& dF_dg) const override;
  double stiffness_scale(double) const override { return _k; }

 private:
  double _k;
};

/// PRESSURE-OVERCLOSURE=EXPONENTIAL: p = 0 for g <= -c0, p = p0/(e-1) x (exp(x) - 1) with
/// x = g/c0 + 1 otherwise (p(0) = p0); with K_max > 0 the curve continues linearly with slope K_max
/// beyond the point where its slope reaches K_max.
class ExponentialLaw final : public NormalForceLaw {
 public:
  ExponentialLaw(double c0, double p0, double kmax, double area);
  void force(double g, double, double& F, double& dF_dg) const override;
  double stiffness_scale(double) const override;

 private:
  void raw(double g, double& p, double& dp) const;
  double _c0, _p0, _kmax, _area, _g_switch;
};

/// PRESSURE-OVERCLOSURE=TABULAR: piecewise linear p(g) through the pairs, 0 below the first
/// overclosure, extrapolated with the last slope beyond the last.
class TabularLaw final : public NormalForceLaw {
 public:
  TabularLaw(std::vector<double> p, std::vector<double> g, double area);
  void force(double g, double, double& F, double& dF_dg) const override;
  double stiffness_scale(double) const override;

 private:
  std::vector<double> _p, _g;
  double _area;
};

/// Hard contact by the penalty method: F = K max(g, 0). K: the given stiffness times the area, or
/// (automatic) 10 x the stiffness of the connected elements.
class PenaltyLaw final : public NormalForceLaw {
 public:
  explicit PenaltyLaw(double stiffness) : _k(stiffness) {}
  void force(double g, double hint, double& F, double& dF_dg) const override;
  double stiffness_scale(double hint) const override {
    return _k > 0 ? _k : kAutomaticFactor * hint;
  }
  static constexpr double kAutomaticFactor = 10.0;

 private:
  double _k; ///< 0: automatic
};

/// Multiplier factor of the automatic augmented-Lagrange penalty stiffness.
inline constexpr double kAugmentedAutomaticFactor = 1000.0;

/// The force law of a gap section, or nullptr for hard contact handled with multipliers
/// (DIRECT, augmented Lagrange, NO SEPARATION).
std::unique_ptr<NormalForceLaw> make_normal_law(const GapSection& section);

} // namespace gapfem
