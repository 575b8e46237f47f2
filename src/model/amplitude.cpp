// *AMPLITUDE curves, their slopes and antiderivatives in closed form. The definitions follow the
// Abaqus Analysis User's Guide, "Amplitude curves" (docs/theory/dynamics.md, "Base motion").
#include "model/amplitude.hpp"

#include <algorithm>
#include <cmath>

namespace gapfem {

namespace {

/// The shape of one table segment in xi in [0, 1] (linear: xi; smooth step: xi^3 (10 - 15 xi +
/// 6 xi^2)) and, for which = 1..3, its derivative, integral from 0 and double integral from 0.
double shape(bool smooth, double xi, int which) {
  if (!smooth) {
    switch (which) {
    case 0:
      return xi;
    case 1:
      return 1.0;
    case 2:
      return 0.5 * xi * xi;
    default:
      return xi * xi * xi / 6.0;
    }
  }
  const double x2 = xi * xi, x3 = x2 * xi;
  switch (which) {
  case 0:
    return x3 * (10.0 - 15.0 * xi + 6.0 * x2);
  case 1:
    return 30.0 * x2 * (1.0 - xi) * (1.0 - xi);
  case 2:
    return x2 * x2 * (2.5 - 3.0 * xi + x2);
  default:
    return x3 * x2 * (0.5 - 0.5 * xi + x2 / 7.0);
  }
}

/// cos(c s) over s in [0, tau]: which 0: cos(c tau), 1: its derivative, 2: integral from 0,
/// 3: double integral from 0 (stable for small c tau).
double cosine(double c, double tau, int which) {
  const double h = 0.5 * c * tau;
  switch (which) {
  case 0:
    return std::cos(c * tau);
  case 1:
    return -c * std::sin(c * tau);
  case 2:
    return c == 0.0 ? tau : std::sin(c * tau) / c;
  default: {
    if (c == 0.0) return 0.5 * tau * tau;
    const double s = std::sin(h) / c;
    return 2.0 * s * s;
  }
  }
}

/// The same for sin(c s).
double sine(double c, double tau, int which) {
  const double h = 0.5 * c * tau;
  switch (which) {
  case 0:
    return std::sin(c * tau);
  case 1:
    return c * std::cos(c * tau);
  case 2:
    return c == 0.0 ? 0.0 : 2.0 * std::sin(h) * std::sin(h) / c;
  default: {
    const double ct = c * tau;
    if (std::abs(ct) < 1e-3) // tau/c - sin(c tau)/c^2 by its series: no cancellation
      return c * tau * tau * tau / 6.0 * (1.0 - ct * ct / 20.0);
    return (ct - std::sin(ct)) / (c * c);
  }
  }
}

/// a0 (value 0), its slope (1), antiderivatives a0 r (2), a0 r^2/2 (3).
double constant(double a0, double r, int which) {
  switch (which) {
  case 0:
    return a0;
  case 1:
    return 0.0;
  case 2:
    return a0 * r;
  default:
    return 0.5 * a0 * r * r;
  }
}

} // namespace

void Amplitude::finish() {
  if (kind != Kind::Tabular && kind != Kind::SmoothStep) return;
  const bool smooth = kind == Kind::SmoothStep;
  c1.assign(t.size(), 0.0);
  c2.assign(t.size(), 0.0);
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    const double h = t[i + 1] - t[i], d = a[i + 1] - a[i];
    c1[i + 1] = c1[i] + a[i] * h + d * h * shape(smooth, 1.0, 2);
    c2[i + 1] = c2[i] + c1[i] * h + 0.5 * a[i] * h * h + d * h * h * shape(smooth, 1.0, 3);
  }
}

double Amplitude::raw_table(double r, int which) const {
  if (t.empty()) return constant(1.0, r, which);
  const bool smooth = kind == Kind::SmoothStep;
  const std::size_t n = t.size();
  // the segment [t_i, t_i+1] holding r; before the first or after the last point the curve is
  // constant (index 0 or n-1, no segment)
  std::size_t i = 0;
  bool inside = false;
  if (r >= t.back()) {
    i = n - 1;
  } else if (r > t.front()) {
    i = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), r) - t.begin()) - 1;
    inside = true;
  } else if (r == t.front() && n > 1) {
    inside = true;
  }
  const double dx = r - t[i];
  const double base_c1 = c1.empty() ? 0.0 : c1[i], base_c2 = c2.empty() ? 0.0 : c2[i];
  double h = 1.0, d = 0.0, xi = 0.0;
  if (inside) {
    h = t[i + 1] - t[i];
    d = a[i + 1] - a[i];
    xi = dx / h;
  }
  switch (which) {
  case 0:
    return a[i] + d * shape(smooth, xi, 0);
  case 1:
    return inside ? d / h * shape(smooth, xi, 1) : 0.0;
  case 2:
    return base_c1 + a[i] * dx + d * h * shape(smooth, xi, 2);
  default:
    return base_c2 + base_c1 * dx + 0.5 * a[i] * dx * dx + d * h * h * shape(smooth, xi, 3);
  }
}

double Amplitude::raw(double r, int which) const {
  const double tau = r - t0;
  switch (kind) {
  case Kind::Tabular:
  case Kind::SmoothStep:
    return raw_table(r, which);
  case Kind::Periodic: {
    double v = constant(a0, r, which);
    if (tau < 0.0) return v;
    // the series, and for the integrals its integrals from t0 (continuous there: zero at t0)
    for (std::size_t k = 0; k + 1 < coef.size(); k += 2) {
      const double c = static_cast<double>(k / 2 + 1) * omega;
      v += coef[k] * cosine(c, tau, which) + coef[k + 1] * sine(c, tau, which);
    }
    return v;
  }
  case Kind::Modulated: {
    // sin(w1 s) sin(w2 s) = (cos((w1 - w2) s) - cos((w1 + w2) s)) / 2
    double v = constant(a0, r, which);
    if (tau <= 0.0) return v;
    return v +
           0.5 * amp * (cosine(omega - omega2, tau, which) - cosine(omega + omega2, tau, which));
  }
  case Kind::Decay: {
    double v = constant(a0, r, which);
    if (tau < 0.0) return v;
    const double e = std::exp(-tau / td), m1 = -std::expm1(-tau / td); // 1 - e
    switch (which) {
    case 0:
      return v + amp * e;
    case 1:
      return v - amp / td * e;
    case 2:
      return v + amp * td * m1;
    default:
      return v + amp * td * (tau - td * m1);
    }
  }
  }
  return 0.0;
}

double Amplitude::at(double x) const {
  return scale_y * raw((x - shift_x) / scale_x, 0) + shift_y;
}

double Amplitude::slope(double x) const {
  return scale_y / scale_x * raw((x - shift_x) / scale_x, 1);
}

double Amplitude::integral(double x) const {
  return scale_y * scale_x * raw((x - shift_x) / scale_x, 2) + shift_y * x;
}

double Amplitude::integral2(double x) const {
  return scale_y * scale_x * scale_x * raw((x - shift_x) / scale_x, 3) + 0.5 * shift_y * x * x;
}

} // namespace gapfem
