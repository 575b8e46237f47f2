#include "linalg/csr_matrix.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace gapfem {

LocalIndex SparsityPattern::find(LocalIndex row, LocalIndex column) const {
  const auto* begin = col.data() + row_ptr[row];
  const auto* end = col.data() + row_ptr[row + 1];
  const auto* it = std::lower_bound(begin, end, column);
  return (it != end && *it == column) ? static_cast<LocalIndex>(it - col.data()) : -1;
}

void CsrMatrix::set_zero() {
  std::fill(_values.begin(), _values.end(), 0.0);
}

namespace {
/// Adds a dense block into rows of a CSR matrix. For each local row, local columns are visited in
/// ascending equation order (via a small sort of indices) and merged with the sorted CSR row.
template <typename Add>
void scatter_block(const SparsityPattern& p, std::span<const LocalIndex> rows,
                   std::span<const LocalIndex> cols, std::span<const double> block, Add&& add) {
  const std::size_t nr = rows.size(), nc = cols.size();
  constexpr std::size_t kMax = 128;
  std::array<std::uint16_t, kMax> order_small{};
  std::vector<std::uint16_t> order_big;
  std::uint16_t* order = order_small.data();
  if (nc > kMax) {
    order_big.resize(nc);
    order = order_big.data();
  }
  std::size_t n_valid = 0;
  for (std::size_t j = 0; j < nc; ++j)
    if (cols[j] >= 0) order[n_valid++] = static_cast<std::uint16_t>(j);
  std::sort(order, order + n_valid, [&](auto a, auto b) { return cols[a] < cols[b]; });
  for (std::size_t i = 0; i < nr; ++i) {
    const LocalIndex r = rows[i];
    if (r < 0) continue;
    LocalIndex pos = p.row_ptr[r];
    const LocalIndex end = p.row_ptr[r + 1];
    const double* brow = block.data() + i * nc;
    for (std::size_t k = 0; k < n_valid; ++k) {
      const std::size_t j = order[k];
      const LocalIndex c = cols[j];
      while (pos < end && p.col[pos] < c) ++pos;
      FE_CHECK(pos < end && p.col[pos] == c, "matrix entry outside the sparsity pattern");
      add(pos, brow[j]);
    }
  }
}
} // namespace

void CsrMatrix::add_block(std::span<const LocalIndex> rows, std::span<const LocalIndex> cols,
                          std::span<const double> block) {
  double* v = _values.data();
  scatter_block(*_pattern, rows, cols, block, [v](LocalIndex pos, double x) { v[pos] += x; });
}

void CsrMatrix::add_block_atomic(std::span<const LocalIndex> rows, std::span<const LocalIndex> cols,
                                 std::span<const double> block) {
  double* v = _values.data();
  scatter_block(*_pattern, rows, cols, block, [v](LocalIndex pos, double x) {
    std::atomic_ref<double>(v[pos]).fetch_add(x, std::memory_order_relaxed);
  });
}

void CsrMatrix::add(LocalIndex row, LocalIndex column, double v) {
  const LocalIndex pos = _pattern->find(row, column);
  FE_CHECK(pos >= 0, "matrix entry outside the sparsity pattern");
  _values[pos] += v;
}

double CsrMatrix::diagonal(LocalIndex row) const {
  const LocalIndex pos = _pattern->find(row, row);
  return pos >= 0 ? _values[pos] : 0.0;
}

void CsrMatrix::multiply(std::span<const double> x, std::span<double> y) const {
  const auto& p = *_pattern;
  for (LocalIndex r = 0; r < p.n; ++r) {
    double s = 0.0;
    for (LocalIndex k = p.row_ptr[r]; k < p.row_ptr[r + 1]; ++k) s += _values[k] * x[p.col[k]];
    y[r] = s;
  }
}

double CsrMatrix::asymmetry() const {
  const auto& p = *_pattern;
  double amax = 0.0, dmax = 0.0;
  for (LocalIndex r = 0; r < p.n; ++r)
    for (LocalIndex k = p.row_ptr[r]; k < p.row_ptr[r + 1]; ++k) {
      amax = std::max(amax, std::abs(_values[k]));
      const LocalIndex t = p.find(p.col[k], r);
      const double vt = t >= 0 ? _values[t] : 0.0;
      dmax = std::max(dmax, std::abs(_values[k] - vt));
    }
  return amax > 0 ? dmax / amax : 0.0;
}

std::shared_ptr<SparsityPattern>
build_pattern(LocalIndex n, std::span<const std::span<const LocalIndex>> elements) {
  // Count-then-fill with per-row dedup: first collect (row, col) pairs row by row through a
  // row-wise adjacency built in two passes, then sort/unique each row.
  std::vector<std::int64_t> count(static_cast<std::size_t>(n) + 1, 0);
  for (const auto& eqs : elements) {
    std::int64_t valid = 0;
    for (LocalIndex e : eqs) valid += (e >= 0);
    for (LocalIndex e : eqs)
      if (e >= 0) count[e + 1] += valid;
  }
  for (LocalIndex r = 0; r < n; ++r) count[r + 1] += count[r] + 0;
  // add diagonal slot per row
  std::vector<std::int64_t> start(static_cast<std::size_t>(n) + 1, 0);
  for (LocalIndex r = 0; r < n; ++r) start[r + 1] = count[r + 1] + (r + 1);
  std::vector<LocalIndex> raw(static_cast<std::size_t>(start[n]));
  std::vector<std::int64_t> fill(start.begin(), start.end() - 1);
  for (LocalIndex r = 0; r < n; ++r) raw[fill[r]++] = r;
  for (const auto& eqs : elements)
    for (LocalIndex a : eqs) {
      if (a < 0) continue;
      for (LocalIndex b : eqs)
        if (b >= 0) raw[fill[a]++] = b;
    }
  auto pattern = std::make_shared<SparsityPattern>();
  pattern->n = n;
  pattern->row_ptr.assign(static_cast<std::size_t>(n) + 1, 0);
  std::int64_t total = 0;
  for (LocalIndex r = 0; r < n; ++r) {
    auto* b = raw.data() + start[r];
    auto* e = raw.data() + fill[r];
    std::sort(b, e);
    const auto* u = std::unique(b, e);
    total += (u - b);
    if (total > std::numeric_limits<LocalIndex>::max())
      throw AnalysisError(
          "the stiffness matrix has more than 2^31 non-zeros; the model is too large "
          "for this build");
    fill[r] = start[r] + (u - b);
  }
  pattern->col.reserve(static_cast<std::size_t>(total));
  for (LocalIndex r = 0; r < n; ++r) {
    pattern->col.insert(pattern->col.end(), raw.data() + start[r], raw.data() + fill[r]);
    pattern->row_ptr[r + 1] = static_cast<LocalIndex>(pattern->col.size());
  }
  return pattern;
}

} // namespace gapfem
