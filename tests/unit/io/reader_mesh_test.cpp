// Mesh keywords: *HEADING, *PREPRINT, *NODE, *ELEMENT, *NSET/*ELSET errors, *SURFACE.
#include "unit/io/reader_test_util.hpp"

namespace gapfem {
namespace {

using test::error_text;
using test::kTrussModel;
using test::read;

constexpr std::string_view kBrick = R"(*NODE
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
*MATERIAL, NAME=M
*ELASTIC
1000., 0.25
*SOLID SECTION, ELSET=B, MATERIAL=M
)";

TEST(ReaderMesh, HeadingAndPreprint) {
  const Model m =
      read("*HEADING\n  Gap test  \nsecond line\n*PREPRINT, ECHO=NO, MODEL=NO\n*NODE\n1\n");
  EXPECT_EQ(m.heading, "Gap test\nsecond line");
  ASSERT_EQ(m.warnings.size(), 1u); // a print control: accepted with a note
  EXPECT_CONTAINS(m.warnings[0], "*PREPRINT controls Abaqus's printed or results-file output");
  EXPECT_EQ(m.job_name, "");
  EXPECT_EQ(m.source_files.at(0), "deck.inp");
}

TEST(ReaderMesh, NodesWithTwoOrThreeCoordinatesAndNset) {
  const Model m = read("*NODE, NSET=N\n1, 1., 2.\n2, 1., 2., 3.\n");
  EXPECT_EQ(m.mesh.coords[0], (Vec3{1.0, 2.0, 0.0}));
  EXPECT_EQ(m.mesh.coords[1], (Vec3{1.0, 2.0, 3.0}));
  EXPECT_EQ(m.nsets.at("N").size(), 2u);
  EXPECT_EQ(m.initial_temperature.size(), 2u);
}

TEST(ReaderMesh, NodeErrors) {
  EXPECT_CONTAINS(error_text("*NODE, SYSTEM=C\n1, 1., 2.\n"), "deck.inp:1: *NODE: SYSTEM=C");
  EXPECT_CONTAINS(
      error_text("*NODE\n1\n1, 2.\n"),
      "deck.inp:3: *NODE: node 1: this node number is defined twice (first at deck.inp:2)");
  EXPECT_CONTAINS(
      error_text("*NODE\n0, 1.\n"),
      "deck.inp:2: *NODE: field 1 (node number): 0 is out of range: node and element numbers run "
      "from 1 to 999999999");
  EXPECT_CONTAINS(error_text("*NODE\nA, 1.\n"), "field 1 (node number): 'A' is not a whole number");
  EXPECT_CONTAINS(error_text("*NODE\n1, 1., 2., 3., 4.\n"), "at most 4 fields");
}

TEST(ReaderMesh, ElementWithoutDataLinesIsRemarked) {
  const Model m = read(std::string(kBrick) + "*ELEMENT, TYPE=C3D8, ELSET=EMPTY\n");
  EXPECT_EQ(test::count_warnings(
                m, "deck.inp:16: *ELEMENT: TYPE=C3D8: this *ELEMENT has no data lines and defines "
                   "no elements"),
            1);
  EXPECT_EQ(test::count_warnings(read(kBrick), "no data lines"), 0);
}

TEST(ReaderMesh, ElementsKeepLabelsTypesAndLocations) {
  const Model m = read(kBrick);
  ASSERT_EQ(m.mesh.n_elements(), 1);
  EXPECT_EQ(m.mesh.elem_types[0], ElementType::C3D8);
  EXPECT_EQ(m.mesh.element_nodes(0).size(), 8u);
  EXPECT_EQ(m.element_location(0).str(), "deck.inp:11 (*ELEMENT)");
  EXPECT_EQ(m.space, ModelSpace::ThreeD);
}

TEST(ReaderMesh, ElementErrors) {
  const std::string nodes = "*NODE\n1\n2\n3\n";
  EXPECT_CONTAINS(error_text(nodes + "*ELEMENT, ELSET=E\n1, 1, 2\n"),
                  "the parameter TYPE= is required");
  {
    const std::string e = error_text(nodes + "*ELEMENT, TYPE=C3D27\n1, 1, 2\n*ELSET, ELSET=X\n1\n");
    EXPECT_CONTAINS(e, "deck.inp:5: *ELEMENT: TYPE=C3D27: gapfem does not know this element type");
    EXPECT_CONTAINS(e, "GAPUNI"); // the list of supported types
    EXPECT_EQ(e.find("ELSET"), std::string::npos) << "no follow-up error for element 1:\n" << e;
  }
  EXPECT_CONTAINS(error_text(nodes + "*ELEMENT, TYPE=T3D2\n1, 1\n"),
                  "deck.inp:6: *ELEMENT: element 1: T3D2 needs 2 nodes but 1 are given");
  EXPECT_CONTAINS(error_text(nodes + "*ELEMENT, TYPE=T3D2\n1, 1, 2, 3\n"),
                  "T3D2 needs 2 nodes but 3");
  EXPECT_CONTAINS(error_text(nodes + "*ELEMENT, TYPE=T3D2\n12, 1, 99\n"),
                  "deck.inp:6: *ELEMENT: element 12: node 99 is not defined; define it with *NODE "
                  "before use");
  EXPECT_CONTAINS(error_text(nodes + "*ELEMENT, TYPE=T3D2\n1, 1, 2\n1, 2, 3\n"),
                  "deck.inp:7: *ELEMENT: element 1: this element number is defined twice (first at "
                  "deck.inp:6)");
  EXPECT_CONTAINS(error_text(nodes + "*ELEMENT, TYPE=T3D2\n-4, 1, 2\n"),
                  "field 1 (element number): -4 is out of range");
}

TEST(ReaderMesh, SetReferencesToUndefinedLabels) {
  EXPECT_CONTAINS(error_text("*NODE\n1\n*NSET, NSET=A\n1, 2\n"),
                  "deck.inp:4: *NSET: node 2: this node is not defined");
  EXPECT_CONTAINS(error_text("*NODE\n1\n*ELSET, ELSET=A\n5\n"),
                  "deck.inp:4: *ELSET: element 5: this element is not defined");
  EXPECT_CONTAINS(error_text("*NODE\n1\n*NSET\n1\n"), "the parameter NSET= is required");
}

TEST(ReaderMesh, FailedNodeDoesNotCascade) {
  // node 2 has a bad coordinate: the element using it and the set naming it add no more errors
  const std::string e =
      error_text("*NODE\n1\n2, x\n*ELEMENT, TYPE=T3D2, ELSET=E\n1, 1, 2\n*NSET, NSET=S\n2\n");
  EXPECT_CONTAINS(e, "deck.inp:3: *NODE: field 2 (x)");
  EXPECT_EQ(e.find("not defined"), std::string::npos) << e;
}

TEST(ReaderMesh, SurfaceFacesPerElementType) {
  const Model m =
      read(std::string(kBrick) + "*ELSET, ELSET=ALLB\n1\n*SURFACE, NAME=Top\n1, S2\nALLB, s6\n");
  const Surface& s = m.surfaces.at("TOP");
  ASSERT_EQ(s.faces.size(), 2u);
  EXPECT_EQ(s.faces[0].face, 2);
  EXPECT_EQ(s.faces[1].face, 6);
  EXPECT_EQ(s.faces[1].elem, 0);
}

TEST(ReaderMesh, SurfaceErrors) {
  const std::string b(kBrick);
  EXPECT_CONTAINS(error_text(b + "*SURFACE, NAME=S\n1, S7\n"),
                  "deck.inp:17: *SURFACE: element 1 (C3D8): face S7 does not exist; this element "
                  "type has faces S1-S6");
  EXPECT_CONTAINS(error_text(b + "*SURFACE, NAME=S\n1, P2\n"), "face 'P2'");
  EXPECT_CONTAINS(error_text(b + "*SURFACE, NAME=S, TYPE=NODE\n1, -1.\n"),
                  "deck.inp:17: *SURFACE: field 2 (area): the area (weight) of a surface node "
                  "must be positive");
  EXPECT_CONTAINS(error_text(b + "*SURFACE, NAME=S, TYPE=NODE\n1\n*SURFACE, NAME=S\n1, S1\n"),
                  "surface S: the surface is already defined as node-based");
  EXPECT_CONTAINS(error_text(std::string(kTrussModel) + "*SURFACE, NAME=S\n1, S1\n"),
                  "element 1 (T3D2): this element type has no faces");
  // faces of tetrahedra, quads and triangles
  const std::string tet = "*NODE\n1\n2,1\n3,0,1\n4,0,0,1\n*ELEMENT, TYPE=C3D4\n1,1,2,3,4\n"
                          "*SURFACE, NAME=S\n1, S5\n";
  EXPECT_CONTAINS(error_text(tet), "faces S1-S4");
  const std::string tri =
      "*NODE\n1\n2,1\n3,0,1\n*ELEMENT, TYPE=CPS3\n1,1,2,3\n*SURFACE, NAME=S\n1, S4\n";
  EXPECT_CONTAINS(error_text(tri), "faces S1-S3");
  const std::string quad = "*NODE\n1\n2,1\n3,1,1\n4,0,1\n*ELEMENT, TYPE=CPE4\n1,1,2,3,4\n"
                           "*SURFACE, NAME=S\n1, S5\n";
  EXPECT_CONTAINS(error_text(quad), "faces S1-S4");
}

} // namespace
} // namespace gapfem
