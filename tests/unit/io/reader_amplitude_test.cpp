// *AMPLITUDE definitions (EQUALLY SPACED, SMOOTH STEP, PERIODIC, MODULATED, DECAY, SCALEX/SCALEY/
// SHIFTX/SHIFTY, INPUT=) and *BOUNDARY, TYPE=: what the reader builds and one clear message per
// malformed line or parameter.
#include "unit/io/reader_test_util.hpp"

#include <cmath>

namespace gapfem {
namespace {

using test::error_text;
using test::read;

TEST(ReaderAmplitude, EquallySpacedPeriodicModulatedDecaySmoothStep) {
  const Model m =
      read(R"(*AMPLITUDE, NAME=EQ, DEFINITION=EQUALLY SPACED, FIXED INTERVAL=0.5, BEGIN=1.
0., 1., 4.
2.
*AMPLITUDE, NAME=PER, DEFINITION=PERIODIC
2, 6.283, 0.1, 0.5
1., 0., 0., -2.
*AMPLITUDE, NAME=MOD, DEFINITION=MODULATED
0.1, 2., 0.3, 10., 1.
*AMPLITUDE, NAME=DEC, DEFINITION=DECAY, TIME=TOTAL TIME
0., 1., 0., 0.2
*AMPLITUDE, NAME=SM, DEFINITION=SMOOTH STEP, SCALEX=2., SCALEY=3., SHIFTX=1., SHIFTY=-1.
0., 0., 1., 1.
)");
  ASSERT_EQ(m.amplitudes.size(), 5u);
  const Amplitude& eq = m.amplitudes[0];
  EXPECT_EQ(eq.kind, Amplitude::Kind::Tabular);
  EXPECT_EQ(eq.t, (std::vector<double>{1.0, 1.5, 2.0, 2.5}));
  EXPECT_EQ(eq.a, (std::vector<double>{0.0, 1.0, 4.0, 2.0}));
  EXPECT_DOUBLE_EQ(eq.at(1.75), 2.5);
  const Amplitude& per = m.amplitudes[1];
  EXPECT_EQ(per.kind, Amplitude::Kind::Periodic);
  EXPECT_EQ(per.omega, 6.283);
  EXPECT_EQ(per.t0, 0.1);
  EXPECT_EQ(per.a0, 0.5);
  EXPECT_EQ(per.coef, (std::vector<double>{1.0, 0.0, 0.0, -2.0}));
  EXPECT_DOUBLE_EQ(per.at(0.1), 1.5);
  const Amplitude& mod = m.amplitudes[2];
  EXPECT_EQ(mod.kind, Amplitude::Kind::Modulated);
  EXPECT_EQ(mod.omega2, 1.0);
  EXPECT_DOUBLE_EQ(mod.at(0.3), 0.1);
  const Amplitude& dec = m.amplitudes[3];
  EXPECT_EQ(dec.time, Amplitude::TimeBase::Total);
  EXPECT_DOUBLE_EQ(dec.at(0.0), 1.0);
  EXPECT_EQ(dec.td, 0.2);
  const Amplitude& sm = m.amplitudes[4];
  EXPECT_EQ(sm.kind, Amplitude::Kind::SmoothStep);
  EXPECT_DOUBLE_EQ(sm.at(2.0), 3.0 * 0.5 - 1.0); // halfway up the step, scaled and shifted
}

TEST(ReaderAmplitude, PeriodicFromAnInputFile) {
  const auto dir = test::fresh_dir();
  test::write_file(dir / "data" / "per.txt", "1, 2., 0., 0.\n0., 1.\n");
  test::write_file(dir / "main.inp",
                   "*AMPLITUDE, NAME=P, DEFINITION=PERIODIC, INPUT=data/per.txt\n");
  const Model m = read_deck(dir / "main.inp");
  EXPECT_DOUBLE_EQ(m.amplitudes.at(0).at(0.25), std::sin(0.5));
  test::write_file(dir / "missing.inp", "*AMPLITUDE, NAME=P, INPUT=nowhere.txt\n");
  try {
    read_deck(dir / "missing.inp");
    ADD_FAILURE() << "a missing INPUT file was accepted";
  } catch (const InputError& e) {
    EXPECT_CONTAINS(std::string(e.what()), "INPUT=nowhere.txt");
  }
}

TEST(ReaderAmplitude, MalformedDefinitionsGiveOneClearMessage) {
  EXPECT_CONTAINS(error_text("*AMPLITUDE, NAME=A, DEFINITION=SMOOTH STEP\n0., 0., 1.\n"),
                  "deck.inp:2: *AMPLITUDE: give time, amplitude pairs: this line has an odd "
                  "number of values");
  EXPECT_CONTAINS(error_text("*AMPLITUDE, NAME=A, DEFINITION=EQUALLY SPACED, FIXED INTERVAL=0.\n"
                             "1., 2.\n"),
                  "deck.inp:1: *AMPLITUDE: FIXED INTERVAL=0.: the fixed interval must be a "
                  "positive time");
  EXPECT_CONTAINS(error_text("*AMPLITUDE, NAME=A, DEFINITION=EQUALLY SPACED\n1., 2.\n"),
                  "FIXED INTERVAL= is required");
  EXPECT_CONTAINS(error_text("*AMPLITUDE, NAME=A, DEFINITION=SINE\n1., 2.\n"),
                  "DEFINITION=SINE: this is not an amplitude definition");
  EXPECT_CONTAINS(error_text("*AMPLITUDE, NAME=A, DEFINITION=USER\n"),
                  "DEFINITION=USER: this Abaqus amplitude definition is not supported");
  EXPECT_CONTAINS(error_text("*AMPLITUDE, NAME=A, DEFINITION=PERIODIC\n2, 1., 0., 0.\n1., 0.\n"),
                  "N = 2 terms are announced but 1 pairs A_n, B_n are given");
  EXPECT_CONTAINS(error_text("*AMPLITUDE, NAME=A, DEFINITION=PERIODIC\n1, 1., 0., 0.\n1.\n"),
                  "deck.inp:3: *AMPLITUDE: give A_n, B_n pairs");
  EXPECT_CONTAINS(error_text("*AMPLITUDE, NAME=A, DEFINITION=DECAY\n0., 1., 0., 0.\n"),
                  "the decay time td must be positive");
  EXPECT_CONTAINS(error_text("*AMPLITUDE, NAME=A, DEFINITION=MODULATED\n0., 1., 0., 1.\n"),
                  "deck.inp:2: *AMPLITUDE");
  EXPECT_CONTAINS(error_text("*AMPLITUDE, NAME=A, FIXED INTERVAL=1.\n0., 1.\n"),
                  "FIXED INTERVAL belongs to DEFINITION=EQUALLY SPACED");
  EXPECT_CONTAINS(error_text("*AMPLITUDE, NAME=A, SCALEX=-1.\n0., 1.\n"),
                  "SCALEX=-1.: the time scale must be positive");
  EXPECT_CONTAINS(error_text("*AMPLITUDE, NAME=A, SMOOTH=0.25\n0., 1.\n"), "does not smooth them");
}

constexpr std::string_view kStep = R"(*STEP
*DYNAMIC, DIRECT
0.1, 1.
)";

TEST(ReaderAmplitude, BoundaryTypes) {
  const Model m = read(std::string(test::kTrussModel) + std::string(kStep) +
                       "*BOUNDARY, TYPE=ACCELERATION\n1, 1, 1, 9.81\n"
                       "*BOUNDARY, TYPE=VELOCITY\n1, 2, 2, 0.5\n*BOUNDARY\n1, 3\n*END STEP\n");
  const auto& bcs = m.steps.at(0).boundary;
  ASSERT_EQ(bcs.size(), 3u);
  EXPECT_EQ(bcs[0].type, BoundaryType::Acceleration);
  EXPECT_EQ(bcs[0].value, 9.81);
  EXPECT_EQ(bcs[1].type, BoundaryType::Velocity);
  EXPECT_EQ(bcs[2].type, BoundaryType::Displacement);

  const std::string model(test::kTrussModel);
  EXPECT_CONTAINS(error_text(model + "*STEP\n*STATIC\n*BOUNDARY, TYPE=ACCELERATION\n1, 1, 1, 1.\n"
                                     "*END STEP\n"),
                  "deck.inp:13: *BOUNDARY: TYPE=ACCELERATION: a prescribed acceleration needs a "
                  "*DYNAMIC step; step 1 is *STATIC");
  EXPECT_CONTAINS(
      error_text(model + std::string(kStep) + "*BOUNDARY, TYPE=VELOCITY, FIXED\n1, 1\n*END STEP\n"),
      "cannot be used with TYPE=VELOCITY or ACCELERATION");
  EXPECT_CONTAINS(
      error_text(model + std::string(kStep) + "*BOUNDARY, TYPE=JERK\n1, 1\n*END STEP\n"),
      "TYPE=JERK: this value is not supported by gapfem; use one of: DISPLACEMENT, "
      "VELOCITY, ACCELERATION");
  EXPECT_CONTAINS(error_text(model + "*BOUNDARY, TYPE=VELOCITY\n1, 1\n"),
                  "a prescribed velocity or acceleration is history data");
}

} // namespace
} // namespace gapfem
