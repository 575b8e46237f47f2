#include "elements/element_kernel.hpp"
#include "elements/heat/heat_shell.hpp"
#include "elements/rayleigh_damping.hpp"
#include "elements/structural/coupled_shell.hpp"
#include "model/model.hpp"

#include <fmt/format.h>

namespace gapfem {

std::string_view contact_status_name(ContactStatus s) {
  switch (s) {
  case ContactStatus::Open:
    return "open";
  case ContactStatus::Closed:
    return "closed";
  case ContactStatus::Stick:
    return "stick";
  case ContactStatus::Slip:
    return "slip";
  }
  return "?";
}

namespace {
std::unique_ptr<ElementKernel> make_family_kernel(const KernelContext& ctx) {
  switch (element_info(ctx.type).family) {
  case ElementFamily::Shell:
    if (!element_info(ctx.type).displacement) return make_heat_shell_kernel(ctx);  // DS3, DS4, DS8
    if (element_info(ctx.type).temperature) return make_coupled_shell_kernel(ctx); // S4RT, …
    return make_structural_kernel(ctx);
  case ElementFamily::Spring:
  case ElementFamily::Mass:
  case ElementFamily::Truss:
  case ElementFamily::Beam:
    return make_structural_kernel(ctx);
  case ElementFamily::Continuum:
    return make_continuum_kernel(ctx);
  case ElementFamily::Gap:
    return make_gap_kernel(ctx);
  case ElementFamily::HeatTransfer:
    return make_heat_kernel(ctx);
  case ElementFamily::User:
    return make_user_kernel(ctx);
  case ElementFamily::Substructure:
    return make_substructure_kernel(ctx);
  }
  throw InternalError("unknown element family");
}
} // namespace

std::unique_ptr<ElementKernel> make_element_kernel(const KernelContext& ctx) {
  // material Rayleigh damping (*DAMPING) wraps the kernels of the materials that have it
  return with_material_damping(ctx, make_family_kernel(ctx));
}

} // namespace gapfem
