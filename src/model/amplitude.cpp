#include "model/amplitude.hpp"

#include <algorithm>

namespace gapfem {

double Amplitude::value(double step_time, double step_start) const {
  const double x = time == TimeBase::Step ? step_time : step_start + step_time;
  if (t.empty()) return 1.0;
  if (x <= t.front()) return a.front();
  if (x >= t.back()) return a.back();
  const auto it = std::upper_bound(t.begin(), t.end(), x);
  const auto hi = static_cast<std::size_t>(it - t.begin());
  const auto lo = hi - 1;
  const double span = t[hi] - t[lo];
  return span > 0 ? a[lo] + (x - t[lo]) / span * (a[hi] - a[lo]) : a[hi];
}

} // namespace gapfem
