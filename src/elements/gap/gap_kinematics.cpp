#include "elements/gap/gap_kinematics.hpp"

#include <cmath>

namespace gapfem {

GapGeometry gap_geometry(const GapGeometryParams& p, const Eigen::Vector3d& r12,
                         const Eigen::Vector3d& du21, const Eigen::Vector3d& fallback_c,
                         double length_scale) {
  GapGeometry g;
  if (p.shape == GapShape::Uni) {
    g.h = p.d + p.n.dot(du21);
    g.c = p.n;
    return g;
  }
  Eigen::Vector3d r = r12;
  Eigen::Matrix3d P = Eigen::Matrix3d::Identity();
  if (p.shape == GapShape::Cyl) {
    P -= p.a * p.a.transpose();
    r = P * r12;
  }
  const double rho = r.norm();
  const double s = p.d > 0 ? 1.0 : -1.0;
  g.rho = rho;
  g.h = p.d - s * rho;
  if (rho <= 1e-14 * length_scale) {
    g.degenerate = true;
    g.c = fallback_c;
    return g;
  }
  const Eigen::Vector3d nr = r / rho; // radial direction, from node 2's axis/centre to node 1
  g.c = s * nr;                       // -dh/dx1 = s * d(rho)/dx1 = s * nr
  g.H = -s * (P - nr * nr.transpose()) / rho; // d2h/dx1^2 = -s d2(rho)/dx1^2
  return g;
}

void slip_basis(const Eigen::Vector3d& normal, Eigen::Vector3d& t1, Eigen::Vector3d& t2) {
  constexpr double kCos01Deg = 0.9999984769132877; // cos(0.1 degree)
  const Eigen::Vector3d axis =
      std::abs(normal.x()) > kCos01Deg ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
  t1 = axis - axis.dot(normal) * normal;
  t1.normalize();
  t2 = normal.cross(t1);
}

} // namespace gapfem
