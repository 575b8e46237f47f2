#include "solver/substructure_mass.hpp"

#include "model/substructure_file.hpp"

#include <algorithm>

namespace gapfem {

std::vector<double> reduce_mass(const CsrMatrix& M, std::span<const LocalIndex> retained_eq,
                                std::span<const LocalIndex> internal_eq,
                                std::span<const LocalIndex> ret_index,
                                std::span<const LocalIndex> int_index,
                                const SubstructureRecovery& rec, ConstrainedFactor* Kii) {
  const std::size_t nR = retained_eq.size(), nI = internal_eq.size();
  const SparsityPattern& p = M.pattern();
  const auto v = M.values();
  std::vector<double> Mr(nR * nR, 0.0);
  // M_RR
  for (std::size_t r = 0; r < nR; ++r) {
    const LocalIndex row = retained_eq[r];
    for (LocalIndex k = p.row_ptr[row]; k < p.row_ptr[row + 1]; ++k)
      if (const LocalIndex c = ret_index[p.col[k]]; c >= 0) Mr[r * nR + c] += v[k];
  }
  if (nI > 0 && Kii != nullptr) {
    // X = K_II^-1 K_IR, column-major (X[c nI + i]), one multi-column solve
    std::vector<double> B(nI * nR, 0.0), X(nI * nR, 0.0);
    for (std::size_t i = 0; i < nI; ++i)
      for (std::int64_t k = rec.ir_ptr[i]; k < rec.ir_ptr[i + 1]; ++k)
        B[static_cast<std::size_t>(rec.ir_col[k]) * nI + i] = rec.ir_val[k];
    Kii->solve(B, {}, X, {}, static_cast<int>(nR));
    // P = M_IR^T X and Q = M_II X from the internal rows of M
    std::vector<double> P(nR * nR, 0.0), Q(nI * nR, 0.0);
    for (std::size_t i = 0; i < nI; ++i) {
      const LocalIndex row = internal_eq[i];
      for (LocalIndex k = p.row_ptr[row]; k < p.row_ptr[row + 1]; ++k) {
        const LocalIndex col = p.col[k];
        const double m = v[k];
        if (m == 0.0) continue;
        if (const LocalIndex r = ret_index[col]; r >= 0) {
          for (std::size_t c = 0; c < nR; ++c) P[r * nR + c] += m * X[c * nI + i];
        } else if (const LocalIndex j = int_index[col]; j >= 0) {
          for (std::size_t c = 0; c < nR; ++c) Q[c * nI + i] += m * X[c * nI + j];
        }
      }
    }
    // M_red = M_RR - P - P^T + X^T Q
    for (std::size_t r = 0; r < nR; ++r)
      for (std::size_t c = 0; c < nR; ++c) {
        double xq = 0.0;
        for (std::size_t i = 0; i < nI; ++i) xq += X[r * nI + i] * Q[c * nI + i];
        Mr[r * nR + c] += xq - P[r * nR + c] - P[c * nR + r];
      }
  }
  for (std::size_t i = 0; i < nR; ++i) // round-off: exactly symmetric
    for (std::size_t j = i + 1; j < nR; ++j)
      Mr[i * nR + j] = Mr[j * nR + i] = 0.5 * (Mr[i * nR + j] + Mr[j * nR + i]);
  return Mr;
}

} // namespace gapfem
