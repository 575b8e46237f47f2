// Abaqus's mesh generators *NGEN, *NFILL and *ELGEN and the local system *SYSTEM
// (io/inp/handlers_generate.cpp) against the
// nodes and elements written out by hand: straight lines, circular arcs (under and over 180
// degrees), parabolas, biased fills, rows/layers/planes of elements, and a whole analysis of a
// generated block against its expanded twin (the same displacements at every node).
#include "test_util.hpp"
#include "unit/io/reader_test_util.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace gapfem {
namespace {

using test::error_text;
using test::read;

constexpr double kPi = 3.14159265358979323846;

Vec3 at(const Model& m, Label node) {
  const NodeId n = m.mesh.find_node(node);
  EXPECT_GE(n, 0) << "node " << node;
  return n >= 0 ? m.mesh.coords[n] : Vec3{};
}

void expect_at(const Model& m, Label node, const Vec3& x) {
  const Vec3 got = at(m, node);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(got[i], x[i], 1e-12) << "node " << node << " [" << i << "]";
}

std::vector<Label> labels(const Model& m, const std::vector<NodeId>& set) {
  std::vector<Label> out;
  for (NodeId n : set) out.push_back(m.mesh.node_labels[n]);
  return out;
}

TEST(ReaderGenerate, NgenOnALine) {
  const Model m = read("*NODE\n1, 0., 0., 0.\n11, 10., 5., 0.\n*NGEN, NSET=LINE\n1, 11, 2\n");
  EXPECT_EQ(m.mesh.n_nodes(), 6);
  for (int k = 1; k <= 4; ++k) expect_at(m, 1 + 2 * k, {2.0 * k, 1.0 * k, 0.0});
  std::vector<Label> line = labels(m, m.nsets.at("LINE"));
  std::sort(line.begin(), line.end());
  EXPECT_EQ(line, (std::vector<Label>{1, 3, 5, 7, 9, 11}));
  // a decreasing increment walks from the first end down to the second
  const Model d = read("*NODE\n20, 0., 0., 0.\n10, 10., 0., 0.\n*NGEN\n20, 10, -5\n");
  expect_at(d, 15, {5.0, 0.0, 0.0});
}

TEST(ReaderGenerate, NgenOnCircularArcs) {
  // a quarter circle about node 100, its centre; then a half circle about the centre given by
  // coordinates, with the arc's normal (180 degrees: the plane needs it)
  const Model m = read("*NODE\n100, 0., 0., 0.\n1, 1., 0., 0.\n5, 0., 1., 0.\n11, 2., 0., 3.\n"
                       "15, -2., 0., 3.\n*NGEN, LINE=C\n1, 5, 1, 100\n11, 15, 1, , 0., 0., 3., "
                       "0., 0., -1.\n");
  for (int k = 1; k <= 3; ++k) {
    const double a = k * kPi / 8.0;
    expect_at(m, 1 + k, {std::cos(a), std::sin(a), 0.0});
  }
  // about -z from +x: through -y
  for (int k = 1; k <= 3; ++k) {
    const double a = -k * kPi / 4.0;
    expect_at(m, 11 + k, {2.0 * std::cos(a), 2.0 * std::sin(a), 3.0});
  }
  // a cylindrical centre (SYSTEM=C: r, theta, z): (sqrt 2, 45 degrees, 0) is (1, 1, 0)
  const Model c = read("*NODE\n1, 2., 1., 0.\n3, 1., 2., 0.\n*NGEN, LINE=C, SYSTEM=C\n"
                       "1, 3, 1, , 1.4142135623730951, 45., 0.\n");
  expect_at(c, 2, {1.0 + std::sqrt(0.5), 1.0 + std::sqrt(0.5), 0.0});
}

TEST(ReaderGenerate, NgenOnAParabola) {
  // ends (0, 0) and (4, 0), midpoint (2, 2): y = x (4 - x) / 2
  const Model m = read("*NODE\n1, 0., 0., 0.\n5, 4., 0., 0.\n*NGEN, LINE=P\n1, 5, 1, , 2., 2.\n");
  for (int k = 1; k <= 3; ++k) {
    const double x = k;
    expect_at(m, 1 + k, {x, x * (4 - x) / 2, 0.0});
  }
}

TEST(ReaderGenerate, NfillBetweenTwoNodeSets) {
  const std::string bounds = "*NODE\n1, 0., 0., 0.\n2, 0., 1., 0.\n41, 8., 0., 0.\n42, 8., 1., "
                             "0.\n*NSET, NSET=A\n1, 2\n*NSET, NSET=B\n41, 42\n";
  const Model m = read(bounds + "*NFILL, NSET=ALLN\nA, B, 4, 10\n");
  for (int k = 1; k <= 3; ++k) {
    expect_at(m, 1 + 10 * k, {2.0 * k, 0.0, 0.0});
    expect_at(m, 2 + 10 * k, {2.0 * k, 1.0, 0.0});
  }
  EXPECT_EQ(m.nsets.at("ALLN").size(), 10u);
  // a biased spacing is refused (which end a ratio favours is not settled), BIAS=1 is uniform
  EXPECT_CONTAINS(error_text(bounds + "*NFILL, BIAS=2.\nA, B, 4, 10\n"),
                  "BIAS=2.: biased node spacing is not supported by gapfem");
  expect_at(read(bounds + "*NFILL, BIAS=1.\nA, B, 4, 10\n"), 21, {4.0, 0.0, 0.0});
}

TEST(ReaderGenerate, ElgenRowsLayersAndPlanes) {
  // a 3 x 2 x 2 block of C3D8 from element 1 (nodes numbered i + 10 j + 100 k, 4 x 3 x 3)
  std::string nodes = "*NODE\n";
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i)
        nodes += fmt::format("{}, {}, {}, {}\n", 1 + i + 10 * j + 100 * k, i, j, k);
  const Model m = read(nodes + "*ELEMENT, TYPE=C3D8\n1, 1, 2, 12, 11, 101, 102, 112, 111\n"
                               "*ELGEN, ELSET=BLOCK\n1, 3, 1, 1, 2, 10, 10, 2, 100, 100\n"
                               "*SOLID SECTION, ELSET=BLOCK, MATERIAL=M\n*MATERIAL, NAME=M\n"
                               "*ELASTIC\n1., 0.3\n");
  EXPECT_EQ(m.mesh.n_elements(), 12);
  EXPECT_EQ(m.elsets.at("BLOCK").size(), 12u);
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) {
        const ElemId e = m.mesh.find_element(1 + i + 10 * j + 100 * k);
        ASSERT_GE(e, 0);
        EXPECT_EQ(m.mesh.elem_types[e], ElementType::C3D8);
        const int s = i + 10 * j + 100 * k;
        const std::vector<Label> want{1 + s,   2 + s,   12 + s,  11 + s,
                                      101 + s, 102 + s, 112 + s, 111 + s};
        std::vector<Label> got;
        for (NodeId n : m.mesh.element_nodes(e)) got.push_back(m.mesh.node_labels[n]);
        EXPECT_EQ(got, want) << "element " << 1 + s;
      }
}

TEST(ReaderGenerate, AGeneratedBlockGivesItsExpandedTwinsAnswer) {
  // the same cantilever block of 6 x 1 x 1 C3D8, once generated (*NGEN, *NFILL, *ELGEN) and once
  // written out; loaded at its free end: the displacements of every node agree (to round-off:
  // the node numbers are the same, their order in the mesh is not)
  const std::string tail = "*SOLID SECTION, ELSET=BAR, MATERIAL=M\n*MATERIAL, NAME=M\n*ELASTIC\n"
                           "1000., 0.3\n*NSET, NSET=FIX\n1, 2, 101, 102\n*NSET, NSET=TIP\n13, 14, "
                           "113, 114\n*BOUNDARY\nFIX, 1, 3\n*STEP\n*STATIC\n*CLOAD\nTIP, 3, "
                           "-0.25\n*END STEP\n";
  const std::string generated =
      "*NODE\n1, 0., 0., 0.\n13, 6., 0., 0.\n2, 0., 1., 0.\n14, 6., 1., 0.\n*NGEN, NSET=E1\n1, 13, "
      "2\n*NGEN, NSET=E2\n2, 14, 2\n*NODE\n101, 0., 0., 1.\n113, 6., 0., 1.\n102, 0., 1., 1.\n114, "
      "6., 1., 1.\n*NGEN, NSET=T1\n101, 113, 2\n*NGEN, NSET=T2\n102, 114, 2\n"
      "*ELEMENT, TYPE=C3D8\n1, 1, 3, 4, 2, 101, 103, 104, 102\n*ELGEN, ELSET=BAR\n1, 6, 2, 1\n" +
      tail;
  std::string written = "*NODE\n";
  for (int i = 0; i <= 6; ++i)
    for (int k = 0; k <= 1; ++k)
      for (int j = 0; j <= 1; ++j)
        written += fmt::format("{}, {}., {}., {}.\n", 1 + 2 * i + j + 100 * k, i, j, k);
  written += "*ELEMENT, TYPE=C3D8, ELSET=BAR\n";
  for (int i = 0; i < 6; ++i) {
    const int b = 1 + 2 * i;
    written += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", i + 1, b, b + 2, b + 3, b + 1,
                           b + 100, b + 102, b + 103, b + 101);
  }
  written += tail;
  const JobResult a = test::run_deck(generated), w = test::run_deck(written);
  ASSERT_EQ(a.exit_code, 0) << a.error;
  ASSERT_EQ(w.exit_code, 0) << w.error;
  const Frame* fa = a.step_end(1);
  const Frame* fw = w.step_end(1);
  ASSERT_TRUE(fa && fw);
  for (int i = 0; i <= 6; ++i)
    for (int k = 0; k <= 1; ++k)
      for (int j = 0; j <= 1; ++j) {
        const Label n = 1 + 2 * i + j + 100 * k;
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(test::U(a, *fa, n)[c], test::U(w, *fw, n)[c], 1e-12) << "node " << n;
      }
  EXPECT_LT(test::U(a, *fa, 14)[2], -1e-3); // it bends
}

TEST(ReaderGenerate, SystemGivesTheLaterNodesLocalCoordinates) {
  // a translation; then X1 toward (0, 1, 5) projected onto X-Y (Z kept): X1 = Y, Y1 = -X; then
  // X1 = Z through (1, 1, 1) with c on +X: Z1 = X1 x (c - a) = Y, Y1 = X; then global again
  const Model m = read("*SYSTEM\n10., 0., 0.\n*NODE\n1, 1., 2., 3.\n*SYSTEM\n0., 0., 0., 0., "
                       "1., 5.\n*NODE\n2, 1., 2., 3.\n*SYSTEM\n1., 1., 1., 1., 1., 2.\n2., 1., "
                       "1.\n*NODE\n3, 1., 2., 3.\n*SYSTEM\n*NODE\n4, 1., 2., 3.\n");
  expect_at(m, 1, {11.0, 2.0, 3.0});
  expect_at(m, 2, {-2.0, 1.0, 3.0});
  expect_at(m, 3, {3.0, 4.0, 2.0});
  expect_at(m, 4, {1.0, 2.0, 3.0});
  // an *NGEN extra point given by coordinates is entered in the system too
  const Model p = read("*SYSTEM\n0., 0., 1.\n*NODE\n1, 0., 0., -1.\n3, 2., 0., -1.\n"
                       "*NGEN, LINE=P\n1, 3, 1, , 1., 1., -1.\n");
  expect_at(p, 2, {1.0, 1.0, 0.0});
  EXPECT_CONTAINS(error_text("*SYSTEM\n0., 0., 0., 0., 0., 7.\n"),
                  "the points do not define the local axes");
}

TEST(ReaderGenerate, TimePointsAreAnOutputDefinition) {
  const Model m = read("*NODE\n1, 0., 0., 0.\n*TIME POINTS, NAME=T1\n0.1, 0.5, 1.\n");
  EXPECT_EQ(test::count_warnings(m, "*TIME POINTS is not supported by gapfem and was ignored"), 1);
}

TEST(ReaderGenerate, BadGeneratorLinesAreOneClearErrorEach) {
  EXPECT_CONTAINS(error_text("*NODE\n1, 0., 0., 0.\n*NGEN\n1, 9, 2\n"),
                  "deck.inp:4: *NGEN: node 9: the second end node is not defined above this line");
  EXPECT_CONTAINS(error_text("*NODE\n1, 0., 0., 0.\n10, 1., 0., 0.\n*NGEN\n1, 10, 2\n"),
                  "the end nodes 1 and 10 are not a whole positive number of increments 2 apart");
  EXPECT_CONTAINS(error_text("*NODE\n1, 0., 0., 0.\n5, 1., 0., 0.\n*NGEN, LINE=C\n1, 5\n"),
                  "LINE=C and LINE=P need an extra point");
  EXPECT_CONTAINS(error_text("*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=T3D2\n1, 1, "
                             "2\n*ELGEN\n1, 3, 1, 1\n"),
                  "*ELGEN: element 2: node 3 of this generated element is not defined");
  EXPECT_CONTAINS(error_text("*NODE\n1, 0., 0., 0.\n*ELGEN\n7, 3\n"),
                  "element 7: the master element is not defined above this line");
  EXPECT_CONTAINS(error_text("*NODE\n1, 0., 0., 0.\n*NSET, NSET=A\n1\n*NFILL\nA, B, 4\n"),
                  "node set B: this node set is not defined above this line");
  EXPECT_CONTAINS(error_text("*NODE\n1, 0., 0., 0.\n*NSET, NSET=A\n1\n*NFILL, TWO STEP\nA, A, "
                             "4\n"),
                  "TWO STEP");
}

} // namespace
} // namespace gapfem
