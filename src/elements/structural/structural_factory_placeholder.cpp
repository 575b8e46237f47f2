// Placeholder until the structural element family lands: replaced by the family's real factory.
#include "elements/element_kernel.hpp"
#include "model/model.hpp"

namespace gapfem {
std::unique_ptr<ElementKernel> make_structural_kernel(const KernelContext& ctx) {
  throw InputError(ctx.model.element_location(ctx.elements.empty() ? -1 : ctx.elements[0]),
                   std::string(element_info(ctx.type).name) + " elements are not available in this build");
}
} // namespace gapfem
