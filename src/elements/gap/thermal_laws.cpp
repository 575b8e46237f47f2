#include "elements/gap/thermal_laws.hpp"

#include "model/model.hpp"
#include "model/section.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace gapfem {
namespace {

/// Interval of `at` in the ascending `x`: index lo with x[lo] <= at < x[lo + 1] (clamped).
std::size_t interval(const std::vector<double>& x, double at) {
  const auto it = std::upper_bound(x.begin(), x.end(), at);
  const auto hi = static_cast<std::size_t>(it - x.begin());
  return std::clamp<std::size_t>(hi, 1, x.size() - 1) - 1;
}

} // namespace

// ------------------------------------------------------------------------- conductance

GapConductanceLaw::GapConductanceLaw(const GapConductanceSpec& spec) : _pressure(spec.pressure) {
  if (spec.rows.empty())
    throw InputError(spec.loc, "*GAP CONDUCTANCE needs data lines (conductance, clearance)");
  for (const auto& row : spec.rows) {
    if (_groups.empty() || row.temperature != _groups.back().temperature) {
      if (!_groups.empty() && !(row.temperature > _groups.back().temperature))
        throw InputError(
            spec.loc,
            fmt::format("the data lines must be grouped by temperature in ascending order "
                        "(temperature {} follows {}); give all lines of the lowest temperature "
                        "first",
                        row.temperature, _groups.back().temperature));
      _groups.push_back({row.temperature, {}, {}});
    }
    _groups.back().x.push_back(row.x);
    _groups.back().k.push_back(row.k);
  }
}

void GapConductanceLaw::group_value(const Group& g, double x, double& k, double& dk_dx) const {
  dk_dx = 0.0;
  if (x <= g.x.front()) {
    k = g.k.front();
    return;
  }
  if (x > g.x.back()) {
    k = _pressure ? g.k.back() : 0.0;
    return;
  }
  if (g.x.size() == 1) { // x == the only point
    k = g.k.front();
    return;
  }
  const std::size_t lo = interval(g.x, x);
  const double span = g.x[lo + 1] - g.x[lo];
  dk_dx = (g.k[lo + 1] - g.k[lo]) / span;
  k = g.k[lo] + dk_dx * (x - g.x[lo]);
}

ConductanceValue GapConductanceLaw::evaluate(double x, double Tbar) const {
  ConductanceValue v;
  if (_groups.size() == 1 || Tbar <= _groups.front().temperature) {
    group_value(_groups.front(), x, v.k, v.dk_dx);
    return v;
  }
  if (Tbar >= _groups.back().temperature) {
    group_value(_groups.back(), x, v.k, v.dk_dx);
    return v;
  }
  std::size_t lo = 0;
  while (_groups[lo + 1].temperature <= Tbar) ++lo;
  const Group& a = _groups[lo];
  const Group& b = _groups[lo + 1];
  double ka, da, kb, db;
  group_value(a, x, ka, da);
  group_value(b, x, kb, db);
  const double span = b.temperature - a.temperature;
  const double w = (Tbar - a.temperature) / span;
  v.k = ka + w * (kb - ka);
  v.dk_dx = da + w * (db - da);
  v.dk_dT = (kb - ka) / span;
  return v;
}

GapFluxValue GapConductanceLaw::conduction(double Ta, double Tb, double x) const {
  const ConductanceValue c = evaluate(x, 0.5 * (Ta + Tb));
  const double dT = Ta - Tb;
  GapFluxValue f;
  f.q = c.k * dT;
  f.dq_dTa = c.k + 0.5 * c.dk_dT * dT;
  f.dq_dTb = -c.k + 0.5 * c.dk_dT * dT;
  f.dq_dx = c.dk_dx * dT;
  return f;
}

// ------------------------------------------------------------------------- radiation

GapRadiationLaw::GapRadiationLaw(const GapRadiationSpec& spec, const PhysicalConstants& constants)
    : _h(spec.clearance), _F(spec.view_factor) {
  std::string missing;
  if (!constants.absolute_zero) missing = "ABSOLUTE ZERO=";
  if (!constants.stefan_boltzmann)
    missing += std::string(missing.empty() ? "" : " and ") + "STEFAN BOLTZMANN=";
  if (!missing.empty())
    throw InputError(spec.loc,
                     fmt::format("gap radiation needs the absolute zero and the Stefan-Boltzmann "
                                 "constant; add *PHYSICAL CONSTANTS with {} to the model data",
                                 missing));
  if (_h.empty() || _h.size() != _F.size())
    throw InputError(spec.loc, "*GAP RADIATION needs at least one line of view factor, clearance");
  const double inv = 1.0 / spec.emissivity_a + 1.0 / spec.emissivity_b - 1.0;
  _factor = *constants.stefan_boltzmann / inv;
  _zero = *constants.absolute_zero;
}

double GapRadiationLaw::coefficient(double h, double* dC_dh) const {
  double F, dF = 0.0;
  if (_h.size() == 1 || h <= _h.front()) {
    F = _F.front();
  } else if (h >= _h.back()) {
    F = _F.back();
  } else {
    const std::size_t lo = interval(_h, h);
    dF = (_F[lo + 1] - _F[lo]) / (_h[lo + 1] - _h[lo]);
    F = _F[lo] + dF * (h - _h[lo]);
  }
  if (dC_dh) *dC_dh = _factor * dF;
  return _factor * F;
}

GapFluxValue GapRadiationLaw::evaluate(double Ta, double Tb, double h) const {
  double dC = 0.0;
  const double C = coefficient(h, &dC);
  const double a = Ta - _zero, b = Tb - _zero;
  const double a2 = a * a, b2 = b * b;
  GapFluxValue f;
  f.q = C * (a2 * a2 - b2 * b2);
  f.dq_dTa = 4.0 * C * a2 * a;
  f.dq_dTb = -4.0 * C * b2 * b;
  f.dq_dx = dC * (a2 * a2 - b2 * b2);
  return f;
}

// ------------------------------------------------------------------------- heat generation

GapHeatGeneration::GapHeatGeneration(const GapHeatGenerationSpec& spec)
    : _eta(spec.eta), _f(spec.fraction) {}

} // namespace gapfem
