// *GAP and its sub-options (spec gap-elements.md §0b, §2.2, §2.3, §3, §4).
#include "unit/io/reader_test_util.hpp"

namespace gapfem {
namespace {

using test::error_text;
using test::read;

/// Nodes 1-4 and one element of each gap type, in its own ELSET.
constexpr std::string_view kGapMesh = R"(*NODE
1, 0., 0., 0.
2, 0., -1., 0.
3, 0., 0., 0.
*ELEMENT, TYPE=GAPUNI, ELSET=GU
1, 1, 2
*ELEMENT, TYPE=GAPCYL, ELSET=GC
2, 1, 3
*ELEMENT, TYPE=GAPSPHER, ELSET=GS
3, 1, 3
)";
// line 11 is the first line after kGapMesh
constexpr std::string_view kOtherGaps = R"(*GAP, ELSET=GC
0.02, 1., 0., 0.
*GAP, ELSET=GS
0.2
)";

std::string deck(std::string_view gu) {
  return std::string(kGapMesh) + std::string(gu) + std::string(kOtherGaps);
}

TEST(ReaderGap, GapDataLine) {
  const Model m = read(deck("*GAP, ELSET=gu\n0.5, 0., -2., 0., 3.\n"));
  ASSERT_EQ(m.gap_sections.size(), 3u);
  const GapSection& g = m.gap_sections[0];
  EXPECT_EQ(g.elset, "GU");
  EXPECT_EQ(g.d, 0.5);
  EXPECT_EQ(g.direction, (Vec3{0.0, -2.0, 0.0})); // stored as given
  EXPECT_TRUE(g.direction_given);
  EXPECT_EQ(g.area, 3.0);
  EXPECT_TRUE(g.area_given);
  EXPECT_FALSE(g.ccx_penalty);
  EXPECT_FALSE(g.behavior.given);
  EXPECT_EQ(m.element_property[0], (PropertyRef{PropertyRef::Kind::Gap, 0}));
  EXPECT_EQ(m.element_property[1], (PropertyRef{PropertyRef::Kind::Gap, 1}));
  EXPECT_FALSE(m.gap_sections[2].direction_given);
}

TEST(ReaderGap, BlankAreaIsOneWithOneWarningPerGap) {
  const Model m = read(deck("*GAP, ELSET=GU\n0.5, 0., 0., 0.\n"));
  EXPECT_EQ(m.gap_sections[0].area, 1.0);
  EXPECT_FALSE(m.gap_sections[0].area_given);
  EXPECT_FALSE(m.gap_sections[0].direction_given); // all zero: computed from the coordinates
  // one warning for each of the three *GAP keywords (none gives an area)
  EXPECT_EQ(test::count_warnings(m, "A = 1"), 3);
  EXPECT_CONTAINS(m.warnings[0], "deck.inp:12: *GAP: ELSET=GU");
}

TEST(ReaderGap, DirectionOfSphericalGapIsIgnoredWithWarning) {
  const Model m =
      read(std::string(kGapMesh) + "*GAP, ELSET=GU\n0.5, 0., -1., 0., 1.\n*GAP, ELSET=GC\n"
                                   "0.02, 1., 0., 0., 1.\n*GAP, ELSET=GS\n0.2, 1., 0., 0., 1.\n");
  EXPECT_EQ(test::count_warnings(m, "not used by GAPSPHER"), 1);
  EXPECT_EQ(test::count_warnings(m, "deck.inp:15: *GAP: ELSET=GS"), 1);
}

TEST(ReaderGap, ThermalOptionsOnMechanicalGapsAreRemarked) {
  // GAPUNI carries no temperature: *GAP CONDUCTANCE / HEAT GENERATION on it have no effect
  const Model m = read(deck("*GAP, ELSET=GU\n0.5, 0., -1., 0., 1.\n*GAP CONDUCTANCE\n10., 0.\n"
                            "10., 1.\n*GAP HEAT GENERATION\n0.5\n"));
  EXPECT_EQ(test::count_warnings(m, "holds GAPUNI elements, which carry no temperature"), 2);
  EXPECT_EQ(test::count_warnings(m, "deck.inp:13: *GAP CONDUCTANCE: ELSET=GU"), 1);
  EXPECT_EQ(test::count_warnings(m, "deck.inp:16: *GAP HEAT GENERATION: ELSET=GU"), 1);
  // the same options on a GAPUNIT: no remark
  const Model t = read("*NODE\n1, 0., 0., 0.\n2, 0., -1., 0.\n*ELEMENT, TYPE=GAPUNIT, ELSET=G\n"
                       "1, 1, 2\n*GAP, ELSET=G\n0.5, 0., -1., 0., 1.\n*GAP HEAT GENERATION\n0.5\n");
  EXPECT_EQ(test::count_warnings(t, "carry no temperature"), 0);
}

TEST(ReaderGap, CalculixPenaltyFields) {
  const Model m = read(deck("*GAP, ELSET=GU\n0.5, 0., -1., 0., , 1.E7\n"));
  EXPECT_TRUE(m.gap_sections[0].ccx_penalty);
  EXPECT_EQ(m.gap_sections[0].ccx_stiffness, 1e7);
  EXPECT_EQ(m.gap_sections[0].ccx_tension, 1e-3); // default
  const Model t = read(deck("*GAP, ELSET=GU\n0.5, 0., -1., 0., , 1.E7, 0.5\n"));
  EXPECT_EQ(t.gap_sections[0].ccx_tension, 0.5);
  EXPECT_FALSE(
      read(deck("*GAP, ELSET=GU\n0.5, 0., -1., 0., , , 0.5\n")).gap_sections[0].ccx_penalty);
}

TEST(ReaderGap, GapLineErrors) {
  EXPECT_CONTAINS(error_text(deck("*GAP\n0.5\n")),
                  "deck.inp:11: *GAP: the parameter ELSET= is required");
  EXPECT_CONTAINS(error_text(deck("*GAP, ELSET=GU\n")), "the data line is missing");
  EXPECT_CONTAINS(error_text(deck("*GAP, ELSET=GU\n0.5\n0.6\n")), "deck.inp:13: *GAP:");
  EXPECT_CONTAINS(error_text(deck("*GAP, ELSET=GU\n0.5, 0, 1, 0, -1.\n")),
                  "deck.inp:12: *GAP: field 5 (area A): the area must not be negative");
  EXPECT_CONTAINS(error_text(deck("*GAP, ELSET=GU\n0.5, 0, 1, 0, 1., 1., 1., 1.\n")),
                  "at most 7 fields");
}

TEST(ReaderGap, ElsetMustHoldOnlyGapElements) {
  const std::string mesh = std::string(kGapMesh) + "*ELEMENT, TYPE=SPRINGA, ELSET=GU\n9, 1, 2\n";
  const std::string e =
      error_text(mesh + "*GAP, ELSET=GU\n0.5, 0., -1., 0., 1.\n" + std::string(kOtherGaps));
  EXPECT_CONTAINS(e, "deck.inp:13: *GAP: element 9 (SPRINGA): ELSET GU of *GAP must hold only gap "
                     "elements");
}

TEST(ReaderGap, CylindricalAndSphericalNeedNonZeroD) {
  const std::string e =
      error_text(std::string(kGapMesh) +
                 "*GAP, ELSET=GU\n0.5, 0., -1., 0., 1.\n*GAP, ELSET=GC\n0., 1., 0., 0.\n"
                 "*GAP, ELSET=GS\n0.\n");
  EXPECT_CONTAINS(
      e, "deck.inp:8: *ELEMENT: element 2 (GAPCYL): GAPCYL and GAPSPHER need a non-zero d");
  EXPECT_CONTAINS(e, "(*GAP at deck.inp:13 (*GAP))");
  EXPECT_CONTAINS(
      e, "deck.inp:10: *ELEMENT: element 3 (GAPSPHER): GAPCYL and GAPSPHER need a non-zero d");
}

TEST(ReaderGap, CylinderNeedsAxis) {
  const std::string e = error_text(std::string(kGapMesh) +
                                   "*GAP, ELSET=GU\n0.5, 0., -1., 0., 1.\n*GAP, ELSET=GC\n0.1\n"
                                   "*GAP, ELSET=GS\n0.1\n");
  EXPECT_CONTAINS(e, "element 2 (GAPCYL): GAPCYL needs the cylinder axis");
}

TEST(ReaderGap, CoincidentNodesWithComputedDirection) {
  const std::string mesh = "*NODE\n1\n2\n*ELEMENT, TYPE=GAPUNI, ELSET=G\n5, 1, 2\n";
  EXPECT_CONTAINS(
      error_text(mesh + "*GAP, ELSET=G\n0.1\n"),
      "deck.inp:5: *ELEMENT: element 5 (GAPUNI): the direction is computed from the node "
      "coordinates but the two nodes coincide");
  // with a given direction coincident nodes are fine
  EXPECT_EQ(read(mesh + "*GAP, ELSET=G\n0.1, 1., 0., 0., 1.\n").gap_sections.size(), 1u);
}

TEST(ReaderGap, TwoDimensionalModelsNeedInPlaneDirectionsAndZAxisCylinders) {
  const std::string mesh =
      "*NODE\n1\n2,1\n3,1,1\n4,0,1\n*MATERIAL, NAME=M\n*ELASTIC\n1.,0.\n"
      "*ELEMENT, TYPE=CPE4, ELSET=P\n1, 1, 2, 3, 4\n*SOLID SECTION, ELSET=P, MATERIAL=M\n"
      "*ELEMENT, TYPE=GAPUNI, ELSET=G\n5, 1, 3\n*ELEMENT, TYPE=GAPCYL, ELSET=C\n6, 2, 4\n";
  EXPECT_CONTAINS(
      error_text(mesh + "*GAP, ELSET=G\n0.1, 0., 1., 0.5, 1.\n*GAP, ELSET=C\n0.1, 0., 0., 1.\n"),
      "element 5 (GAPUNI): in a two-dimensional (planar) model the gap direction must lie "
      "in the x-y plane");
  EXPECT_CONTAINS(
      error_text(mesh + "*GAP, ELSET=G\n0.1, 0., 1., 0., 1.\n*GAP, ELSET=C\n0.1, 1., 0., 1.\n"),
      "element 6 (GAPCYL): in a two-dimensional (planar) model the GAPCYL axis must be the z-axis");
  // a z component of 1e-14 relative to the norm is round-off, not an error
  const Model m =
      read(mesh + "*GAP, ELSET=G\n0.1, 0., 1., 1.E-14, 1.\n*GAP, ELSET=C\n0.1, 0., 0., 1.\n");
  EXPECT_EQ(m.space, ModelSpace::Planar);
}

TEST(ReaderGap, SurfaceBehaviorLaws) {
  const auto law = [](std::string_view sb) {
    return read(deck(std::string("*GAP, ELSET=GU\n0.5, 0., -1., 0., 1.\n") + std::string(sb)))
        .gap_sections[0]
        .behavior;
  };
  const SurfaceBehavior hard = law("*SURFACE BEHAVIOR, NO SEPARATION\n");
  EXPECT_TRUE(hard.given);
  EXPECT_EQ(hard.law, PressureOverclosure::Hard);
  EXPECT_EQ(hard.method, ContactMethod::Direct);
  EXPECT_TRUE(hard.no_separation);
  const SurfaceBehavior exp =
      law("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL\n0.01, 100.\n");
  EXPECT_EQ(exp.law, PressureOverclosure::Exponential);
  EXPECT_EQ(exp.c0, 0.01);
  EXPECT_EQ(exp.p0, 100.0);
  const SurfaceBehavior lin = law("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=linear\n1.E6\n");
  EXPECT_EQ(lin.law, PressureOverclosure::Linear);
  EXPECT_EQ(lin.slope, 1e6);
  const SurfaceBehavior tab =
      law("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TABULAR\n0., -0.01\n10., 0.\n100., 0.01\n");
  EXPECT_EQ(tab.law, PressureOverclosure::Tabular);
  EXPECT_EQ(tab.table_p, (std::vector<double>{0., 10., 100.}));
  EXPECT_EQ(tab.table_g, (std::vector<double>{-0.01, 0., 0.01}));
  const SurfaceBehavior pen = law("*SURFACE BEHAVIOR, PENALTY\n1.E8\n");
  EXPECT_EQ(pen.method, ContactMethod::Penalty);
  EXPECT_EQ(pen.penalty_stiffness, 1e8);
  const SurfaceBehavior aug = law("*SURFACE BEHAVIOR, AUGMENTED LAGRANGE\n");
  EXPECT_EQ(aug.method, ContactMethod::AugmentedLagrange);
  EXPECT_EQ(aug.penalty_stiffness, 0.0); // automatic
}

TEST(ReaderGap, SurfaceBehaviorErrors) {
  const std::string g = "*GAP, ELSET=GU\n0.5, 0., -1., 0., 1.\n";
  // line 13 is the *SURFACE BEHAVIOR line
  EXPECT_CONTAINS(
      error_text(deck(g + "*SURFACE BEHAVIOR, NO SEPARATION, PRESSURE-OVERCLOSURE=LINEAR\n1.\n")),
      "deck.inp:13: *SURFACE BEHAVIOR: NO SEPARATION: NO SEPARATION cannot be combined");
  EXPECT_CONTAINS(
      error_text(deck(g + "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=SCALE FACTOR\n1.\n")),
      "PRESSURE-OVERCLOSURE=SCALE FACTOR");
  EXPECT_CONTAINS(error_text(deck(g + "*SURFACE BEHAVIOR, PENALTY, DIRECT\n")),
                  "exclude each other");
  EXPECT_CONTAINS(
      error_text(deck(g + "*SURFACE BEHAVIOR, PENALTY, PRESSURE-OVERCLOSURE=LINEAR\n1.\n")),
      "hard contact only");
  EXPECT_CONTAINS(error_text(deck(g + "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TABULAR\n0., 0.\n")),
                  "at least two data lines");
  EXPECT_CONTAINS(
      error_text(deck(g + "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TABULAR\n0., 0.\n1., 0.\n")),
      "deck.inp:15: *SURFACE BEHAVIOR: field 2 (overclosure): overclosures must increase");
  EXPECT_CONTAINS(
      error_text(deck(g + "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL\n0.01\n")),
      "deck.inp:14: *SURFACE BEHAVIOR: field 2 (pressure p0)");
  EXPECT_CONTAINS(error_text(deck(g + "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n-1.\n")),
                  "the slope must be positive");
  EXPECT_CONTAINS(error_text(deck(g + "*SURFACE BEHAVIOR\n1.\n")), "takes no data lines");
  EXPECT_CONTAINS(error_text(deck(g + "*SURFACE BEHAVIOR, PENALTY\n1.E8, 0.1\n")),
                  "field 2 (clearance at zero pressure)");
  EXPECT_CONTAINS(
      error_text(deck(g + "*SURFACE BEHAVIOR\n*SURFACE BEHAVIOR\n")),
      "deck.inp:14: *SURFACE BEHAVIOR: *GAP, ELSET=GU: *SURFACE BEHAVIOR is given twice");
}

TEST(ReaderGap, Friction) {
  const std::string g = "*GAP, ELSET=GU\n0.5, 0., -1., 0., 1.\n";
  const Model m = read(deck(g + "*FRICTION, ELASTIC SLIP=1.E-4, TAUMAX=50.\n0.3\n"));
  const FrictionSpec& f = m.gap_sections[0].friction;
  EXPECT_TRUE(f.given);
  ASSERT_EQ(f.rows.size(), 1u);
  EXPECT_EQ(f.rows[0].mu, 0.3);
  EXPECT_EQ(f.n_columns, 1);
  EXPECT_EQ(f.elastic_slip, 1e-4);
  EXPECT_EQ(f.taumax, 50.0);
  EXPECT_EQ(f.slip_tolerance, 0.005); // default
  const FrictionSpec t =
      read(deck(g + "*FRICTION, SLIP TOLERANCE=0.01\n0.3, 0., 0., 20.\n0.2, 0., 0., 100.\n"))
          .gap_sections[0]
          .friction;
  EXPECT_EQ(t.n_columns, 4);
  EXPECT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[1].temperature, 100.0);
  EXPECT_EQ(t.slip_tolerance, 0.01);
  const FrictionSpec r = read(deck(g + "*FRICTION, ROUGH\n")).gap_sections[0].friction;
  EXPECT_TRUE(r.rough);
  const FrictionSpec l = read(deck(g + "*FRICTION, LAGRANGE\n0.1\n")).gap_sections[0].friction;
  EXPECT_TRUE(l.lagrange);

  for (const char* bad : {"EXPONENTIAL DECAY", "ANISOTROPIC", "USER"})
    EXPECT_CONTAINS(error_text(deck(g + "*FRICTION, " + bad + "\n0.3\n")),
                    std::string("deck.inp:13: *FRICTION: ") + bad);
  EXPECT_CONTAINS(error_text(deck(g + "*FRICTION, DEPENDENCIES=1\n0.3\n")), "DEPENDENCIES=1");
  EXPECT_CONTAINS(error_text(deck(g + "*FRICTION\n")), "the friction coefficient is missing");
  EXPECT_CONTAINS(error_text(deck(g + "*FRICTION\n-0.3\n")), "field 1 (friction coefficient)");
  EXPECT_CONTAINS(error_text(deck(g + "*FRICTION, LAGRANGE, ELASTIC SLIP=0.1\n0.3\n")),
                  "cannot be combined with ELASTIC SLIP");
  EXPECT_CONTAINS(error_text(deck(g + "*FRICTION, ELASTIC SLIP=0.1, SLIP TOLERANCE=0.1\n0.3\n")),
                  "exclude each other");
}

TEST(ReaderGap, ThermalAndDampingOptions) {
  const std::string g = "*GAP, ELSET=GU\n0.5, 0., -1., 0., 2.\n";
  const Model m =
      read(deck(g + R"(*CONTACT DAMPING, DEFINITION=DAMPING COEFFICIENT, TANGENT FRACTION=0.1
5., 0.01, 0.2
*GAP CONDUCTANCE, PRESSURE
10., 0.
20., 100.
*GAP RADIATION
0.45167, 0.45167
1., 0.
1., 1.
*GAP HEAT GENERATION
0.9, 0.6
)"));
  const GapSection& gap = m.gap_sections[0];
  EXPECT_TRUE(gap.damping.given);
  EXPECT_EQ(gap.damping.coefficient, 5.0);
  EXPECT_EQ(gap.damping.clearance, 0.01);
  EXPECT_EQ(gap.damping.fraction, 0.2);
  EXPECT_EQ(gap.damping.tangent_fraction, 0.1);
  EXPECT_TRUE(gap.conductance.pressure);
  ASSERT_EQ(gap.conductance.rows.size(), 2u);
  EXPECT_EQ(gap.conductance.rows[1].k, 20.0);
  EXPECT_EQ(gap.conductance.rows[1].x, 100.0);
  EXPECT_FALSE(gap.conductance.temperature_dependent);
  EXPECT_EQ(gap.radiation.emissivity_a, 0.45167);
  EXPECT_EQ(gap.radiation.view_factor, (std::vector<double>{1.0, 1.0}));
  EXPECT_EQ(gap.radiation.clearance, (std::vector<double>{0.0, 1.0}));
  EXPECT_EQ(gap.heat_generation.eta, 0.9);
  EXPECT_EQ(gap.heat_generation.fraction, 0.6);
  // defaults of *GAP HEAT GENERATION
  const GapHeatGenerationSpec h =
      read(deck(g + "*GAP HEAT GENERATION\n")).gap_sections[0].heat_generation;
  EXPECT_TRUE(h.given);
  EXPECT_EQ(h.eta, 1.0);
  EXPECT_EQ(h.fraction, 0.5);
  const GapConductanceSpec c =
      read(deck(g + "*GAP CONDUCTANCE\n10., 0., 20.\n10., 1., 20.\n5., 0., 200.\n5., 1., 200.\n"))
          .gap_sections[0]
          .conductance;
  EXPECT_TRUE(c.temperature_dependent);
  EXPECT_FALSE(c.pressure);
}

TEST(ReaderGap, ThermalAndDampingErrors) {
  const std::string g = "*GAP, ELSET=GU\n0.5, 0., -1., 0., 2.\n";
  EXPECT_CONTAINS(
      error_text(deck(g + "*CONTACT DAMPING, DEFINITION=CRITICAL DAMPING FRACTION\n0.1\n")),
      "deck.inp:13: *CONTACT DAMPING: DEFINITION=CRITICAL DAMPING FRACTION");
  EXPECT_CONTAINS(error_text(deck(g + "*GAP CONDUCTANCE, USER\n")),
                  "deck.inp:13: *GAP CONDUCTANCE: USER");
  EXPECT_CONTAINS(error_text(deck(g + "*GAP CONDUCTANCE\n10., 0.\n")), "at least two data lines");
  EXPECT_CONTAINS(error_text(deck(g + "*GAP CONDUCTANCE\n10., 1.\n10., 0.\n")),
                  "deck.inp:15: *GAP CONDUCTANCE: field 2 (clearance): within one temperature");
  EXPECT_CONTAINS(error_text(deck(g + "*GAP RADIATION\n0.5, 0.5\n")),
                  "at least one line of view factor");
  EXPECT_CONTAINS(error_text(deck(g + "*GAP RADIATION\n0., 0.5\n1., 0.\n")),
                  "emissivities must lie in (0, 1]");
  EXPECT_CONTAINS(error_text(deck(g + "*GAP HEAT GENERATION\n1., 1.5\n")),
                  "field 2 (f): must lie between 0 and 1");
}

TEST(ReaderGap, SubOptionsMustFollowGap) {
  const std::string m(kGapMesh);
  for (const char* kw : {"*SURFACE BEHAVIOR", "*CONTACT DAMPING", "*GAP CONDUCTANCE",
                         "*GAP RADIATION", "*GAP HEAT GENERATION"})
    EXPECT_CONTAINS(error_text(m + kw + "\n1.\n"),
                    std::string("deck.inp:11: ") + kw + ": " + kw + " must follow *GAP");
  EXPECT_CONTAINS(error_text(m + "*FRICTION\n0.3\n"),
                  "*FRICTION must follow *GAP (model data) or *CHANGE FRICTION (inside a step)");
}

TEST(ReaderGap, SubOptionsAttachUntilAnotherKeyword) {
  const std::string g = "*GAP, ELSET=GU\n0.5, 0., -1., 0., 1.\n";
  // sub-options in any order attach to the *GAP above them
  const Model m =
      read(deck(g + "*FRICTION\n0.3\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1.E6\n"));
  EXPECT_TRUE(m.gap_sections[0].friction.given);
  EXPECT_TRUE(m.gap_sections[0].behavior.given);
  EXPECT_FALSE(m.gap_sections[1].friction.given);
  // a second *GAP takes the sub-options that follow it
  const Model two = read(std::string(kGapMesh) + g +
                         "*FRICTION\n0.3\n*GAP, ELSET=GC\n0.02, 1., 0., 0.\n"
                         "*FRICTION\n0.1\n*GAP, ELSET=GS\n0.2\n");
  EXPECT_EQ(two.gap_sections[0].friction.rows.at(0).mu, 0.3);
  EXPECT_EQ(two.gap_sections[1].friction.rows.at(0).mu, 0.1);
  EXPECT_FALSE(two.gap_sections[2].friction.given);
  // another keyword ends the block
  EXPECT_CONTAINS(error_text(deck(g + "*NSET, NSET=X\n1\n*FRICTION\n0.3\n")),
                  "deck.inp:15: *FRICTION: *FRICTION must follow *GAP");
}

} // namespace
} // namespace gapfem
