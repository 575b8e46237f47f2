#include "elements/gap/normal_law.hpp"

#include "model/section.hpp"

#include <algorithm>
#include <cmath>

namespace gapfem {

void CcxPenaltyLaw::force(double g, double, double& F, double& dF_dg) const {
  constexpr double kPi = 3.141592653589793;
  const double x = g / _eps;
  const double f = 0.5 + std::atan(x) / kPi;
  F = _k * g * f;
  dF_dg = _k * f + _k * x / (kPi * (1.0 + x * x));
}

void LinearLaw::force(double g, double, double& F, double& dF_dg) const {
  F = g > 0 ? _k * g : 0.0;
  dF_dg = g > 0 ? _k : 0.0;
}

ExponentialLaw::ExponentialLaw(double c0, double p0, double kmax, double area)
    : _c0(c0), _p0(p0), _kmax(kmax), _area(area),
      _g_switch(std::numeric_limits<double>::infinity()) {
  if (_kmax > 0) {
    // the slope grows monotonically with g: bisection for dp/dg = K_max
    double lo = -_c0, hi = _c0;
    double p, dp;
    raw(hi, p, dp);
    while (dp < _kmax) {
      hi *= 2;
      raw(hi, p, dp);
    }
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      raw(mid, p, dp);
      (dp < _kmax ? lo : hi) = mid;
    }
    _g_switch = 0.5 * (lo + hi);
  }
}

void ExponentialLaw::raw(double g, double& p, double& dp) const {
  if (g <= -_c0) {
    p = dp = 0.0;
    return;
  }
  const double x = g / _c0 + 1.0;
  const double a = _p0 / (std::exp(1.0) - 1.0);
  const double ex = std::exp(x);
  p = a * x * (ex - 1.0);
  dp = a * (ex - 1.0 + x * ex) / _c0;
}

void ExponentialLaw::force(double g, double, double& F, double& dF_dg) const {
  double p, dp;
  if (g > _g_switch) {
    raw(_g_switch, p, dp);
    p += _kmax * (g - _g_switch);
    dp = _kmax;
  } else {
    raw(g, p, dp);
  }
  F = _area * p;
  dF_dg = _area * dp;
}

double ExponentialLaw::stiffness_scale(double) const {
  if (_kmax > 0) return _area * _kmax;
  double p, dp; // the slope at zero overclosure, where p = p0
  raw(0.0, p, dp);
  return _area * dp;
}

double TabularLaw::stiffness_scale(double) const {
  double s = 0.0;
  for (std::size_t i = 1; i < _g.size(); ++i)
    s = std::max(s, std::abs((_p[i] - _p[i - 1]) / (_g[i] - _g[i - 1])));
  return _area * s;
}

TabularLaw::TabularLaw(std::vector<double> p, std::vector<double> g, double area)
    : _p(std::move(p)), _g(std::move(g)), _area(area) {}

void TabularLaw::force(double g, double, double& F, double& dF_dg) const {
  const std::size_t n = _g.size();
  double p = 0.0, dp = 0.0;
  if (g <= _g.front()) {
    p = 0.0;
    dp = 0.0;
  } else if (g >= _g.back()) {
    const double s = n >= 2 ? (_p[n - 1] - _p[n - 2]) / (_g[n - 1] - _g[n - 2]) : 0.0;
    p = _p.back() + s * (g - _g.back());
    dp = s;
  } else {
    const auto hi =
        static_cast<std::size_t>(std::upper_bound(_g.begin(), _g.end(), g) - _g.begin());
    const std::size_t lo = hi - 1;
    dp = (_p[hi] - _p[lo]) / (_g[hi] - _g[lo]);
    p = _p[lo] + dp * (g - _g[lo]);
  }
  F = _area * p;
  dF_dg = _area * dp;
}

void PenaltyLaw::force(double g, double hint, double& F, double& dF_dg) const {
  const double k = _k > 0 ? _k : kAutomaticFactor * hint;
  F = g > 0 ? k * g : 0.0;
  dF_dg = g > 0 ? k : 0.0;
}

std::unique_ptr<NormalForceLaw> make_normal_law(const GapSection& s) {
  if (s.ccx_penalty) return std::make_unique<CcxPenaltyLaw>(s.ccx_stiffness, s.ccx_tension);
  const SurfaceBehavior& b = s.behavior;
  if (!b.given) return nullptr;
  switch (b.law) {
  case PressureOverclosure::Linear:
    return std::make_unique<LinearLaw>(b.slope, s.area);
  case PressureOverclosure::Exponential:
    return std::make_unique<ExponentialLaw>(b.c0, b.p0, b.max_stiffness, s.area);
  case PressureOverclosure::Tabular:
    return std::make_unique<TabularLaw>(b.table_p, b.table_g, s.area);
  case PressureOverclosure::Hard:
    if (b.method == ContactMethod::Penalty && !b.no_separation)
      return std::make_unique<PenaltyLaw>(b.penalty_stiffness * s.area);
    return nullptr;
  }
  return nullptr;
}

} // namespace gapfem
