#pragma once
/// @file low_rank_correction.hpp
/// A Cholesky factor kept exact for rank-one changes without touching it (the Woodbury identity).
/// With A0 = L L^T (in the factor's own ordering) and A = A0 + sum_j s_j u_j u_j^T, s_j = +-1:
///
///     A = L (I + Y S Y^T) L^T,   Y = L^-1 U,   (I + Y S Y^T)^-1 = I - Y G^-1 Y^T,   G = S + Y^T Y
///
/// so a solve with A is the forward solve with L, the correction y -= Y G^-1 Y^T y and the backward
/// solve with L^T: the supernodal factor and its BLAS-3 solves stay as they are. A column removed
/// after it was added cancels it exactly (contact rows that close, then open again).
/// CHOLMOD's own update/downdate instead rewrites the factor column by column along the
/// elimination tree after converting it to its slower simplicial form (docs/performance.md).
#include "common/types.hpp"

#include <Eigen/Dense>
#include <span>
#include <vector>

namespace gapfem {

class LowRankCorrection {
 public:
  /// One rank-one term s u u^T: u and y = L^-1 u as sparse vectors (rows ascending).
  struct Column {
    std::vector<LocalIndex> u_row, y_row;
    std::vector<double> u_val, y_val;
    double sign = 1.0;
  };

  explicit LowRankCorrection(LocalIndex n = 0) : _n(n) {}
  void reset(LocalIndex n);
  int size() const { return static_cast<int>(_cols.size()); }
  bool empty() const { return _cols.empty(); }
  /// Cancel the term that `u` with `sign` would undo (the same u to 1e-12, the opposite sign):
  /// true when there was one (it is removed), false otherwise.
  bool cancel(std::span<const LocalIndex> rows, std::span<const double> vals, double sign);
  /// Add terms. Call factorize() after the last one.
  void add(std::vector<Column> cols);
  void add(Column c) {
    std::vector<Column> one;
    one.push_back(std::move(c));
    add(std::move(one));
  }
  /// Factorise G. Throws SingularSystem when L L^T + U S U^T is not positive definite (its
  /// smallest eigenvalue relative to L L^T's below 1e-12): the terms are then unusable.
  void factorize();
  /// y := (I + Y S Y^T)^-1 y for k right-hand sides (column-major, n x k).
  void apply(std::span<double> y, int k) const;
  /// Bytes held (the sparse columns and G).
  std::size_t bytes() const;
  /// Nonzeros of Y (the work of one correction is twice this).
  std::size_t y_nonzeros() const { return _y_nnz; }

 private:
  /// G's columns k0.. (the terms just added): y_i^T y_j over the rows the new columns reach, as
  /// dense products (BLAS), the old columns gathered onto those rows a chunk at a time.
  void fill_columns(int k0);

  LocalIndex _n = 0;
  std::vector<Column> _cols;
  Eigen::MatrixXd _G;                ///< S + Y^T Y
  std::vector<int> _added, _removed; ///< indices with s = +1 and s = -1
  Eigen::LLT<Eigen::MatrixXd> _Gaa;  ///< G_AA = I + Y_A^T Y_A (positive definite)
  Eigen::LLT<Eigen::MatrixXd> _T;    ///< T = -(G_RR - G_RA G_AA^-1 G_AR) (positive definite)
  Eigen::MatrixXd _GaaInvGar;        ///< G_AA^-1 G_AR
  std::vector<int> _pos;             ///< row -> its place among the new columns' rows (-1: none)
  std::size_t _y_nnz = 0;
};

} // namespace gapfem
