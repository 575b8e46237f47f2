#include "elements/heat/heat_material.hpp"

#include <algorithm>

namespace gapfem {

HeatMaterial::HeatMaterial(const Material& m)
    : _name(m.name), _k(m.conductivity), _rho(m.density), _c(m.specific_heat) {
  if (_k.empty()) { // the reader requires *CONDUCTIVITY; keep the kernel defined regardless
    _k.n_values = 1;
    _k.values = {0.0};
  }
  if (!has_capacity()) return;
  for (const PropertyTable* t : {&_rho, &_c})
    if (t->n_rows() > 1) _T.insert(_T.end(), t->keys.begin(), t->keys.end());
  std::sort(_T.begin(), _T.end());
  _T.erase(std::unique(_T.begin(), _T.end()), _T.end());
  if (_T.empty()) _T.push_back(0.0);
  _E.assign(_T.size(), 0.0);
  for (std::size_t i = 1; i < _T.size(); ++i) {
    const double a = _T[i - 1], b = _T[i];
    _E[i] = _E[i - 1] + (b - a) / 6.0 * (capacity(a) + 4.0 * capacity(0.5 * (a + b)) + capacity(b));
  }
}

double HeatMaterial::capacity(double T) const {
  if (!has_capacity()) return 0.0;
  return _rho.value(T) * _c.value(T);
}

double HeatMaterial::energy(double T) const {
  if (!has_capacity()) return 0.0;
  // Below the first and above the last breakpoint rho c is constant.
  if (T <= _T.front()) return capacity(_T.front()) * (T - _T.front());
  if (T >= _T.back()) return _E.back() + capacity(_T.back()) * (T - _T.back());
  const auto it = std::upper_bound(_T.begin(), _T.end(), T);
  const std::size_t i = static_cast<std::size_t>(it - _T.begin()) - 1;
  const double a = _T[i];
  // rho c is quadratic on [a, T]: Simpson's rule is exact.
  return _E[i] + (T - a) / 6.0 * (capacity(a) + 4.0 * capacity(0.5 * (a + T)) + capacity(T));
}

} // namespace gapfem
