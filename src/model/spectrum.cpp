#include "model/spectrum.hpp"

#include <algorithm>
#include <cmath>

namespace gapfem {
namespace {

/// One curve at f: log-log between its points (linear when a value is not positive), the end
/// values outside.
double along(const Spectrum::Curve& c, double f, bool& clamped) {
  const auto& x = c.frequency;
  const auto& y = c.value;
  if (x.size() == 1) return y[0];
  if (f <= x.front() || f >= x.back()) {
    clamped |= f < x.front() || f > x.back();
    return f <= x.front() ? y.front() : y.back();
  }
  const std::size_t k =
      static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), f) - x.begin());
  const double x0 = x[k - 1], x1 = x[k], y0 = y[k - 1], y1 = y[k];
  if (x0 > 0.0 && y0 > 0.0 && y1 > 0.0) {
    const double t = std::log(f / x0) / std::log(x1 / x0);
    return std::exp(std::log(y0) + t * std::log(y1 / y0));
  }
  return y0 + (y1 - y0) * (f - x0) / (x1 - x0);
}

} // namespace

double Spectrum::value(double f, double zeta, bool* clamped) const {
  bool out = false;
  double v = 0.0;
  if (curves.size() == 1 || zeta <= curves.front().damping) {
    out = curves.size() > 1 && zeta < curves.front().damping;
    v = along(curves.front(), f, out);
  } else if (zeta >= curves.back().damping) {
    out = zeta > curves.back().damping;
    v = along(curves.back(), f, out);
  } else {
    std::size_t k = 1;
    while (curves[k].damping < zeta) ++k;
    const Curve& a = curves[k - 1];
    const Curve& b = curves[k];
    const double t = (zeta - a.damping) / (b.damping - a.damping);
    v = (1.0 - t) * along(a, f, out) + t * along(b, f, out);
  }
  if (clamped) *clamped |= out;
  return type == Type::G ? v * g : v;
}

double Spectrum::displacement(double f, double zeta, bool* clamped) const {
  const double w = 2.0 * 3.14159265358979323846 * f;
  if (!(w > 0.0)) return 0.0;
  const double s = value(f, zeta, clamped);
  switch (type) {
  case Type::Displacement:
    return s;
  case Type::Velocity:
    return s / w;
  case Type::Acceleration:
  case Type::G:
    return s / (w * w);
  }
  return s;
}

} // namespace gapfem
