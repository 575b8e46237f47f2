// The isotropic (thermo-)elastic solid law.
#include "elements/material/isotropic_elastic.hpp"

#include <array>

namespace gapfem {

void elastic_derivatives(Kinematics kin, const Material& mat, double T, double& dlambda,
                         double& dmu) {
  std::array<double, 2> v{}, dv{};
  mat.elastic.evaluate(T, v, dv);
  const double E = v[0], nu = v[1], dE = dv[0], dnu = dv[1];
  dmu = dE / (2.0 * (1.0 + nu)) - E * dnu / (2.0 * (1.0 + nu) * (1.0 + nu));
  const double D = (1.0 + nu) * (1.0 - 2.0 * nu);
  const double dD = dnu * (1.0 - 2.0 * nu) - 2.0 * dnu * (1.0 + nu);
  const double l3 = E * nu / D;
  const double dl3 = (dE * nu + E * dnu) / D - E * nu * dD / (D * D);
  if (kin == Kinematics::PlaneStress) {
    const double mu = E / (2.0 * (1.0 + nu));
    const double s = l3 + 2.0 * mu;
    dlambda = (2.0 * (dl3 * mu + l3 * dmu) * s - 2.0 * l3 * mu * (dl3 + 2.0 * dmu)) / (s * s);
  } else if (kin == Kinematics::Beam) { // lambda* = 2 mu nu
    const double mu = E / (2.0 * (1.0 + nu));
    dlambda = 2.0 * (dmu * nu + mu * dnu);
  } else {
    dlambda = dl3;
  }
}

IsotropicElasticLaw::IsotropicElasticLaw(const Material& material, Kinematics kinematics)
    : _material(material), _kin(kinematics), _n_normal(voigt_normals(kinematics)),
      _const_elastic(material.elastic.n_rows() <= 1 || material.elastic.keys.size() <= 1) {
  if (_const_elastic) {
    double E = 0.0, nu = 0.0;
    _material.elastic_at(0.0, E, nu);
    _p0 = ElasticPoint::make(_kin, E, nu, 0.0);
  }
}

void IsotropicElasticLaw::update(const MaterialPointInput& in, MaterialPointOutput& out) const {
  const auto n = static_cast<int>(in.strain.size());
  const double* e = in.strain.data();
  const double T = in.temperature, Ti = in.initial_temperature;
  if (n == 6)
    stress<6>(e, T, Ti, in.thermal, out.stress.data(), out.moduli);
  else if (_kin == Kinematics::Beam)
    stress<3, 1>(e, T, Ti, in.thermal, out.stress.data(), out.moduli);
  else if (n == 4)
    stress<4>(e, T, Ti, in.thermal, out.stress.data(), out.moduli);
  else
    stress<3>(e, T, Ti, in.thermal, out.stress.data(), out.moduli);
  out.isotropic = true;
  if (out.dstress_dT.empty() && !in.recovery) return;
  const ElasticPoint p = point(T, Ti, in.thermal);
  const int nn = _n_normal;
  double tr = 0.0;
  for (int c = 0; c < nn; ++c) tr += e[c] - p.eps_th;
  if (!out.dstress_dT.empty()) {
    const double deth = _material.thermal_strain_derivative(in.temperature);
    double dlambda = 0.0, dmu = 0.0;
    if (!_const_elastic) elastic_derivatives(_kin, _material, in.temperature, dlambda, dmu);
    for (int c = 0; c < nn; ++c)
      out.dstress_dT[c] =
          dlambda * tr + 2.0 * dmu * (e[c] - p.eps_th) - deth * (p.lambda * nn + 2.0 * p.mu);
    for (int c = nn; c < n; ++c) out.dstress_dT[c] = dmu * e[c];
  }
  if (in.recovery) {
    double w = 0.0; // 1/2 S : (E - eps_th I)
    for (int c = 0; c < n; ++c) w += out.stress[c] * (e[c] - (c < nn ? p.eps_th : 0.0));
    out.energy = 0.5 * w;
    out.thickness_strain = _kin == Kinematics::PlaneStress ? p.plane_stress_e33(e[0] + e[1]) : 0.0;
  }
}

IsotropicModuli IsotropicElasticLaw::elastic_moduli(double T, IsotropicModuli* dT) const {
  if (dT) {
    *dT = {};
    if (!_const_elastic) elastic_derivatives(_kin, _material, T, dT->lambda, dT->mu);
  }
  return point(T, T, false);
}

} // namespace gapfem
