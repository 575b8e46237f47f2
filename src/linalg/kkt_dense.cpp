// KktSolver's step with the dense multiplier matrix of its kept factor (linalg/
// multiplier_columns.hpp): one forward solve, a dense solve of the multipliers and one backward
// solve, instead of a Krylov iteration on the multipliers with one back-substitution per iteration.
#include "common/log.hpp"
#include "common/memory.hpp"
#include "linalg/kkt_solver.hpp"

#include <algorithm>
#include <cmath>

namespace gapfem {

namespace {
/// A pivot of the scaled multiplier matrix below this marks rows that are (nearly) redundant:
/// the Krylov path, which copes with them, takes over.
constexpr double kDensePivot = 1e-12;

/// The multiplier matrix S = [S_cc S_ca; S_ac S_aa] of current rows (c, positive definite) and
/// anti-rows (a, whose Schur complement is negative definite), symmetrically scaled by its
/// diagonal and factorised by blocks.
class DenseMultiplierSystem {
 public:
  /// False when S_cc is not (numerically) positive definite or the anti-rows' complement is not
  /// negative definite.
  bool factorize(Eigen::MatrixXd S, int m) {
    _S = std::move(S);
    _m = m;
    const auto mt = _S.rows();
    _scale.resize(mt);
    for (Eigen::Index i = 0; i < mt; ++i) {
      const double d = std::abs(_S(i, i));
      if (!(d > 0) || !std::isfinite(d)) return false;
      _scale(i) = 1.0 / std::sqrt(d);
    }
    const Eigen::MatrixXd Ss = _scale.asDiagonal() * _S * _scale.asDiagonal();
    const auto na = mt - m;
    _cc.compute(Ss.topLeftCorner(m, m));
    if (_cc.info() != Eigen::Success) return false;
    if (m > 0 && !(_cc.matrixLLT().diagonal().cwiseAbs2().minCoeff() > kDensePivot)) return false;
    if (na == 0) return true;
    _X = _cc.solve(Ss.topRightCorner(m, na)); // S_cc^-1 S_ca
    const Eigen::MatrixXd T = Ss.bottomLeftCorner(na, m) * _X - Ss.bottomRightCorner(na, na);
    _aa.compute(T);
    if (_aa.info() != Eigen::Success) return false;
    return _aa.matrixLLT().diagonal().cwiseAbs2().minCoeff() > kDensePivot;
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
    const auto na = hs.size() - _m;
    Eigen::VectorXd ws(hs.size());
    const Eigen::VectorXd w0 = _m > 0 ? Eigen::VectorXd(_cc.solve(hs.head(_m))) : Eigen::VectorXd();
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
  Eigen::LLT<Eigen::MatrixXd> _cc;
  Eigen::LLT<Eigen::MatrixXd> _aa;
  Eigen::MatrixXd _X;
};
} // namespace

bool KktSolver::dense_columns(const ConstraintBlock& C, std::span<const int> gone,
                              std::vector<int>& idx, RunStatistics* stats) {
  const int m = C.n_rows();
  const auto na = static_cast<int>(gone.size());
  idx.assign(static_cast<std::size_t>(m + na), -1);
  std::vector<int> missing_c, missing_f; // rows of C, rows of _frows
  std::vector<int> missing_f_at;         // their places in idx
  for (int r = 0; r < m; ++r)
    if ((idx[r] = _mcols.find(C, r)) < 0) missing_c.push_back(r);
  for (int k = 0; k < na; ++k)
    if ((idx[m + k] = _mcols.find(_frows, gone[k])) < 0) {
      missing_f.push_back(gone[k]);
      missing_f_at.push_back(m + k);
    }
  const auto added = missing_c.size() + missing_f.size();
  if (added == 0) return true;
  ScopedTimer timer(stats, TimeCategory::Factorization); // counted as the factor's updates
  const Stopwatch watch;
  std::vector<int> got;
  if (!_mcols.add(*_cholmod, C, missing_c, got)) return false;
  for (std::size_t j = 0; j < got.size(); ++j) idx[missing_c[j]] = got[j];
  if (!_mcols.add(*_cholmod, _frows, missing_f, got)) return false;
  for (std::size_t j = 0; j < got.size(); ++j) idx[missing_f_at[j]] = got[j];
  if (stats) stats->factor_updates += static_cast<long>(added);
  const double per_row = watch.seconds() / static_cast<double>(added);
  _t_update_row = _t_update_row > 0 ? 0.5 * (_t_update_row + per_row) : per_row;
  log::debug("  multiplier columns: {} new ({:.2e} s each), {} kept", added, per_row,
             _mcols.size() - static_cast<int>(added));
  return true;
}

bool KktSolver::dense_step(const ConstraintBlock& C, std::span<const int> p_of,
                           std::span<const int> gone, std::span<const double> d,
                           std::span<const double> bb, std::span<const double> gg,
                           std::span<double> x_u, std::span<double> x_l, RunStatistics* stats) {
  const int m = C.n_rows();
  const auto mt = static_cast<Eigen::Index>(m + gone.size());
  const auto n = static_cast<LocalIndex>(bb.size());
  std::vector<int> idx;
  if (!dense_columns(C, gone, idx, stats)) return false;
  // S = Z^T Z - diag(d) over the extended rows (current rows, then anti-rows)
  Eigen::MatrixXd S = _mcols.gram()(idx, idx);
  for (Eigen::Index i = 0; i < mt; ++i) S(i, i) -= d[i];
  DenseMultiplierSystem system;
  if (!system.factorize(std::move(S), m)) {
    log::debug("  dense multiplier matrix is singular (redundant rows): Krylov path");
    return false;
  }
  // b1 = bb - C_P^T R_F gg;  t = L^-1 P b1;  rhs = Z^T t + gg
  std::vector<double> b1(bb.begin(), bb.end());
  std::vector<double> Rg(static_cast<std::size_t>(m), 0.0);
  for (int r = 0; r < m; ++r)
    if (p_of[r] >= 0) Rg[r] = _fR[p_of[r]] * gg[r];
  C.add_transpose_multiply(Rg, -1.0, b1);
  std::vector<double> t(static_cast<std::size_t>(n));
  {
    ScopedTimer timer(stats, TimeCategory::Solve);
    const Stopwatch watch;
    if (stats) ++stats->linear_solves;
    ++_solves;
    _cholmod->forward(b1, t);
    Eigen::VectorXd rhs(mt), w;
    _mcols.dot(idx, t, {rhs.data(), static_cast<std::size_t>(mt)});
    for (int r = 0; r < m; ++r) rhs(r) += gg[r];
    const double residual = system.solve(rhs, w);
    _mcols.subtract(idx, {w.data(), static_cast<std::size_t>(mt)}, t);
    _cholmod->backward(t, x_u);
    const double dt = watch.seconds();
    _t_solve = _t_solve > 0 ? 0.8 * _t_solve + 0.2 * dt : dt;
    _dense_residual = residual;
    // the multipliers: dl = w + R_F (C du + g) on the rows whose springs are in the factor
    std::copy(w.data(), w.data() + m, x_l.begin());
  }
  std::vector<double> cdu(static_cast<std::size_t>(m));
  C.multiply(x_u, cdu);
  for (int r = 0; r < m; ++r)
    if (p_of[r] >= 0) x_l[r] += _fR[p_of[r]] * (cdu[r] + gg[r]);
  // keep the columns in use, and the others while they are few (a gap that opens often closes
  // again in a later increment)
  std::vector<int> used(idx.begin(), idx.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  if (_mcols.size() > 2 * static_cast<int>(used.size()) + 64) _mcols.keep(used);
  return true;
}

} // namespace gapfem
