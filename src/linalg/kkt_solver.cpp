#include "linalg/kkt_solver.hpp"

#include "common/error.hpp"
#include "common/log.hpp"
#include "common/memory.hpp"
#include "linalg/kkt_factor.hpp"
#include "linalg/norms.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numeric>
#include <string_view>

namespace gapfem {

namespace {
/// A compliant row's spring in the factor must stay softer than the row itself (R E < 1, see
/// solve()); half of it keeps the Schur system well away from that limit.
constexpr double kCompliantSpringShare = 0.5;

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

KktSolver::KktSolver(const KktTuning& tuning)
    : _modify(tuning.factor_updates), _dense(tuning.dense_multipliers) {}
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
  _cholmod_ready = _umfpack_ready = _memory_checked = false;
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

std::unique_ptr<ConstrainedFactor> KktSolver::factorize(const CsrMatrix& K,
                                                        const ConstraintBlock& C, bool symmetric,
                                                        RunStatistics* stats) {
  FE_CHECK(_pattern && K.n() == _pattern->n, "KKT solver not analysed for this pattern");
  return std::make_unique<KktFactor>(K, C, symmetric, KktOptions{}.augmentation, stats);
}

std::size_t KktSolver::factor_bytes_estimate() {
  FE_CHECK(_pattern, "KKT solver not analysed");
  if (!_cholmod) _cholmod = make_cholmod_solver();
  if (!_cholmod_ready) {
    _cholmod->analyze(*_pattern);
    _cholmod_ready = true;
  }
  return _cholmod->factor_bytes();
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
    }
    if (!_memory_checked) {
      check_memory(_cholmod->factor_bytes());
      _memory_checked = true;
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
  add_row_springs(K, C, R);
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

void KktSolver::row_weights(const CsrMatrix& K, const ConstraintBlock& C, const KktOptions& opt,
                            System& sys) const {
  // Augmentation weights from the stiffness at each row's DOFs (before augmenting); without the
  // current matrix, from the factored one's diagonal (which has drifted little).
  if (opt.matrix_current)
    augmentation_weights(K, C, opt.augmentation, sys.R, sys.ks);
  else
    weights_from_diagonal(
        K.n(), [&](LocalIndex i) { return _factored.empty() ? 1.0 : _factored_diag[i]; }, C,
        opt.augmentation, sys.R, sys.ks);
}

bool KktSolver::use_dense(const System& sys, bool reused, const KktOptions& opt) const {
  // A kept symmetric factor serves the changed rows through the dense multiplier matrix of
  // its own rows, new rows and anti-rows (one forward and one backward solve per step), or,
  // where that cannot be used, is made exact for the current rows by updating and downdating
  // it (no anti-rows, no new rows: the multiplier iteration is the one of a fresh factor)
  // A fresh factor that will be kept (reuse is allowed and a factorisation is not too cheap
  // to keep) makes its columns at once: the next system needs them anyway.
  const ConstraintBlock& C = *sys.C;
  const int m = C.n_rows();
  const bool kept =
      reused || (opt.reuse == FactorReuse::Always ||
                 (opt.reuse == FactorReuse::Auto && _t_factor >= kMinReusedFactorSeconds));
  return _dense && !_dense_failed && kept && m > 0 && _active == _cholmod.get() &&
         _cholmod->has_split_solves() &&
         dense_pays(m + static_cast<int>(sys.gone.size()), C.has_columns());
}

void KktSolver::prepare_rows(System& sys, const KktOptions& opt, bool stale,
                             bool unsymmetric) const {
  const ConstraintBlock& C = *sys.C;
  const int m = C.n_rows();
  // A compliant row in the factor whose column D differs from its row C (friction that depends
  // on a penalty gap's force): in the unknown w = (1 - R_F E) dl its column is
  // C^T + (D - C^T) / (1 - R_F E), which keeps K du + D dl = b exact (see solve's derivation in
  // docs/theory/gap_elements.md).
  sys.Cs = &C;
  if (C.has_columns())
    for (int r = 0; r < m; ++r) {
      const double E = C.row_compliance(r);
      if (sys.p_of[r] < 0 || E == 0.0) continue;
      if (sys.Cs == &C) {
        sys.scaled = C;
        sys.Cs = &sys.scaled;
      }
      const double f = 1.0 / (1.0 - _fR[sys.p_of[r]] * E);
      for (LocalIndex k = C.row_ptr[r]; k < C.row_ptr[r + 1]; ++k)
        sys.scaled.dval[k] = C.val[k] + (C.dval[k] - C.val[k]) * f;
    }
  // Extended rows: the current rows, then anti-rows cancelling the springs of rows gone.
  sys.Ch = sys.Cs;
  if (!sys.gone.empty()) {
    sys.ext = *sys.Cs;
    for (int f : sys.gone) {
      const LocalIndex b0 = _frows.row_ptr[f], b1 = _frows.row_ptr[f + 1];
      sys.ext.add_row({_frows.col.data() + b0, static_cast<std::size_t>(b1 - b0)},
                      {_frows.val.data() + b0, static_cast<std::size_t>(b1 - b0)}, 0.0, -1);
    }
    sys.Ch = &sys.ext;
  }
  const int mt = sys.Ch->n_rows();
  sys.d.assign(static_cast<std::size_t>(mt), 0.0);
  sys.p.assign(static_cast<std::size_t>(mt), 0.0);
  // Rows in the factor (spring R_F) carry w = (1 - R_F E) dl: their Schur block is
  // C M^-1 C^T + E / (1 - R_F E); new rows carry w = dl with C M^-1 C^T + E. The preconditioner
  // is the inverse of the block's estimate (C M^-1 C^T ~ 1/R_F for rows in the factor).
  for (int r = 0; r < m; ++r) {
    const double E = C.row_compliance(r);
    if (sys.p_of[r] >= 0) {
      const double Rf = _fR[sys.p_of[r]];
      sys.d[r] = -E / (1.0 - Rf * E);
      sys.p[r] = 1.0 / (1.0 / (Rf + _fks[sys.p_of[r]]) - sys.d[r]);
    } else {
      sys.d[r] = -E;
      sys.p[r] = 1.0 / (1.0 / sys.ks[r] + E);
    }
  }
  for (std::size_t k = 0; k < sys.gone.size(); ++k) {
    const double Rf = _fR[sys.gone[k]];
    sys.d[m + k] = 1.0 / Rf;
    sys.p[m + k] = -opt.augmentation * Rf; // the anti-row block is ~ -1/(augmentation R)
  }
  sys.cg = !unsymmetric && !sys.Ch->has_columns() && sys.gone.empty();
  sys.max_iterations = opt.max_iterations;
  if (stale && opt.reuse == FactorReuse::Auto)
    sys.max_iterations = std::min(
        sys.max_iterations, std::max(20, static_cast<int>(_t_factor / std::max(_t_solve, 1e-9))));
}

KktSolver::SchurResult KktSolver::solve_step(const System& sys, std::span<const double> bb,
                                             std::span<const double> gg, std::span<double> x_u,
                                             std::span<double> x_l, const KktOptions& opt,
                                             RunStatistics* stats) {
  const ConstraintBlock& C = *sys.C;
  const LocalIndex n = _pattern->n;
  const int m = C.n_rows(), mt = sys.Ch->n_rows();
  if (sys.dense) {
    if (dense_step(C, *sys.Cs, sys.p_of, sys.gone, sys.d, bb, gg, x_u, x_l, stats)) {
      SchurResult exact;
      exact.residual = _dense_residual;
      return exact;
    }
    _dense_failed = true;
  }
  // y = M^-1 b1
  const std::vector<double> b1 = spring_rhs(C, sys.p_of, bb, gg);
  std::vector<double> y(static_cast<std::size_t>(n));
  back_solve(b1, y, stats);
  SchurResult sr;
  if (mt == 0) {
    std::copy(y.begin(), y.end(), x_u.begin());
    return sr;
  }
  // Schur system; its residual is the predicted constraint value C du + g.
  std::vector<double> rhs(static_cast<std::size_t>(mt));
  sys.Ch->multiply(y, rhs);
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
  sr = schur(*sys.Ch, sys.d, sys.p, rhs, w, x, sys.cg, sys.max_iterations, tol_r, stats);
  for (LocalIndex i = 0; i < n; ++i) x_u[i] = y[i] - x[i];
  multipliers(C, sys.p_of, w, x_u, gg, x_l);
  return sr;
}

KktStatistics KktSolver::solve(CsrMatrix& K, std::span<const double> b, const ConstraintBlock& C,
                               std::span<double> du, std::span<double> dl, bool symmetric,
                               const KktOptions& opt, RunStatistics* stats) {
  FE_CHECK(_pattern && K.n() == _pattern->n, "KKT solver not analysed for this pattern");
  KktStatistics out;
  _solves = 0;
  const int m = C.n_rows();
  if (opt.matrix_current) _max_drift = opt.max_drift;
  _reuse = opt.reuse;
  System sys;
  sys.C = &C;
  row_weights(K, C, opt, sys);

  // Compare with what the current factor is of: rows kept (P), new rows (N), rows gone (O).
  sys.p_of.assign(static_cast<std::size_t>(m), -1); // row of _frows, for P rows
  const Plan plan = compare(K, C, symmetric, opt, sys.p_of, sys.gone);
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
      fresh_factor(K, C, sys.R, sys.ks, symmetric, stats);
      for (int r = 0; r < m; ++r) sys.p_of[r] = r;
      sys.gone.clear();
    }
    out.reused_factor = exact_same || stale;
    out.stale_factor = stale;
    out.used_unsymmetric = _active != _cholmod.get();
    sys.dense = use_dense(sys, stale || exact_same, opt);
    if (stale && !sys.dense && _modify && _active == _cholmod.get() &&
        (!sys.gone.empty() || std::find(sys.p_of.begin(), sys.p_of.end(), -1) != sys.p_of.end()) &&
        !modify_factor(C, sys.R, sys.ks, sys.p_of, sys.gone, stats)) {
      if (!opt.matrix_current) return need_matrix();
      stale = false;
      continue;
    }
    prepare_rows(sys, opt, stale, out.used_unsymmetric);
    const SchurResult sr = solve_step(sys, b, C.g, du, dl, opt, stats);
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

} // namespace gapfem
