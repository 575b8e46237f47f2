/// @file substructure_generate.cpp
/// A *SUBSTRUCTURE GENERATE step (docs/substructures.md): the static (Guyan) reduction of the
/// model's linear stiffness onto the retained DOFs, S = K_RR - K_RI K_II^-1 K_IR, exact for the
/// linear static response; written with the recovery data to the substructure library file.
#include "common/log.hpp"
#include "model/substructure_file.hpp"
#include "solver/analysis_impl.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace gapfem {
namespace {

/// Equation blocks of a generation step: per free equation, its retained index or internal index.
struct Partition {
  std::vector<LocalIndex> retained_eq; ///< per retained DOF (element order): its equation
  std::vector<LocalIndex> internal_eq; ///< per internal DOF: its equation
  std::vector<LocalIndex> index;       ///< per equation: retained index, or -(internal index)-1
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

} // namespace

void Analysis::Impl::generate_substructure(StepRun& r) {
  const Step& step = *r.step;
  const SubstructureGeneration& g = *step.generation;
  const SourceLocation& at = g.loc;
  const std::string what = fmt::format("TYPE={}", g.type);
  // what a linear reduction cannot hold
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
  const EquationMap& eqmap = r.loads->equations();
  const DofMap& dofs = disc.dofs();
  for (const BoundaryEntry& b : step.boundary)
    if (b.value != 0.0)
      throw InputError(b.loc, what,
                       "a generation step takes fixed (zero) boundary conditions only; prescribe "
                       "the displacement in the model that uses the substructure");

  // retained and internal equations
  Partition part;
  part.index.assign(static_cast<std::size_t>(eqmap.n_eq()), 0);
  SubstructureLibrary lib;
  SubstructureType& t = lib.type;
  t.name = g.type;
  for (const auto& [node, given] : g.retained) {
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
    std::vector<int> kept;
    for (int d : list) {
      DofType dt{};
      dof_from_abaqus(d, dt);
      const LocalIndex slot = dofs.slot(node, dt);
      if (slot < 0) {
        throw InputError(g.retained_loc, what,
                         fmt::format("node {} has no DOF {}: no element of the substructure acts "
                                     "on it; retain the DOFs its elements carry",
                                     model.node_label(node), d));
      }
      const LocalIndex eq = eqmap.slot_eq[slot];
      if (eq < 0)
        throw InputError(g.retained_loc, what,
                         fmt::format("DOF {} of node {} is fixed by a boundary condition of the "
                                     "generation step, so it cannot be retained; retain it free, "
                                     "or fix it in the model that uses the substructure",
                                     d, model.node_label(node)));
      part.index[eq] = static_cast<LocalIndex>(part.retained_eq.size()) + 1;
      part.retained_eq.push_back(eq);
      kept.push_back(d);
    }
    if (kept.empty()) continue;
    t.node_labels.push_back(model.mesh.node_labels[node]);
    t.coords.push_back(model.mesh.coords[node]);
    t.node_dofs.push_back(std::move(kept));
  }
  std::vector<LocalIndex> ret_index(static_cast<std::size_t>(eqmap.n_eq()), -1),
      int_index(static_cast<std::size_t>(eqmap.n_eq()), -1);
  for (LocalIndex eq = 0; eq < eqmap.n_eq(); ++eq) {
    if (part.index[eq] > 0) {
      ret_index[eq] = part.index[eq] - 1;
      continue;
    }
    int_index[eq] = static_cast<LocalIndex>(part.internal_eq.size());
    part.internal_eq.push_back(eq);
  }
  const auto nR = part.retained_eq.size(), nI = part.internal_eq.size();
  if (nR > 16384) // Abaqus's limit too: the reduced stiffness is dense
    throw InputError(g.retained_loc, what,
                     fmt::format("{} DOFs are retained; a substructure retains at most 16,384 (its "
                                 "reduced stiffness is a dense matrix): retain fewer, or split the "
                                 "part into several substructures",
                                 nR));
  log::progress("  substructure {}: {} retained DOFs at {} nodes, {} internal DOFs", g.type, nR,
                t.node_labels.size(), nI);

  // the stiffness at the step start
  StepProblem& prob = *r.prob;
  prob.begin_increment(0.0, 0.0);
  prob.evaluate(true);
  const CsrMatrix& K = prob.matrix();

  // K_II, factorised
  SubstructureRecovery& rec = lib.recovery;
  extract(K, part.internal_eq, int_index, rec.ii_ptr, rec.ii_col, rec.ii_val);
  extract(K, part.internal_eq, ret_index, rec.ir_ptr, rec.ir_col, rec.ir_val);
  std::vector<double> S(nR * nR, 0.0);
  for (std::size_t i = 0; i < nR; ++i) {
    const LocalIndex row = part.retained_eq[i];
    const SparsityPattern& p = K.pattern();
    for (LocalIndex k = p.row_ptr[row]; k < p.row_ptr[row + 1]; ++k)
      if (ret_index[p.col[k]] >= 0) S[i * nR + ret_index[p.col[k]]] += K.values()[k];
  }
  if (nI > 0) {
    ScopedTimer timer(&stats, TimeCategory::Factorization);
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
    CsrMatrix Kii(pattern);
    std::copy(rec.ii_val.begin(), rec.ii_val.end(), Kii.values().begin());
    auto cholmod = make_cholmod_solver();
    cholmod->analyze(*pattern);
    try {
      cholmod->factorize(Kii);
    } catch (const SingularSystem& e) {
      const LocalIndex eq = e.equations().empty() ? 0 : e.equations().front();
      const LocalIndex slot = eqmap.eq_slot[part.internal_eq[std::min<std::size_t>(eq, nI - 1)]];
      throw InputError(at, what,
                       fmt::format("the stiffness of the internal DOFs is singular (first at node "
                                   "{} DOF {}): with the retained DOFs held, a part of the "
                                   "substructure can still move; retain DOFs on it or fix it with "
                                   "*BOUNDARY in the generation step",
                                   model.node_label(dofs.slot_node(slot)),
                                   abaqus_number(dofs.slot_dof(slot))));
    }
    // S -= K_RI K_II^-1 K_IR, blocks of retained columns at a time (one multi-column solve each)
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
      cholmod->solve_many(B, X, static_cast<int>(nb));
      for (std::size_t i = 0; i < nI; ++i)
        for (std::int64_t k = rec.ir_ptr[i]; k < rec.ir_ptr[i + 1]; ++k) {
          const auto rrow = static_cast<std::size_t>(rec.ir_col[k]);
          const double v = rec.ir_val[k];
          for (std::size_t c = 0; c < nb; ++c) S[rrow * nR + c0 + c] -= v * X[c * nI + i];
        }
    }
  }
  for (std::size_t i = 0; i < nR; ++i) // round-off: exactly symmetric
    for (std::size_t j = i + 1; j < nR; ++j)
      S[i * nR + j] = S[j * nR + i] = 0.5 * (S[i * nR + j] + S[j * nR + i]);
  t.stiffness = std::move(S);
  // the substructure's largest dimension (the default position tolerance)
  Vec3 lo = model.mesh.coords.empty() ? Vec3{} : model.mesh.coords[0], hi = lo;
  for (const Vec3& x : model.mesh.coords)
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], x[i]);
      hi[i] = std::max(hi[i], x[i]);
    }
  t.size = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-300});

  lib.deck = options.restart_header.deck;
  lib.job = options.restart_header.job;
  lib.fingerprint = fingerprint();
  lib.has_recovery = g.recovery;
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
  const std::filesystem::path file = options.output_dir / (library + "_" + g.type + ".sub");
  std::error_code ec;
  if (std::filesystem::exists(file, ec) && !g.overwrite) {
    bool ours = false;
    try {
      ours = read_substructure_file(file, false).job == lib.job;
    } catch (const SubstructureFileError&) {
    }
    if (!ours)
      throw InputError(at, what,
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

} // namespace gapfem
