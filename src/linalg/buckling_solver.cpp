// Eigenvalue buckling K0 x = lambda G x under the perturbation's rows (eigen_solver.hpp,
// docs/theory/buckling.md): Lanczos on mu = 1 / lambda, whose largest magnitudes are the
// buckling loads nearest zero, in the K0 inner product.
#include "linalg/eigen_solver.hpp"
#include "linalg/krylov_eigen.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <numeric>

namespace gapfem {
namespace {

/// K0 under the rows: its constrained inverse (the factor) and its product, compliant rows' C^T C /
/// E included (the Lanczos run's inner product).
class StiffnessOp {
 public:
  using Scalar = double;
  StiffnessOp(ConstrainedSolver& solver, const CsrMatrix& K, const ConstraintBlock& C,
              RunStatistics* stats, EigenPairs& out, std::unique_ptr<ConstrainedFactor> factor)
      : _K(K), _C(C), _stats(stats), _out(out), _factor(std::move(factor)) {
    ++out.factorizations; // the caller's, or one made here
    if (!_factor) _factor = solver.factorize(K, C, true, stats);
  }
  Eigen::Index rows() const { return _K.n(); }
  Eigen::Index cols() const { return _K.n(); }
  /// y = K0^-1_C x for k columns.
  void solve(const double* x, double* y, int k = 1) const {
    ScopedTimer timer(_stats, TimeCategory::Solve);
    if (_stats) _stats->linear_solves += k;
    const std::size_t n = static_cast<std::size_t>(_K.n()), m = _C.g.size();
    _g.assign(m * static_cast<std::size_t>(k), 0.0);
    _l.assign(_g.size(), 0.0);
    _factor->solve({x, n * k}, _g, {y, n * k}, _l, k);
    _out.operations += k;
  }
  /// y = (K0 + C_c^T E^-1 C_c) x, C_c the compliant rows. A Lanczos run's K0-inner products
  /// multiply the same vector again and again (its norm, then its products with each basis vector):
  /// the last product is kept and handed back while the vector is the same one.
  void perform_op(const double* x, double* y) const {
    const std::size_t n = static_cast<std::size_t>(_K.n());
    if (_x.size() == n && std::equal(x, x + n, _x.begin())) {
      std::copy(_y.begin(), _y.end(), y);
      return;
    }
    _K.multiply({x, n}, {y, n});
    for (int r = 0; r < _C.n_rows(); ++r) {
      const double e = _C.row_compliance(r);
      if (e == 0.0) continue;
      double cx = 0.0;
      for (LocalIndex k = _C.row_ptr[r]; k < _C.row_ptr[r + 1]; ++k) cx += _C.val[k] * x[_C.col[k]];
      for (LocalIndex k = _C.row_ptr[r]; k < _C.row_ptr[r + 1]; ++k)
        y[_C.col[k]] += _C.val[k] * cx / e;
    }
    _x.assign(x, x + n);
    _y.assign(y, y + n);
  }

 private:
  const CsrMatrix& _K;
  const ConstraintBlock& _C;
  RunStatistics* _stats;
  EigenPairs& _out;
  std::unique_ptr<ConstrainedFactor> _factor;
  mutable std::vector<double> _g, _l;
  mutable std::vector<double> _x, _y; ///< the last vector and its product
};

/// G x.
struct GeometricOp {
  using Scalar = double;
  const CsrMatrix& G;
  Eigen::Index rows() const { return G.n(); }
  Eigen::Index cols() const { return G.n(); }
  void perform_op(const double* x, double* y) const {
    const std::size_t n = static_cast<std::size_t>(G.n());
    G.multiply({x, n}, {y, n});
  }
};

/// Keep the pairs in range, by ascending magnitude, at most `count` when > 0.
void select_buckling(const std::vector<double>& lam, const Eigen::MatrixXd& X,
                     const EigenRequest& req, EigenPairs& out) {
  std::vector<std::size_t> order(lam.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) {
    return std::abs(lam[a]) < std::abs(lam[b]) ||
           (std::abs(lam[a]) == std::abs(lam[b]) && lam[a] > lam[b]);
  });
  const auto n = static_cast<std::size_t>(X.rows());
  out.values.clear();
  out.vectors.clear();
  for (std::size_t k : order) {
    if (lam[k] < req.lower || lam[k] > req.upper) continue;
    if (req.count > 0 && static_cast<int>(out.values.size()) == req.count) break;
    out.values.push_back(lam[k]);
    const auto c = static_cast<Eigen::Index>(k);
    out.vectors.insert(out.vectors.end(), X.col(c).data(), X.col(c).data() + n);
  }
}

/// Every pair through the operator: S = K0^-1_C = R R^T, T = R^T G R, mu its eigenvalues.
void dense_buckling(const StiffnessOp& op, const CsrMatrix& G, const EigenRequest& req,
                    EigenPairs& out) {
  const auto n = static_cast<Eigen::Index>(G.n());
  Eigen::MatrixXd S(n, n);
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n, n);
  op.solve(I.data(), S.data(), static_cast<int>(n));
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> se(0.5 * (S + S.transpose()));
  const double smax = se.eigenvalues().cwiseAbs().maxCoeff();
  if (se.eigenvalues().minCoeff() < -1e-10 * smax)
    throw EigenProblemError("the stiffness of the base state is not positive definite: the base "
                            "state is past a stability limit already, and buckling loads about it "
                            "have no meaning");
  std::vector<Eigen::Index> keep;
  for (Eigen::Index i = 0; i < n; ++i)
    if (se.eigenvalues()(i) > 1e-12 * smax) keep.push_back(i);
  const auto r = static_cast<Eigen::Index>(keep.size());
  Eigen::MatrixXd R(n, r);
  for (Eigen::Index j = 0; j < r; ++j)
    R.col(j) = std::sqrt(se.eigenvalues()(keep[j])) * se.eigenvectors().col(keep[j]);
  Eigen::MatrixXd GR(n, r);
  for (Eigen::Index j = 0; j < r; ++j) {
    GeometricOp g{G};
    g.perform_op(R.col(j).data(), GR.col(j).data());
  }
  const Eigen::MatrixXd T = R.transpose() * GR;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> te(0.5 * (T + T.transpose()));
  const double mumax = te.eigenvalues().cwiseAbs().maxCoeff();
  std::vector<double> lam;
  Eigen::MatrixXd X(n, r);
  for (Eigen::Index j = 0; j < r; ++j) {
    const double mu = te.eigenvalues()(j);
    if (!(std::abs(mu) > 1e-10 * mumax)) continue; // no load stiffness there: no buckling
    X.col(static_cast<Eigen::Index>(lam.size())) = R * te.eigenvectors().col(j);
    lam.push_back(1.0 / mu);
  }
  X.conservativeResize(n, static_cast<Eigen::Index>(lam.size()));
  out.finite_modes = static_cast<long>(lam.size());
  select_buckling(lam, X, req, out);
}

/// A start vector in the constrained space: K0^-1_C w.
std::vector<double> buckling_start(const StiffnessOp& op, LocalIndex n) {
  const std::vector<double> w = fixed_start_vector(static_cast<std::size_t>(n));
  std::vector<double> r(w.size());
  op.solve(w.data(), r.data());
  return r;
}

/// Lanczos for `nev` values of mu = 1 / lambda, the eigenvalues of T = K0^-1_C G in the K0 inner
/// product (largest magnitude, or largest when only positive loads count), by the backend's
/// Krylov method.
bool lanczos_buckling(ConstrainedSolver& solver, StiffnessOp& op, const CsrMatrix& G, int nev,
                      const EigenRequest& req, std::vector<double>& lam, Eigen::MatrixXd& X,
                      EigenPairs& out) {
  const LocalIndex n = static_cast<LocalIndex>(op.rows());
  const std::size_t size = static_cast<std::size_t>(n);
  KrylovRequest kr;
  kr.n = n;
  kr.solve = [&](const double* x, double* y) { op.solve(x, y); };
  kr.apply = [&](const double* x, double* y) { G.multiply({x, size}, {y, size}); };
  kr.inner = [&](const double* x, double* y) { op.perform_op(x, y); };
  kr.nev = nev;
  kr.ncv = std::min(n, std::max(2 * nev + 1, nev + 20));
  kr.tolerance = req.tolerance;
  kr.largest_algebraic = req.lower >= 0.0;
  kr.start = buckling_start(op, n);
  KrylovResult r;
  try {
    const auto method = solver.krylov_eigen_solver();
    out.method = method->name();
    r = method->solve(kr);
  } catch (const std::invalid_argument& e) {
    throw EigenProblemError(fmt::format("the Lanczos iteration could not start ({})", e.what()));
  }
  out.restarts += r.restarts;
  if (!r.converged) return false;
  double mumax = 0.0;
  for (double mu : r.theta) mumax = std::max(mumax, std::abs(mu));
  lam.clear();
  for (double mu : r.theta)
    lam.push_back(std::abs(mu) > 1e-12 * mumax ? 1.0 / mu
                                               : std::numeric_limits<double>::infinity());
  X = Eigen::Map<const Eigen::MatrixXd>(r.vectors.data(), n, static_cast<Eigen::Index>(lam.size()));
  return true;
}

bool no_load_stiffness(const CsrMatrix& G) {
  const auto v = G.values();
  double big = 0.0;
  for (double x : v) big = std::max(big, std::abs(x));
  return !(big > 0.0);
}

} // namespace

EigenPairs constrained_buckling_pairs(ConstrainedSolver& solver, const CsrMatrix& K0,
                                      const CsrMatrix& G, const ConstraintBlock& C,
                                      const EigenRequest& req, RunStatistics* stats,
                                      std::unique_ptr<ConstrainedFactor> factor) {
  EigenPairs out;
  const LocalIndex n = K0.n();
  if (n == 0)
    throw EigenProblemError("every degree of freedom is held by a boundary condition: nothing "
                            "can buckle");
  if (no_load_stiffness(G))
    throw EigenProblemError("the perturbation load makes no stresses that change the stiffness "
                            "(no initial stress or load stiffness): there is no buckling load; "
                            "check the loads of the *BUCKLE step");
  ConstraintBlock rows = C;
  std::fill(rows.g.begin(), rows.g.end(), 0.0);
  StiffnessOp op(solver, K0, rows, stats, out, std::move(factor));
  if (n <= 400 || (req.count > 0 && 2 * req.count + 20 > n)) {
    dense_buckling(op, G, req, out);
    if (req.count > 0 && static_cast<int>(out.values.size()) < req.count && out.values.empty())
      throw EigenProblemError("no buckling eigenvalue lies in the range asked for");
    return out;
  }
  int nev = req.count > 0 ? req.count : 10;
  nev += std::max(3, nev / 2); // negative ones may take places
  for (;;) {
    nev = static_cast<int>(std::min<long>(nev, n - 1));
    std::vector<double> lam;
    Eigen::MatrixXd X;
    if (!lanczos_buckling(solver, op, G, nev, req, lam, X, out))
      throw EigenProblemError(fmt::format(
          "the Lanczos iteration did not converge to {} buckling eigenvalues; ask for fewer", nev));
    select_buckling(lam, X, req, out);
    double top = 0.0; // the Ritz values reach this far from zero
    for (double l : lam) top = std::max(top, std::abs(l));
    double bound = 0.0; // ... and must reach past the range's finite ends
    for (double e : {req.lower, req.upper})
      if (std::isfinite(e)) bound = std::max(bound, std::abs(e));
    const bool enough =
        req.count > 0 ? static_cast<int>(out.values.size()) >= req.count : top > bound;
    if (enough || nev >= n - 1) return out;
    nev *= 2;
  }
}

} // namespace gapfem
