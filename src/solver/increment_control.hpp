#pragma once
/// @file increment_control.hpp
/// Automatic incrementation of a step (Abaqus/Standard defaults): start with the initial increment,
/// cut back by 0.25 after a failed attempt, grow by 1.5 after two consecutive increments that
/// converged in at most 4 equilibrium iterations, shrink by 0.75 after one that needed more than
/// 10, never exceed the maximum, stop below the minimum or after 5 attempts of one increment.
/// DIRECT: fixed increments, no cut-backs. Transient heat transfer: DELTMX limits the increment
/// (accept()'s suggested ratio, retry_smaller(); the rule is in thermal_step.hpp).
#include "common/archive.hpp"
#include "model/step.hpp"

#include <string>

namespace gapfem {

struct IncrementRules {
  double cutback = 0.25;        ///< D_f
  double growth = 1.5;          ///< D_A
  double shrink = 0.75;         ///< D_B
  int easy_iterations = 4;      ///< I_G
  int hard_iterations = 10;     ///< I_L
  int max_attempts = 5;         ///< I_A
  double deltmx_cutback = 0.85; ///< D_A (transient heat transfer, thermal_step.hpp)
  /// > 0: growth never takes the increment above this size (a dynamic step without HAFTOL grows
  /// back after a cut-back only up to its initial increment)
  double ceiling = 0.0;
};
/// The rules of a step's *CONTROLS, PARAMETERS=TIME INCREMENTATION.
IncrementRules increment_rules(const SolutionControls& c);

class IncrementController {
 public:
  IncrementController(const Incrementation& inc, int max_increments, IncrementRules rules = {});

  double step_time() const { return _t; }
  double period() const { return _period; }
  bool finished() const { return _t >= _period * (1.0 - 1e-12); }
  int increment() const { return _increment; } ///< completed increments
  int attempt() const { return _attempt; }     ///< attempts of the current increment so far
  double minimum() const { return _min; }
  /// Size of the next attempt (trimmed to end exactly at the period).
  double next() const;
  /// The attempt converged: advance time, choose the next size.
  void accept(int equilibrium_iterations, double suggested_ratio = 0.0);
  /// The attempt failed: returns false (and sets failure()) when no further cut-back is allowed.
  /// `ratio` in (0, 1): the next attempt is that fraction of this one (an element's request)
  /// instead of the cut-back factor.
  bool reject(double ratio = 0.0);
  /// The attempt converged but violated a time-integration accuracy limit (DELTMX): try it again
  /// with `factor` (< 1) times the attempted size. Returns false, changing nothing, when that is
  /// not possible (DIRECT, already at the minimum, or the attempts of the increment are used up);
  /// the caller then accepts the attempt as it is.
  bool retry_smaller(double factor);
  const std::string& failure() const { return _failure; }
  /// Restart: the state after a converged increment.
  void save(ArchiveWriter& a) const;
  void restore(ArchiveReader& a);

 private:
  double _period, _dt, _min, _max;
  bool _direct;
  int _max_increments;
  IncrementRules _rules;
  double _t = 0.0;
  int _increment = 0, _attempt = 0, _easy_streak = 0;
  std::string _failure;
};

} // namespace gapfem
