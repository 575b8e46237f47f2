// Substructure (Zn) elements: the reduced stiffness (and, when generated with MASS MATRIX=YES, the
// reduced mass) of the substructure's library, turned into the global directions of its usage by
// *SUBSTRUCTURE PROPERTY: K = T K_gen T^T (M likewise) with T the rotation R on each node's
// translations and det(R) R on its rotations (rotations are axial vectors, so a reflection flips
// them once more). Linear, as Abaqus's substructures without large rotations.
#include "elements/user/matrix_kernel.hpp"
#include "model/model.hpp"

#include <fmt/format.h>

namespace gapfem {

std::unique_ptr<ElementKernel> make_substructure_kernel(const KernelContext& ctx) {
  const Model& model = ctx.model;
  FE_CHECK(ctx.variant >= 0 && ctx.variant < static_cast<int>(model.substructures.size()),
           "substructure block without its type");
  const SubstructureType& t = model.substructures[static_cast<std::size_t>(ctx.variant)];
  const ElemId first = ctx.elements.empty() ? -1 : ctx.elements[0];
  if (ctx.property.kind != PropertyRef::Kind::Substructure)
    throw InputError(model.element_location(first),
                     fmt::format("element {} ({})", model.element_label(first), t.name),
                     "a substructure element needs *SUBSTRUCTURE PROPERTY for its element set");
  const SubstructureProperty& p = model.substructure_properties[ctx.property.index];
  const std::array<double, 9>& R = p.rotation;
  const double det = R[0] * (R[4] * R[8] - R[5] * R[7]) - R[1] * (R[3] * R[8] - R[5] * R[6]) +
                     R[2] * (R[3] * R[7] - R[4] * R[6]);
  const auto n = static_cast<std::size_t>(t.n_dofs());
  if (R == std::array<double, 9>{1, 0, 0, 0, 1, 0, 0, 0, 1})
    return std::make_unique<MatrixKernel>(ElementType::SUBSTRUCTURE, NodeDofTable(t.node_dofs),
                                          t.stiffness, false, t.mass);
  // T: the generation DOFs in the usage directions, block diagonal over the nodes (at most three
  // entries per row: kept sparse, so K = T K_gen T^T costs O(n^2))
  struct Entry {
    std::size_t col;
    double value;
  };
  std::vector<std::vector<Entry>> T(n);
  std::size_t k = 0;
  for (const auto& dofs : t.node_dofs) {
    for (std::size_t i = 0; i < dofs.size(); ++i) {
      const int d = dofs[i];
      if (d > 6) { // temperatures: scalars
        T[k + i].push_back({k + i, 1.0});
        continue;
      }
      const int group = (d - 1) / 3, row = (d - 1) % 3;
      const double sign = group == 1 ? det : 1.0;
      for (std::size_t j = 0; j < dofs.size(); ++j) {
        const int e = dofs[j];
        if (e > 6 || (e - 1) / 3 != group) continue;
        T[k + i].push_back({k + j, sign * R[row * 3 + (e - 1) % 3]});
      }
    }
    k += dofs.size();
  }
  auto turned = [&](const std::vector<double>& A) { // T A T^T
    if (A.empty()) return std::vector<double>{};
    std::vector<double> TA(n * n, 0.0), B(n * n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
      for (const Entry& a : T[i])
        for (std::size_t j = 0; j < n; ++j) TA[i * n + j] += a.value * A[a.col * n + j];
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) {
        double v = 0.0;
        for (const Entry& b : T[j]) v += TA[i * n + b.col] * b.value;
        B[i * n + j] = v;
      }
    return B;
  };
  return std::make_unique<MatrixKernel>(ElementType::SUBSTRUCTURE, NodeDofTable(t.node_dofs),
                                        turned(t.stiffness), false, turned(t.mass));
}

} // namespace gapfem
