// UMFPACK LU behind the LinearSolver interface (unsymmetric systems: friction slip, coupled
// temperature-displacement, follower loads). The 64-bit interface (umfpack_dl_*) is used so the
// factor may exceed 2^31 units (16 GiB with int indices is the limit of umfpack_di_*); METIS
// orders the larger systems, as it does for CHOLMOD.
#include "common/error.hpp"
#include "linalg/linear_solver.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <umfpack.h>

namespace gapfem {
namespace {

class UmfpackSolver final : public LinearSolver {
 public:
  UmfpackSolver() {
    umfpack_dl_defaults(_control);
    _control[UMFPACK_IRSTEP] = 0; // no iterative refinement: solve() needs only the factor
  }
  ~UmfpackSolver() override { release(); }
  std::string_view name() const override { return "UMFPACK (LU)"; }
  bool symmetric() const override { return false; }

  void analyze(const SparsityPattern& p) override {
    release();
    _pattern = &p;
    _n = p.n;
    _ptr.assign(p.row_ptr.begin(), p.row_ptr.end());
    _idx.assign(p.col.begin(), p.col.end());
    // AMD/COLAMD is UMFPACK's default; nested dissection fills far less on 3-D meshes.
    _control[UMFPACK_ORDERING] = _n >= 10000 ? UMFPACK_ORDERING_METIS : UMFPACK_ORDERING_AMD;
  }

  void factorize(const CsrMatrix& M) override {
    FE_CHECK(_pattern && M.n() == _n, "factorize before analyze");
    FE_CHECK(&M.pattern() == _pattern || M.pattern().col.size() == _idx.size(),
             "factorize with a pattern other than the analysed one");
    // Our CSR arrays are the CSC arrays of A^T; we factorise A^T and solve with UMFPACK_At.
    if (!_symbolic) {
      const auto st = umfpack_dl_symbolic(_n, _n, _ptr.data(), _idx.data(), M.values().data(),
                                          &_symbolic, _control, _info);
      if (st != UMFPACK_OK) throw AnalysisError(describe("symbolic analysis", st));
    }
    if (_numeric) umfpack_dl_free_numeric(&_numeric);
    const auto st = umfpack_dl_numeric(_ptr.data(), _idx.data(), M.values().data(), _symbolic,
                                       &_numeric, _control, _info);
    if (st == UMFPACK_WARNING_singular_matrix || st == UMFPACK_OK) {
      auto bad = small_pivots(M);
      if (st == UMFPACK_WARNING_singular_matrix || !bad.empty()) {
        if (bad.empty()) bad.push_back(0);
        throw SingularSystem("singular matrix", std::move(bad));
      }
      _values = &M;
      return;
    }
    throw AnalysisError(describe("LU factorisation", st));
  }

  void solve(std::span<const double> b, std::span<double> x) override {
    FE_CHECK(_numeric && _values, "solve before factorize");
    const auto st = umfpack_dl_solve(UMFPACK_At, _ptr.data(), _idx.data(), _values->values().data(),
                                     x.data(), b.data(), _numeric, _control, _info);
    if (st != UMFPACK_OK) throw AnalysisError(describe("solve", st));
  }

  std::size_t factor_bytes() const override {
    return static_cast<std::size_t>(_info[UMFPACK_NUMERIC_SIZE] * _info[UMFPACK_SIZE_OF_UNIT]);
  }

 private:
  using Long = SuiteSparse_long;

  /// A sentence for a failed UMFPACK call; running out of memory names the size reached.
  std::string describe(std::string_view what, Long status) const {
    if (status == UMFPACK_ERROR_out_of_memory)
      return fmt::format("UMFPACK {} ran out of memory on {} equations (the LU factor needs about "
                         "{:.1f} GiB); use a coarser mesh or run on a machine with more memory",
                         what, _n,
                         _info[UMFPACK_NUMERIC_SIZE_ESTIMATE] * _info[UMFPACK_SIZE_OF_UNIT] /
                             1073741824.0);
    return fmt::format("UMFPACK {} failed (status {}) on {} equations", what, status, _n);
  }

  /// Equations whose pivot is negligible against the largest entry of their column.
  std::vector<LocalIndex> small_pivots(const CsrMatrix& M) {
    std::vector<double> udiag(static_cast<std::size_t>(_n));
    std::vector<Long> P(static_cast<std::size_t>(_n)), Q(static_cast<std::size_t>(_n));
    std::vector<double> rs(static_cast<std::size_t>(_n));
    Long do_recip = 0;
    umfpack_dl_get_numeric(nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, P.data(), Q.data(),
                           udiag.data(), &do_recip, rs.data(), _numeric);
    // scale of each equation: max |entry| in its row of A (= column of A^T)
    const auto& p = M.pattern();
    std::vector<double> scale(static_cast<std::size_t>(_n), 0.0);
    for (LocalIndex r = 0; r < _n; ++r)
      for (LocalIndex k = p.row_ptr[r]; k < p.row_ptr[r + 1]; ++k)
        scale[r] = std::max(scale[r], std::abs(M.values()[k]));
    std::vector<LocalIndex> bad;
    for (LocalIndex k = 0; k < _n; ++k) {
      // U is of the row-scaled matrix R A^T; undo the scaling of the pivot row P[k].
      const double s = do_recip ? 1.0 / rs[P[k]] : rs[P[k]];
      const double u = std::abs(udiag[k]) * s;
      const auto eq = static_cast<LocalIndex>(Q[k]);
      if (!(u > 1e-12 * scale[eq])) bad.push_back(eq);
    }
    return bad;
  }

  void release() {
    if (_numeric) umfpack_dl_free_numeric(&_numeric);
    if (_symbolic) umfpack_dl_free_symbolic(&_symbolic);
    _values = nullptr;
  }

  double _control[UMFPACK_CONTROL];
  double _info[UMFPACK_INFO];
  void* _symbolic = nullptr;
  void* _numeric = nullptr;
  const SparsityPattern* _pattern = nullptr;
  const CsrMatrix* _values = nullptr;
  std::vector<Long> _ptr, _idx; // 64-bit copies of the pattern's CSR arrays
  Long _n = 0;
};

} // namespace

std::unique_ptr<LinearSolver> make_umfpack_solver() {
  return std::make_unique<UmfpackSolver>();
}

} // namespace gapfem
