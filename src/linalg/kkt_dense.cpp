// KktSolver's step with the dense multiplier matrix of its kept factor (linalg/
// multiplier_columns.hpp): one forward solve, a dense solve of the multipliers and one backward
// solve, instead of a Krylov iteration on the multipliers with one back-substitution per iteration.
#include "common/log.hpp"
#include "common/memory.hpp"
#include "linalg/dense_factor.hpp"
#include "linalg/kkt_solver.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace gapfem {

namespace {
/// A pivot of the scaled multiplier matrix below this marks rows that are (nearly) redundant:
/// the Krylov path, which copes with them, takes over.
constexpr double kDensePivot = 1e-12;

/// The multiplier matrix S = [S_cc S_ca; S_ac S_aa] of current rows (c) and anti-rows (a),
/// diagonally scaled. Symmetric (every row its own column): S_cc is positive definite and the
/// anti-rows' Schur complement negative definite, factorised by blocks with Cholesky, which also
/// proves the rows independent. With force columns of their own (friction on the normal
/// multiplier) S is unsymmetric: LU with partial pivoting, its condition estimate in place of the
/// pivots.
class DenseMultiplierSystem {
 public:
  /// False when the rows are (nearly) redundant.
  bool factorize(Eigen::MatrixXd S, int m, bool symmetric) {
    _S = std::move(S);
    _m = m;
    _symmetric = symmetric;
    const auto mt = _S.rows();
    _scale.resize(mt);
    for (Eigen::Index i = 0; i < mt; ++i) {
      const double d = std::abs(_S(i, i));
      if (!(d > 0) || !std::isfinite(d)) return false;
      _scale(i) = 1.0 / std::sqrt(d);
    }
    Eigen::MatrixXd Ss = _scale.asDiagonal() * _S * _scale.asDiagonal();
    if (!symmetric) return _lu.compute(std::move(Ss)) && _lu.rcond() > kDensePivot;
    const auto na = mt - m;
    if (!_cc.compute(Ss.topLeftCorner(m, m)) || !(_cc.min_pivot() > kDensePivot)) return false;
    if (na == 0) return true;
    _X = Ss.topRightCorner(m, na);
    _cc.solve_in_place(_X); // S_cc^-1 S_ca
    const Eigen::MatrixXd T = Ss.bottomLeftCorner(na, m) * _X - Ss.bottomRightCorner(na, na);
    return _aa.compute(T) && _aa.min_pivot() > kDensePivot;
  }
  /// w = S^-1 h, refined once against S; returns max |S w - h|.
  double solve(const Eigen::VectorXd& h, Eigen::VectorXd& w) const {
    w = apply(h);
    Eigen::VectorXd r = h - _S * w;
    w += apply(r);
    r = h - _S * w;
    return r.size() > 0 ? r.cwiseAbs().maxCoeff() : 0.0;
  }

 private:
  Eigen::VectorXd apply(const Eigen::VectorXd& h) const {
    const Eigen::VectorXd hs = _scale.cwiseProduct(h);
    if (!_symmetric) return _scale.cwiseProduct(_lu.solve(hs));
    const auto na = hs.size() - _m;
    Eigen::VectorXd ws(hs.size());
    const Eigen::VectorXd w0 = _m > 0 ? _cc.solve(hs.head(_m)) : Eigen::VectorXd();
    if (na == 0) {
      ws = w0;
    } else {
      // S_cc w_c + S_ca w_a = h_c, S_ac w_c + S_aa w_a = h_a, T = S_ac S_cc^-1 S_ca - S_aa
      const Eigen::VectorXd wa = _aa.solve(
          (_m > 0 ? Eigen::VectorXd(_X.transpose() * hs.head(_m)) : Eigen::VectorXd::Zero(na)) -
          hs.tail(na));
      ws.tail(na) = wa;
      if (_m > 0) ws.head(_m) = w0 - _X * wa;
    }
    return _scale.cwiseProduct(ws);
  }

  Eigen::MatrixXd _S;
  Eigen::VectorXd _scale;
  Eigen::Index _m = 0;
  bool _symmetric = true;
  DenseCholesky _cc, _aa;
  Eigen::MatrixXd _X;
  DenseLu _lu;
};
} // namespace

bool KktSolver::dense_columns(const ConstraintBlock& C, const ConstraintBlock& D,
                              std::span<const int> gone, MultiplierColumns::Combination& rows,
                              MultiplierColumns::Combination& cols, RunStatistics* stats) {
  ScopedTimer timer(stats, TimeCategory::Factorization); // counted as the factor's updates
  const Stopwatch watch;
  std::vector<int> all(static_cast<std::size_t>(C.n_rows()));
  std::iota(all.begin(), all.end(), 0);
  int total = 0;
  auto express = [&](const ConstraintBlock& B, std::span<const int> which, bool columns,
                     MultiplierColumns::Combination& out) {
    int made = 0;
    const bool ok = _mcols.express(*_cholmod, B, which, columns, out, made);
    total += made;
    return ok;
  };
  // rows: the current rows, then the anti-rows (the rows gone, whose columns are their rows)
  if (!express(C, all, false, rows) || !express(_frows, gone, false, rows)) return false;
  if (D.has_columns()) {
    if (!express(D, all, true, cols)) return false;
    const auto r0 = static_cast<std::size_t>(rows.ptr[C.n_rows()]);
    for (std::size_t k = C.n_rows(); k + 1 < rows.ptr.size(); ++k)
      cols.ptr.push_back(cols.ptr.back() + rows.ptr[k + 1] - rows.ptr[k]);
    cols.unit.insert(cols.unit.end(), rows.unit.begin() + static_cast<std::ptrdiff_t>(r0),
                     rows.unit.end());
    cols.coef.insert(cols.coef.end(), rows.coef.begin() + static_cast<std::ptrdiff_t>(r0),
                     rows.coef.end());
  }
  if (total == 0) return true;
  if (stats) stats->factor_updates += total;
  const double per_column = watch.seconds() / total;
  _t_update_row = _t_update_row > 0 ? 0.5 * (_t_update_row + per_column) : per_column;
  log::debug("  multiplier columns: {} new ({:.2e} s each), {} kept", total, per_column,
             _mcols.size() - total);
  return true;
}

bool KktSolver::dense_step(const ConstraintBlock& C, const ConstraintBlock& D,
                           std::span<const int> p_of, std::span<const int> gone,
                           std::span<const double> d, std::span<const double> bb,
                           std::span<const double> gg, std::span<double> x_u, std::span<double> x_l,
                           RunStatistics* stats) {
  const int m = C.n_rows();
  const auto mt = static_cast<Eigen::Index>(m + gone.size());
  const auto n = static_cast<LocalIndex>(bb.size());
  MultiplierColumns::Combination rows, own_cols;
  if (!dense_columns(C, D, gone, rows, own_cols, stats)) return false;
  const bool symmetric = !D.has_columns();
  MultiplierColumns::Combination& cols = symmetric ? rows : own_cols;
  // S = Z_C^T Z_D - diag(d) over the extended rows (current rows, then anti-rows)
  Eigen::MatrixXd S = _mcols.product(rows, cols);
  if (symmetric) S = 0.5 * (S + S.transpose()).eval();
  for (Eigen::Index i = 0; i < mt; ++i) S(i, i) -= d[i];
  DenseMultiplierSystem system;
  bool factored = false;
  {
    ScopedTimer timer(stats, TimeCategory::Factorization); // the multipliers' factor
    const Stopwatch watch;
    factored = system.factorize(std::move(S), m, symmetric);
    log::debug("  dense multiplier matrix: {} rows ({}), {:.3f} s", mt,
               symmetric ? "symmetric" : "unsymmetric", watch.seconds());
  }
  if (!factored) {
    log::debug("  dense multiplier matrix is singular (redundant rows): Krylov path");
    return false;
  }
  // t = L^-1 P b1;  rhs = Z_C^T t + gg
  const std::vector<double> b1 = spring_rhs(C, p_of, bb, gg);
  std::vector<double> t(static_cast<std::size_t>(n));
  Eigen::VectorXd w;
  {
    ScopedTimer timer(stats, TimeCategory::Solve);
    const Stopwatch watch;
    if (stats) ++stats->linear_solves;
    ++_solves;
    _cholmod->forward(b1, t);
    Eigen::VectorXd rhs(mt);
    _mcols.dot(rows, t, {rhs.data(), static_cast<std::size_t>(mt)});
    for (int r = 0; r < m; ++r) rhs(r) += gg[r];
    const double residual = system.solve(rhs, w);
    _mcols.subtract(cols, {w.data(), static_cast<std::size_t>(mt)}, t);
    _cholmod->backward(t, x_u);
    const double dt = watch.seconds();
    _t_solve = _t_solve > 0 ? 0.8 * _t_solve + 0.2 * dt : dt;
    _dense_residual = residual;
  }
  multipliers(C, p_of, {w.data(), static_cast<std::size_t>(mt)}, x_u, gg, x_l);
  _mcols.prune(rows, cols);
  return true;
}

} // namespace gapfem
