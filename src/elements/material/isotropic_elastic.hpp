#pragma once
/// @file isotropic_elastic.hpp
/// The first solid law: isotropic linear (thermo-)elasticity, sigma = C : (eps - eps_th I) for
/// small strain and S = C : (E - eps_th I) (St. Venant-Kirchhoff) under NLGEOM, with E and nu
/// from the *ELASTIC table and the thermal strain from *EXPANSION at the point's temperature.
/// Plane stress condenses sigma33 = 0 into lambda* = 2 lambda mu / (lambda + 2 mu), a beam fibre
/// sigma22 = sigma33 = 0 into sigma11 = E eps11 (lambda* = 2 mu nu), tau = G gamma. No history.
#include "elements/material/solid_law.hpp"

namespace gapfem {

/// Lame constants and thermal strain at one point (the law's arithmetic, kept in one place).
struct ElasticPoint : IsotropicModuli {
  double eps_th = 0.0;

  /// From Young's modulus, Poisson's ratio and the thermal strain.
  static ElasticPoint make(Kinematics kin, double E, double nu, double eps_th) {
    ElasticPoint p;
    p.mu = E / (2.0 * (1.0 + nu));
    p.lambda3 = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    p.lambda = kin == Kinematics::PlaneStress
                   ? 2.0 * p.lambda3 * p.mu / (p.lambda3 + 2.0 * p.mu)
                   : (kin == Kinematics::Beam ? 2.0 * p.mu * nu : p.lambda3);
    p.eps_th = eps_th;
    return p;
  }

  /// Plane stress: the out-of-plane strain that makes sigma33 = 0, given e11 + e22.
  double plane_stress_e33(double e11_plus_e22) const {
    return eps_th - lambda3 * (e11_plus_e22 - 2.0 * eps_th) / (lambda3 + 2.0 * mu);
  }
};

/// d lambda / dT (the effective lambda of the kinematics: lambda* for plane stress) and d mu / dT
/// from the material's *ELASTIC table at temperature T.
void elastic_derivatives(Kinematics kin, const Material& mat, double T, double& dlambda,
                         double& dmu);

class IsotropicElasticLaw final : public SolidLaw {
 public:
  IsotropicElasticLaw(const Material& material, Kinematics kinematics);

  bool temperature_dependent() const override { return !_const_elastic; }
  bool linear_isotropic_elastic() const override { return true; }
  void update(const MaterialPointInput& in, MaterialPointOutput& out) const override;
  IsotropicModuli elastic_moduli(double T, IsotropicModuli* dT = nullptr) const override;

  /// The hot part of update(): the stress s of the strain e (NS Voigt components, NN of them
  /// normal) and the isotropic tangent's moduli. The kernels call it directly for this law
  /// (solid_point.hpp).
  template <int NS, int NN = (NS == 3 ? 2 : 3)>
  void stress(const double* e, double T, double Ti, bool thermal, double* s,
              IsotropicModuli& moduli) const {
    constexpr int nn = NN;
    const ElasticPoint p = point(T, Ti, thermal);
    double tr = 0.0;
    for (int c = 0; c < nn; ++c) tr += e[c] - p.eps_th;
    for (int c = 0; c < nn; ++c) s[c] = p.lambda * tr + 2.0 * p.mu * (e[c] - p.eps_th);
    for (int c = nn; c < NS; ++c) s[c] = p.mu * e[c];
    moduli = p;
  }

  /// The Lame constants and thermal strain at temperature T (initial temperature Ti).
  ElasticPoint point(double T, double Ti, bool thermal) const {
    ElasticPoint p = _p0;
    if (!_const_elastic) {
      double E = 0.0, nu = 0.0;
      _material.elastic_at(T, E, nu);
      p = ElasticPoint::make(_kin, E, nu, 0.0);
    }
    p.eps_th = thermal ? _material.thermal_strain(T, Ti) : 0.0;
    return p;
  }

 private:
  Material _material;
  Kinematics _kin;
  int _n_normal;
  bool _const_elastic;
  ElasticPoint _p0; ///< the constants when they do not depend on temperature
};

} // namespace gapfem
