// The first guess of an increment (*STEP, EXTRAPOLATION): exact for histories of the degree it
// assumes, with unequal increments; nothing to guess in a step's first increment or with NO; the
// history survives a restart record.
#include "solver/extrapolation.hpp"

#include <gtest/gtest.h>

using namespace gapfem;

namespace {
/// Record the increments of u(t) over the times ts (per slot: a and b of u = a f(t) + b).
void record_history(IncrementPredictor& p, const std::vector<double>& ts, double (*f)(double)) {
  for (std::size_t i = 1; i < ts.size(); ++i) {
    const std::vector<double> u0{f(ts[i - 1]), -2.0 * f(ts[i - 1]) + 1.0};
    const std::vector<double> u1{f(ts[i]), -2.0 * f(ts[i]) + 1.0};
    p.record(u1, u0, ts[i] - ts[i - 1]);
  }
}
double line(double t) {
  return 3.0 * t - 0.5;
}
double parabola(double t) {
  return 2.0 * t * t - t + 0.25;
}
} // namespace

TEST(IncrementPredictor, NothingToGuessInAStepsFirstIncrementOrWithNo) {
  IncrementPredictor p;
  EXPECT_TRUE(p.guess(Extrapolation::Linear, 0.1).empty());
  record_history(p, {0.0, 0.1}, line);
  EXPECT_FALSE(p.guess(Extrapolation::Linear, 0.1).empty());
  EXPECT_TRUE(p.guess(Extrapolation::None, 0.1).empty());
  p.start_step();
  EXPECT_TRUE(p.guess(Extrapolation::Linear, 0.1).empty());
  EXPECT_EQ(p.known(), 0);
}

TEST(IncrementPredictor, LinearIsExactForALinearHistoryWithAnyIncrements) {
  IncrementPredictor p;
  record_history(p, {0.0, 0.1, 0.25}, line);
  const double dt = 0.4; // a grown increment: the guess is scaled by dt / dt_last
  const auto g = p.guess(Extrapolation::Linear, dt);
  ASSERT_EQ(g.size(), 2u);
  EXPECT_NEAR(g[0], line(0.65) - line(0.25), 1e-14);
  EXPECT_NEAR(g[1], -2.0 * (line(0.65) - line(0.25)), 1e-14);
}

TEST(IncrementPredictor, ParabolicIsExactForAQuadraticHistoryAndLinearUntilItCanBe) {
  IncrementPredictor p;
  record_history(p, {0.0, 0.2}, parabola);
  // one increment known: PARABOLIC falls back to LINEAR
  EXPECT_NEAR(p.guess(Extrapolation::Parabolic, 0.1)[0], 0.5 * (parabola(0.2) - parabola(0.0)),
              1e-14);
  p.start_step();
  record_history(p, {0.0, 0.2, 0.3}, parabola);
  const double dt = 0.15;
  const auto g = p.guess(Extrapolation::Parabolic, dt);
  EXPECT_NEAR(g[0], parabola(0.45) - parabola(0.3), 1e-14);
  EXPECT_NEAR(g[1], -2.0 * (parabola(0.45) - parabola(0.3)), 1e-14);
  // LINEAR on the same history is not exact: the parabola's curvature is left out
  EXPECT_GT(std::abs(p.guess(Extrapolation::Linear, dt)[0] - (parabola(0.45) - parabola(0.3))),
            1e-3);
}

TEST(IncrementPredictor, TheHistoryTravelsInARestartRecord) {
  IncrementPredictor p, q;
  record_history(p, {0.0, 0.2, 0.3}, parabola);
  ArchiveWriter a;
  p.save(a);
  ArchiveReader in(a.data());
  q.restore(in, 2);
  EXPECT_EQ(q.known(), 2);
  const auto gp = p.guess(Extrapolation::Parabolic, 0.1);
  const std::vector<double> want(gp.begin(), gp.end());
  const auto gq = q.guess(Extrapolation::Parabolic, 0.1);
  EXPECT_EQ(std::vector<double>(gq.begin(), gq.end()), want);
  // a record of another model (3 slots) is refused
  ArchiveReader again(a.data());
  EXPECT_THROW(q.restore(again, 3), RestartDataError);
}
