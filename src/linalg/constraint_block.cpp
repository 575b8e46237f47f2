#include "linalg/constraint_block.hpp"

namespace gapfem {

bool ConstraintBlock::add_row(std::span<const LocalIndex> eqs, std::span<const double> coeff,
                              double value, std::int64_t multiplier_index,
                              std::span<const double> column, double row_compliance) {
  const auto start = col.size();
  if (!column.empty() && dval.size() < val.size()) dval = val; // rows so far: D = C^T
  for (std::size_t k = 0; k < eqs.size(); ++k)
    if (eqs[k] >= 0 && (coeff[k] != 0.0 || (!column.empty() && column[k] != 0.0))) {
      col.push_back(eqs[k]);
      val.push_back(coeff[k]);
      if (!column.empty())
        dval.push_back(column[k]);
      else if (!dval.empty())
        dval.push_back(coeff[k]);
    }
  if (col.size() == start) return false;
  row_ptr.push_back(static_cast<LocalIndex>(col.size()));
  g.push_back(value);
  compliance.push_back(row_compliance);
  multiplier.push_back(multiplier_index);
  return true;
}

bool ConstraintBlock::has_compliance() const {
  for (double e : compliance)
    if (e != 0.0) return true;
  return false;
}

void ConstraintBlock::multiply(std::span<const double> x, std::span<double> y) const {
  for (int r = 0; r < n_rows(); ++r) {
    double s = 0.0;
    for (LocalIndex k = row_ptr[r]; k < row_ptr[r + 1]; ++k) s += val[k] * x[col[k]];
    y[r] = s;
  }
}

void ConstraintBlock::add_transpose_multiply(std::span<const double> y, double alpha,
                                             std::span<double> x) const {
  for (int r = 0; r < n_rows(); ++r) {
    const double a = alpha * y[r];
    if (a == 0.0) continue;
    for (LocalIndex k = row_ptr[r]; k < row_ptr[r + 1]; ++k) x[col[k]] += val[k] * a;
  }
}

void ConstraintBlock::add_column_multiply(std::span<const double> y, double alpha,
                                          std::span<double> x) const {
  const auto& d = dval.empty() ? val : dval;
  for (int r = 0; r < n_rows(); ++r) {
    const double a = alpha * y[r];
    if (a == 0.0) continue;
    for (LocalIndex k = row_ptr[r]; k < row_ptr[r + 1]; ++k) x[col[k]] += d[k] * a;
  }
}

} // namespace gapfem
