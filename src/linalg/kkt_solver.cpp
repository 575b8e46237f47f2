#include "linalg/kkt_solver.hpp"

#include "common/error.hpp"
#include "common/log.hpp"
#include "common/memory.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numeric>
#include <string_view>

namespace gapfem {

namespace {
double norm_inf(std::span<const double> v) {
  double s = 0.0;
  for (double x : v) s = std::max(s, std::abs(x));
  return s;
}
/// A compliant row's spring in the factor must stay softer than the row itself (R E < 1, see
/// solve()); half of it keeps the Schur system well away from that limit.
constexpr double kCompliantSpringShare = 0.5;
/// The dense multiplier matrix is used up to this many rows, where its factorisation costs less
/// than the back-substitutions it saves (at kDenseFlopRate flop/s, what one core's BLAS does).
constexpr int kMaxDenseRows = 4000;
constexpr double kDenseFlopRate = 1e10;
/// Below this factorisation time the measured costs are noise: no reuse.
constexpr double kMinReusedFactorSeconds = 2e-3;
bool same_row(const ConstraintBlock& a, int ra, const ConstraintBlock& b, int rb) {
  const LocalIndex a0 = a.row_ptr[ra], a1 = a.row_ptr[ra + 1];
  const LocalIndex b0 = b.row_ptr[rb], b1 = b.row_ptr[rb + 1];
  if (a1 - a0 != b1 - b0) return false;
  for (LocalIndex k = 0; k < a1 - a0; ++k)
    if (a.col[a0 + k] != b.col[b0 + k] || a.val[a0 + k] != b.val[b0 + k]) return false;
  return true;
}
} // namespace

namespace {
/// augmentation_weights() from |diag K| given by diag(i), i < n
template <class Diagonal>
void weights_from_diagonal(LocalIndex n, Diagonal diag, const ConstraintBlock& C,
                           double augmentation, std::vector<double>& R, std::vector<double>& ks) {
  const int m = C.n_rows();
  R.assign(static_cast<std::size_t>(m), 0.0);
  ks.assign(R.size(), 0.0);
  if (m == 0) return;
  double mean_diag = 0.0;
  for (LocalIndex i = 0; i < n; ++i) mean_diag += diag(i);
  mean_diag = n > 0 ? mean_diag / n : 1.0;
  if (!(mean_diag > 0)) mean_diag = 1.0;
  for (int r = 0; r < m; ++r) {
    double num = 0.0, den = 0.0;
    for (LocalIndex k = C.row_ptr[r]; k < C.row_ptr[r + 1]; ++k) {
      const double c2 = C.val[k] * C.val[k];
      num += c2 * diag(C.col[k]);
      den += c2;
    }
    double stiff = den > 0 ? num / den : 0.0;
    if (!(stiff > 1e-12 * mean_diag)) stiff = mean_diag;
    ks[r] = stiff / std::max(den, 1e-300); // the structure's stiffness along the row
    R[r] = augmentation * ks[r];
    const double E = C.row_compliance(r);
    if (E > 0) R[r] = std::min(R[r], kCompliantSpringShare / E);
  }
}
} // namespace

void augmentation_weights(const CsrMatrix& K, const ConstraintBlock& C, double augmentation,
                          std::vector<double>& R, std::vector<double>& ks) {
  weights_from_diagonal(
      K.n(), [&](LocalIndex i) { return std::abs(K.diagonal(i)); }, C, augmentation, R, ks);
}

KktSolver::KktSolver() {
  if (const char* env = std::getenv("GAPFEM_FACTOR_UPDATES"))
    _modify = std::string_view(env) != "0" && std::string_view(env) != "off";
  if (const char* env = std::getenv("GAPFEM_DENSE_MULTIPLIERS"))
    _dense = std::string_view(env) != "0" && std::string_view(env) != "off";
}
KktSolver::~KktSolver() = default;

void KktSolver::forget_factor() {
  _umfpack_ready = false;
  _active = nullptr;
  _factored.clear();
  _frows.clear();
  _fR.clear();
  _fks.clear();
  _frow_of.clear();
  _t_factor = _t_solve = _t_update_row = 0.0;
}

void KktSolver::analyze(std::shared_ptr<const SparsityPattern> pattern) {
  _pattern = std::move(pattern);
  _cholmod_ready = _umfpack_ready = false;
  _active = nullptr;
  _factored.clear();
  _frows.clear();
  _fR.clear();
  _fks.clear();
  _frow_of.clear();
}

void KktSolver::check_memory(std::size_t factor_bytes) const {
  const auto available = available_memory_bytes();
  // the factor plus CHOLMOD's workspace and the copies the solve keeps: 1.25 x the factor
  const double need = 1.25 * static_cast<double>(factor_bytes);
  if (!available || need <= static_cast<double>(*available)) return;
  throw AnalysisError(fmt::format(
      "the factor of this step's {} equations needs about {} (CHOLMOD's symbolic analysis) but "
      "only {} of memory are available; nothing was factorised. Use a coarser mesh, reduce a "
      "linear part to a substructure (docs/substructures.md), or run on a machine with more "
      "memory",
      _pattern->n, memory_size_text(need), memory_size_text(static_cast<double>(*available))));
}

void KktSolver::factorize(const CsrMatrix& M, bool symmetric, RunStatistics* stats) {
  ScopedTimer timer(stats, TimeCategory::Factorization);
  Stopwatch watch;
  if (stats) ++stats->factorizations;
  if (symmetric) {
    if (!_cholmod) _cholmod = make_cholmod_solver();
    if (!_cholmod_ready) {
      _cholmod->analyze(*_pattern);
      _cholmod_ready = true;
      check_memory(_cholmod->factor_bytes());
    }
    try {
      _cholmod->factorize(M);
      _active = _cholmod.get();
      _t_factor = watch.seconds();
      return;
    } catch (const SingularSystem& e) {
      // An indefinite (negative pivot) matrix, e.g. from the geometric stiffness of two external
      // cylinders in contact, is still solvable by LU; a zero pivot is a genuine singularity.
      if (!e.indefinite()) throw;
      log::debug("matrix not positive definite; switching to LU");
    }
  }
  if (!_umfpack) _umfpack = make_umfpack_solver();
  if (!_umfpack_ready) {
    _umfpack->analyze(*_pattern);
    _umfpack_ready = true;
  }
  _umfpack->factorize(M);
  _active = _umfpack.get();
  _t_factor = watch.seconds();
}

bool KktSolver::modify_factor(const ConstraintBlock& C, std::span<const double> R,
                              std::span<const double> ks, std::vector<int>& p_of,
                              std::vector<int>& gone, RunStatistics* stats) {
  ScopedTimer timer(stats, TimeCategory::Factorization);
  const Stopwatch watch;
  const int m = C.n_rows();
  SparseColumns add, del;
  auto push = [](SparseColumns& W, const ConstraintBlock& B, int r, double weight) {
    const double s = std::sqrt(weight);
    for (LocalIndex k = B.row_ptr[r]; k < B.row_ptr[r + 1]; ++k) {
      W.row.push_back(B.col[k]);
      W.val.push_back(s * B.val[k]);
    }
    W.ptr.push_back(static_cast<LocalIndex>(W.row.size()));
  };
  std::vector<double> weights(static_cast<std::size_t>(m)), stiffness(weights.size());
  std::vector<int> added;
  for (int r = 0; r < m; ++r) {
    if (p_of[r] >= 0) {
      weights[r] = _fR[p_of[r]];
      stiffness[r] = _fks[p_of[r]];
    } else {
      weights[r] = R[r];
      stiffness[r] = ks[r];
      push(add, C, r, R[r]);
      added.push_back(r);
    }
  }
  for (int f : gone) push(del, _frows, f, _fR[f]);
  // the backend may soften a new row's spring (its weight then is R s^2), and tells how stiff
  // the spring is against the matrix along the row (gain = weight / the structure's stiffness)
  std::vector<double> scale(added.size(), 1.0), gain(added.size(), 0.0);
  try {
    // updates first: the matrix stays positive definite throughout
    if (!_cholmod->modify(true, add, scale, gain) || !_cholmod->modify(false, del)) return false;
  } catch (const SingularSystem&) {
    _factored.clear(); // the factor is unusable: the caller factorises afresh
    return false;
  }
  for (std::size_t j = 0; j < added.size(); ++j) {
    weights[added[j]] *= scale[j] * scale[j];
    // the exact stiffness along the row (the preconditioner's estimate of its Schur block);
    // the diagonal's estimate is far too stiff on a flexible structure
    if (gain[j] > 0) stiffness[added[j]] = weights[added[j]] / gain[j];
  }
  const int rows = add.n_cols() + del.n_cols();
  if (stats) stats->factor_updates += rows;
  if (rows > 0) {
    const double per_row = watch.seconds() / rows;
    _t_update_row = _t_update_row > 0 ? 0.5 * (_t_update_row + per_row) : per_row;
  }
  _frows = C;
  _fR = std::move(weights);
  _fks = std::move(stiffness);
  _frow_of.clear();
  for (int r = 0; r < m; ++r) {
    _frow_of[C.multiplier[r]] = r;
    p_of[r] = r;
  }
  log::debug("  factor updated: {} rows added, {} removed ({:.2e} s per row)", add.n_cols(),
             del.n_cols(), watch.seconds() / std::max(rows, 1));
  gone.clear();
  return true;
}

void KktSolver::back_solve(std::span<const double> b, std::span<double> x, RunStatistics* stats) {
  ScopedTimer timer(stats, TimeCategory::Solve);
  Stopwatch watch;
  if (stats) ++stats->linear_solves;
  ++_solves;
  _active->solve(b, x);
  const double dt = watch.seconds();
  _t_solve = _t_solve > 0 ? 0.8 * _t_solve + 0.2 * dt : dt;
}

void KktSolver::fresh_factor(CsrMatrix& K, const ConstraintBlock& C, std::span<const double> R,
                             std::span<const double> ks, bool symmetric, RunStatistics* stats) {
  _factored.clear(); // no stale factor survives a failed factorisation
  _frows.clear();
  _fR.clear();
  _fks.clear();
  _frow_of.clear();
  const auto vals = K.values();
  std::vector<double> raw(vals.begin(), vals.end());
  double scale = 0.0;
  for (LocalIndex i = 0; i < K.n(); ++i) scale = std::max(scale, std::abs(K.diagonal(i)));
  _factored_diag.resize(static_cast<std::size_t>(K.n()));
  for (LocalIndex i = 0; i < K.n(); ++i)
    _factored_diag[i] = std::max(std::abs(K.diagonal(i)), 1e-12 * (scale > 0 ? scale : 1.0));
  // M = K + C^T R C (entries lie inside each row's element block, hence inside the pattern).
  std::vector<LocalIndex> eqs;
  std::vector<double> block;
  for (int r = 0; r < C.n_rows(); ++r) {
    const LocalIndex b0 = C.row_ptr[r], b1 = C.row_ptr[r + 1];
    const auto len = static_cast<std::size_t>(b1 - b0);
    eqs.assign(C.col.begin() + b0, C.col.begin() + b1);
    block.resize(len * len);
    for (std::size_t i = 0; i < len; ++i)
      for (std::size_t j = 0; j < len; ++j)
        block[i * len + j] = R[r] * C.val[b0 + i] * C.val[b0 + j];
    K.add_block(eqs, eqs, block);
  }
  factorize(K, symmetric, stats);
  _factored = std::move(raw);
  _mcols.reset(_active == _cholmod.get() ? K.n() : 0);
  _dense_failed = false;
  _drift = 0.0;
  _drift_step = std::numeric_limits<double>::infinity();
  _last_changes = 0;
  _last_rows = C.n_rows();
  _factored_scale = scale > 0 ? scale : 1.0;
  _factored_symmetric = symmetric;
  _frows = C;
  _fR.assign(R.begin(), R.end());
  _fks.assign(ks.begin(), ks.end());
  for (int r = 0; r < C.n_rows(); ++r) _frow_of[C.multiplier[r]] = r;
}

KktSolver::Plan KktSolver::compare(const CsrMatrix& K, const ConstraintBlock& C, bool symmetric,
                                   const KktOptions& opt, std::vector<int>& p_of,
                                   std::vector<int>& gone) {
  Plan plan;
  const int m = C.n_rows();
  const auto vals = K.values();
  const bool comparable = _active && !_factored.empty() && symmetric == _factored_symmetric &&
                          _factored.size() == vals.size();
  if (!comparable) return plan;
  std::vector<char> used(static_cast<std::size_t>(_frows.n_rows()), 0);
  for (int r = 0; r < m; ++r) {
    const auto it = _frow_of.find(C.multiplier[r]);
    // a compliant row whose spring in the factor is no longer softer than the row (it got
    // stiffer since) is replaced like a changed row
    if (it != _frow_of.end() && !used[it->second] && same_row(C, r, _frows, it->second) &&
        _fR[it->second] * C.row_compliance(r) <= 0.9) {
      p_of[r] = it->second;
      used[it->second] = 1;
    } else {
      ++plan.changes;
    }
  }
  for (int f = 0; f < _frows.n_rows(); ++f)
    if (!used[f]) gone.push_back(f);
  plan.changes += static_cast<int>(gone.size());
  _last_changes = plan.changes;
  _last_rows = m;
  // drift entry by entry relative to the diagonals of its row and column: a change that is
  // small against the stiffest DOF of the model can still be large where it happens (a
  // friction gap going from slip to a stiff stick in a model with stiffer gaps elsewhere).
  // Without the current matrix, the drift is the one last measured.
  double drift = _drift;
  if (opt.matrix_current) {
    const double before = _drift;
    drift = 0.0;
    const SparsityPattern& pat = K.pattern();
    for (LocalIndex i = 0; i < pat.n; ++i)
      for (LocalIndex k = pat.row_ptr[i]; k < pat.row_ptr[i + 1]; ++k) {
        const double change = std::abs(vals[k] - _factored[k]);
        if (change != 0.0)
          drift =
              std::max(drift, change / std::sqrt(_factored_diag[i] * _factored_diag[pat.col[k]]));
      }
    _drift_step = std::max(drift - before, 0.0);
    _drift = drift;
    _max_drift = opt.max_drift;
  }
  log::debug(
      "  system: drift {:.2e}{}, {} changed constraint rows, factor {:.3f} s, solve {:.4f} s",
      drift, opt.matrix_current ? "" : " (last measured)", plan.changes, _t_factor, _t_solve);
  // the same matrix (a linear model, an unchanged contact set): the step factorises once
  plan.exact_same = opt.matrix_current && drift == 0.0 && plan.changes == 0;
  if (!plan.exact_same && !opt.force_fresh && opt.reuse != FactorReuse::Never &&
      drift <= opt.max_drift)
    plan.stale = opt.reuse == FactorReuse::Always || reuse_pays(plan.changes, m);
  return plan;
}

bool KktSolver::dense_possible() const {
  return _dense && !_dense_failed && _cholmod && _active == _cholmod.get() &&
         _cholmod->has_split_solves();
}

double KktSolver::solve_seconds() const {
  // before the first solve of a factor is timed: a solve costs about 1/40 of a factorisation on
  // the 3-D meshes measured (1/27 at 11k equations, 1/42 at 50k, 1/35 at 200k)
  return _t_solve > 0 ? _t_solve : _t_factor / 40.0;
}

bool KktSolver::reuse_pays(int changes, int rows) const {
  // a factorisation this cheap costs no more than the timer's noise: factorising every system
  // (full Newton) keeps small models' answers independent of the machine's timing
  if (!(_t_solve > 0) || _t_factor < kMinReusedFactorSeconds) return false;
  if (dense_possible()) {
    // the dense path serves this factor: a changed row costs at most a new column, and a fresh
    // factor would make every column again (a column costs ~1/3000 of a factorisation at 50k
    // equations until measured)
    const double per_column = _t_update_row > 0 ? _t_update_row : 5e-4 * _t_factor;
    return 2 * _t_solve + changes * per_column <
           _t_factor + std::max(_mcols.size(), rows) * per_column;
  }
  const double per_row = _t_update_row > 0 ? _t_update_row : 0.002 * _t_factor;
  if (_modify && _active == _cholmod.get())
    // reuse pays when updating the factor for the changed rows and the multiplier iterations of
    // an exact factor (about 5; an update costs a few hundredths of a factorisation per row
    // until measured) cost less than a factorisation
    return 5 * _t_solve + changes * per_row < _t_factor;
  // reuse pays when the extra multiplier iterations (measured: about 5 + one per two changed
  // rows) cost less than a factorisation
  return (0.5 * changes + 5) * _t_solve < _t_factor;
}

bool KktSolver::dense_pays(int rows, bool columns) const {
  // the dense factorisation (rows^3 / 3 flops for Cholesky, twice that for LU, at a few
  // GFlop/s) must cost less than the back-substitutions it saves (the Krylov path's CG takes a
  // few, its GMRES with force columns of their own 10-20), and the Gram matrix must fit next to
  // the factor
  const double r = rows, flops = (columns ? 2.0 : 1.0) * r * r * r / 3.0;
  const double saved = (columns ? 10.0 : 2.0) * std::max(solve_seconds(), 1e-3);
  if (rows > kMaxDenseRows || flops / kDenseFlopRate > saved) return false;
  const auto available = available_memory_bytes();
  return !available || 3.0 * r * r * sizeof(double) < 0.25 * static_cast<double>(*available);
}

bool KktSolver::matrix_optional() const {
  // the drift grows by less per iteration as Newton converges: twice the last growth bounds it
  // (unknown right after a factorisation: the next system brings its matrix)
  return _active && !_factored.empty() && _reuse != FactorReuse::Never &&
         _drift + 2.0 * _drift_step <= _max_drift &&
         (_reuse == FactorReuse::Always || reuse_pays(_last_changes, _last_rows));
}

std::vector<double> KktSolver::spring_rhs(const ConstraintBlock& C, std::span<const int> p_of,
                                          std::span<const double> bb,
                                          std::span<const double> gg) const {
  std::vector<double> b1(bb.begin(), bb.end());
  const int m = C.n_rows();
  if (m == 0) return b1;
  std::vector<double> Rg(static_cast<std::size_t>(m), 0.0);
  for (int r = 0; r < m; ++r)
    if (p_of[r] >= 0) Rg[r] = _fR[p_of[r]] * gg[r];
  C.add_transpose_multiply(Rg, -1.0, b1);
  return b1;
}

void KktSolver::multipliers(const ConstraintBlock& C, std::span<const int> p_of,
                            std::span<const double> w, std::span<const double> du,
                            std::span<const double> gg, std::span<double> dl) const {
  // M du + D w = b - C_P^T R_F g gives K du + C^T dl = b exactly with dl = w + R_F (C du + g) on
  // the rows whose springs are in the factor: the multiplier iteration stops once C du + g is
  // within the constraint tolerance, and the spring force R_F (C du + g) left over (large, R_F
  // being stiff) belongs to the multiplier, not to the residual.
  const int m = C.n_rows();
  std::copy(w.begin(), w.begin() + m, dl.begin());
  std::vector<double> cdu(static_cast<std::size_t>(m));
  C.multiply(du, cdu);
  for (int r = 0; r < m; ++r)
    if (p_of[r] >= 0) dl[r] += _fR[p_of[r]] * (cdu[r] + gg[r]);
}

KktStatistics KktSolver::solve(CsrMatrix& K, std::span<const double> b, const ConstraintBlock& C,
                               std::span<double> du, std::span<double> dl, bool symmetric,
                               const KktOptions& opt, RunStatistics* stats) {
  FE_CHECK(_pattern && K.n() == _pattern->n, "KKT solver not analysed for this pattern");
  KktStatistics out;
  _solves = 0;
  const LocalIndex n = K.n();
  const int m = C.n_rows();
  if (opt.matrix_current) _max_drift = opt.max_drift;
  _reuse = opt.reuse;

  // Augmentation weights from the stiffness at each row's DOFs (before augmenting); without the
  // current matrix, from the factored one's diagonal (which has drifted little).
  std::vector<double> R, ks;
  if (opt.matrix_current)
    augmentation_weights(K, C, opt.augmentation, R, ks);
  else
    weights_from_diagonal(
        n, [&](LocalIndex i) { return _factored.empty() ? 1.0 : _factored_diag[i]; }, C,
        opt.augmentation, R, ks);

  // Compare with what the current factor is of: rows kept (P), new rows (N), rows gone (O).
  std::vector<int> p_of(static_cast<std::size_t>(m), -1); // row of _frows, for P rows
  std::vector<int> gone;                                  // rows of _frows no longer present
  const Plan plan = compare(K, C, symmetric, opt, p_of, gone);
  out.changed_rows = plan.changes;
  bool exact_same = plan.exact_same, stale = plan.stale;
  // without the current matrix only the kept factor can be used
  auto need_matrix = [&] {
    out.needs_matrix = true;
    log::debug("  the kept factor cannot be used: the system needs the current matrix");
    return out;
  };
  if (!opt.matrix_current && !stale) return need_matrix();

  for (;;) {
    if (!exact_same && !stale) {
      fresh_factor(K, C, R, ks, symmetric, stats);
      for (int r = 0; r < m; ++r) p_of[r] = r;
      gone.clear();
    }
    out.reused_factor = exact_same || stale;
    out.stale_factor = stale;
    out.used_unsymmetric = _active != _cholmod.get();

    // A kept symmetric factor serves the changed rows through the dense multiplier matrix of
    // its own rows, new rows and anti-rows (one forward and one backward solve per step), or,
    // where that cannot be used, is made exact for the current rows by updating and downdating
    // it (no anti-rows, no new rows: the multiplier iteration is the one of a fresh factor)
    // A fresh factor that will be kept (reuse is allowed and a factorisation is not too cheap
    // to keep) makes its columns at once: the next system needs them anyway.
    const bool kept = stale || exact_same ||
                      (opt.reuse == FactorReuse::Always ||
                       (opt.reuse == FactorReuse::Auto && _t_factor >= kMinReusedFactorSeconds));
    const bool dense = _dense && !_dense_failed && kept && m > 0 && _active == _cholmod.get() &&
                       _cholmod->has_split_solves() &&
                       dense_pays(m + static_cast<int>(gone.size()), C.has_columns());
    if (stale && !dense && _modify && _active == _cholmod.get() &&
        (!gone.empty() || std::find(p_of.begin(), p_of.end(), -1) != p_of.end()) &&
        !modify_factor(C, R, ks, p_of, gone, stats)) {
      if (!opt.matrix_current) return need_matrix();
      stale = false;
      continue;
    }
    // A compliant row in the factor whose column D differs from its row C (friction that depends
    // on a penalty gap's force): in the unknown w = (1 - R_F E) dl its column is
    // C^T + (D - C^T) / (1 - R_F E), which keeps K du + D dl = b exact (see solve's derivation in
    // docs/theory/gap_elements.md).
    const ConstraintBlock* Cs = &C;
    ConstraintBlock scaled;
    if (C.has_columns())
      for (int r = 0; r < m; ++r) {
        const double E = C.row_compliance(r);
        if (p_of[r] < 0 || E == 0.0) continue;
        if (Cs == &C) {
          scaled = C;
          Cs = &scaled;
        }
        const double f = 1.0 / (1.0 - _fR[p_of[r]] * E);
        for (LocalIndex k = C.row_ptr[r]; k < C.row_ptr[r + 1]; ++k)
          scaled.dval[k] = C.val[k] + (C.dval[k] - C.val[k]) * f;
      }
    // Extended rows: the current rows, then anti-rows cancelling the springs of rows gone.
    const ConstraintBlock* Ch = Cs;
    ConstraintBlock ext;
    if (!gone.empty()) {
      ext = *Cs;
      for (int f : gone) {
        const LocalIndex b0 = _frows.row_ptr[f], b1 = _frows.row_ptr[f + 1];
        ext.add_row({_frows.col.data() + b0, static_cast<std::size_t>(b1 - b0)},
                    {_frows.val.data() + b0, static_cast<std::size_t>(b1 - b0)}, 0.0, -1);
      }
      Ch = &ext;
    }
    const int mt = Ch->n_rows();
    std::vector<double> d(static_cast<std::size_t>(mt), 0.0), p(static_cast<std::size_t>(mt));
    // Rows in the factor (spring R_F) carry w = (1 - R_F E) dl: their Schur block is
    // C M^-1 C^T + E / (1 - R_F E); new rows carry w = dl with C M^-1 C^T + E. The preconditioner
    // is the inverse of the block's estimate (C M^-1 C^T ~ 1/R_F for rows in the factor).
    for (int r = 0; r < m; ++r) {
      const double E = C.row_compliance(r);
      if (p_of[r] >= 0) {
        const double Rf = _fR[p_of[r]];
        d[r] = -E / (1.0 - Rf * E);
        p[r] = 1.0 / (1.0 / (Rf + _fks[p_of[r]]) - d[r]);
      } else {
        d[r] = -E;
        p[r] = 1.0 / (1.0 / ks[r] + E);
      }
    }
    for (std::size_t k = 0; k < gone.size(); ++k) {
      const double Rf = _fR[gone[k]];
      d[m + k] = 1.0 / Rf;
      p[m + k] = -opt.augmentation * Rf; // the anti-row block is ~ -1/(augmentation R)
    }

    const bool cg = !out.used_unsymmetric && !Ch->has_columns() && gone.empty();
    int max_it = opt.max_iterations;
    if (stale && opt.reuse == FactorReuse::Auto)
      max_it =
          std::min(max_it, std::max(20, static_cast<int>(_t_factor / std::max(_t_solve, 1e-9))));
    // One solve of the system for the right-hand side (bb, -gg) with this factor.
    auto step = [&](std::span<const double> bb, std::span<const double> gg, std::span<double> x_u,
                    std::span<double> x_l) {
      if (dense) {
        if (dense_step(C, *Cs, p_of, gone, d, bb, gg, x_u, x_l, stats)) {
          SchurResult exact;
          exact.residual = _dense_residual;
          return exact;
        }
        _dense_failed = true;
      }
      // y = M^-1 b1
      const std::vector<double> b1 = spring_rhs(C, p_of, bb, gg);
      std::vector<double> y(static_cast<std::size_t>(n));
      back_solve(b1, y, stats);
      SchurResult sr;
      if (mt == 0) {
        std::copy(y.begin(), y.end(), x_u.begin());
        return sr;
      }
      // Schur system; its residual is the predicted constraint value C du + g.
      std::vector<double> rhs(static_cast<std::size_t>(mt));
      Ch->multiply(y, rhs);
      for (int r = 0; r < m; ++r) rhs[r] += gg[r];
      // Per-row tolerances. An exact row's residual is a length: the constraint tolerance. A
      // compliant row's residual r means a force error r / E, large for a stiff penalty: it is
      // solved until that error is 1e-13 of the largest force of bb (what a direct solve of the
      // penalty matrix would give), or to round-off.
      const double tol = std::max(opt.constraint_tolerance, 1e-14 * norm_inf(rhs));
      std::vector<double> tol_r(static_cast<std::size_t>(mt), tol);
      const double force_scale = norm_inf(bb), floor = 1e-15 * norm_inf(rhs);
      for (int r = 0; r < m; ++r)
        if (const double E = C.row_compliance(r); E > 0)
          tol_r[r] = std::min(tol, std::max(1e-8 * force_scale * E, floor));
      std::vector<double> w(static_cast<std::size_t>(mt), 0.0), x(static_cast<std::size_t>(n));
      sr = schur(*Ch, d, p, rhs, w, x, cg, max_it, tol_r, stats);
      for (LocalIndex i = 0; i < n; ++i) x_u[i] = y[i] - x[i];
      multipliers(C, p_of, w, x_u, gg, x_l);
      return sr;
    };
    const SchurResult sr = step(b, C.g, du, dl);
    out.schur_iterations += sr.iterations;
    if (stale && sr.ratio > 1.0) {
      log::debug("stale factor: multiplier iteration stalled ({} iterations, residual {:.3e}); "
                 "refactorising",
                 sr.iterations, sr.residual);
      if (!opt.matrix_current) {
        _factored.clear(); // the solve with the current matrix factorises afresh
        return need_matrix();
      }
      stale = false;
      continue;
    }
    out.constraint_residual = sr.residual;
    out.solves = _solves;
    log::debug("  {} factor, {} multiplier iterations",
               stale ? "stale" : (exact_same ? "same" : "new"), sr.iterations);
    return out;
  }
}

KktSolver::SchurResult KktSolver::schur(const ConstraintBlock& Ch, std::span<const double> d,
                                        std::span<const double> p, std::span<const double> rhs,
                                        std::span<double> w, std::span<double> x, bool cg,
                                        int max_iterations, std::span<const double> tol,
                                        RunStatistics* stats) {
  SchurResult out;
  const int m = Ch.n_rows();
  const auto n = x.size();
  std::vector<double> tmp(n), v_x(n);
  // S v = Ch M^-1 D v - d v  (D = Ch^T unless the rows carry their own columns); Minv_D_v kept
  auto apply_S = [&](std::span<const double> v, std::span<double> Sv, std::span<double> Minv_D_v) {
    std::fill(tmp.begin(), tmp.end(), 0.0);
    Ch.add_column_multiply(v, 1.0, tmp);
    back_solve(tmp, Minv_D_v, stats);
    Ch.multiply(Minv_D_v, Sv);
    for (int r = 0; r < m; ++r) Sv[r] -= d[r] * v[r];
  };
  std::vector<double> res(rhs.begin(), rhs.end());
  // the largest residual relative to its row's tolerance: converged at <= 1
  auto ratio = [&] {
    double q = 0.0;
    for (int r = 0; r < m; ++r) q = std::max(q, std::abs(res[r]) / tol[r]);
    return q;
  };
  std::fill(w.begin(), w.end(), 0.0);
  std::fill(x.begin(), x.end(), 0.0);

  if (cg) {
    // Preconditioned CG (S symmetric positive (semi)definite, diagonal preconditioner p > 0).
    std::vector<double> z(static_cast<std::size_t>(m)), pv(static_cast<std::size_t>(m)),
        Sp(static_cast<std::size_t>(m));
    for (int r = 0; r < m; ++r) z[r] = p[r] * res[r];
    pv = z;
    double rz = std::inner_product(res.begin(), res.end(), z.begin(), 0.0);
    for (int it = 0; it < max_iterations && ratio() > 1.0; ++it) {
      apply_S(pv, Sp, v_x);
      const double pSp = std::inner_product(pv.begin(), pv.end(), Sp.begin(), 0.0);
      if (!(pSp > 0)) break; // redundant constraints exhausted
      const double alpha = rz / pSp;
      for (int r = 0; r < m; ++r) {
        w[r] += alpha * pv[r];
        res[r] -= alpha * Sp[r];
      }
      for (std::size_t i = 0; i < n; ++i) x[i] += alpha * v_x[i];
      ++out.iterations;
      for (int r = 0; r < m; ++r) z[r] = p[r] * res[r];
      const double rz_new = std::inner_product(res.begin(), res.end(), z.begin(), 0.0);
      const double beta = rz_new / rz;
      rz = rz_new;
      for (int r = 0; r < m; ++r) pv[r] = z[r] + beta * pv[r];
    }
    out.residual = norm_inf(res);
    out.ratio = ratio();
    return out;
  }
  // Right-preconditioned restarted GMRES.
  const int restart = std::min(m, 50);
  std::vector<std::vector<double>> V(static_cast<std::size_t>(restart) + 1,
                                     std::vector<double>(static_cast<std::size_t>(m)));
  std::vector<double> H(static_cast<std::size_t>((restart + 1) * restart), 0.0), cs(restart),
      sn(restart), s(restart + 1), zv(static_cast<std::size_t>(m)), Sz(static_cast<std::size_t>(m));
  while (ratio() > 1.0 && out.iterations < max_iterations) {
    const double beta = std::sqrt(std::inner_product(res.begin(), res.end(), res.begin(), 0.0));
    if (!(beta > 0)) break;
    for (int r = 0; r < m; ++r) V[0][r] = res[r] / beta;
    std::fill(s.begin(), s.end(), 0.0);
    s[0] = beta;
    int k = 0;
    for (; k < restart && out.iterations < max_iterations; ++k, ++out.iterations) {
      for (int r = 0; r < m; ++r) zv[r] = p[r] * V[k][r];
      apply_S(zv, Sz, v_x);
      auto& vn = V[k + 1];
      vn = Sz;
      for (int j = 0; j <= k; ++j) {
        const double h = std::inner_product(vn.begin(), vn.end(), V[j].begin(), 0.0);
        H[j * restart + k] = h;
        for (int r = 0; r < m; ++r) vn[r] -= h * V[j][r];
      }
      const double hn = std::sqrt(std::inner_product(vn.begin(), vn.end(), vn.begin(), 0.0));
      H[(k + 1) * restart + k] = hn;
      if (hn > 0)
        for (int r = 0; r < m; ++r) vn[r] /= hn;
      for (int j = 0; j < k; ++j) {
        const double a = H[j * restart + k], bb = H[(j + 1) * restart + k];
        H[j * restart + k] = cs[j] * a + sn[j] * bb;
        H[(j + 1) * restart + k] = -sn[j] * a + cs[j] * bb;
      }
      const double a = H[k * restart + k], bb = H[(k + 1) * restart + k];
      const double dd = std::hypot(a, bb);
      cs[k] = dd > 0 ? a / dd : 1.0;
      sn[k] = dd > 0 ? bb / dd : 0.0;
      H[k * restart + k] = dd;
      H[(k + 1) * restart + k] = 0.0;
      s[k + 1] = -sn[k] * s[k];
      s[k] = cs[k] * s[k];
      if (std::abs(s[k + 1]) <= 1e-15 * beta || hn == 0) {
        ++k;
        ++out.iterations;
        break;
      }
    }
    // back substitution for the Krylov coefficients, then w += p V c
    std::vector<double> c(static_cast<std::size_t>(k), 0.0);
    for (int i = k - 1; i >= 0; --i) {
      double v = s[i];
      for (int j = i + 1; j < k; ++j) v -= H[i * restart + j] * c[j];
      c[i] = H[i * restart + i] != 0 ? v / H[i * restart + i] : 0.0;
    }
    for (int j = 0; j < k; ++j)
      for (int r = 0; r < m; ++r) w[r] += p[r] * V[j][r] * c[j];
    // true residual rhs - S w, and x = M^-1 D w from the same evaluation
    apply_S(w, Sz, x);
    for (int r = 0; r < m; ++r) res[r] = rhs[r] - Sz[r];
    if (k == 0) break;
  }
  out.residual = norm_inf(res);
  out.ratio = ratio();
  return out;
}

} // namespace gapfem
