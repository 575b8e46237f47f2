#include "elements/structural/structural_common.hpp"

#include <fmt/format.h>
#include <limits>

namespace gapfem::structural {

namespace {
/// Key below every table row: PropertyTable::evaluate returns the first row for it.
constexpr double kFirstRow = -std::numeric_limits<double>::infinity();
} // namespace

double table_value(const PropertyTable& table, std::optional<double> T) {
  return table.value(T.value_or(kFirstRow));
}

void elastic_at(const Material& material, std::optional<double> T, double& E, double& nu) {
  material.elastic_at(T.value_or(kFirstRow), E, nu);
}

double element_thermal_strain(const Material& material, const ElementInput& in) {
  if (material.expansion.empty() || in.temperature.empty()) return 0.0;
  const double T = *average(in.temperature);
  const double Ti = in.initial_temperature.empty() ? T : *average(in.initial_temperature);
  return material.thermal_strain(T, Ti);
}

bool material_uses_temperature(const Material& material) {
  return !material.expansion.empty() || material.elastic.n_rows() > 1 ||
         material.density.n_rows() > 1;
}

double line_load_intensity(const Material& material, double area, const DistributedLoad& load,
                           double magnitude, std::optional<double> T, const EntityLabel& label) {
  switch (load.kind) {
  case DistLoadKind::Gravity:
    if (material.density.empty())
      throw InputError(load.loc, fmt::format("element {}", label),
                       fmt::format("GRAV needs the mass density of material {}; add *DENSITY to "
                                   "the material",
                                   material.name));
    return table_value(material.density, T) * area * magnitude;
  case DistLoadKind::BodyForce:
    return magnitude * area;
  default:
    break;
  }
  throw InternalError("line_load_intensity: unsupported load kind");
}

AxialKinematics axial_reference(int ndim, std::span<const Vec3> X) {
  AxialKinematics k;
  k.ndim = ndim;
  Vec3 d = sub(X[1], X[0]);
  if (ndim == 2) d[2] = 0.0;
  k.L = norm(d);
  k.l = k.L;
  if (k.L > 0.0) k.n = scale(1.0 / k.L, d);
  return k;
}

AxialKinematics axial_kinematics(int ndim, std::span<const Vec3> X, std::span<const double> u,
                                 bool nlgeom) {
  AxialKinematics k = axial_reference(ndim, X);
  Vec3 du{};
  for (int i = 0; i < ndim; ++i) du[i] = u[ndim + i] - u[i];
  if (!nlgeom) {
    k.delta = dot(k.n, du);
    k.l = k.L + k.delta;
    return k;
  }
  Vec3 d = sub(X[1], X[0]);
  if (ndim == 2) d[2] = 0.0;
  for (int i = 0; i < ndim; ++i) d[i] += du[i];
  k.l = norm(d);
  k.delta = k.l - k.L;
  // A member compressed to zero length has no direction; keep the reference one (the residual is
  // still finite and the Newton update will move it away from the singular point).
  if (k.l > 0.0) k.n = scale(1.0 / k.l, d);
  return k;
}

void axial_assemble(const AxialKinematics& kin, bool nlgeom, double N, double dN_dl,
                    ElementOutput& out) {
  const int nd = kin.ndim;
  const int n = 2 * nd;
  for (int i = 0; i < nd; ++i) {
    out.residual[i] += -N * kin.n[i];
    out.residual[nd + i] += N * kin.n[i];
  }
  if (!out.want_tangent) return;
  const double geo = (nlgeom && kin.l > 0.0) ? N / kin.l : 0.0;
  for (int i = 0; i < nd; ++i)
    for (int j = 0; j < nd; ++j) {
      const double kij =
          dN_dl * kin.n[i] * kin.n[j] + geo * ((i == j ? 1.0 : 0.0) - kin.n[i] * kin.n[j]);
      out.tangent[i * n + j] += kij;
      out.tangent[i * n + nd + j] -= kij;
      out.tangent[(nd + i) * n + j] -= kij;
      out.tangent[(nd + i) * n + nd + j] += kij;
    }
}

void axial_stress_stiffness(const AxialKinematics& kin, double dN, std::span<double> K) {
  const int nd = kin.ndim, n = 2 * nd;
  const double geo = dN / kin.l;
  for (int i = 0; i < nd; ++i)
    for (int j = 0; j < nd; ++j) {
      const double kij = geo * ((i == j ? 1.0 : 0.0) - kin.n[i] * kin.n[j]);
      K[i * n + j] += kij;
      K[i * n + nd + j] -= kij;
      K[(nd + i) * n + j] -= kij;
      K[(nd + i) * n + nd + j] += kij;
    }
}

double axial_stretch(const AxialKinematics& kin, std::span<const double> du) {
  double dl = 0.0;
  for (int i = 0; i < kin.ndim; ++i) dl += kin.n[i] * (du[kin.ndim + i] - du[i]);
  return dl;
}

OutputBlock& add_block(ElementRecovery& out, ElemVar var, std::span<const std::string_view> names,
                       int n_points) {
  OutputBlock& b = out.blocks.emplace_back();
  b.var = var;
  b.names = names;
  b.n_points = n_points;
  b.values.assign(static_cast<std::size_t>(n_points) * names.size(), 0.0);
  return b;
}

} // namespace gapfem::structural
