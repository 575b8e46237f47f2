#include "linalg/sparse_forward.hpp"

#include "common/error.hpp"
#include "linalg/blas.hpp"

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
  std::vector<double> X, W;
  for (int k : touched) {
    const int c0 = super[k], ncol = super[k + 1] - c0, nrow = pi[k + 1] - pi[k];
    const int nbelow = nrow - ncol;
    const std::vector<int>& cols = _active[k];
    const int na = static_cast<int>(cols.size());
    // X = the block's rows of the columns that reach it (ncol x na), solved with L11
    X.resize(static_cast<std::size_t>(ncol) * na);
    for (int c = 0; c < na; ++c)
      std::copy_n(_dense.data() + cols[c] * n + c0, ncol, X.data() + c * ncol);
    const double one = 1.0, zero = 0.0;
    dtrsm_("L", "L", "N", "N", &ncol, &na, &one, x + px[k], &nrow, X.data(), &ncol);
    for (int c = 0; c < na; ++c)
      std::copy_n(X.data() + c * ncol, ncol, _dense.data() + cols[c] * n + c0);
    if (nbelow > 0) { // the rows below: W = L21 X, subtracted where they belong
      W.resize(static_cast<std::size_t>(nbelow) * na);
      dgemm_("N", "N", &nbelow, &na, &ncol, &one, x + px[k] + ncol, &nrow, X.data(), &ncol, &zero,
             W.data(), &nbelow);
      const int* below = s + pi[k] + ncol;
      for (int c = 0; c < na; ++c) {
        double* d = _dense.data() + cols[c] * n;
        const double* wc = W.data() + c * nbelow;
        for (int i = 0; i < nbelow; ++i) d[below[i]] -= wc[i];
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
