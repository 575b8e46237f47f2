#include "output/vtu_writer.hpp"

#include "common/error.hpp"
#include "model/model.hpp"
#include "output/field_selection.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <deque>
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
    // the deck's own types (user elements, substructures) have no shape: their nodes
    return info.n_nodes == 0 && n_nodes > 0 ? 2 : 0; // VTK_POLY_VERTEX
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

void VtuWriter::begin(const Model& model) {
  _entries.clear();
  build_topology(model);
  write_pvd();
}

void VtuWriter::save_state(ArchiveWriter& a) {
  a.pod(static_cast<std::uint64_t>(_entries.size()));
  for (const PvdEntry& e : _entries) {
    a.pod(e.time);
    a.str(e.file);
  }
}

void VtuWriter::resume(const Model& model, int, ArchiveReader& a, const ResumeFiles& from) {
  build_topology(model);
  _entries.resize(a.get<std::uint64_t>());
  const bool same = from.job == _job && std::filesystem::equivalent(from.directory, _dir);
  for (PvdEntry& e : _entries) {
    a.pod(e.time);
    a.str(e.file);
    if (same) continue;
    // a new job: its own copies of the earlier frames (linked when the file system can)
    const std::filesystem::path source = from.directory / e.file;
    if (e.file.rfind(from.job, 0) == 0) e.file = _job + e.file.substr(from.job.size());
    const std::filesystem::path target = _dir / e.file;
    std::error_code ec;
    std::filesystem::remove(target, ec);
    std::filesystem::create_hard_link(source, target, ec);
    if (ec) std::filesystem::copy_file(source, target, ec);
    if (ec)
      throw AnalysisError(fmt::format("cannot copy the ParaView frame '{}' of the restarted job "
                                      "to '{}': {}",
                                      source.string(), target.string(), ec.message()));
  }
  write_pvd();
}

void VtuWriter::build_topology(const Model& model) {
  const Mesh& mesh = model.mesh;
  const auto ne = static_cast<std::size_t>(mesh.n_elements());
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
    const int own = element_info(type).n_nodes; // 0: the deck's own types, all their nodes
    const int n =
        own > 0 ? std::min(static_cast<int>(nodes.size()), own) : static_cast<int>(nodes.size());
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
}

namespace {

/// The point arrays the frame's requests ask for (masked copies kept in `kept*`).
std::vector<Array> node_arrays(const Model& model, const Frame& frame,
                               const output::FieldSelection& sel,
                               std::deque<std::vector<double>>& kept,
                               std::deque<std::vector<Vec3>>& kept_vectors) {
  const auto nn = static_cast<std::size_t>(model.mesh.n_nodes());
  const NodeResults& r = frame.nodes;
  std::vector<Array> arrays;
  // ParaView warps and colours by global components: vectors at *TRANSFORM nodes go back from
  // their local systems (v_global = Q^T v_local); NaN off the variable's node set
  auto vec = [&](std::string_view name, NodeVar var, const std::vector<Vec3>& v) {
    const std::vector<char>* mask = sel.nodes(var);
    if (!mask || v.size() != nn) return;
    std::vector<Vec3>& g = kept_vectors.emplace_back(v);
    for (const auto& entry : r.local_axes)
      if (static_cast<std::size_t>(entry.first) < g.size())
        g[entry.first] = r.global(entry.first, g[entry.first]);
    for (std::size_t n = 0; n < nn; ++n)
      if (!(*mask)[n]) g[n] = Vec3{kNaN, kNaN, kNaN};
    arrays.push_back(Array{name, "Float64", 3, g.data(), nn * sizeof(Vec3), {}});
  };
  auto scalar = [&](std::string_view name, NodeVar var, const std::vector<double>& v) {
    const std::vector<char>* mask = sel.nodes(var);
    if (!mask || v.size() != nn) return;
    kept.push_back(output::FieldSelection::masked(v, 1, *mask));
    arrays.push_back(make_array(name, "Float64", 1, kept.back()));
  };
  if (r.any_displacement || !r.any_temperature) {
    vec("U", NodeVar::U, r.U);
    vec("RF", NodeVar::RF, r.RF);
    vec("CF", NodeVar::CF, r.CF);
    vec("V", NodeVar::V, r.V); // velocities and accelerations: dynamic steps only (else empty)
    vec("A", NodeVar::A, r.A);
  }
  if (r.any_rotation) {
    vec("UR", NodeVar::UR, r.UR);
    vec("RM", NodeVar::RM, r.RM);
    vec("CM", NodeVar::CM, r.CM);
    vec("VR", NodeVar::VR, r.VR);
    vec("AR", NodeVar::AR, r.AR);
  }
  if (!r.any_temperature) return arrays;
  if (!r.nt_field.empty()) {
    // a predefined field (stress analysis) is NT at the nodes of the elements that read it and
    // NaN elsewhere (ground nodes of gaps have no temperature); it has no RFL
    std::vector<double> nt = r.NT;
    for (std::size_t n = 0; n < nt.size() && n < r.nt_field.size(); ++n)
      if (!r.nt_field[n]) nt[n] = kNaN;
    scalar("NT", NodeVar::NT, nt);
    return arrays;
  }
  scalar("NT", NodeVar::NT, r.NT);
  scalar("RFL", NodeVar::RFL, r.RFL);
  scalar("CFL", NodeVar::CFL, r.CFL);
  // heat-transfer shells: NT12 … through the thickness; a node with fewer temperatures shows its
  // last one (a solid's single temperature), so colour maps stay continuous
  static const std::array<std::string, kMaxTemperaturePoints> kNtNames = [] {
    std::array<std::string, kMaxTemperaturePoints> a;
    for (int k = 0; k < kMaxTemperaturePoints; ++k) a[k] = fmt::format("NT{}", 11 + k);
    return a;
  }();
  const int n_points = std::clamp(r.temperature_points, 1, kMaxTemperaturePoints);
  for (int k = 1; k < n_points && r.NT_more.size() == nn * (n_points - 1); ++k) {
    std::vector<double> v(nn);
    for (std::size_t n = 0; n < nn; ++n) {
      const int have = r.temperatures_at(static_cast<NodeId>(n));
      const int j = std::min(k, have - 1);
      v[n] = j <= 0 ? r.NT[n] : r.NT_more[(n_points - 1) * n + j - 1];
    }
    scalar(kNtNames[k], NodeVar::NT, v);
  }
  return arrays;
}

} // namespace

void VtuWriter::frame(const Model& model, int step_index, const Frame& frame) {
  if (!frame.field_due) return;
  const Mesh& mesh = model.mesh;
  const auto nn = static_cast<std::size_t>(mesh.n_nodes());
  const auto ne = static_cast<std::size_t>(mesh.n_elements());
  const output::FieldSelection sel(model, step_index, frame);
  _cells.collect(model, frame, _has_gaps);
  // masked copies must outlive the arrays that point at them: deques keep their elements in place
  std::deque<std::vector<double>> kept;
  std::deque<std::vector<Vec3>> kept_vectors;
  std::vector<Array> point_arrays = node_arrays(model, frame, sel, kept, kept_vectors);
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
  // a requested variable on its element set (NaN elsewhere); nothing when not requested
  auto cell = [&](std::string_view name, ElemVar var, bool any, const std::vector<double>& v,
                  int width, std::string_view components = {}) {
    const std::vector<char>* mask = sel.elements(var);
    if (!any || !mask) return;
    kept.push_back(output::FieldSelection::masked(v, static_cast<std::size_t>(width), *mask));
    cell_arrays.push_back(make_array(name, "Float64", width, kept.back()));
    cell_arrays.back().component_names = components;
  };
  cell("S", ElemVar::S, _cells.any_S, _cells.S, 6, kVoigt);
  cell("E", ElemVar::E, _cells.any_E, _cells.E, 6, kVoigt);
  // shells: their SNEG and SPOS sides (section points 1 and n)
  cell("S_SNEG", ElemVar::S, _cells.any_sides, _cells.S_neg, 6, kVoigt);
  cell("S_SPOS", ElemVar::S, _cells.any_sides, _cells.S_pos, 6, kVoigt);
  cell("E_SNEG", ElemVar::E, _cells.any_sides, _cells.E_neg, 6, kVoigt);
  cell("E_SPOS", ElemVar::E, _cells.any_sides, _cells.E_pos, 6, kVoigt);
  cell("SF", ElemVar::SF, _cells.any_SF, _cells.SF, 6);
  cell("SM", ElemVar::SF, _cells.any_SM, _cells.SM, 3);
  cell("HFL", ElemVar::HFL, _cells.any_HFL, _cells.HFL, 3);
  if (_has_gaps) {
    cell_arrays.push_back(make_array("gap_status", "Int32", 1, _cells.gap_status));
    cell_arrays.push_back(make_array("gap_clearance", "Float64", 1, _cells.gap_clearance));
    cell_arrays.push_back(make_array("gap_pressure", "Float64", 1, _cells.gap_pressure));
  }
  const bool has_U = std::any_of(point_arrays.begin(), point_arrays.end(),
                                 [](const Array& a) { return a.name == "U"; });
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
                 _type_legend, kByteOrder,
                 frame.mode       ? static_cast<double>(frame.mode->mode)
                 : frame.harmonic ? frame.harmonic->frequency
                                  : frame.total_time,
                 nn, ne);
  b.append(std::string_view(has_U ? "      <PointData Vectors=\"U\">\n" : "      <PointData>\n"));
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

  if (frame.mode || frame.harmonic) { // the step's own series: modes, or frequencies (the real
                                      // part of a steady-state response as U)
    if (frame.increment == 1) _mode_entries.clear();
    _mode_entries.push_back(PvdEntry{
        frame.mode ? static_cast<double>(frame.mode->mode) : frame.harmonic->frequency, file});
    write_modes_pvd(frame.step);
    return;
  }
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

void VtuWriter::write_modes_pvd(int step) {
  write_pvd(fmt::format("{}_step{}_modes.pvd", _job, step), _mode_entries);
}

void VtuWriter::write_pvd() {
  write_pvd(_job + ".pvd", _entries);
}

void VtuWriter::write_pvd(const std::string& name, const std::vector<PvdEntry>& entries) {
  output::OutputFile out; // replaced whole: the collection lists complete frame files only
  out.open(_dir / name, output::OutputFile::Mode::Replace);
  auto& b = out.buffer();
  fmt::format_to(fmt::appender(b),
                 "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" "
                 "byte_order=\"{}\">\n  <Collection>\n",
                 kByteOrder);
  for (const auto& e : entries) {
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
