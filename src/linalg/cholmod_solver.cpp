// CHOLMOD supernodal Cholesky behind the LinearSolver interface.
#include "common/error.hpp"
#include "common/memory.hpp"
#include "linalg/linear_solver.hpp"
#include "linalg/low_rank_correction.hpp"
#include "linalg/sparse_forward.hpp"

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
    cholmod_finish(&_c);
  }
  std::string_view name() const override { return "CHOLMOD (supernodal Cholesky)"; }
  bool symmetric() const override { return true; }

  void analyze(const SparsityPattern& p) override {
    if (_L) cholmod_free_factor(&_L, &_c);
    free_work();
    _n = p.n;
    _correction.reset(_n);
    _forward.reset();
    cholmod_sparse A = view(p, nullptr);
    // CHOLMOD's own choice: AMD, then METIS as well when AMD's fill is high (3-D meshes), keeping
    // the better ordering. Forcing METIS costs minutes on graphs of many small disconnected blocks
    // (springs to ground, gaps to fixed nodes), where AMD is exact and instant.
    _c.nmethods = 0;
    _c.postorder = true;
    _L = cholmod_analyze(&A, &_c);
    if (!_L || _c.status < CHOLMOD_OK) throw AnalysisError(failure("ordering/analysis"));
    _inverse_perm.assign(static_cast<std::size_t>(_n), 0);
    const auto* perm = static_cast<const int*>(_L->Perm);
    for (LocalIndex k = 0; k < _n; ++k) _inverse_perm[perm ? perm[k] : k] = k;
  }

  /// A + W W^T or A - W W^T through the Woodbury identity on the untouched supernodal factor
  /// (linalg/low_rank_correction.hpp); a column that undoes an earlier one cancels it. The
  /// correction of a spring w w^T loses about log10(1 + w^T A^-1 w) digits; where `scale` lets
  /// it, an added spring is softened to w^T A^-1 w = kMaxSpringGain.
  bool modify(bool add, const SparseColumns& W, std::span<double> scale,
              std::span<double> gain) override {
    FE_CHECK(_L && _L->xtype != CHOLMOD_PATTERN, "modify before factorize");
    // what it may take is checked first: declining leaves everything as it was
    const int cols = W.n_cols();
    if (_correction.size() + cols > kMaxCorrectionColumns) return false;
    // Y = L^-1 U by sparse forward solves, a block of columns at a time (the block's dense
    // scratch, n x block, is bounded)
    const int block = correction_block();
    if (!scratch_fits(std::min(block, cols))) return false;
    const double sign = add ? 1.0 : -1.0;
    std::vector<LocalIndex> rows;
    std::vector<double> vals;
    std::vector<LowRankCorrection::Column> fresh;
    std::vector<int> index; // column of W of each fresh column
    for (int j = 0; j < cols; ++j) {
      if (!scale.empty()) scale[j] = 1.0;
      if (!gain.empty()) gain[j] = 0.0;
      permuted_column(W, j, rows, vals);
      if (_correction.cancel(rows, vals, sign)) continue;
      index.push_back(j);
      LowRankCorrection::Column c;
      c.u_row = rows;
      c.u_val = vals;
      c.sign = sign;
      fresh.push_back(std::move(c));
    }
    const int k = static_cast<int>(fresh.size());
    if (!_forward) _forward = std::make_unique<SparseForwardSolver>(*_L);
    std::vector<SparseForwardSolver::Column> in, out;
    for (int j0 = 0; j0 < k; j0 += block) {
      const int nb = std::min(block, k - j0);
      in.resize(static_cast<std::size_t>(nb));
      for (int j = 0; j < nb; ++j) {
        in[j].rows = fresh[j0 + j].u_row;
        in[j].vals = fresh[j0 + j].u_val;
      }
      _forward->solve(in, out);
      std::vector<LowRankCorrection::Column> batch;
      for (int j = 0; j < nb; ++j) {
        auto& c = fresh[j0 + j];
        c.y_row = std::move(out[j].rows);
        c.y_val = std::move(out[j].vals);
        double g = 0.0; // u^T (L L^T)^-1 u
        for (double v : c.y_val) g += v * v;
        if (add && !scale.empty() && g > kMaxSpringGain) {
          const double f = std::sqrt(kMaxSpringGain / g);
          for (double& v : c.u_val) v *= f;
          for (double& v : c.y_val) v *= f;
          scale[index[j0 + j]] = f;
          g = kMaxSpringGain;
        }
        if (add && !gain.empty()) gain[index[j0 + j]] = g;
        batch.push_back(std::move(c));
      }
      _correction.add(std::move(batch));
    }
    _correction.factorize(); // throws SingularSystem: the caller factorises afresh
    return true;
  }

  void factorize(const CsrMatrix& M) override {
    FE_CHECK(_L && M.n() == _n, "factorize before analyze");
    _correction.reset(_n);
    _forward.reset();
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
    const auto n = static_cast<std::size_t>(_n);
    if (_correction.empty()) {
      cholmod_dense* X = solve_system(CHOLMOD_A, b.data(), k);
      std::memcpy(x.data(), X->x, sizeof(double) * n * k);
      cholmod_free_dense(&X, &_c);
      return;
    }
    // x = P^T L^-T (I + Y S Y^T)^-1 L^-1 P b
    const auto* perm = static_cast<const int*>(_L->Perm);
    _work.resize(n * k);
    for (int c = 0; c < k; ++c)
      for (std::size_t r = 0; r < n; ++r)
        _work[c * n + r] = b[c * n + (perm ? static_cast<std::size_t>(perm[r]) : r)];
    cholmod_dense* Y = solve_system(CHOLMOD_L, _work.data(), k);
    _correction.apply({static_cast<double*>(Y->x), n * k}, k);
    cholmod_dense* Z = solve_system(CHOLMOD_Lt, static_cast<const double*>(Y->x), k);
    const auto* z = static_cast<const double*>(Z->x);
    for (int c = 0; c < k; ++c)
      for (std::size_t r = 0; r < n; ++r)
        x[c * n + (perm ? static_cast<std::size_t>(perm[r]) : r)] = z[c * n + r];
    cholmod_free_dense(&Y, &_c);
    cholmod_free_dense(&Z, &_c);
  }

  bool has_split_solves() const override { return _L && _L->is_super && _correction.empty(); }

  void forward(std::span<const double> b, std::span<double> t) override {
    FE_CHECK(has_split_solves(), "split solves need an unmodified supernodal factor");
    const auto n = static_cast<std::size_t>(_n);
    const auto* perm = static_cast<const int*>(_L->Perm);
    _work.resize(n);
    for (std::size_t r = 0; r < n; ++r) _work[r] = b[perm ? static_cast<std::size_t>(perm[r]) : r];
    cholmod_dense* Y = solve_system(CHOLMOD_L, _work.data(), 1);
    std::memcpy(t.data(), Y->x, sizeof(double) * n);
    cholmod_free_dense(&Y, &_c);
  }

  void backward(std::span<const double> t, std::span<double> x) override {
    FE_CHECK(has_split_solves(), "split solves need an unmodified supernodal factor");
    const auto n = static_cast<std::size_t>(_n);
    const auto* perm = static_cast<const int*>(_L->Perm);
    cholmod_dense* Z = solve_system(CHOLMOD_Lt, t.data(), 1);
    const auto* z = static_cast<const double*>(Z->x);
    for (std::size_t r = 0; r < n; ++r) x[perm ? static_cast<std::size_t>(perm[r]) : r] = z[r];
    cholmod_free_dense(&Z, &_c);
  }

  bool forward_sparse(const SparseColumns& W, SparseColumns& Z) override {
    FE_CHECK(has_split_solves(), "split solves need an unmodified supernodal factor");
    const int cols = W.n_cols();
    const int block = correction_block();
    if (!scratch_fits(std::min(block, cols))) return false;
    if (!_forward) _forward = std::make_unique<SparseForwardSolver>(*_L);
    Z = SparseColumns{};
    std::vector<SparseForwardSolver::Column> in, out;
    for (int j0 = 0; j0 < cols; j0 += block) {
      const int nb = std::min(block, cols - j0);
      in.resize(static_cast<std::size_t>(nb));
      for (int j = 0; j < nb; ++j) permuted_column(W, j0 + j, in[j].rows, in[j].vals);
      _forward->solve(in, out);
      for (int j = 0; j < nb; ++j) {
        Z.row.insert(Z.row.end(), out[j].rows.begin(), out[j].rows.end());
        Z.val.insert(Z.val.end(), out[j].vals.begin(), out[j].vals.end());
        Z.ptr.push_back(static_cast<LocalIndex>(Z.row.size()));
      }
    }
    return true;
  }

  /// A sentence for a failed CHOLMOD call; running out of memory names the factor's size.
  std::string failure(std::string_view what) const {
    if (_c.status == CHOLMOD_OUT_OF_MEMORY || _c.status == CHOLMOD_TOO_LARGE)
      return fmt::format("CHOLMOD {} ran out of memory on {} equations (the factor needs about "
                         "{:.1f} GiB); use a coarser mesh or run on a machine with more memory",
                         what, _n, _c.lnz * sizeof(double) / 1073741824.0);
    if (_c.status == CHOLMOD_INVALID && what == "ordering/analysis") // CHOLMOD's input is ours
      return fmt::format("CHOLMOD's ordering (METIS) failed on {} equations, which happens when "
                         "memory runs out; use a coarser mesh, raise the memory limit (ulimit -v) "
                         "or run on a machine with more memory",
                         _n);
    return fmt::format("CHOLMOD {} failed (status {}) on {} equations", what, _c.status, _n);
  }

  /// After analyze() CHOLMOD's prediction (supernodal: the value array it will fill; simplicial:
  /// the predicted nnz(L)), after factorize() the factor's own size.
  std::size_t factor_bytes() const override {
    if (!_L) return 0;
    const double entries = _L->is_super ? static_cast<double>(_L->xsize)
                                        : std::max(static_cast<double>(_L->nzmax), _c.lnz);
    return static_cast<std::size_t>(entries) * sizeof(double) + _correction.bytes();
  }

 private:
  /// Larger corrections cost more per solve than a factorisation saves: refactorise instead.
  static constexpr int kMaxCorrectionColumns = 3000;
  /// The stiffest an added spring may be relative to the matrix along it (w^T A^-1 w): the
  /// augmentation's purpose (a multiplier spectrum clustered within 1%) needs no more.
  static constexpr double kMaxSpringGain = 100.0;
  /// Right-hand sides per forward solve when forming Y = L^-1 U, and the most doubles its
  /// scratch may take (64 MB).
  static constexpr int kCorrectionBlock = 64;
  static constexpr std::size_t kScratchDoubles = std::size_t{8} << 20;

  /// Columns per sparse forward solve (their dense scratch, n x block, is bounded).
  int correction_block() const {
    return std::clamp(static_cast<int>(kScratchDoubles / std::max<LocalIndex>(_n, 1)), 1,
                      kCorrectionBlock);
  }
  /// The scratch of a forward solve of `cols` columns fits in the memory left.
  bool scratch_fits(int cols) const {
    const auto available = available_memory_bytes();
    return cols <= 0 || !available ||
           2.0 * sizeof(double) * static_cast<double>(_n) * cols <= static_cast<double>(*available);
  }

  /// Column j of W in the factor's ordering (CHOLMOD factors P A P^T), rows ascending.
  void permuted_column(const SparseColumns& W, int j, std::vector<LocalIndex>& rows,
                       std::vector<double>& vals) const {
    std::vector<std::pair<LocalIndex, double>> col;
    for (LocalIndex q = W.ptr[j]; q < W.ptr[j + 1]; ++q)
      col.emplace_back(_inverse_perm[W.row[q]], W.val[q]);
    std::sort(col.begin(), col.end());
    rows.clear();
    vals.clear();
    for (const auto& [r, v] : col) {
      rows.push_back(r);
      vals.push_back(v);
    }
  }

  /// CHOLMOD's solve of system `sys` for k right-hand sides (n x k, column-major); the caller
  /// frees the result.
  cholmod_dense* solve_system(int sys, const double* b, int k) {
    cholmod_dense B{};
    B.nrow = static_cast<std::size_t>(_n);
    B.ncol = static_cast<std::size_t>(k);
    B.nzmax = B.nrow * B.ncol;
    B.d = B.nrow;
    B.x = const_cast<double*>(b);
    B.xtype = CHOLMOD_REAL;
    B.dtype = CHOLMOD_DOUBLE;
    cholmod_dense* X = nullptr;
    if (!cholmod_solve2(sys, _L, &B, nullptr, &X, nullptr, &_Y, &_E, &_c) || !X)
      throw AnalysisError(failure("solve"));
    return X;
  }

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
  std::vector<int> _inverse_perm; ///< equation -> position in the factor's ordering
  cholmod_dense* _Y = nullptr;
  cholmod_dense* _E = nullptr;
  LocalIndex _n = 0;
  LowRankCorrection _correction; ///< rank-one changes since the factorisation (modify())
  std::unique_ptr<SparseForwardSolver> _forward; ///< for _L's structure (made on first use)
  std::vector<double> _work;
};

} // namespace

std::unique_ptr<LinearSolver> make_cholmod_solver() {
  return std::make_unique<CholmodSolver>();
}

void LinearSolver::forward(std::span<const double>, std::span<double>) {
  FE_CHECK(false, "this solver has no split solves");
}
void LinearSolver::backward(std::span<const double>, std::span<double>) {
  FE_CHECK(false, "this solver has no split solves");
}
bool LinearSolver::forward_sparse(const SparseColumns&, SparseColumns&) {
  return false;
}

void LinearSolver::solve_many(std::span<const double> b, std::span<double> x, int k) {
  const auto n = b.size() / static_cast<std::size_t>(k);
  for (int j = 0; j < k; ++j) solve(b.subspan(j * n, n), x.subspan(j * n, n));
}

} // namespace gapfem
