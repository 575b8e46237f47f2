#include "model/table.hpp"

#include "common/error.hpp"

#include <algorithm>

namespace gapfem {

void PropertyTable::evaluate(double key, std::span<double> out, std::span<double> dout) const {
  const int rows = n_rows();
  FE_CHECK(rows > 0 && static_cast<int>(out.size()) >= n_values, "empty property table");
  auto row = [&](int r) { return std::span<const double>(values.data() + r * n_values, n_values); };
  if (!dout.empty()) std::fill(dout.begin(), dout.begin() + n_values, 0.0);
  if (rows == 1 || static_cast<int>(keys.size()) < rows || key <= keys.front()) {
    auto r = row(0);
    std::copy(r.begin(), r.end(), out.begin());
    return;
  }
  if (key >= keys.back()) {
    auto r = row(rows - 1);
    std::copy(r.begin(), r.end(), out.begin());
    return;
  }
  const auto it = std::upper_bound(keys.begin(), keys.end(), key);
  const int hi = static_cast<int>(it - keys.begin());
  const int lo = hi - 1;
  const double span = keys[hi] - keys[lo];
  const double w = span > 0 ? (key - keys[lo]) / span : 0.0;
  auto a = row(lo);
  auto b = row(hi);
  for (int i = 0; i < n_values; ++i) {
    out[i] = a[i] + w * (b[i] - a[i]);
    if (!dout.empty() && span > 0) dout[i] = (b[i] - a[i]) / span;
  }
}

double PropertyTable::value(double key) const {
  double v = 0;
  evaluate(key, {&v, 1});
  return v;
}

double PropertyTable::derivative(double key) const {
  double v = 0, d = 0;
  evaluate(key, {&v, 1}, {&d, 1});
  return d;
}

double Curve::value(double at) const {
  FE_CHECK(!x.empty() && x.size() == y.size(), "empty curve");
  if (x.size() == 1) return y[0];
  if (at <= x.front())
    return extrapolation == Extrapolation::Constant ? y.front() : y[0] + slope(at) * (at - x[0]);
  if (at >= x.back())
    return extrapolation == Extrapolation::Constant ? y.back()
                                                    : y.back() + slope(at) * (at - x.back());
  const auto it = std::upper_bound(x.begin(), x.end(), at);
  const auto hi = static_cast<std::size_t>(it - x.begin());
  const auto lo = hi - 1;
  const double span = x[hi] - x[lo];
  return span > 0 ? y[lo] + (at - x[lo]) / span * (y[hi] - y[lo]) : y[hi];
}

double Curve::slope(double at) const {
  if (x.size() < 2) return 0.0;
  std::size_t lo;
  if (at <= x.front()) {
    if (extrapolation == Extrapolation::Constant && at < x.front()) return 0.0;
    lo = 0;
  } else if (at >= x.back()) {
    if (extrapolation == Extrapolation::Constant && at > x.back()) return 0.0;
    lo = x.size() - 2;
  } else {
    lo = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), at) - x.begin()) - 1;
  }
  const double span = x[lo + 1] - x[lo];
  return span > 0 ? (y[lo + 1] - y[lo]) / span : 0.0;
}

} // namespace gapfem
