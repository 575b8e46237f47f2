#include "linalg/multiplier_columns.hpp"

#include "common/memory.hpp"
#include "linalg/sparse_gram.hpp"

#include <algorithm>

namespace gapfem {

void MultiplierColumns::reset(LocalIndex n) {
  _n = n;
  _cols.clear();
  _of.clear();
  _G.resize(0, 0);
  _pos.assign(static_cast<std::size_t>(n), -1);
}

int MultiplierColumns::find(const ConstraintBlock& B, int r) const {
  const LocalIndex b0 = B.row_ptr[r], b1 = B.row_ptr[r + 1];
  const auto [first, last] = _of.equal_range(B.multiplier[r]);
  for (auto it = first; it != last; ++it) {
    const Column& c = _cols[it->second];
    if (std::equal(c.c_col.begin(), c.c_col.end(), B.col.begin() + b0, B.col.begin() + b1) &&
        std::equal(c.c_val.begin(), c.c_val.end(), B.val.begin() + b0, B.val.begin() + b1))
      return it->second;
  }
  return -1;
}

bool MultiplierColumns::add(LinearSolver& solver, const ConstraintBlock& B,
                            std::span<const int> rows, std::vector<int>& index) {
  index.clear();
  if (rows.empty()) return true;
  SparseColumns W, Z;
  for (int r : rows) {
    for (LocalIndex k = B.row_ptr[r]; k < B.row_ptr[r + 1]; ++k) {
      W.row.push_back(B.col[k]);
      W.val.push_back(B.val[k]);
    }
    W.ptr.push_back(static_cast<LocalIndex>(W.row.size()));
  }
  if (!solver.forward_sparse(W, Z)) return false;
  // the columns are kept: they must leave room for the rest of the run
  if (const auto available = available_memory_bytes();
      available && 2.0 * static_cast<double>(Z.row.size()) * (sizeof(LocalIndex) + sizeof(double)) >
                       static_cast<double>(*available))
    return false;
  const int k0 = size();
  for (std::size_t j = 0; j < rows.size(); ++j) {
    const int r = rows[j];
    Column c;
    c.multiplier = B.multiplier[r];
    c.c_col.assign(B.col.begin() + B.row_ptr[r], B.col.begin() + B.row_ptr[r + 1]);
    c.c_val.assign(B.val.begin() + B.row_ptr[r], B.val.begin() + B.row_ptr[r + 1]);
    c.z_row.assign(Z.row.begin() + Z.ptr[j], Z.row.begin() + Z.ptr[j + 1]);
    c.z_val.assign(Z.val.begin() + Z.ptr[j], Z.val.begin() + Z.ptr[j + 1]);
    index.push_back(size());
    _of.emplace(c.multiplier, size());
    _cols.push_back(std::move(c));
  }
  const int k = size();
  _G.conservativeResize(k, k);
  if (_pos.size() != static_cast<std::size_t>(_n)) _pos.assign(static_cast<std::size_t>(_n), -1);
  fill_gram(
      k, k0,
      [&](int j) {
        return SparseColumnView{_cols[j].z_row, _cols[j].z_val};
      },
      _G, _pos);
  return true;
}

void MultiplierColumns::keep(std::span<const int> keep) {
  std::vector<Column> cols;
  cols.reserve(keep.size());
  for (int j : keep) cols.push_back(std::move(_cols[j]));
  std::vector<int> idx(keep.begin(), keep.end());
  Eigen::MatrixXd G = _G(idx, idx);
  _G = std::move(G);
  _cols = std::move(cols);
  _of.clear();
  for (int j = 0; j < size(); ++j) _of.emplace(_cols[j].multiplier, j);
}

void MultiplierColumns::dot(std::span<const int> idx, std::span<const double> t,
                            std::span<double> out) const {
  for (std::size_t j = 0; j < idx.size(); ++j) {
    const Column& c = _cols[idx[j]];
    double s = 0.0;
    for (std::size_t q = 0; q < c.z_row.size(); ++q) s += c.z_val[q] * t[c.z_row[q]];
    out[j] = s;
  }
}

void MultiplierColumns::subtract(std::span<const int> idx, std::span<const double> w,
                                 std::span<double> t) const {
  for (std::size_t j = 0; j < idx.size(); ++j) {
    const Column& c = _cols[idx[j]];
    const double a = w[j];
    if (a == 0.0) continue;
    for (std::size_t q = 0; q < c.z_row.size(); ++q) t[c.z_row[q]] -= a * c.z_val[q];
  }
}

std::size_t MultiplierColumns::bytes() const {
  std::size_t b = static_cast<std::size_t>(_G.size()) * sizeof(double);
  for (const Column& c : _cols)
    b += (c.c_col.size() + c.z_row.size()) * (sizeof(LocalIndex) + sizeof(double));
  return b;
}

} // namespace gapfem
