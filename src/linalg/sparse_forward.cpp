#include "linalg/sparse_forward.hpp"

#include "common/error.hpp"

#include <Eigen/Dense>
#include <algorithm>

namespace gapfem {

SparseForwardSolver::SparseForwardSolver(const cholmod_factor& L) : _L(L) {
  FE_CHECK(L.is_super && L.xtype == CHOLMOD_REAL, "sparse forward solves need a supernodal factor");
  const auto* super = static_cast<const int*>(L.super);
  const auto* pi = static_cast<const int*>(L.pi);
  const auto* s = static_cast<const int*>(L.s);
  const auto ns = static_cast<int>(L.nsuper);
  _col_super.assign(L.n, -1);
  for (int k = 0; k < ns; ++k)
    for (int j = super[k]; j < super[k + 1]; ++j) _col_super[j] = k;
  _parent.assign(static_cast<std::size_t>(ns), -1);
  for (int k = 0; k < ns; ++k) {
    const int ncol = super[k + 1] - super[k];
    if (pi[k + 1] - pi[k] > ncol) _parent[k] = _col_super[s[pi[k] + ncol]];
  }
  _stamp.assign(static_cast<std::size_t>(ns), -1);
  _active.resize(static_cast<std::size_t>(ns));
}

void SparseForwardSolver::solve(const std::vector<Column>& rhs, std::vector<Column>& out) {
  using Mat = Eigen::MatrixXd;
  using Block = Eigen::Map<const Mat, 0, Eigen::OuterStride<>>;
  const auto* super = static_cast<const int*>(_L.super);
  const auto* pi = static_cast<const int*>(_L.pi);
  const auto* px = static_cast<const int*>(_L.px);
  const auto* s = static_cast<const int*>(_L.s);
  const auto* x = static_cast<const double*>(_L.x);
  const auto n = static_cast<std::size_t>(_L.n);
  const int nb = static_cast<int>(rhs.size());
  out.assign(rhs.size(), {});
  // the supernodes each column reaches, and the columns each supernode is reached by
  std::vector<std::vector<int>> paths(rhs.size());
  std::vector<int> touched;
  for (int j = 0; j < nb; ++j) {
    for (LocalIndex r : rhs[j].rows)
      for (int k = _col_super[r]; k >= 0 && _stamp[k] != j; k = _parent[k]) {
        _stamp[k] = j;
        paths[j].push_back(k);
        if (_active[k].empty()) touched.push_back(k);
        _active[k].push_back(j);
      }
    std::sort(paths[j].begin(), paths[j].end());
  }
  std::sort(touched.begin(), touched.end()); // children before parents
  _dense.resize(n * static_cast<std::size_t>(nb));
  for (int j = 0; j < nb; ++j)
    for (std::size_t q = 0; q < rhs[j].rows.size(); ++q)
      _dense[j * n + rhs[j].rows[q]] = rhs[j].vals[q];
  Mat X, W;
  for (int k : touched) {
    const int c0 = super[k], ncol = super[k + 1] - c0, nrow = pi[k + 1] - pi[k];
    const std::vector<int>& cols = _active[k];
    const auto na = static_cast<Eigen::Index>(cols.size());
    X.resize(ncol, na);
    for (Eigen::Index c = 0; c < na; ++c)
      for (int i = 0; i < ncol; ++i) X(i, c) = _dense[cols[c] * n + c0 + i];
    const Block L11(x + px[k], ncol, ncol, Eigen::OuterStride<>(nrow));
    L11.triangularView<Eigen::Lower>().solveInPlace(X);
    for (Eigen::Index c = 0; c < na; ++c)
      for (int i = 0; i < ncol; ++i) _dense[cols[c] * n + c0 + i] = X(i, c);
    if (nrow > ncol) {
      const Block L21(x + px[k] + ncol, nrow - ncol, ncol, Eigen::OuterStride<>(nrow));
      W.noalias() = L21 * X;
      const int* below = s + pi[k] + ncol;
      for (Eigen::Index c = 0; c < na; ++c) {
        double* d = _dense.data() + cols[c] * n;
        for (int i = 0; i < nrow - ncol; ++i) d[below[i]] -= W(i, c);
      }
    }
  }
  // gather each column from its path's rows, and leave the scratch zero
  for (int j = 0; j < nb; ++j) {
    double* d = _dense.data() + j * n;
    for (int k : paths[j])
      for (int r = super[k]; r < super[k + 1]; ++r) {
        if (d[r] != 0.0) {
          out[j].rows.push_back(r);
          out[j].vals.push_back(d[r]);
        }
        d[r] = 0.0;
      }
  }
  for (int k : touched) {
    _active[k].clear();
    _stamp[k] = -1;
  }
}

} // namespace gapfem
