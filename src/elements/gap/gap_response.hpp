#pragma once
/// @file gap_response.hpp
/// Internal to the mechanical gap kernel (mechanical_gap.cpp, gap_response.cpp): what one
/// evaluation computes, stage by stage (geometry, normal behaviour, friction, damping, heat) before
/// the residual and tangent are assembled.
#include "elements/gap/mechanical_gap.hpp"

#include <Eigen/Dense>

namespace gapfem {

inline constexpr int kGapMaxDofs = 8;
using GapVec = Eigen::Matrix<double, kGapMaxDofs, 1>;

/// The results of one evaluation that output and augmentation read.
struct MechanicalGapKernel::Response {
  GapGeometry geom;
  Eigen::Vector3d t1, t2;
  ContactStatus status = ContactStatus::Open;
  double g = 0.0;             ///< overclosure -(h + v)
  double normal_force = 0.0;  ///< contact force (compression > 0)
  double damping_force = 0.0; ///< normal damping force (compression > 0)
  Eigen::Vector2d slip = Eigen::Vector2d::Zero();
  Eigen::Vector2d friction = Eigen::Vector2d::Zero();
  Eigen::Vector2d tangential_damping = Eigen::Vector2d::Zero();
  double dissipation = 0.0;
  GapThermalModel::Flux heat; ///< GAPUNIT conduction/radiation
  double heat_rate = 0.0;     ///< frictional heating rate eta * dissipation / dt
};

/// Intermediate quantities of one evaluation, passed from stage to stage.
struct MechanicalGapKernel::Local {
  int nd = 0;
  bool update = false;    ///< writing trial state and multipliers (evaluate), or only reading
  GapVec dg;              ///< d g / d u = [c, -c]
  GapVec ds[2];           ///< d s_a / d u = [t_a, -t_a] (slip basis frozen over the increment)
  GapVec q[2];            ///< directions of the friction forces: [P t_a, -P t_a]
  bool projected = false; ///< rotating gap: friction forces projected on the current tangent plane
  Eigen::Vector2d dslip = Eigen::Vector2d::Zero(), slip_start = Eigen::Vector2d::Zero();
  Eigen::Vector2d plastic_start = Eigen::Vector2d::Zero(), plastic = Eigen::Vector2d::Zero();
  ContactStatus previous = ContactStatus::Open, status = ContactStatus::Open;
  bool was_closed = false;
  /// A linear perturbation step (*FREQUENCY): the status is the base state's, frozen (a closed
  /// gap bilateral, sticking when it has friction; docs/theory/frequency.md)
  bool perturbation = false;
  double hint = 0.0, dt = 0.0, temperature = 0.0;
  int iT1 = -1, iT2 = -1; ///< GAPUNIT temperature DOFs
  // normal behaviour
  double FN = 0.0, dFN_dg = 0.0;
  bool lagrange_normal = false, is_closed = false;
  /// a force law's stiffness carried by a compliant row (compliance 1/F') instead of the tangent
  bool compliant_row = false;
  double row_compliance = 0.0;
  // friction
  const FrictionLaw* fl = nullptr;
  Eigen::Matrix2d dtau_ds = Eigen::Matrix2d::Zero();
  Eigen::Vector2d dtau_dN = Eigen::Vector2d::Zero();
  bool friction_rows = false;   ///< Lagrange stick rows are active
  bool predicted_stick = false; ///< penalty stick predicted after a slip reversal
  /// elastic-slip stiffness carried by compliant rows (slots 1, 2): directions, compliances
  int n_slip_rows = 0;
  GapVec slip_row[2];
  double slip_row_compliance[2] = {0.0, 0.0};
  bool slip_in_rows = false; ///< the slip tangent went to rows (what is left in dtau_ds is ~0)
  Eigen::Vector2d dD_de = Eigen::Vector2d::Zero(); ///< d(dissipation)/d(elastic slip)
  double dD_dN = 0.0;                              ///< d(dissipation)/d(normal force)
  // contact damping
  double Fd = 0.0, dFd_du = 0.0, dtd = 0.0, dcoef_dh_t = 0.0;
  double closure = 0.0; ///< the increment's closure h_start - h (the damping force's work)
  Eigen::Vector2d td = Eigen::Vector2d::Zero();
  // frictional heating
  double w1 = 0.0, w2 = 0.0, eta_dt = 0.0;
};

} // namespace gapfem
