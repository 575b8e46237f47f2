#include "elements/user/matrix_kernel.hpp"

#include <algorithm>

namespace gapfem {

MatrixKernel::MatrixKernel(ElementType type, NodeDofTable dofs, std::vector<double> K,
                           bool unsymmetric, std::vector<double> M)
    : _type(type), _dofs(std::move(dofs)), _K(std::move(K)), _M(std::move(M)),
      _unsymmetric(unsymmetric) {
  const auto n = static_cast<std::size_t>(_dofs.n_dofs());
  FE_CHECK(_K.size() == n * n, "MatrixKernel: matrix size does not match the DOFs");
  FE_CHECK(_M.empty() || _M.size() == n * n, "MatrixKernel: mass size does not match the DOFs");
}

void MatrixKernel::internal_force(std::span<const double> u, std::span<double> f) const {
  const auto n = static_cast<std::size_t>(_dofs.n_dofs());
  for (std::size_t i = 0; i < n; ++i) {
    const double* row = _K.data() + i * n;
    double s = 0.0;
    for (std::size_t j = 0; j < n; ++j) s += row[j] * u[j];
    f[i] = s;
  }
}

void MatrixKernel::evaluate(const ElementInput& in, ElementOutput& out) const {
  internal_force(in.u, out.residual);
  if (out.want_tangent) std::copy(_K.begin(), _K.end(), out.tangent.begin());
  if (out.want_mass && !_M.empty()) std::copy(_M.begin(), _M.end(), out.mass.begin());
  out.unsymmetric = _unsymmetric;
}

void MatrixKernel::recover(const ElementInput& in, ElementRecovery& out) const {
  std::vector<double> f(in.u.size());
  internal_force(in.u, f);
  add_nodal_forces(_dofs, f, out);
}

} // namespace gapfem
