#pragma once
/// @file extrapolation.hpp
/// The first guess of an increment (Abaqus/Standard's *STEP, EXTRAPOLATION): the solution
/// increments of the step's last converged increments extrapolated in time. Newton then starts
/// from u_n + du_guess instead of u_n, so a monotonic history closes the gaps an increment will
/// close and carries the structure's deflection before the first solve. Theory:
/// docs/theory/extrapolation.md.
#include "common/archive.hpp"
#include "model/step.hpp"

#include <span>
#include <vector>

namespace gapfem {

class IncrementPredictor {
 public:
  /// A new step: no increment of it has converged yet (the first is never extrapolated).
  void start_step();
  /// A converged increment of length dt took the solution from u_start to u (per slot).
  void record(std::span<const double> u, std::span<const double> u_start, double dt);
  /// The guessed increment over the next dt (per slot; empty when there is nothing to
  /// extrapolate: the step's first increment, or EXTRAPOLATION=NO). PARABOLIC falls back to
  /// LINEAR until two increments of the step have converged.
  std::span<const double> guess(Extrapolation how, double dt);
  /// How many converged increments of the step the predictor knows (at most 2).
  int known() const { return _known; }

  void save(ArchiveWriter& a) const;
  /// The history saved by save(); RestartDataError unless it fits a model of `slots` slots.
  void restore(ArchiveReader& in, std::size_t slots);

 private:
  std::vector<double> _du1, _du2; ///< the last and the one-before-last converged increments
  double _dt1 = 0.0, _dt2 = 0.0;  ///< their lengths
  int _known = 0;
  std::vector<double> _guess;
};

} // namespace gapfem
