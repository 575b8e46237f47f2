#include "output/dat_writer.hpp"

#include "common/log.hpp"
#include "model/model.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <string>

namespace gapfem {
namespace {

using output::append_e12;

constexpr std::array<std::string_view, 3> kU = {"U1", "U2", "U3"};
constexpr std::array<std::string_view, 3> kRF = {"RF1", "RF2", "RF3"};
constexpr std::array<std::string_view, 3> kCF = {"CF1", "CF2", "CF3"};
constexpr std::array<std::string_view, 3> kUR = {"UR1", "UR2", "UR3"};
constexpr std::array<std::string_view, 3> kRM = {"RM1", "RM2", "RM3"};
constexpr std::array<std::string_view, 3> kCM = {"CM1", "CM2", "CM3"};
constexpr std::array<std::string_view, 3> kV = {"V1", "V2", "V3"};
constexpr std::array<std::string_view, 3> kVR = {"VR1", "VR2", "VR3"};
constexpr std::array<std::string_view, 3> kA = {"A1", "A2", "A3"};
constexpr std::array<std::string_view, 3> kAR = {"AR1", "AR2", "AR3"};

/// The columns of one nodal variable: which array, which components, which
/// nodes carry it.
struct NodeColumns {
  const std::vector<Vec3>* vec = nullptr;      ///< vector fields
  const std::vector<double>* scalar = nullptr; ///< scalar fields (NT, RFL, CFL): DOF 11
  /// DOFs 12 … of heat-transfer shells (NodeResults::NT_more …), columns 2 … of a scalar field
  const std::vector<double>* more = nullptr;
  std::array<std::string_view, kMaxTemperaturePoints> names{};
  std::array<int, kMaxTemperaturePoints> comp{};
  int n = 0;
  /// Temperature: NT (a DOF or the predefined field); Flux: RFL, CFL (temperature DOFs only)
  enum class Carrier { Displacement, Rotation, Temperature, Flux } carrier = Carrier::Displacement;
};

/// "NT11" … "NT25" (and RFL, CFL): one column per temperature DOF.
struct TemperatureNames {
  std::array<std::string, kMaxTemperaturePoints> text;
  explicit TemperatureNames(std::string_view var) {
    for (int k = 0; k < kMaxTemperaturePoints; ++k) text[k] = fmt::format("{}{}", var, 11 + k);
  }
};

NodeColumns node_columns(const Model& model, const NodeResults& r, NodeVar var) {
  NodeColumns c;
  const int nt = output::n_translations(model.space);
  auto translations = [&](const std::vector<Vec3>& v, const std::array<std::string_view, 3>& nm) {
    c.vec = &v;
    c.n = nt;
    for (int i = 0; i < nt; ++i) {
      c.names[i] = nm[i];
      c.comp[i] = i;
    }
    c.carrier = NodeColumns::Carrier::Displacement;
  };
  auto rotations = [&](const std::vector<Vec3>& v, const std::array<std::string_view, 3>& nm) {
    c.vec = &v;
    c.carrier = NodeColumns::Carrier::Rotation;
    if (model.space == ModelSpace::ThreeD) {
      c.n = 3;
      for (int i = 0; i < 3; ++i) {
        c.names[i] = nm[i];
        c.comp[i] = i;
      }
    } else { // in-plane rotation only
      c.n = 1;
      c.names[0] = nm[2];
      c.comp[0] = 2;
    }
  };
  auto scalar = [&](const std::vector<double>& v, const std::vector<double>& more,
                    std::string_view nm) {
    static const TemperatureNames nt_names("NT"), rfl("RFL"), cfl("CFL");
    const auto& names = nm == "NT" ? nt_names : nm == "RFL" ? rfl : cfl;
    c.scalar = &v;
    c.more = &more;
    c.n = std::clamp(r.temperature_points, 1, kMaxTemperaturePoints);
    for (int k = 0; k < c.n; ++k) c.names[k] = names.text[k];
    c.carrier = nm == "NT" ? NodeColumns::Carrier::Temperature : NodeColumns::Carrier::Flux;
  };
  switch (var) {
  case NodeVar::U:
    translations(r.U, kU);
    break;
  case NodeVar::RF:
    translations(r.RF, kRF);
    break;
  case NodeVar::CF:
    translations(r.CF, kCF);
    break;
  case NodeVar::UR:
    rotations(r.UR, kUR);
    break;
  case NodeVar::RM:
    rotations(r.RM, kRM);
    break;
  case NodeVar::CM:
    rotations(r.CM, kCM);
    break;
  case NodeVar::NT:
    scalar(r.NT, r.NT_more, "NT");
    break;
  case NodeVar::RFL:
    scalar(r.RFL, r.RFL_more, "RFL");
    break;
  case NodeVar::CFL:
    scalar(r.CFL, r.CFL_more, "CFL");
    break;
  case NodeVar::V:
    translations(r.V, kV);
    break;
  case NodeVar::VR:
    rotations(r.VR, kVR);
    break;
  case NodeVar::A:
    translations(r.A, kA);
    break;
  case NodeVar::AR:
    rotations(r.AR, kAR);
    break;
  }
  return c;
}

/// Does the frame hold `var` at all? Velocities and accelerations exist in dynamic steps only;
/// elsewhere a request for them prints nothing (the input layer warned).
bool printable(const NodeResults& r, NodeVar var) {
  switch (var) {
  case NodeVar::V:
    return !r.V.empty();
  case NodeVar::VR:
    return !r.VR.empty();
  case NodeVar::A:
    return !r.A.empty();
  case NodeVar::AR:
    return !r.AR.empty();
  default:
    return true;
  }
}

bool carries(const NodeResults& r, NodeId n, NodeColumns::Carrier carrier) {
  const auto f = output::node_fields(r, n);
  switch (carrier) {
  case NodeColumns::Carrier::Displacement:
    return f.displacement;
  case NodeColumns::Carrier::Rotation:
    return f.rotation;
  case NodeColumns::Carrier::Temperature:
    return f.nt;
  case NodeColumns::Carrier::Flux:
    return f.temperature;
  }
  return false;
}

std::string_view position_text(ElPosition p) {
  return p == ElPosition::IntegrationPoints ? "AT THE INTEGRATION POINTS"
                                            : "AT THE CENTROID OF THE ELEMENT";
}

std::string upper(std::string_view s) {
  std::string u(s);
  for (auto& ch : u) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return u;
}

void reset_summary(std::vector<double>& mx, std::vector<double>& mn, std::vector<double>& tot,
                   std::vector<Label>& mx_at, std::vector<Label>& mn_at, std::size_t n) {
  mx.assign(n, -std::numeric_limits<double>::infinity());
  mn.assign(n, std::numeric_limits<double>::infinity());
  tot.assign(n, 0.0);
  mx_at.assign(n, 0);
  mn_at.assign(n, 0);
}

void track(std::size_t c, double v, Label at, std::vector<double>& mx, std::vector<double>& mn,
           std::vector<double>& tot, std::vector<Label>& mx_at, std::vector<Label>& mn_at) {
  if (std::isnan(v)) return;
  if (v > mx[c]) {
    mx[c] = v;
    mx_at[c] = at;
  }
  if (v < mn[c]) {
    mn[c] = v;
    mn_at[c] = at;
  }
  tot[c] += v;
}

} // namespace

bool DatWriter::fixed_increments(const Step& step) {
  // *STATIC, DIRECT; and transient heat transfer / coupled steps without DELTMX, which the analysis
  // runs with fixed increments of the initial size (fixed_transient_increments in
  // solver/thermal_step.hpp; docs/theory/thermal.md).
  return step.inc.direct ||
         (is_thermal(step.procedure) && !step.inc.steady_state && step.inc.deltmx <= 0.0);
}

DatWriter::DatWriter(std::filesystem::path path) : _path(std::move(path)) {}

void DatWriter::begin(const Model& model) {
  _out.open(_path);
  auto out = std::back_inserter(_out.buffer());
  fmt::format_to(out, "\n\n{:>30}{}\n\n", "", output::spaced("gapfem"));
  fmt::format_to(out, "{:>30}VERSION {}\n\n\n", "", GAPFEM_VERSION);
  if (!model.heading.empty()) {
    std::string_view rest = model.heading;
    while (!rest.empty()) {
      const auto eol = rest.find('\n');
      fmt::format_to(out, " {}\n", rest.substr(0, eol));
      rest = eol == std::string_view::npos ? std::string_view{} : rest.substr(eol + 1);
    }
    fmt::format_to(out, "\n\n");
  }
  if (!model.job_name.empty()) fmt::format_to(out, " JOB NAME    {}\n", model.job_name);
  if (!model.source_files.empty()) fmt::format_to(out, " INPUT DECK  {}\n", model.source_files[0]);
  fmt::format_to(out, "\n\n{:>20}{}\n\n", "", output::spaced("PROBLEM SIZE"));
  fmt::format_to(out, " NUMBER OF ELEMENTS IS {:>24}\n", model.mesh.n_elements());
  fmt::format_to(out, " NUMBER OF NODES IS {:>27}\n", model.mesh.n_nodes());
  fmt::format_to(out, " MODEL SPACE IS {:>31}\n", upper(model_space_name(model.space)));
  fmt::format_to(out, " NUMBER OF STEPS IS {:>27}\n", model.steps.size());
  _out.flush();
}

void DatWriter::begin_step(const Model& model, int step_index) {
  const Step& step = model.steps[step_index];
  auto out = std::back_inserter(_out.buffer());
  fmt::format_to(out, "\n\n\n{:>19}{}{:>5}     {}\n\n", "", output::spaced("STEP"), step.number,
                 output::spaced(fmt::format("{} ANALYSIS", procedure_name(step.procedure))));
  if (!step.name.empty()) fmt::format_to(out, "\n{:>10}{}\n\n", "", step.name);
  if (step.perturbation) {
    write_perturbation_header(step);
    prepare_step(model, step_index);
    _out.flush();
    return;
  }
  const auto& inc = step.inc;
  const double initial = inc.initial > 0 ? std::min(inc.initial, inc.period) : inc.period;
  if (fixed_increments(step)) {
    fmt::format_to(out, "{:>10}FIXED TIME INCREMENTS\n", "");
    fmt::format_to(out, "{:>10}TIME INCREMENT IS {:>35.4E}\n", "", initial);
  } else {
    fmt::format_to(out, "{:>10}AUTOMATIC TIME CONTROL\n", "");
    fmt::format_to(out, "{:>10}INITIAL TIME INCREMENT {:>30.4E}\n", "", initial);
    if (inc.minimum > 0)
      fmt::format_to(out, "{:>10}MINIMUM TIME INCREMENT {:>30.4E}\n", "", inc.minimum);
    fmt::format_to(out, "{:>10}MAXIMUM TIME INCREMENT {:>30.4E}\n", "",
                   inc.maximum > 0 ? inc.maximum : inc.period);
  }
  fmt::format_to(out, "{:>10}TIME PERIOD IS {:>38.4E}\n", "", inc.period);
  fmt::format_to(out, "{:>10}MAXIMUM NUMBER OF INCREMENTS {:>24}\n", "", step.max_increments);
  if (step.nlgeom) fmt::format_to(out, "{:>10}LARGE DISPLACEMENT THEORY (NLGEOM)\n", "");
  if (is_thermal(step.procedure))
    fmt::format_to(out, "{:>10}{}\n", "", inc.steady_state ? "STEADY STATE" : "TRANSIENT");
  prepare_step(model, step_index);
  _out.flush();
}

void DatWriter::prepare_step(const Model& model, int step_index) {
  const Step& step = model.steps[step_index];
  _node_lists.clear();
  for (const auto& req : step.node_prints)
    _node_lists.push_back(output::request_nodes_by_label(model, req.nset, req.nodes));
  _elem_lists.clear();
  for (const auto& req : step.el_prints)
    _elem_lists.push_back(output::request_elements_by_type(model, req.elset, req.elements));
  _printed_increment = -1;
}

void DatWriter::save_state(ArchiveWriter& a) {
  a.pod(static_cast<std::uint64_t>(_out.position()));
  a.pod(_printed_increment);
  a.pod(_printed_dt);
  const std::vector<char> node(_printed_node.begin(), _printed_node.end()),
      el(_printed_el.begin(), _printed_el.end());
  a.vec(node);
  a.vec(el);
}

void DatWriter::resume(const Model& model, int step_index, ArchiveReader& a,
                       const ResumeFiles& from) {
  const auto keep = a.get<std::uint64_t>();
  _out.open_resumed(_path, from.file(".dat"), keep);
  prepare_step(model, step_index);
  a.pod(_printed_increment);
  a.pod(_printed_dt);
  std::vector<char> node, el;
  a.vec(node);
  a.vec(el);
  _printed_node.assign(node.begin(), node.end());
  _printed_el.assign(el.begin(), el.end());
}

void DatWriter::increment(const IncrementInfo&) {
  _out.flush();
} // tail -f, kill -9

void DatWriter::write_increment_header(const Model& model, int step_index, const Frame& frame,
                                       bool repeated) {
  if (frame.mode) {
    write_mode_header(model, frame);
    return;
  }
  auto out = std::back_inserter(_out.buffer());
  if (frame.harmonic) { // *STEADY STATE DYNAMICS: the frame is a frequency
    const std::string heading =
        model.heading.substr(0, std::min<std::size_t>(60, model.heading.find('\n')));
    fmt::format_to(out, "\n\n{:<66}STEP {:>4}  FREQUENCY POINT {:>4}\n\n", heading, frame.step,
                   frame.increment);
    fmt::format_to(out,
                   " EXCITATION FREQUENCY {:>11.4E} CYCLES/TIME; THE NODE TABLES GIVE THE REAL "
                   "PART, THEN THE IMAGINARY PART\n",
                   frame.harmonic->frequency);
    return;
  }
  const std::string heading =
      model.heading.substr(0, std::min<std::size_t>(60, model.heading.find('\n')));
  fmt::format_to(out, "\n\n{:<66}STEP {:>4}  INCREMENT {:>4}\n", heading, frame.step,
                 frame.increment);
  fmt::format_to(out, "{:<66}TIME COMPLETED IN THIS STEP {:>11.4E}\n\n", "", frame.step_time);
  fmt::format_to(out, "\n{:>32}INCREMENT {:>5} SUMMARY\n\n\n", "", frame.increment);
  fmt::format_to(out,
                 " TIME INCREMENT COMPLETED {:>11.4E},  FRACTION OF STEP "
                 "COMPLETED {:>11.4E}\n",
                 repeated ? _printed_dt : frame.dt,
                 output::step_fraction(model, step_index, frame.step_time));
  fmt::format_to(out,
                 " STEP TIME COMPLETED      {:>11.4E},  TOTAL TIME COMPLETED   "
                 "    {:>11.4E}\n",
                 frame.step_time, frame.total_time);
  if (repeated)
    fmt::format_to(out, "\n THE STEP STOPPED EARLY: FINAL OUTPUT OF ITS LAST CONVERGED INCREMENT; "
                        "TABLES ALREADY PRINTED\n FOR THIS INCREMENT ABOVE ARE NOT REPEATED\n");
  else if (frame.last_in_step && frame.dt == 0.0 && frame.increment > 0)
    fmt::format_to(out,
                   "\n THE STEP STOPPED EARLY: FINAL OUTPUT OF ITS LAST CONVERGED INCREMENT\n");
}

void DatWriter::frame(const Model& model, int step_index, const Frame& frame) {
  const Step& step = model.steps[step_index];
  FE_CHECK(_node_lists.size() == step.node_prints.size() &&
               _elem_lists.size() == step.el_prints.size(),
           "DatWriter::frame called without begin_step for this step");
  // A step that stops early hands its last converged increment over again as the final frame
  // (Frame::last_in_step): print only the requests not printed for that increment yet.
  const bool repeated = frame.increment == _printed_increment;
  std::vector<bool> node_due(step.node_prints.size()), el_due(step.el_prints.size());
  bool any_node = false, any_el = false;
  for (std::size_t k = 0; k < step.node_prints.size(); ++k) {
    const auto& vars = step.node_prints[k].vars;
    node_due[k] =
        k < frame.node_print_due.size() && frame.node_print_due[k] &&
        !(repeated && _printed_node[k]) &&
        std::any_of(vars.begin(), vars.end(), [&](NodeVar v) { return printable(frame.nodes, v); });
    any_node |= node_due[k];
  }
  for (std::size_t k = 0; k < step.el_prints.size(); ++k) {
    el_due[k] =
        k < frame.el_print_due.size() && frame.el_print_due[k] && !(repeated && _printed_el[k]);
    any_el |= el_due[k];
  }
  if (!any_node && !any_el) return;

  write_increment_header(model, step_index, frame, repeated);
  if (!repeated) {
    _printed_increment = frame.increment;
    _printed_dt = frame.dt;
    _printed_node.assign(step.node_prints.size(), false);
    _printed_el.assign(step.el_prints.size(), false);
  }
  if (any_el) {
    fmt::format_to(std::back_inserter(_out.buffer()), "\n\n{:>29}{}\n", "",
                   output::spaced("ELEMENT OUTPUT"));
    for (std::size_t k = 0; k < step.el_prints.size(); ++k)
      if (el_due[k]) {
        write_element_tables(model, frame, step.el_prints[k], _elem_lists[k]);
        _printed_el[k] = true;
      }
  }
  if (any_node) {
    fmt::format_to(std::back_inserter(_out.buffer()), "\n\n{:>39}{}\n", "",
                   output::spaced("NODE OUTPUT"));
    for (std::size_t k = 0; k < step.node_prints.size(); ++k)
      if (node_due[k]) {
        for (NodeVar var : step.node_prints[k].vars)
          write_node_table(model, frame, step.node_prints[k], _node_lists[k], var);
        _printed_node[k] = true;
      }
    if (frame.harmonic) write_imaginary_tables(model, step, frame, node_due);
  }
  _out.flush();
}

void DatWriter::write_imaginary_tables(const Model& model, const Step& step, const Frame& frame,
                                       const std::vector<bool>& node_due) {
  Frame im;
  im.nodes = frame.nodes;
  im.nodes.U = frame.harmonic->U;
  im.nodes.UR = frame.harmonic->UR;
  fmt::format_to(std::back_inserter(_out.buffer()), "\n\n{:>30}{}\n", "",
                 output::spaced("IMAGINARY PART"));
  for (std::size_t k = 0; k < step.node_prints.size(); ++k)
    if (node_due[k])
      for (NodeVar var : step.node_prints[k].vars)
        if (var == NodeVar::U || var == NodeVar::UR)
          write_node_table(model, im, step.node_prints[k], _node_lists[k], var);
}

void DatWriter::write_node_table(const Model& model, const Frame& frame,
                                 const NodePrintRequest& request, const std::vector<NodeId>& nodes,
                                 NodeVar var) {
  const NodeResults& r = frame.nodes;
  if (!printable(r, var)) return;
  const NodeColumns cols = node_columns(model, r, var);
  auto& buf = _out.buffer();
  auto out = std::back_inserter(buf);
  const std::size_t n_avail = cols.vec ? cols.vec->size() : cols.scalar->size();

  fmt::format_to(out, "\n\n");
  if (!request.nset.empty())
    fmt::format_to(out,
                   "   THE FOLLOWING TABLE IS PRINTED FOR NODES BELONGING TO "
                   "NODE SET {}\n",
                   upper(request.nset));
  else // no NSET: the input layer lists every node
    fmt::format_to(out, "   THE FOLLOWING TABLE IS PRINTED FOR ALL NODES\n");

  // header
  fmt::format_to(out, "\n       NODE FOOT-   ");
  for (int c = 0; c < cols.n; ++c) fmt::format_to(out, "{:<12}", cols.names[c]);
  while (buf.size() && buf[buf.size() - 1] == ' ') buf.resize(buf.size() - 1);
  fmt::format_to(out, "\n            NOTE\n\n");

  reset_summary(_max, _min, _total, _max_at, _min_at, cols.n);
  std::size_t rows = 0;
  for (NodeId n : nodes) {
    if (static_cast<std::size_t>(n) >= n_avail || !carries(r, n, cols.carrier)) continue;
    const EntityLabel label = model.node_label(n);
    const std::size_t mark = buf.size();
    fmt::format_to(out, "{:>11}    ", label);
    // GLOBAL=YES: global components at *TRANSFORM nodes too (default: their local system)
    const Vec3 vec = !cols.vec        ? Vec3{}
                     : request.global ? r.global(n, (*cols.vec)[n])
                                      : (*cols.vec)[n];
    const int n_values = cols.vec ? cols.n : std::clamp(r.temperatures_at(n), 1, cols.n);
    for (int c = 0; c < cols.n; ++c) {
      if (c >= n_values) { // a node with fewer temperatures than a shell's: blank columns
        fmt::format_to(out, "{:>12}", "");
        continue;
      }
      const double v = cols.vec ? vec[cols.comp[c]]
                       : c == 0 ? (*cols.scalar)[n]
                                : (*cols.more)[static_cast<std::size_t>(cols.n - 1) * n + c - 1];
      append_e12(buf, v);
      track(c, v, label.key, _max, _min, _total, _max_at, _min_at);
    }
    buf.push_back('\n');
    ++rows;
    if (request.totals_only) buf.resize(mark);
    _out.maybe_flush();
  }
  if (rows == 0) {
    fmt::format_to(out, "   NO NODE OF THIS SET CARRIES {}: NOTHING TO PRINT\n",
                   node_var_name(var));
    return;
  }
  if (request.summary) {
    fmt::format_to(out, "\n MAXIMUM       ");
    for (int c = 0; c < cols.n; ++c) append_e12(buf, _max[c]);
    fmt::format_to(out, "\n AT NODE       ");
    for (int c = 0; c < cols.n; ++c) fmt::format_to(out, "{:>12}", model.label_of_key(_max_at[c]));
    fmt::format_to(out, "\n\n MINIMUM       ");
    for (int c = 0; c < cols.n; ++c) append_e12(buf, _min[c]);
    fmt::format_to(out, "\n AT NODE       ");
    for (int c = 0; c < cols.n; ++c) fmt::format_to(out, "{:>12}", model.label_of_key(_min_at[c]));
    buf.push_back('\n');
  }
  if (request.totals) {
    fmt::format_to(out, "\n TOTAL         ");
    for (int c = 0; c < cols.n; ++c) append_e12(buf, _total[c]);
    buf.push_back('\n');
  }
}

void DatWriter::write_element_tables(const Model& model, const Frame& frame,
                                     const ElPrintRequest& request,
                                     const std::vector<ElemId>& elements) {
  const auto& types = model.mesh.elem_types;
  std::size_t begin = 0;
  while (begin < elements.size()) {
    std::size_t end = begin + 1;
    while (end < elements.size() && types[elements[end]] == types[elements[begin]] &&
           model.mesh.variant(elements[end]) == model.mesh.variant(elements[begin]))
      ++end;
    const std::span<const ElemId> group(elements.data() + begin, end - begin);
    for (ElemVar var : request.vars) write_element_table(model, frame, request, group, var);
    begin = end;
  }
}

namespace {

/// The section points a request prints from a block with `ns` points per integration point:
/// the requested ones that exist, or by default SNEG and SPOS of a shell and all of a beam.
std::vector<int> printed_section_points(const ElPrintRequest& request, int ns, bool shell) {
  std::vector<int> pts;
  for (int k : request.section_points)
    if (k >= 1 && k <= ns) pts.push_back(k);
  if (!request.section_points.empty()) return pts;
  if (shell) return {1, ns};
  for (int k = 1; k <= ns; ++k) pts.push_back(k);
  return pts;
}

} // namespace

void DatWriter::write_section_rows(const OutputBlock& block, const ElPrintRequest& request,
                                   bool shell, const EntityLabel& label, std::size_t ncols,
                                   bool at_points) {
  auto& buf = _out.buffer();
  auto out = std::back_inserter(buf);
  const std::size_t bn = block.names.size();
  const int ns = block.section_points;
  const auto np = static_cast<int>(std::min<std::size_t>(block.n_points, block.values.size() / bn));
  const int nip = np / ns;
  const std::vector<int> pts = printed_section_points(request, ns, shell);
  if (at_points) {
    for (int p = 0; p < nip; ++p)
      for (int k : pts) {
        fmt::format_to(out, "{:>12}{:>4}{:>4}   ", label, p + 1, k);
        for (std::size_t c = 0; c < ncols; ++c) {
          const double v = block.values[static_cast<std::size_t>(p * ns + k - 1) * bn + c];
          append_e12(buf, v);
          track(c, v, label.key, _max, _min, _total, _max_at, _min_at);
        }
        buf.push_back('\n');
      }
    return;
  }
  // centroidal: each section point averaged over the integration points
  for (int k : pts) {
    fmt::format_to(out, "{:>12}    {:>4}   ", label, k);
    for (std::size_t c = 0; c < ncols; ++c) {
      double v = 0.0;
      for (int p = 0; p < nip; ++p)
        v += block.values[static_cast<std::size_t>(p * ns + k - 1) * bn + c];
      v /= std::max(nip, 1);
      append_e12(buf, v);
      track(c, v, label.key, _max, _min, _total, _max_at, _min_at);
    }
    buf.push_back('\n');
  }
}

void DatWriter::warn_unavailable(const ElPrintRequest& request, ElemVar var,
                                 std::string_view type_name) {
  if (!_unavailable.emplace(request.loc.str(), static_cast<int>(var), std::string(type_name))
           .second)
    return;
  log::warning("{}: {} is not available for element type {}{}; those elements are left out of "
               "its table",
               request.loc.str().empty() ? std::string("*EL PRINT") : request.loc.str(),
               elem_var_name(var), type_name,
               request.elset.empty() ? std::string() : fmt::format(" (set {})", request.elset));
}

void DatWriter::write_element_table(const Model& model, const Frame& frame,
                                    const ElPrintRequest& request, std::span<const ElemId> group,
                                    ElemVar var) {
  // Column names from the first element of the group that reports the variable.
  const OutputBlock* first = nullptr;
  for (ElemId e : group) {
    const ElementResult* res = frame.element(e);
    if (res && (first = res->data.find(var))) break;
  }
  const std::string_view type_name = model.element_type_name(group[0]);
  if (!first || first->names.empty()) {
    warn_unavailable(request, var, type_name);
    return;
  }
  const std::size_t nc = first->names.size();
  const bool whole = is_whole_element_var(var);
  const bool at_points = request.position == ElPosition::IntegrationPoints && !whole;
  const ElementTypeInfo& info = element_info(model.mesh.elem_types[group[0]]);
  const bool nodal =
      request.position == ElPosition::Averaged && var != ElemVar::SF && !whole && info.cell &&
      (info.family == ElementFamily::Continuum || info.family == ElementFamily::HeatTransfer);
  if (nodal) return write_nodal_table(model, frame, request, group, var, *first);

  auto& buf = _out.buffer();
  auto out = std::back_inserter(buf);
  if (!request.elset.empty())
    fmt::format_to(out,
                   "\n\n THE FOLLOWING TABLE IS PRINTED {} FOR ELEMENT TYPE {} "
                   "AND ELEMENT "
                   "SET {}\n",
                   whole ? "FOR THE WHOLE ELEMENT" : position_text(request.position), type_name,
                   upper(request.elset));
  else
    fmt::format_to(out,
                   "\n\n THE FOLLOWING TABLE IS PRINTED FOR ALL ELEMENTS WITH "
                   "TYPE {} {}\n",
                   type_name, whole ? "FOR THE WHOLE ELEMENT" : position_text(request.position));
  if (request.position == ElPosition::Averaged && !whole)
    fmt::format_to(out, " (VALUES AT THE NODES ARE AVERAGED FOR CONTINUUM AND HEAT TRANSFER "
                        "ELEMENTS ONLY: ELEMENT CENTROID VALUES ARE PRINTED)\n");
  const bool sections = first->section_points > 1;
  if (sections) {
    fmt::format_to(out, "\n    ELEMENT  {} SEC FOOT-   ", at_points ? "PT" : "  ");
  } else {
    fmt::format_to(out, "\n    ELEMENT  {} FOOT-       ", at_points ? "PT" : "  ");
  }
  for (auto name : first->names) fmt::format_to(out, "{:<12}", name);
  while (buf.size() && buf[buf.size() - 1] == ' ') buf.resize(buf.size() - 1);
  const std::string_view note =
      sections ? "\n                 PT NOTE\n\n" : "\n                NOTE\n\n";
  buf.append(note);
  const bool shell = element_info(model.mesh.elem_types[group[0]]).family == ElementFamily::Shell;

  reset_summary(_max, _min, _total, _max_at, _min_at, nc);
  for (ElemId e : group) {
    const ElementResult* res = frame.element(e);
    const OutputBlock* block = res ? res->data.find(var) : nullptr;
    if (!block) continue;
    const EntityLabel label = model.element_label(e);
    const std::size_t ncols = std::min(nc, block->names.size());
    if (ncols == 0) continue;
    const std::size_t mark = buf.size();
    if (block->section_points > 1) {
      write_section_rows(*block, request, shell, label, ncols, at_points);
    } else if (at_points) {
      const std::size_t bn = block->names.size();
      const std::size_t np = std::min<std::size_t>(block->n_points, block->values.size() / bn);
      for (std::size_t p = 0; p < np; ++p) {
        fmt::format_to(out, "{:>12}{:>4}       ", label, p + 1);
        for (std::size_t c = 0; c < ncols; ++c) {
          const double v = block->values[p * bn + c];
          append_e12(buf, v);
          track(c, v, label.key, _max, _min, _total, _max_at, _min_at);
        }
        buf.push_back('\n');
      }
    } else {
      output::average_block(*block, _avg);
      fmt::format_to(out, "{:>12}           ", label);
      for (std::size_t c = 0; c < ncols; ++c) {
        append_e12(buf, _avg[c]);
        track(c, _avg[c], label.key, _max, _min, _total, _max_at, _min_at);
      }
      buf.push_back('\n');
    }
    if (request.totals_only) buf.resize(mark);
    _out.maybe_flush();
  }
  write_column_summary(model, request, nc, "ELEMENT");
}

void DatWriter::write_column_summary(const Model& model, const ElPrintRequest& request,
                                     std::size_t nc, std::string_view entity) {
  auto& buf = _out.buffer();
  auto out = std::back_inserter(buf);
  if (request.summary) {
    fmt::format_to(out, "\n MAXIMUM               ");
    for (std::size_t c = 0; c < nc; ++c) append_e12(buf, _max[c]);
    fmt::format_to(out, "\n {:<22}", entity);
    for (std::size_t c = 0; c < nc; ++c)
      fmt::format_to(out, "{:>12}", model.label_of_key(_max_at[c]));
    fmt::format_to(out, "\n\n MINIMUM               ");
    for (std::size_t c = 0; c < nc; ++c) append_e12(buf, _min[c]);
    fmt::format_to(out, "\n {:<22}", entity);
    for (std::size_t c = 0; c < nc; ++c)
      fmt::format_to(out, "{:>12}", model.label_of_key(_min_at[c]));
    buf.push_back('\n');
  }
  if (request.totals) {
    fmt::format_to(out, "\n TOTAL                 ");
    for (std::size_t c = 0; c < nc; ++c) append_e12(buf, _total[c]);
    buf.push_back('\n');
  }
}

void DatWriter::write_nodal_table(const Model& model, const Frame& frame,
                                  const ElPrintRequest& request, std::span<const ElemId> group,
                                  ElemVar var, const OutputBlock& first) {
  std::vector<char> mask(static_cast<std::size_t>(model.mesh.n_elements()), 0);
  for (ElemId e : group) mask[static_cast<std::size_t>(e)] = 1;
  const output::NodalField f = _averager.average(model, frame, var, &mask);
  const std::size_t nc = first.names.size();
  std::vector<int> slot(nc);
  for (std::size_t c = 0; c < nc; ++c) slot[c] = output::nodal_slot(first.names[c], f.width);
  std::vector<NodeId> nodes;
  for (NodeId n = 0; n < model.mesh.n_nodes(); ++n)
    if (f.count[static_cast<std::size_t>(n)] > 0) nodes.push_back(n);
  std::sort(nodes.begin(), nodes.end(), [&](NodeId a, NodeId b) {
    return model.mesh.node_labels[a] < model.mesh.node_labels[b];
  });
  auto& buf = _out.buffer();
  auto out = std::back_inserter(buf);
  const std::string_view type_name = model.element_type_name(group[0]);
  if (!request.elset.empty())
    fmt::format_to(out,
                   "\n\n THE FOLLOWING TABLE IS PRINTED AVERAGED AT THE NODES FOR ELEMENT "
                   "TYPE {} AND ELEMENT SET {}\n",
                   type_name, upper(request.elset));
  else
    fmt::format_to(out,
                   "\n\n THE FOLLOWING TABLE IS PRINTED FOR ALL ELEMENTS WITH TYPE {} "
                   "AVERAGED AT THE NODES\n",
                   type_name);
  fmt::format_to(out, "\n       NODE FOOT-       ");
  for (auto name : first.names) fmt::format_to(out, "{:<12}", name);
  while (buf.size() && buf[buf.size() - 1] == ' ') buf.resize(buf.size() - 1);
  buf.append(std::string_view("\n            NOTE\n\n"));
  reset_summary(_max, _min, _total, _max_at, _min_at, nc);
  for (NodeId n : nodes) {
    const EntityLabel label = model.node_label(n);
    const std::size_t mark = buf.size();
    fmt::format_to(out, "{:>12}           ", label);
    for (std::size_t c = 0; c < nc; ++c) {
      const double v =
          slot[c] < 0 ? 0.0
                      : f.values[static_cast<std::size_t>(n) * static_cast<std::size_t>(f.width) +
                                 static_cast<std::size_t>(slot[c])];
      append_e12(buf, v);
      track(c, v, label.key, _max, _min, _total, _max_at, _min_at);
    }
    buf.push_back('\n');
    if (request.totals_only) buf.resize(mark);
    _out.maybe_flush();
  }
  write_column_summary(model, request, nc, "NODE");
}

} // namespace gapfem
