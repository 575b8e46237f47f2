#include "linalg/multiplier_columns.hpp"

#include "common/memory.hpp"
#include "linalg/sparse_gram.hpp"

#include <algorithm>

namespace gapfem {

void MultiplierColumns::reset(LocalIndex n) {
  _n = n;
  _units.clear();
  _of_row.clear();
  _of_equation.clear();
  _G.resize(0, 0);
  _pos.assign(static_cast<std::size_t>(n), -1);
}

int MultiplierColumns::find_row(std::int64_t multiplier, std::span<const LocalIndex> col,
                                std::span<const double> val) const {
  const auto [first, last] = _of_row.equal_range(multiplier);
  for (auto it = first; it != last; ++it) {
    const Unit& u = _units[it->second];
    if (std::equal(u.c_col.begin(), u.c_col.end(), col.begin(), col.end()) &&
        std::equal(u.c_val.begin(), u.c_val.end(), val.begin(), val.end()))
      return it->second;
  }
  return -1;
}

void MultiplierColumns::index_unit(int u) {
  if (_units[u].equation >= 0)
    _of_equation[_units[u].equation] = u;
  else
    _of_row.emplace(_units[u].multiplier, u);
}

bool MultiplierColumns::make(LinearSolver& solver, std::vector<Unit>& fresh) {
  if (fresh.empty()) return true;
  SparseColumns W, Z;
  for (const Unit& u : fresh) {
    W.row.insert(W.row.end(), u.c_col.begin(), u.c_col.end());
    W.val.insert(W.val.end(), u.c_val.begin(), u.c_val.end());
    W.ptr.push_back(static_cast<LocalIndex>(W.row.size()));
  }
  if (!solver.forward_sparse(W, Z)) return false;
  // the columns are kept: they must leave room for the rest of the run
  if (const auto available = available_memory_bytes();
      available && 2.0 * static_cast<double>(Z.row.size()) * (sizeof(LocalIndex) + sizeof(double)) >
                       static_cast<double>(*available))
    return false;
  const int k0 = size();
  for (std::size_t j = 0; j < fresh.size(); ++j) {
    Unit& u = fresh[j];
    u.z_row.assign(Z.row.begin() + Z.ptr[j], Z.row.begin() + Z.ptr[j + 1]);
    u.z_val.assign(Z.val.begin() + Z.ptr[j], Z.val.begin() + Z.ptr[j + 1]);
    _units.push_back(std::move(u));
    index_unit(size() - 1);
  }
  const int k = size();
  _G.conservativeResize(k, k);
  if (_pos.size() != static_cast<std::size_t>(_n)) _pos.assign(static_cast<std::size_t>(_n), -1);
  fill_gram(
      k, k0,
      [&](int j) {
        return SparseColumnView{_units[j].z_row, _units[j].z_val};
      },
      _G, _pos);
  return true;
}

bool MultiplierColumns::express(LinearSolver& solver, const ConstraintBlock& B,
                                std::span<const int> rows, bool columns, Combination& out,
                                int& made) {
  made = 0;
  const bool own = columns && B.has_columns();
  const std::vector<double>& V = own ? B.dval : B.val;
  auto coefficients = [&](int r) {
    const auto b0 = static_cast<std::size_t>(B.row_ptr[r]);
    const auto len = static_cast<std::size_t>(B.row_ptr[r + 1] - B.row_ptr[r]);
    return std::pair{std::span<const LocalIndex>(B.col).subspan(b0, len),
                     std::span<const double>(V).subspan(b0, len)};
  };
  // Pass 1: how each row is expressed, and the columns missing for it. A row is a combination of
  // equation columns when they all exist already, or when it varies (its multiplier had other
  // coefficients before, or it is a column of its own, which follows the state) over a few
  // equations; otherwise it is a column of its own.
  std::vector<char> by_equation(rows.size(), 0);
  std::vector<Unit> fresh;
  std::unordered_map<LocalIndex, char> fresh_equation;
  for (std::size_t j = 0; j < rows.size(); ++j) {
    const int r = rows[j];
    const auto [col, val] = coefficients(r);
    bool all = true;
    for (std::size_t k = 0; k < col.size(); ++k)
      if (val[k] != 0.0 && !_of_equation.contains(col[k])) all = false;
    if (all) {
      by_equation[j] = 1;
      continue;
    }
    if (find_row(B.multiplier[r], col, val) >= 0) continue;
    // (a one-equation row is its equation's column: the same cost, and shared with the other
    // rows of that equation)
    const bool varies = own || col.size() == 1 || _of_row.contains(B.multiplier[r]);
    if (varies && static_cast<int>(col.size()) <= kMaxEquations) {
      by_equation[j] = 1;
      for (std::size_t k = 0; k < col.size(); ++k)
        if (val[k] != 0.0 && !_of_equation.contains(col[k]) &&
            fresh_equation.emplace(col[k], 1).second) {
          Unit u;
          u.equation = col[k];
          u.c_col = {col[k]};
          u.c_val = {1.0};
          fresh.push_back(std::move(u));
        }
    } else {
      bool pending = false; // the same row twice in one call
      for (const Unit& u : fresh)
        pending = pending || (u.multiplier == B.multiplier[r] &&
                              std::equal(u.c_col.begin(), u.c_col.end(), col.begin(), col.end()) &&
                              std::equal(u.c_val.begin(), u.c_val.end(), val.begin(), val.end()));
      if (pending) continue;
      Unit u;
      u.multiplier = B.multiplier[r];
      u.c_col.assign(col.begin(), col.end());
      u.c_val.assign(val.begin(), val.end());
      fresh.push_back(std::move(u));
    }
  }
  if (!make(solver, fresh)) return false;
  made = static_cast<int>(fresh.size());
  // Pass 2: the combinations.
  for (std::size_t j = 0; j < rows.size(); ++j) {
    const int r = rows[j];
    const auto [col, val] = coefficients(r);
    if (by_equation[j]) {
      for (std::size_t k = 0; k < col.size(); ++k)
        if (val[k] != 0.0) {
          out.unit.push_back(_of_equation.at(col[k]));
          out.coef.push_back(val[k]);
        }
    } else {
      out.unit.push_back(find_row(B.multiplier[r], col, val));
      out.coef.push_back(1.0);
    }
    out.ptr.push_back(static_cast<int>(out.unit.size()));
  }
  return true;
}

std::vector<int> MultiplierColumns::used_units(const Combination& A, const Combination& B,
                                               std::vector<int>& local) const {
  local.assign(_units.size(), -1);
  std::vector<int> used;
  for (const auto* X : {&A, &B})
    for (int u : X->unit)
      if (local[u] < 0) {
        local[u] = static_cast<int>(used.size());
        used.push_back(u);
      }
  return used;
}

Eigen::MatrixXd MultiplierColumns::product(const Combination& A, const Combination& B) const {
  // the units in use, their Gram block, then T = G_U B^T and S = A T
  std::vector<int> local;
  const std::vector<int> used = used_units(A, B, local);
  const Eigen::MatrixXd GU = _G(used, used);
  // column by column throughout (contiguous): T = G_U B^T, then S^T = T^T A^T
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(GU.rows(), B.rows());
  for (int s = 0; s < B.rows(); ++s)
    for (int k = B.ptr[s]; k < B.ptr[s + 1]; ++k) T.col(s) += B.coef[k] * GU.col(local[B.unit[k]]);
  const Eigen::MatrixXd Tt = T.transpose();
  Eigen::MatrixXd St = Eigen::MatrixXd::Zero(B.rows(), A.rows());
  for (int r = 0; r < A.rows(); ++r)
    for (int k = A.ptr[r]; k < A.ptr[r + 1]; ++k) St.col(r) += A.coef[k] * Tt.col(local[A.unit[k]]);
  return St.transpose();
}

void MultiplierColumns::dot(const Combination& A, std::span<const double> t,
                            std::span<double> out) const {
  std::vector<double> zt(_units.size(), 0.0);
  std::vector<char> done(_units.size(), 0);
  for (int r = 0; r < A.rows(); ++r) {
    double s = 0.0;
    for (int k = A.ptr[r]; k < A.ptr[r + 1]; ++k) {
      const int u = A.unit[k];
      if (!done[u]) {
        const Unit& c = _units[u];
        double v = 0.0;
        for (std::size_t q = 0; q < c.z_row.size(); ++q) v += c.z_val[q] * t[c.z_row[q]];
        zt[u] = v;
        done[u] = 1;
      }
      s += A.coef[k] * zt[u];
    }
    out[r] = s;
  }
}

void MultiplierColumns::subtract(const Combination& B, std::span<const double> w,
                                 std::span<double> t) const {
  std::vector<double> weight(_units.size(), 0.0);
  for (int s = 0; s < B.rows(); ++s)
    for (int k = B.ptr[s]; k < B.ptr[s + 1]; ++k) weight[B.unit[k]] += B.coef[k] * w[s];
  for (std::size_t u = 0; u < _units.size(); ++u) {
    const double a = weight[u];
    if (a == 0.0) continue;
    const Unit& c = _units[u];
    for (std::size_t q = 0; q < c.z_row.size(); ++q) t[c.z_row[q]] -= a * c.z_val[q];
  }
}

void MultiplierColumns::prune(Combination& A, Combination& B) {
  std::vector<int> renumber;
  const std::vector<int> keep = used_units(A, B, renumber);
  if (size() <= 2 * static_cast<int>(keep.size()) + 64) return;
  std::vector<Unit> units;
  units.reserve(keep.size());
  for (int u : keep) units.push_back(std::move(_units[u]));
  Eigen::MatrixXd G = _G(keep, keep);
  _G = std::move(G);
  _units = std::move(units);
  _of_row.clear();
  _of_equation.clear();
  for (int u = 0; u < size(); ++u) index_unit(u);
  for (int& u : A.unit) u = renumber[u];
  if (&A != &B)
    for (int& u : B.unit) u = renumber[u];
}

std::size_t MultiplierColumns::bytes() const {
  std::size_t b = static_cast<std::size_t>(_G.size()) * sizeof(double);
  for (const Unit& c : _units)
    b += (c.c_col.size() + c.z_row.size()) * (sizeof(LocalIndex) + sizeof(double));
  return b;
}

} // namespace gapfem
