// Boundary conditions and loads, and their resolution from step to step (OP=MOD/NEW,
// propagation flags).
#include "unit/io/reader_test_util.hpp"

#include <algorithm>

namespace gapfem {
namespace {

using test::error_text;
using test::kTrussModel;
using test::read;

std::string with(std::string_view history) {
  return std::string(kTrussModel) + std::string(history);
}

/// The DOFs (deck numbers) of the boundary entries of a node label.
std::vector<int> bc_dofs(const Model& m, const Step& s, Label node) {
  std::vector<int> out;
  for (const auto& b : s.boundary)
    if (m.node_label(b.node).key == node) out.push_back(abaqus_number(b.dof));
  std::sort(out.begin(), out.end());
  return out;
}

const BoundaryEntry* find_bc(const Model& m, const Step& s, Label node, int dof) {
  for (const auto& b : s.boundary)
    if (m.node_label(b.node).key == node && abaqus_number(b.dof) == dof) return &b;
  return nullptr;
}

TEST(ReaderLoads, BoundaryTypesUseAbaqusDofLists) {
  const std::pair<const char*, std::vector<int>> cases[] = {
      {"ENCASTRE", {1, 2, 3, 4, 5, 6}},
      {"PINNED", {1, 2, 3}},
      {"XSYMM", {1, 5, 6}},
      {"YSYMM", {2, 4, 6}},
      {"ZSYMM", {3, 4, 5}},
      {"XASYMM", {2, 3, 4}},
      {"YASYMM", {1, 3, 5}},
      {"ZASYMM", {1, 2, 6}},
  };
  for (const auto& [type, dofs] : cases) {
    const Model m =
        read(with(std::string("*STEP\n*STATIC\n*BOUNDARY\n1, ") + type + "\n*END STEP\n"));
    EXPECT_EQ(bc_dofs(m, m.steps[0], 1), dofs) << type;
  }
}

TEST(ReaderLoads, BoundaryDirectFormat) {
  const Model m = read(with(R"(*AMPLITUDE, NAME=AMP
0., 0., 1., 1.
*STEP
*STATIC
*BOUNDARY, AMPLITUDE=amp
1, 1, 3
2, 2, , 0.25
2, 11, 11, 100.
*BOUNDARY, FIXED
2, 1
*END STEP
)"));
  const Step& s = m.steps[0];
  EXPECT_EQ(bc_dofs(m, s, 1), (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(bc_dofs(m, s, 2), (std::vector<int>{1, 2, 11}));
  const BoundaryEntry* b = find_bc(m, s, 2, 2);
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->value, 0.25);
  EXPECT_EQ(b->amplitude, 0);
  EXPECT_FALSE(b->propagated);
  EXPECT_EQ(b->loc.str(), "deck.inp:17 (*BOUNDARY)");
  EXPECT_EQ(find_bc(m, s, 2, 11)->value, 100.0);
  EXPECT_EQ(find_bc(m, s, 2, 11)->dof, DofType::NT);
  EXPECT_TRUE(find_bc(m, s, 2, 1)->fixed);
  EXPECT_EQ(find_bc(m, s, 2, 1)->amplitude, -1);
}

TEST(ReaderLoads, BoundaryErrors) {
  auto in_step = [](std::string lines) {
    return with("*STEP\n*STATIC\n*BOUNDARY\n" + lines + "\n*END STEP\n");
  };
  // data at line 14
  EXPECT_CONTAINS(error_text(in_step("1, 7")),
                  "deck.inp:14: *BOUNDARY: field 2 (degree of freedom): DOF 7 is not available");
  EXPECT_CONTAINS(error_text(in_step("1, 0")), "DOF 0 is not available");
  EXPECT_CONTAINS(error_text(in_step("1, 1, 11")), "DOFs 1-11: this range includes DOFs 7-10");
  EXPECT_CONTAINS(error_text(in_step("1, 3, 1")), "the last DOF 1 is smaller than the first DOF 3");
  EXPECT_CONTAINS(error_text(in_step("1, CLAMPED")),
                  "field 2 (CLAMPED): write a DOF number or one of ENCASTRE");
  EXPECT_CONTAINS(error_text(in_step("9, 1")),
                  "deck.inp:14: *BOUNDARY: node 9: this node is not defined");
  EXPECT_CONTAINS(error_text(with("*STEP\n*STATIC\n*BOUNDARY, AMPLITUDE=NONE\n1, 1\n*END STEP\n")),
                  "deck.inp:13: *BOUNDARY: AMPLITUDE=NONE: amplitude NONE is not defined");
  EXPECT_CONTAINS(error_text(with("*BOUNDARY, OP=NEW\n1, 1\n")),
                  "deck.inp:11: *BOUNDARY: OP: OP is a history-data parameter");
}

TEST(ReaderLoads, BoundaryPropagationAndOpNew) {
  const Model m = read(with(R"(*BOUNDARY
1, ENCASTRE
*STEP
*STATIC
*BOUNDARY
2, 2, 2, 0.5
*END STEP
*STEP
*STATIC
*BOUNDARY, OP=MOD
2, 2, 2, 0.7
*END STEP
*STEP
*STATIC
*END STEP
*STEP
*STATIC
*BOUNDARY, OP=NEW
1, 1
*BOUNDARY, OP=NEW
2, 3
*END STEP
)"));
  ASSERT_EQ(m.steps.size(), 4u);
  // step 1: model-data BCs are carried in (propagated), the new one is not
  const Step& s1 = m.steps[0];
  EXPECT_EQ(s1.boundary.size(), 7u);
  EXPECT_TRUE(find_bc(m, s1, 1, 4)->propagated);
  EXPECT_FALSE(find_bc(m, s1, 2, 2)->propagated);
  // step 2: OP=MOD redefines (2,2) and keeps the rest
  const Step& s2 = m.steps[1];
  EXPECT_EQ(s2.boundary.size(), 7u);
  EXPECT_EQ(find_bc(m, s2, 2, 2)->value, 0.7);
  EXPECT_FALSE(find_bc(m, s2, 2, 2)->propagated);
  EXPECT_TRUE(find_bc(m, s2, 1, 1)->propagated);
  // step 3: nothing given: everything carried over unchanged
  const Step& s3 = m.steps[2];
  EXPECT_EQ(s3.boundary.size(), 7u);
  for (const auto& b : s3.boundary) EXPECT_TRUE(b.propagated);
  EXPECT_EQ(find_bc(m, s3, 2, 2)->value, 0.7);
  // step 4: OP=NEW removes everything inherited, model-data BCs included; two OP=NEW keywords
  // in one step add up
  const Step& s4 = m.steps[3];
  ASSERT_EQ(s4.boundary.size(), 2u);
  EXPECT_EQ(bc_dofs(m, s4, 1), (std::vector<int>{1}));
  EXPECT_EQ(bc_dofs(m, s4, 2), (std::vector<int>{3}));
  for (const auto& b : s4.boundary) EXPECT_FALSE(b.propagated);
}

TEST(ReaderLoads, ConcentratedLoadsAndFluxesAreSeparateFamilies) {
  const Model m = read(with(R"(*STEP
*STATIC
*CLOAD
2, 1, 10.
ALL, 2, -1.
*CFLUX
2, 11, 5.
1, , 3.
*END STEP
*STEP
*STATIC
*CLOAD, OP=NEW
2, 1, 20.
*END STEP
)"));
  const Step& s1 = m.steps[0];
  ASSERT_EQ(s1.cloads.size(), 5u);
  const Step& s2 = m.steps[1];
  // OP=NEW on *CLOAD removed the three inherited forces but not the two fluxes
  ASSERT_EQ(s2.cloads.size(), 3u);
  int forces = 0, fluxes = 0;
  for (const auto& l : s2.cloads) {
    if (l.dof == DofType::NT) {
      ++fluxes;
      EXPECT_TRUE(l.propagated);
    } else {
      ++forces;
      EXPECT_FALSE(l.propagated);
      EXPECT_EQ(l.value, 20.0);
    }
  }
  EXPECT_EQ(forces, 1);
  EXPECT_EQ(fluxes, 2);

  auto step = [](std::string kw) { return with("*STEP\n*STATIC\n" + kw + "\n*END STEP\n"); };
  EXPECT_CONTAINS(error_text(step("*CLOAD\n1, 11, 1.")),
                  "deck.inp:14: *CLOAD: field 2 (DOF): use *CFLUX");
  EXPECT_CONTAINS(error_text(step("*CLOAD\n1, 7, 1.")), "*CLOAD acts on DOFs 1-6, not 7");
  EXPECT_CONTAINS(error_text(step("*CLOAD\n1, 1")), "field 3 (magnitude): this value is required");
  EXPECT_CONTAINS(
      error_text(step("*CFLUX\n1, 2, 1.")),
      "deck.inp:14: *CFLUX: field 2 (DOF): a concentrated heat flux acts on a temperature DOF: 11");
}

TEST(ReaderLoads, RepeatedEntryInOneKeywordReplaces) {
  const Model m = read(with("*STEP\n*STATIC\n*CLOAD\n2, 1, 1.\n2, 1, 3.\n*END STEP\n"));
  ASSERT_EQ(m.steps[0].cloads.size(), 1u);
  EXPECT_EQ(m.steps[0].cloads[0].value, 3.0);
}

constexpr std::string_view kBrickAndSpring = R"(*NODE
1, 0, 0, 0
2, 1, 0, 0
3, 1, 1, 0
4, 0, 1, 0
5, 0, 0, 1
6, 1, 0, 1
7, 1, 1, 1
8, 0, 1, 1
*ELEMENT, TYPE=C3D8, ELSET=B
1, 1, 2, 3, 4, 5, 6, 7, 8
*ELEMENT, TYPE=SPRINGA, ELSET=S
2, 1, 7
*ELSET, ELSET=EVERY
B, S
*MATERIAL, NAME=M
*ELASTIC
1000., 0.25
*DENSITY
1.
*SOLID SECTION, ELSET=B, MATERIAL=M
*SPRING, ELSET=S

1.
*SURFACE, NAME=TOP
1, S2
*STEP
*STATIC
)";
// the first history line after kBrickAndSpring is line 29 (its data: line 30)

TEST(ReaderLoads, DistributedLoads) {
  const Model m = read(std::string(kBrickAndSpring) + R"(*DLOAD
EVERY, GRAV, 9.81, 0., 0., -2.
1, BY, 5.
1, BX, 4.
1, P2, 3.
*DSLOAD
TOP, P, 7.
*END STEP
)");
  const auto& d = m.steps[0].dloads;
  ASSERT_EQ(d.size(), 5u); // GRAV skips the spring of EVERY; BX and BY are separate loads
  EXPECT_EQ(d[0].kind, DistLoadKind::Gravity);
  EXPECT_EQ(d[0].elem, 0);
  EXPECT_EQ(d[0].magnitude, 9.81);
  EXPECT_EQ(d[0].direction, (Vec3{0.0, 0.0, -1.0})); // normalised
  EXPECT_EQ(d[1].kind, DistLoadKind::BodyForce);
  EXPECT_EQ(d[1].direction, (Vec3{0.0, 1.0, 0.0}));
  EXPECT_EQ(d[2].direction, (Vec3{1.0, 0.0, 0.0}));
  EXPECT_EQ(d[3].kind, DistLoadKind::Pressure);
  EXPECT_EQ(d[3].face, 2);
  EXPECT_EQ(d[3].loc.keyword, "*DLOAD");
  EXPECT_EQ(d[4].face, 2);
  EXPECT_EQ(d[4].magnitude, 7.0);
  EXPECT_EQ(d[4].loc.keyword, "*DSLOAD"); // same face, other keyword: both apply
}

TEST(ReaderLoads, DistributedLoadErrors) {
  const std::string b(kBrickAndSpring);
  auto err = [&](std::string lines) { return error_text(b + lines + "\n*END STEP\n"); };
  EXPECT_CONTAINS(
      err("*DLOAD\n1, P, 1."),
      "deck.inp:30: *DLOAD: field 2 (P): element 1 is not a shell: give the face of the "
      "pressure");
  EXPECT_CONTAINS(err("*DLOAD\n1, P7, 1."),
                  "deck.inp:30: *DLOAD: element 1 (C3D8): face 7 does not exist");
  EXPECT_CONTAINS(err("*DLOAD\n1, PX, 1."),
                  "element 1 (C3D8): PX is a load per unit length on beams");
  EXPECT_CONTAINS(err("*DLOAD\n1, PE, 1."),
                  "element 1 (C3D8): PE is a pressure on pipe elements (PIPE31, PIPE32)");
  EXPECT_CONTAINS(err("*DLOAD\n1, HPI, 1., 10., 0."),
                  "element 1 (C3D8): HPI is a pressure on pipe elements (PIPE31, PIPE32)");
  EXPECT_CONTAINS(err("*DLOAD\n1, HPI, 1."), "field 4 (zero-pressure height z0): this value is "
                                             "required");
  EXPECT_CONTAINS(err("*DLOAD\n1, HPX, 1."), "field 2 (HPX): this load label is not supported");
  EXPECT_CONTAINS(err("*DLOAD\n1, GRAV, 9.81"), "GRAV needs a non-zero direction");
  EXPECT_CONTAINS(err("*DLOAD\n2, GRAV, 9.81, 0, 0, -1"),
                  "element 2 (SPRINGA): body loads need an element");
  EXPECT_CONTAINS(err("*DLOAD\n2, P1, 1."), "element 2 (SPRINGA): this element type has no faces");
  EXPECT_CONTAINS(err("*DSLOAD\nNOPE, P, 1."),
                  "deck.inp:30: *DSLOAD: surface NOPE: this surface is not defined");
  EXPECT_CONTAINS(err("*DSLOAD\nTOP, TRSHR, 1."), "*DSLOAD supports the label P");
  EXPECT_CONTAINS(err("*DFLUX\n1, BF, 1."),
                  "element 1 (C3D8): this element has no temperature DOF");
}

TEST(ReaderLoads, DloadOpNewKeepsDsload) {
  const Model m = read(std::string(kBrickAndSpring) + R"(*DLOAD
1, P1, 1.
*DSLOAD
TOP, P, 2.
*END STEP
*STEP
*STATIC
*DLOAD, OP=NEW
1, P3, 5.
*END STEP
)");
  const auto& d = m.steps[1].dloads;
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].loc.keyword, "*DSLOAD");
  EXPECT_TRUE(d[0].propagated);
  EXPECT_EQ(d[1].face, 3);
  EXPECT_FALSE(d[1].propagated);
}

TEST(ReaderLoads, ThermalLoads) {
  const Model m = read(R"(*NODE
1
2, 1
3, 1, 1
4, 0, 1
*ELEMENT, TYPE=DC2D4, ELSET=H
1, 1, 2, 3, 4
*MATERIAL, NAME=M
*CONDUCTIVITY
1.
*SOLID SECTION, ELSET=H, MATERIAL=M
*SURFACE, NAME=EDGE
1, S3
*AMPLITUDE, NAME=A1
0., 0., 1., 1.
*AMPLITUDE, NAME=A2
0., 1., 1., 2.
*STEP
*HEAT TRANSFER, STEADY STATE
*DFLUX
H, BF, 10.
1, S2, 3.
*DSFLUX
EDGE, S, 4.
*FILM, AMPLITUDE=A1, FILM AMPLITUDE=A2
1, F1, 20., 5.
*SFILM
EDGE, F, 30., 6.
*END STEP
)");
  const auto& d = m.steps[0].dloads;
  ASSERT_EQ(d.size(), 5u);
  EXPECT_EQ(d[0].kind, DistLoadKind::BodyFlux);
  EXPECT_EQ(d[0].face, 0);
  EXPECT_EQ(d[1].kind, DistLoadKind::SurfaceFlux);
  EXPECT_EQ(d[1].face, 2);
  EXPECT_EQ(d[2].kind, DistLoadKind::SurfaceFlux);
  EXPECT_EQ(d[2].face, 3);
  EXPECT_EQ(d[3].kind, DistLoadKind::Film);
  EXPECT_EQ(d[3].face, 1);
  EXPECT_EQ(d[3].sink_temperature, 20.0);
  EXPECT_EQ(d[3].magnitude, 5.0);
  EXPECT_EQ(d[3].amplitude, 0);
  EXPECT_EQ(d[3].film_amplitude, 1);
  EXPECT_EQ(d[4].face, 3);
  EXPECT_EQ(d[4].sink_temperature, 30.0);
  EXPECT_EQ(d[4].film_amplitude, -1);
}

TEST(ReaderLoads, PredefinedTemperatures) {
  const Model m = read(with(R"(*STEP
*STATIC
*TEMPERATURE
ALL, 50.
*END STEP
*STEP
*STATIC
*TEMPERATURE, OP=NEW
2, 80.
*END STEP
)"));
  ASSERT_EQ(m.steps[0].temperatures.size(), 2u);
  ASSERT_EQ(m.steps[1].temperatures.size(), 1u);
  EXPECT_EQ(m.steps[1].temperatures[0].value, 80.0);
  EXPECT_FALSE(m.steps[1].temperatures[0].propagated);
  EXPECT_CONTAINS(error_text(with("*STEP\n*STATIC\n*TEMPERATURE, FILE=t.fil\n*END STEP\n")),
                  "deck.inp:13: *TEMPERATURE: FILE=t.fil");
}

/// A DC2D4 (nodes 1-4, DOF 11), a thermal GAPUNIT (nodes 4-5, DOFs 1, 2 and 11) and a mechanical
/// GAPUNI (nodes 6-7, no DOF 11), for heat transfer and coupled steps.
constexpr std::string_view kThermalNodes = R"(*NODE
1, 0., 0.
2, 1., 0.
3, 1., 1.
4, 0., 1.
5, 0., 2.
6, 3., 0.
7, 4., 0.
*NSET, NSET=SQUARE
1, 2, 3, 4
*ELEMENT, TYPE=DC2D4, ELSET=H
1, 1, 2, 3, 4
*ELEMENT, TYPE=GAPUNIT, ELSET=GT
2, 4, 5
*ELEMENT, TYPE=GAPUNI, ELSET=GM
3, 6, 7
*MATERIAL, NAME=M
*CONDUCTIVITY
1.
*SOLID SECTION, ELSET=H, MATERIAL=M
*GAP, ELSET=GT
0., 0., 1., 0., 1.
*GAP, ELSET=GM
0., 1., 0., 0., 1.
)";
// kThermalNodes has 24 lines: *STEP is line 25, the procedure 26, the next keyword 27 and its first
// data line 28

TEST(ReaderLoads, PredefinedTemperatureOnTemperatureDofIsAnError) {
  const std::string model(kThermalNodes);
  for (const char* procedure :
       {"*HEAT TRANSFER, STEADY STATE", "*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE"}) {
    SCOPED_TRACE(procedure);
    const std::string step = std::string("*STEP\n") + procedure + "\n";
    // Node 3 belongs to the DC2D4: its temperature is DOF 11, prescribed with *BOUNDARY.
    const std::string e1 = error_text(model + step + "*TEMPERATURE\n3, 100.\n*END STEP\n");
    EXPECT_CONTAINS(e1, "deck.inp:28: *TEMPERATURE: node 3: this node carries the temperature DOF "
                        "11 (element 1 is a DC2D4 element)");
    EXPECT_CONTAINS(e1,
                    "prescribe it with *BOUNDARY on DOF 11 instead (node, 11, 11, temperature)");
    EXPECT_CONTAINS(e1, std::string("in a ") + std::string(procedure).substr(0, 14));
    // Node 5 only belongs to the thermal gap GAPUNIT, which has DOF 11 too; a node set is reported
    // once per data line (node 1, the first of SQUARE).
    EXPECT_CONTAINS(error_text(model + step + "*TEMPERATURE\n5, 100.\n*END STEP\n"),
                    "node 5: this node carries the temperature DOF 11 (element 2 is a GAPUNIT");
    const std::string e2 = error_text(model + step + "*TEMPERATURE\nSQUARE, 100.\n*END STEP\n");
    EXPECT_CONTAINS(e2, "deck.inp:28: *TEMPERATURE: node 1: this node carries");
    EXPECT_EQ(e2.find("node 2:"), std::string::npos) << e2;
  }
  // Nodes 6 and 7 belong to the mechanical GAPUNI only: no DOF 11, a predefined temperature is fine
  // in a coupled step.
  const Model m = read(model + "*STEP\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n"
                               "*TEMPERATURE\n6, 50.\n7, 60.\n*END STEP\n");
  ASSERT_EQ(m.steps[0].temperatures.size(), 2u);
  EXPECT_EQ(m.steps[0].temperatures[1].value, 60.0);
}

TEST(ReaderLoads, PredefinedTemperatureCarriedFromAStaticStep) {
  // *STATIC keeps *TEMPERATURE as it is (the reader does not check it; a model with DOF 11 cannot
  // run a *STATIC step, which the analysis reports). Carried over into a heat transfer step, the
  // entry is an error there, with the way to remove it.
  const std::string deck = std::string(kThermalNodes) +
                           "*STEP\n*STATIC\n*TEMPERATURE\n3, 100.\n*END STEP\n"
                           "*STEP\n*HEAT TRANSFER, STEADY STATE\n*END STEP\n";
  const std::string e = error_text(deck);
  EXPECT_CONTAINS(e, "deck.inp:28: *TEMPERATURE: node 3: this node carries the temperature DOF 11");
  EXPECT_CONTAINS(e, "remove this *TEMPERATURE from step 2 with *TEMPERATURE, OP=NEW");
  // ... which works: an empty *TEMPERATURE, OP=NEW removes the carried entry.
  const Model m = read(std::string(kThermalNodes) +
                       "*STEP\n*STATIC\n*TEMPERATURE\n3, 100.\n*END STEP\n"
                       "*STEP\n*HEAT TRANSFER, STEADY STATE\n*TEMPERATURE, OP=NEW\n*END STEP\n");
  ASSERT_EQ(m.steps[0].temperatures.size(), 1u);
  EXPECT_TRUE(m.steps[1].temperatures.empty());
}

constexpr std::string_view kGaps = R"(*NODE
1
2, 0., -1.
*ELEMENT, TYPE=GAPUNI, ELSET=G
1, 1, 2
3, 2, 1
*ELEMENT, TYPE=SPRINGA, ELSET=S
2, 1, 2
*GAP, ELSET=G
-0.1, 0., -1., 0., 1.
*SPRING, ELSET=S

100.
*AMPLITUDE, NAME=OUT
0., 1., 1., 0.
*STEP
*STATIC
)";
// the first history line after kGaps is line 18

TEST(ReaderLoads, ContactInterference) {
  const Model m = read(std::string(kGaps) + R"(*CONTACT INTERFERENCE, TYPE=ELEMENT, AMPLITUDE=OUT
G, 0.1
*END STEP
*STEP
*STATIC
*CONTACT INTERFERENCE, TYPE=ELEMENT
3, 0.05
*END STEP
)");
  const auto& i1 = m.steps[0].interference;
  ASSERT_EQ(i1.size(), 2u);
  EXPECT_EQ(i1[0].allowance, 0.1);
  EXPECT_EQ(i1[0].amplitude, 0);
  EXPECT_FALSE(i1[0].shrink);
  const auto& i2 = m.steps[1].interference;
  ASSERT_EQ(i2.size(), 2u);
  EXPECT_TRUE(i2[0].propagated);  // element 1 carried over
  EXPECT_FALSE(i2[1].propagated); // element 3 redefined (OP=MOD)
  EXPECT_EQ(i2[1].allowance, 0.05);
  EXPECT_EQ(i2[1].amplitude, -1);

  const Model s =
      read(std::string(kGaps) + "*CONTACT INTERFERENCE, TYPE=ELEMENT, SHRINK\nG\n*END STEP\n");
  EXPECT_TRUE(s.steps[0].interference.at(0).shrink);
}

TEST(ReaderLoads, ContactInterferenceErrors) {
  const std::string g(kGaps);
  auto err = [&](std::string lines) { return error_text(g + lines + "\n*END STEP\n"); };
  EXPECT_CONTAINS(err("*CONTACT INTERFERENCE\nG, 0.1"),
                  "deck.inp:18: *CONTACT INTERFERENCE: TYPE=ELEMENT is required");
  EXPECT_CONTAINS(err("*CONTACT INTERFERENCE, TYPE=CONTACT PAIR\nG, 0.1"),
                  "TYPE=CONTACT PAIR: gapfem has no contact pairs");
  EXPECT_CONTAINS(err("*CONTACT INTERFERENCE, TYPE=ELEMENT\nS, 0.1"),
                  "deck.inp:19: *CONTACT INTERFERENCE: element 2 (SPRINGA): *CONTACT INTERFERENCE, "
                  "TYPE=ELEMENT applies to mechanical gap elements");
  EXPECT_CONTAINS(err("*CONTACT INTERFERENCE, TYPE=ELEMENT, SHRINK\nG, 0.1"),
                  "SHRINK takes no value");
  EXPECT_CONTAINS(err("*CONTACT INTERFERENCE, TYPE=ELEMENT\nG"),
                  "field 2 (allowable interference v)");
  EXPECT_CONTAINS(
      error_text(
          g +
          "*END STEP\n*STEP\n*STATIC\n*CONTACT INTERFERENCE, TYPE=ELEMENT, SHRINK\nG\n*END STEP\n"),
      "SHRINK can be used in the first step only");
}

} // namespace
} // namespace gapfem
