// The excitation frequencies of *STEADY STATE DYNAMICS (solver/modal_response.hpp): by hand.
#include "solver/modal_response.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace gapfem {
namespace {

SteadyStateSettings settings(SteadyStateSettings::Interval interval, bool logarithmic,
                             std::vector<SteadyStateSettings::Range> ranges) {
  SteadyStateSettings ss;
  ss.interval = interval;
  ss.logarithmic = logarithmic;
  ss.ranges = std::move(ranges);
  return ss;
}

void expect_points(const std::vector<double>& got, const std::vector<double>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t k = 0; k < want.size(); ++k) EXPECT_NEAR(got[k], want[k], 1e-12 * want.back());
}

TEST(SteadyStateFrequencies, LinearRangeIsEquallySpaced) {
  const auto ss = settings(SteadyStateSettings::Interval::Range, false, {{0.5, 3.0, 6, 1.0, 1.0}});
  expect_points(steady_state_frequencies(ss, {}), {0.5, 1.0, 1.5, 2.0, 2.5, 3.0});
}

TEST(SteadyStateFrequencies, LogarithmicRangeIsGeometric) {
  const auto ss = settings(SteadyStateSettings::Interval::Range, true, {{1.0, 100.0, 3, 1.0, 1.0}});
  expect_points(steady_state_frequencies(ss, {}), {1.0, 10.0, 100.0});
}

TEST(SteadyStateFrequencies, EigenfrequenciesSplitTheRangeAndArePoints) {
  // [1, 5] and [5, 10] with 3 points each (linear, no bias); 20 lies outside
  const std::vector<double> fe{5.0, 20.0};
  const auto ss =
      settings(SteadyStateSettings::Interval::Eigenfrequency, false, {{1.0, 10.0, 3, 1.0, 1.0}});
  expect_points(steady_state_frequencies(ss, fe), {1.0, 3.0, 5.0, 7.5, 10.0});
}

TEST(SteadyStateFrequencies, BiasGathersThePointsAtTheEnds) {
  // y = -1, -1/2, 0, 1/2, 1; |y|^(1/3): 0.5^(1/3) = 0.7937005
  const auto ss = settings(SteadyStateSettings::Interval::Range, false, {{0.0, 2.0, 5, 3.0, 1.0}});
  const double z = std::cbrt(0.5);
  expect_points(steady_state_frequencies(ss, {}), {0.0, 1.0 - z, 1.0, 1.0 + z, 2.0});
  // the default bias with eigenfrequency intervals is 3
  const auto dflt = settings(SteadyStateSettings::Interval::Eigenfrequency, false,
                             {{0.0, 2.0, 5, std::nullopt, 1.0}});
  expect_points(steady_state_frequencies(dflt, {}), {0.0, 1.0 - z, 1.0, 1.0 + z, 2.0});
}

TEST(SteadyStateFrequencies, AnUpperFrequencyOfZeroIsOneFrequency) {
  const auto ss = settings(SteadyStateSettings::Interval::Range, false, {{7.0, 0.0, 20, {}, 1.0}});
  expect_points(steady_state_frequencies(ss, {}), {7.0});
}

} // namespace
} // namespace gapfem
