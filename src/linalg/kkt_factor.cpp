// The serial backend's factor for many right-hand sides (kkt_factor.hpp).
#include "linalg/kkt_factor.hpp"

#include "common/log.hpp"

#include <algorithm>

namespace gapfem {

namespace {
/// Columns of M^-1 (D - C^T R E) made per block when S is formed (bounds the dense scratch).
constexpr int kColumnBlock = 64;
} // namespace

void add_row_springs(CsrMatrix& K, const ConstraintBlock& C, std::span<const double> R) {
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
}

KktFactor::KktFactor(const CsrMatrix& K, const ConstraintBlock& C, bool symmetric,
                     double augmentation, RunStatistics* stats)
    : _M(K) {
  if (C.n_rows() > 0) {
    std::vector<double> ks;
    augmentation_weights(K, C, augmentation, _R, ks);
    add_row_springs(_M, C, _R);
    _rows = C;
  }
  factorize_matrix(symmetric, stats);
  if (_rows.n_rows() > 0) factorize_rows();
}

void KktFactor::factorize_matrix(bool symmetric, RunStatistics* stats) {
  if (stats) ++stats->factorizations;
  if (symmetric) {
    _solver = make_cholmod_solver();
    _solver->analyze(_M.pattern());
    try {
      ScopedTimer timer(stats, TimeCategory::Factorization);
      _solver->factorize(_M);
      return;
    } catch (const SingularSystem& e) {
      if (!e.indefinite()) throw; // as KktSolver: an indefinite matrix is still solvable by LU
      log::debug("matrix not positive definite; switching to LU");
    }
  }
  _lu = true;
  _solver = make_umfpack_solver();
  _solver->analyze(_M.pattern());
  ScopedTimer timer(stats, TimeCategory::Factorization);
  _solver->factorize(_M);
}

void KktFactor::add_row_columns(std::span<const double> w, double alpha,
                                std::span<double> y) const {
  for (int r = 0; r < _rows.n_rows(); ++r) {
    const double E = _rows.row_compliance(r);
    for (LocalIndex k = _rows.row_ptr[r]; k < _rows.row_ptr[r + 1]; ++k)
      y[_rows.col[k]] += alpha * (_rows.column_value(k) - _rows.val[k] * _R[r] * E) * w[r];
  }
}

void KktFactor::factorize_rows() {
  const auto n = static_cast<std::size_t>(_M.n());
  const int m = _rows.n_rows();
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(m, m);
  std::vector<double> B, X, unit(static_cast<std::size_t>(m)), cx(unit.size());
  for (int r0 = 0; r0 < m; r0 += kColumnBlock) {
    const int nb = std::min(kColumnBlock, m - r0);
    B.assign(n * nb, 0.0);
    X.assign(n * nb, 0.0);
    for (int j = 0; j < nb; ++j) { // column r0 + j of D - C^T R E
      std::fill(unit.begin(), unit.end(), 0.0);
      unit[r0 + j] = 1.0;
      add_row_columns(unit, 1.0, {B.data() + j * n, n});
    }
    _solver->solve_many(B, X, nb);
    for (int j = 0; j < nb; ++j) {
      _rows.multiply({X.data() + j * n, n}, cx);
      for (int q = 0; q < m; ++q) S(q, r0 + j) = cx[q];
      S(r0 + j, r0 + j) += _rows.row_compliance(r0 + j);
    }
  }
  if (!_S.compute(std::move(S)))
    throw SingularSystem("the constraint rows are linearly dependent", {});
}

void KktFactor::solve(std::span<const double> b, std::span<const double> g, std::span<double> x,
                      std::span<double> l, int k) {
  const auto n = static_cast<std::size_t>(_M.n());
  const int m = _rows.n_rows();
  if (m == 0) {
    _solver->solve_many(b, x, k);
    return;
  }
  const auto ms = static_cast<std::size_t>(m);
  // b1 = b - C^T R g, y = M^-1 b1
  std::vector<double> b1(b.begin(), b.begin() + static_cast<std::ptrdiff_t>(n * k)), y(n * k),
      Rg(ms), cy(ms);
  for (int j = 0; j < k; ++j) {
    for (int r = 0; r < m; ++r) Rg[r] = _R[r] * g[j * ms + r];
    _rows.add_transpose_multiply(Rg, -1.0, {b1.data() + j * n, n});
  }
  _solver->solve_many(b1, y, k);
  // S l = C y + g, then b1 -= (D - C^T R E) l and x = M^-1 b1
  Eigen::VectorXd rhs(m);
  for (int j = 0; j < k; ++j) {
    _rows.multiply({y.data() + j * n, n}, cy);
    for (int r = 0; r < m; ++r) rhs[r] = cy[r] + g[j * ms + r];
    const Eigen::VectorXd lj = _S.solve(rhs);
    for (int r = 0; r < m; ++r) l[j * ms + r] = lj[r];
    add_row_columns({l.data() + j * ms, ms}, -1.0, {b1.data() + j * n, n});
  }
  _solver->solve_many(b1, x, k);
}

} // namespace gapfem
