#include "output/json_writer.hpp"

#include "model/model.hpp"

#include <algorithm>
#include <numeric>

namespace gapfem {
namespace {

using output::append_json_array;
using output::append_json_number;
using output::append_json_string;

std::string_view space_key(ModelSpace s) {
  switch (s) {
  case ModelSpace::ThreeD:
    return "3D";
  case ModelSpace::Planar:
    return "planar";
  case ModelSpace::Axisymmetric:
    return "axisymmetric";
  }
  return "3D";
}

void key(fmt::memory_buffer& b, std::string_view k) {
  output::append_json_key(b, k);
}
void number_field(fmt::memory_buffer& b, std::string_view k, double v) {
  output::append_json_field(b, k, v);
}

/// Writes a comma before every field but the first of an object.
struct Separator {
  bool first = true;
  void operator()(fmt::memory_buffer& b) {
    if (!first) b.push_back(',');
    first = false;
  }
};

/// Append the first `n` components of `v` (or component 2 alone when `only_z`).
void vec_field(fmt::memory_buffer& b, Separator& sep, std::string_view k, const Vec3& v, int n,
               bool only_z) {
  sep(b);
  key(b, k);
  if (only_z)
    append_json_array(b, std::span<const double>(&v[2], 1));
  else
    append_json_array(b, std::span<const double>(v.data(), static_cast<std::size_t>(n)));
}

bool nonzero(const Vec3& v) {
  return v[0] != 0.0 || v[1] != 0.0 || v[2] != 0.0;
}

} // namespace

JsonWriter::JsonWriter(std::filesystem::path path, std::string job)
    : _path(std::move(path)), _job(std::move(job)) {}

void JsonWriter::begin(const Model& model) {
  _model = &model;
  _watch = Stopwatch();
  _failed = false;
  _has_last = false;
  _seen = RunStatistics{};
  _shadow.begin(_path);
  _publish_seconds = 0.0;
  _out.open(part_path());
  auto& b = _out.buffer();
  b.append(std::string_view("{\"schema\":\"gapfem.results/1\",\"job\":"));
  append_json_string(b, _job.empty() ? model.job_name : _job);
  b.append(std::string_view(",\"heading\":"));
  append_json_string(b, model.heading);
  fmt::format_to(fmt::appender(b), ",\"model\":{{\"space\":\"{}\",\"nodes\":{},\"elements\":{}",
                 space_key(model.space), model.mesh.n_nodes(), model.mesh.n_elements());
  if (!model.instances.empty()) { // part instances: node and element keys are "INSTANCE.label"
    b.append(std::string_view(",\"instances\":["));
    for (std::size_t i = 0; i < model.instances.size(); ++i) {
      if (i) b.push_back(',');
      append_json_string(b, model.instances[i]);
    }
    b.push_back(']');
  }
  b.push_back('}');
  b.append(std::string_view(",\"steps\":["));
  _first_step = true;
  _step_open = false;
  _components.clear();
  prepare_model(model);
  checkpoint();
}

void JsonWriter::prepare_model(const Model& model) {
  _node_mark.assign(model.mesh.n_nodes(), 0);
  _elem_mark.assign(model.mesh.n_elements(), 0);
  _all_nodes = output::request_nodes_by_label(model, {}, {});
}

void JsonWriter::prepare_step(const Model& model, int step_index) {
  const Step& step = model.steps[step_index];
  _node_lists.clear();
  for (const auto& req : step.node_prints)
    _node_lists.push_back(output::request_nodes_by_label(model, req.nset, req.nodes));
  _elem_lists.clear();
  for (const auto& req : step.el_prints)
    _elem_lists.push_back(output::request_elements_by_type(model, req.elset, req.elements));
}

void JsonWriter::save_state(ArchiveWriter& a) {
  a.pod(static_cast<std::uint64_t>(_failed ? 0 : _out.position()));
  a.pod(_seen);
  a.pod(_has_last);
  a.pod(_last.step);
  a.pod(_last.increment);
  a.pod(_last.step_time);
  a.pod(_last.total_time);
  a.pod(_step_open);
  a.pod(_first_step);
  a.pod(_first_frame);
  a.pod(_open_step_number);
  a.pod(_last_increment);
  a.pod(_publish_seconds);
  a.vec(_energy_history);
  a.strings(_history_columns);
  a.pod(static_cast<std::uint64_t>(_history_rows.size()));
  for (const auto& row : _history_rows) a.vec(row);
  a.pod(static_cast<std::uint64_t>(_components.size()));
  for (const auto& [k, c] : _components) {
    a.pod(k.first);
    a.str(k.second);
    a.pod(c.seen);
    for (const auto& names : c.names) a.strings(names);
  }
}

void JsonWriter::resume(const Model& model, int step_index, ArchiveReader& a,
                        const ResumeFiles& from) {
  _model = &model;
  _watch = Stopwatch();
  _failed = false;
  const auto keep = a.get<std::uint64_t>();
  // The published document begins with the body as it was at the restart point (a checkpoint
  // only ever appends to the body): its first `keep` bytes are the body to continue.
  _out.open_resumed(part_path(), from.file(".results.json"), keep);
  _shadow.begin(_path);
  a.pod(_seen);
  a.pod(_has_last);
  a.pod(_last.step);
  a.pod(_last.increment);
  a.pod(_last.step_time);
  a.pod(_last.total_time);
  a.pod(_step_open);
  a.pod(_first_step);
  a.pod(_first_frame);
  a.pod(_open_step_number);
  a.pod(_last_increment);
  a.pod(_publish_seconds);
  a.vec(_energy_history);
  a.strings(_history_columns);
  _history_rows.resize(a.get<std::uint64_t>());
  for (auto& row : _history_rows) a.vec(row);
  _components.clear();
  for (auto n = a.get<std::uint64_t>(); n > 0; --n) {
    const auto t = a.get<int>();
    TypeComponents& c = _components[{t, a.str()}];
    a.pod(c.seen);
    for (auto& names : c.names) a.strings(names);
  }
  prepare_model(model);
  prepare_step(model, step_index);
}

void JsonWriter::begin_step(const Model& model, int step_index) {
  if (_step_open) close_step(nullptr);
  const Step& step = model.steps[step_index];
  auto& b = _out.buffer();
  if (!_first_step) b.push_back(',');
  _first_step = false;
  fmt::format_to(fmt::appender(b), "\n{{\"step\":{},\"name\":", step.number);
  append_json_string(b, step.name);
  b.append(std::string_view(",\"procedure\":"));
  append_json_string(b, procedure_name(step.procedure));
  b.append(std::string_view(",\"frames\":["));
  prepare_step(model, step_index);
  _requested.fill(false);
  for (const ElPrintRequest& r : step.el_prints)
    for (ElemVar v : r.vars) _requested[static_cast<std::size_t>(v)] = true;
  for (const FieldOutputRequest& r : step.field_outputs)
    for (ElemVar v : r.elem_vars) _requested[static_cast<std::size_t>(v)] = true;
  for (const HistoryOutputRequest& r : step.history_outputs)
    for (const auto& [v, set] : r.elem_vars) _requested[static_cast<std::size_t>(v)] = true;
  _step_open = true;
  _first_frame = true;
  _energy_history.clear();
  _history_columns.clear();
  _history_rows.clear();
  _modes_json.clear();
  _open_step_number = step.number;
  _last_increment = -1;
}

void JsonWriter::frame(const Model& model, int step_index, const Frame& frame) {
  const auto& mesh = model.mesh;
  _frame_nodes.clear();
  _frame_elems.clear();
  if (frame.last_in_step || frame.mode || frame.harmonic) { // a mode's frame: its whole shape
    _frame_nodes = _all_nodes;
    for (const auto& res : frame.elements)
      if (res.elem >= 0 && res.elem < mesh.n_elements()) _frame_elems.push_back(&res);
  } else {
    bool due = false;
    for (std::size_t k = 0; k < _node_lists.size() && k < frame.node_print_due.size(); ++k) {
      if (!frame.node_print_due[k]) continue;
      due = true;
      for (NodeId n : _node_lists[k])
        if (!_node_mark[n]) {
          _node_mark[n] = 1;
          _frame_nodes.push_back(n);
        }
    }
    for (std::size_t k = 0; k < _elem_lists.size() && k < frame.el_print_due.size(); ++k) {
      if (!frame.el_print_due[k]) continue;
      due = true;
      for (ElemId e : _elem_lists[k]) {
        const ElementResult* res = _elem_mark[e] ? nullptr : frame.element(e);
        if (!res) continue;
        _elem_mark[e] = 1;
        _frame_elems.push_back(res);
      }
    }
    for (NodeId n : _frame_nodes) _node_mark[n] = 0;
    for (const ElementResult* res : _frame_elems) _elem_mark[res->elem] = 0;
    if (!due) return;
  }
  if (!frame.last_in_step && !frame.mode && !frame.harmonic)
    std::sort(_frame_nodes.begin(), _frame_nodes.end(),
              [&](NodeId a, NodeId c) { return mesh.node_labels[a] < mesh.node_labels[c]; });
  std::sort(_frame_elems.begin(), _frame_elems.end(),
            [&](const ElementResult* a, const ElementResult* c) {
              return mesh.elem_labels[a->elem] < mesh.elem_labels[c->elem];
            });

  auto& b = _out.buffer();
  if (!_first_frame) b.push_back(',');
  _first_frame = false;
  fmt::format_to(fmt::appender(b), "\n{{\"increment\":{}", frame.increment);
  number_field(b, "step_time", frame.step_time);
  number_field(b, "total_time", frame.total_time);
  number_field(b, "dt", frame.dt);
  b.append(frame.last_in_step ? std::string_view(",\"last_in_step\":true")
                              : std::string_view(",\"last_in_step\":false"));
  // The stream cannot take back the earlier frame of this increment; readers take the last frame
  // with a given increment (docs/results.md).
  const bool repeated = frame.increment == _last_increment;
  _last_increment = frame.increment;
  b.append(repeated ? std::string_view(",\"repeated\":true")
                    : std::string_view(",\"repeated\":false"));
  if (frame.energies) output::append_energies(b, *frame.energies);
  if (frame.mode) {
    fmt::format_to(fmt::appender(b), ",\"mode\":{}", frame.mode->mode);
    output::append_json_field(b, "eigenvalue", frame.mode->eigenvalue);
    if (frame.mode->generalized_mass > 0.0) // not a buckling mode (a load multiplier)
      output::append_json_field(b, "frequency", frame.mode->frequency());
  }
  if (frame.harmonic) output::append_json_field(b, "frequency", frame.harmonic->frequency);
  b.append(std::string_view(",\"nodes\":{"));
  bool first = true;
  for (NodeId n : _frame_nodes) {
    write_node(model, frame.nodes, n, first, frame.harmonic ? &*frame.harmonic : nullptr);
    _out.maybe_flush();
  }
  b.append(std::string_view("},\"elements\":{"));
  first = true;
  for (const ElementResult* res : _frame_elems) {
    write_element(model, *res, first);
    _out.maybe_flush();
  }
  b.append(std::string_view("}}"));
  _out.maybe_flush();
}

namespace {

/// A steady-state vector: its imaginary part, amplitude |re + i im| and phase atan2(im, re) in
/// degrees per component.
void harmonic_fields(fmt::memory_buffer& b, Separator& sep, std::string_view name, const Vec3& re,
                     const Vec3& im, int n, bool only_z) {
  Vec3 amplitude{}, phase{};
  for (int i = 0; i < 3; ++i) {
    amplitude[i] = std::hypot(re[i], im[i]);
    phase[i] = amplitude[i] > 0.0 ? std::atan2(im[i], re[i]) * 180.0 / 3.14159265358979323846 : 0.0;
  }
  vec_field(b, sep, fmt::format("{}_imaginary", name), im, n, only_z);
  vec_field(b, sep, fmt::format("{}_amplitude", name), amplitude, n, only_z);
  vec_field(b, sep, fmt::format("{}_phase", name), phase, n, only_z);
}

} // namespace

void JsonWriter::write_node(const Model& model, const NodeResults& r, NodeId n, bool& first,
                            const Frame::Harmonic* h) {
  const auto f = output::node_fields(r, n);
  auto& b = _out.buffer();
  if (!first) b.push_back(',');
  first = false;
  fmt::format_to(fmt::appender(b), "\"{}\":{{", model.node_label(n));
  const auto idx = static_cast<std::size_t>(n);
  const int nt = output::n_translations(model.space);
  const bool planar = model.space != ModelSpace::ThreeD;
  Separator sep;
  auto scalar = [&](std::string_view k, double v) {
    sep(b);
    key(b, k);
    append_json_number(b, v);
  };
  if (f.displacement) {
    if (idx < r.U.size()) vec_field(b, sep, "U", r.U[idx], nt, false);
    if (h && idx < h->U.size() && idx < r.U.size())
      harmonic_fields(b, sep, "U", r.U[idx], h->U[idx], nt, false);
    if (idx < r.RF.size()) vec_field(b, sep, "RF", r.RF[idx], nt, false);
    if (idx < r.CF.size() && nonzero(r.CF[idx])) vec_field(b, sep, "CF", r.CF[idx], nt, false);
    // velocity and acceleration: dynamic steps only (empty elsewhere)
    if (idx < r.V.size()) vec_field(b, sep, "V", r.V[idx], nt, false);
    if (idx < r.A.size()) vec_field(b, sep, "A", r.A[idx], nt, false);
  }
  if (f.rotation) {
    if (idx < r.UR.size()) vec_field(b, sep, "UR", r.UR[idx], 3, planar);
    if (h && idx < h->UR.size() && idx < r.UR.size())
      harmonic_fields(b, sep, "UR", r.UR[idx], h->UR[idx], 3, planar);
    if (idx < r.RM.size()) vec_field(b, sep, "RM", r.RM[idx], 3, planar);
    if (idx < r.CM.size() && nonzero(r.CM[idx])) vec_field(b, sep, "CM", r.CM[idx], 3, planar);
    if (idx < r.VR.size()) vec_field(b, sep, "VR", r.VR[idx], 3, planar);
    if (idx < r.AR.size()) vec_field(b, sep, "AR", r.AR[idx], 3, planar);
  }
  if (const auto it = r.local_axes.find(n); it != r.local_axes.end()) {
    // a *TRANSFORM node: the vectors above are in its local system, whose axes follow (rows)
    sep(b);
    key(b, "axes");
    b.push_back('[');
    for (int i = 0; i < 9; ++i) {
      if (i) b.push_back(',');
      append_json_number(b, it->second[i]);
    }
    b.push_back(']');
  }
  if (f.nt && idx < r.NT.size()) scalar("NT", r.NT[idx]);
  if (f.temperature) {
    if (idx < r.RFL.size()) scalar("RFL", r.RFL[idx]);
    if (idx < r.CFL.size() && r.CFL[idx] != 0.0) scalar("CFL", r.CFL[idx]);
    // heat-transfer shells: all temperatures through the thickness, DOF 11 (SNEG) first
    if (const int k = r.temperatures_at(n); k > 1 && r.temperature_points > 1) {
      sep(b);
      key(b, "NT_SECTION");
      b.push_back('[');
      append_json_number(b, r.NT[idx]);
      for (int j = 1; j < k; ++j) {
        b.push_back(',');
        append_json_number(b, r.NT_more[static_cast<std::size_t>(r.temperature_points - 1) * idx +
                                        static_cast<std::size_t>(j - 1)]);
      }
      b.push_back(']');
    }
  }
  b.push_back('}');
}

JsonWriter::TypeComponents& JsonWriter::components(const Model& model, ElemId e) {
  const auto type = static_cast<int>(model.mesh.elem_types[e]);
  TypeComponents& tc = _components[{type, std::string(model.element_type_name(e))}];
  tc.seen = true;
  return tc;
}

void JsonWriter::write_element(const Model& model, const ElementResult& res, bool& first) {
  auto& b = _out.buffer();
  if (!first) b.push_back(',');
  first = false;
  const ElementType type = model.mesh.elem_types[res.elem];
  fmt::format_to(fmt::appender(b), "\"{}\":{{\"type\":\"{}\"", model.element_label(res.elem),
                 model.element_type_name(res.elem));
  TypeComponents& tc = components(model, res.elem);
  const bool shell = element_info(type).family == ElementFamily::Shell;
  const bool beam = element_info(type).family == ElementFamily::Beam;
  for (const OutputBlock& block : res.data.blocks) {
    const bool on_request = block.var == ElemVar::ENER || block.var == ElemVar::ELSE ||
                            block.var == ElemVar::EVOL || block.var == ElemVar::COORD;
    if (on_request && !_requested[static_cast<std::size_t>(block.var)]) continue;
    auto& names = tc.names[static_cast<std::size_t>(block.var)];
    if (names.empty())
      for (auto nm : block.names) names.emplace_back(nm);
    b.push_back(',');
    key(b, elem_var_name(block.var));
    if (block.var == ElemVar::NFORC) { // per element node: one row each
      const std::size_t nc = block.names.size();
      b.push_back('[');
      for (int p = 0; p < block.n_points; ++p) {
        if (p) b.push_back(',');
        append_json_array(b, std::span<const double>(block.values).subspan(p * nc, nc));
      }
      b.push_back(']');
      continue;
    }
    output::average_block(block, _avg);
    append_json_array(b, _avg);
    if (block.section_points < 2) continue;
    if (beam) { // every section point, averaged over the integration points: the fibres
      b.push_back(',');
      key(b, fmt::format("{}_POINTS", elem_var_name(block.var)));
      b.push_back('[');
      for (int k = 0; k < block.section_points; ++k) {
        if (k) b.push_back(',');
        output::average_section_point(block, k, _avg);
        append_json_array(b, _avg);
      }
      b.push_back(']');
      continue;
    }
    if (!shell) continue;
    // a shell's SNEG and SPOS sides (section points 1 and n), averaged over its points
    for (const bool top : {false, true}) {
      output::average_section_point(block, top ? block.section_points - 1 : 0, _avg);
      b.push_back(',');
      key(b, fmt::format("{}_{}", elem_var_name(block.var), top ? "SPOS" : "SNEG"));
      append_json_array(b, _avg);
    }
  }
  if (res.data.gap) {
    const GapRecord& g = *res.data.gap;
    b.append(std::string_view(",\"gap\":{\"status\":"));
    append_json_string(b, contact_status_name(g.status));
    number_field(b, "clearance", g.clearance);
    number_field(b, "normal_force", g.normal_force);
    number_field(b, "pressure", g.pressure);
    b.append(std::string_view(",\"direction\":"));
    append_json_array(b, g.direction);
    b.append(std::string_view(",\"t1\":"));
    append_json_array(b, g.t1);
    b.append(std::string_view(",\"t2\":"));
    append_json_array(b, g.t2);
    b.append(std::string_view(",\"slip\":"));
    append_json_array(b, g.slip);
    b.append(std::string_view(",\"shear\":"));
    append_json_array(b, g.shear);
    b.append(std::string_view(",\"friction_force\":"));
    append_json_array(b, g.friction_force);
    number_field(b, "damping_force", g.damping_force);
    number_field(b, "dissipation", g.dissipation);
    number_field(b, "area", g.area);
    if (g.thermal) {
      number_field(b, "heat_flux", g.heat_flux);
      number_field(b, "heat_flow", g.heat_flow);
      number_field(b, "conductance", g.conductance);
    }
    b.push_back('}');
  }
  b.push_back('}');
}

void JsonWriter::end_step(const Model& model, int step_index, const StepSummary& summary) {
  if (_step_open) close_step(&summary);
  checkpoint();
}

} // namespace gapfem
