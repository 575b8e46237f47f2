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
  EXPECT_CONTAINS(error_text("*NODE\n1, 1., 2., 3., 4.\n"), "field 5: normals given on *NODE");
  EXPECT_CONTAINS(error_text("*NODE\n1, 1., 2., 3., 0., 0., 1., 9.\n"), "at most 7 fields");
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
                  "deck.inp:6: *ELEMENT: element 1: T3D2 needs 2 nodes but only 1 is given");
  EXPECT_CONTAINS(error_text(nodes + "*ELEMENT, TYPE=T3D2\n1, 1, 2, 3\n"),
                  "T3D2 needs 2 nodes but 3");
  EXPECT_CONTAINS(error_text(nodes + "*ELEMENT, TYPE=T3D2\n12, 1, 99\n"),
                  "deck.inp:6: *ELEMENT: element 12: node 99 is not defined; define it with *NODE");
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

TEST(ReaderMesh, ElementsAndNodeSetsMayNameNodesDefinedFurtherDown) {
  // Abaqus reads the model data in any order: an element or a node set may come before the *NODE
  // line of its nodes (the campaign's sem_gap_node_defined_later)
  const std::string later = "*NSET, NSET=GROUND\n11, 12\n*ELEMENT, TYPE=T3D2, ELSET=TRUSS\n1, 1, "
                            "2\n*ELEMENT, TYPE=GAPUNI, ELSET=GAP\n2, 2, 12\n*NODE, NSET=ALL\n1, "
                            "0., 0., 0.\n2, 1., 0., 0.\n*NODE\n11, 0., 0., -1.\n12, 1., 0., -1.\n"
                            "*MATERIAL, NAME=STEEL\n*ELASTIC\n200000., 0.3\n*SOLID SECTION, "
                            "ELSET=TRUSS, MATERIAL=STEEL\n1.\n*GAP, ELSET=GAP\n0., 0., 0., -1.\n";
  const Model m = read(later);
  ASSERT_EQ(m.mesh.n_nodes(), 4);
  auto coords_of = [&](Label label) { return m.mesh.coords[m.mesh.find_node(label)]; };
  EXPECT_EQ(coords_of(2), (Vec3{1.0, 0.0, 0.0}));
  EXPECT_EQ(coords_of(12), (Vec3{1.0, 0.0, -1.0}));
  const auto gap = m.mesh.element_nodes(m.mesh.find_element(2));
  EXPECT_EQ(m.mesh.node_labels[gap[1]], 12);
  ASSERT_EQ(m.nsets.at("GROUND").size(), 2u);
  EXPECT_EQ(m.nsets.at("ALL").size(), 2u); // NSET= on the *NODE that gives the coordinates
  // GENERATE ranges too
  EXPECT_EQ(read("*NSET, NSET=G, GENERATE\n1, 3\n*NODE\n1\n2\n3\n").nsets.at("G").size(), 3u);
  // other keywords need their nodes above them, and say so
  EXPECT_CONTAINS(error_text("*NODE\n1\n*BOUNDARY\n2, 1\n*NODE\n2\n"),
                  "deck.inp:4: *BOUNDARY: node 2: node 2 is defined further down, at deck.inp:6; "
                  "*BOUNDARY needs its nodes defined above it (only *ELEMENT and *NSET may name a "
                  "node defined further down): move that *NODE line up");
  EXPECT_CONTAINS(error_text("*NSET, NSET=A\n2\n*BOUNDARY\nA, 1\n*NODE\n2\n"),
                  "deck.inp:4: *BOUNDARY: node 2: node 2 is defined further down, at deck.inp:6");
  // a node defined nowhere, or only after the model data, is not defined
  EXPECT_CONTAINS(error_text("*ELEMENT, TYPE=T3D2\n1, 1, 2\n*NODE\n1\n"),
                  "deck.inp:2: *ELEMENT: element 1: node 2 is not defined; define it with *NODE");
  // a *NODE line in error that an element named above adds nothing more
  const std::string e = error_text("*ELEMENT, TYPE=T3D2\n1, 1, 2\n*NSET, NSET=S\n2\n*NODE\n1\n2, "
                                   "x\n*BOUNDARY\nS, 1\n");
  EXPECT_CONTAINS(e, "deck.inp:7: *NODE: field 2 (x)");
  EXPECT_EQ(e.find("input errors"), std::string::npos) << e;
}

TEST(ReaderMesh, AWrongKindOfNameIsSaidToBeOne) {
  const std::string m = std::string(kTrussModel) + "*STEP\n*STATIC\n";
  EXPECT_CONTAINS(error_text(m + "*CLOAD\nTRUSS, 1, 1.\n"),
                  "*CLOAD: TRUSS is an element set, not a node set; *CLOAD needs a node or a node "
                  "set here: list the nodes of element set TRUSS in an *NSET and name that set");
  EXPECT_CONTAINS(error_text(m + "*DLOAD\nALL, GRAV, 9.81, 0., 0., -1.\n"),
                  "*DLOAD: ALL is a node set, not an element set; *DLOAD needs an element or an "
                  "element set here");
  EXPECT_CONTAINS(error_text(m + "*NODE PRINT, NSET=TRUSS\nU\n"),
                  "*NODE PRINT: NSET=TRUSS: TRUSS is an element set, not a node set; *NODE PRINT "
                  "needs a node set here");
  EXPECT_CONTAINS(
      error_text(m + "*DSLOAD\nTRUSS, P, 1.\n"),
      "surface TRUSS: TRUSS is an element set, not a surface; *DSLOAD needs a surface of "
      "element faces here: define one with *SURFACE and name it");
}

TEST(ReaderMesh, PartNamesUsedOutsideTheirInstancesAreSaidToBe) {
  const std::string assembly = "*PART, NAME=P\n*ELEMENT, TYPE=T3D2, ELSET=E\n1, 1, 2\n*NODE\n1\n2, "
                               "1.\n*NSET, NSET=ENDS\n1, 2\n*SOLID SECTION, ELSET=E, "
                               "MATERIAL=STEEL\n1.\n*END PART\n*ASSEMBLY, NAME=A\n*INSTANCE, "
                               "NAME=I, PART=P\n*END INSTANCE\n*INSTANCE, NAME=J, PART=P\n0., 1."
                               "\n*END INSTANCE\n";
  const std::string end = "*END ASSEMBLY\n*MATERIAL, NAME=STEEL\n*ELASTIC\n200000., 0.3\n";
  // a part's element may name a node its *NODE lines define further down
  EXPECT_EQ(read(assembly + end).mesh.n_nodes(), 4);
  EXPECT_CONTAINS(
      error_text(assembly + "*NODE\n5\n*ELEMENT, TYPE=SPRINGA, ELSET=S\n9, 5, 2\n" + end),
      "*ELEMENT: element 9: node 2 is not an assembly node; a node of a part instance "
      "is named INSTANCE.node, e.g. I.2 or J.2");
  EXPECT_CONTAINS(
      error_text(assembly + "*NODE\n5\n*ELEMENT, TYPE=SPRINGA, ELSET=S\n9, 5, J.7\n" + end),
      "*ELEMENT: element 9: instance J (part P) has no node 7; check the number");
  EXPECT_CONTAINS(
      error_text(assembly + end + "*STEP\n*STATIC\n*BOUNDARY\nENDS, 1\n*END STEP\n"),
      "*BOUNDARY: node set ENDS is defined in part P; outside the part, name it through "
      "an instance, e.g. I.ENDS or J.ENDS");
  EXPECT_CONTAINS(error_text(assembly + end + "*STEP\n*STATIC\n*BOUNDARY\nE, 1\n*END STEP\n"),
                  "*BOUNDARY: E is an element set of part P, not a node set; *BOUNDARY needs a "
                  "node or a node set here");
}

} // namespace
} // namespace gapfem
