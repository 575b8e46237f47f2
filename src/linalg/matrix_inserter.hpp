#pragma once
/// @file matrix_inserter.hpp
/// Where assembly writes the tangent: a MatSet-style sink (the idea of DOLFINx's `la::MatSet`).
/// The assembler never sees the storage; it adds dense element blocks by local equation number
/// (negative numbers are prescribed DOFs and are skipped). Threads write through separate lanes:
/// a lane is written by one thread only, and close() merges the lanes in a fixed order, so the
/// assembled matrix is bitwise reproducible whatever the thread timing. A backend with its own
/// matrix (a distributed one) implements the same four calls on its storage.
#include "linalg/csr_matrix.hpp"

#include <memory>
#include <span>
#include <vector>

namespace gapfem {

class MatrixInserter {
 public:
  virtual ~MatrixInserter() = default;
  /// Zero every entry of the target (the pattern stays).
  virtual void set_zero() = 0;
  /// Prepare `lanes` independent writers (lane 0 always exists).
  virtual void open(int lanes) = 0;
  /// target[rows, cols] += block (dense, row-major); only lane `lane` is touched.
  virtual void add(int lane, std::span<const LocalIndex> rows, std::span<const LocalIndex> cols,
                   std::span<const double> block) = 0;
  /// Merge the lanes into the target; after it the target holds the sum of everything added.
  virtual void close() = 0;
};

/// Inserts into a CsrMatrix: lane 0 writes the matrix itself, lanes 1.. private value arrays over
/// the same pattern, added to it in lane order by close().
class CsrInserter final : public MatrixInserter {
 public:
  explicit CsrInserter(CsrMatrix& target) : _A(&target) {}
  CsrMatrix& target() { return *_A; }
  void set_zero() override { _A->set_zero(); }
  void open(int lanes) override;
  void add(int lane, std::span<const LocalIndex> rows, std::span<const LocalIndex> cols,
           std::span<const double> block) override;
  void close() override;

 private:
  CsrMatrix* _A;
  int _lanes = 1;
  std::vector<std::unique_ptr<CsrMatrix>> _private; ///< lanes 1.. (index lane - 1)
  std::vector<char> _touched;                       ///< per private lane: written since open()
};

} // namespace gapfem
