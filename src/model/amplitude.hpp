#pragma once
/// @file amplitude.hpp
/// *AMPLITUDE curves (tabular): a(t) at step time or total time.
#include "common/error.hpp"

#include <string>
#include <vector>

namespace gapfem {

struct Amplitude {
  enum class TimeBase { Step, Total };
  std::string name;
  SourceLocation loc;
  TimeBase time = TimeBase::Step;
  bool absolute = false;    ///< VALUE=ABSOLUTE (magnitudes are the amplitude values themselves)
  std::vector<double> t, a; ///< (time, value) pairs, time ascending
  double shift_time = 0.0;  ///< reserved for TIME=... offsets; 0
  /// Value at step time `step_time` of a step that started at total time `step_start`:
  /// linear between points, constant before the first and after the last point.
  double value(double step_time, double step_start) const;
};

} // namespace gapfem
