#pragma once
/// @file timer.hpp
/// Wall-clock timers and a per-run timing table (assembly, factorisation, solve, gap work, output).
#include <array>
#include <chrono>
#include <string_view>

namespace gapfem {

enum class TimeCategory { Input = 0, Assembly, Factorization, Solve, GapWork, Output, Other };
inline constexpr int kNumTimeCategories = 7;
constexpr std::string_view time_category_name(TimeCategory c) {
  constexpr std::array<std::string_view, kNumTimeCategories> names = {
      "input", "assembly", "factorization", "solve", "gap work", "output", "other"};
  return names[static_cast<int>(c)];
}

/// Accumulated seconds per category, plus counters the summary and the benchmarks print.
struct RunStatistics {
  std::array<double, kNumTimeCategories> seconds{};
  long increments = 0;
  long attempts = 0;   ///< increment attempts including cut-back ones
  long iterations = 0; ///< Newton iterations (= linear solves of the Newton system)
  long factorizations = 0;
  long linear_solves = 0;      ///< back-substitutions with a factor
  long factor_updates = 0;     ///< constraint rows added to or removed from a factor (rank-1 each)
  long evaluations = 0;        ///< assemblies of the residual (and constraints)
  long tangent_assemblies = 0; ///< ... of which also assembled the tangent
  double& operator[](TimeCategory c) { return seconds[static_cast<int>(c)]; }
  double operator[](TimeCategory c) const { return seconds[static_cast<int>(c)]; }
};

class Stopwatch {
 public:
  Stopwatch() : _start(std::chrono::steady_clock::now()) {}
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - _start).count();
  }
  void restart() { _start = std::chrono::steady_clock::now(); }

 private:
  std::chrono::steady_clock::time_point _start;
};

/// Adds the lifetime of the scope to one category of a RunStatistics (if given).
class ScopedTimer {
 public:
  ScopedTimer(RunStatistics* stats, TimeCategory cat) : _stats(stats), _cat(cat) {}
  ~ScopedTimer() {
    if (_stats) (*_stats)[_cat] += _watch.seconds();
  }
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;

 private:
  RunStatistics* _stats;
  TimeCategory _cat;
  Stopwatch _watch;
};

} // namespace gapfem
