// Point inertias MASS and ROTARYI (point_inertia.hpp).
#include "elements/structural/point_inertia.hpp"

#include "model/model.hpp"

#include <fmt/format.h>

namespace gapfem {

PointInertiaKernel::PointInertiaKernel(ElementType type, const MassSection& section,
                                       ModelSpace space)
    : _type(type), _alpha(section.alpha) {
  const bool planar = space != ModelSpace::ThreeD;
  if (type == ElementType::MASS) {
    _n = planar ? 2 : 3;
    for (int i = 0; i < _n; ++i) {
      _dofs[i] = static_cast<DofType>(i);
      _M[i * _n + i] = section.mass;
    }
    return;
  }
  const auto& I = section.inertia; // I11, I22, I33, I12, I13, I23
  if (planar) {
    _n = 1;
    _dofs[0] = DofType::UR3;
    _M[0] = I[2];
    return;
  }
  _n = 3;
  _dofs = {DofType::UR1, DofType::UR2, DofType::UR3};
  _M = {I[0], I[3], I[4], I[3], I[1], I[5], I[4], I[5], I[2]};
}

void PointInertiaKernel::evaluate(const ElementInput&, ElementOutput& out) const {
  // no stiffness: residual and tangent stay zero; the inertia (and ALPHA's damping) forces come
  // from the mass (damping) block
  if (out.want_mass)
    for (int i = 0; i < _n * _n; ++i) out.mass[i] += _M[i];
  if (out.want_damping)
    for (int i = 0; i < _n * _n; ++i) out.damping[i] += _alpha * _M[i];
}

void PointInertiaKernel::load(const ElementInput&, const DistributedLoad& load, double magnitude,
                              double, std::span<double> f_ext, std::span<double>) const {
  // GRAV: m g along the load's direction
  for (int i = 0; i < _n; ++i) f_ext[i] += _M[i * _n + i] * magnitude * load.direction[i];
}

std::unique_ptr<ElementKernel> make_point_inertia_kernel(const KernelContext& ctx) {
  const Model& model = ctx.model;
  const ElemId e = ctx.elements.empty() ? -1 : ctx.elements[0];
  const bool rotary = ctx.type == ElementType::ROTARYI;
  const char* keyword = rotary ? "*ROTARY INERTIA" : "*MASS";
  const auto& list = model.mass_sections;
  if (ctx.property.kind != PropertyRef::Kind::Mass || ctx.property.index < 0 ||
      ctx.property.index >= static_cast<int>(list.size()))
    throw InputError(model.element_location(e),
                     e >= 0 ? fmt::format("element {}", model.element_label(e)) : "",
                     fmt::format("{} elements need a {}; add {}, ELSET=... for the element set "
                                 "that contains them",
                                 element_info(ctx.type).name, keyword, keyword));
  const MassSection& sec = list[ctx.property.index];
  if (sec.rotary != rotary)
    throw InputError(sec.loc, fmt::format("ELSET={}", sec.elset),
                     fmt::format("{} elements take {}, not {}; give the element set its own "
                                 "keyword",
                                 element_info(ctx.type).name, keyword,
                                 rotary ? "*MASS" : "*ROTARY INERTIA"));
  return std::make_unique<PointInertiaKernel>(ctx.type, sec, model.space);
}

} // namespace gapfem
