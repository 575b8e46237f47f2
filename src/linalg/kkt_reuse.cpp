// KktSolver's reuse decisions: what a system differs by from the kept factor (its rows and the
// stiffness's drift), whether reusing the factor pays against a fresh one, and whether the dense
// multiplier path does (docs/theory/gap_elements.md §4).
#include "common/log.hpp"
#include "common/memory.hpp"
#include "linalg/kkt_solver.hpp"

#include <algorithm>
#include <cmath>

namespace gapfem {

namespace {
bool same_row(const ConstraintBlock& a, int ra, const ConstraintBlock& b, int rb) {
  const LocalIndex a0 = a.row_ptr[ra], a1 = a.row_ptr[ra + 1];
  const LocalIndex b0 = b.row_ptr[rb], b1 = b.row_ptr[rb + 1];
  if (a1 - a0 != b1 - b0) return false;
  for (LocalIndex k = 0; k < a1 - a0; ++k)
    if (a.col[a0 + k] != b.col[b0 + k] || a.val[a0 + k] != b.val[b0 + k]) return false;
  return true;
}
} // namespace

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

} // namespace gapfem
