#pragma once
/// @file friction.hpp
/// Isotropic Coulomb friction for gap elements (*FRICTION after *GAP): the friction coefficient
/// (optionally tabulated against slip rate, contact pressure and temperature), the critical shear
/// force min(mu F_N, taumax A), and the stick/slip return mapping with an elastic-slip stick
/// stiffness k = tau_crit / gamma_crit (Abaqus's penalty friction), with consistent derivatives.
#include "model/section.hpp"

#include <Eigen/Dense>

namespace gapfem {

/// Derivatives a gap kernel needs from one friction evaluation.
struct FrictionResponse {
  bool slipping = false;
  Eigen::Vector2d force = Eigen::Vector2d::Zero(); ///< friction force on the elastic-slip sense
  Eigen::Matrix2d dforce_dslip = Eigen::Matrix2d::Zero();   ///< d force / d (slip increment)
  Eigen::Vector2d dforce_dnormal = Eigen::Vector2d::Zero(); ///< d force / d F_N
  Eigen::Vector2d plastic_slip = Eigen::Vector2d::Zero();   ///< updated plastic slip
  double dissipation = 0.0; ///< force · plastic slip increment of this evaluation
  /// the trial force exceeded tau_crit against the slip direction of the previous iteration, so
  /// the evaluation was taken as stick (see FrictionLaw::penalty)
  bool predicted_stick = false;
};

class FrictionLaw {
 public:
  /// area: the gap area (pressure = F_N / area, taumax in stress units); elastic_slip: absolute
  /// allowable elastic slip gamma_crit.
  FrictionLaw(const FrictionSpec& spec, double area);

  bool rough() const { return _spec.rough; }
  bool lagrange() const { return _spec.lagrange || _spec.rough; }
  /// gamma_crit for an element of characteristic length lc.
  double elastic_slip(double lc) const;
  /// Friction coefficient and its derivatives with respect to slip rate and pressure.
  double mu(double slip_rate, double pressure, double temperature, double* dmu_drate = nullptr,
            double* dmu_dpressure = nullptr) const;
  /// Critical friction force for normal force F_N (>= 0) and its derivative.
  double critical_force(double normal_force, double slip_rate, double temperature,
                        double* dcrit_dnormal = nullptr, double* dcrit_drate = nullptr) const;

  /// Penalty return mapping. slip: accumulated slip (t1, t2) now; slip_increment: its change in
  /// this increment; plastic_start: plastic slip at the start of the increment; dt: increment size
  /// (for the slip rate); gamma: elastic slip.
  ///
  /// previous_slip: the slip direction of the previous Newton iteration when that iteration
  /// slipped (else nullptr). The slip tangent has no stiffness along the slip direction, so a
  /// Newton step from a slipping state that should end in stick jumps over the whole stick band
  /// (width 2 gamma, tiny for a small elastic slip) and lands in slip the other way; the next step
  /// jumps back, and Newton alternates between the two. A trial force that has turned against the
  /// previous slip direction is therefore taken as stick (the stick predictor): the stick branch is
  /// linear, so the next step lands on the stick solution, which is then either consistent (stick,
  /// converged) or outside the band in the true slip direction. The predicted evaluation is
  /// flagged (predicted_stick) so that Newton does not accept it.
  FrictionResponse penalty(const Eigen::Vector2d& slip, const Eigen::Vector2d& slip_increment,
                           const Eigen::Vector2d& plastic_start, double normal_force, double dt,
                           double temperature, double gamma,
                           const Eigen::Vector2d* previous_slip = nullptr) const;

 private:
  FrictionSpec _spec;
  double _area;
};

} // namespace gapfem
