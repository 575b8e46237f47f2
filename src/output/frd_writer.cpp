#include "output/frd_writer.hpp"

#include "model/element_types.hpp"
#include "model/model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>

namespace gapfem {
namespace {

/// A number in the format's E12.5 field; values too small or too large for a two-digit exponent
/// are written as 0 and ±9.99999E+99 (cgx reads fixed columns).
void append_value(fmt::memory_buffer& out, double v) {
  if (!std::isfinite(v) || std::fabs(v) >= 9.99999e99)
    v = std::isnan(v) ? 0.0 : std::copysign(9.99999e99, v);
  else if (std::fabs(v) < 1e-99)
    v = 0.0;
  fmt::format_to(fmt::appender(out), "{:12.5E}", v);
}

std::string pad8(std::string_view name) {
  return fmt::format("{:<8}", name.substr(0, 8));
}

} // namespace

/// One dataset: its name, cgx's component type (1 scalar, 2 vector, 4 tensor), the component names
/// and per listed node the values.
struct FrdWriter::Block {
  std::string name;
  int type = 1;
  std::vector<std::string> components;
  std::vector<double> values; ///< per listed node, components.size() values
};

int frd_element_type(ElementType type) {
  const ElementTypeInfo& info = element_info(type);
  if (info.cell) switch (*info.cell) {
    case Shape::Hex8:
      return 1;
    case Shape::Wedge6:
      return 2;
    case Shape::Tet4:
      return 3;
    case Shape::Hex20:
      return 4;
    case Shape::Wedge15:
      return 5;
    case Shape::Tet10:
      return 6;
    case Shape::Tri3:
      return 7;
    case Shape::Tri6:
      return 8;
    case Shape::Quad4:
      return 9;
    case Shape::Quad8:
      return 10;
    case Shape::Line2:
      return 11;
    case Shape::Line3:
      return 12;
    }
  // shells, beams without a cell, springs and gaps: by their node count
  switch (info.n_nodes) {
  case 2:
    return 11;
  case 3:
    return info.family == ElementFamily::Shell ? 7 : 12;
  case 4:
    return 9;
  case 6:
    return 8;
  case 8:
    return 10;
  default:
    return 0;
  }
}

int frd_node_from_abaqus(ElementType type, int frd_index) {
  const int frd = frd_element_type(type);
  if (frd == 4 && frd_index >= 12) // he20: 13-16 (top face) and 17-20 (vertical edges) swap
    return frd_index < 16 ? frd_index + 4 : frd_index - 4;
  if (frd == 5 && frd_index >= 9) // pe15: 10-12 (top face) and 13-15 (vertical edges) swap
    return frd_index < 12 ? frd_index + 3 : frd_index - 3;
  return frd_index;
}

FrdWriter::FrdWriter(std::filesystem::path path, std::string job)
    : _path(std::move(path)), _job(std::move(job)) {}

long long FrdWriter::node_number(NodeId n) const {
  return _flat ? static_cast<long long>(_model->mesh.node_labels[n]) : n + 1LL;
}

void FrdWriter::save_state(ArchiveWriter& a) {
  a.pod(static_cast<std::uint64_t>(_out.position()));
  a.pod(_datasets);
  a.pod(_frames);
}

void FrdWriter::resume(const Model& model, int, ArchiveReader& a, const ResumeFiles& from) {
  const auto keep = a.get<std::uint64_t>();
  a.pod(_datasets);
  a.pod(_frames);
  if (keep == 0) { // the job wrote no .frd so far
    begin(model);
    return;
  }
  _model = &model;
  _flat = model.instances.empty();
  _out.open_resumed(_path, from.file(".frd"), keep);
}

void FrdWriter::begin(const Model& model) {
  const bool wanted = std::any_of(model.steps.begin(), model.steps.end(),
                                  [](const Step& s) { return !s.file_outputs.empty(); });
  if (!wanted) return;
  _model = &model;
  _flat = model.instances.empty();
  _out.open(_path);
  auto out = fmt::appender(_out.buffer());
  fmt::format_to(out, "    1C{}\n", _job.substr(0, 66));
  fmt::format_to(out, "    1UPGM               gapfem\n");
  if (!_flat)
    fmt::format_to(out, "    1UNOTE              nodes and elements numbered 1..n in model "
                        "order (part instances)\n");
  const Mesh& mesh = model.mesh;
  fmt::format_to(out, "    2C{:30}{:38}\n", mesh.n_nodes(), 1);
  for (NodeId n = 0; n < mesh.n_nodes(); ++n) {
    fmt::format_to(out, " -1{:10}", node_number(n));
    for (int k = 0; k < 3; ++k) append_value(_out.buffer(), mesh.coords[n][k]);
    _out.write("\n");
    _out.maybe_flush();
  }
  _out.write(" -3\n");
  int n_written = 0;
  for (ElemId e = 0; e < mesh.n_elements(); ++e)
    n_written += frd_element_type(mesh.elem_types[e]) != 0;
  fmt::format_to(out, "    3C{:30}{:38}\n", n_written, 1);
  for (ElemId e = 0; e < mesh.n_elements(); ++e) {
    const ElementType t = mesh.elem_types[e];
    const int type = frd_element_type(t);
    if (type == 0) continue;
    const long long label = _flat ? static_cast<long long>(mesh.elem_labels[e]) : e + 1LL;
    fmt::format_to(out, " -1{:10}{:5}{:5}{:5}\n", label, type, 0, 1);
    const auto nodes = mesh.element_nodes(e);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      if (i % 10 == 0) _out.write(i == 0 ? " -2" : "\n -2");
      fmt::format_to(out, "{:10}",
                     node_number(nodes[frd_node_from_abaqus(t, static_cast<int>(i))]));
    }
    _out.write("\n");
    _out.maybe_flush();
  }
  _out.write(" -3\n");
  _out.flush();
}

void FrdWriter::write_block(const Frame& frame, const Block& b, const std::vector<NodeId>& nodes) {
  auto out = fmt::appender(_out.buffer());
  fmt::format_to(out, "    1PSTEP{:26}{:12}{:12}\n", ++_datasets, frame.increment, frame.step);
  // a mode (*FREQUENCY): its frequency as the value, analysis type 2 (frequency), its number;
  // a buckling mode (no generalized mass) its load multiplier
  if (frame.mode) fmt::format_to(out, "    1PMODE{:26}\n", frame.mode->mode);
  fmt::format_to(out, "  100CL{:5}", 100 + _frames);
  const bool buckling = frame.mode && frame.mode->generalized_mass == 0.0;
  append_value(_out.buffer(), buckling         ? frame.mode->eigenvalue
                              : frame.mode     ? frame.mode->frequency()
                              : frame.harmonic ? frame.harmonic->frequency
                                               : frame.total_time);
  fmt::format_to(out, "{:12}{:20}{:2}{:5}{:10}{:2}\n", nodes.size(), "", frame.mode ? 2 : 0,
                 frame.mode ? frame.mode->mode : frame.step, "", 1);
  const int nc = static_cast<int>(b.components.size());
  fmt::format_to(out, " -4  {}{:5}{:5}\n", pad8(b.name), b.type == 2 ? nc + 1 : nc, 1);
  static constexpr std::array<std::array<int, 2>, 6> kTensor{
      {{1, 1}, {2, 2}, {3, 3}, {1, 2}, {2, 3}, {3, 1}}};
  for (int c = 0; c < nc; ++c) {
    const int i1 = b.type == 4 ? kTensor[c][0] : (b.type == 2 ? c + 1 : 0);
    const int i2 = b.type == 4 ? kTensor[c][1] : 0;
    fmt::format_to(out, " -5  {}{:5}{:5}{:5}{:5}\n", pad8(b.components[c]), 1, b.type, i1, i2);
  }
  if (b.type == 2)
    fmt::format_to(out, " -5  {}{:5}{:5}{:5}{:5}{:5}ALL\n", pad8("ALL"), 1, 2, 0, 0, 1);
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    fmt::format_to(out, " -1{:10}", node_number(nodes[k]));
    for (int c = 0; c < nc; ++c) {
      if (c == 6) fmt::format_to(out, "\n -2{:10}", "");
      append_value(_out.buffer(),
                   b.values[k * static_cast<std::size_t>(nc) + static_cast<std::size_t>(c)]);
    }
    _out.write("\n");
    _out.maybe_flush();
  }
  _out.write(" -3\n");
}

void FrdWriter::node_blocks(const Model& model, const Frame& frame,
                            const std::vector<NodeVar>& vars,
                            const std::vector<std::vector<char>>& masks, bool global) {
  const NodeResults& r = frame.nodes;
  for (std::size_t k = 0; k < vars.size(); ++k) {
    const NodeVar v = vars[k];
    Block b;
    const std::vector<Vec3>* vec = nullptr;
    const std::vector<double>* scalar = nullptr;
    switch (v) {
    case NodeVar::U:
      b = {"DISP", 2, {"D1", "D2", "D3"}, {}}, vec = &r.U;
      break;
    case NodeVar::UR:
      b = {"ROT", 2, {"UR1", "UR2", "UR3"}, {}}, vec = &r.UR;
      break;
    case NodeVar::RF:
      b = {"FORC", 2, {"F1", "F2", "F3"}, {}}, vec = &r.RF;
      break;
    case NodeVar::RM:
      b = {"RM", 2, {"RM1", "RM2", "RM3"}, {}}, vec = &r.RM;
      break;
    case NodeVar::CF:
      b = {"CF", 2, {"CF1", "CF2", "CF3"}, {}}, vec = &r.CF;
      break;
    case NodeVar::CM:
      b = {"CM", 2, {"CM1", "CM2", "CM3"}, {}}, vec = &r.CM;
      break;
    case NodeVar::NT:
      b = {"NDTEMP", 1, {"T"}, {}}, scalar = &r.NT;
      break;
    case NodeVar::RFL:
      b = {"RFL", 1, {"RFL"}, {}}, scalar = &r.RFL;
      break;
    case NodeVar::CFL:
      b = {"CFL", 1, {"CFL"}, {}}, scalar = &r.CFL;
      break;
    // CalculiX's velocity block (VELO: V1 V2 V3 ALL); it writes no accelerations or rotational
    // rates, which take names of the same form (cgx shows any named vector block)
    case NodeVar::V:
      b = {"VELO", 2, {"V1", "V2", "V3"}, {}}, vec = &r.V;
      break;
    case NodeVar::VR:
      b = {"VELR", 2, {"VR1", "VR2", "VR3"}, {}}, vec = &r.VR;
      break;
    case NodeVar::A:
      b = {"ACCE", 2, {"A1", "A2", "A3"}, {}}, vec = &r.A;
      break;
    case NodeVar::AR:
      b = {"ACCR", 2, {"AR1", "AR2", "AR3"}, {}}, vec = &r.AR;
      break;
    }
    // velocities and accelerations of a step that has none (not *DYNAMIC): nothing to write
    if (vec && vec->size() != static_cast<std::size_t>(model.mesh.n_nodes())) continue;
    std::vector<NodeId> nodes;
    for (NodeId n = 0; n < model.mesh.n_nodes(); ++n) {
      if (!masks[k][static_cast<std::size_t>(n)]) continue;
      const output::NodeFields f = output::node_fields(r, n);
      const bool rotational = v == NodeVar::UR || v == NodeVar::RM || v == NodeVar::CM ||
                              v == NodeVar::VR || v == NodeVar::AR;
      const bool carried = vec ? (rotational ? f.rotation : f.displacement)
                               : (v == NodeVar::NT ? f.nt : f.temperature);
      if (!carried) continue;
      nodes.push_back(n);
      if (vec) {
        const Vec3 x = global ? r.global(n, (*vec)[n]) : (*vec)[n];
        b.values.insert(b.values.end(), x.begin(), x.end());
      } else {
        b.values.push_back((*scalar)[n]);
      }
    }
    if (!nodes.empty()) write_block(frame, b, nodes);
  }
}

void FrdWriter::element_blocks(const Model& model, const Frame& frame,
                               const std::vector<ElemVar>& vars,
                               const std::vector<std::vector<char>>& masks) {
  for (std::size_t k = 0; k < vars.size(); ++k) {
    const ElemVar v = vars[k];
    const output::NodalField f = _averager.average(model, frame, v, &masks[k]);
    Block b;
    if (v == ElemVar::S) b = {"STRESS", 4, {"SXX", "SYY", "SZZ", "SXY", "SYZ", "SZX"}, {}};
    if (v == ElemVar::E) b = {"TOSTRAIN", 4, {"EXX", "EYY", "EZZ", "EXY", "EYZ", "EZX"}, {}};
    if (v == ElemVar::HFL) b = {"FLUX", 2, {"F1", "F2", "F3"}, {}};
    if (v == ElemVar::ENER) b = {"ENER", 1, {"ENER"}, {}}; // CalculiX's strain energy density
    // slots of the averaged field (11 22 33 12 13 23) in cgx's order (xx yy zz xy yz zx); strains
    // as tensor components (half the engineering shears), as CalculiX writes them
    static constexpr std::array<int, 6> kOrder{0, 1, 2, 3, 5, 4};
    std::vector<NodeId> nodes;
    for (NodeId n = 0; n < model.mesh.n_nodes(); ++n) {
      if (f.count[static_cast<std::size_t>(n)] == 0) continue;
      nodes.push_back(n);
      const double* x = &f.values[static_cast<std::size_t>(n) * static_cast<std::size_t>(f.width)];
      for (int c = 0; c < f.width; ++c) {
        const int slot = f.width == 6 ? kOrder[c] : c;
        b.values.push_back(v == ElemVar::E && c >= 3 ? 0.5 * x[slot] : x[slot]);
      }
    }
    if (!nodes.empty()) write_block(frame, b, nodes);
  }
}

void FrdWriter::frame(const Model& model, int step_index, const Frame& frame) {
  if (!_out.is_open()) return;
  const Step& step = model.steps[step_index];
  std::vector<NodeVar> node_vars;
  std::vector<ElemVar> elem_vars;
  std::vector<std::vector<char>> node_masks, elem_masks;
  bool global = false;
  const auto nn = static_cast<std::size_t>(model.mesh.n_nodes());
  const auto ne = static_cast<std::size_t>(model.mesh.n_elements());
  // the union of the due requests: one dataset per variable, on the union of their sets
  auto add = [](auto& vars, auto& masks, auto v, std::size_t n, const FileOutputRequest& r) {
    auto it = std::find(vars.begin(), vars.end(), v);
    if (it == vars.end()) {
      vars.push_back(v);
      masks.emplace_back(n, 0);
      it = vars.end() - 1;
    }
    auto& m = masks[static_cast<std::size_t>(it - vars.begin())];
    if (r.set.empty())
      std::fill(m.begin(), m.end(), 1);
    else
      for (auto id : r.members) m[static_cast<std::size_t>(id)] = 1;
  };
  for (std::size_t k = 0; k < step.file_outputs.size() && k < frame.file_output_due.size(); ++k) {
    if (!frame.file_output_due[k]) continue;
    const FileOutputRequest& r = step.file_outputs[k];
    global |= r.global;
    for (NodeVar v : r.node_vars) add(node_vars, node_masks, v, nn, r);
    for (ElemVar v : r.elem_vars) add(elem_vars, elem_masks, v, ne, r);
  }
  if (node_vars.empty() && elem_vars.empty()) return;
  ++_frames;
  node_blocks(model, frame, node_vars, node_masks, global);
  element_blocks(model, frame, elem_vars, elem_masks);
  _out.flush();
}

void FrdWriter::end(const Model& model, const RunSummary& summary) {
  if (!_out.is_open()) return;
  _out.write(" 9999\n");
  _out.close();
}

} // namespace gapfem
