#include "fem/assembler.hpp"

#include "common/error.hpp"
#include "common/timer.hpp"
#include "model/model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <thread>

namespace gapfem {

int default_thread_count(int ranks_here) {
  // the ranks of a run on this machine share its cores
  const unsigned hw =
      std::thread::hardware_concurrency() / static_cast<unsigned>(std::max(ranks_here, 1));
  return static_cast<int>(std::clamp(hw, 1u, 2u));
}

Assembler::Assembler(Discretization& disc, int threads)
    : _disc(disc), _threads(std::max(1, threads)), _scratch(static_cast<std::size_t>(_threads)),
      _thread_constraints(static_cast<std::size_t>(_threads)),
      _thread_f(static_cast<std::size_t>(_threads)),
      _thread_rates(static_cast<std::size_t>(_threads)),
      _rate_scratch(static_cast<std::size_t>(_threads)) {}

namespace {
/// Runs body(thread, begin, end) over [0, n) split into `threads` contiguous chunks.
template <typename Body>
void parallel_chunks(int threads, std::size_t n, Body&& body) {
  if (threads <= 1 || n < 2000) {
    body(0, std::size_t{0}, n);
    return;
  }
  std::vector<std::thread> pool;
  std::exception_ptr error;
  std::mutex error_mutex;
  const std::size_t chunk = (n + threads - 1) / threads;
  for (int t = 0; t < threads; ++t) {
    const std::size_t b = t * chunk, e = std::min(n, b + chunk);
    if (b >= e) break;
    pool.emplace_back([&, t, b, e] {
      try {
        body(t, b, e);
      } catch (...) {
        std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
      }
    });
  }
  for (auto& th : pool) th.join();
  if (error) std::rethrow_exception(error);
}
} // namespace

namespace {
/// *STEP, UNSYMM=NO: the symmetric part of the element tangent, constraint rows as their columns.
void symmetrize(ElementOutput& out, int nd) {
  if (out.want_tangent)
    for (int i = 0; i < nd; ++i)
      for (int j = i + 1; j < nd; ++j) {
        const double m = 0.5 * (out.tangent[i * nd + j] + out.tangent[j * nd + i]);
        out.tangent[i * nd + j] = out.tangent[j * nd + i] = m;
      }
  out.has_columns = false;
  out.unsymmetric = false;
}
} // namespace

namespace {
/// Which operators of a block an assembly weighs (and so asks its kernel for).
struct BlockOperators {
  bool mass = false, damping = false;
  bool rates = false; ///< the elements' rates are gathered (an operator applied needs them)
};

BlockOperators block_operators(const ElementKernel& kernel, const StepContext& ctx,
                               const OperatorWeights& w) {
  BlockOperators ops;
  if (w.m != 0.0 && kernel.has_mass()) ops.mass = true;
  // a kernel integrating its own damping has it in residual and tangent while rates are defined
  if (w.c != 0.0 && kernel.has_damping() && !(kernel.damping_in_residual() && ctx.rates.defined()))
    ops.damping = true;
  ops.rates = ctx.rates.defined() && (ops.mass || ops.damping);
  return ops;
}

/// r += scale B x for a row-major n x n block B; `plain` (if not empty) gets B x.
void add_product(std::span<const double> B, std::span<const double> x, std::span<double> r,
                 double scale = 1.0, std::span<double> plain = {}) {
  const std::size_t n = r.size();
  for (std::size_t i = 0; i < n; ++i) {
    double s = 0.0;
    for (std::size_t j = 0; j < n; ++j) s += B[i * n + j] * x[j];
    r[i] += scale * s;
    if (!plain.empty()) plain[i] = s;
  }
}

/// plain = B x for a row-major n x n block B.
void product(std::span<const double> B, std::span<const double> x, std::span<double> plain) {
  const std::size_t n = plain.size();
  for (std::size_t i = 0; i < n; ++i) {
    double s = 0.0;
    for (std::size_t j = 0; j < n; ++j) s += B[i * n + j] * x[j];
    plain[i] = s;
  }
}

/// One element's M a, C v and M v alone (RateForces), where asked.
using ElementRates = std::array<std::span<double>, 3>;

/// The operators' forces M a + C v into the residual (rates defined) and k K + c C + m M into the
/// tangent (K alone, as the kernel left it, when k = 1 and no operator is weighted).
/// The element's M a, C v (unweighted) and M v go to `plain` where not empty.
void apply_operators(const ElementInput& in, ElementOutput& out, const OperatorWeights& w,
                     const ElementRates& plain) {
  if (out.want_mass && !in.a.empty())
    add_product(out.mass, in.a, out.residual, w.inertia, plain[0]);
  if (out.want_damping && !in.v.empty())
    add_product(out.damping, in.v, out.residual, 1.0, plain[1]);
  if (out.want_mass && !in.v.empty() && !plain[2].empty()) product(out.mass, in.v, plain[2]);
  if (!out.want_tangent) return;
  if (w.k != 1.0)
    for (double& t : out.tangent) t *= w.k;
  if (out.want_mass)
    for (std::size_t i = 0; i < out.tangent.size(); ++i) out.tangent[i] += w.m * out.mass[i];
  if (out.want_damping)
    for (std::size_t i = 0; i < out.tangent.size(); ++i) out.tangent[i] += w.c * out.damping[i];
}

/// The spans of RateForces in order (M a, C v, M v).
std::array<std::span<double>, 3> rate_spans(const RateForces& r) {
  return {r.inertia, r.damping, r.momentum};
}
} // namespace

void Assembler::assemble_chunk(ElementBlock& block, std::size_t b, std::size_t e, int t,
                               const FieldView& fields, const StepContext& ctx, std::span<double> f,
                               MatrixInserter* K, int lane, bool rows, const OperatorWeights& w,
                               const RateForces& rate_out, AssemblyResult& res) {
  const DofMap& dofs = _disc.dofs();
  const int nd = block.n_dofs;
  ElementGather& g = _scratch[t];
  const BlockOperators ops = block_operators(*block.kernel, ctx, w);
  const bool operators = ops.mass || ops.damping || w.k != 1.0;
  for (std::size_t i = b; i < e; ++i) {
    ElementInput& in = g.gather(_disc, block, i, fields, &ctx, ops.rates);
    ElementOutput& out = g.output(block, K != nullptr, ops.mass, ops.damping);
    block.kernel->evaluate(in, out);
    if (ctx.symmetric_only && (out.unsymmetric || out.has_columns)) symmetrize(out, nd);
    // the element's M a, C v, M v where asked and the block has the operator and its rates
    const auto global = rate_spans(rate_out);
    const bool has[3] = {ops.mass && !in.a.empty(), ops.damping && !in.v.empty(),
                         ops.mass && !in.v.empty()};
    ElementRates local{};
    for (int q = 0; q < 3; ++q)
      if (!global[q].empty() && has[q]) {
        _rate_scratch[t][q].assign(static_cast<std::size_t>(nd), 0.0);
        local[q] = _rate_scratch[t][q];
      }
    if (operators) apply_operators(in, out, w, local);
    const auto slots = block.element_slots(i);
    for (int q = 0; q < 3; ++q)
      if (!local[q].empty())
        for (int k = 0; k < nd; ++k) global[q][slots[k]] += local[q][k];
    for (int k = 0; k < nd; ++k) {
      const double r = out.residual[k];
      if (!std::isfinite(r))
        throw ConvergenceFailure("a non-finite force appeared in element " + in.label.str());
      f[slots[k]] += r;
      const int fld = static_cast<int>(dofs.slot_field(slots[k]));
      if (r != 0.0) {
        res.flux_sum[fld] += std::abs(r);
        ++res.flux_count[fld];
      }
    }
    // each thread writes its own lane of the inserter (merged in lane order by close())
    if (K) {
      const auto eqs = block.element_eqs(i);
      K->add(lane, eqs, eqs, out.tangent);
    }
    res.unsymmetric |= out.unsymmetric;
    res.stiffness_changed |= out.stiffness_changed;
    res.branch_changes += out.branch_changes;
    res.friction |= out.friction;
    res.dt_ratio = std::min(res.dt_ratio, out.dt_ratio);
    if (out.status_changes) {
      res.status_changes += out.status_changes;
      res.changed.push_back(block.elements[i]);
    }
    if (rows)
      for (int c = 0; c < out.n_constraints; ++c) {
        const auto off = static_cast<std::size_t>(c) * nd;
        const auto coeff = out.constraint_coeff.subspan(off, nd);
        const bool added = _thread_constraints[t].add_row(
            block.element_eqs(i), coeff, out.constraint_value[c],
            block.mult_offset + static_cast<std::int64_t>(i) * block.n_mult +
                out.constraint_slot[c],
            out.has_columns ? out.constraint_column.subspan(off, nd) : std::span<const double>{},
            out.constraint_compliance[c]);
        if (added && !fields.v_start.empty()) // a dynamic step: the rows' prescribed rates
          _thread_constraints[t].add_given(
              block.element_eqs(i), block.element_slots(i), coeff,
              {fields.v_start, fields.a_start, fields.u, fields.u_start});
      }
  }
}

AssemblyResult Assembler::assemble(const FieldView& fields, const StepContext& ctx,
                                   std::span<double> f_int, MatrixInserter* K, ConstraintBlock* C,
                                   const OperatorWeights& weights, const RateForces& rate_forces) {
  const DofMap& dofs = _disc.dofs();
  std::fill(f_int.begin(), f_int.end(), 0.0);
  const auto rates = rate_spans(rate_forces);
  for (const auto& r : rates) std::fill(r.begin(), r.end(), 0.0);
  if (K) {
    K->set_zero();
    K->open(_threads);
  }
  if (C) C->clear();
  AssemblyResult total;
  std::vector<AssemblyResult> partial(static_cast<std::size_t>(_threads));
  for (auto& blk : _disc.blocks()) {
    ElementBlock* block = &blk;
    const bool gap_block = element_info(block->type).family == ElementFamily::Gap;
    const Stopwatch block_watch;
    const bool multi = _threads > 1 && block->size() >= 2000;
    for (int t = 0; t < _threads; ++t) {
      _thread_constraints[t].clear();
      if (multi) _thread_f[t].assign(f_int.size(), 0.0);
      for (int q = 0; q < 3; ++q)
        if (multi && !rates[q].empty()) _thread_rates[t][q].assign(f_int.size(), 0.0);
    }
    parallel_chunks(multi ? _threads : 1, block->size(), [&](int t, std::size_t b, std::size_t e) {
      std::span<double> f = multi ? std::span<double>(_thread_f[t]) : f_int;
      RateForces mine = rate_forces;
      if (multi) {
        auto& tr = _thread_rates[t];
        mine = {rates[0].empty() ? std::span<double>{} : std::span<double>(tr[0]),
                rates[1].empty() ? std::span<double>{} : std::span<double>(tr[1]),
                rates[2].empty() ? std::span<double>{} : std::span<double>(tr[2])};
      }
      assemble_chunk(*block, b, e, t, fields, ctx, f, K, multi ? t : 0, C != nullptr, weights, mine,
                     partial[t]);
    });
    if (multi) {
      for (int t = 0; t < _threads; ++t)
        for (std::size_t s = 0; s < f_int.size(); ++s) f_int[s] += _thread_f[t][s];
      for (int q = 0; q < 3; ++q)
        if (!rates[q].empty())
          for (int t = 0; t < _threads; ++t)
            for (std::size_t s = 0; s < rates[q].size(); ++s) rates[q][s] += _thread_rates[t][q][s];
    }
    if (C)
      for (int t = 0; t < _threads; ++t) {
        const auto& tc = _thread_constraints[t];
        // rows with their own columns make every row carry one (D = C^T where none was given);
        // `columns` is kept apart from has_columns() because an empty C has no dval to show it
        const bool columns = C->has_columns() || tc.has_columns();
        if (columns && C->dval.size() < C->val.size()) C->dval = C->val;
        for (int r = 0; r < tc.n_rows(); ++r) {
          const auto b0 = tc.row_ptr[r], b1 = tc.row_ptr[r + 1];
          C->col.insert(C->col.end(), tc.col.begin() + b0, tc.col.begin() + b1);
          C->val.insert(C->val.end(), tc.val.begin() + b0, tc.val.begin() + b1);
          if (columns) {
            const auto& src = tc.has_columns() ? tc.dval : tc.val;
            C->dval.insert(C->dval.end(), src.begin() + b0, src.begin() + b1);
          }
          C->row_ptr.push_back(static_cast<LocalIndex>(C->col.size()));
          C->g.push_back(tc.g[r]);
          C->compliance.push_back(tc.compliance[r]);
          C->multiplier.push_back(tc.multiplier[r]);
          if (!tc.given_v.empty()) {
            C->given_v.push_back(tc.given_v[r]);
            C->given_a.push_back(tc.given_a[r]);
            C->travel.push_back(tc.travel[r]);
          }
        }
      }
    if (gap_block) total.gap_seconds += block_watch.seconds();
  }
  // Linear constraints: constraint forces and their rows, after the elements' rows.
  _disc.constraints().assemble(fields.u, f_int, C, _disc.constraint_multiplier_offset(), dofs,
                               total.flux_sum, total.flux_count,
                               {fields.v_start, fields.a_start, fields.u, fields.u_start});
  // stiffness matrices of the model as a whole (*MATRIX ASSEMBLE)
  _disc.matrix_terms().assemble(fields.u, f_int, K, dofs, total.flux_sum, total.flux_count);
  if (K) K->close();
  for (auto& p : partial) {
    total.status_changes += p.status_changes;
    total.branch_changes += p.branch_changes;
    total.unsymmetric |= p.unsymmetric;
    total.stiffness_changed |= p.stiffness_changed;
    total.friction |= p.friction;
    total.dt_ratio = std::min(total.dt_ratio, p.dt_ratio);
    for (int f = 0; f < kNumFields; ++f) {
      total.flux_sum[f] += p.flux_sum[f];
      total.flux_count[f] += p.flux_count[f];
    }
    total.changed.insert(total.changed.end(), p.changed.begin(), p.changed.end());
  }
  return total;
}

void Assembler::assemble_loads(std::span<const ActiveLoad> loads, const FieldView& fields,
                               const StepContext& ctx, std::span<double> f_ext, MatrixInserter* K,
                               bool symmetrize) {
  ElementGather& g = _scratch[0];
  std::vector<double> fe, Ke;
  if (K) K->open(1);
  for (const ActiveLoad& al : loads) {
    const auto [bi, idx] = _disc.locate(al.load->elem);
    ElementBlock& block = _disc.blocks()[bi];
    ElementInput& in = g.gather(_disc, block, static_cast<std::size_t>(idx), fields, &ctx);
    const auto nd = static_cast<std::size_t>(block.n_dofs);
    fe.assign(nd, 0.0);
    Ke.assign(nd * nd, 0.0);
    block.kernel->load(in, *al.load, al.magnitude, al.sink_temperature, fe, Ke);
    const auto slots = block.element_slots(static_cast<std::size_t>(idx));
    for (std::size_t k = 0; k < nd; ++k) f_ext[slots[k]] += fe[k];
    if (K) {
      bool any = false;
      for (double v : Ke) any |= v != 0.0;
      if (any && symmetrize)
        for (std::size_t i = 0; i < nd; ++i)
          for (std::size_t j = i + 1; j < nd; ++j) {
            const double m = 0.5 * (Ke[i * nd + j] + Ke[j * nd + i]);
            Ke[i * nd + j] = Ke[j * nd + i] = m;
          }
      if (any)
        K->add(0, block.element_eqs(static_cast<std::size_t>(idx)),
               block.element_eqs(static_cast<std::size_t>(idx)), Ke);
    }
  }
  if (K) K->close();
}

void Assembler::element_residual(ElemId e, const FieldView& fields, const StepContext& ctx,
                                 std::vector<double>& out, std::vector<LocalIndex>& slots) {
  const auto [bi, idx] = _disc.locate(e);
  ElementBlock& block = _disc.blocks()[bi];
  ElementGather& g = _scratch[0];
  ElementInput& in = g.gather(_disc, block, static_cast<std::size_t>(idx), fields, &ctx);
  ElementOutput& o = g.output(block, false);
  block.kernel->evaluate(in, o);
  out.assign(o.residual.begin(), o.residual.end());
  const auto s = block.element_slots(static_cast<std::size_t>(idx));
  slots.assign(s.begin(), s.end());
}

double Assembler::step_limit(const FieldView& fields, const StepContext& ctx,
                             std::span<const double> du) {
  double alpha = 1.0;
  ElementGather& g = _scratch[0];
  std::vector<double> local;
  for (auto& b : _disc.blocks()) {
    if (!b.kernel->limits_steps()) continue;
    for (std::size_t i = 0; i < b.size(); ++i) {
      const auto slots = b.element_slots(i);
      local.resize(slots.size());
      for (std::size_t k = 0; k < slots.size(); ++k) local[k] = du[slots[k]];
      alpha = std::min(alpha, b.kernel->step_limit(g.gather(_disc, b, i, fields, &ctx), local));
    }
  }
  return alpha;
}

int Assembler::augment(const FieldView& fields, const StepContext& ctx) {
  int changed = 0;
  ElementGather& g = _scratch[0];
  for (auto& b : _disc.blocks()) {
    if (element_info(b.type).family != ElementFamily::Gap) continue;
    for (std::size_t i = 0; i < b.size(); ++i)
      changed += b.kernel->augment(g.gather(_disc, b, i, fields, &ctx)) ? 1 : 0;
  }
  return changed;
}

std::vector<double> Assembler::diagonal_stiffness(const FieldView& fields, const StepContext& ctx,
                                                  bool skip_gaps) {
  std::vector<double> diag(static_cast<std::size_t>(_disc.dofs().n_slots()), 0.0);
  ElementGather& g = _scratch[0];
  std::vector<double> state_backup, mult_backup;
  for (auto& b : _disc.blocks()) {
    if (skip_gaps && element_info(b.type).family == ElementFamily::Gap) continue;
    state_backup = b.state_trial;
    mult_backup = b.mult_trial;
    const auto nd = static_cast<std::size_t>(b.n_dofs);
    for (std::size_t i = 0; i < b.size(); ++i) {
      ElementInput& in = g.gather(_disc, b, i, fields, &ctx);
      ElementOutput& out = g.output(b, true);
      b.kernel->evaluate(in, out);
      const auto slots = b.element_slots(i);
      for (std::size_t k = 0; k < nd; ++k) diag[slots[k]] += std::abs(out.tangent[k * nd + k]);
    }
    b.state_trial = state_backup; // evaluation must not leave trial history behind, nor
    b.mult_trial = mult_backup;   // a gap's multiplier (a kernel may project it)
  }
  _disc.matrix_terms().add_diagonal(diag);
  return diag;
}

void Assembler::recover(ElemId e, const FieldView& fields, const StepContext& ctx,
                        ElementRecovery& out) {
  const auto [bi, idx] = _disc.locate(e);
  ElementBlock& block = _disc.blocks()[bi];
  ElementInput& in = _scratch[0].gather(_disc, block, static_cast<std::size_t>(idx), fields, &ctx);
  out.clear();
  block.kernel->recover(in, out);
  if (out.strain_energy) { // ELSE, the element's elastic strain energy, for every kernel with one
    static constexpr std::array<std::string_view, 1> kElse{"ELSE"};
    OutputBlock b;
    b.var = ElemVar::ELSE;
    b.names = kElse;
    b.n_points = 1;
    b.values = {*out.strain_energy};
    out.blocks.push_back(std::move(b));
  }
}

} // namespace gapfem
