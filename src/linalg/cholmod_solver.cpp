// CHOLMOD supernodal Cholesky behind the LinearSolver interface.
#include "common/error.hpp"
#include "linalg/linear_solver.hpp"

#include <algorithm>
#include <cholmod.h>
#include <cmath>
#include <cstring>
#include <fmt/format.h>

namespace gapfem {
namespace {

/// Pivots whose square falls below this fraction of the original diagonal mark a singular matrix.
constexpr double kPivotRatio = 1e-12;

class CholmodSolver final : public LinearSolver {
 public:
  CholmodSolver() {
    cholmod_start(&_c);
    _c.supernodal = CHOLMOD_SUPERNODAL;
    _c.final_ll = true;
    _c.quick_return_if_not_posdef = true;
    _c.print = 0;
    _c.error_handler = nullptr;
  }
  ~CholmodSolver() override {
    free_work();
    if (_L) cholmod_free_factor(&_L, &_c);
    if (_Lsym) cholmod_free_factor(&_Lsym, &_c);
    cholmod_finish(&_c);
  }
  std::string_view name() const override { return "CHOLMOD (supernodal Cholesky)"; }
  bool symmetric() const override { return true; }

  void analyze(const SparsityPattern& p) override {
    if (_L) cholmod_free_factor(&_L, &_c);
    if (_Lsym) cholmod_free_factor(&_Lsym, &_c);
    free_work();
    _n = p.n;
    cholmod_sparse A = view(p, nullptr);
    // CHOLMOD's own choice: AMD, then METIS as well when AMD's fill is high (3-D meshes), keeping
    // the better ordering. Forcing METIS costs minutes on graphs of many small disconnected blocks
    // (springs to ground, gaps to fixed nodes), where AMD is exact and instant.
    _c.nmethods = 0;
    _c.postorder = true;
    _L = cholmod_analyze(&A, &_c);
    if (!_L || _c.status < CHOLMOD_OK) throw AnalysisError(failure("ordering/analysis"));
    // the symbolic supernodal factor, to start from again after modify() made L simplicial
    _Lsym = cholmod_copy_factor(_L, &_c);
    _inverse_perm.assign(static_cast<std::size_t>(_n), 0);
    const auto* perm = static_cast<const int*>(_L->Perm);
    for (LocalIndex k = 0; k < _n; ++k) _inverse_perm[perm ? perm[k] : k] = k;
  }

  bool modify(bool add, const SparseColumns& W) override {
    FE_CHECK(_L && _L->xtype != CHOLMOD_PATTERN, "modify before factorize");
    if (W.n_cols() == 0) return true;
    // C = P W (CHOLMOD's factor is of P A P^T), rows sorted in each column
    std::vector<int> p(W.ptr.begin(), W.ptr.end()), rows;
    std::vector<double> vals;
    std::vector<std::pair<int, double>> col;
    for (int j = 0; j < W.n_cols(); ++j) {
      col.clear();
      for (LocalIndex k = W.ptr[j]; k < W.ptr[j + 1]; ++k)
        col.emplace_back(_inverse_perm[W.row[k]], W.val[k]);
      std::sort(col.begin(), col.end());
      for (const auto& [r, v] : col) {
        rows.push_back(r);
        vals.push_back(v);
      }
    }
    cholmod_sparse C{};
    C.nrow = static_cast<std::size_t>(_n);
    C.ncol = static_cast<std::size_t>(W.n_cols());
    C.nzmax = rows.size();
    C.p = p.data();
    C.i = rows.data();
    C.x = vals.data();
    C.stype = 0;
    C.itype = CHOLMOD_INT;
    C.xtype = CHOLMOD_REAL;
    C.dtype = CHOLMOD_DOUBLE;
    C.sorted = true;
    C.packed = true;
    // (a supernodal factor is converted to simplicial LDL^T, which the next factorize() undoes)
    const int ok = cholmod_updown(add ? 1 : 0, &C, _L, &_c);
    if (_c.status < CHOLMOD_OK) throw AnalysisError(failure("factor update"));
    if (!ok || _c.status == CHOLMOD_NOT_POSDEF || _L->minor < static_cast<std::size_t>(_n))
      throw SingularSystem("the modified matrix is not positive definite", {});
    if (!add) check_downdate();
    return true;
  }

  /// A downdate that removes the only support of a mode leaves a pivot at round-off (CHOLMOD
  /// does not notice a zero that is not negative): the simplicial LDL^T diagonal is checked.
  void check_downdate() const {
    const auto* Lp = static_cast<const int*>(_L->p);
    const auto* Lx = static_cast<const double*>(_L->x);
    double dmax = 0.0;
    for (LocalIndex j = 0; j < _n; ++j) dmax = std::max(dmax, std::abs(Lx[Lp[j]]));
    for (LocalIndex j = 0; j < _n; ++j)
      if (!(Lx[Lp[j]] > kPivotRatio * dmax))
        throw SingularSystem("the modified matrix is not positive definite", {});
  }

  void factorize(const CsrMatrix& M) override {
    FE_CHECK(_L && M.n() == _n, "factorize before analyze");
    if (!_L->is_super) { // modified since: back to the supernodal analysis
      cholmod_free_factor(&_L, &_c);
      _L = cholmod_copy_factor(_Lsym, &_c);
    }
    cholmod_sparse A = view(M.pattern(), M.values().data());
    const int ok = cholmod_factorize(&A, _L, &_c);
    if (_c.status < CHOLMOD_OK) throw AnalysisError(failure("Cholesky factorisation"));
    if (!ok || _c.status == CHOLMOD_NOT_POSDEF) {
      const auto* perm = static_cast<const int*>(_L->Perm);
      const auto k = static_cast<LocalIndex>(_L->minor);
      std::vector<LocalIndex> eqs;
      if (k < _n) eqs.push_back(perm ? perm[k] : k);
      // decided before eqs is moved (argument evaluation order is unspecified)
      const bool indefinite = k < _n && M.diagonal(eqs[0]) > 0;
      throw SingularSystem("the matrix is not positive definite", std::move(eqs), indefinite);
    }
    check_pivots(M);
  }

  void solve(std::span<const double> b, std::span<double> x) override { solve_many(b, x, 1); }

  void solve_many(std::span<const double> b, std::span<double> x, int k) override {
    FE_CHECK(_L, "solve before factorize");
    cholmod_dense B{};
    B.nrow = static_cast<std::size_t>(_n);
    B.ncol = static_cast<std::size_t>(k);
    B.nzmax = B.nrow * B.ncol;
    B.d = B.nrow;
    B.x = const_cast<double*>(b.data());
    B.xtype = CHOLMOD_REAL;
    B.dtype = CHOLMOD_DOUBLE;
    cholmod_dense* X = nullptr;
    if (!cholmod_solve2(CHOLMOD_A, _L, &B, nullptr, &X, nullptr, &_Y, &_E, &_c) || !X)
      throw AnalysisError(failure("solve"));
    std::memcpy(x.data(), X->x, sizeof(double) * B.nzmax);
    cholmod_free_dense(&X, &_c);
  }

  /// A sentence for a failed CHOLMOD call; running out of memory names the factor's size.
  std::string failure(std::string_view what) const {
    if (_c.status == CHOLMOD_OUT_OF_MEMORY || _c.status == CHOLMOD_TOO_LARGE)
      return fmt::format("CHOLMOD {} ran out of memory on {} equations (the factor needs about "
                         "{:.1f} GiB); use a coarser mesh or run on a machine with more memory",
                         what, _n, _c.lnz * sizeof(double) / 1073741824.0);
    return fmt::format("CHOLMOD {} failed (status {}) on {} equations", what, _c.status, _n);
  }

  /// After analyze() CHOLMOD's prediction (supernodal: the value array it will fill; simplicial:
  /// the predicted nnz(L)), after factorize() the factor's own size.
  std::size_t factor_bytes() const override {
    if (!_L) return 0;
    const double entries = _L->is_super ? static_cast<double>(_L->xsize)
                                        : std::max(static_cast<double>(_L->nzmax), _c.lnz);
    return static_cast<std::size_t>(entries) * sizeof(double);
  }

 private:
  cholmod_sparse view(const SparsityPattern& p, const double* values) {
    cholmod_sparse A{};
    A.nrow = A.ncol = static_cast<std::size_t>(p.n);
    A.nzmax = p.nnz();
    A.p = const_cast<LocalIndex*>(p.row_ptr.data());
    A.i = const_cast<LocalIndex*>(p.col.data());
    A.x = const_cast<double*>(values);
    A.stype = 1; // symmetric, upper part of the column view (= lower part of our rows) used
    A.itype = CHOLMOD_INT;
    A.xtype = values ? CHOLMOD_REAL : CHOLMOD_PATTERN;
    A.dtype = CHOLMOD_DOUBLE;
    A.sorted = true;
    A.packed = true;
    return A;
  }

  /// Near-zero pivots (singular positive semi-definite matrix) do not stop CHOLMOD; find them.
  void check_pivots(const CsrMatrix& M) {
    if (!_L->is_super) return;
    const auto* super = static_cast<const int*>(_L->super);
    const auto* pi = static_cast<const int*>(_L->pi);
    const auto* px = static_cast<const int*>(_L->px);
    const auto* Lx = static_cast<const double*>(_L->x);
    const auto* perm = static_cast<const int*>(_L->Perm);
    std::vector<LocalIndex> bad;
    for (std::size_t s = 0; s < _L->nsuper; ++s) {
      const int k1 = super[s], k2 = super[s + 1];
      const int nrows = pi[s + 1] - pi[s];
      for (int j = k1; j < k2; ++j) {
        const double l = Lx[px[s] + (j - k1) + static_cast<std::size_t>(j - k1) * nrows];
        const LocalIndex eq = perm ? perm[j] : j;
        const double d = M.diagonal(eq);
        if (!(l * l > kPivotRatio * d) || d <= 0) bad.push_back(eq);
      }
    }
    if (!bad.empty()) throw SingularSystem("zero pivot", std::move(bad));
  }

  void free_work() {
    if (_Y) cholmod_free_dense(&_Y, &_c);
    if (_E) cholmod_free_dense(&_E, &_c);
  }

  cholmod_common _c{};
  cholmod_factor* _L = nullptr;
  cholmod_factor* _Lsym = nullptr; ///< the symbolic analysis (supernodal)
  std::vector<int> _inverse_perm;  ///< equation -> position in the factor's ordering
  cholmod_dense* _Y = nullptr;
  cholmod_dense* _E = nullptr;
  LocalIndex _n = 0;
};

} // namespace

std::unique_ptr<LinearSolver> make_cholmod_solver() {
  return std::make_unique<CholmodSolver>();
}

void LinearSolver::solve_many(std::span<const double> b, std::span<double> x, int k) {
  const auto n = b.size() / static_cast<std::size_t>(k);
  for (int j = 0; j < k; ++j) solve(b.subspan(j * n, n), x.subspan(j * n, n));
}

} // namespace gapfem
