#include "linalg/row_elimination.hpp"

#include "common/error.hpp"

#include <cmath>

namespace gapfem {

namespace {
/// Append row r of C to `to`.
void append_row(ConstraintBlock& to, const ConstraintBlock& C, int r) {
  const LocalIndex k0 = C.row_ptr[r], k1 = C.row_ptr[r + 1];
  to.col.insert(to.col.end(), C.col.begin() + k0, C.col.begin() + k1);
  to.val.insert(to.val.end(), C.val.begin() + k0, C.val.begin() + k1);
  if (C.has_columns()) to.dval.insert(to.dval.end(), C.dval.begin() + k0, C.dval.begin() + k1);
  to.row_ptr.push_back(static_cast<LocalIndex>(to.col.size()));
  to.g.push_back(C.g[r]);
  if (!C.compliance.empty()) to.compliance.push_back(C.row_compliance(r));
  to.multiplier.push_back(C.multiplier[r]);
}
} // namespace

void RowElimination::reduce(CsrMatrix& K, std::span<const double> b, const ConstraintBlock& C,
                            bool pin) {
  const SparsityPattern& pat = K.pattern();
  auto vals = K.values();
  *this = RowElimination{};
  _n_rows = C.n_rows();
  _b.assign(b.begin(), b.end());

  // how many row entries fall on each equation
  std::vector<int> touches(static_cast<std::size_t>(K.n()), 0);
  for (LocalIndex i : C.col) ++touches[i];

  auto modify = [&](LocalIndex pos, double value) {
    _saved.emplace_back(pos, vals[pos]);
    vals[pos] = value;
  };
  for (int r = 0; r < C.n_rows(); ++r) {
    const LocalIndex k0 = C.row_ptr[r], k1 = C.row_ptr[r + 1];
    const double E = C.row_compliance(r);
    if (E > 0 && k1 > k0) { // K + D E^-1 C, b - D E^-1 g
      _folded.push_back(r);
      for (LocalIndex a = k0; a < k1; ++a) {
        const double da = C.column_value(a) / E;
        _b[C.col[a]] -= da * C.g[r];
        for (LocalIndex c = k0; c < k1; ++c) {
          const LocalIndex pos = pat.find(C.col[a], C.col[c]);
          FE_CHECK(pos >= 0, "constraint row outside the sparsity pattern");
          modify(pos, vals[pos] + da * C.val[c]);
        }
      }
      continue;
    }
    if (pin && E == 0 && k1 - k0 == 1 && touches[C.col[k0]] == 1 && C.val[k0] != 0 &&
        C.column_value(k0) != 0) {
      _pin_row.push_back(r);
      _pin_eq.push_back(C.col[k0]);
      _pin_du.push_back(-C.g[r] / C.val[k0]);
      _pin_d.push_back(C.column_value(k0));
      continue;
    }
    _kept.push_back(r);
  }

  // the pinned equations' rows as they are (their multipliers come from them), then their rows
  // and columns replaced by the diagonal
  _pin_row_start.push_back(0);
  for (LocalIndex j : _pin_eq) {
    for (LocalIndex k = pat.row_ptr[j]; k < pat.row_ptr[j + 1]; ++k) {
      _pin_cols.push_back(pat.col[k]);
      _pin_vals.push_back(vals[k]);
    }
    _pin_row_start.push_back(static_cast<LocalIndex>(_pin_cols.size()));
  }
  for (std::size_t p = 0; p < _pin_eq.size(); ++p) {
    const LocalIndex j = _pin_eq[p];
    const double du = _pin_du[p];
    for (LocalIndex k = pat.row_ptr[j]; k < pat.row_ptr[j + 1]; ++k) {
      const LocalIndex i = pat.col[k];
      if (i == j) continue;
      if (const LocalIndex pos = pat.find(i, j); pos >= 0) {
        _b[i] -= vals[pos] * du;
        modify(pos, 0.0);
      }
      modify(k, 0.0);
    }
    const LocalIndex diag = pat.find(j, j);
    FE_CHECK(diag >= 0, "pinned equation without a diagonal entry");
    if (!(vals[diag] > 0)) modify(diag, 1.0);
    _b[j] = vals[diag] * du;
  }

  // the rows left
  for (int r : _kept) append_row(_rows, C, r);
}

ConstraintBlock RowElimination::unpinned_rows(const ConstraintBlock& C) const {
  ConstraintBlock out;
  std::size_t p = 0;
  for (int r = 0; r < C.n_rows(); ++r) {
    if (p < _pin_row.size() && _pin_row[p] == r) {
      ++p;
      continue;
    }
    append_row(out, C, r);
  }
  return out;
}

void RowElimination::recover(std::span<const double> b, const ConstraintBlock& C,
                             std::span<double> du, std::span<const double> dl_reduced,
                             std::span<double> dl) const {
  for (std::size_t i = 0; i < _kept.size(); ++i) dl[_kept[i]] = dl_reduced[i];
  for (std::size_t p = 0; p < _pin_eq.size(); ++p) du[_pin_eq[p]] = _pin_du[p];
  for (std::size_t p = 0; p < _pin_eq.size(); ++p) {
    double rest = b[_pin_eq[p]];
    for (LocalIndex k = _pin_row_start[p]; k < _pin_row_start[p + 1]; ++k)
      rest -= _pin_vals[k] * du[_pin_cols[k]];
    dl[_pin_row[p]] = rest / _pin_d[p];
  }
  for (int r : _folded) {
    double cdu = C.g[r];
    for (LocalIndex k = C.row_ptr[r]; k < C.row_ptr[r + 1]; ++k) cdu += C.val[k] * du[C.col[k]];
    dl[r] = cdu / C.row_compliance(r);
  }
}

void RowElimination::restore(CsrMatrix& K) const {
  auto vals = K.values();
  for (auto it = _saved.rbegin(); it != _saved.rend(); ++it) vals[it->first] = it->second;
}

} // namespace gapfem
