// KktSolver's Krylov path: the multiplier (Schur) system C M^-1 D - diag(d) solved by
// preconditioned CG, or restarted GMRES when it is unsymmetric or indefinite, with one
// back-substitution of the factor per iteration (docs/theory/gap_elements.md §3).
#include "linalg/kkt_solver.hpp"
#include "linalg/norms.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace gapfem {

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
