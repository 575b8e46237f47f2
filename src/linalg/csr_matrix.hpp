#pragma once
/// @file csr_matrix.hpp
/// Compressed sparse row storage with a shared, immutable pattern (built once per step). Both
/// triangles are stored, so the same matrix serves the symmetric (CHOLMOD) and unsymmetric
/// (UMFPACK) paths. Column indices are sorted within each row.
#include "common/types.hpp"

#include <memory>
#include <span>
#include <vector>

namespace gapfem {

struct SparsityPattern {
  LocalIndex n = 0;
  std::vector<LocalIndex> row_ptr; ///< n + 1
  std::vector<LocalIndex> col;     ///< sorted per row, diagonal always present
  std::size_t nnz() const { return col.size(); }
  /// Position of (row, column) in col/values, or -1 if not in the pattern.
  LocalIndex find(LocalIndex row, LocalIndex column) const;
};

class CsrMatrix {
 public:
  CsrMatrix() = default;
  explicit CsrMatrix(std::shared_ptr<const SparsityPattern> pattern)
      : _pattern(std::move(pattern)), _values(_pattern->nnz(), 0.0) {}

  const SparsityPattern& pattern() const { return *_pattern; }
  std::shared_ptr<const SparsityPattern> pattern_ptr() const { return _pattern; }
  LocalIndex n() const { return _pattern ? _pattern->n : 0; }
  std::span<double> values() { return _values; }
  std::span<const double> values() const { return _values; }
  void set_zero();
  /// Adds a dense row-major block: rows/cols are equation numbers, negative ones are skipped.
  void add_block(std::span<const LocalIndex> rows, std::span<const LocalIndex> cols,
                 std::span<const double> block);
  /// Thread-safe variant of add_block (atomic adds), for threaded assembly.
  void add_block_atomic(std::span<const LocalIndex> rows, std::span<const LocalIndex> cols,
                        std::span<const double> block);
  void add(LocalIndex row, LocalIndex column, double v);
  double diagonal(LocalIndex row) const;
  /// y = A x
  void multiply(std::span<const double> x, std::span<double> y) const;
  /// max |A - A^T| / max |A| (0 for symmetric)
  double asymmetry() const;

 private:
  std::shared_ptr<const SparsityPattern> _pattern;
  std::vector<double> _values;
};

/// Build the pattern from a list of element equation lists (negative entries ignored). Each
/// element couples all its equations. `n` is the number of equations.
std::shared_ptr<SparsityPattern>
build_pattern(LocalIndex n, std::span<const std::span<const LocalIndex>> elements);

} // namespace gapfem
