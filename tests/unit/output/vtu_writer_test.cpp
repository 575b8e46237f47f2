// VtuWriter: well-formed VTK XML UnstructuredGrid with raw appended data
// (UInt64 headers), values as handed over, and the .pvd collection.
#include "fe/shape_functions.hpp"
#include "output/vtu_writer.hpp"
#include "test_util.hpp"
#include "writer_fixture.hpp"

#include <cmath>
#include <cstring>
#include <map>
#include <regex>

namespace gapfem {
namespace {

using namespace testing_output;

/// A parsed .vtu file: the declared arrays and the raw appended section.
struct Vtu {
  struct ArrayDecl {
    std::string section; ///< PointData, CellData, Points, Cells
    std::string type;
    int components = 1;
    std::uint64_t offset = 0;
  };
  std::string header;
  std::map<std::string, ArrayDecl> arrays;
  std::string raw; ///< bytes after '_' up to the closing tag
  long points = -1, cells = -1;

  std::uint64_t block_size(const std::string& name) const {
    std::uint64_t n = 0;
    std::memcpy(&n, raw.data() + arrays.at(name).offset, sizeof n);
    return n;
  }
  template <typename T>
  std::vector<T> values(const std::string& name) const {
    const auto& a = arrays.at(name);
    const std::uint64_t n = block_size(name);
    std::vector<T> v(n / sizeof(T));
    std::memcpy(v.data(), raw.data() + a.offset + sizeof n, n);
    return v;
  }
};

Vtu parse_vtu(const std::filesystem::path& path) {
  const std::string text = read_file(path);
  Vtu v;
  const std::string open_tag = "<AppendedData encoding=\"raw\">";
  const auto app = text.find(open_tag);
  EXPECT_NE(app, std::string::npos);
  v.header = text.substr(0, app);
  const auto underscore = text.find('_', app + open_tag.size());
  const std::string close_tag = "\n  </AppendedData>\n</VTKFile>\n";
  EXPECT_EQ(text.substr(text.size() - close_tag.size()), close_tag);
  v.raw = text.substr(underscore + 1, text.size() - close_tag.size() - underscore - 1);

  std::smatch m;
  if (std::regex_search(v.header, m,
                        std::regex("NumberOfPoints=\"(\\d+)\" NumberOfCells=\"(\\d+)\""))) {
    v.points = std::stol(m[1]);
    v.cells = std::stol(m[2]);
  }
  // Walk the header line by line, tracking the enclosing section.
  std::string section;
  const std::regex sec("<(PointData|CellData|Points|Cells)[ >]");
  const std::regex arr("<DataArray type=\"(\\w+)\" Name=\"(\\w+)\"(?: "
                       "NumberOfComponents=\"(\\d+)\")?"
                       "[^>]* format=\"appended\" offset=\"(\\d+)\"/>");
  std::istringstream in(v.header);
  for (std::string line; std::getline(in, line);) {
    if (std::regex_search(line, m, sec)) section = m[1];
    if (std::regex_search(line, m, arr)) {
      Vtu::ArrayDecl d;
      d.section = section;
      d.type = m[1];
      d.components = m[3].matched ? std::stoi(m[3]) : 1;
      d.offset = std::stoull(m[4]);
      v.arrays[m[2]] = d;
    }
  }
  return v;
}

std::size_t type_size(const std::string& t) {
  if (t == "Float64" || t == "Int64" || t == "UInt64") return 8;
  if (t == "Int32" || t == "Float32") return 4;
  if (t == "UInt8" || t == "Int8") return 1;
  ADD_FAILURE() << "unexpected type " << t;
  return 0;
}

TEST(OutputVtu, WellFormedAndSizesAddUp) {
  const Model m = make_model();
  const auto dir = fresh_dir();
  VtuWriter w(dir, "wt");
  run_standard(w, m);
  const Vtu v = parse_vtu(dir / "wt_1_2.vtu");
  EXPECT_NE(v.header.find("<VTKFile type=\"UnstructuredGrid\" version=\"1.0\""), std::string::npos);
  EXPECT_NE(v.header.find("header_type=\"UInt64\""), std::string::npos);
  // The file names the element type ids it uses (the values of gapfem's ElementType, listed in
  // docs/results.md).
  EXPECT_NE(v.header.find("element_type ids: 6=C3D8 15=GAPUNI\n"), std::string::npos);
  EXPECT_EQ(v.points, 9);
  EXPECT_EQ(v.cells, 2);
  // Each block: 8-byte size header + tuples * components * type size, blocks
  // back to back, the last one ending where the appended section ends.
  // Connectivity has 8 + 2 = 10 entries.
  std::vector<std::pair<std::uint64_t, std::uint64_t>> extents; // (offset, end)
  for (const auto& [name, a] : v.arrays) {
    std::uint64_t tuples = 0;
    if (a.section == "PointData" || a.section == "Points")
      tuples = 9;
    else if (a.section == "CellData")
      tuples = 2;
    else if (name == "connectivity")
      tuples = 10;
    else
      tuples = 2; // offsets, types
    const std::uint64_t expected = tuples * a.components * type_size(a.type);
    ASSERT_LT(a.offset + 8, v.raw.size() + 1) << name;
    EXPECT_EQ(v.block_size(name), expected) << name;
    extents.emplace_back(a.offset, a.offset + 8 + expected);
  }
  std::sort(extents.begin(), extents.end());
  ASSERT_FALSE(extents.empty());
  EXPECT_EQ(extents.front().first, 0u);
  for (std::size_t k = 1; k < extents.size(); ++k)
    EXPECT_EQ(extents[k].first, extents[k - 1].second);
  EXPECT_EQ(extents.back().second, v.raw.size());
  for (const char* name :
       {"U", "RF", "element_label", "element_type", "S", "E", "gap_status", "gap_clearance",
        "gap_pressure", "Points", "connectivity", "offsets", "types"})
    EXPECT_TRUE(v.arrays.count(name)) << name;
  EXPECT_FALSE(v.arrays.count("NT")) << "no temperature in this model";
}

TEST(OutputVtu, ValuesAndTopology) {
  const Model m = make_model();
  const auto dir = fresh_dir();
  VtuWriter w(dir, "wt");
  run_standard(w, m);
  const Vtu v = parse_vtu(dir / "wt_1_2.vtu");
  const auto u = v.values<double>("U");
  ASSERT_EQ(u.size(), 27u);
  for (int n = 0; n < 9; ++n) {
    const Vec3 e = disp(kNodeLabels[n], 1.0);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(u[3 * n + c], e[c]);
  }
  EXPECT_EQ(v.values<double>("Points")[3 * 8 + 2], 1.1); // node 5 at z = 1.1
  EXPECT_EQ(v.values<std::int32_t>("connectivity"),
            (std::vector<std::int32_t>{0, 1, 2, 3, 4, 5, 6, 7, 4, 8}));
  EXPECT_EQ(v.values<std::int64_t>("offsets"), (std::vector<std::int64_t>{8, 10}));
  EXPECT_EQ(v.values<std::uint8_t>("types"), (std::vector<std::uint8_t>{12, 3})); // hex, line
  EXPECT_EQ(v.values<std::int64_t>("element_label"), (std::vector<std::int64_t>{7, 3}));
  EXPECT_EQ(v.values<std::int32_t>("element_type"),
            (std::vector<std::int32_t>{static_cast<int>(ElementType::C3D8),
                                       static_cast<int>(ElementType::GAPUNI)}));
  // S of the brick: point averages 45 + c. S of the gap (S11 S12 S13 = 50 2 0)
  // lands in the Voigt slots 11, 12, 13 = 0, 3, 4; the slots it does not have
  // are 0.
  const auto s = v.values<double>("S");
  for (int c = 0; c < 6; ++c) EXPECT_DOUBLE_EQ(s[c], 45.0 + c);
  EXPECT_EQ(std::vector<double>(s.begin() + 6, s.end()),
            (std::vector<double>{50.0, 0.0, 0.0, 2.0, 0.0, 0.0}));
  // Gap status: -1 for the brick, Stick (2) for the gap; clearance NaN for the
  // brick.
  EXPECT_EQ(v.values<std::int32_t>("gap_status"), (std::vector<std::int32_t>{-1, 2}));
  const auto h = v.values<double>("gap_clearance");
  EXPECT_TRUE(std::isnan(h[0]));
  EXPECT_EQ(h[1], 0.0);
  EXPECT_EQ(v.values<double>("gap_pressure")[1], 50.0);

  // Frame 1 has no element output for the brick: its S is NaN.
  const Vtu v1 = parse_vtu(dir / "wt_1_1.vtu");
  EXPECT_TRUE(std::isnan(v1.values<double>("S")[0]));
  EXPECT_EQ(v1.values<double>("S")[6], 50.0);
}

TEST(OutputVtu, PvdListsFrames) {
  const Model m = make_model();
  const auto dir = fresh_dir();
  VtuWriter w(dir, "wt");
  w.begin(m);
  w.begin_step(m, 0);
  w.frame(m, 0, make_frame(m, 1, 0.5, false));
  // The collection is rewritten after each frame.
  std::string pvd = read_file(dir / "wt.pvd");
  EXPECT_NE(pvd.find("<DataSet timestep=\"0.5\" group=\"\" part=\"0\" "
                     "file=\"wt_1_1.vtu\"/>"),
            std::string::npos);
  EXPECT_EQ(pvd.find("wt_1_2.vtu"), std::string::npos);
  Frame no_field = make_frame(m, 2, 0.75, false);
  no_field.field_due = false;
  w.frame(m, 0, no_field);
  w.frame(m, 0, make_frame(m, 3, 1.0, true));
  w.frame(m, 0, make_frame(m, 3, 1.0, true)); // a failed step repeats its last increment
  w.end(m, make_run());
  pvd = read_file(dir / "wt.pvd");
  EXPECT_NE(pvd.find("<VTKFile type=\"Collection\""), std::string::npos);
  EXPECT_NE(pvd.find("timestep=\"1\" group=\"\" part=\"0\" file=\"wt_1_3.vtu\""),
            std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "wt_1_2.vtu")) << "no field output due";
  std::size_t n_sets = 0;
  for (auto p = pvd.find("<DataSet"); p != std::string::npos; p = pvd.find("<DataSet", p + 1))
    ++n_sets;
  EXPECT_EQ(n_sets, 2u); // wt_1_1.vtu and wt_1_3.vtu, the repeated frame listed once
  EXPECT_NE(pvd.find("</Collection>\n</VTKFile>"), std::string::npos);
}

TEST(OutputVtu, CellTypes) {
  EXPECT_EQ(vtk_cell_type(ElementType::C3D8, 8), 12);
  EXPECT_EQ(vtk_cell_type(ElementType::DC3D8, 8), 12);
  EXPECT_EQ(vtk_cell_type(ElementType::C3D4, 4), 10);
  EXPECT_EQ(vtk_cell_type(ElementType::C3D10, 10), 24);
  EXPECT_EQ(vtk_cell_type(ElementType::CPS3, 3), 5);
  EXPECT_EQ(vtk_cell_type(ElementType::CAX4, 4), 9);
  EXPECT_EQ(vtk_cell_type(ElementType::DC2D4, 4), 9);
  EXPECT_EQ(vtk_cell_type(ElementType::T3D2, 2), 3);
  EXPECT_EQ(vtk_cell_type(ElementType::B31, 2), 3);
  EXPECT_EQ(vtk_cell_type(ElementType::GAPUNI, 2), 3);
  EXPECT_EQ(vtk_cell_type(ElementType::SPRING2, 2), 3);
  EXPECT_EQ(vtk_cell_type(ElementType::SPRING1, 1), 1);
  EXPECT_EQ(vtk_cell_type(ElementType::B21, 2), 3);
  EXPECT_EQ(vtk_cell_type(ElementType::PIPE31, 2), 3);
  // three-node beams (end, middle, end) are VTK quadratic edges (end, end, middle)
  for (ElementType t : {ElementType::B32, ElementType::B22, ElementType::PIPE32}) {
    EXPECT_EQ(vtk_cell_type(t, 3), 21);
    EXPECT_EQ(vtk_node_from_abaqus(t, 0), 0);
    EXPECT_EQ(vtk_node_from_abaqus(t, 1), 2);
    EXPECT_EQ(vtk_node_from_abaqus(t, 2), 1);
  }
}

// Quadratic and wedge cells: VTK's cell types, and the node order written for them puts every
// midside node at the middle of the VTK edge it belongs to (vtkQuadraticHexahedron, -Wedge, -Quad:
// corners, then the edges listed below). VTK's wedges are oriented the other way round from
// Abaqus's (vtkWedge: the right-hand normal of (0, 1, 2) points away from (3, 4, 5)).
TEST(OutputVtu, QuadraticAndWedgeNodeOrders) {
  EXPECT_EQ(vtk_cell_type(ElementType::C3D20R, 20), 25);
  EXPECT_EQ(vtk_cell_type(ElementType::C3D15, 15), 26);
  EXPECT_EQ(vtk_cell_type(ElementType::C3D6, 6), 13);
  EXPECT_EQ(vtk_cell_type(ElementType::CAX8R, 8), 23);
  EXPECT_EQ(vtk_cell_type(ElementType::CPS6, 6), 22);
  struct Case {
    ElementType type;
    std::vector<std::array<int, 2>> edges;
  };
  const std::vector<Case> cases = {
      {ElementType::C3D20,
       {{0, 1},
        {1, 2},
        {2, 3},
        {3, 0},
        {4, 5},
        {5, 6},
        {6, 7},
        {7, 4},
        {0, 4},
        {1, 5},
        {2, 6},
        {3, 7}}},
      {ElementType::C3D15,
       {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}, {0, 3}, {1, 4}, {2, 5}}},
      {ElementType::CPS8, {{0, 1}, {1, 2}, {2, 3}, {3, 0}}},
      {ElementType::CAX6, {{0, 1}, {1, 2}, {2, 0}}}};
  for (const Case& c : cases) {
    const auto xi = shape_node_coords(*element_info(c.type).cell);
    auto at = [&](int vtk) {
      return xi[static_cast<std::size_t>(vtk_node_from_abaqus(c.type, vtk))];
    };
    const int corners = static_cast<int>(xi.size() - c.edges.size());
    for (std::size_t e = 0; e < c.edges.size(); ++e)
      for (int k = 0; k < 3; ++k)
        EXPECT_DOUBLE_EQ(at(corners + static_cast<int>(e))[k],
                         0.5 * (at(c.edges[e][0])[k] + at(c.edges[e][1])[k]))
            << element_info(c.type).name << " edge " << e;
  }
  for (ElementType t : {ElementType::C3D6, ElementType::C3D15}) {
    const auto xi = shape_node_coords(*element_info(t).cell);
    auto at = [&](int vtk) { return xi[static_cast<std::size_t>(vtk_node_from_abaqus(t, vtk))]; };
    const auto a = at(0), b = at(1), c = at(2), top = at(3);
    const double n[3] = {(b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
                         (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
                         (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])};
    EXPECT_LT(n[0] * (top[0] - a[0]) + n[1] * (top[1] - a[1]) + n[2] * (top[2] - a[2]), 0.0);
  }
}

// C3D10 nodes in Abaqus order: corners 1-4, then mid-edge nodes of edges 1-2,
// 2-3, 3-1, 1-4, 2-4, 3-4 (Abaqus element library). VTK_QUADRATIC_TETRA expects
// mid-edge nodes of edges (0,1), (1,2), (2,0), (0,3), (1,3), (2,3)
// (vtkQuadraticTetra documentation). Written points must sit at the midpoints
// of the VTK edges.
TEST(OutputVtu, QuadraticTetraNodeOrder) {
  Model m;
  m.job_name = "tet";
  const std::vector<Vec3> corners = {{0, 0, 0}, {2, 0, 0}, {0, 3, 0}, {0, 0, 5}};
  const int abaqus_edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  std::vector<Vec3> x = corners;
  for (const auto& e : abaqus_edges) {
    Vec3 mid;
    for (int c = 0; c < 3; ++c) mid[c] = 0.5 * (corners[e[0]][c] + corners[e[1]][c]);
    x.push_back(mid);
  }
  for (int i = 0; i < 10; ++i) {
    m.mesh.node_labels.push_back(100 + i);
    m.mesh.coords.push_back(x[i]);
    m.mesh.node_index[100 + i] = i;
  }
  m.mesh.elem_labels = {1};
  m.mesh.elem_types = {ElementType::C3D10};
  m.mesh.conn = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  m.mesh.conn_offset = {0, 10};
  m.mesh.elem_src = {{0, 1}};
  m.mesh.elem_index[1] = 0;
  Frame fr;
  fr.step = fr.increment = 1;
  fr.field_due = true;
  fr.element_slot = {-1};

  const auto dir = fresh_dir();
  VtuWriter w(dir, "tet");
  w.begin(m);
  w.frame(m, 0, fr);
  const Vtu v = parse_vtu(dir / "tet_1_1.vtu");
  const auto conn = v.values<std::int32_t>("connectivity");
  const auto pts = v.values<double>("Points");
  ASSERT_EQ(conn.size(), 10u);
  EXPECT_EQ(v.values<std::uint8_t>("types")[0], 24);
  const int vtk_edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  for (int k = 0; k < 6; ++k)
    for (int c = 0; c < 3; ++c) {
      const double a = pts[3 * conn[vtk_edges[k][0]] + c], b = pts[3 * conn[vtk_edges[k][1]] + c];
      EXPECT_EQ(pts[3 * conn[4 + k] + c], 0.5 * (a + b)) << "VTK edge " << k;
    }
  EXPECT_FALSE(v.arrays.count("U")) << "no nodal results in this frame";
}

} // namespace
} // namespace gapfem

namespace gapfem {
namespace {

TEST(OutputVtu, ShellsShowBothSides) {
  // a strip of two S4R bent by an end moment: the section average S11 is zero, the SNEG and
  // SPOS sides (section points 1 and 5) carry -/+ the bending stress M / (t^2 / 6) per width
  const std::string deck =
      "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 2, 0, 0\n4, 0, 1, 0\n5, 1, 1, 0\n6, 2, 1, 0\n"
      "*ELEMENT, TYPE=S4R, ELSET=S\n1, 1, 2, 5, 4\n2, 2, 3, 6, 5\n*MATERIAL, NAME=M\n*ELASTIC\n"
      "210000., 0.3\n*SHELL SECTION, ELSET=S, MATERIAL=M\n0.1, 5\n*BOUNDARY\n1, ENCASTRE\n"
      "4, ENCASTRE\n*STEP\n*STATIC\n*CLOAD\n3, 5, 0.5\n6, 5, 0.5\n*END STEP\n";
  const JobResult r = test::run_deck(deck, true);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  const Vtu v = parse_vtu(test::test_dir() / "job_1_1.vtu");
  ASSERT_EQ(v.arrays.count("S_SNEG"), 1u);
  ASSERT_EQ(v.arrays.count("E_SPOS"), 1u);
  EXPECT_EQ(v.arrays.at("S_SPOS").components, 6);
  const auto neg = v.values<double>("S_SNEG"), pos = v.values<double>("S_SPOS");
  const auto avg = v.values<double>("S");
  const double sigma = 1.0 / (0.1 * 0.1 / 6.0); // M = 1 over width 1
  for (int e = 0; e < 2; ++e) {
    EXPECT_NEAR(std::abs(neg[6 * e]), sigma, 1e-6 * sigma);
    EXPECT_NEAR(pos[6 * e], -neg[6 * e], 1e-9 * sigma);
    EXPECT_NEAR(avg[6 * e], 0.0, 1e-9 * sigma);
  }
  // the JSON results carry the same sides next to the average
  const std::string json = read_file(test::test_dir() / "job.results.json");
  EXPECT_NE(json.find("\"S_SNEG\":["), std::string::npos);
  EXPECT_NE(json.find("\"E_SPOS\":["), std::string::npos);
}

// A predefined temperature (stress analysis): one rule everywhere. NT is reported at the nodes of
// the elements that read the field (the truss) — in job.dat, the JSON and the VTU — and nowhere
// else: the gap's ground node has no temperature (VTU NaN, no JSON key, no .dat row), and there is
// no RFL (no temperature DOF).
TEST(OutputVtu, PredefinedTemperatureIsReportedWhereElementsReadIt) {
  const std::string deck =
      "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, -0.1, 0\n"
      "*ELEMENT, TYPE=T3D2, ELSET=BAR\n1, 1, 2\n*ELEMENT, TYPE=GAPUNI, ELSET=G\n2, 2, 3\n"
      "*SOLID SECTION, ELSET=BAR, MATERIAL=M\n0.01\n*MATERIAL, NAME=M\n*ELASTIC\n2e11, 0.3\n"
      "*EXPANSION\n1e-5\n*GAP, ELSET=G\n0.5, 0., -1., 0.\n*INITIAL CONDITIONS, TYPE=TEMPERATURE\n"
      "1, 20.\n2, 20.\n*BOUNDARY\n1, 1, 3\n2, 2, 3\n3, 1, 3\n*STEP\n*STATIC\n*TEMPERATURE\n"
      "1, 120.\n2, 120.\n*NODE PRINT\nNT\n*END STEP\n";
  const JobResult r = test::run_deck(deck, true);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  const Vtu v = parse_vtu(test::test_dir() / "job_1_1.vtu");
  ASSERT_EQ(v.arrays.count("NT"), 1u);
  EXPECT_EQ(v.arrays.count("RFL"), 0u);
  const auto nt = v.values<double>("NT");
  ASSERT_EQ(nt.size(), 3u);
  EXPECT_DOUBLE_EQ(nt[0], 120.0);
  EXPECT_DOUBLE_EQ(nt[1], 120.0);
  EXPECT_TRUE(std::isnan(nt[2]));
  const std::string json = read_file(test::test_dir() / "job.results.json");
  EXPECT_NE(json.find("\"1\":{\"U\":[0,0,0],\"RF\":"), std::string::npos) << json.substr(0, 800);
  EXPECT_NE(json.find("\"NT\":120"), std::string::npos);
  EXPECT_EQ(json.find("\"RFL\""), std::string::npos);
  const auto n3 = json.find("\"3\":{");
  ASSERT_NE(n3, std::string::npos);
  EXPECT_EQ(json.substr(n3, json.find('}', n3) - n3).find("NT"), std::string::npos);
  const std::string dat = read_file(test::test_dir() / "job.dat");
  EXPECT_EQ(dat.find("NO NODE OF THIS SET CARRIES NT"), std::string::npos);
  EXPECT_NE(dat.find("          2      1.2000E+02"), std::string::npos) << dat;
  EXPECT_EQ(dat.find("          3      "), std::string::npos);
}

/// A B31 cantilever of 2 elements along x (RECT a = 10 along n1 = -z, b = 20 along n2 = +y) with a
/// GAPUNI support under its tip (clearance 0.5, open under these loads), loaded by `loads`.
std::string cantilever(const std::string& output, const std::string& loads) {
  return "*NODE, NSET=ALLN\n1, 0, 0, 0\n2, 50, 0, 0\n3, 100, 0, 0\n4, 100, -1, 0\n"
         "*NSET, NSET=TIP\n3\n*ELEMENT, TYPE=B31, ELSET=BEAM\n1, 1, 2\n2, 2, 3\n"
         "*ELEMENT, TYPE=GAPUNI, ELSET=G\n3, 3, 4\n*MATERIAL, NAME=M\n*ELASTIC\n200000., 0.3\n"
         "*BEAM SECTION, ELSET=BEAM, MATERIAL=M, SECTION=RECT\n10., 20.\n0., 0., -1.\n"
         "*GAP, ELSET=G\n0.5, 0., -1., 0., 1.\n*BOUNDARY\n1, ENCASTRE\n4, 1, 3\n"
         "*STEP\n*STATIC\n*CLOAD\n" +
         loads + output + "*END STEP\n";
}

TEST(OutputVtu, FieldRequestsChooseTheArrays) {
  // *NODE OUTPUT CF and *ELEMENT OUTPUT SF only: no U, RF, S or E in the frame, CF and SF/SM are
  const JobResult r = test::run_deck(
      cantilever("*OUTPUT, FIELD\n*NODE OUTPUT\nCF\n*ELEMENT OUTPUT\nSF\n", "3, 2, -10.\n"), true);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  const Vtu v = parse_vtu(test::test_dir() / "job_1_1.vtu");
  for (const char* absent : {"U", "RF", "UR", "RM", "S", "E"})
    EXPECT_EQ(v.arrays.count(absent), 0u) << absent;
  ASSERT_EQ(v.arrays.count("CF"), 1u);
  ASSERT_EQ(v.arrays.count("SF"), 1u);
  ASSERT_EQ(v.arrays.count("SM"), 1u);
  EXPECT_EQ(v.header.find("Vectors=\"U\""), std::string::npos); // no U to warp by
  const auto cf = v.values<double>("CF");
  EXPECT_DOUBLE_EQ(cf[3 * 2 + 1], -10.0); // node 3, y
  EXPECT_DOUBLE_EQ(cf[3 * 1 + 1], 0.0);
  // the tip moves 10 L^3 / (3 E I11) = 0.0025 < 0.5: the gap stays open and both elements carry
  // the shear 10
  const auto sf = v.values<double>("SF"), sm = v.values<double>("SM");
  ASSERT_EQ(sf.size(), 6u * 3u);
  ASSERT_EQ(sm.size(), 3u * 3u);
  EXPECT_NEAR(std::abs(sf[6 * 0 + 1]), 10.0, 1e-9); // SF2: shear along n2 = +y
  EXPECT_TRUE(std::isnan(sf[6 * 2]));               // the gap has no section forces
  // gap arrays are always there
  EXPECT_EQ(v.arrays.count("gap_status"), 1u);
}

TEST(OutputVtu, NodeOutputOnASetIsNaNElsewhere) {
  const JobResult r = test::run_deck(
      cantilever("*OUTPUT, FIELD\n*NODE OUTPUT, NSET=TIP\nU\n*NODE OUTPUT\nRF\n", "3, 2, -10.\n"),
      true);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  const Vtu v = parse_vtu(test::test_dir() / "job_1_1.vtu");
  const auto u = v.values<double>("U"), rf = v.values<double>("RF");
  for (int n : {0, 1, 3}) EXPECT_TRUE(std::isnan(u[3 * n + 1])) << "node index " << n;
  EXPECT_LT(u[3 * 2 + 1], 0.0);   // the tip moves down
  EXPECT_NEAR(rf[1], 10.0, 1e-9); // RF everywhere: the root carries the load
  EXPECT_FALSE(std::isnan(rf[3 * 1 + 1]));
}

TEST(OutputVtu, VelocityAndAccelerationInGlobalComponents) {
  // a dynamic bar along x whose free node has a *TRANSFORM (local 1 = y, local 2 = -x): the frame
  // and job.dat hold V and A in that system, the VTU in global components, like U
  const std::string deck = R"(*NODE
1, 0., 0., 0.
2, 1., 0., 0.
*NSET, NSET=TIP
2
*TRANSFORM, NSET=TIP
0., 1., 0., -1., 0., 0.
*ELEMENT, TYPE=T3D2, ELSET=BAR
1, 1, 2
*MATERIAL, NAME=M
*ELASTIC
1000., 0.
*DENSITY
2.
*SOLID SECTION, ELSET=BAR, MATERIAL=M
0.5
*BOUNDARY
1, 1, 3
2, 1, 1
2, 3, 3
*STEP
*DYNAMIC, DIRECT, ALPHA=0.
0.01, 0.02
*CLOAD
2, 2, -5.
*OUTPUT, FIELD
*NODE OUTPUT
U, V, A
*END STEP
)";
  const JobResult r = test::run_deck(deck, true);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  const Frame& f = test::last_frame(r);
  const NodeId tip = r.model->mesh.find_node(2);
  ASSERT_EQ(f.nodes.V.size(), 2u);
  const Vec3 v_local = f.nodes.V[tip], a_local = f.nodes.A[tip];
  EXPECT_LT(v_local[1], 0.0); // pulled along +x = -local 2
  EXPECT_EQ(v_local[0], 0.0);
  const Vtu v = parse_vtu(test::test_dir() / "job_1_2.vtu");
  for (const char* absent : {"RF", "VR", "AR"}) EXPECT_EQ(v.arrays.count(absent), 0u) << absent;
  const auto vel = v.values<double>("V"), acc = v.values<double>("A"), u = v.values<double>("U");
  ASSERT_EQ(vel.size(), 6u);
  EXPECT_DOUBLE_EQ(vel[3 * tip], -v_local[1]);
  EXPECT_DOUBLE_EQ(vel[3 * tip + 1], v_local[0]);
  EXPECT_DOUBLE_EQ(acc[3 * tip], -a_local[1]);
  EXPECT_DOUBLE_EQ(acc[3 * tip + 1], a_local[0]);
  EXPECT_DOUBLE_EQ(u[3 * tip], -f.nodes.U[tip][1]);
  EXPECT_GT(vel[3 * tip], 0.0);
}

TEST(OutputVtu, BeamStressIsTheExtremeFibre) {
  // pure bending by a tip moment M = 1e5 about global y = n2: the section average of S11 is 0;
  // the extreme fibre, a/2 from the axis along n1, carries S11 = M (a/2) / I22, I22 = b a^3 / 12
  const JobResult r = test::run_deck(cantilever("", "3, 5, 1.e5\n"), true);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  const Vtu v = parse_vtu(test::test_dir() / "job_1_1.vtu");
  const auto S = v.values<double>("S");
  const double a = 10.0, b = 20.0, I22 = b * a * a * a / 12.0, sigma = 1e5 * (a / 2) / I22;
  for (int e = 0; e < 2; ++e) EXPECT_NEAR(std::abs(S[6 * e]), sigma, 1e-6 * sigma) << e;
  ASSERT_EQ(v.arrays.count("SM"), 1u); // SF and SM in the default frame too
  const auto sm = v.values<double>("SM");
  EXPECT_NEAR(std::abs(sm[3 * 0 + 1]), 1e5, 1e-6 * 1e5); // SM2: about n2
  // the JSON results list the beam's section points: the four corners, +/- sigma
  const std::string json = read_file(test::test_dir() / "job.results.json");
  const auto at = json.find("\"S_POINTS\":[[");
  ASSERT_NE(at, std::string::npos) << json.substr(0, 2000);
  const double s1 = std::stod(json.substr(at + 13));
  EXPECT_NEAR(std::abs(s1), sigma, 1e-6 * sigma);
}

} // namespace
} // namespace gapfem
