// Element faces in the reader (S1..Sn, Pn, Fn) against the element kernels: for every element type
// the face counts of io/inp n_faces() are exactly the faces the kernel accepts for pressure and for
// heat loads, and the ends of the heat-conducting links (DC1D2, T2D2T, T3D2T) take S1/S2, F1/F2.
#include "elements/element_kernel.hpp"
#include "fe/shape_functions.hpp"
#include "io/inp/model_builder.hpp"
#include "unit/io/reader_test_util.hpp"

#include <fmt/format.h>

namespace gapfem {
namespace {

using test::error_text;
using test::read;

/// Node coordinates for a one-element model of `info` (x >= 1, so axisymmetric radii are
/// positive): a unit hexahedron, a tetrahedron (with mid-edge nodes for 10 nodes), a unit square,
/// a triangle, a link along x, or a single node.
std::string nodes_for(const ElementTypeInfo& info) {
  const bool solid3d = info.space == SpaceRequirement::ThreeD &&
                       info.family != ElementFamily::Truss && info.family != ElementFamily::Beam;
  std::vector<std::array<double, 3>> x;
  if (info.cell && shape_dim(*info.cell) >= 2) {
    // the reference cell under x = (1.5, 0, 0) + xi / 2 (positive Jacobian, x >= 1)
    for (const auto& xi : shape_node_coords(*info.cell))
      x.push_back({1.5 + 0.5 * xi[0], 0.5 * xi[1], 0.5 * xi[2]});
  } else
    switch (info.n_nodes) {
    case 1:
      x = {{1, 0, 0}};
      break;
    case 2:
      x = {{1, 0, 0}, {2, 0, 0}};
      break;
    case 3:
      x = {{1, 0, 0}, {2, 0, 0}, {1, 1, 0}};
      break;
    case 4:
      x = solid3d ? std::vector<std::array<double, 3>>{{1, 0, 0}, {2, 0, 0}, {1, 1, 0}, {1, 0, 1}}
                  : std::vector<std::array<double, 3>>{{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}};
      break;
    case 8:
      x = {{1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 0, 1}, {2, 0, 1}, {2, 1, 1}, {1, 1, 1}};
      break;
    case 10: // corners, then the midpoints of edges 1-2, 2-3, 3-1, 1-4, 2-4, 3-4
      x = {{1, 0, 0},     {2, 0, 0},   {1, 1, 0},   {1, 0, 1},     {1.5, 0, 0},
           {1.5, 0.5, 0}, {1, 0.5, 0}, {1, 0, 0.5}, {1.5, 0, 0.5}, {1, 0.5, 0.5}};
      break;
    default:
      ADD_FAILURE() << info.name << ": no coordinates for " << info.n_nodes << " nodes";
    }
  std::string deck = "*NODE\n";
  std::string conn = "1";
  for (std::size_t i = 0; i < x.size(); ++i) {
    deck += fmt::format("{}, {}, {}, {}\n", i + 1, x[i][0], x[i][1], x[i][2]);
    conn += fmt::format(", {}", i + 1);
  }
  deck += fmt::format("*ELEMENT, TYPE={}, ELSET=E\n{}\n", info.name, conn);
  return deck;
}

/// Property keywords that make a one-element model of `info` valid.
std::string property_for(const ElementTypeInfo& info) {
  const std::string material = "*MATERIAL, NAME=M\n*ELASTIC\n200000., 0.3\n*CONDUCTIVITY\n50.\n"
                               "*DENSITY\n7.8e-9\n*SPECIFIC HEAT\n4.6e8\n*EXPANSION\n1.2e-5\n";
  switch (info.family) {
  case ElementFamily::Spring: { // (and the dashpots, which take *DASHPOT with the same lines)
    const ElementType t = info.type;
    const std::string dofs = t == ElementType::SPRING1 || t == ElementType::DASHPOT1   ? "1"
                             : t == ElementType::SPRING2 || t == ElementType::DASHPOT2 ? "1, 1"
                                                                                       : "";
    const bool dashpot =
        t == ElementType::DASHPOT1 || t == ElementType::DASHPOT2 || t == ElementType::DASHPOTA;
    return std::string(dashpot ? "*DASHPOT" : "*SPRING") + ", ELSET=E\n" + dofs + "\n100.\n";
  }
  case ElementFamily::Beam:
    if (info.type == ElementType::PIPE31 || info.type == ElementType::PIPE32)
      return material + "*BEAM SECTION, ELSET=E, MATERIAL=M, SECTION=PIPE\n1., 0.1\n";
    return material + "*BEAM SECTION, ELSET=E, MATERIAL=M, SECTION=RECT\n1., 2.\n0., 0., -1.\n";
  case ElementFamily::Shell:
    return material + "*SHELL SECTION, ELSET=E, MATERIAL=M\n0.1\n";
  case ElementFamily::Mass:
    return info.type == ElementType::MASS ? "*MASS, ELSET=E\n1.\n"
                                          : "*ROTARY INERTIA, ELSET=E\n1., 1., 1.\n";
  case ElementFamily::Gap:
    // GAPCYL needs an axis (z), GAPSPHER a non-zero diameter; the others a direction (x).
    return info.type == ElementType::GAPCYL ? "*GAP, ELSET=E\n0.1, 0., 0., 1., 1.\n"
                                            : "*GAP, ELSET=E\n0.1, 1., 0., 0., 1.\n";
  default:
    return material + "*SOLID SECTION, ELSET=E, MATERIAL=M\n1.\n";
  }
}

// The reader's face counts must be the faces the kernel accepts: a larger count would pass loads
// the kernel ignores, a smaller one would reject loads the kernel supports. The kernel is built
// from a one-element deck of each type (the same route as the analysis: reader, then
// make_element_kernel with the element's property).
TEST(ReaderFaces, FaceCountsMatchTheKernelsForEveryElementType) {
  for (const ElementTypeInfo& info : all_element_types()) {
    if (info.n_nodes == 0) continue; // user elements and substructures: no faces (their own tests)
    SCOPED_TRACE(std::string(info.name));
    const Model m = read(nodes_for(info) + property_for(info));
    ASSERT_EQ(m.mesh.n_elements(), 1);
    const ElemId elems[] = {0};
    const auto kernel = make_element_kernel(
        KernelContext{m, info.type, m.element_property.at(0), std::span<const ElemId>(elems)});
    ASSERT_NE(kernel, nullptr);
    const int n_pressure = inp::n_faces(info.type, inp::FaceUse::Pressure);
    const int n_thermal = inp::n_faces(info.type, inp::FaceUse::Thermal);
    EXPECT_EQ(inp::n_faces(info.type), std::max(n_pressure, n_thermal));
    // Faces 1..9 are the labels the reader can parse (face_of in handlers_loads.cpp).
    for (int face = 1; face <= 9; ++face) {
      EXPECT_EQ(kernel->supports_load(DistLoadKind::Pressure, face), face <= n_pressure)
          << "P" << face;
      EXPECT_EQ(kernel->supports_load(DistLoadKind::SurfaceFlux, face), face <= n_thermal)
          << "S" << face;
      EXPECT_EQ(kernel->supports_load(DistLoadKind::Film, face), face <= n_thermal) << "F" << face;
    }
  }
}

/// A DC1D2 link (nodes 1-2) and a T3D2T link (nodes 2-3) with their material and sections.
constexpr std::string_view kLinks = R"(*NODE
1, 0., 0., 0.
2, 1., 0., 0.
3, 2., 0., 0.
*ELEMENT, TYPE=DC1D2, ELSET=H
1, 1, 2
*ELEMENT, TYPE=T3D2T, ELSET=C
2, 2, 3
*MATERIAL, NAME=M
*ELASTIC
200000., 0.3
*CONDUCTIVITY
50.
*SOLID SECTION, ELSET=H, MATERIAL=M
2.
*SOLID SECTION, ELSET=C, MATERIAL=M
3.
*SURFACE, NAME=ENDS
1, S1
2, S2
)";
// kLinks has 20 lines; after "*STEP\n*COUPLED TEMPERATURE-DISPLACEMENT\n" the next keyword is on
// line 23 and its first data line on line 24

TEST(ReaderFaces, LinkEndsTakeSurfaceFluxesAndFilms) {
  const Model m = read(std::string(kLinks) + R"(*STEP
*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE
*DFLUX
1, S2, 3.
2, S1, 4.
*FILM
1, F1, 20., 5.
2, F2, 30., 6.
*DSFLUX
ENDS, S, 7.
*SFILM
ENDS, F, 40., 8.
*END STEP
)");
  const auto& surf = m.surfaces.at("ENDS");
  ASSERT_EQ(surf.faces.size(), 2u);
  EXPECT_EQ(surf.faces[0].face, 1);
  EXPECT_EQ(surf.faces[1].face, 2);
  const auto& d = m.steps[0].dloads;
  ASSERT_EQ(d.size(), 8u);
  // *DFLUX and *FILM in input order, then the surface loads face by face.
  const std::pair<DistLoadKind, int> expected[] = {
      {DistLoadKind::SurfaceFlux, 2}, {DistLoadKind::SurfaceFlux, 1},
      {DistLoadKind::Film, 1},        {DistLoadKind::Film, 2},
      {DistLoadKind::SurfaceFlux, 1}, {DistLoadKind::SurfaceFlux, 2},
      {DistLoadKind::Film, 1},        {DistLoadKind::Film, 2}};
  for (std::size_t i = 0; i < d.size(); ++i) {
    EXPECT_EQ(d[i].kind, expected[i].first) << i;
    EXPECT_EQ(d[i].face, expected[i].second) << i;
  }
}

TEST(ReaderFaces, LinkEndErrors) {
  const std::string deck = std::string(kLinks) + "*STEP\n*COUPLED TEMPERATURE-DISPLACEMENT\n";
  auto err = [&](std::string lines) { return error_text(deck + lines + "\n*END STEP\n"); };
  // A link has two ends.
  EXPECT_CONTAINS(err("*DFLUX\n1, S3, 1."),
                  "deck.inp:24: *DFLUX: element 1 (DC1D2): face 3 does not exist; this element "
                  "type has faces 1-2");
  EXPECT_CONTAINS(err("*FILM\n2, F3, 20., 5."),
                  "element 2 (T3D2T): face 3 does not exist; this element type has faces 1-2");
  // The ends of a coupled truss take heat loads, not pressures.
  EXPECT_CONTAINS(err("*DLOAD\n2, P1, 1."),
                  "deck.inp:24: *DLOAD: element 2 (T3D2T): the faces of this element type take "
                  "heat fluxes and films only");
  EXPECT_CONTAINS(err("*DSLOAD\nENDS, P, 1."), "element 1 (DC1D2): this element has no "
                                               "displacement DOFs");
  const std::string only_truss = std::string(kLinks) + "*SURFACE, NAME=TEND\n2, S1\n*STEP\n"
                                                       "*COUPLED TEMPERATURE-DISPLACEMENT\n";
  EXPECT_CONTAINS(error_text(only_truss + "*DSLOAD\nTEND, P, 1.\n*END STEP\n"),
                  "element 2 (T3D2T): the faces of this element type take heat fluxes and films "
                  "only");
  EXPECT_CONTAINS(error_text(std::string(kLinks) + "*SURFACE, NAME=BAD\n1, S3\n"),
                  "element 1 (DC1D2): face S3 does not exist; this element type has faces S1-S2");
}

} // namespace
} // namespace gapfem
