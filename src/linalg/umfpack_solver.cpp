// UMFPACK LU behind the LinearSolver interface (unsymmetric systems: friction slip, coupled
// temperature-displacement, follower loads).
#include "common/error.hpp"
#include "linalg/linear_solver.hpp"

#include <fmt/format.h>
#include <umfpack.h>

#include <algorithm>
#include <cmath>

namespace gapfem {
namespace {

class UmfpackSolver final : public LinearSolver {
public:
  UmfpackSolver() {
    umfpack_di_defaults(_control);
    _control[UMFPACK_IRSTEP] = 0; // no iterative refinement: solve() needs only the factor
  }
  ~UmfpackSolver() override { release(); }
  std::string_view name() const override { return "UMFPACK (LU)"; }
  bool symmetric() const override { return false; }

  void analyze(const SparsityPattern& p) override {
    release();
    _pattern = &p;
    _n = p.n;
  }

  void factorize(const CsrMatrix& M) override {
    FE_CHECK(_pattern && M.n() == _n, "factorize before analyze");
    const auto& p = M.pattern();
    // Our CSR arrays are the CSC arrays of A^T; we factorise A^T and solve with UMFPACK_At.
    if (!_symbolic) {
      const int st = umfpack_di_symbolic(_n, _n, p.row_ptr.data(), p.col.data(), M.values().data(),
                                         &_symbolic, _control, _info);
      if (st != UMFPACK_OK) throw AnalysisError(fmt::format("UMFPACK symbolic analysis failed ({})", st));
    }
    if (_numeric) umfpack_di_free_numeric(&_numeric);
    const int st = umfpack_di_numeric(p.row_ptr.data(), p.col.data(), M.values().data(), _symbolic,
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
    throw AnalysisError(fmt::format("UMFPACK factorisation failed ({})", st));
  }

  void solve(std::span<const double> b, std::span<double> x) override {
    FE_CHECK(_numeric && _values, "solve before factorize");
    const auto& p = _values->pattern();
    const int st = umfpack_di_solve(UMFPACK_At, p.row_ptr.data(), p.col.data(),
                                    _values->values().data(), x.data(), b.data(), _numeric, _control,
                                    _info);
    if (st != UMFPACK_OK) throw AnalysisError(fmt::format("UMFPACK solve failed ({})", st));
  }

  std::size_t factor_bytes() const override {
    return static_cast<std::size_t>(_info[UMFPACK_NUMERIC_SIZE] * _info[UMFPACK_SIZE_OF_UNIT]);
  }

private:
  /// Equations whose pivot is negligible against the largest entry of their column.
  std::vector<LocalIndex> small_pivots(const CsrMatrix& M) {
    int lnz, unz, nr, nc, nz_udiag;
    umfpack_di_get_lunz(&lnz, &unz, &nr, &nc, &nz_udiag, _numeric);
    std::vector<double> udiag(static_cast<std::size_t>(_n));
    std::vector<int> P(static_cast<std::size_t>(_n)), Q(static_cast<std::size_t>(_n));
    std::vector<double> rs(static_cast<std::size_t>(_n));
    int do_recip = 0;
    umfpack_di_get_numeric(nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, P.data(), Q.data(),
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
      const LocalIndex eq = Q[k];
      if (!(u > 1e-12 * scale[eq])) bad.push_back(eq);
    }
    return bad;
  }

  void release() {
    if (_numeric) umfpack_di_free_numeric(&_numeric);
    if (_symbolic) umfpack_di_free_symbolic(&_symbolic);
    _values = nullptr;
  }

  double _control[UMFPACK_CONTROL];
  double _info[UMFPACK_INFO];
  void* _symbolic = nullptr;
  void* _numeric = nullptr;
  const SparsityPattern* _pattern = nullptr;
  const CsrMatrix* _values = nullptr;
  LocalIndex _n = 0;
};

} // namespace

std::unique_ptr<LinearSolver> make_umfpack_solver() { return std::make_unique<UmfpackSolver>(); }

} // namespace gapfem
