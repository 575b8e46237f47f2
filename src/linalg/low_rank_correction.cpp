#include "linalg/low_rank_correction.hpp"

#include "linalg/linear_solver.hpp"
#include "linalg/sparse_gram.hpp"

#include <algorithm>
#include <cmath>

namespace gapfem {

namespace {
/// The smallest eigenvalue of I + Y S Y^T (A relative to L L^T) a modified matrix may have.
constexpr double kPivotRatio = 1e-12;
} // namespace

void LowRankCorrection::reset(LocalIndex n) {
  _n = n;
  _cols.clear();
  _G.resize(0, 0);
  _added.clear();
  _removed.clear();
  _Gaa = {};
  _T = {};
  _GaaInvGar.resize(0, 0);
  _pos.assign(static_cast<std::size_t>(n), -1);
  _y_nnz = 0;
}

bool LowRankCorrection::cancel(std::span<const LocalIndex> rows, std::span<const double> vals,
                               double sign) {
  for (std::size_t j = _cols.size(); j-- > 0;) {
    const Column& c = _cols[j];
    if (c.sign != -sign || !std::equal(rows.begin(), rows.end(), c.u_row.begin(), c.u_row.end()))
      continue;
    // the same values up to round-off (a softened spring is removed as its caller recomputes it)
    double big = 0.0, diff = 0.0;
    for (std::size_t q = 0; q < vals.size(); ++q) {
      big = std::max(big, std::abs(vals[q]));
      diff = std::max(diff, std::abs(vals[q] - c.u_val[q]));
    }
    if (diff > 1e-12 * big) continue;
    _y_nnz -= c.y_row.size();
    _cols.erase(_cols.begin() + static_cast<std::ptrdiff_t>(j));
    const auto k = static_cast<Eigen::Index>(_cols.size());
    const auto J = static_cast<Eigen::Index>(j);
    // drop row and column j of G
    Eigen::MatrixXd G(k, k);
    for (Eigen::Index q = 0, qq = 0; q <= k; ++q) {
      if (q == J) continue;
      for (Eigen::Index p = 0, pp = 0; p <= k; ++p) {
        if (p == J) continue;
        G(pp++, qq) = _G(p, q);
      }
      ++qq;
    }
    _G = std::move(G);
    return true;
  }
  return false;
}

void LowRankCorrection::add(std::vector<Column> cols) {
  if (cols.empty()) return;
  const int k0 = size();
  for (Column& c : cols) {
    _y_nnz += c.y_row.size();
    _cols.push_back(std::move(c));
  }
  const auto k = static_cast<Eigen::Index>(_cols.size());
  _G.conservativeResize(k, k);
  fill_columns(k0);
}

void LowRankCorrection::fill_columns(int k0) {
  if (_pos.size() != static_cast<std::size_t>(_n)) _pos.assign(static_cast<std::size_t>(_n), -1);
  const int k = size();
  fill_gram(
      k, k0,
      [&](int j) {
        return SparseColumnView{_cols[j].y_row, _cols[j].y_val};
      },
      _G, _pos);
  for (int j = k0; j < k; ++j) _G(j, j) += _cols[j].sign;
}

void LowRankCorrection::factorize() {
  _added.clear();
  _removed.clear();
  for (int j = 0; j < size(); ++j) (_cols[j].sign > 0 ? _added : _removed).push_back(j);
  auto refuse = [] { throw SingularSystem("the modified matrix is not positive definite", {}); };
  if (!_added.empty()) {
    _Gaa.compute(_G(_added, _added));
    if (_Gaa.info() != Eigen::Success) refuse();
  }
  if (_removed.empty()) return;
  // Haynsworth: I + Y S Y^T is positive definite exactly when the Schur complement of G_AA in G
  // is negative definite, i.e. T = -(G_RR - G_RA G_AA^-1 G_AR) positive definite
  Eigen::MatrixXd T = -_G(_removed, _removed);
  if (!_added.empty()) {
    _GaaInvGar = _Gaa.solve(_G(_added, _removed));
    T.noalias() += _G(_removed, _added) * _GaaInvGar;
  }
  _T.compute(T);
  if (_T.info() != Eigen::Success) refuse();
  const Eigen::MatrixXd& L = _T.matrixLLT();
  for (Eigen::Index i = 0; i < L.rows(); ++i)
    if (!(L(i, i) * L(i, i) > kPivotRatio)) refuse();
}

void LowRankCorrection::apply(std::span<double> y, int k) const {
  if (_cols.empty()) return;
  const auto m = static_cast<Eigen::Index>(_cols.size());
  const auto n = static_cast<std::size_t>(_n);
  Eigen::MatrixXd t(m, k);
  for (int c = 0; c < k; ++c) {
    const double* yc = y.data() + c * n;
    for (Eigen::Index i = 0; i < m; ++i) {
      const Column& col = _cols[i];
      double s = 0.0;
      for (std::size_t q = 0; q < col.y_row.size(); ++q) s += col.y_val[q] * yc[col.y_row[q]];
      t(i, c) = s;
    }
  }
  // G c = t by block elimination of the added terms
  Eigen::MatrixXd coef(m, k);
  Eigen::MatrixXd zA;
  if (!_added.empty()) zA = _Gaa.solve(t(_added, Eigen::all));
  if (!_removed.empty()) {
    Eigen::MatrixXd rhs = t(_removed, Eigen::all);
    if (!_added.empty()) rhs.noalias() -= _GaaInvGar.transpose() * t(_added, Eigen::all);
    const Eigen::MatrixXd cR = -_T.solve(rhs);
    coef(_removed, Eigen::all) = cR;
    if (!_added.empty()) zA.noalias() -= _GaaInvGar * cR;
  }
  if (!_added.empty()) coef(_added, Eigen::all) = zA;
  for (int c = 0; c < k; ++c) {
    double* yc = y.data() + c * n;
    for (Eigen::Index i = 0; i < m; ++i) {
      const Column& col = _cols[i];
      const double a = coef(i, c);
      for (std::size_t q = 0; q < col.y_row.size(); ++q) yc[col.y_row[q]] -= a * col.y_val[q];
    }
  }
}

std::size_t LowRankCorrection::bytes() const {
  std::size_t b = static_cast<std::size_t>(_G.size()) * 2 * sizeof(double);
  for (const Column& c : _cols)
    b += (c.u_row.size() + c.y_row.size()) * (sizeof(LocalIndex) + sizeof(double));
  return b;
}

} // namespace gapfem
