#include "model/model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gapfem {

std::string_view procedure_name(Procedure p) {
  switch (p) {
  case Procedure::Static:
    return "STATIC";
  case Procedure::HeatTransfer:
    return "HEAT TRANSFER";
  case Procedure::CoupledTempDisp:
    return "COUPLED TEMPERATURE-DISPLACEMENT";
  case Procedure::SubstructureGenerate:
    return "SUBSTRUCTURE GENERATE";
  case Procedure::Dynamic:
    return "DYNAMIC";
  case Procedure::Frequency:
    return "FREQUENCY";
  case Procedure::ResponseSpectrum:
    return "RESPONSE SPECTRUM";
  case Procedure::Buckle:
    return "BUCKLE";
  case Procedure::SteadyStateDynamics:
    return "STEADY STATE DYNAMICS";
  case Procedure::ModalDynamic:
    return "MODAL DYNAMIC";
  }
  return "?";
}

double ModalDamping::fraction(int k, double omega) const {
  if (by_frequency) { // linear between the points, the end values outside (Abaqus)
    const double f = omega / (2.0 * 3.14159265358979323846);
    if (ranges.empty()) return 0.0;
    if (f <= ranges.front().frequency) return ranges.front().zeta;
    for (std::size_t i = 1; i < ranges.size(); ++i)
      if (f <= ranges[i].frequency) {
        const Range& a = ranges[i - 1];
        const Range& b = ranges[i];
        return a.zeta + (b.zeta - a.zeta) * (f - a.frequency) / (b.frequency - a.frequency);
      }
    return ranges.back().zeta;
  }
  for (auto it = ranges.rbegin(); it != ranges.rend(); ++it) { // a later line overrides
    const Range& r = *it;
    if (k >= r.first && k <= r.last) {
      if (kind == Kind::Fraction) return r.zeta;
      return (omega > 0.0 ? r.alpha / (2.0 * omega) : 0.0) + r.beta * omega / 2.0;
    }
  }
  return 0.0;
}

SourceLocation Model::element_location(ElemId e) const {
  SourceLocation loc;
  if (e < 0 || e >= mesh.n_elements()) return loc;
  const SourceRef ref = mesh.elem_src[e];
  if (ref.file >= 0 && ref.file < static_cast<int>(source_files.size()))
    loc.file = source_files[ref.file];
  loc.line = ref.line;
  loc.keyword = "*ELEMENT";
  return loc;
}

bool on_cylinder_axis(const NodeTransform& t, const Vec3& X) {
  if (t.type != NodeTransform::Type::Cylindrical) return false;
  Vec3 e3{t.b[0] - t.a[0], t.b[1] - t.a[1], t.b[2] - t.a[2]};
  const Vec3 r{X[0] - t.a[0], X[1] - t.a[1], X[2] - t.a[2]};
  const double l3 = std::sqrt(e3[0] * e3[0] + e3[1] * e3[1] + e3[2] * e3[2]);
  if (!(l3 > 0)) return false;
  const double axial = (r[0] * e3[0] + r[1] * e3[1] + r[2] * e3[2]) / l3;
  double rr = 0.0, n2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double d = r[i] - axial * e3[i] / l3;
    rr += d * d;
    n2 += r[i] * r[i];
  }
  return !(std::sqrt(rr) > 1e-12 * std::max(1.0, std::sqrt(n2)));
}

std::string EntityLabel::str() const {
  const int i = instance();
  if (i <= 0 || !instances || i > static_cast<int>(instances->size())) return std::to_string(key);
  return (*instances)[static_cast<std::size_t>(i - 1)] + "." + std::to_string(local());
}

std::optional<std::array<double, 9>> local_axes(const NodeTransform& t, const Vec3& X) {
  auto norm = [](const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); };
  auto cross = [](const Vec3& a, const Vec3& b) {
    return Vec3{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  Vec3 e1, e3;
  if (t.type == NodeTransform::Type::Rectangular) {
    e1 = t.a;
    e3 = cross(t.a, t.b);
  } else {
    e3 = {t.b[0] - t.a[0], t.b[1] - t.a[1], t.b[2] - t.a[2]};
    const double l3 = norm(e3);
    if (!(l3 > 0)) return std::nullopt;
    for (double& v : e3) v /= l3;
    const Vec3 r{X[0] - t.a[0], X[1] - t.a[1], X[2] - t.a[2]};
    const double axial = r[0] * e3[0] + r[1] * e3[1] + r[2] * e3[2];
    e1 = {r[0] - axial * e3[0], r[1] - axial * e3[1], r[2] - axial * e3[2]};
    if (!(norm(e1) > 1e-12 * std::max(1.0, norm(r)))) {
      // on the axis: any direction normal to it (the global axis least aligned with e3, made
      // normal); the reader allows only uses that do not depend on the choice
      int k = 0;
      for (int i = 1; i < 3; ++i)
        if (std::abs(e3[i]) < std::abs(e3[k])) k = i;
      Vec3 g{};
      g[k] = 1.0;
      e1 = {g[0] - e3[k] * e3[0], g[1] - e3[k] * e3[1], g[2] - e3[k] * e3[2]};
    }
  }
  const double l1 = norm(e1), l3 = norm(e3);
  if (!(l1 > 0) || !(l3 > 0)) return std::nullopt;
  for (double& v : e1) v /= l1;
  for (double& v : e3) v /= l3;
  const Vec3 e2 = cross(e3, e1);
  return std::array<double, 9>{e1[0], e1[1], e1[2], e2[0], e2[1], e2[2], e3[0], e3[1], e3[2]};
}

double Model::model_size() const {
  if (mesh.coords.empty()) return 1.0;
  Vec3 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
          std::numeric_limits<double>::max()};
  Vec3 hi{-lo[0], -lo[1], -lo[2]};
  for (const auto& x : mesh.coords)
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], x[i]);
      hi[i] = std::max(hi[i], x[i]);
    }
  // the diagonal without overflow: hypot, on halves where a span itself overflows (1e308 apart)
  double d = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  if (!std::isfinite(d))
    d = std::min(2.0 * std::hypot(0.5 * hi[0] - 0.5 * lo[0], 0.5 * hi[1] - 0.5 * lo[1],
                                  0.5 * hi[2] - 0.5 * lo[2]),
                 std::numeric_limits<double>::max());
  return d > 0 && std::isfinite(d) ? d : 1.0;
}

} // namespace gapfem

namespace gapfem {

std::string_view Model::element_type_name(ElemId e) const {
  const ElementType t = mesh.elem_types[static_cast<std::size_t>(e)];
  const std::int32_t v = mesh.variant(e);
  if (t == ElementType::USER && v >= 0 && v < static_cast<std::int32_t>(user_elements.size()))
    return user_elements[static_cast<std::size_t>(v)].name;
  if (t == ElementType::SUBSTRUCTURE && v >= 0 &&
      v < static_cast<std::int32_t>(substructures.size()))
    return substructures[static_cast<std::size_t>(v)].name;
  return element_info(t).name;
}

Model::ElementFields Model::element_fields(ElemId e) const {
  const ElementType t = mesh.elem_types[static_cast<std::size_t>(e)];
  const std::int32_t v = mesh.variant(e);
  ElementFields f{element_info(t).displacement, element_info(t).temperature};
  if (t == ElementType::USER && v >= 0 && v < static_cast<std::int32_t>(user_elements.size()))
    for (const auto& node : user_elements[static_cast<std::size_t>(v)].node_dofs)
      for (int d : node) (d <= 6 ? f.displacement : f.temperature) = true;
  if (t == ElementType::SUBSTRUCTURE && v >= 0 &&
      v < static_cast<std::int32_t>(substructures.size()))
    for (const auto& node : substructures[static_cast<std::size_t>(v)].node_dofs)
      for (int d : node) (d <= 6 ? f.displacement : f.temperature) = true;
  return f;
}

} // namespace gapfem
