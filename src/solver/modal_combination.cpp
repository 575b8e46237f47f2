#include "solver/modal_combination.hpp"

#include <algorithm>
#include <cmath>

namespace gapfem {
namespace {

/// Two modes are close (TENP, GRP) when their frequencies differ by at most 10 % of the lower.
bool close(double lo, double hi) {
  return std::abs(hi - lo) <= 0.1 * std::min(std::abs(lo), std::abs(hi));
}

double srss(std::span<const double> r) {
  double s = 0.0;
  for (double x : r) s += x * x;
  return std::sqrt(s);
}

/// sqrt(sum_ij r_i rho_ij r_j) for a correlation rho (`absolute`: |r_i r_j|, DSC's form).
template <typename Rho>
double double_sum(const ModalPeaks& p, Rho rho, bool absolute = false) {
  double s = 0.0;
  const std::size_t n = p.r.size();
  for (std::size_t i = 0; i < n; ++i) {
    s += p.r[i] * p.r[i];
    for (std::size_t j = i + 1; j < n; ++j) {
      const double rr = absolute ? std::abs(p.r[i] * p.r[j]) : p.r[i] * p.r[j];
      s += 2.0 * rr * rho(i, j);
    }
  }
  return std::sqrt(std::max(s, 0.0));
}

/// Sum of squares plus the products of the modes' absolute peaks within each group of close modes
/// (groups start at the lowest mode not yet grouped: NRC Regulatory Guide 1.92's grouping).
double grouped(const ModalPeaks& p) {
  double s = 0.0;
  const std::size_t n = p.r.size();
  for (std::size_t i = 0; i < n; ++i) s += p.r[i] * p.r[i];
  for (std::size_t start = 0; start < n;) {
    std::size_t end = start + 1;
    while (end < n && close(p.omega[start], p.omega[end])) ++end;
    for (std::size_t i = start; i < end; ++i)
      for (std::size_t j = start; j < end; ++j)
        if (i != j) s += std::abs(p.r[i] * p.r[j]);
    start = end;
  }
  return std::sqrt(s);
}

/// Ten percent method: sum of squares plus twice the absolute products of close pairs.
double ten_percent(const ModalPeaks& p) {
  double s = 0.0;
  const std::size_t n = p.r.size();
  for (std::size_t i = 0; i < n; ++i) {
    s += p.r[i] * p.r[i];
    for (std::size_t j = i + 1; j < n; ++j)
      if (close(p.omega[i], p.omega[j])) s += 2.0 * std::abs(p.r[i] * p.r[j]);
  }
  return std::sqrt(s);
}

} // namespace

double cqc_correlation(double wi, double wj, double zi, double zj) {
  if (wi <= 0.0 || wj <= 0.0) return wi == wj ? 1.0 : 0.0;
  const double r = wj / wi;
  const double num = 8.0 * std::sqrt(zi * zj) * (zi + r * zj) * std::pow(r, 1.5);
  const double den = (1.0 - r * r) * (1.0 - r * r) + 4.0 * zi * zj * r * (1.0 + r * r) +
                     4.0 * (zi * zi + zj * zj) * r * r;
  return den > 0.0 ? num / den : 1.0;
}

double dsc_correlation(double wi, double wj, double zi, double zj, double duration) {
  const auto damped = [](double w, double z) { return w * std::sqrt(std::max(1.0 - z * z, 0.0)); };
  const auto eff = [&](double w, double z) {
    return duration > 0.0 && w > 0.0 ? z + 2.0 / (duration * w) : z;
  };
  const double zi2 = eff(wi, zi), zj2 = eff(wj, zj);
  const double den = zi2 * wi + zj2 * wj;
  if (den <= 0.0) return wi == wj ? 1.0 : 0.0;
  const double e = (damped(wi, zi) - damped(wj, zj)) / den;
  return 1.0 / (1.0 + e * e);
}

double combine_modes(ModalSum rule, const ModalPeaks& p) {
  switch (rule) {
  case ModalSum::Abs: {
    double s = 0.0;
    for (double x : p.r) s += std::abs(x);
    return s;
  }
  case ModalSum::Srss:
    return srss(p.r);
  case ModalSum::Cqc:
    return double_sum(p, [&](std::size_t i, std::size_t j) {
      return cqc_correlation(p.omega[i], p.omega[j], p.zeta[i], p.zeta[j]);
    });
  case ModalSum::Dsc:
    return double_sum(
        p,
        [&](std::size_t i, std::size_t j) {
          return dsc_correlation(p.omega[i], p.omega[j], p.zeta[i], p.zeta[j], p.duration);
        },
        true);
  case ModalSum::Nrl: {
    std::size_t big = 0;
    for (std::size_t k = 1; k < p.r.size(); ++k)
      if (std::abs(p.r[k]) > std::abs(p.r[big])) big = k;
    double s = 0.0;
    for (std::size_t k = 0; k < p.r.size(); ++k)
      if (k != big) s += p.r[k] * p.r[k];
    return p.r.empty() ? 0.0 : std::abs(p.r[big]) + std::sqrt(s);
  }
  case ModalSum::Tenp:
    return ten_percent(p);
  case ModalSum::Grp:
    return grouped(p);
  }
  return 0.0;
}

} // namespace gapfem
