// placeholder replaced by the substructure implementation
#include "elements/element_kernel.hpp"

namespace gapfem {
std::unique_ptr<ElementKernel> make_substructure_kernel(const KernelContext&) {
  throw InternalError("substructure elements are not available yet");
}
} // namespace gapfem
