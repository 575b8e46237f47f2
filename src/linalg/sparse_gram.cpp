#include "linalg/sparse_gram.hpp"

#include "linalg/blas.hpp"

#include <algorithm>

namespace gapfem {

void fill_gram(int k, int k0, const std::function<SparseColumnView(int)>& column,
               Eigen::MatrixXd& G, std::vector<int>& pos) {
  const int nb = k - k0;
  if (nb <= 0) return;
  // the rows the new columns reach, and the new columns on them (dense, column-major)
  std::vector<LocalIndex> rows;
  for (int j = k0; j < k; ++j)
    for (LocalIndex r : column(j).row)
      if (pos[r] < 0) {
        pos[r] = static_cast<int>(rows.size());
        rows.push_back(r);
      }
  const int m = static_cast<int>(rows.size());
  std::vector<double> Ynew(static_cast<std::size_t>(m) * nb, 0.0);
  for (int j = k0; j < k; ++j) {
    const SparseColumnView c = column(j);
    for (std::size_t q = 0; q < c.row.size(); ++q)
      Ynew[static_cast<std::size_t>(j - k0) * m + pos[c.row[q]]] = c.val[q];
  }
  G.block(0, k0, k, nb).setZero();
  G.block(k0, 0, nb, k).setZero();
  const double one = 1.0, zero = 0.0;
  std::vector<double> prod;
  auto products = [&](const double* Y, int ncols, int i0) { // G(i0.., k0..) = Y^T Ynew
    if (m == 0) return;
    prod.resize(static_cast<std::size_t>(ncols) * nb);
    dgemm_("T", "N", &ncols, &nb, &m, &one, Y, &m, Ynew.data(), &m, &zero, prod.data(), &ncols);
    for (int j = 0; j < nb; ++j)
      for (int i = 0; i < ncols; ++i)
        G(i0 + i, k0 + j) = G(k0 + j, i0 + i) = prod[static_cast<std::size_t>(j) * ncols + i];
  };
  products(Ynew.data(), nb, k0);
  // the old columns on the same rows, in chunks that keep the gathered block near 64 MB
  const int chunk = std::max(1, static_cast<int>((std::size_t{8} << 20) / std::max(m, 1)));
  std::vector<double> Yold;
  for (int i0 = 0; i0 < k0; i0 += chunk) {
    const int nc = std::min(chunk, k0 - i0);
    Yold.assign(static_cast<std::size_t>(m) * nc, 0.0);
    for (int i = 0; i < nc; ++i) {
      const SparseColumnView c = column(i0 + i);
      for (std::size_t q = 0; q < c.row.size(); ++q)
        if (const int p = pos[c.row[q]]; p >= 0)
          Yold[static_cast<std::size_t>(i) * m + p] = c.val[q];
    }
    products(Yold.data(), nc, i0);
  }
  for (LocalIndex r : rows) pos[r] = -1;
}

} // namespace gapfem
