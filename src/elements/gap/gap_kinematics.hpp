#pragma once
/// @file gap_kinematics.hpp
/// Clearance h of the mechanical gap elements and its derivatives with respect to the current
/// positions x1, x2 of the two nodes (spec §1.2-1.4, docs/theory/gap_elements.md):
///   GAPUNI/GAPUNIT  h = d + n·(u2 - u1)                      n fixed in space
///   GAPCYL          r = P (x1 - x2), rho = |r|, P = I - a a^T  h = d - sgn(d) rho
///   GAPSPHER        r = x1 - x2,     rho = |r|                 h = d - sgn(d) rho
/// Translation invariance gives dh/dx2 = -dh/dx1 and the Hessian blocks [[H, -H], [-H, H]].
/// The *closure direction* c = -dh/dx1 is the direction in which node 1 moves relative to node 2 to
/// close the gap; it is the local normal of the slip basis (t1, t2) of spec §1.6.
#include "common/types.hpp"

#include <Eigen/Dense>

namespace gapfem {

enum class GapShape : std::uint8_t { Uni, Cyl, Sph };

/// Per-element constants of the kinematics.
struct GapGeometryParams {
  GapShape shape = GapShape::Uni;
  double d = 0.0;
  Eigen::Vector3d n = Eigen::Vector3d::Zero();  ///< GAPUNI: unit closure direction
  Eigen::Vector3d a = Eigen::Vector3d::UnitX(); ///< GAPCYL: unit axis
};

struct GapGeometry {
  double h = 0.0;                               ///< clearance
  Eigen::Vector3d c = Eigen::Vector3d::UnitX(); ///< closure direction = -dh/dx1 (unit)
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();  ///< d2h/dx1dx1
  bool degenerate = false; ///< cyl/sph nodes on the axis/centre: c is not defined by the positions
  double rho = 0.0;
};

/// Evaluate h, c and H at the relative position r12 = x1 - x2 (and relative displacement
/// du = u2 - u1 for GAPUNI). `fallback_c` is used when the direction is undefined (rho ~ 0).
GapGeometry gap_geometry(const GapGeometryParams& p, const Eigen::Vector3d& x1_minus_x2,
                         const Eigen::Vector3d& u2_minus_u1, const Eigen::Vector3d& fallback_c,
                         double length_scale);

/// Local slip basis (spec §1.6): t1 = projection of global X on the plane normal to `normal`
/// (global Z if X is within 0.1 degree of the normal), t2 = normal × t1.
void slip_basis(const Eigen::Vector3d& normal, Eigen::Vector3d& t1, Eigen::Vector3d& t2);

} // namespace gapfem
