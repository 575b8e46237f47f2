#include "solver/substructure_recovery.hpp"

#include "common/error.hpp"
#include "common/log.hpp"
#include "fem/assembler.hpp"
#include "fem/discretization.hpp"
#include "linalg/constrained_solver.hpp"
#include "model/model.hpp"
#include "model/substructure_file.hpp"
#include "solver/analysis.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <map>

namespace gapfem {

/// The recovery data of one library file: K_II factorised, and the generation model when its
/// deck is there and unchanged (for stresses).
struct SubstructureRecoverer::Library {
  SubstructureLibrary lib;
  std::unique_ptr<ConstrainedFactor> factor; ///< of K_II (none without internal DOFs)
  std::unique_ptr<Model> model;
  std::unique_ptr<Discretization> disc;
  std::unique_ptr<Assembler> assembler;
  std::string note; ///< why there are no stresses ("" when there are)
};

namespace {

using Library = SubstructureRecoverer::Library;

/// K_II of the library, factorised through the solver seam.
void factorise_internal(Library& d) {
  const SubstructureRecovery& r = d.lib.recovery;
  const auto nI = r.internal_node.size();
  if (nI == 0) return;
  auto pattern = std::make_shared<SparsityPattern>();
  pattern->n = static_cast<LocalIndex>(nI);
  pattern->row_ptr.assign(r.ii_ptr.begin(), r.ii_ptr.end());
  pattern->col.assign(r.ii_col.begin(), r.ii_col.end());
  CsrMatrix K(pattern);
  std::copy(r.ii_val.begin(), r.ii_val.end(), K.values().begin());
  // the serial backend, as at the generation (every rank recovers alike)
  const auto solver = make_constrained_solver("cholmod");
  solver->analyze(pattern);
  d.factor = solver->factorize(K, ConstraintBlock{}, true);
}

/// The generation model, for stresses: its deck as it was when the library was written.
void read_generation_model(Library& d, const DeckReader& read_deck) {
  if (!read_deck) {
    d.note = "the generation deck is not read in this run: displacements only";
    return;
  }
  try {
    d.model = read_deck(d.lib.deck);
    d.disc = std::make_unique<Discretization>(*d.model);
    if (model_fingerprint(*d.model, *d.disc) != d.lib.fingerprint) {
      d.note = fmt::format("the generation deck '{}' has changed since the substructure was "
                           "generated: displacements only",
                           d.lib.deck);
      d.disc.reset();
      d.model.reset();
    } else {
      d.assembler = std::make_unique<Assembler>(*d.disc, 1);
    }
  } catch (const std::exception& e) {
    d.note = fmt::format("the generation deck '{}' cannot be read ({}): displacements only",
                         d.lib.deck, e.what());
    d.disc.reset();
    d.model.reset();
  }
}

std::shared_ptr<const Library> load(const SubstructureType& t, const DeckReader& read_deck) {
  auto d = std::make_shared<Library>();
  try {
    d->lib = read_substructure_file(t.file, true);
  } catch (const SubstructureFileError& e) {
    throw AnalysisError(fmt::format("substructure recovery: {}", e.what()));
  }
  if (!d->lib.has_recovery)
    throw AnalysisError(fmt::format("substructure recovery: '{}' holds no recovery data (it was "
                                    "generated with RECOVERY MATRIX=NO)",
                                    t.file));
  factorise_internal(*d);
  read_generation_model(*d, read_deck);
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

/// The average of an output block's components over its points.
std::vector<double> point_average(const OutputBlock& blk) {
  const std::size_t nc = blk.names.size();
  std::vector<double> avg(nc, 0.0);
  const std::size_t np = nc > 0 ? std::min<std::size_t>(blk.n_points, blk.values.size() / nc) : 0;
  for (std::size_t p = 0; p < np; ++p)
    for (std::size_t c = 0; c < nc; ++c) avg[c] += blk.values[p * nc + c];
  if (np > 0)
    for (double& v : avg) v /= static_cast<double>(np);
  return avg;
}

/// Stresses and strains (averaged over the points) of the generation model's elements at the
/// recovered nodal values.
void element_results(const Library& d, RecoveredSubstructure& out) {
  const Model& gm = *d.model;
  const DofMap& dofs = d.disc->dofs();
  std::vector<double> u(static_cast<std::size_t>(dofs.n_slots()), 0.0);
  for (const auto& [node, x] : out.nodes) {
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
  const FieldView fields{u, u, T0, T0, T0, {}, {}, {}};
  StepContext ctx;
  ctx.space = gm.space;
  ctx.model_size = gm.model_size();
  ctx.constants = &gm.constants;
  ctx.increment = 1;
  ElementRecovery er;
  for (ElemId e = 0; e < gm.mesh.n_elements(); ++e) {
    d.assembler->recover(e, fields, ctx, er);
    RecoveredSubstructure::Element el{
        gm.element_label(e).str(), std::string(gm.element_type_name(e)), {}};
    for (const OutputBlock& blk : er.blocks) {
      if (blk.var != ElemVar::S && blk.var != ElemVar::E) continue;
      el.averages.emplace_back(blk.var, point_average(blk));
    }
    out.elements.push_back(std::move(el));
  }
}

} // namespace

SubstructureRecoverer::SubstructureRecoverer(const Model& model, const DeckReader& read_deck) {
  std::map<std::string, std::shared_ptr<const Library>> by_file;
  for (const Step& s : model.steps)
    for (ElemId e : s.recover_substructures) {
      if (std::any_of(_elements.begin(), _elements.end(),
                      [&](const Element& r) { return r.elem == e; }))
        continue;
      const SubstructureType& t = model.substructures[model.mesh.variant(e)];
      Element el;
      el.elem = e;
      const SubstructureProperty& p =
          model.substructure_properties[model.element_property[e].index];
      el.R = p.rotation;
      const auto& R = p.rotation;
      el.det = R[0] * (R[4] * R[8] - R[5] * R[7]) - R[1] * (R[3] * R[8] - R[5] * R[6]) +
               R[2] * (R[3] * R[7] - R[4] * R[6]);
      auto& lib = by_file[t.file];
      if (!lib) lib = load(t, read_deck);
      el.lib = lib;
      _elements.push_back(std::move(el));
    }
}

SubstructureRecoverer::~SubstructureRecoverer() = default;

std::vector<RecoveredSubstructure>
SubstructureRecoverer::recover(const Model& model, int step_index, const Frame& f) const {
  std::vector<RecoveredSubstructure> out;
  const Step& step = model.steps[step_index];
  for (const Element& el : _elements)
    if (std::find(step.recover_substructures.begin(), step.recover_substructures.end(), el.elem) !=
        step.recover_substructures.end())
      out.push_back(recover_one(model, el, f));
  return out;
}

RecoveredSubstructure SubstructureRecoverer::recover_one(const Model& model, const Element& el,
                                                         const Frame& f) const {
  const Library& d = *el.lib;
  const SubstructureType& t = d.lib.type;
  const SubstructureRecovery& rec = d.lib.recovery;
  RecoveredSubstructure out;
  out.elem = el.elem;
  out.label = model.element_label(el.elem).str();
  out.type = t.name;
  out.library = t.file;
  out.deck = d.lib.deck;
  out.stresses = d.assembler != nullptr;
  out.note = d.note;
  // the retained values in the substructure's own directions: v_gen = T^T v_usage
  const auto nodes = model.mesh.element_nodes(el.elem);
  std::vector<double> uR;
  std::vector<std::pair<Label, int>> retained;
  for (std::size_t a = 0; a < t.node_dofs.size(); ++a)
    for (int dof : t.node_dofs[a]) {
      double v = 0.0;
      if (dof > 6) {
        v = usage_value(model, f, nodes[a], dof);
      } else {
        const int group = (dof - 1) / 3, row = (dof - 1) % 3;
        const double sign = group == 1 ? el.det : 1.0;
        for (int i = 0; i < 3; ++i) // (R^T)_{row,i} = R_{i,row}
          v += sign * el.R[i * 3 + row] * usage_value(model, f, nodes[a], 3 * group + i + 1);
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
  if (nI > 0) d.factor->solve(b, {}, uI, {});
  if (d.model) // every node of the substructure, fixed ones too
    for (Label l : d.model->mesh.node_labels) out.nodes[l] = {};
  auto put = [&](Label node, int dof, double v) {
    out.nodes[node][static_cast<std::size_t>(dof <= 6 ? dof - 1 : 6)] = v;
  };
  for (std::size_t k = 0; k < retained.size(); ++k)
    put(retained[k].first, retained[k].second, uR[k]);
  for (std::size_t i = 0; i < nI; ++i) put(rec.internal_node[i], rec.internal_dof[i], uI[i]);
  if (d.assembler) element_results(d, out);
  return out;
}

} // namespace gapfem
