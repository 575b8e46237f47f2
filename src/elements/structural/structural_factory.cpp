// make_structural_kernel: springs, trusses, beams and shells.
#include "elements/structural/structural_factory.hpp"

#include "elements/structural/beam.hpp"
#include "elements/structural/coupled_truss.hpp"
#include "elements/structural/point_inertia.hpp"
#include "elements/structural/shell.hpp"
#include "elements/structural/spring.hpp"
#include "elements/structural/truss.hpp"
#include "model/model.hpp"

#include <fmt/format.h>
#include <vector>

namespace gapfem {

namespace structural {

namespace {
ElemId first_element(const KernelContext& ctx) {
  return ctx.elements.empty() ? -1 : ctx.elements[0];
}

std::string element_entity(const KernelContext& ctx) {
  const ElemId e = first_element(ctx);
  return e >= 0 ? fmt::format("element {}", ctx.model.element_label(e)) : std::string{};
}

[[noreturn]] void missing_property(const KernelContext& ctx, std::string_view keyword) {
  throw InputError(ctx.model.element_location(first_element(ctx)), element_entity(ctx),
                   fmt::format("{} elements need a {} property; add {}, ELSET=... for the element "
                               "set that contains them",
                               element_info(ctx.type).name, keyword, keyword));
}
} // namespace

const SolidSection& solid_section_of(const KernelContext& ctx) {
  const auto& list = ctx.model.solid_sections;
  if (ctx.property.kind != PropertyRef::Kind::Solid || ctx.property.index < 0 ||
      ctx.property.index >= static_cast<int>(list.size()))
    missing_property(ctx, "*SOLID SECTION");
  return list[ctx.property.index];
}

const BeamSection& beam_section_of(const KernelContext& ctx) {
  const auto& list = ctx.model.beam_sections;
  if (ctx.property.kind != PropertyRef::Kind::Beam || ctx.property.index < 0 ||
      ctx.property.index >= static_cast<int>(list.size()))
    missing_property(ctx, "*BEAM SECTION");
  return list[ctx.property.index];
}

const Material& section_material(const Model& model, int material, const SourceLocation& loc,
                                 const std::string& entity) {
  if (material < 0 || material >= static_cast<int>(model.materials.size()))
    throw InputError(loc, entity,
                     "the section names no known material; give MATERIAL=<name> of a "
                     "*MATERIAL defined in the deck");
  const Material& m = model.materials[material];
  if (!m.has_elastic())
    throw InputError(m.loc, fmt::format("NAME={}", m.name),
                     "the material has no *ELASTIC data, which this element needs; add *ELASTIC "
                     "with Young's modulus and Poisson's ratio");
  return m;
}

void check_density_for_gravity(const KernelContext& ctx, const Material& material) {
  if (!material.density.empty() || ctx.elements.empty()) return;
  std::vector<bool> in_block(static_cast<std::size_t>(ctx.model.mesh.n_elements()), false);
  for (ElemId e : ctx.elements) in_block[e] = true;
  for (const Step& step : ctx.model.steps)
    for (const DistributedLoad& load : step.dloads)
      if (load.kind == DistLoadKind::Gravity && load.elem >= 0 &&
          load.elem < static_cast<ElemId>(in_block.size()) && in_block[load.elem])
        throw InputError(load.loc, fmt::format("element {}", ctx.model.element_label(load.elem)),
                         fmt::format("GRAV needs the mass density of material {}; add *DENSITY to "
                                     "the material",
                                     material.name));
}

} // namespace structural

std::unique_ptr<ElementKernel> make_structural_kernel(const KernelContext& ctx) {
  switch (ctx.type) {
  case ElementType::SPRING1:
  case ElementType::SPRING2:
  case ElementType::SPRINGA:
  case ElementType::DASHPOT1:
  case ElementType::DASHPOT2:
  case ElementType::DASHPOTA:
    return make_spring_kernel(ctx);
  case ElementType::T2D2:
  case ElementType::T3D2:
    return make_truss_kernel(ctx);
  case ElementType::B31:
  case ElementType::B32:
  case ElementType::B32R:
  case ElementType::B21:
  case ElementType::B22:
  case ElementType::PIPE31:
  case ElementType::PIPE32:
    return make_beam_kernel(ctx);
  case ElementType::S3:
  case ElementType::S3R:
  case ElementType::S4:
  case ElementType::S4R:
  case ElementType::S8R:
  case ElementType::S8:
    return make_shell_kernel(ctx);
  case ElementType::T2D2T:
  case ElementType::T3D2T:
    return make_coupled_truss_kernel(ctx);
  case ElementType::MASS:
  case ElementType::ROTARYI:
    return make_point_inertia_kernel(ctx);
  default:
    break;
  }
  const ElemId e = ctx.elements.empty() ? -1 : ctx.elements[0];
  const std::string_view name = element_info(ctx.type).name;
  throw InputError(ctx.model.element_location(e),
                   fmt::format("{} is not a spring, truss, beam or shell element type", name));
}

} // namespace gapfem
