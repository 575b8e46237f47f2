#include "linalg/kkt_solver.hpp"

#include "common/error.hpp"
#include "common/log.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace gapfem {

KktSolver::KktSolver() = default;
KktSolver::~KktSolver() = default;

void KktSolver::analyze(std::shared_ptr<const SparsityPattern> pattern) {
  _pattern = std::move(pattern);
  _cholmod_ready = _umfpack_ready = false;
  _active = nullptr;
  _factored.clear();
}

void KktSolver::factorize(const CsrMatrix& M, bool symmetric, RunStatistics* stats) {
  ScopedTimer timer(stats, TimeCategory::Factorization);
  if (stats) ++stats->factorizations;
  if (symmetric) {
    if (!_cholmod) _cholmod = make_cholmod_solver();
    if (!_cholmod_ready) {
      _cholmod->analyze(*_pattern);
      _cholmod_ready = true;
    }
    try {
      _cholmod->factorize(M);
      _active = _cholmod.get();
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
}

void KktSolver::back_solve(std::span<const double> b, std::span<double> x, RunStatistics* stats) {
  ScopedTimer timer(stats, TimeCategory::Solve);
  if (stats) ++stats->linear_solves;
  ++_solves;
  _active->solve(b, x);
}

KktStatistics KktSolver::solve(CsrMatrix& K, std::span<const double> b, const ConstraintBlock& C,
                               std::span<double> du, std::span<double> dl, bool symmetric,
                               const KktOptions& opt, RunStatistics* stats) {
  FE_CHECK(_pattern && K.n() == _pattern->n, "KKT solver not analysed for this pattern");
  KktStatistics out;
  // The multiplier system is solved by CG when [K D; C 0] is symmetric, by GMRES otherwise.
  _solves = 0;
  const LocalIndex n = K.n();
  const int m = C.n_rows();

  // Augmentation weights from the stiffness at each row's DOFs (before augmenting).
  std::vector<double> R(static_cast<std::size_t>(m), 0.0);
  if (m > 0) {
    double mean_diag = 0.0;
    for (LocalIndex i = 0; i < n; ++i) mean_diag += std::abs(K.diagonal(i));
    mean_diag = n > 0 ? mean_diag / n : 1.0;
    if (!(mean_diag > 0)) mean_diag = 1.0;
    for (int r = 0; r < m; ++r) {
      double num = 0.0, den = 0.0;
      for (LocalIndex k = C.row_ptr[r]; k < C.row_ptr[r + 1]; ++k) {
        const double c2 = C.val[k] * C.val[k];
        num += c2 * std::abs(K.diagonal(C.col[k]));
        den += c2;
      }
      double stiff = den > 0 ? num / den : 0.0;
      if (!(stiff > 1e-12 * mean_diag)) stiff = mean_diag;
      R[r] = opt.augmentation * stiff / std::max(den, 1e-300);
    }
    // M = K + C^T R C (entries lie inside each row's element block, hence inside the pattern).
    std::vector<LocalIndex> eqs;
    std::vector<double> block;
    for (int r = 0; r < m; ++r) {
      const LocalIndex b0 = C.row_ptr[r], b1 = C.row_ptr[r + 1];
      const auto len = static_cast<std::size_t>(b1 - b0);
      eqs.assign(C.col.begin() + b0, C.col.begin() + b1);
      block.resize(len * len);
      for (std::size_t i = 0; i < len; ++i)
        for (std::size_t j = 0; j < len; ++j) block[i * len + j] = R[r] * C.val[b0 + i] * C.val[b0 + j];
      K.add_block(eqs, eqs, block);
    }
  }
  // A matrix equal to the one already factored (a linear model, an unchanged contact set) reuses
  // the factor: the step factorises once and solves many times.
  const auto vals = K.values();
  if (_active && symmetric == _factored_symmetric && _factored.size() == vals.size() &&
      std::equal(vals.begin(), vals.end(), _factored.begin())) {
    out.reused_factor = true;
  } else {
    _factored.clear(); // no stale factor survives a failed factorisation
    factorize(K, symmetric, stats);
    _factored.assign(vals.begin(), vals.end());
    _factored_symmetric = symmetric;
  }
  out.used_unsymmetric = _active != _cholmod.get();

  // b1 = b - C^T R g ;  y = M^-1 b1
  std::vector<double> b1(b.begin(), b.end());
  if (m > 0) {
    std::vector<double> Rg(static_cast<std::size_t>(m));
    for (int r = 0; r < m; ++r) Rg[r] = R[r] * C.g[r];
    C.add_transpose_multiply(Rg, -1.0, b1);
  }
  std::vector<double> y(static_cast<std::size_t>(n));
  back_solve(b1, y, stats);
  if (m == 0) {
    std::copy(y.begin(), y.end(), du.begin());
    out.solves = _solves;
    return out;
  }

  // Schur system S dl = rhs, S = C M^-1 C^T, rhs = C y + g. Residual = C du + g (predicted gap).
  std::vector<double> rhs(static_cast<std::size_t>(m));
  C.multiply(y, rhs);
  for (int r = 0; r < m; ++r) rhs[r] += C.g[r];
  std::fill(dl.begin(), dl.end(), 0.0);
  std::vector<double> w(static_cast<std::size_t>(n)), tmp(static_cast<std::size_t>(n));
  // S v = C M^-1 D v  (D = C^T unless the rows carry their own residual columns)
  auto apply_S = [&](std::span<const double> v, std::span<double> Sv, std::span<double> Minv_Ct_v) {
    std::fill(tmp.begin(), tmp.end(), 0.0);
    C.add_column_multiply(v, 1.0, tmp);
    back_solve(tmp, Minv_Ct_v, stats);
    C.multiply(Minv_Ct_v, Sv);
  };
  auto norm_inf = [](std::span<const double> v) {
    double s = 0.0;
    for (double x : v) s = std::max(s, std::abs(x));
    return s;
  };
  const double tol = std::max(opt.constraint_tolerance, 1e-14 * norm_inf(rhs));
  std::vector<double> res(rhs);
  std::copy(y.begin(), y.end(), du.begin()); // du = y - M^-1 C^T dl, accumulated

  if (!out.used_unsymmetric && !C.has_columns()) {
    // Preconditioned CG (S symmetric positive (semi)definite, preconditioner R).
    std::vector<double> z(static_cast<std::size_t>(m)), p(static_cast<std::size_t>(m)),
        Sp(static_cast<std::size_t>(m));
    for (int r = 0; r < m; ++r) z[r] = R[r] * res[r];
    p = z;
    double rz = std::inner_product(res.begin(), res.end(), z.begin(), 0.0);
    for (int it = 0; it < opt.max_iterations && norm_inf(res) > tol; ++it) {
      apply_S(p, Sp, w);
      const double pSp = std::inner_product(p.begin(), p.end(), Sp.begin(), 0.0);
      if (!(pSp > 0)) break; // redundant constraints exhausted
      const double alpha = rz / pSp;
      for (int r = 0; r < m; ++r) {
        dl[r] += alpha * p[r];
        res[r] -= alpha * Sp[r];
      }
      for (LocalIndex i = 0; i < n; ++i) du[i] -= alpha * w[i];
      ++out.schur_iterations;
      for (int r = 0; r < m; ++r) z[r] = R[r] * res[r];
      const double rz_new = std::inner_product(res.begin(), res.end(), z.begin(), 0.0);
      const double beta = rz_new / rz;
      rz = rz_new;
      for (int r = 0; r < m; ++r) p[r] = z[r] + beta * p[r];
    }
  } else {
    // Right-preconditioned restarted GMRES on S with preconditioner R.
    const int restart = std::min(m, 30);
    std::vector<std::vector<double>> V(static_cast<std::size_t>(restart) + 1,
                                       std::vector<double>(static_cast<std::size_t>(m)));
    std::vector<double> H(static_cast<std::size_t>((restart + 1) * restart), 0.0), cs(restart),
        sn(restart), s(restart + 1), zv(static_cast<std::size_t>(m)), Sz(static_cast<std::size_t>(m));
    int total = 0;
    while (norm_inf(res) > tol && total < opt.max_iterations) {
      const double beta = std::sqrt(std::inner_product(res.begin(), res.end(), res.begin(), 0.0));
      if (!(beta > 0)) break;
      for (int r = 0; r < m; ++r) V[0][r] = res[r] / beta;
      std::fill(s.begin(), s.end(), 0.0);
      s[0] = beta;
      int k = 0;
      for (; k < restart && total < opt.max_iterations; ++k, ++total) {
        for (int r = 0; r < m; ++r) zv[r] = R[r] * V[k][r];
        apply_S(zv, Sz, w);
        ++out.schur_iterations;
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
        const double d = std::hypot(a, bb);
        cs[k] = d > 0 ? a / d : 1.0;
        sn[k] = d > 0 ? bb / d : 0.0;
        H[k * restart + k] = d;
        H[(k + 1) * restart + k] = 0.0;
        s[k + 1] = -sn[k] * s[k];
        s[k] = cs[k] * s[k];
        if (std::abs(s[k + 1]) <= 1e-15 * beta || hn == 0) {
          ++k;
          break;
        }
      }
      // back substitution for the Krylov coefficients, then dl += R V c
      std::vector<double> c(static_cast<std::size_t>(k), 0.0);
      for (int i = k - 1; i >= 0; --i) {
        double v = s[i];
        for (int j = i + 1; j < k; ++j) v -= H[i * restart + j] * c[j];
        c[i] = H[i * restart + i] != 0 ? v / H[i * restart + i] : 0.0;
      }
      std::vector<double> ddl(static_cast<std::size_t>(m), 0.0);
      for (int j = 0; j < k; ++j)
        for (int r = 0; r < m; ++r) ddl[r] += R[r] * V[j][r] * c[j];
      for (int r = 0; r < m; ++r) dl[r] += ddl[r];
      // true residual: rhs - S dl
      apply_S(dl, Sz, w);
      for (int r = 0; r < m; ++r) res[r] = rhs[r] - Sz[r];
      if (k == 0) break;
    }
    // du = y - M^-1 C^T dl  (w holds M^-1 C^T dl from the last residual evaluation)
    for (LocalIndex i = 0; i < n; ++i) du[i] = y[i] - w[i];
  }
  out.constraint_residual = norm_inf(res);
  out.solves = _solves;
  return out;
}

} // namespace gapfem
