// Input conventions Abaqus accepts (issue 45): abbreviated parameters and parameter values (the
// Input Syntax Rules: "need not be spelled out completely, but there must be enough characters
// given to distinguish them"), SYSTEM=R on *NODE (the default), zero or blank node normals, a blank
// Poisson's ratio (a blank field is 0), and CalculiX's SOLVER= on the procedures and INCF= on
// *STEP (warnings).
#include "unit/io/reader_test_util.hpp"

namespace gapfem {
namespace {

using test::error_text;
using test::kTrussModel;
using test::read;

std::string with_step(std::string_view step_line, std::string_view procedure) {
  return std::string(kTrussModel) + "*BOUNDARY\n1, 1, 3\n2, 2, 3\n" + std::string(step_line) +
         "\n" + std::string(procedure) + "\n*CLOAD\n2, 1, 1.\n*END STEP\n";
}

TEST(ReaderConventions, ParametersAndValuesMayBeAbbreviated) {
  const Model m = read(with_step("*STEP, NLGEO, AMP=STEP", "*STATIC, DIRECT\n0.5, 1."));
  ASSERT_EQ(m.steps.size(), 1u);
  EXPECT_TRUE(m.steps[0].nlgeom);
  EXPECT_TRUE(m.warnings.empty());
  // values: *OUTPUT, VARIABLE=PRESEL is PRESELECT
  const Model v = read(std::string(kTrussModel) +
                       "*STEP\n*STATIC\n*OUTPUT, FIELD, VARIABLE=PRESEL\n*END STEP\n");
  ASSERT_EQ(v.steps[0].field_outputs.size(), 1u);
  EXPECT_FALSE(v.steps[0].field_outputs[0].node_vars.empty());
  // too short, or not telling two apart: unknown as before
  EXPECT_CONTAINS(error_text(with_step("*STEP, NL", "*STATIC")), "NL");
  EXPECT_CONTAINS(error_text(std::string(kTrussModel) +
                             "*STEP\n*STATIC\n*OUTPUT, FIELD, VARIABLE=P\n*END STEP\n"),
                  "VARIABLE=P");
}

TEST(ReaderConventions, SystemRIsTheDefault) {
  std::string d(kTrussModel);
  d.replace(0, std::string_view("*NODE, NSET=ALL").size(), "*NODE, NSET=ALL, SYSTEM=R");
  EXPECT_EQ(read(d).mesh.n_nodes(), 2);
  d.replace(d.find("SYSTEM=R"), 8, "SYSTEM=C");
  EXPECT_CONTAINS(error_text(d), "SYSTEM=C");
}

TEST(ReaderConventions, ZeroNodeNormalsDefineNothingAndOthersAreAnError) {
  std::string d(kTrussModel);
  d.replace(d.find("2, 1., 0., 0."), 13, "2, 1., 0., , 0., , ");
  const Model m = read(d);
  EXPECT_DOUBLE_EQ(m.mesh.coords[1][0], 1.0);
  d = std::string(kTrussModel);
  d.replace(d.find("2, 1., 0., 0."), 13, "2, 1., 0., 0., 0., 0., 1.");
  EXPECT_CONTAINS(error_text(d), "deck.inp:3: *NODE: field 7: normals given on *NODE");
}

TEST(ReaderConventions, ABlankPoissonsRatioIsZero) {
  std::string d(kTrussModel);
  d.replace(d.find("200000., 0.3"), 12, "200000.,");
  const Model m = read(d);
  ASSERT_EQ(m.materials.size(), 1u);
  double E = 0.0, nu = 1.0;
  m.materials[0].elastic_at(20.0, E, nu);
  EXPECT_EQ(E, 200000.0);
  EXPECT_EQ(nu, 0.0);
  // Young's modulus stays required
  d.replace(d.find("200000.,"), 8, ", 0.3");
  EXPECT_CONTAINS(error_text(d), "Young's modulus E");
}

TEST(ReaderConventions, CalculixOptionsWithoutMeaningHereAreWarnings) {
  EXPECT_EQ(test::count_warnings(read(with_step("*STEP, INC=10, INCF=20", "*STATIC")), "INCF"), 1);
  for (const char* procedure : {"*STATIC, SOLVER=SPOOLES", "*DYNAMIC, SOLVER=PARDISO\n0.1, 1."}) {
    const Model m = read(with_step("*STEP", procedure));
    EXPECT_EQ(test::count_warnings(m, "CalculiX's choice of its linear solver"), 1) << procedure;
  }
}

} // namespace
} // namespace gapfem
