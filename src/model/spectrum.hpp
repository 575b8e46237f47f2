#pragma once
/// @file spectrum.hpp
/// *SPECTRUM (model data): a response spectrum, magnitudes at increasing frequencies for one or
/// more damping fractions, read by *RESPONSE SPECTRUM steps (docs/theory/frequency.md §6).
#include "common/error.hpp"

#include <string>
#include <vector>

namespace gapfem {

struct Spectrum {
  enum class Type { Acceleration, Velocity, Displacement, G };
  std::string name;
  Type type = Type::Acceleration;
  double g = 1.0; ///< TYPE=G: the acceleration of one g
  /// One curve per damping fraction, ascending in damping; frequencies ascending (cycles/time)
  struct Curve {
    double damping = 0.0;
    std::vector<double> frequency, value;
  };
  std::vector<Curve> curves;
  SourceLocation loc;

  /// The spectrum at frequency f (cycles/time) and damping fraction zeta: log-log in frequency
  /// along each curve, linear in damping between the two curves around zeta; the end values
  /// outside the table (`clamped` set when f or zeta lies outside it).
  double value(double f, double zeta, bool* clamped = nullptr) const;
  /// The displacement spectrum S_d at f (S_v / omega, S_a / omega^2 for small damping, Abaqus);
  /// 0 at f = 0.
  double displacement(double f, double zeta, bool* clamped = nullptr) const;
};

} // namespace gapfem
