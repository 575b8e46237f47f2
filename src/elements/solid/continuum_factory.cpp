// make_continuum_kernel: the continuum stress/displacement element family.
#include "elements/solid/continuum_factory.hpp"

#include "elements/solid/coupled_continuum.hpp"
#include "model/model.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace gapfem {
namespace {

SourceLocation first_location(const KernelContext& ctx) {
  return ctx.model.element_location(ctx.elements.empty() ? -1 : ctx.elements[0]);
}

std::string first_entity(const KernelContext& ctx) {
  return ctx.elements.empty() ? std::string{}
                              : fmt::format("element {}", ctx.model.element_label(ctx.elements[0]));
}

/// GRAV and CENTRIF need a density: report the first such load on an element of this block.
void check_gravity_density(const KernelContext& ctx, const Material& mat) {
  if (!mat.density.empty()) return;
  std::vector<ElemId> sorted;
  for (const Step& step : ctx.model.steps)
    for (const DistributedLoad& ld : step.dloads) {
      if (ld.kind != DistLoadKind::Gravity && ld.kind != DistLoadKind::Centrifugal) continue;
      if (sorted.empty()) {
        sorted.assign(ctx.elements.begin(), ctx.elements.end());
        std::sort(sorted.begin(), sorted.end());
      }
      if (!std::binary_search(sorted.begin(), sorted.end(), ld.elem)) continue;
      const EntityLabel label = ctx.model.element_label(ld.elem);
      throw InputError(ld.loc, fmt::format("element {}", label),
                       fmt::format("{} on element {} needs *DENSITY in material {}",
                                   ld.kind == DistLoadKind::Gravity ? "GRAV" : "CENTRIF", label,
                                   mat.name));
    }
}

} // namespace

std::unique_ptr<ElementKernel> make_continuum_kernel(const KernelContext& ctx) {
  const ElementTypeInfo& info = element_info(ctx.type);
  if (ctx.property.kind != PropertyRef::Kind::Solid || ctx.property.index < 0 ||
      ctx.property.index >= static_cast<int>(ctx.model.solid_sections.size()))
    throw InputError(
        first_location(ctx), first_entity(ctx),
        fmt::format("{} elements need a *SOLID SECTION; assign one to their element set",
                    info.name));
  const SolidSection& sec = ctx.model.solid_sections[ctx.property.index];
  if (sec.material < 0 || sec.material >= static_cast<int>(ctx.model.materials.size()))
    throw InputError(sec.loc, sec.elset, "the *SOLID SECTION has no valid MATERIAL");
  const Material& mat = ctx.model.materials[sec.material];
  if (!mat.has_elastic())
    throw InputError(
        mat.loc, mat.name,
        fmt::format("material {} is used by {} elements but has no *ELASTIC", mat.name, info.name));
  if (mat.elastic.n_values < 2)
    throw InputError(mat.loc, mat.name, "*ELASTIC needs Young's modulus and Poisson's ratio");
  for (int r = 0; r < mat.elastic.n_rows(); ++r) {
    const double E = mat.elastic.values[r * mat.elastic.n_values];
    const double nu = mat.elastic.values[r * mat.elastic.n_values + 1];
    if (!(E > 0.0) || !(nu > -1.0 && nu < 0.5))
      throw InputError(
          mat.loc, mat.name,
          fmt::format("*ELASTIC needs E > 0 and -1 < nu < 0.5 (got E = {}, nu = {})", E, nu));
  }
  check_gravity_density(ctx, mat);

  ContinuumSetup setup;
  setup.material = mat;
  setup.thickness = info.plane == PlaneKind::PlaneStress || info.plane == PlaneKind::PlaneStrain
                        ? sec.thickness
                        : 1.0;
  if (sec.controls >= 0) {
    const SectionControls& c = ctx.model.section_controls[sec.controls];
    setup.hourglass = c.hourglass;
    setup.hourglass_scale = c.scale;
  }
  setup.needs_temperature =
      !mat.expansion.empty() || mat.elastic.keys.size() > 1 || mat.density.keys.size() > 1;

  if (info.temperature) // coupled temperature-displacement types (coupled_continuum.hpp)
    if (auto k = make_coupled_continuum_kernel(ctx, setup, sec.thickness)) return k;
  if (auto k = make_continuum_3d(ctx.type, setup)) return k;
  if (auto k = make_continuum_2d(ctx.type, std::move(setup))) return k;
  throw InputError(first_location(ctx), first_entity(ctx),
                   fmt::format("{} is not a continuum stress/displacement element", info.name));
}

} // namespace gapfem
