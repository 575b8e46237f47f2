// RayleighDampingKernel: C_e = alpha M_e + beta K_e around any displacement kernel (material
// *DAMPING); docs/theory/dynamics.md, "Rayleigh damping".
#include "elements/rayleigh_damping.hpp"

#include "model/model.hpp"

#include <algorithm>
#include <array>
#include <fmt/format.h>

namespace gapfem {

RayleighDampingKernel::RayleighDampingKernel(std::unique_ptr<ElementKernel> inner, double alpha,
                                             double beta)
    : _inner(std::move(inner)), _alpha(alpha), _beta(beta) {
  if (!_inner) throw InternalError("RayleighDampingKernel: no kernel to wrap");
  if (_inner->damping_in_residual())
    throw InternalError("RayleighDampingKernel: the kernel integrates its own damping");
  if (_inner->n_dofs() > kMaxDofs)
    throw InternalError(fmt::format("RayleighDampingKernel: {} DOFs exceed the scratch of {}",
                                    _inner->n_dofs(), kMaxDofs));
  _has_damping = _beta != 0.0 || (_alpha != 0.0 && _inner->has_mass());
}

void RayleighDampingKernel::evaluate(const ElementInput& in, ElementOutput& out) const {
  if (!out.want_damping || !_has_damping) {
    _inner->evaluate(in, out);
    return;
  }
  const auto n = static_cast<std::size_t>(out.residual.size());
  const std::size_t nn = n * n;
  const bool need_mass = _alpha != 0.0 && _inner->has_mass();
  const bool need_tangent = _beta != 0.0;
  // the blocks the caller did not ask for go to scratch on the stack (zeroed as the caller would)
  std::array<double, kMaxDofs * kMaxDofs> tangent_scratch, mass_scratch;
  const std::span<double> tangent_given = out.tangent, mass_given = out.mass;
  const bool tangent_wanted = out.want_tangent, mass_wanted = out.want_mass;
  if (need_tangent && !tangent_wanted) {
    std::fill_n(tangent_scratch.begin(), nn, 0.0);
    out.tangent = std::span<double>(tangent_scratch.data(), nn);
    out.want_tangent = true;
  }
  if (need_mass && !mass_wanted) {
    std::fill_n(mass_scratch.begin(), nn, 0.0);
    out.mass = std::span<double>(mass_scratch.data(), nn);
    out.want_mass = true;
  }
  // an inner kernel with a damping block of its own (none today) fills it first
  out.want_damping = _inner->has_damping();
  _inner->evaluate(in, out);
  const std::span<double> C = out.damping;
  if (need_mass)
    for (std::size_t i = 0; i < nn; ++i) C[i] += _alpha * out.mass[i];
  if (need_tangent)
    for (std::size_t i = 0; i < nn; ++i) C[i] += _beta * out.tangent[i];
  out.want_damping = true;
  out.tangent = tangent_given;
  out.want_tangent = tangent_wanted;
  out.mass = mass_given;
  out.want_mass = mass_wanted;
}

const Material* property_material(const KernelContext& ctx) {
  const Model& m = ctx.model;
  const int i = ctx.property.index;
  int material = -1;
  switch (ctx.property.kind) {
  case PropertyRef::Kind::Solid:
    if (i >= 0 && i < static_cast<int>(m.solid_sections.size()))
      material = m.solid_sections[i].material;
    break;
  case PropertyRef::Kind::Beam:
    if (i >= 0 && i < static_cast<int>(m.beam_sections.size()))
      material = m.beam_sections[i].material;
    break;
  case PropertyRef::Kind::Shell:
    if (i >= 0 && i < static_cast<int>(m.shell_sections.size()))
      material = m.shell_sections[i].material;
    break;
  default:
    break;
  }
  if (material < 0 || material >= static_cast<int>(m.materials.size())) return nullptr;
  return &m.materials[material];
}

std::unique_ptr<ElementKernel> with_material_damping(const KernelContext& ctx,
                                                     std::unique_ptr<ElementKernel> kernel) {
  const Material* mat = property_material(ctx);
  if (!kernel || !mat || !mat->damping || !mat->damping->viscous()) return kernel;
  const auto& info = element_info(ctx.type);
  if (!info.displacement) return kernel; // heat transfer: no dynamics, nothing to damp
  if (kernel->damping_in_residual()) {
    const bool dynamic =
        std::any_of(ctx.model.steps.begin(), ctx.model.steps.end(),
                    [](const Step& s) { return s.procedure == Procedure::Dynamic; });
    if (!dynamic) return kernel; // coupled elements in heat/coupled steps: Abaqus ignores *DAMPING
    throw InputError(mat->damping->loc, fmt::format("material {}", mat->name),
                     fmt::format("Rayleigh damping (*DAMPING, ALPHA/BETA) of coupled "
                                 "temperature-displacement elements ({}) in a *DYNAMIC step is "
                                 "not supported; use the element without temperature DOFs or "
                                 "remove *DAMPING from the material",
                                 info.name));
  }
  return std::make_unique<RayleighDampingKernel>(std::move(kernel), mat->damping->alpha,
                                                 mat->damping->beta);
}

} // namespace gapfem
