// make_heat_kernel: the heat-transfer element family (DC1D2 … DC3D10).
#include "elements/heat/heat_kernel.hpp"
#include "model/model.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace gapfem {

HeatMaterial heat_material_for(const KernelContext& ctx, const Material& material) {
  HeatMaterial hm(material);
  if (material.conductivity.empty())
    throw InputError(material.loc, fmt::format("material {}", material.name),
                     fmt::format("{} elements need *CONDUCTIVITY; add it to material {}",
                                 element_info(ctx.type).name, material.name));
  if (hm.has_capacity()) return hm;
  const auto transient =
      std::find_if(ctx.model.steps.begin(), ctx.model.steps.end(),
                   [](const Step& s) { return is_thermal(s.procedure) && !s.inc.steady_state; });
  if (transient != ctx.model.steps.end())
    throw InputError(material.loc, fmt::format("material {}", material.name),
                     fmt::format("step {} is a transient {} step, which needs the heat capacity of "
                                 "material {}; add *DENSITY and *SPECIFIC HEAT to the material",
                                 transient->number, procedure_name(transient->procedure),
                                 material.name));
  return hm;
}

namespace {

template <ElementType T, Shape S, HeatGeometry G>
std::unique_ptr<ElementKernel> make(HeatMaterial m, double section) {
  return std::make_unique<HeatKernel<T, S, G>>(std::move(m), section);
}

} // namespace

std::unique_ptr<ElementKernel> make_heat_kernel(const KernelContext& ctx) {
  const Model& model = ctx.model;
  const ElementTypeInfo& info = element_info(ctx.type);
  const SourceLocation loc = model.element_location(ctx.elements.empty() ? -1 : ctx.elements[0]);
  const std::string entity = ctx.elements.empty()
                                 ? std::string{}
                                 : fmt::format("element {}", model.element_label(ctx.elements[0]));
  if (ctx.property.kind != PropertyRef::Kind::Solid || ctx.property.index < 0 ||
      ctx.property.index >= static_cast<int>(model.solid_sections.size()))
    throw InputError(
        loc, entity,
        fmt::format("{} elements need a *SOLID SECTION; assign one to their element set",
                    info.name));
  const SolidSection& sec = model.solid_sections[ctx.property.index];
  if (sec.material < 0 || sec.material >= static_cast<int>(model.materials.size()))
    throw InputError(sec.loc, sec.elset, "the *SOLID SECTION has no valid MATERIAL");
  HeatMaterial m = heat_material_for(ctx, model.materials[sec.material]);
  using T = ElementType;
  using HG = HeatGeometry;
  switch (ctx.type) {
  case T::DC1D2:
    return make<T::DC1D2, Shape::Line2, HG::Line>(std::move(m), sec.thickness);
  case T::DC2D3:
    return make<T::DC2D3, Shape::Tri3, HG::Planar>(std::move(m), sec.thickness);
  case T::DC2D4:
    return make<T::DC2D4, Shape::Quad4, HG::Planar>(std::move(m), sec.thickness);
  case T::DCAX3:
    return make<T::DCAX3, Shape::Tri3, HG::Axisymmetric>(std::move(m), 1.0);
  case T::DCAX4:
    return make<T::DCAX4, Shape::Quad4, HG::Axisymmetric>(std::move(m), 1.0);
  case T::DC3D4:
    return make<T::DC3D4, Shape::Tet4, HG::Solid>(std::move(m), 1.0);
  case T::DC3D8:
    return make<T::DC3D8, Shape::Hex8, HG::Solid>(std::move(m), 1.0);
  case T::DC3D10:
    return make<T::DC3D10, Shape::Tet10, HG::Solid>(std::move(m), 1.0);
  case T::DC3D20:
    return make<T::DC3D20, Shape::Hex20, HG::Solid>(std::move(m), 1.0);
  case T::DC3D15:
    return make<T::DC3D15, Shape::Wedge15, HG::Solid>(std::move(m), 1.0);
  case T::DC3D6:
    return make<T::DC3D6, Shape::Wedge6, HG::Solid>(std::move(m), 1.0);
  case T::DC2D8:
    return make<T::DC2D8, Shape::Quad8, HG::Planar>(std::move(m), sec.thickness);
  case T::DC2D6:
    return make<T::DC2D6, Shape::Tri6, HG::Planar>(std::move(m), sec.thickness);
  case T::DCAX8:
    return make<T::DCAX8, Shape::Quad8, HG::Axisymmetric>(std::move(m), 1.0);
  case T::DCAX6:
    return make<T::DCAX6, Shape::Tri6, HG::Axisymmetric>(std::move(m), 1.0);
  default:
    break;
  }
  throw InputError(loc, entity, fmt::format("{} is not a heat-transfer element type", info.name));
}

} // namespace gapfem
