#pragma once
/// @file sparse_gram.hpp
/// Inner products of sparse columns (the Gram matrix Y^T Y) by dense BLAS products over the rows
/// the columns reach: the columns of L^-1 U of a sparse factor share the rows near the root of
/// the elimination tree, where their products are dense.
#include "common/types.hpp"

#include <Eigen/Dense>
#include <functional>
#include <span>
#include <vector>

namespace gapfem {

/// One sparse column: rows ascending (all below the scratch's size), values.
struct SparseColumnView {
  std::span<const LocalIndex> row;
  std::span<const double> val;
};

/// G(i, j) = G(j, i) = y_i^T y_j for i < k and k0 <= j < k, where column(i) gives y_i; G is at
/// least k x k and its other entries are left alone. `pos` is scratch of one entry per row, -1
/// on entry and on return.
void fill_gram(int k, int k0, const std::function<SparseColumnView(int)>& column,
               Eigen::MatrixXd& G, std::vector<int>& pos);

} // namespace gapfem
