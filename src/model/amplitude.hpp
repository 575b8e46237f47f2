#pragma once
/// @file amplitude.hpp
/// *AMPLITUDE curves a(t) at step time or total time: TABULAR and EQUALLY SPACED (linear between
/// points), SMOOTH STEP (Abaqus's fifth-order step between points), PERIODIC (Fourier series),
/// MODULATED and DECAY, with SCALEX/SCALEY/SHIFTX/SHIFTY. Besides the value: its slope and two
/// antiderivatives in closed form (exact), from which prescribed velocities and accelerations
/// are integrated (docs/theory/dynamics.md, "Base motion"). No member allocates after finish().
#include "common/error.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace gapfem {

struct Amplitude {
  enum class TimeBase { Step, Total };
  /// DEFINITION= (EQUALLY SPACED is stored as Tabular with its points)
  enum class Kind : std::uint8_t { Tabular, SmoothStep, Periodic, Modulated, Decay };
  std::string name;
  SourceLocation loc;
  TimeBase time = TimeBase::Step;
  Kind kind = Kind::Tabular;
  bool absolute = false;    ///< VALUE=ABSOLUTE (magnitudes are the amplitude values themselves)
  std::vector<double> t, a; ///< Tabular, SmoothStep: (time, value) points, time ascending
  /// Periodic: a0 + sum over n of coef[2n-2] cos(n omega tau) + coef[2n-1] sin(n omega tau),
  /// tau = t - t0 >= 0, a0 before t0. Modulated: a0 + amp sin(omega tau) sin(omega2 tau) for
  /// tau > 0. Decay: a0 + amp exp(-tau / td) for tau >= 0. All: a0 before t0.
  double a0 = 0.0, amp = 0.0, t0 = 0.0, omega = 0.0, omega2 = 0.0, td = 1.0;
  std::vector<double> coef;
  /// SCALEX, SCALEY, SHIFTX, SHIFTY: a(x) = scale_y r((x - shift_x) / scale_x) + shift_y with r
  /// the curve as defined by the data (scale_x > 0)
  double scale_x = 1.0, scale_y = 1.0, shift_x = 0.0, shift_y = 0.0;
  /// Tabular, SmoothStep: an antiderivative and its antiderivative at the points (finish())
  std::vector<double> c1, c2;

  /// Prepares the integrals (call once after the data are set).
  void finish();
  /// The amplitude's own time at step time `step_time` of a step that started at total time
  /// `step_start`.
  double time_of(double step_time, double step_start) const {
    return time == TimeBase::Step ? step_time : step_start + step_time;
  }
  /// Value at step time `step_time` of a step that started at total time `step_start`.
  double value(double step_time, double step_start) const {
    return at(time_of(step_time, step_start));
  }
  /// a(x) at amplitude time x (an empty table reads as 1).
  double at(double x) const;
  /// da/dx (the right-hand slope where a tabular curve has a kink).
  double slope(double x) const;
  /// F1 with F1' = a, and F2 with F2' = F1 (fixed but arbitrary constants: use differences).
  double integral(double x) const;
  double integral2(double x) const;
  /// The integral of a over [x0, x1] and the double integral of a from x0 to x1
  /// (int_{x0}^{x1} int_{x0}^{s} a): what a prescribed rate adds over an increment.
  double integral(double x0, double x1) const { return integral(x1) - integral(x0); }
  double integral2(double x0, double x1) const {
    return integral2(x1) - integral2(x0) - integral(x0) * (x1 - x0);
  }

 private:
  /// The curve as defined by the data, at its own time r: value, slope, F1, F2 (which = 0..3).
  double raw(double r, int which) const;
  double raw_table(double r, int which) const;
};

} // namespace gapfem
