#include "output/vtu_writer.hpp"

#include "common/error.hpp"
#include "model/model.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <system_error>

namespace gapfem {
namespace {

static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles");
static_assert(std::endian::native == std::endian::little ||
              std::endian::native == std::endian::big);

constexpr std::string_view kByteOrder =
    std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// One data array of the appended section.
struct Array {
  std::string_view name;
  std::string_view type; ///< VTK type name
  int components = 1;
  const void* data = nullptr;
  std::size_t bytes = 0;
  std::string_view component_names; ///< pre-formatted ComponentName attributes, or empty
};

constexpr std::string_view kVoigt =
    R"( ComponentName0="11" ComponentName1="22" ComponentName2="33" ComponentName3="12" ComponentName4="13" ComponentName5="23")";

void declare(fmt::memory_buffer& b, const Array& a, std::uint64_t& offset) {
  fmt::format_to(fmt::appender(b), "        <DataArray type=\"{}\" Name=\"{}\"", a.type, a.name);
  if (a.components > 1)
    fmt::format_to(fmt::appender(b), " NumberOfComponents=\"{}\"", a.components);
  b.append(a.component_names);
  fmt::format_to(fmt::appender(b), " format=\"appended\" offset=\"{}\"/>\n", offset);
  offset += sizeof(std::uint64_t) + a.bytes;
}

template <typename T>
Array make_array(std::string_view name, std::string_view type, int comps, const std::vector<T>& v) {
  return Array{name, type, comps, v.data(), v.size() * sizeof(T), {}};
}

} // namespace

int vtk_cell_type(ElementType type, int n_nodes) {
  const auto& info = element_info(type);
  if (info.cell && n_nodes == shape_n_nodes(*info.cell)) {
    switch (*info.cell) {
    case Shape::Line2:
      return 3; // VTK_LINE
    case Shape::Line3:
      return 21; // VTK_QUADRATIC_EDGE
    case Shape::Tri3:
      return 5; // VTK_TRIANGLE
    case Shape::Tri6:
      return 22; // VTK_QUADRATIC_TRIANGLE
    case Shape::Quad4:
      return 9; // VTK_QUAD
    case Shape::Quad8:
      return 23; // VTK_QUADRATIC_QUAD
    case Shape::Tet4:
      return 10; // VTK_TETRA
    case Shape::Tet10:
      return 24; // VTK_QUADRATIC_TETRA
    case Shape::Wedge6:
      return 13; // VTK_WEDGE
    case Shape::Wedge15:
      return 26; // VTK_QUADRATIC_WEDGE
    case Shape::Hex8:
      return 12; // VTK_HEXAHEDRON
    case Shape::Hex20:
      return 25; // VTK_QUADRATIC_HEXAHEDRON
    }
  }
  if (info.family == ElementFamily::Beam && n_nodes == 3) return 21; // VTK_QUADRATIC_EDGE
  switch (n_nodes) {
  case 1:
    return 1; // VTK_VERTEX (SPRING1, grounded gap)
  case 2:
    return 3; // VTK_LINE (springs, gaps)
  default:
    return 0;
  }
}

int vtk_node_from_abaqus(ElementType type, int vtk_index) {
  // VTK's wedges have the opposite orientation of Abaqus's (the right-hand normal of the first
  // triangle points out of the cell); every other cell shares the Abaqus node order
  static constexpr int kWedge[15] = {0, 2, 1, 3, 5, 4, 8, 7, 6, 11, 10, 9, 12, 14, 13};
  const auto& info = element_info(type);
  const auto cell = info.cell;
  if (cell && (*cell == Shape::Wedge6 || *cell == Shape::Wedge15) && vtk_index < 15)
    return kWedge[vtk_index];
  // three-node beams are end, middle, end; VTK's quadratic edge is end, end, middle
  if (info.family == ElementFamily::Beam && info.n_nodes == 3 && vtk_index < 3)
    return std::array<int, 3>{0, 2, 1}[vtk_index];
  return vtk_index;
}

VtuWriter::VtuWriter(std::filesystem::path directory, std::string job)
    : _dir(std::move(directory)), _job(std::move(job)) {}

/// The values at section point `k` of a block (averaged over the integration points), in the
/// Voigt slots of element `e` of `target` (zeros in components the block does not have).
static void add_side(const OutputBlock& block, int k, std::size_t e, std::vector<double>& target) {
  std::vector<double> avg;
  output::average_section_point(block, k, avg);
  std::fill_n(target.begin() + 6 * e, 6, 0.0);
  for (std::size_t c = 0; c < block.names.size(); ++c)
    if (const int slot = output::voigt_slot(block.names[c]); slot >= 0)
      target[6 * e + slot] = avg[c];
}

void VtuWriter::begin(const Model& model) {
  const Mesh& mesh = model.mesh;
  const auto ne = static_cast<std::size_t>(mesh.n_elements());
  _entries.clear();
  _connectivity.clear();
  _connectivity.reserve(mesh.conn.size());
  _offsets.resize(ne);
  _cell_types.resize(ne);
  _type_ids.resize(ne);
  if (!model.instances.empty()) {
    _elem_local.resize(ne);
    _elem_instance.resize(ne);
    for (std::size_t e = 0; e < ne; ++e) {
      _elem_local[e] = key_local(mesh.elem_labels[e]);
      _elem_instance[e] = key_instance(mesh.elem_labels[e]);
    }
    const std::size_t nn = mesh.node_labels.size();
    _node_local.resize(nn);
    _node_instance.resize(nn);
    for (std::size_t n = 0; n < nn; ++n) {
      _node_local[n] = key_local(mesh.node_labels[n]);
      _node_instance[n] = key_instance(mesh.node_labels[n]);
    }
  }
  _has_gaps = false;
  std::vector<bool> present(all_element_types().size(), false);
  for (std::size_t e = 0; e < ne; ++e) {
    const ElementType type = mesh.elem_types[e];
    const auto nodes = mesh.element_nodes(static_cast<ElemId>(e));
    // Extra nodes beyond the element's own (e.g. a beam orientation node) are not drawn.
    const int n = std::min(static_cast<int>(nodes.size()), element_info(type).n_nodes);
    const int cell = vtk_cell_type(type, n);
    FE_CHECK(cell != 0, fmt::format("no VTK cell for element {} ({} with {} nodes)",
                                    mesh.elem_labels[e], element_info(type).name, n));
    for (int i = 0; i < n; ++i) _connectivity.push_back(nodes[vtk_node_from_abaqus(type, i)]);
    _offsets[e] = static_cast<std::int64_t>(_connectivity.size());
    _cell_types[e] = static_cast<std::uint8_t>(cell);
    _type_ids[e] = static_cast<std::int32_t>(type);
    _has_gaps |= element_info(type).family == ElementFamily::Gap;
    present[static_cast<std::size_t>(type)] = true;
  }
  _type_legend.clear();
  for (std::size_t t = 0; t < present.size(); ++t)
    if (present[t])
      _type_legend += fmt::format(" {}={}", t, element_info(static_cast<ElementType>(t)).name);
  write_pvd();
}

void VtuWriter::frame(const Model& model, int step_index, const Frame& frame) {
  if (!frame.field_due) return;
  const Mesh& mesh = model.mesh;
  const auto nn = static_cast<std::size_t>(mesh.n_nodes());
  const auto ne = static_cast<std::size_t>(mesh.n_elements());
  const NodeResults& r = frame.nodes;

  // Cell data: point averages of S, E, HFL in Voigt slots; gap status,
  // clearance, pressure.
  _S.assign(6 * ne, kNaN);
  _E.assign(6 * ne, kNaN);
  _HFL.assign(3 * ne, kNaN);
  bool any_S = false, any_E = false, any_HFL = false, any_sides = false;
  for (auto* side : {&_S_neg, &_S_pos, &_E_neg, &_E_pos}) side->assign(6 * ne, kNaN);
  if (_has_gaps) {
    _gap_status.assign(ne, -1);
    _gap_clearance.assign(ne, kNaN);
    _gap_pressure.assign(ne, kNaN);
  }
  for (const ElementResult& res : frame.elements) {
    if (res.elem < 0 || static_cast<std::size_t>(res.elem) >= ne) continue;
    const auto e = static_cast<std::size_t>(res.elem);
    for (const OutputBlock& block : res.data.blocks) {
      if (block.var == ElemVar::SF) continue;
      if (block.section_points > 1 && (block.var == ElemVar::S || block.var == ElemVar::E) &&
          element_info(mesh.elem_types[res.elem]).family == ElementFamily::Shell) {
        const bool stress = block.var == ElemVar::S;
        add_side(block, 0, e, stress ? _S_neg : _E_neg);
        add_side(block, block.section_points - 1, e, stress ? _S_pos : _E_pos);
        any_sides = true;
      }
      output::average_block(block, _avg);
      for (std::size_t c = 0; c < block.names.size(); ++c) {
        const std::string_view name = block.names[c];
        if (block.var == ElemVar::HFL) {
          if (name.size() == 4 && name.substr(0, 3) == "HFL" && name[3] >= '1' && name[3] <= '3') {
            if (std::isnan(_HFL[3 * e])) std::fill_n(_HFL.begin() + 3 * e, 3, 0.0);
            _HFL[3 * e + static_cast<std::size_t>(name[3] - '1')] = _avg[c];
            any_HFL = true;
          }
          continue;
        }
        const int slot = output::voigt_slot(name);
        if (slot < 0) continue;
        auto& target = block.var == ElemVar::S ? _S : _E;
        // An element that reports the tensor gets zeros in the components it
        // does not have.
        if (std::isnan(target[6 * e])) std::fill_n(target.begin() + 6 * e, 6, 0.0);
        target[6 * e + slot] = _avg[c];
        (block.var == ElemVar::S ? any_S : any_E) = true;
      }
    }
    if (_has_gaps && res.data.gap) {
      _gap_status[e] = static_cast<std::int32_t>(res.data.gap->status);
      _gap_clearance[e] = res.data.gap->clearance;
      _gap_pressure[e] = res.data.gap->pressure;
    }
  }

  std::vector<Array> point_arrays;
  auto vec_point = [&](std::string_view name, const std::vector<Vec3>& v) {
    if (v.size() == nn)
      point_arrays.push_back(Array{name, "Float64", 3, v.data(), nn * sizeof(Vec3), {}});
  };
  auto scalar_point = [&](std::string_view name, const std::vector<double>& v) {
    if (v.size() == nn) point_arrays.push_back(make_array(name, "Float64", 1, v));
  };
  // ParaView warps and colours by global components: vectors at *TRANSFORM nodes go back from
  // their local systems (v_global = Q^T v_local)
  std::vector<Vec3> U = r.U, RF = r.RF, UR = r.UR, RM = r.RM;
  for (const auto& entry : r.local_axes)
    for (auto* v : {&U, &RF, &UR, &RM})
      if (static_cast<std::size_t>(entry.first) < v->size())
        (*v)[entry.first] = r.global(entry.first, (*v)[entry.first]);
  vec_point("U", U);
  vec_point("RF", RF);
  if (r.any_rotation) {
    vec_point("UR", UR);
    vec_point("RM", RM);
  }
  // heat-transfer shells: NT12 … through the thickness; a node with fewer temperatures shows its
  // last one (a solid's single temperature), so colour maps stay continuous
  static const std::array<std::string, kMaxTemperaturePoints> kNtNames = [] {
    std::array<std::string, kMaxTemperaturePoints> a;
    for (int k = 0; k < kMaxTemperaturePoints; ++k) a[k] = fmt::format("NT{}", 11 + k);
    return a;
  }();
  const int n_points = std::clamp(r.temperature_points, 1, kMaxTemperaturePoints);
  std::vector<std::vector<double>> nt_more(static_cast<std::size_t>(n_points - 1));
  // a predefined field (stress analysis) is NT at the nodes of the elements that read it and NaN
  // elsewhere (ground nodes of gaps have no temperature); it has no RFL
  std::vector<double> nt_field;
  if (r.any_temperature && !r.nt_field.empty()) {
    nt_field = r.NT;
    for (std::size_t n = 0; n < nt_field.size() && n < r.nt_field.size(); ++n)
      if (!r.nt_field[n]) nt_field[n] = std::numeric_limits<double>::quiet_NaN();
    scalar_point("NT", nt_field);
  }
  if (r.any_temperature && r.nt_field.empty()) {
    scalar_point("NT", r.NT);
    scalar_point("RFL", r.RFL);
    for (int k = 1; k < n_points && r.NT_more.size() == nn * (n_points - 1); ++k) {
      auto& v = nt_more[k - 1];
      v.resize(nn);
      for (std::size_t n = 0; n < nn; ++n) {
        const int have = r.temperatures_at(static_cast<NodeId>(n));
        const int j = std::min(k, have - 1);
        v[n] = j <= 0 ? r.NT[n] : r.NT_more[(n_points - 1) * n + j - 1];
      }
      scalar_point(kNtNames[k], v);
    }
  }

  std::vector<Array> cell_arrays;
  if (_elem_local.empty()) {
    cell_arrays.push_back(make_array("element_label", "Int64", 1, mesh.elem_labels));
  } else { // labels in their parts, and the instance (1-based, in the order of the deck)
    cell_arrays.push_back(make_array("element_label", "Int64", 1, _elem_local));
    cell_arrays.push_back(make_array("instance", "Int32", 1, _elem_instance));
    point_arrays.push_back(make_array("node_label", "Int64", 1, _node_local));
    point_arrays.push_back(make_array("node_instance", "Int32", 1, _node_instance));
  }
  cell_arrays.push_back(make_array("element_type", "Int32", 1, _type_ids));
  if (any_S) {
    cell_arrays.push_back(make_array("S", "Float64", 6, _S));
    cell_arrays.back().component_names = kVoigt;
  }
  if (any_E) {
    cell_arrays.push_back(make_array("E", "Float64", 6, _E));
    cell_arrays.back().component_names = kVoigt;
  }
  if (any_sides) { // shells: their SNEG and SPOS sides (section points 1 and n)
    const std::pair<std::string_view, const std::vector<double>*> sides[] = {
        {"S_SNEG", &_S_neg}, {"S_SPOS", &_S_pos}, {"E_SNEG", &_E_neg}, {"E_SPOS", &_E_pos}};
    for (const auto& [name, v] : sides) {
      cell_arrays.push_back(make_array(name, "Float64", 6, *v));
      cell_arrays.back().component_names = kVoigt;
    }
  }
  if (any_HFL) cell_arrays.push_back(make_array("HFL", "Float64", 3, _HFL));
  if (_has_gaps) {
    cell_arrays.push_back(make_array("gap_status", "Int32", 1, _gap_status));
    cell_arrays.push_back(make_array("gap_clearance", "Float64", 1, _gap_clearance));
    cell_arrays.push_back(make_array("gap_pressure", "Float64", 1, _gap_pressure));
  }
  const Array points{"Points", "Float64", 3, mesh.coords.data(), nn * sizeof(Vec3), {}};
  const std::vector<Array> cells = {make_array("connectivity", "Int32", 1, _connectivity),
                                    make_array("offsets", "Int64", 1, _offsets),
                                    make_array("types", "UInt8", 1, _cell_types)};

  const std::string file = fmt::format("{}_{}_{}.vtu", _job, frame.step, frame.increment);
  output::OutputFile out; // written aside and renamed: a frame file is complete or absent
  out.open(_dir / file, output::OutputFile::Mode::Replace);
  auto& b = out.buffer();
  std::uint64_t offset = 0;
  fmt::format_to(fmt::appender(b),
                 "<?xml version=\"1.0\"?>\n"
                 "<!-- gapfem {}: step {} increment {}, step time {}, total time {}.\n"
                 "     element_type ids:{}\n"
                 "     gap_status: -1 not a gap, 0 open, 1 closed, 2 stick, 3 slip -->\n"
                 "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"{}\" "
                 "header_type=\"UInt64\">\n  <UnstructuredGrid>\n    <FieldData>\n"
                 "      <DataArray type=\"Float64\" Name=\"TimeValue\" "
                 "NumberOfTuples=\"1\" "
                 "format=\"ascii\">{}</DataArray>\n    </FieldData>\n"
                 "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n",
                 GAPFEM_VERSION, frame.step, frame.increment, frame.step_time, frame.total_time,
                 _type_legend, kByteOrder, frame.total_time, nn, ne);
  b.append(std::string_view(point_arrays.empty() ? "      <PointData>\n"
                                                 : "      <PointData Vectors=\"U\">\n"));
  for (const auto& a : point_arrays) declare(b, a, offset);
  b.append(std::string_view("      </PointData>\n      <CellData Scalars=\"element_label\">\n"));
  for (const auto& a : cell_arrays) declare(b, a, offset);
  b.append(std::string_view("      </CellData>\n      <Points>\n"));
  declare(b, points, offset);
  b.append(std::string_view("      </Points>\n      <Cells>\n"));
  for (const auto& a : cells) declare(b, a, offset);
  b.append(std::string_view("      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n"
                            "  <AppendedData encoding=\"raw\">\n   _"));
  auto emit = [&](const Array& a) {
    const std::uint64_t n = a.bytes;
    out.write_bytes(&n, sizeof n);
    out.write_bytes(a.data, a.bytes);
  };
  for (const auto& a : point_arrays) emit(a);
  for (const auto& a : cell_arrays) emit(a);
  emit(points);
  for (const auto& a : cells) emit(a);
  out.write("\n  </AppendedData>\n</VTKFile>\n");
  out.close();

  // A step that stops early repeats its last converged increment as the final frame: the file
  // is rewritten, and listed once.
  auto same = std::find_if(_entries.begin(), _entries.end(),
                           [&](const PvdEntry& e) { return e.file == file; });
  if (same != _entries.end())
    same->time = frame.total_time;
  else
    _entries.push_back(PvdEntry{frame.total_time, file});
  write_pvd();
}

void VtuWriter::write_pvd() {
  output::OutputFile out; // replaced whole: the collection lists complete frame files only
  out.open(_dir / (_job + ".pvd"), output::OutputFile::Mode::Replace);
  auto& b = out.buffer();
  fmt::format_to(fmt::appender(b),
                 "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" "
                 "byte_order=\"{}\">\n  <Collection>\n",
                 kByteOrder);
  for (const auto& e : _entries) {
    b.append(std::string_view("    <DataSet timestep=\""));
    output::append_json_number(b, e.time);
    b.append(std::string_view("\" group=\"\" part=\"0\" file=\""));
    output::append_xml_text(b, e.file);
    b.append(std::string_view("\"/>\n"));
  }
  b.append(std::string_view("  </Collection>\n</VTKFile>\n"));
  out.close();
}

} // namespace gapfem
