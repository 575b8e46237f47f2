#include "fem/matrix_terms.hpp"

#include "model/model.hpp"

#include <cmath>

namespace gapfem {

MatrixTerms::MatrixTerms(const Model& model, const DofMap& dofs) {
  for (const MatrixTerm& t : model.matrix_terms) {
    DofType r{}, c{};
    FE_CHECK(dof_from_abaqus(t.row_dof, r) && dof_from_abaqus(t.col_dof, c),
             "matrix term DOF not checked");
    _row.push_back(dofs.slot(t.row_node, r));
    _col.push_back(dofs.slot(t.col_node, c));
    _value.push_back(t.value);
  }
}

void MatrixTerms::set_equations(const EquationMap& eqmap) {
  _eqs.resize(_value.size());
  for (std::size_t k = 0; k < _value.size(); ++k)
    _eqs[k] = {eqmap.slot_eq[_row[k]], eqmap.slot_eq[_col[k]]};
}

void MatrixTerms::assemble(std::span<const double> u, std::span<double> f_int, MatrixInserter* K,
                           const DofMap& dofs, std::array<double, kNumFields>& flux_sum,
                           std::array<long, kNumFields>& flux_count) const {
  for (std::size_t k = 0; k < _value.size(); ++k) {
    const double f = _value[k] * u[_col[k]];
    f_int[_row[k]] += f;
    if (f != 0.0) {
      const int fld = static_cast<int>(dofs.slot_field(_row[k]));
      flux_sum[fld] += std::abs(f);
      ++flux_count[fld];
    }
    if (K && _eqs[k][0] >= 0 && _eqs[k][1] >= 0)
      K->add(0, {&_eqs[k][0], 1}, {&_eqs[k][1], 1}, {&_value[k], 1});
  }
}

void MatrixTerms::add_diagonal(std::span<double> diag) const {
  for (std::size_t k = 0; k < _value.size(); ++k)
    if (_row[k] == _col[k]) diag[_row[k]] += std::abs(_value[k]);
}

} // namespace gapfem
