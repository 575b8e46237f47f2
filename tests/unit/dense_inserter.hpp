#pragma once
/// @file dense_inserter.hpp
/// A dense n x n target for the assembler in unit tests (equations index rows and columns; one
/// lane; rows or columns of prescribed DOFs, < 0, are dropped as CsrInserter drops them).
#include "linalg/matrix_inserter.hpp"

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

namespace gapfem::test {

class DenseInserter final : public MatrixInserter {
 public:
  explicit DenseInserter(std::size_t size) : n(size), A(size * size, 0.0) {}
  void set_zero() override { std::fill(A.begin(), A.end(), 0.0); }
  void open(int) override {}
  void add(int, std::span<const LocalIndex> rows, std::span<const LocalIndex> cols,
           std::span<const double> block) override {
    for (std::size_t i = 0; i < rows.size(); ++i)
      for (std::size_t j = 0; j < cols.size(); ++j)
        if (rows[i] >= 0 && cols[j] >= 0) A[rows[i] * n + cols[j]] += block[i * cols.size() + j];
  }
  void close() override {}
  double at(LocalIndex i, LocalIndex j) const { return A[i * n + j]; }
  std::size_t n;
  std::vector<double> A;
};

} // namespace gapfem::test
