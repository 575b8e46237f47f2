// Materials, sections, element-property binding, amplitudes, initial conditions, physical
// constants and the model space.
#include "unit/io/reader_test_util.hpp"

namespace gapfem {
namespace {

using test::error_text;
using test::kTrussModel;
using test::read;

/// Truss mesh without material and section (tests add their own).
constexpr std::string_view kTrussMesh = R"(*NODE, NSET=ALL
1, 0., 0., 0.
2, 1., 0., 0.
*ELEMENT, TYPE=T3D2, ELSET=TRUSS
1, 1, 2
)";

TEST(ReaderMaterial, ElasticTableSortedByTemperature) {
  const Model m = read(std::string(kTrussMesh) + R"(*MATERIAL, NAME=hot
*ELASTIC, TYPE=ISOTROPIC
150000., 0.31, 400.
200000., 0.30, 20.
*SOLID SECTION, ELSET=TRUSS, MATERIAL=HOT
2.5
)");
  const Material& mat = m.materials.at(0);
  EXPECT_EQ(mat.name, "HOT");
  ASSERT_EQ(mat.elastic.n_values, 2);
  ASSERT_EQ(mat.elastic.n_rows(), 2);
  EXPECT_EQ(mat.elastic.keys, (std::vector<double>{20.0, 400.0}));
  EXPECT_EQ(mat.elastic.values, (std::vector<double>{200000., 0.30, 150000., 0.31}));
  EXPECT_EQ(m.solid_sections.at(0).thickness, 2.5);
  EXPECT_TRUE(m.solid_sections.at(0).thickness_given);
}

TEST(ReaderMaterial, OtherMaterialOptions) {
  const Model m = read(std::string(kTrussMesh) + R"(*MATERIAL, NAME=M
*ELASTIC
1., 0.
*DENSITY
7.8E-9
*EXPANSION, TYPE=ISO, ZERO=20.
1.2E-5, 20.
1.4E-5, 200.
*CONDUCTIVITY, TYPE=ISO
45.
*SPECIFIC HEAT
4.6E8
*SOLID SECTION, ELSET=TRUSS, MATERIAL=M
)");
  const Material& mat = m.materials.at(0);
  EXPECT_EQ(mat.density.value(0.0), 7.8e-9);
  EXPECT_EQ(mat.expansion_zero, 20.0);
  EXPECT_EQ(mat.expansion.n_rows(), 2);
  EXPECT_EQ(mat.conductivity.value(0.0), 45.0);
  EXPECT_EQ(mat.specific_heat.value(0.0), 4.6e8);
  EXPECT_FALSE(m.solid_sections.at(0).thickness_given);
  EXPECT_EQ(m.solid_sections.at(0).thickness, 1.0);
}

// A rejected *ELASTIC raises no follow-on "the material has no *ELASTIC" for its elements.
TEST(ReaderMaterial, RejectedElasticRaisesNoFollowOnError) {
  const std::string deck = R"(*NODE
1, 0., 0., 0.
2, 1., 0., 0.
*ELEMENT, TYPE=T3D2, ELSET=TRUSS
1, 1, 2
*MATERIAL, NAME=M
*ELASTIC, TYPE=ORTHO
1., 2., 3., 4., 5., 6., 7., 8.
*SOLID SECTION, ELSET=TRUSS, MATERIAL=M
1.
*STEP
*STATIC
*END STEP
)";
  const std::string text = error_text(deck);
  EXPECT_CONTAINS(text, "TYPE=ORTHO: this value is not supported");
  EXPECT_EQ(text.find("has none"), std::string::npos) << text;
}

TEST(ReaderMaterial, MaterialErrors) {
  const std::string b(kTrussMesh);
  EXPECT_CONTAINS(error_text(b + "*MATERIAL, NAME=M\n*ELASTIC, TYPE=ORTHOTROPIC\n1,2,3\n"),
                  "deck.inp:7: *ELASTIC: TYPE=ORTHOTROPIC: this value is not supported by gapfem; "
                  "use one of: ISOTROPIC");
  EXPECT_CONTAINS(error_text(b + "*MATERIAL, NAME=M\n*ELASTIC, DEPENDENCIES=1\n1, 0.3, 0, 1\n"),
                  "DEPENDENCIES=1");
  EXPECT_CONTAINS(error_text(b + "*MATERIAL, NAME=M\n*ELASTIC\n-5, 0.3\n"),
                  "deck.inp:8: *ELASTIC: Young's modulus must be positive");
  EXPECT_CONTAINS(error_text(b + "*MATERIAL, NAME=M\n*ELASTIC\n5, 0.5\n"), "Poisson's ratio");
  EXPECT_CONTAINS(error_text(b + "*MATERIAL, NAME=M\n*ELASTIC\n5, 0.3, 10\n6, 0.3, 10\n"),
                  "deck.inp:9: *ELASTIC: two data lines are given for temperature 10");
  EXPECT_CONTAINS(error_text(b + "*MATERIAL, NAME=M\n*ELASTIC\n"), "a data line is required");
  EXPECT_CONTAINS(error_text(b + "*MATERIAL, NAME=M\n*DENSITY\n1.\n*DENSITY\n2.\n"),
                  "deck.inp:9: *DENSITY: *DENSITY is given twice for material M");
  EXPECT_CONTAINS(error_text(b + "*MATERIAL, NAME=M\n*MATERIAL, NAME=m\n"),
                  "deck.inp:7: *MATERIAL: material M: this material is defined twice (first at "
                  "deck.inp:6");
  EXPECT_CONTAINS(error_text(b + "*MATERIAL, NAME=M\n*CONDUCTIVITY, TYPE=ORTHO\n1., 2., 3.\n"),
                  "deck.inp:7: *CONDUCTIVITY: TYPE=ORTHO: this value is not supported by gapfem; "
                  "use one of: ISO");
  EXPECT_CONTAINS(error_text(b + "*MATERIAL, NAME=M\n*EXPANSION, TYPE=ANISO\n1.\n"), "TYPE=ANISO");
  EXPECT_CONTAINS(error_text(b + "*MATERIAL, NAME=M\n*SPECIFIC HEAT, DEPENDENCIES=2\n1.\n"),
                  "deck.inp:7: *SPECIFIC HEAT: DEPENDENCIES=2: field-variable dependencies");
  EXPECT_CONTAINS(error_text(b + "*MATERIAL, NAME=M\n*DENSITY\n0.\n"),
                  "deck.inp:8: *DENSITY: the value must be positive");
  EXPECT_CONTAINS(error_text(b + "*MATERIAL, NAME=M\n*DENSITY\n1., 20., 3.\n"), "at most 2 fields");
  EXPECT_CONTAINS(error_text(b + "*ELASTIC\n1., 0.3\n"),
                  "deck.inp:6: *ELASTIC: *ELASTIC must follow *MATERIAL");
  // a non-material keyword ends the material block
  EXPECT_CONTAINS(error_text(b + "*MATERIAL, NAME=M\n*NSET, NSET=A\n1\n*DENSITY\n1.\n"),
                  "deck.inp:9: *DENSITY: *DENSITY must follow *MATERIAL");
}

TEST(ReaderMaterial, SolidSectionErrors) {
  const std::string b = std::string(kTrussMesh) + "*MATERIAL, NAME=M\n*ELASTIC\n1., 0.\n";
  EXPECT_CONTAINS(error_text(b + "*SOLID SECTION, ELSET=TRUSS, MATERIAL=M, ORIENTATION=OR1\n"),
                  "deck.inp:9: *SOLID SECTION: ORIENTATION=OR1");
  EXPECT_CONTAINS(error_text(b + "*SOLID SECTION, ELSET=TRUSS, MATERIAL=M\n-1.\n"),
                  "must be positive");
  EXPECT_CONTAINS(error_text(b + "*SOLID SECTION, ELSET=TRUSS\n"), "MATERIAL= is required");
  EXPECT_CONTAINS(error_text(b + "*SOLID SECTION, ELSET=TRUSS, MATERIAL=STEEL\n"),
                  "deck.inp:9: *SOLID SECTION: MATERIAL=STEEL: material STEEL is not defined; "
                  "define it with *MATERIAL, NAME=STEEL");
  EXPECT_CONTAINS(error_text(b + "*SOLID SECTION, ELSET=NOPE, MATERIAL=M\n"),
                  "deck.inp:9: *SOLID SECTION: ELSET=NOPE: this element set is not defined");
}

TEST(ReaderMaterial, ElementWithoutSectionNamesKeyword) {
  EXPECT_CONTAINS(error_text(kTrussMesh),
                  "deck.inp:5: *ELEMENT: element 1 (T3D2): this element has no section: add it to "
                  "the ELSET of a *SOLID SECTION");
  const std::string gaps = "*NODE\n1\n2\n*ELEMENT, TYPE=GAPUNI\n7, 1, 2\n8, 2, 1\n";
  EXPECT_CONTAINS(error_text(gaps),
                  "element 7 (GAPUNI): this element has no section: add it to the "
                  "ELSET of a *GAP (2 GAPUNI elements have none)");
}

TEST(ReaderMaterial, ElementInTwoSectionsNamesBothLines) {
  const std::string e =
      error_text(std::string(kTrussModel) + "*SOLID SECTION, ELSET=ALLE, MATERIAL=STEEL\n"
                                            "*ELSET, ELSET=ALLE\n1\n");
  // the second section names its own line and the first one
  EXPECT_CONTAINS(e, "element 1 (T3D2): this element gets two property definitions, deck.inp:9 "
                     "(*SOLID SECTION) and deck.inp:11 (*SOLID SECTION)");
}

TEST(ReaderMaterial, WrongFamilyInSectionElset) {
  const std::string e =
      error_text(std::string(kTrussModel) + "*ELEMENT, TYPE=SPRINGA, ELSET=TRUSS\n5, 1, 2\n");
  EXPECT_CONTAINS(e, "deck.inp:9: *SOLID SECTION: element 5 (SPRINGA): this element is in ELSET "
                     "TRUSS but a SPRINGA element needs a *SPRING, not a *SOLID SECTION");
}

TEST(ReaderMaterial, MaterialMustProvideWhatElementsNeed) {
  const std::string no_elastic =
      std::string(kTrussMesh) +
      "*MATERIAL, NAME=M\n*DENSITY\n1.\n*SOLID SECTION, ELSET=TRUSS, MATERIAL=M\n";
  EXPECT_CONTAINS(
      error_text(no_elastic),
      "deck.inp:6: *MATERIAL: material M: element 1 (T3D2) (ELSET TRUSS) needs *ELASTIC");
  const std::string heat =
      "*NODE\n1\n2,1\n*ELEMENT, TYPE=DC1D2, ELSET=H\n1, 1, 2\n"
      "*MATERIAL, NAME=M\n*ELASTIC\n1., 0.\n*SOLID SECTION, ELSET=H, MATERIAL=M\n";
  EXPECT_CONTAINS(error_text(heat), "needs *CONDUCTIVITY but the material has none");
  // a heat-transfer element needs no *ELASTIC
  const Model m =
      read("*NODE\n1\n2,1\n*ELEMENT, TYPE=DC1D2, ELSET=H\n1, 1, 2\n"
           "*MATERIAL, NAME=M\n*CONDUCTIVITY\n1.\n*SOLID SECTION, ELSET=H, MATERIAL=M\n0.5\n");
  EXPECT_EQ(m.solid_sections[0].thickness, 0.5);
}

TEST(ReaderMaterial, BeamSections) {
  const std::string mesh = "*NODE\n1\n2,1\n*ELEMENT, TYPE=B31, ELSET=B\n1, 1, 2\n"
                           "*MATERIAL, NAME=M\n*ELASTIC\n1., 0.3\n";
  const Model m =
      read(mesh + "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=PIPE\n0.5, 0.1\n0., 1., 0.\n");
  const BeamSection& b = m.beam_sections.at(0);
  EXPECT_EQ(b.shape, BeamSection::Shape::Pipe);
  EXPECT_EQ(b.dims, (std::vector<double>{0.5, 0.1}));
  EXPECT_TRUE(b.n1_given);
  EXPECT_EQ(b.n1, (Vec3{0.0, 1.0, 0.0}));
  EXPECT_EQ(m.element_property[0].kind, PropertyRef::Kind::Beam);

  const Model r = read(mesh + "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=RECT\n0.2, 0.3\n");
  EXPECT_EQ(r.beam_sections[0].dims, (std::vector<double>{0.2, 0.3}));
  EXPECT_FALSE(r.beam_sections[0].n1_given);
  EXPECT_EQ(r.beam_sections[0].n1, (Vec3{0.0, 0.0, -1.0})); // Abaqus default
  // ROTARY INERTIA=EXACT is Abaqus's default and gapfem's; ISOTROPIC is not offered
  EXPECT_NO_THROW(read(mesh +
                       "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=RECT, ROTARY INERTIA=EXACT\n"
                       "0.2, 0.3\n"));
  EXPECT_CONTAINS(error_text(mesh + "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=RECT, "
                                    "ROTARY INERTIA=ISOTROPIC\n0.2, 0.3\n"),
                  "ROTARY INERTIA=ISOTROPIC: gapfem forms the beam's exact rotary inertia");
  const Model c = read(mesh + "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=CIRC\n0.1\n");
  EXPECT_EQ(c.beam_sections[0].shape, BeamSection::Shape::Circ);

  // an error in the section is the only error (no "element has no section" after it)
  const std::string bad_i =
      error_text(mesh + "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=I\n1,2,3,4,5\n");
  EXPECT_CONTAINS(bad_i, "deck.inp:10: *BEAM SECTION: field 6 (t2): this value is required");
  EXPECT_EQ(bad_i.find("has no section"), std::string::npos) << bad_i;
  EXPECT_CONTAINS(
      error_text(mesh + "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=ARBITRARY\n1,1,0.1,0.1\n"),
      "deck.inp:9: *BEAM SECTION: SECTION=ARBITRARY: this section is not available in gapfem; "
      "gapfem's beam sections are RECT, CIRC, PIPE, BOX, I, HEX, L, TRAPEZOID");
  EXPECT_CONTAINS(error_text(mesh + "*BEAM SECTION, ELSET=B, MATERIAL=M\n1,2\n"),
                  "SECTION= is required");
  EXPECT_CONTAINS(
      error_text(mesh + "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=RECT\n0.2, 0.\n"),
      "deck.inp:10: *BEAM SECTION: field 2 (height b): section dimensions must be positive");
  EXPECT_CONTAINS(error_text(mesh + "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=PIPE\n0.5, 0.5\n"),
                  "must be smaller than the outer radius");
  EXPECT_CONTAINS(
      error_text(mesh + "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=CIRC\n0.5\n0,0,0\n"),
      "deck.inp:11: *BEAM SECTION: n1 direction");
  EXPECT_CONTAINS(error_text(mesh + "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=CIRC\n"),
                  "dimensions are missing");
  EXPECT_CONTAINS(error_text(mesh + "*SOLID SECTION, ELSET=B, MATERIAL=M\n"),
                  "a B31 element needs a *BEAM SECTION, not a *SOLID SECTION");
}

TEST(ReaderMaterial, Springs) {
  const std::string mesh =
      "*NODE\n1\n2,1\n*ELEMENT, TYPE=SPRING1, ELSET=S1\n1, 1\n"
      "*ELEMENT, TYPE=SPRING2, ELSET=S2\n2, 1, 2\n*ELEMENT, TYPE=SPRINGA, ELSET=SA\n3, 1, 2\n";
  const Model m =
      read(mesh + "*SPRING, ELSET=S1\n2\n100.\n*SPRING, ELSET=S2\n1, 3\n50., , 0.\n60., , 100.\n"
                  "*SPRING, ELSET=SA\n\n1000.\n");
  ASSERT_EQ(m.spring_sections.size(), 3u);
  EXPECT_EQ(m.spring_sections[0].dof1, 2);
  EXPECT_EQ(m.spring_sections[0].stiffness.value(0.0), 100.0);
  EXPECT_EQ(m.spring_sections[1].dof1, 1);
  EXPECT_EQ(m.spring_sections[1].dof2, 3);
  EXPECT_EQ(m.spring_sections[1].stiffness.n_rows(), 2); // Abaqus's k, frequency, temperature
  EXPECT_EQ(m.spring_sections[1].stiffness.value(50.0), 55.0);
  EXPECT_EQ(m.spring_sections[2].dof1, 0);
  EXPECT_EQ(m.spring_sections[2].stiffness.value(0.0), 1000.0);
  for (ElemId e = 0; e < 3; ++e) EXPECT_EQ(m.element_property[e].kind, PropertyRef::Kind::Spring);

  const std::string ok = "*SPRING, ELSET=S2\n1, 3\n50.\n*SPRING, ELSET=SA\n\n1000.\n";
  // NONLINEAR (force, relative displacement) tables: at least two lines, ascending
  EXPECT_CONTAINS(error_text(mesh + "*SPRING, ELSET=S1, NONLINEAR\n2\n1., 0.1\n" + ok),
                  "deck.inp:12: *SPRING: ELSET=S1: a nonlinear spring needs at least two");
  EXPECT_CONTAINS(error_text(mesh + "*SPRING, ELSET=S1, NONLINEAR\n2\n1., 0.1\n0., 0.\n" + ok),
                  "the relative displacements must increase");
  EXPECT_CONTAINS(error_text(mesh + "*SPRING, ELSET=S1\n7\n1.\n" + ok),
                  "deck.inp:11: *SPRING: field 1 (DOF at node 1): springs act on DOFs 1-6, not 7");
  EXPECT_CONTAINS(error_text(mesh + "*SPRING, ELSET=S1\n2\n" + ok), "the stiffness is missing");
  EXPECT_CONTAINS(error_text(mesh + "*SPRING, ELSET=S1\n2\n1.\n*SPRING, ELSET=S2\n1\n5.\n"
                                    "*SPRING, ELSET=SA\n\n1.\n"),
                  "deck.inp:14: *SPRING: field 2 (DOF at node 2)");
  EXPECT_CONTAINS(error_text(mesh + "*SPRING, ELSET=S1\n2\n1.\n*SPRING, ELSET=S2\n1,1\n5.\n"
                                    "*SPRING, ELSET=SA\n1000.\n5.\n"),
                  "for SPRINGA elements the first data line must be blank");
  // field 2 is the frequency (steady-state dynamics): a value there is not a temperature
  EXPECT_CONTAINS(error_text(mesh + "*SPRING, ELSET=S1\n2\n100., 20.\n" + ok),
                  "deck.inp:12: *SPRING: field 2: this is the frequency");
}

TEST(ReaderMaterial, Amplitudes) {
  const Model m = read(R"(*AMPLITUDE, NAME=ramp2, TIME=TOTAL TIME, VALUE=ABSOLUTE
0., 0., 1., 0.5, 2., 1.0, 3., 1.0
4., 2.
*AMPLITUDE, NAME=STEPPY, DEFINITION=TABULAR
0., 1.
)");
  ASSERT_EQ(m.amplitudes.size(), 2u);
  const Amplitude& a = m.amplitudes[0];
  EXPECT_EQ(a.name, "RAMP2");
  EXPECT_EQ(a.time, Amplitude::TimeBase::Total);
  EXPECT_TRUE(a.absolute);
  EXPECT_EQ(a.t, (std::vector<double>{0, 1, 2, 3, 4}));
  EXPECT_EQ(a.a, (std::vector<double>{0, 0.5, 1, 1, 2}));
  EXPECT_EQ(m.amplitudes[1].time, Amplitude::TimeBase::Step);
  EXPECT_FALSE(m.amplitudes[1].absolute);

  EXPECT_CONTAINS(error_text("*AMPLITUDE, NAME=A\n0., 0., 1., 1.\n1., 2.\n"),
                  "deck.inp:3: *AMPLITUDE: time 1: amplitude times must increase strictly");
  EXPECT_CONTAINS(error_text("*AMPLITUDE, NAME=A\n0., 0., 1.\n"), "odd number of values");
  EXPECT_CONTAINS(error_text("*AMPLITUDE, NAME=A, DEFINITION=SOLUTION DEPENDENT\n0., 0.\n"),
                  "DEFINITION=SOLUTION DEPENDENT");
  EXPECT_CONTAINS(error_text("*AMPLITUDE, NAME=A\n0., 0.\n*AMPLITUDE, NAME=a\n0., 1.\n"),
                  "deck.inp:3: *AMPLITUDE: amplitude A: this amplitude is defined twice");
  EXPECT_CONTAINS(error_text("*AMPLITUDE, NAME=A\n"), "no time, amplitude pairs");
}

TEST(ReaderMaterial, AmplitudeFromInputFile) {
  const auto dir = test::fresh_dir();
  test::write_file(dir / "amp.txt", "0., 0.\n1., 1.\n");
  test::write_file(dir / "main.inp", "*AMPLITUDE, NAME=A, INPUT=amp.txt\n");
  const Model m = read_deck(dir / "main.inp");
  EXPECT_EQ(m.amplitudes.at(0).t.size(), 2u);
}

TEST(ReaderMaterial, InitialTemperatures) {
  const Model m =
      read(std::string(kTrussModel) + "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nALL, 20.\n2, 100.\n");
  EXPECT_TRUE(m.has_initial_temperature);
  EXPECT_EQ(m.initial_temperature, (std::vector<double>{20.0, 100.0}));
  EXPECT_CONTAINS(
      error_text(std::string(kTrussModel) + "*INITIAL CONDITIONS, TYPE=STRESS\n1, 2.\n"),
      "deck.inp:11: *INITIAL CONDITIONS: TYPE=STRESS: gapfem supports TYPE=TEMPERATURE, VELOCITY "
      "and ROTATING VELOCITY");
  const Model none = read(kTrussModel);
  EXPECT_FALSE(none.has_initial_temperature);
  EXPECT_EQ(none.initial_temperature, (std::vector<double>{0.0, 0.0}));
}

TEST(ReaderMaterial, PhysicalConstants) {
  const Model m = read("*PHYSICAL CONSTANTS, ABSOLUTE ZERO=-273.15, STEFAN BOLTZMANN=5.67E-8, "
                       "UNIVERSAL GAS CONSTANT=8.31\n");
  EXPECT_EQ(m.constants.absolute_zero, -273.15);
  EXPECT_EQ(m.constants.stefan_boltzmann, 5.67e-8);
  EXPECT_EQ(test::count_warnings(m, "UNIVERSAL GAS CONSTANT"), 1);
}

TEST(ReaderMaterial, ModelSpaceFromElementTypes) {
  const std::string nodes = "*NODE\n1\n2,1\n3,1,1\n4,0,1\n*MATERIAL, NAME=M\n*ELASTIC\n1.,0.\n";
  const std::string planar = "*ELEMENT, TYPE=CPS4, ELSET=P\n1, 1, 2, 3, 4\n"
                             "*SOLID SECTION, ELSET=P, MATERIAL=M\n";
  const std::string axi = "*ELEMENT, TYPE=CAX4, ELSET=A\n2, 1, 2, 3, 4\n"
                          "*SOLID SECTION, ELSET=A, MATERIAL=M\n";
  const std::string solid =
      "*ELEMENT, TYPE=T3D2, ELSET=T\n3, 1, 2\n*SOLID SECTION, ELSET=T, MATERIAL=M\n";
  const std::string spring = "*ELEMENT, TYPE=SPRINGA, ELSET=S\n4, 1, 2\n*SPRING, ELSET=S\n\n1.\n";
  EXPECT_EQ(read(nodes + planar + spring).space, ModelSpace::Planar);
  EXPECT_EQ(read(nodes + axi).space, ModelSpace::Axisymmetric);
  EXPECT_EQ(read(nodes + spring).space, ModelSpace::ThreeD); // only "Any" types
  EXPECT_CONTAINS(
      error_text(nodes + planar + axi),
      "element 2 (CAX4): planar and axisymmetric elements cannot be mixed in one model: "
      "element 1 (CPS4)");
  EXPECT_CONTAINS(error_text(nodes + axi + solid),
                  "three-dimensional and two-dimensional elements");
}

} // namespace
} // namespace gapfem

// An element in a section of the wrong kind is one error, without a follow-on "has no section".
TEST(ReaderMaterial, WrongSectionKindIsOneError) {
  const std::string deck = "*NODE\n1,0,0,0\n2,1,0,0\n3,1,1,0\n4,0,1,0\n5,0,0,1\n6,1,0,1\n7,1,1,1\n"
                           "8,0,1,1\n*ELEMENT, TYPE=C3D8R, ELSET=A\n1, 1,2,3,4,5,6,7,8\n"
                           "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n"
                           "*BEAM SECTION, ELSET=A, MATERIAL=M, SECTION=RECT\n1., 1.\n";
  const std::string e = gapfem::test::error_text(deck);
  EXPECT_CONTAINS(e, "deck.inp:15: *BEAM SECTION: element 1 (C3D8R)");
  EXPECT_CONTAINS(e, "a C3D8R element needs a *SOLID SECTION, not a *BEAM SECTION");
  EXPECT_EQ(e.find("has no section"), std::string::npos) << e;
}
