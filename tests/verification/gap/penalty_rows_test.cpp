// Penalty gaps as compliant constraint rows (issue 16): a force law's slope carried by a row of
// compliance 1/F' instead of the tangent. Eliminating the row's multiplier gives back the tangent
// term, so the Newton iterates are the force law's: every deck must give the same converged answer
// with the rows (default) and without them (GAPFEM_PENALTY_ROWS=0): displacements to 1e-8 of their
// scale, forces to 1e-8 of theirs plus what a displacement difference of 1e-10 of the
// displacement scale makes in the stiffest gap (a gap force is k times a penetration that is a
// small difference of large displacements: with k = 1e7 on springs of 1e2 its last digits are
// round-off in either path). The increments (iterations per attempt) must be the same but for a
// convergence test that lands on its threshold. Randomised PENALTY networks, friction and
// GAPCYL/GAPSPHER units (the generators of the random contact test with every gap made a penalty
// gap), the softened laws with friction on rotating gaps, a thermal GAPUNIT and the C3D8 block with
// CalculiX's penalty (NLGEOM).
#include "random/random_generators.hpp"
#include "same_answer.hpp"
#include "test_util.hpp"

#include <cstdio>
#include <cstdlib>
#include <gtest/gtest.h>

using namespace gapfem;
using namespace gapfem::test;
using namespace gapfem::test::random_contact;

namespace {

JobResult run_with_rows(const std::string& deck, bool rows) {
  if (rows)
    unsetenv("GAPFEM_PENALTY_ROWS");
  else
    setenv("GAPFEM_PENALTY_ROWS", "0", 1);
  // a fresh factor in every iteration: the rows give the force law's Newton iterates exactly,
  // while a reused (stale) factor's modified-Newton path would depend on the measured timings
  JobResult r = run_deck_exact(deck);
  unsetenv("GAPFEM_PENALTY_ROWS");
  return r;
}

double max_penalty(const ModelDef& m) {
  double k = 0.0;
  for (const GapDef& g : m.gaps) k = std::max(k, g.penalty);
  return k;
}

/// Every gap a penalty gap, and tight convergence controls (R_n = 1e-8, C_n = 1e-6): the
/// converged state is then determined far below the 1e-8 compared, whichever path the round-off
/// of a build (optimised or sanitized) takes to it.
void all_penalty(ModelDef& m, std::uint64_t seed) {
  m.tight_controls = true;
  m.residual_tolerance = 1e-8;
  Rng r(seed * 7919 + 1);
  for (GapDef& g : m.gaps) {
    g.normal = NormalMethod::Penalty;
    g.penalty = r.log_uniform(1e2, 1e7);
  }
}

} // namespace

TEST(PenaltyRows, RandomPenaltyNetworksGiveTheForceLawsAnswer) {
  if (std::getenv("GAPFEM_PENALTY_ROWS")) GTEST_SKIP() << "GAPFEM_PENALTY_ROWS is set";
  int compared = 0, same_history = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    ModelDef m = network_model(seed, NormalMethod::Direct);
    all_penalty(m, seed);
    const std::string deck = write_deck(m);
    const JobResult a = run_with_rows(deck, true), b = run_with_rows(deck, false);
    same_history += expect_same(a, b, 1e-8, max_penalty(m), m.tag);
    compared += a.exit_code == 0;
  }
  EXPECT_GE(compared, 30);
  EXPECT_GE(same_history, 30) << "iteration histories differ beyond threshold cases";
}

TEST(PenaltyRows, RandomPenaltyFrictionAndRadialUnitsGiveTheForceLawsAnswer) {
  if (std::getenv("GAPFEM_PENALTY_ROWS")) GTEST_SKIP() << "GAPFEM_PENALTY_ROWS is set";
  int same_history = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    ModelDef m = friction_model(seed);
    all_penalty(m, seed);
    const std::string deck = write_deck(m);
    same_history += expect_same(run_with_rows(deck, true), run_with_rows(deck, false), 1e-8,
                                max_penalty(m), m.tag);
  }
  // GAPCYL/GAPSPHER units under NLGEOM: the displacements to 1e-7 (springs down to 1e2 against
  // penalties up to 1e7 and a rotating normal: the residual tolerance itself, 1e-8 of the flux,
  // leaves the displacements free by ~1e-8 of the load over the softest spring; a sanitized build
  // lands 7e-8 away). With friction their
  // answer depends on the path (the random contact test checks only convergence and the Coulomb
  // bound for them), so round-off may lead the two runs to different admissible states: both
  // must converge.
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const bool friction = seed % 2 == 0;
    ModelDef m = radial_model(seed, friction);
    all_penalty(m, seed);
    const std::string deck = write_deck(m);
    const JobResult a = run_with_rows(deck, true), b = run_with_rows(deck, false);
    if (friction) {
      EXPECT_EQ(a.exit_code, b.exit_code) << m.tag << ": " << a.error << " | " << b.error;
      continue;
    }
    same_history += expect_same(a, b, 1e-7, max_penalty(m), m.tag);
  }
  // (elastic slips down to 1e-9 make stick/slip decisions that round-off can move by an
  // iteration; the answers above are compared regardless)
  std::printf("[ penalty rows ] %d of 30 models with identical iteration histories\n",
              same_history);
  EXPECT_GE(same_history, 15) << "iteration histories differ beyond threshold cases";
}

TEST(PenaltyRows, SoftenedLawsWithFrictionOnRotatingGaps) {
  if (std::getenv("GAPFEM_PENALTY_ROWS")) GTEST_SKIP() << "GAPFEM_PENALTY_ROWS is set";
  // a shaft node inside a GAPCYL bearing and a ball inside a GAPSPHER socket, pushed sideways and
  // dragged along/around with friction; each softened law in turn
  const std::vector<std::string> laws = {
      "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1.E4",
      "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL\n0.01, 20.",
      "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TABULAR\n0., 0.\n5., 0.001\n25., 0.002",
      "*SURFACE BEHAVIOR, PENALTY\n1.E6"};
  for (const auto& law : laws)
    for (const char* gap : {"GAPCYL", "GAPSPHER"}) {
      const std::string deck = fmt::format(R"(*NODE
1, 0., 0., 0.
2, 0., 0., 0.
3, 0., 0., 0.
*ELEMENT, TYPE={0}, ELSET=G
10, 1, 2
*GAP, ELSET=G
0.05, 0., 0., 1.
{1}
*FRICTION, ELASTIC SLIP=1.E-5
0.3
*ELEMENT, TYPE=SPRING2, ELSET=S1
20, 1, 3
*SPRING, ELSET=S1
1, 1
1.E3
*ELEMENT, TYPE=SPRING2, ELSET=S2
21, 1, 3
*SPRING, ELSET=S2
2, 2
1.E3
*ELEMENT, TYPE=SPRING2, ELSET=S3
22, 1, 3
*SPRING, ELSET=S3
3, 3
1.E3
*BOUNDARY
2, 1, 3
3, 1, 3
*STEP, NLGEOM
*STATIC
0.25, 1.
*CLOAD
1, 1, 80.
1, 2, 20.
1, 3, 15.
*END STEP
*STEP, NLGEOM
*STATIC
0.25, 1.
*CLOAD
1, 1, 20.
1, 2, -30.
1, 3, -15.
*END STEP
)",
                                           gap, law);
      // (the stiffest slope of these laws: the penalty 1e6)
      EXPECT_TRUE(expect_same(run_with_rows(deck, true), run_with_rows(deck, false), 1e-8, 1e6,
                              std::string(gap) + " " + law));
    }
}

TEST(PenaltyRows, ThermalGapunitWithASoftenedLaw) {
  if (std::getenv("GAPFEM_PENALTY_ROWS")) GTEST_SKIP() << "GAPFEM_PENALTY_ROWS is set";
  // pressure-dependent conductance through a softened gap pressed by a load, coupled step
  const std::string deck = R"(*NODE
1, 0., 0., 0.
2, 0., -1., 0.
3, 0., 1., 0.
*ELEMENT, TYPE=GAPUNIT, ELSET=G
10, 1, 2
*GAP, ELSET=G
0.001, 0., -1., 0., 1.
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL
0.002, 50.
*GAP CONDUCTANCE, PRESSURE
10., 0.
30., 100.
*ELEMENT, TYPE=SPRING2, ELSET=S
20, 1, 3
*SPRING, ELSET=S
2, 2
1.E3
*BOUNDARY
1, 1, 1
1, 3, 3
2, 1, 3
3, 1, 3
2, 11, 11, 100.
*INITIAL CONDITIONS, TYPE=TEMPERATURE
1, 0.
2, 100.
3, 0.
*PHYSICAL CONSTANTS, ABSOLUTE ZERO=-273.15
*STEP
*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE
0.2, 1.
*CLOAD
1, 2, -40.
*END STEP
)";
  EXPECT_TRUE(
      expect_same(run_with_rows(deck, true), run_with_rows(deck, false), 1e-8, 1e5, "GAPUNIT"));
}

TEST(PenaltyRows, CalculixPenaltyBlockUnderNlgeom) {
  if (std::getenv("GAPFEM_PENALTY_ROWS")) GTEST_SKIP() << "GAPFEM_PENALTY_ROWS is set";
  const auto path = test_dir() / "penalty_rows_block.inp";
  const std::string cmd = "python3 '" + std::string(GAPFEM_SOURCE_DIR) +
                          "/bench/gen_block.py' --nx 8 --nz 6 --dmax 2e-4 --pressure 10 "
                          "--penalty 1e7 --max-inc 0.1 -o '" +
                          path.string() + "' 2>/dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const std::string deck = slurp(path);
  EXPECT_TRUE(
      expect_same(run_with_rows(deck, true), run_with_rows(deck, false), 1e-8, 1e7, "block"));
}
