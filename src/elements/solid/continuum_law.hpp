#pragma once
/// @file continuum_law.hpp
/// Isotropic linear (thermo-)elasticity at one integration point, in engineering Voigt notation
/// (normal components first, then engineering shears gamma = 2 E_ij). The same law serves small
/// strain (sigma = C : (eps - eps_th I)) and NLGEOM St. Venant-Kirchhoff (S = C : (E_GL - eps_th
/// I)).
///
/// Component layouts (Abaqus output order):
///   ThreeD        11 22 33 12 13 23   (3 normal components)
///   PlaneStrain   11 22 33 12         (eps33 = 0 kinematically; sigma33 from the law)
///   Axisymmetric  11 22 33 12         (r, z, hoop, rz)
///   PlaneStress   11 22 12            (sigma33 = 0 condensed: lambda* = 2 lambda mu / (lambda + 2
///   mu))
#include "model/material.hpp"

#include <cstdint>

namespace gapfem {

/// Kinematic class of a continuum element.
enum class Kinematics : std::uint8_t { ThreeD, PlaneStress, PlaneStrain, Axisymmetric };

/// Lame constants and thermal strain at one point. `lambda` is the effective constant that enters
/// the law (lambda* for plane stress); `lambda3` is the 3-D value (for the plane-stress eps33).
struct ElasticPoint {
  double lambda = 0.0;
  double lambda3 = 0.0;
  double mu = 0.0;
  double eps_th = 0.0;

  /// From Young's modulus, Poisson's ratio and the thermal strain.
  static ElasticPoint make(Kinematics kin, double E, double nu, double eps_th) {
    ElasticPoint p;
    p.mu = E / (2.0 * (1.0 + nu));
    p.lambda3 = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    p.lambda = kin == Kinematics::PlaneStress ? 2.0 * p.lambda3 * p.mu / (p.lambda3 + 2.0 * p.mu)
                                              : p.lambda3;
    p.eps_th = eps_th;
    return p;
  }

  /// Stress from strain (Voigt, `n_normal` normal components first, `n` in total).
  template <class VecS>
  void stress(int n_normal, const VecS& e, VecS& s) const {
    double tr = 0.0;
    for (int c = 0; c < n_normal; ++c) tr += e(c) - eps_th;
    for (int c = 0; c < n_normal; ++c) s(c) = lambda * tr + 2.0 * mu * (e(c) - eps_th);
    for (int c = n_normal; c < e.size(); ++c) s(c) = mu * e(c);
  }

  /// D * B for a strain-displacement matrix B (rows = Voigt components).
  template <class MatB>
  void apply(int n_normal, const MatB& B, MatB& DB) const {
    auto tr = B.row(0).eval();
    for (int c = 1; c < n_normal; ++c) tr += B.row(c);
    for (int c = 0; c < n_normal; ++c) DB.row(c) = 2.0 * mu * B.row(c) + lambda * tr;
    for (int c = n_normal; c < B.rows(); ++c) DB.row(c) = mu * B.row(c);
  }

  /// Plane stress: the out-of-plane strain that makes sigma33 = 0, given e11 + e22.
  double plane_stress_e33(double e11_plus_e22) const {
    return eps_th - lambda3 * (e11_plus_e22 - 2.0 * eps_th) / (lambda3 + 2.0 * mu);
  }
};

} // namespace gapfem
