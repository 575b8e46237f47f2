/// @file substructure_generate.cpp
/// A *SUBSTRUCTURE GENERATE step (docs/substructures.md): the static (Guyan) reduction of the
/// model's linear stiffness onto the retained DOFs, S = K_RR - K_RI K_II^-1 K_IR, exact for the
/// linear static response; written with the recovery data to the substructure library file.
#include "common/log.hpp"
#include "model/substructure_file.hpp"
#include "solver/analysis_impl.hpp"
#include "solver/substructure_mass.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace gapfem {
namespace {

/// Equation blocks of a generation step: per free equation, its retained index or internal index.
struct Partition {
  std::vector<LocalIndex> retained_eq; ///< per retained DOF (element order): its equation
  std::vector<LocalIndex> internal_eq; ///< per internal DOF: its equation
  std::vector<LocalIndex> index;       ///< per equation: retained index + 1, or 0 (internal)
  std::vector<LocalIndex> ret_index;   ///< per equation: its retained index, or -1
  std::vector<LocalIndex> int_index;   ///< per equation: its internal index, or -1
};

/// What the stages of a generation step read and name in their messages.
struct Generation {
  const Model& model;
  const DofMap& dofs;
  const EquationMap& eqmap;
  const SubstructureGeneration& g;
  std::string what; ///< "TYPE=name", the messages' entity
};

/// The rows `rows` and columns (by `col_index`, >= 0 kept) of a CSR matrix, in compressed rows.
void extract(const CsrMatrix& K, std::span<const LocalIndex> rows,
             std::span<const LocalIndex> col_index, std::vector<std::int64_t>& ptr,
             std::vector<std::int32_t>& col, std::vector<double>& val) {
  const SparsityPattern& p = K.pattern();
  const auto v = K.values();
  ptr.assign(1, 0);
  for (LocalIndex r : rows) {
    for (LocalIndex k = p.row_ptr[r]; k < p.row_ptr[r + 1]; ++k) {
      const LocalIndex c = col_index[p.col[k]];
      if (c < 0 || v[k] == 0.0) continue;
      col.push_back(c);
      val.push_back(v[k]);
    }
    ptr.push_back(static_cast<std::int64_t>(col.size()));
  }
}

/// What a linear reduction cannot hold: gaps, history, linear constraints, loads, no retained
/// DOFs, prescribed non-zero displacements (InputError at the *SUBSTRUCTURE GENERATE line).
void require_reducible(const Model& model, const Discretization& disc, const Step& step,
                       const std::string& what) {
  const SubstructureGeneration& g = *step.generation;
  const SourceLocation& at = g.loc;
  if (disc.has_gaps())
    throw InputError(at, what,
                     "gap elements respond nonlinearly and cannot be inside a substructure; keep "
                     "them in the model that uses it (they connect to its retained nodes)");
  for (const ElementBlock& b : disc.blocks())
    if (b.n_mult > 0 || b.n_state > 0)
      throw InputError(at, what,
                       fmt::format("{} elements carry a history and cannot be reduced to a linear "
                                   "substructure; keep them in the model that uses it",
                                   model.element_type_name(b.elements.front())));
  for (int k = 0; k < disc.constraints().n_rows(); ++k)
    if (disc.constraints().active(k))
      throw InputError(
          at, what,
          "linear constraints (*EQUATION, *MPC, couplings, ties) inside a substructure "
          "are not reduced by gapfem; apply them in the model that uses it");
  if (!step.cloads.empty() || !step.dloads.empty() || !step.temperatures.empty())
    throw InputError(at, what,
                     "a generation step reduces the stiffness only; its loads would need "
                     "*SUBSTRUCTURE LOAD CASE, which gapfem does not read: apply the loads in the "
                     "model that uses the substructure");
  if (g.retained.empty())
    throw InputError(at, what, "no DOFs are retained; list them with *RETAINED NODAL DOFS");
  for (const BoundaryEntry& b : step.boundary)
    if (b.value != 0.0)
      throw InputError(b.loc, what,
                       "a generation step takes fixed (zero) boundary conditions only; prescribe "
                       "the displacement in the model that uses the substructure");
}

/// The DOFs a retained node's entry names (all it carries when none are given), each free;
/// InputError otherwise.
std::vector<int> retained_dofs(const Generation& gen, NodeId node, const std::vector<int>& given) {
  const auto& [model, dofs, eqmap, g, what] = gen;
  std::vector<int> list = given;
  if (list.empty()) // the node with every DOF it carries
    for (int d = 0; d < kNumDofTypes; ++d)
      if (dofs.has(node, static_cast<DofType>(d)))
        list.push_back(abaqus_number(static_cast<DofType>(d)));
  if (list.empty())
    throw InputError(g.retained_loc, what,
                     fmt::format("node {} carries no DOF: no element of the substructure acts "
                                 "on it; retain nodes of its elements",
                                 model.node_label(node)));
  for (int d : list) {
    DofType dt{};
    dof_from_abaqus(d, dt);
    const LocalIndex slot = dofs.slot(node, dt);
    if (slot < 0)
      throw InputError(g.retained_loc, what,
                       fmt::format("node {} has no DOF {}: no element of the substructure acts "
                                   "on it; retain the DOFs its elements carry",
                                   model.node_label(node), d));
    if (eqmap.slot_eq[slot] < 0)
      throw InputError(g.retained_loc, what,
                       fmt::format("DOF {} of node {} is fixed by a boundary condition of the "
                                   "generation step, so it cannot be retained; retain it free, "
                                   "or fix it in the model that uses the substructure",
                                   d, model.node_label(node)));
  }
  return list;
}

/// The retained equations (in the order *RETAINED NODAL DOFS gives them) and the internal ones;
/// the type's retained nodes with their DOFs.
Partition partition(const Generation& gen, SubstructureType& t) {
  const auto& [model, dofs, eqmap, g, what] = gen;
  Partition part;
  part.index.assign(static_cast<std::size_t>(eqmap.n_eq()), 0);
  for (const auto& [node, given] : g.retained) {
    std::vector<int> kept = retained_dofs(gen, node, given);
    for (int d : kept) {
      DofType dt{};
      dof_from_abaqus(d, dt);
      const LocalIndex eq = eqmap.slot_eq[dofs.slot(node, dt)];
      part.index[eq] = static_cast<LocalIndex>(part.retained_eq.size()) + 1;
      part.retained_eq.push_back(eq);
    }
    if (kept.empty()) continue;
    t.node_labels.push_back(model.mesh.node_labels[node]);
    t.coords.push_back(model.mesh.coords[node]);
    t.node_dofs.push_back(std::move(kept));
  }
  part.ret_index.assign(static_cast<std::size_t>(eqmap.n_eq()), -1);
  part.int_index.assign(part.ret_index.size(), -1);
  for (LocalIndex eq = 0; eq < eqmap.n_eq(); ++eq) {
    if (part.index[eq] > 0) {
      part.ret_index[eq] = part.index[eq] - 1;
      continue;
    }
    part.int_index[eq] = static_cast<LocalIndex>(part.internal_eq.size());
    part.internal_eq.push_back(eq);
  }
  if (part.retained_eq.size() > 16384) // Abaqus's limit too: the reduced stiffness is dense
    throw InputError(g.retained_loc, what,
                     fmt::format("{} DOFs are retained; a substructure retains at most 16,384 (its "
                                 "reduced stiffness is a dense matrix): retain fewer, or split the "
                                 "part into several substructures",
                                 part.retained_eq.size()));
  return part;
}

/// The pattern of K_II (its rows as extracted); InputError naming an internal DOF without a
/// diagonal (no stiffness).
std::shared_ptr<SparsityPattern>
internal_pattern(const Generation& gen, const SubstructureRecovery& rec, const Partition& part) {
  const auto& [model, dofs, eqmap, g, what] = gen;
  const SourceLocation& at = g.loc;
  const std::size_t nI = part.internal_eq.size();
  auto pattern = std::make_shared<SparsityPattern>();
  pattern->n = static_cast<LocalIndex>(nI);
  pattern->row_ptr.assign(rec.ii_ptr.begin(), rec.ii_ptr.end());
  pattern->col.assign(rec.ii_col.begin(), rec.ii_col.end());
  for (std::size_t i = 0; i < nI; ++i) { // the pattern keeps every diagonal
    auto b = pattern->col.begin() + pattern->row_ptr[i],
         e = pattern->col.begin() + pattern->row_ptr[i + 1];
    if (!std::binary_search(b, e, static_cast<LocalIndex>(i)))
      throw InputError(
          at, what,
          fmt::format("the internal DOF {} of node {} has no stiffness: the "
                      "substructure can move there freely; retain it or hold it",
                      abaqus_number(dofs.slot_dof(eqmap.eq_slot[part.internal_eq[i]])),
                      model.node_label(dofs.slot_node(eqmap.eq_slot[part.internal_eq[i]]))));
  }
  return pattern;
}

/// S -= K_RI K_II^-1 K_IR with the factor of K_II, blocks of retained columns at a time (one
/// multi-column solve each).
void subtract_internal(const SubstructureRecovery& rec, ConstrainedFactor& Kii, std::size_t nI,
                       std::size_t nR, std::vector<double>& S) {
  const std::size_t block = 64;
  std::vector<double> B, X;
  for (std::size_t c0 = 0; c0 < nR; c0 += block) {
    const std::size_t nb = std::min(block, nR - c0);
    B.assign(nI * nb, 0.0);
    X.assign(nI * nb, 0.0);
    for (std::size_t i = 0; i < nI; ++i)
      for (std::int64_t k = rec.ir_ptr[i]; k < rec.ir_ptr[i + 1]; ++k) {
        const auto c = static_cast<std::size_t>(rec.ir_col[k]);
        if (c >= c0 && c < c0 + nb) B[(c - c0) * nI + i] = rec.ir_val[k];
      }
    Kii.solve(B, {}, X, {}, static_cast<int>(nb));
    for (std::size_t i = 0; i < nI; ++i)
      for (std::int64_t k = rec.ir_ptr[i]; k < rec.ir_ptr[i + 1]; ++k) {
        const auto rrow = static_cast<std::size_t>(rec.ir_col[k]);
        const double v = rec.ir_val[k];
        for (std::size_t c = 0; c < nb; ++c) S[rrow * nR + c0 + c] -= v * X[c * nI + i];
      }
  }
}

/// K_II of the generation's stiffness factorised through the solver seam (the serial backend on
/// every rank, as the rest of the analysis is replicated: the library is the same whatever
/// --solver says); InputError naming a DOF where it is singular.
std::unique_ptr<ConstrainedFactor> factorise_internal(const Generation& gen, const Partition& part,
                                                      const SubstructureRecovery& rec) {
  const auto& [model, dofs, eqmap, g, what] = gen;
  const std::size_t nI = part.internal_eq.size();
  auto pattern = internal_pattern(gen, rec, part);
  CsrMatrix Kii(pattern);
  std::copy(rec.ii_val.begin(), rec.ii_val.end(), Kii.values().begin());
  const auto solver = make_constrained_solver("cholmod");
  solver->analyze(pattern);
  try {
    return solver->factorize(Kii, ConstraintBlock{}, true);
  } catch (const SingularSystem& e) {
    const LocalIndex eq = e.equations().empty() ? 0 : e.equations().front();
    const LocalIndex slot = eqmap.eq_slot[part.internal_eq[std::min<std::size_t>(eq, nI - 1)]];
    throw InputError(g.loc, what,
                     fmt::format("the stiffness of the internal DOFs is singular (first at node "
                                 "{} DOF {}): with the retained DOFs held, a part of the "
                                 "substructure can still move; retain DOFs on it or fix it with "
                                 "*BOUNDARY in the generation step",
                                 model.node_label(dofs.slot_node(slot)),
                                 abaqus_number(dofs.slot_dof(slot))));
  }
}

/// The reduced stiffness S = K_RR - K_RI K_II^-1 K_IR (exactly symmetric), with K_II and K_IR
/// kept in `rec` for the recovery; with `M` (the model's mass) also the reduced mass on the same
/// static modes (substructure_mass.hpp) into `mass`.
std::vector<double> reduce(const Generation& gen, const CsrMatrix& K, const Partition& part,
                           SubstructureRecovery& rec, RunStatistics& stats,
                           const CsrMatrix* M = nullptr, std::vector<double>* mass = nullptr) {
  const auto nR = part.retained_eq.size(), nI = part.internal_eq.size();
  extract(K, part.internal_eq, part.int_index, rec.ii_ptr, rec.ii_col, rec.ii_val);
  extract(K, part.internal_eq, part.ret_index, rec.ir_ptr, rec.ir_col, rec.ir_val);
  std::vector<double> S(nR * nR, 0.0);
  const SparsityPattern& p = K.pattern();
  for (std::size_t i = 0; i < nR; ++i) {
    const LocalIndex row = part.retained_eq[i];
    for (LocalIndex k = p.row_ptr[row]; k < p.row_ptr[row + 1]; ++k)
      if (part.ret_index[p.col[k]] >= 0) S[i * nR + part.ret_index[p.col[k]]] += K.values()[k];
  }
  std::unique_ptr<ConstrainedFactor> Kii;
  if (nI > 0) {
    ScopedTimer timer(&stats, TimeCategory::Factorization);
    Kii = factorise_internal(gen, part, rec);
    subtract_internal(rec, *Kii, nI, nR, S);
  }
  if (M != nullptr && mass != nullptr)
    *mass = reduce_mass(*M, part.retained_eq, part.internal_eq, part.ret_index, part.int_index, rec,
                        Kii.get());
  for (std::size_t i = 0; i < nR; ++i) // round-off: exactly symmetric
    for (std::size_t j = i + 1; j < nR; ++j)
      S[i * nR + j] = S[j * nR + i] = 0.5 * (S[i * nR + j] + S[j * nR + i]);
  return S;
}

/// The largest dimension of the model (the substructure's default position tolerance).
double model_extent(const Model& model) {
  Vec3 lo = model.mesh.coords.empty() ? Vec3{} : model.mesh.coords[0], hi = lo;
  for (const Vec3& x : model.mesh.coords)
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], x[i]);
      hi[i] = std::max(hi[i], x[i]);
    }
  return std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-300});
}

/// Writes the library file (refusing another job's file unless OVERWRITE).
void write_library(const std::filesystem::path& file, const SubstructureLibrary& lib,
                   const SubstructureGeneration& g, const std::string& what, RunStatistics& stats) {
  std::error_code ec;
  if (std::filesystem::exists(file, ec) && !g.overwrite) {
    bool ours = false;
    try {
      ours = read_substructure_file(file, false).job == lib.job;
    } catch (const SubstructureFileError&) {
    }
    if (!ours)
      throw InputError(g.loc, what,
                       fmt::format("'{}' exists and was written by another job; add OVERWRITE to "
                                   "replace it, or give another LIBRARY=",
                                   file.string()));
  }
  try {
    ScopedTimer timer(&stats, TimeCategory::Output);
    write_substructure_file(file, lib);
  } catch (const SubstructureFileError& e) {
    throw AnalysisError(e.what());
  }
  log::progress("  substructure {} written to {}", g.type, file.string());
}

} // namespace

void Analysis::Impl::generate_substructure(StepRun& r) {
  const Step& step = *r.step;
  const SubstructureGeneration& g = *step.generation;
  const std::string what = fmt::format("TYPE={}", g.type);
  require_reducible(model, disc, step, what);
  const EquationMap& eqmap = r.loads->equations();
  const DofMap& dofs = disc.dofs();
  SubstructureLibrary lib;
  SubstructureType& t = lib.type;
  t.name = g.type;
  const Generation gen{model, dofs, eqmap, g, what};
  const Partition part = partition(gen, t);
  const auto nR = part.retained_eq.size(), nI = part.internal_eq.size();
  log::progress("  substructure {}: {} retained DOFs at {} nodes, {} internal DOFs", g.type, nR,
                t.node_labels.size(), nI);

  // the stiffness at the step start
  StepProblem& prob = *r.prob;
  prob.begin_increment(0.0, 0.0);
  if (g.mass) {
    // the model's mass M alone over the same equations (MASS MATRIX=YES)
    CsrMatrix M(prob.matrix().pattern_ptr());
    CsrInserter Min(M);
    std::vector<double> f(static_cast<std::size_t>(dofs.n_slots()), 0.0);
    assembler.assemble(prob.fields(), prob.context(), f, &Min, nullptr,
                       OperatorWeights{0.0, 0.0, 1.0, 1.0});
    prob.evaluate(true);
    t.stiffness = reduce(gen, prob.matrix(), part, lib.recovery, stats, &M, &t.mass);
  } else {
    prob.evaluate(true);
    t.stiffness = reduce(gen, prob.matrix(), part, lib.recovery, stats);
  }
  t.size = model_extent(model);

  lib.deck = options.restart_header.deck;
  lib.job = options.restart_header.job;
  lib.fingerprint = fingerprint();
  lib.has_recovery = g.recovery;
  SubstructureRecovery& rec = lib.recovery;
  if (g.recovery) {
    for (LocalIndex eq : part.internal_eq) {
      const LocalIndex slot = eqmap.eq_slot[eq];
      rec.internal_node.push_back(model.mesh.node_labels[dofs.slot_node(slot)]);
      rec.internal_dof.push_back(abaqus_number(dofs.slot_dof(slot)));
    }
  } else {
    lib.recovery = {};
  }
  if (options.output_dir.empty()) return; // an analysis that writes no files (tests)
  const std::string library = g.library.empty() ? options.restart_header.job : g.library;
  write_library(options.output_dir / (library + "_" + g.type + ".sub"), lib, g, what, stats);
}

} // namespace gapfem
