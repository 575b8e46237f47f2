#include "solver/increment_control.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace gapfem {

IncrementRules increment_rules(const SolutionControls& c) {
  IncrementRules r;
  r.cutback = c.cutback;
  r.growth = c.growth;
  r.shrink = c.shrink;
  r.easy_iterations = c.easy_iterations;
  r.hard_iterations = c.hard_iterations;
  r.max_attempts = c.max_attempts;
  r.deltmx_cutback = c.deltmx_cutback;
  return r;
}

IncrementController::IncrementController(const Incrementation& inc, int max_increments,
                                         IncrementRules rules)
    : _period(inc.period > 0 ? inc.period : 1.0), _direct(inc.direct),
      _max_increments(max_increments > 0 ? max_increments : 100), _rules(rules) {
  _dt = inc.initial > 0 ? std::min(inc.initial, _period) : _period;
  _max = inc.maximum > 0 ? inc.maximum : _period;
  _min = inc.minimum > 0 ? inc.minimum : std::min(_dt, 1e-5 * _period);
  _dt = std::min(_dt, _max);
}

void IncrementController::save(ArchiveWriter& a) const {
  a.pod(_t);
  a.pod(_dt);
  a.pod(_increment);
  a.pod(_attempt);
  a.pod(_easy_streak);
}

void IncrementController::restore(ArchiveReader& a) {
  a.pod(_t);
  a.pod(_dt);
  a.pod(_increment);
  a.pod(_attempt);
  a.pod(_easy_streak);
}

double IncrementController::next() const {
  const double remaining = _period - _t;
  double dt = std::min(_dt, remaining);
  // Avoid leaving a sliver far below the current size for the last increment.
  if (!_direct && remaining - dt > 0 && remaining - dt < 1e-6 * _period) dt = remaining;
  return dt;
}

void IncrementController::accept(int iterations, double suggested_ratio) {
  const double dt = next();
  _t += dt;
  if (_period - _t < 1e-12 * _period) _t = _period;
  ++_increment;
  _attempt = 0;
  if (_direct) return;
  _easy_streak = iterations <= _rules.easy_iterations ? _easy_streak + 1 : 0;
  const double base = _dt; // the nominal size (a last increment may have been trimmed)
  if (iterations > _rules.hard_iterations)
    _dt = base * _rules.shrink;
  else if (_easy_streak >= 2)
    _dt = base * _rules.growth;
  else
    _dt = base;
  if (suggested_ratio > 0) _dt = std::min(_dt, base * suggested_ratio);
  if (_rules.ceiling > 0.0 && _dt > base) _dt = std::min(_dt, std::max(base, _rules.ceiling));
  _dt = std::clamp(_dt, _min, _max);
}

bool IncrementController::retry_smaller(double factor) {
  const double tried = next();
  const double smaller = std::max(tried * factor, _min);
  if (_direct || !(smaller < tried * (1.0 - 1e-12)) || _attempt + 1 >= _rules.max_attempts)
    return false;
  ++_attempt;
  _easy_streak = 0;
  _dt = smaller;
  return true;
}

bool IncrementController::reject(double ratio) {
  ++_attempt;
  _easy_streak = 0;
  if (_direct) {
    _failure = "the increment did not converge and DIRECT incrementation allows no cut-back; "
               "use a smaller fixed increment or automatic incrementation";
    return false;
  }
  if (_attempt >= _rules.max_attempts) {
    _failure = fmt::format("{} attempts of increment {} failed (last size {:.4g}); the increment "
                           "cannot be cut back further",
                           _attempt, _increment + 1, _dt);
    return false;
  }
  const double smaller = ratio > 0.0 && ratio < 1.0 ? next() * ratio : _dt * _rules.cutback;
  if (smaller < _min * (1.0 - 1e-12)) {
    _failure =
        fmt::format("the time increment required ({:.4g}) is less than the minimum ({:.4g}); "
                    "lower the minimum increment on the procedure's data line, or change the "
                    "loading",
                    smaller, _min);
    return false;
  }
  _dt = smaller;
  return true;
}

} // namespace gapfem
