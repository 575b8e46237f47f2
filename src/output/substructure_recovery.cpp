#include "output/substructure_recovery.hpp"

#include "common/log.hpp"
#include "common/safe_file.hpp"
#include "fem/assembler.hpp"
#include "fem/discretization.hpp"
#include "io/inp/reader.hpp"
#include "linalg/linear_solver.hpp"
#include "model/model.hpp"
#include "model/substructure_file.hpp"
#include "output/output_file.hpp"
#include "solver/analysis.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fmt/format.h>
#include <map>

namespace gapfem {

/// The recovery data of one library file: K_II factorised, and the generation model when its
/// deck is there and unchanged (for stresses).
struct RecoveryData {
  SubstructureLibrary lib;
  std::shared_ptr<SparsityPattern> pattern;
  std::unique_ptr<LinearSolver> solver;
  std::unique_ptr<Model> model;
  std::unique_ptr<Discretization> disc;
  std::unique_ptr<Assembler> assembler;
  std::string note; ///< why there are no stresses ("" when there are)
};

struct SubstructureRecoveryWriter::Recovered {
  ElemId elem = -1;
  std::string label, type;
  std::array<double, 9> R{};
  double det = 1.0;
  std::shared_ptr<RecoveryData> data;
  fmt::memory_buffer frames; ///< the frames so far, comma separated
  bool any = false;
  std::filesystem::path file;
};

namespace {

std::shared_ptr<RecoveryData> load(const SubstructureType& t) {
  auto d = std::make_shared<RecoveryData>();
  try {
    d->lib = read_substructure_file(t.file, true);
  } catch (const SubstructureFileError& e) {
    throw AnalysisError(fmt::format("substructure recovery: {}", e.what()));
  }
  if (!d->lib.has_recovery)
    throw AnalysisError(fmt::format("substructure recovery: '{}' holds no recovery data (it was "
                                    "generated with RECOVERY MATRIX=NO)",
                                    t.file));
  const SubstructureRecovery& r = d->lib.recovery;
  const auto nI = r.internal_node.size();
  if (nI > 0) {
    d->pattern = std::make_shared<SparsityPattern>();
    d->pattern->n = static_cast<LocalIndex>(nI);
    d->pattern->row_ptr.assign(r.ii_ptr.begin(), r.ii_ptr.end());
    d->pattern->col.assign(r.ii_col.begin(), r.ii_col.end());
    CsrMatrix K(d->pattern);
    std::copy(r.ii_val.begin(), r.ii_val.end(), K.values().begin());
    d->solver = make_cholmod_solver();
    d->solver->analyze(*d->pattern);
    d->solver->factorize(K);
  }
  // the generation model, for stresses: its deck as it was when the library was written
  try {
    d->model = std::make_unique<Model>(read_deck(d->lib.deck));
    d->disc = std::make_unique<Discretization>(*d->model);
    if (model_fingerprint(*d->model, *d->disc) != d->lib.fingerprint) {
      d->note = fmt::format("the generation deck '{}' has changed since the substructure was "
                            "generated: displacements only",
                            d->lib.deck);
      d->disc.reset();
      d->model.reset();
    } else {
      d->assembler = std::make_unique<Assembler>(*d->disc, 1);
    }
  } catch (const std::exception& e) {
    d->note = fmt::format("the generation deck '{}' cannot be read ({}): displacements only",
                          d->lib.deck, e.what());
    d->disc.reset();
    d->model.reset();
  }
  if (!d->note.empty()) log::warning("substructure {}: {}", t.name, d->note);
  return d;
}

/// The value of an element node's DOF in the usage frame, in global directions.
double usage_value(const Model& model, const Frame& f, NodeId n, int dof) {
  const NodeResults& nr = f.nodes;
  if (dof > 6) return dof == 11 ? nr.NT[n] : 0.0;
  const Vec3& v = dof <= 3 ? nr.U[n] : nr.UR[n];
  const int c = (dof - 1) % 3;
  if (const auto axes = model.node_axes(n)) { // a *TRANSFORM node: the frame holds local values
    double g = 0.0;
    for (int i = 0; i < 3; ++i) g += (*axes)[i * 3 + c] * v[i];
    return g;
  }
  return v[c];
}

} // namespace

SubstructureRecoveryWriter::SubstructureRecoveryWriter(std::filesystem::path directory,
                                                       std::string job)
    : _dir(std::move(directory)), _job(std::move(job)) {}

SubstructureRecoveryWriter::~SubstructureRecoveryWriter() = default;

void SubstructureRecoveryWriter::begin(const Model& model) {
  _elements.clear();
  std::map<std::string, std::shared_ptr<RecoveryData>> by_file;
  for (const Step& s : model.steps)
    for (ElemId e : s.recover_substructures) {
      if (std::any_of(_elements.begin(), _elements.end(),
                      [&](const auto& r) { return r->elem == e; }))
        continue;
      const SubstructureType& t = model.substructures[model.mesh.variant(e)];
      auto rec = std::make_unique<Recovered>();
      rec->elem = e;
      rec->label = model.element_label(e).str();
      rec->type = t.name;
      const PropertyRef ref = model.element_property[e];
      const SubstructureProperty& p = model.substructure_properties[ref.index];
      rec->R = p.rotation;
      const auto& R = p.rotation;
      rec->det = R[0] * (R[4] * R[8] - R[5] * R[7]) - R[1] * (R[3] * R[8] - R[5] * R[6]) +
                 R[2] * (R[3] * R[7] - R[4] * R[6]);
      auto& data = by_file[t.file];
      if (!data) data = load(t);
      rec->data = data;
      std::string label = rec->label;
      std::replace(label.begin(), label.end(), '.', '_');
      rec->file = _dir / fmt::format("{}_{}_{}.results.json", _job, t.name, label);
      _elements.push_back(std::move(rec));
    }
}

void SubstructureRecoveryWriter::frame(const Model& model, int step_index, const Frame& f) {
  const Step& step = model.steps[step_index];
  if (!f.field_due && !f.last_in_step) return;
  for (auto& rp : _elements) {
    Recovered& r = *rp;
    if (std::find(step.recover_substructures.begin(), step.recover_substructures.end(), r.elem) ==
        step.recover_substructures.end())
      continue;
    const RecoveryData& d = *r.data;
    const SubstructureType& t = d.lib.type;
    const SubstructureRecovery& rec = d.lib.recovery;
    // the retained values in the substructure's own directions: v_gen = T^T v_usage
    const auto nodes = model.mesh.element_nodes(r.elem);
    std::vector<double> uR;
    std::vector<std::pair<Label, int>> retained;
    for (std::size_t a = 0; a < t.node_dofs.size(); ++a)
      for (int dof : t.node_dofs[a]) {
        double v = 0.0;
        if (dof > 6) {
          v = usage_value(model, f, nodes[a], dof);
        } else {
          const int group = (dof - 1) / 3, row = (dof - 1) % 3;
          const double sign = group == 1 ? r.det : 1.0;
          for (int i = 0; i < 3; ++i) // (R^T)_{row,i} = R_{i,row}
            v += sign * r.R[i * 3 + row] * usage_value(model, f, nodes[a], 3 * group + i + 1);
        }
        uR.push_back(v);
        retained.emplace_back(t.node_labels[a], dof);
      }
    // u_I = -K_II^-1 K_IR u_R
    const std::size_t nI = rec.internal_node.size();
    std::vector<double> b(nI, 0.0), uI(nI, 0.0);
    for (std::size_t i = 0; i < nI; ++i)
      for (std::int64_t k = rec.ir_ptr[i]; k < rec.ir_ptr[i + 1]; ++k)
        b[i] -= rec.ir_val[k] * uR[static_cast<std::size_t>(rec.ir_col[k])];
    if (nI > 0) d.solver->solve(b, uI);
    // nodal vectors by node label
    std::map<Label, std::array<double, 7>> values; // U1-3, UR1-3, NT
    if (d.model)                                   // every node of the substructure, fixed ones too
      for (Label l : d.model->mesh.node_labels) values[l] = {};
    auto put = [&](Label node, int dof, double v) {
      auto& x = values[node];
      x[static_cast<std::size_t>(dof <= 6 ? dof - 1 : 6)] = v;
    };
    for (std::size_t k = 0; k < retained.size(); ++k)
      put(retained[k].first, retained[k].second, uR[k]);
    for (std::size_t i = 0; i < nI; ++i) put(rec.internal_node[i], rec.internal_dof[i], uI[i]);
    auto& out = r.frames;
    if (r.any) out.push_back(',');
    r.any = true;
    fmt::format_to(
        fmt::appender(out),
        "\n{{\"step\":{},\"increment\":{},\"step_time\":{},\"total_time\":{},\"nodes\":{{", f.step,
        f.increment, f.step_time, f.total_time);
    bool first = true;
    for (const auto& [node, x] : values) {
      fmt::format_to(fmt::appender(out), "{}\"{}\":{{\"U\":", first ? "" : ",", node);
      output::append_json_array(out, std::span<const double>(x.data(), 3));
      out.append(std::string_view(",\"UR\":"));
      output::append_json_array(out, std::span<const double>(x.data() + 3, 3));
      out.push_back('}');
      first = false;
    }
    out.push_back('}');
    if (d.assembler) { // stresses and strains of the substructure's elements
      const Model& gm = *d.model;
      const DofMap& dofs = d.disc->dofs();
      std::vector<double> u(static_cast<std::size_t>(dofs.n_slots()), 0.0);
      for (const auto& [node, x] : values) {
        const NodeId n = gm.mesh.find_node(node);
        if (n < 0) continue;
        for (int c = 0; c < 7; ++c) {
          const DofType dt = c < 6 ? static_cast<DofType>(c) : DofType::NT;
          const LocalIndex s = dofs.slot(n, dt);
          if (s >= 0) u[static_cast<std::size_t>(s)] = x[static_cast<std::size_t>(c)];
        }
      }
      std::vector<double> T0 = gm.initial_temperature;
      T0.resize(static_cast<std::size_t>(gm.mesh.n_nodes()), 0.0);
      const FieldView fields{u, u, T0, T0, T0, {}};
      StepContext ctx;
      ctx.space = gm.space;
      ctx.model_size = gm.model_size();
      ctx.constants = &gm.constants;
      ctx.increment = 1;
      out.append(std::string_view(",\"elements\":{"));
      ElementRecovery er;
      std::vector<double> avg;
      for (ElemId e = 0; e < gm.mesh.n_elements(); ++e) {
        d.assembler->recover(e, fields, ctx, er);
        fmt::format_to(fmt::appender(out), "{}\"{}\":{{\"type\":\"{}\"", e ? "," : "",
                       gm.element_label(e), gm.element_type_name(e));
        for (const OutputBlock& blk : er.blocks) {
          if (blk.var != ElemVar::S && blk.var != ElemVar::E) continue;
          output::average_block(blk, avg);
          fmt::format_to(fmt::appender(out), ",\"{}\":", elem_var_name(blk.var));
          output::append_json_array(out, avg);
        }
        out.push_back('}');
      }
      out.push_back('}');
    }
    out.push_back('}');
    write(r);
  }
}

void SubstructureRecoveryWriter::write(const Recovered& r) const {
  const RecoveryData& d = *r.data;
  fmt::memory_buffer doc;
  fmt::format_to(fmt::appender(doc), "{{\"schema\":\"gapfem.substructure_recovery/1\",\"job\":");
  output::append_json_string(doc, _job);
  fmt::format_to(fmt::appender(doc), ",\"element\":");
  output::append_json_string(doc, r.label);
  fmt::format_to(fmt::appender(doc), ",\"substructure\":");
  output::append_json_string(doc, r.type);
  fmt::format_to(fmt::appender(doc), ",\"library\":");
  output::append_json_string(doc, d.lib.type.file);
  fmt::format_to(fmt::appender(doc), ",\"generation_deck\":");
  output::append_json_string(doc, d.lib.deck);
  fmt::format_to(fmt::appender(doc), ",\"stresses\":{},\"note\":", d.assembler ? "true" : "false");
  output::append_json_string(doc, d.note);
  doc.append(std::string_view(",\"frames\":["));
  doc.append(r.frames.data(), r.frames.data() + r.frames.size());
  doc.append(std::string_view("\n]}\n"));
  // aside, then renamed: the file is always one complete document (never through a link)
  if (!files::write_replace(r.file, std::string_view(doc.data(), doc.size())))
    throw AnalysisError(fmt::format("cannot write '{}': {}; free space and run again",
                                    r.file.string(), std::strerror(errno)));
}

void SubstructureRecoveryWriter::end(const Model&, const RunSummary&) {}

} // namespace gapfem
