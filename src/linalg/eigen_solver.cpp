#include "linalg/eigen_solver.hpp"

#include "linalg/krylov_eigen.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numeric>
#include <optional>
#include <stdexcept>

namespace gapfem {
namespace {

/// C with zero right sides and D = C^T (the perturbation's rows are symmetric constraints).
ConstraintBlock homogeneous(const ConstraintBlock& C) {
  ConstraintBlock h;
  h.row_ptr = C.row_ptr;
  h.col = C.col;
  h.val = C.val;
  h.g.assign(C.g.size(), 0.0);
  h.compliance = C.compliance;
  h.multiplier = C.multiplier;
  return h;
}

/// (K - sigma M)^-1 under the rows: the shift-invert of the Lanczos runs and of the dense route.
class ShiftInvert {
 public:
  using Scalar = double;
  ShiftInvert(ConstrainedSolver& solver, const CsrMatrix& K, const CsrMatrix& M,
              const ConstraintBlock& C, RunStatistics* stats, EigenPairs& out)
      : _solver(solver), _K(K), _M(M), _C(C), _stats(stats), _out(out) {}
  Eigen::Index rows() const { return _K.n(); }
  Eigen::Index cols() const { return _K.n(); }
  /// Factorise K - sigma M.
  void set_shift(double sigma) {
    CsrMatrix A = _K;
    const auto m = _M.values();
    auto a = A.values();
    for (std::size_t k = 0; k < a.size(); ++k) a[k] -= sigma * m[k];
    _factor = _solver.factorize(A, _C, true, _stats);
    ++_out.factorizations;
  }
  void perform_op(const double* x, double* y) const { solve(x, y, 1); }
  /// y = (K - sigma M)^-1_C x for k columns.
  void solve(const double* x, double* y, int k) const {
    ScopedTimer timer(_stats, TimeCategory::Solve);
    if (_stats) _stats->linear_solves += k;
    const std::size_t n = static_cast<std::size_t>(_K.n()), m = _C.g.size();
    _g.assign(m * static_cast<std::size_t>(k), 0.0);
    _l.assign(_g.size(), 0.0);
    _factor->solve({x, n * k}, _g, {y, n * k}, _l, k);
    _out.operations += k;
  }

 private:
  ConstrainedSolver& _solver;
  const CsrMatrix& _K;
  const CsrMatrix& _M;
  const ConstraintBlock& _C;
  RunStatistics* _stats;
  EigenPairs& _out;
  std::unique_ptr<ConstrainedFactor> _factor;
  mutable std::vector<double> _g, _l;
};

/// M x (the inner product). A Lanczos run's M-inner products multiply the same vector by M again
/// and again (its norm, then its products with each basis vector): the last product is kept and
/// handed back while the vector is the same one (a comparison costs far less than the product).
class MassProduct {
 public:
  using Scalar = double;
  explicit MassProduct(const CsrMatrix& M) : _M(M) {}
  Eigen::Index rows() const { return _M.n(); }
  Eigen::Index cols() const { return _M.n(); }
  void perform_op(const double* x, double* y) const {
    const std::size_t n = static_cast<std::size_t>(_M.n());
    if (_x.size() != n || !std::equal(x, x + n, _x.begin())) {
      _x.assign(x, x + n);
      _y.resize(n);
      _M.multiply({x, n}, _y);
    }
    std::copy(_y.begin(), _y.end(), y);
  }

 private:
  const CsrMatrix& _M;
  mutable std::vector<double> _x, _y; ///< the last vector and its product
};

/// sum K_ii / sum M_ii over the equations with mass: the size of the eigenvalues (a shift scale).
double eigen_scale(const CsrMatrix& K, const CsrMatrix& M) {
  double k = 0.0, m = 0.0;
  for (LocalIndex i = 0; i < K.n(); ++i)
    if (M.diagonal(i) > 0.0) {
      k += std::abs(K.diagonal(i));
      m += M.diagonal(i);
    }
  return m > 0.0 && k > 0.0 ? k / m : 1.0;
}

/// The shifts tried in turn: the requested one, else 0 and then small negative ones (K singular:
/// rigid-body modes, whose eigenvalues then come out near 0).
std::vector<double> shifts(const EigenRequest& req, double scale) {
  if (req.shift) return {*req.shift, *req.shift - 1e-9 * scale};
  if (std::isfinite(req.lower) && req.lower > 0.0) return {req.lower, req.lower * (1 - 1e-9)};
  return {0.0, -1e-9 * scale, -1e-6 * scale};
}

/// Factorise at the first shift that works (SingularSystem from the last when none does).
double factorize_at_shift(ShiftInvert& op, const EigenRequest& req, double scale) {
  const std::vector<double> tries = shifts(req, scale);
  for (std::size_t i = 0; i < tries.size(); ++i) {
    try {
      op.set_shift(tries[i]);
      return tries[i];
    } catch (const SingularSystem&) {
      if (i + 1 == tries.size()) throw;
    }
  }
  return tries.back();
}

/// M x = 0 everywhere: the model has no mass to vibrate.
bool massless(const CsrMatrix& M) {
  const auto v = M.values();
  return std::all_of(v.begin(), v.end(), [](double x) { return x == 0.0; });
}

/// Sort the pairs ascending and keep those in range (at most `count` when > 0).
void select(std::vector<double>& lam, Eigen::MatrixXd& X, const EigenRequest& req,
            EigenPairs& out) {
  std::vector<std::size_t> order(lam.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return lam[a] < lam[b]; });
  const double tol = 1e-9 * std::max(1.0, std::abs(out.shift));
  const auto n = static_cast<std::size_t>(X.rows());
  out.values.clear();
  out.vectors.clear();
  for (std::size_t k : order) {
    if (lam[k] < req.lower - tol || lam[k] > req.upper) continue;
    if (req.count > 0 && static_cast<int>(out.values.size()) == req.count) break;
    out.values.push_back(lam[k]);
    out.vectors.insert(out.vectors.end(), X.col(static_cast<Eigen::Index>(k)).data(),
                       X.col(static_cast<Eigen::Index>(k)).data() + n);
  }
}

/// Every eigenpair through the operator: T = R S R^T with M = R^T R (its eigenvalues nu, the
/// shift-inverted ones), x = S R^T y / nu. For small systems and requests near their size.
void dense_pairs(ShiftInvert& op, const CsrMatrix& M, const EigenRequest& req, EigenPairs& out) {
  const auto n = static_cast<Eigen::Index>(M.n());
  Eigen::MatrixXd Md = Eigen::MatrixXd::Zero(n, n);
  const SparsityPattern& p = M.pattern();
  for (LocalIndex i = 0; i < M.n(); ++i)
    for (LocalIndex k = p.row_ptr[i]; k < p.row_ptr[i + 1]; ++k) Md(i, p.col[k]) = M.values()[k];
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> me(0.5 * (Md + Md.transpose()));
  const double dmax = me.eigenvalues().cwiseAbs().maxCoeff();
  std::vector<Eigen::Index> keep;
  for (Eigen::Index i = 0; i < n; ++i)
    if (me.eigenvalues()(i) > 1e-12 * dmax) keep.push_back(i);
  const auto r = static_cast<Eigen::Index>(keep.size());
  if (r == 0)
    throw EigenProblemError("no free degree of freedom has mass: there is nothing to vibrate");
  Eigen::MatrixXd Rt(n, r); // R^T: columns sqrt(d_i) q_i
  for (Eigen::Index j = 0; j < r; ++j)
    Rt.col(j) = std::sqrt(me.eigenvalues()(keep[j])) * me.eigenvectors().col(keep[j]);
  Eigen::MatrixXd SRt(n, r);
  op.solve(Rt.data(), SRt.data(), static_cast<int>(r));
  const Eigen::MatrixXd T = Rt.transpose() * SRt;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> te(0.5 * (T + T.transpose()));
  const double numax = te.eigenvalues().cwiseAbs().maxCoeff();
  std::vector<double> lam;
  Eigen::MatrixXd X(n, r);
  for (Eigen::Index j = 0; j < r; ++j) {
    const double nu = te.eigenvalues()(j);
    if (!(std::abs(nu) > 1e-10 * numax)) continue; // held by the rows: no finite eigenvalue
    Eigen::VectorXd x = SRt * te.eigenvectors().col(j) / nu;
    Eigen::VectorXd Mx(n);
    M.multiply({x.data(), static_cast<std::size_t>(n)}, {Mx.data(), static_cast<std::size_t>(n)});
    x /= std::sqrt(std::max(x.dot(Mx), 1e-300));
    X.col(static_cast<Eigen::Index>(lam.size())) = x;
    lam.push_back(out.shift + 1.0 / nu);
  }
  out.finite_modes = static_cast<long>(lam.size());
  X.conservativeResize(n, static_cast<Eigen::Index>(lam.size()));
  if (req.count > out.finite_modes)
    throw EigenProblemError(fmt::format(
        "{} eigenvalues were asked for, but the model has only {}: its free degrees of freedom "
        "with mass, less those its constraints hold; ask for at most {}",
        req.count, out.finite_modes, out.finite_modes));
  select(lam, X, req, out);
}

/// A start vector in the operator's range (no component the rows or massless DOFs hold).
std::vector<double> start_vector(ShiftInvert& op, const MassProduct& B, LocalIndex n) {
  const std::vector<double> w = fixed_start_vector(static_cast<std::size_t>(n));
  std::vector<double> Bw(static_cast<std::size_t>(n)), r(Bw.size());
  B.perform_op(w.data(), Bw.data());
  op.perform_op(Bw.data(), r.data());
  return r;
}

/// Lanczos for `nev` eigenvalues nearest the shift: those of T = (K - sigma M)^-1_C M largest in
/// magnitude (nu = 1 / (lambda - sigma)), in the M inner product, by the backend's Krylov method.
bool lanczos_pairs(ConstrainedSolver& solver, ShiftInvert& op, MassProduct& B, int nev,
                   const EigenRequest& req, std::vector<double>& lam, Eigen::MatrixXd& X,
                   EigenPairs& out) {
  const LocalIndex n = static_cast<LocalIndex>(op.rows());
  KrylovRequest kr;
  kr.n = n;
  kr.solve = [&](const double* x, double* y) { op.perform_op(x, y); };
  kr.apply = [&](const double* x, double* y) { B.perform_op(x, y); };
  kr.inner = kr.apply;
  kr.nev = nev;
  kr.ncv = std::min(n, std::max(2 * nev + 1, nev + 20));
  kr.tolerance = req.tolerance;
  kr.start = start_vector(op, B, n);
  KrylovResult r;
  try {
    const auto method = solver.krylov_eigen_solver();
    out.method = method->name();
    r = method->solve(kr);
  } catch (const std::invalid_argument& e) { // the method's word on nev, ncv or the start vector
    throw EigenProblemError(fmt::format("the Lanczos iteration could not start ({})", e.what()));
  }
  out.restarts += r.restarts;
  if (!r.converged) return false;
  lam.clear();
  for (double nu : r.theta) lam.push_back(out.shift + 1.0 / nu);
  X = Eigen::Map<const Eigen::MatrixXd>(r.vectors.data(), n, static_cast<Eigen::Index>(lam.size()));
  return true;
}

/// How many eigenvalues at most: free equations with mass less exact rows.
long finite_bound(const CsrMatrix& M, const ConstraintBlock& C) {
  long with_mass = 0;
  for (LocalIndex i = 0; i < M.n(); ++i) with_mass += M.diagonal(i) > 0.0;
  long exact = 0;
  for (int r = 0; r < C.n_rows(); ++r) exact += C.row_compliance(r) == 0.0;
  return std::max(0L, with_mass - exact);
}

} // namespace

std::vector<double> fixed_start_vector(std::size_t n) {
  std::vector<double> w(n);
  std::uint64_t s = 0x9E3779B97F4A7C15ull;
  for (double& v : w) {
    s ^= s << 13;
    s ^= s >> 7;
    s ^= s << 17;
    v = 0.5 + static_cast<double>(s % 1000003) / 1000003.0;
  }
  return w;
}

EigenPairs constrained_eigenpairs(ConstrainedSolver& solver, const CsrMatrix& K, const CsrMatrix& M,
                                  const ConstraintBlock& C, const EigenRequest& req,
                                  RunStatistics* stats) {
  EigenPairs out;
  const LocalIndex n = K.n();
  if (n == 0 || massless(M))
    throw EigenProblemError(n == 0 ? "every degree of freedom is held by a boundary condition: "
                                     "there is nothing to vibrate"
                                   : "the model has no mass: give the materials a *DENSITY (or "
                                     "add *MASS elements)");
  const ConstraintBlock rows = homogeneous(C);
  ShiftInvert op(solver, K, M, rows, stats, out);
  out.scale = eigen_scale(K, M);
  out.shift = factorize_at_shift(op, req, out.scale);
  const int dense_limit = 400;
  if (n <= dense_limit || (req.count > 0 && 2 * req.count + 20 > n)) {
    dense_pairs(op, M, req, out);
    return out;
  }
  out.finite_modes = finite_bound(M, rows);
  if (out.finite_modes <= 0)
    throw EigenProblemError("no free degree of freedom with mass is left once the constraints "
                            "hold theirs: there is nothing to vibrate");
  if (req.count > out.finite_modes)
    throw EigenProblemError(fmt::format(
        "{} eigenvalues were asked for, but the model has at most {}: its free degrees of "
        "freedom with mass, less those its constraints hold; ask for fewer",
        req.count, out.finite_modes));
  MassProduct B(M);
  int nev = req.count > 0 ? req.count : 10;
  const bool below = std::isfinite(req.lower) && out.shift < req.lower;
  if (below || (req.count > 0 && std::isfinite(req.lower))) nev += std::max(5, nev / 2);
  for (;;) {
    nev = static_cast<int>(std::min<long>(nev, std::min<long>(out.finite_modes, n - 1)));
    std::vector<double> lam;
    Eigen::MatrixXd X;
    if (!lanczos_pairs(solver, op, B, nev, req, lam, X, out))
      throw EigenProblemError(fmt::format(
          "the Lanczos iteration did not converge to {} eigenvalues; ask for fewer, or give a "
          "shift near the frequencies of interest",
          nev));
    select(lam, X, req, out);
    const double top = *std::max_element(lam.begin(), lam.end());
    const bool enough =
        req.count > 0 ? static_cast<int>(out.values.size()) >= req.count : top > req.upper;
    if (enough || nev >= std::min<long>(out.finite_modes, n - 1)) return out;
    nev *= 2;
  }
}

} // namespace gapfem
