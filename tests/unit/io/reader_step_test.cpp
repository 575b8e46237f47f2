// History structure: *STEP … *END STEP, procedures and incrementation, model vs history data,
// *CHANGE FRICTION.
#include "unit/io/reader_test_util.hpp"

namespace gapfem {
namespace {

using test::error_text;
using test::kTrussModel;
using test::read;

std::string with(std::string_view history) {
  return std::string(kTrussModel) + std::string(history);
}

TEST(ReaderStep, StepParametersAndStatic) {
  const Model m = read(with(R"(*STEP, NAME=Load it, NLGEOM, INC=50, UNSYMM=YES, extrapolation=NO
*STATIC, DIRECT
0.1, 2., 1.E-5, 0.5
*END STEP
*STEP, NLGEOM=NO, AMPLITUDE=STEP, EXTRAPOLATION=PARABOLIC
*STATIC
*END STEP
*STEP
*STATIC
*END STEP
)"));
  ASSERT_EQ(m.steps.size(), 3u);
  const Step& s1 = m.steps[0];
  EXPECT_EQ(s1.number, 1);
  EXPECT_EQ(s1.name, "Load it");
  EXPECT_TRUE(s1.nlgeom);
  EXPECT_EQ(s1.max_increments, 50);
  EXPECT_EQ(s1.procedure, Procedure::Static);
  EXPECT_TRUE(s1.inc.direct);
  EXPECT_EQ(s1.inc.initial, 0.1);
  EXPECT_EQ(s1.inc.period, 2.0);
  EXPECT_EQ(s1.inc.minimum, 1e-5);
  EXPECT_EQ(s1.inc.maximum, 0.5);
  EXPECT_TRUE(s1.ramp_default);
  EXPECT_EQ(s1.loc.str(), "deck.inp:11 (*STEP)");
  EXPECT_EQ(s1.extrapolation, Extrapolation::None);
  EXPECT_EQ(m.steps[1].extrapolation, Extrapolation::Parabolic);
  EXPECT_EQ(m.steps[2].extrapolation, Extrapolation::Linear); // Abaqus's default, every step
  const Step& s2 = m.steps[1];
  EXPECT_EQ(s2.name, "Step-2");
  EXPECT_TRUE(s2.nlgeom); // once on, NLGEOM stays on (Abaqus): NO after YES is a warning
  EXPECT_EQ(s2.max_increments, 100);
  EXPECT_FALSE(s2.ramp_default);
  // blank data: defaults (0 = default, period 1)
  EXPECT_EQ(s2.inc.initial, 0.0);
  EXPECT_EQ(s2.inc.period, 1.0);
  EXPECT_FALSE(s2.inc.direct);
}

TEST(ReaderStep, ThermalProceduresAndDefaultAmplitude) {
  const std::string heat_mesh =
      "*NODE\n1\n2,1\n*ELEMENT, TYPE=DC1D2, ELSET=H\n1, 1, 2\n"
      "*MATERIAL, NAME=M\n*CONDUCTIVITY\n1.\n*SPECIFIC HEAT\n1.\n*DENSITY\n1.\n"
      "*SOLID SECTION, ELSET=H, MATERIAL=M\n";
  const Model m = read(heat_mesh + R"(*STEP
*HEAT TRANSFER, STEADY STATE
1., 1.
*END STEP
*STEP
*HEAT TRANSFER, DELTMX=5., END=PERIOD
0.01, 10., 1.E-4, 1.
*END STEP
*STEP, AMPLITUDE=RAMP
*COUPLED TEMPERATURE-DISPLACEMENT, CREEP=NONE
0.1, 1.
*END STEP
*STEP
*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE
*END STEP
)");
  ASSERT_EQ(m.steps.size(), 4u);
  EXPECT_EQ(m.steps[0].procedure, Procedure::HeatTransfer);
  EXPECT_TRUE(m.steps[0].inc.steady_state);
  EXPECT_TRUE(m.steps[0].ramp_default); // steady state: RAMP
  EXPECT_FALSE(m.steps[1].inc.steady_state);
  EXPECT_EQ(m.steps[1].inc.deltmx, 5.0);
  EXPECT_EQ(m.steps[1].inc.period, 10.0);
  EXPECT_FALSE(m.steps[1].ramp_default); // transient: STEP
  EXPECT_EQ(m.steps[2].procedure, Procedure::CoupledTempDisp);
  EXPECT_FALSE(m.steps[2].inc.steady_state);
  EXPECT_TRUE(m.steps[2].ramp_default); // AMPLITUDE=RAMP given
  EXPECT_TRUE(m.steps[3].inc.steady_state);
  EXPECT_TRUE(m.steps[3].ramp_default);
}

TEST(ReaderStep, IncrementationErrors) {
  auto step = [](std::string data) { return with("*STEP\n*STATIC\n" + data + "\n*END STEP\n"); };
  // the data line is line 13
  EXPECT_CONTAINS(error_text(step("0.1, -1.")),
                  "deck.inp:13: *STATIC: field 2 (time period): the time period must be positive");
  EXPECT_CONTAINS(error_text(step("0.1, 0.")), "the time period must be positive");
  EXPECT_CONTAINS(
      error_text(step("0.1, 1., 0.5, 0.2")),
      "field 3 (minimum increment): the minimum increment 0.5 is larger than the maximum "
      "increment 0.2");
  EXPECT_CONTAINS(
      error_text(step("2., 1.")),
      "field 1 (initial increment): the initial increment 2 is larger than the time period 1");
  EXPECT_CONTAINS(error_text(step("-0.1, 1.")), "must not be negative");
  EXPECT_CONTAINS(error_text(step("0.1, 1., 0., 1., 5.")), "at most 4 fields");
}

TEST(ReaderStep, StructureErrors) {
  EXPECT_CONTAINS(error_text(with("*STEP\n*STATIC\n")),
                  "deck.inp:11: *STEP: step 1: the step has no *END STEP");
  EXPECT_CONTAINS(
      error_text(with("*STEP\n*STATIC\n*STEP\n*STATIC\n*END STEP\n")),
      "deck.inp:13: *STEP: step 1: the step that starts at deck.inp:11 (*STEP) has no *END STEP");
  EXPECT_CONTAINS(error_text(with("*END STEP\n")),
                  "deck.inp:11: *END STEP: *END STEP without a matching *STEP");
  EXPECT_CONTAINS(
      error_text(with("*STEP\n*END STEP\n")),
      "deck.inp:11: *STEP: step 1: the step has no procedure; add one after *STEP: *STATIC");
  EXPECT_CONTAINS(
      error_text(with("*STEP\n*STATIC\n*HEAT TRANSFER\n*END STEP\n")),
      "deck.inp:13: *HEAT TRANSFER: step 1: a step has exactly one procedure and this step "
      "already has *STATIC");
  EXPECT_CONTAINS(error_text(with("*STEP, PERTURBATION\n*DYNAMIC\n0.1, 1.\n*END STEP\n")),
                  "deck.inp:11: *STEP: PERTURBATION");
  EXPECT_CONTAINS(error_text(with("*STEP\n*STATIC, RIKS\n*END STEP\n")),
                  "deck.inp:12: *STATIC: RIKS");
  EXPECT_CONTAINS(error_text(with("*STEP\n*HEAT TRANSFER, END=SS\n*END STEP\n")), "END=SS");
  EXPECT_CONTAINS(
      error_text(with("*STEP, INC=0\n*STATIC\n*END STEP\n")),
      "INC=0: the maximum number of increments must be a whole number from 1 to 2147483647");
  EXPECT_CONTAINS(error_text(with("*STEP, NLGEOM=MAYBE\n*STATIC\n*END STEP\n")),
                  "NLGEOM=MAYBE: write YES or NO");
  EXPECT_CONTAINS(error_text(with("*STEP, EXTRAPOLATION=CUBIC\n*STATIC\n*END STEP\n")),
                  "EXTRAPOLATION=CUBIC: this value is not supported by gapfem; use one of: LINEAR, "
                  "PARABOLIC, NO");
}

TEST(ReaderStep, ModelAndHistoryDataMustNotMix) {
  EXPECT_CONTAINS(error_text(with("*STATIC\n")),
                  "deck.inp:11: *STATIC: *STATIC is history data; put it inside a step");
  EXPECT_CONTAINS(error_text(with("*CLOAD\n1, 1, 1.\n")), "*CLOAD is history data");
  EXPECT_CONTAINS(error_text(with("*STEP\n*STATIC\n*NODE\n5\n*END STEP\n")),
                  "deck.inp:13: *NODE: *NODE is model data; move it before the first *STEP");
  EXPECT_CONTAINS(error_text(with("*STEP\n*STATIC\n*END STEP\n*NSET, NSET=A\n1\n")),
                  "deck.inp:14: *NSET: *NSET after *END STEP");
  EXPECT_CONTAINS(
      error_text(with("*STEP\n*STATIC\n*END STEP\n*CLOAD\n1, 1, 1.\n*STEP\n*STATIC\n*END STEP\n")),
      "deck.inp:14: *CLOAD: *CLOAD after *END STEP");
}

TEST(ReaderStep, AmplitudeInHistoryData) {
  const Model m =
      read(with("*STEP\n*STATIC\n*AMPLITUDE, NAME=A\n0., 0., 1., 1.\n*CLOAD, AMPLITUDE=a\n"
                "2, 1, 5.\n*END STEP\n"));
  EXPECT_EQ(m.steps[0].cloads.at(0).amplitude, 0);
}

constexpr std::string_view kGapModel = R"(*NODE
1
2, 0., -1.
*ELEMENT, TYPE=GAPUNI, ELSET=G
1, 1, 2
*ELEMENT, TYPE=SPRINGA, ELSET=S
2, 1, 2
*GAP, ELSET=G
0.5, 0., -1., 0., 1.
*FRICTION
0.3
*SPRING, ELSET=S

100.
)";

TEST(ReaderStep, ChangeFriction) {
  const Model m = read(std::string(kGapModel) + R"(*STEP
*STATIC
*CHANGE FRICTION, ELSET=G
*FRICTION, LAGRANGE
0.5
*END STEP
*STEP
*STATIC
*END STEP
)");
  ASSERT_EQ(m.steps.size(), 2u);
  ASSERT_EQ(m.steps[0].friction_changes.size(), 1u);
  const FrictionChange& c = m.steps[0].friction_changes[0];
  EXPECT_EQ(c.elements, (std::vector<ElemId>{0}));
  EXPECT_TRUE(c.friction.lagrange);
  EXPECT_EQ(c.friction.rows.at(0).mu, 0.5);
  EXPECT_EQ(c.loc.line, 17);
  // a change is an event of its step (the property stays changed; it is not listed again)
  EXPECT_TRUE(m.steps[1].friction_changes.empty());
  EXPECT_EQ(m.gap_sections[0].friction.rows.at(0).mu, 0.3);
}

TEST(ReaderStep, ChangeFrictionErrors) {
  const std::string g(kGapModel);
  EXPECT_CONTAINS(error_text(g + "*STEP\n*STATIC\n*CHANGE FRICTION, ELSET=G\n*END STEP\n"),
                  "deck.inp:17: *CHANGE FRICTION: *CHANGE FRICTION must be followed by *FRICTION");
  EXPECT_CONTAINS(
      error_text(g + "*STEP\n*STATIC\n*CHANGE FRICTION, ELSET=S\n*FRICTION\n0.1\n*END STEP\n"),
      "deck.inp:17: *CHANGE FRICTION: element 2 (SPRINGA): *CHANGE FRICTION applies to "
      "mechanical gap elements only");
  EXPECT_CONTAINS(
      error_text(g + "*STEP\n*STATIC\n*CHANGE FRICTION, ELSET=NONE\n*FRICTION\n0.1\n*END STEP\n"),
      "ELSET=NONE: this element set is not defined");
  EXPECT_CONTAINS(
      error_text(g + "*STEP\n*STATIC\n*FRICTION\n0.1\n*END STEP\n"),
      "deck.inp:17: *FRICTION: *FRICTION must follow *GAP (model data) or *CHANGE FRICTION");
  EXPECT_CONTAINS(
      error_text(g +
                 "*STEP\n*STATIC\n*CHANGE FRICTION, INTERACTION=I\n*FRICTION\n0.1\n*END STEP\n"),
      "INTERACTION=I");
}

} // namespace
} // namespace gapfem
