#pragma once
// Oracle for GAPCYL/GAPSPHER units of the random models: node P (gap node 1) on SPRING1 springs
// (stiffness k_x, k_y, k_z, to ground), centre node C (gap node 2) prescribed, frictionless. The
// answer at a load F is the minimum of 1/2 (x - x_f)^T K (x - x_f), x_f = X_P + K^-1 F, subject to
// the gap condition on r = P (x - x_C) (P = I for GAPSPHER, I - a a^T for GAPCYL):
//   d > 0: |r| <= d (convex): closed where |r(x_f)| > d, then (K + (l/d) P) x = K x_f + (l/d) P x_C
//          with the multiplier l >= 0 found by bisection on |r(x(l))| = d (monotone in l);
//   d < 0: |r| >= |d| with K = k I: x moves out along the radial line through x_f, l = k (|d| -
//   |r_f|).
#include "random_models.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>

namespace gapfem::test::random_contact {

struct RadialAnswer {
  Eigen::Vector3d x; ///< position of P
  double force = 0.0;
  bool closed = false;
};

inline RadialAnswer solve_radial(const Eigen::Vector3d& k, const Eigen::Vector3d& XP,
                                 const Eigen::Vector3d& F, const Eigen::Vector3d& xC, double d,
                                 const Eigen::Matrix3d& P) {
  RadialAnswer a;
  const Eigen::Matrix3d K = k.asDiagonal();
  const Eigen::Vector3d xf = XP + F.cwiseQuotient(k);
  const Eigen::Vector3d rf = P * (xf - xC);
  if (d > 0) {
    if (rf.norm() <= d) {
      a.x = xf;
      return a;
    }
    auto x_of = [&](double l) -> Eigen::Vector3d {
      return (K + (l / d) * P).ldlt().solve(K * xf + (l / d) * P * xC);
    };
    double lo = 0.0, hi = k.maxCoeff() * d;
    while ((P * (x_of(hi) - xC)).norm() > d) hi *= 2;
    for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
      const double mid = 0.5 * (lo + hi);
      ((P * (x_of(mid) - xC)).norm() > d ? lo : hi) = mid;
    }
    a.x = x_of(0.5 * (lo + hi));
    a.force = 0.5 * (lo + hi);
    a.closed = true;
    return a;
  }
  const double R = -d;
  if (rf.norm() >= R) {
    a.x = xf;
    return a;
  }
  if (rf.norm() == 0.0) throw std::runtime_error("radial oracle: free position on the axis");
  a.x = xf + (R / rf.norm() - 1.0) * rf;
  a.force = k[0] * (R - rf.norm());
  a.closed = true;
  return a;
}

} // namespace gapfem::test::random_contact
