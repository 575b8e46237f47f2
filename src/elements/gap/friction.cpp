#include "elements/gap/friction.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace gapfem {
namespace {

/// Linear interpolation of mu in one variable over rows (value, key), constant outside, with slope.
double interp(const std::vector<std::pair<double, double>>& pts, double x, double* slope) {
  if (slope) *slope = 0.0;
  if (pts.size() == 1 || x <= pts.front().second) return pts.front().first;
  if (x >= pts.back().second) return pts.back().first;
  for (std::size_t i = 1; i < pts.size(); ++i)
    if (x <= pts[i].second) {
      const double x0 = pts[i - 1].second, x1 = pts[i].second;
      const double y0 = pts[i - 1].first, y1 = pts[i].first;
      const double s = x1 > x0 ? (y1 - y0) / (x1 - x0) : 0.0;
      if (slope) *slope = s;
      return y0 + s * (x - x0);
    }
  return pts.back().first;
}

} // namespace

FrictionLaw::FrictionLaw(const FrictionSpec& spec, double area) : _spec(spec), _area(area) {
  if (_spec.rows.empty()) _spec.rows.push_back({});
}

double FrictionLaw::elastic_slip(double lc) const {
  if (_spec.elastic_slip) return *_spec.elastic_slip;
  return _spec.slip_tolerance * lc;
}

double FrictionLaw::mu(double rate, double pressure, double temperature, double* dmu_drate,
                       double* dmu_dp) const {
  if (dmu_drate) *dmu_drate = 0.0;
  if (dmu_dp) *dmu_dp = 0.0;
  const auto& rows = _spec.rows;
  if (rows.size() == 1 || _spec.n_columns <= 1) return rows.front().mu;
  // Abaqus tables: the first dependency varies fastest. Interpolate in slip rate within groups of
  // equal (pressure, temperature), then in pressure, then in temperature (linear, constant
  // outside).
  auto group_value = [&](auto pred, double* dr) {
    std::vector<std::pair<double, double>> pts;
    for (const auto& r : rows)
      if (pred(r)) pts.emplace_back(r.mu, r.slip_rate);
    return interp(pts, rate, dr);
  };
  std::vector<double> temps, pressures;
  for (const auto& r : rows) {
    if (std::find(temps.begin(), temps.end(), r.temperature) == temps.end())
      temps.push_back(r.temperature);
  }
  std::sort(temps.begin(), temps.end());
  auto at_temperature = [&](double T, double* dr, double* dp) {
    std::vector<double> ps;
    for (const auto& r : rows)
      if (r.temperature == T && std::find(ps.begin(), ps.end(), r.pressure) == ps.end())
        ps.push_back(r.pressure);
    std::sort(ps.begin(), ps.end());
    std::vector<std::pair<double, double>> by_p, drate_by_p;
    for (double P : ps) {
      double d = 0.0;
      const double v = group_value(
          [&](const FrictionSpec::Row& r) { return r.temperature == T && r.pressure == P; }, &d);
      by_p.emplace_back(v, P);
      drate_by_p.emplace_back(d, P);
    }
    if (dr) *dr = interp(drate_by_p, pressure, nullptr);
    return interp(by_p, pressure, dp);
  };
  if (temps.size() == 1) return at_temperature(temps.front(), dmu_drate, dmu_dp);
  std::vector<std::pair<double, double>> byT, drT, dpT;
  for (double T : temps) {
    double dr = 0.0, dp = 0.0;
    byT.emplace_back(at_temperature(T, &dr, &dp), T);
    drT.emplace_back(dr, T);
    dpT.emplace_back(dp, T);
  }
  if (dmu_drate) *dmu_drate = interp(drT, temperature, nullptr);
  if (dmu_dp) *dmu_dp = interp(dpT, temperature, nullptr);
  return interp(byT, temperature, nullptr);
}

double FrictionLaw::critical_force(double FN, double rate, double temperature, double* dcrit_dN,
                                   double* dcrit_drate) const {
  double dmu_dr = 0.0, dmu_dp = 0.0;
  const double m = mu(rate, FN / _area, temperature, &dmu_dr, &dmu_dp);
  double crit = m * FN;
  double dN = m + dmu_dp * FN / _area;
  double dr = dmu_dr * FN;
  const double cap = _spec.taumax * _area;
  if (crit > cap) {
    crit = cap;
    dN = dr = 0.0;
  }
  if (dcrit_dN) *dcrit_dN = dN;
  if (dcrit_drate) *dcrit_drate = dr;
  return crit;
}

FrictionResponse FrictionLaw::penalty(const Eigen::Vector2d& slip, const Eigen::Vector2d& dslip,
                                      const Eigen::Vector2d& plastic_start, double FN, double dt,
                                      double temperature, double gamma,
                                      const Eigen::Vector2d* previous_slip) const {
  FrictionResponse out;
  out.plastic_slip = plastic_start;
  if (!(FN > 0.0)) return out;
  const double dnorm = dslip.norm();
  const double rate = dt > 0 ? dnorm / dt : 0.0;
  double dcrit_dN = 0.0, dcrit_drate = 0.0;
  const double crit = critical_force(FN, rate, temperature, &dcrit_dN, &dcrit_drate);
  const double k = crit / gamma; // stick stiffness
  const double dk_dN = dcrit_dN / gamma;
  const Eigen::Vector2d e = slip - plastic_start; // elastic slip (trial)
  const Eigen::Vector2d trial = k * e;
  const double tn = trial.norm();
  const bool reversed = previous_slip && tn > crit && crit > 0.0 && e.dot(*previous_slip) < 0.0;
  if (tn <= crit || crit <= 0.0 || reversed) {
    out.predicted_stick = reversed;
    out.force = trial;
    out.dforce_dslip = k * Eigen::Matrix2d::Identity();
    out.dforce_dnormal = dk_dN * e;
    // slip-rate dependence of k is neglected in stick (the rate is the total slip rate)
    return out;
  }
  out.slipping = true;
  const Eigen::Vector2d m = trial / tn;
  out.force = crit * m;
  out.plastic_slip = slip - out.force / k;
  // d(crit e/|e|)/de = crit/|e| (I - m m^T); plus the rate dependence through |dslip|/dt
  const double enorm = e.norm();
  out.dforce_dslip = (crit / enorm) * (Eigen::Matrix2d::Identity() - m * m.transpose());
  if (dt > 0 && dnorm > 0 && dcrit_drate != 0.0)
    out.dforce_dslip += m * (dcrit_drate / dt) * (dslip / dnorm).transpose();
  out.dforce_dnormal = dcrit_dN * m;
  out.dissipation = out.force.dot(out.plastic_slip - plastic_start);
  return out;
}

} // namespace gapfem
