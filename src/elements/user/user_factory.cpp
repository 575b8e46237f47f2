// Kernels of the deck's own element types: user elements (LINEAR: a constant matrix; otherwise the
// user's subroutine) and substructures.
#include "elements/user/matrix_kernel.hpp"
#include "elements/user/uel_kernel.hpp"
#include "model/model.hpp"

#include <fmt/format.h>

namespace gapfem {

std::unique_ptr<ElementKernel> make_user_kernel(const KernelContext& ctx) {
  const Model& model = ctx.model;
  FE_CHECK(ctx.variant >= 0 && ctx.variant < static_cast<int>(model.user_elements.size()),
           "user element block without its type");
  const UserElementType& t = model.user_elements[static_cast<std::size_t>(ctx.variant)];
  if (t.linear)
    return std::make_unique<MatrixKernel>(ElementType::USER, NodeDofTable(t.node_dofs), t.stiffness,
                                          t.unsymmetric, t.mass);
  const UelProperty* props = nullptr;
  if (ctx.property.kind == PropertyRef::Kind::User && ctx.property.index >= 0)
    props = &model.uel_properties[static_cast<std::size_t>(ctx.property.index)];
  return make_uel_kernel(model, t, props);
}

} // namespace gapfem
