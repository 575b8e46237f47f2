// *STEP, EXTRAPOLATION (docs/theory/extrapolation.md): the first guess of each increment. A B21
// cantilever under a growing tip load, geometrically nonlinear, comes down on a GAPUNI stop in
// the middle of the step (10 increments of 0.1). The three choices reach the same answer (to the
// Newton tolerance); extrapolating saves iterations on this monotonic history, the parabola more
// than the line. A load that rises and falls again still converges to the same answer.
#include "test_util.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace gapfem {
namespace {

using test::last_frame;
using test::run_deck;

std::string cantilever(const char* extrapolation, bool up_and_down) {
  std::string d = "*NODE\n";
  for (int i = 1; i <= 11; ++i) d += fmt::format("{}, {}., 0.\n", i, i - 1);
  d += "100, 10., -3.\n*ELEMENT, TYPE=B21, ELSET=BEAM\n";
  for (int i = 1; i <= 10; ++i) d += fmt::format("{}, {}, {}\n", i, i, i + 1);
  d += fmt::format(R"(*MATERIAL, NAME=M
*ELASTIC
1.E7, 0.3
*BEAM SECTION, ELSET=BEAM, MATERIAL=M, SECTION=RECT
0.5, 0.5
*ELEMENT, TYPE=GAPUNI, ELSET=G
101, 11, 100
*GAP, ELSET=G
1.2, 0., -1., 0.
*BOUNDARY
1, 1, 6
100, 1, 2
*AMPLITUDE, NAME=UPDOWN
0., 0., 0.6, 1., 1., 0.4
*STEP, NLGEOM{}
*STATIC
0.1, 1., , 0.1
*CLOAD{}
11, 2, -300.
*END STEP
)",
                   extrapolation, up_and_down ? ", AMPLITUDE=UPDOWN" : "");
  return d;
}

int iterations(const JobResult& r) {
  int n = 0;
  for (const IncrementInfo& i : r.increments) n += i.converged ? i.iterations : 0;
  return n;
}

} // namespace

TEST(VerificationExtrapolation, AMonotonicHistoryNeedsFewerIterationsForTheSameAnswer) {
  const JobResult none = run_deck(cantilever(", EXTRAPOLATION=NO", false));
  const JobResult line = run_deck(cantilever("", false)); // LINEAR: Abaqus's default
  const JobResult parabola = run_deck(cantilever(", EXTRAPOLATION=PARABOLIC", false));
  for (const JobResult* r : {&none, &line, &parabola}) {
    ASSERT_EQ(r->exit_code, 0) << r->error;
    EXPECT_EQ(test::gap(*r, last_frame(*r), 101).status, ContactStatus::Closed);
  }
  // the stop holds the tip at its clearance; the root rotation follows the beam's bending, to
  // the Newton tolerance
  const Vec3& tip = test::U(none, last_frame(none), 11);
  for (const JobResult* r : {&line, &parabola}) {
    const Vec3& u = test::U(*r, last_frame(*r), 11);
    EXPECT_NEAR(u[0], tip[0], 1e-6 * std::abs(tip[1]));
    EXPECT_NEAR(u[1], tip[1], 1e-6 * std::abs(tip[1]));
  }
  EXPECT_LT(iterations(line), iterations(none));
  EXPECT_LE(iterations(parabola), iterations(line));
}

TEST(VerificationExtrapolation, ALoadThatTurnsBackStillConvergesToTheSameAnswer) {
  const JobResult none = run_deck(cantilever(", EXTRAPOLATION=NO", true));
  const JobResult line = run_deck(cantilever("", true));
  const JobResult parabola = run_deck(cantilever(", EXTRAPOLATION=PARABOLIC", true));
  ASSERT_EQ(none.exit_code, 0) << none.error;
  const Vec3& tip = test::U(none, last_frame(none), 11);
  for (const JobResult* r : {&line, &parabola}) {
    ASSERT_EQ(r->exit_code, 0) << r->error;
    const Vec3& u = test::U(*r, last_frame(*r), 11);
    EXPECT_NEAR(u[1], tip[1], 1e-6 * std::abs(tip[1]));
    EXPECT_EQ(test::gap(*r, last_frame(*r), 101).status, ContactStatus::Open);
  }
}

} // namespace gapfem
