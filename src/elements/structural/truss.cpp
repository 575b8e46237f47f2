#include "elements/structural/truss.hpp"

#include "elements/reference_scale.hpp"
#include "elements/structural/structural_common.hpp"
#include "elements/structural/structural_factory.hpp"
#include "model/model.hpp"

#include <cmath>
#include <fmt/format.h>

namespace gapfem {

using namespace structural;

namespace {
constexpr std::array<DofType, 3> kTrussDofs{DofType::U1, DofType::U2, DofType::U3};

bool nlgeom_of(const ElementInput& in) {
  return in.ctx != nullptr && in.ctx->nlgeom;
}
} // namespace

TrussKernel::TrussKernel(ElementType type, Material material, double area)
    : _type(type), _material(std::move(material)), _area(area),
      _ndim(type == ElementType::T2D2 ? 2 : 3) {
  FE_CHECK(type == ElementType::T2D2 || type == ElementType::T3D2, "TrussKernel: not a truss type");
}

std::span<const DofType> TrussKernel::node_dofs(int) const {
  return {kTrussDofs.data(), static_cast<std::size_t>(_ndim)};
}

bool TrussKernel::uses_temperature_field() const {
  return material_uses_temperature(_material);
}

std::string TrussKernel::validate(const ElementInput& in) const {
  Vec3 b = in.X[1]; // (the length without overflow: reference_scale.hpp)
  if (_ndim == 2) b[2] = in.X[0][2];
  if (!(point_distance(in.X[0], b) > 1e-12 * (in.ctx ? in.ctx->model_size : 1.0)))
    return _ndim == 2 ? "the two nodes of this truss coincide in the x-y plane, so it has no "
                        "length; check the node coordinates"
                      : "the two nodes of this truss coincide, so it has no length; check the node "
                        "coordinates";
  return {};
}

TrussKernel::Axial TrussKernel::axial(const ElementInput& in) const {
  const bool nlgeom = nlgeom_of(in);
  const AxialKinematics kin = axial_kinematics(_ndim, in.X, in.u, nlgeom);
  double E = 0.0, nu = 0.0;
  elastic_at(_material, average(in.temperature), E, nu);
  const double eps_th = element_thermal_strain(_material, in);
  Axial a;
  if (nlgeom) {
    if (!(kin.l > 0.0))
      throw ConvergenceFailure(
          fmt::format("truss element {} was compressed to zero length", in.label));
    a.strain = std::log(kin.l / kin.L);
    a.dN_dl = E * _area / kin.l;
  } else {
    a.strain = kin.delta / kin.L;
    a.dN_dl = E * _area / kin.L;
  }
  a.stress = E * (a.strain - eps_th);
  a.force = a.stress * _area;
  return a;
}

void TrussKernel::evaluate(const ElementInput& in, ElementOutput& out) const {
  const bool nlgeom = nlgeom_of(in);
  const Axial a = axial(in);
  axial_assemble(axial_kinematics(_ndim, in.X, in.u, nlgeom), nlgeom, a.force, a.dN_dl, out);
  if (out.want_mass) {
    const double half = 0.5 * table_value(_material.density, average(in.temperature)) * _area *
                        axial_reference(_ndim, in.X).L;
    const std::array<double, 2> m{half, half};
    add_nodal_mass(m, _ndim, _ndim, out.mass);
  }
}

bool TrussKernel::stress_stiffness(const ElementInput& in, std::span<const double> du,
                                   std::span<double> K) const {
  const AxialKinematics kin = axial_kinematics(_ndim, in.X, in.u, true);
  if (!(kin.l > 0.0)) return false;
  double E = 0.0, nu = 0.0;
  elastic_at(_material, average(in.temperature), E, nu);
  axial_stress_stiffness(kin, E * _area / kin.l * axial_stretch(kin, du), K);
  return true;
}

bool TrussKernel::supports_load(DistLoadKind kind, int face) const {
  return face == 0 && (kind == DistLoadKind::Gravity || kind == DistLoadKind::BodyForce);
}

void TrussKernel::load(const ElementInput& in, const DistributedLoad& load, double magnitude,
                       double, std::span<double> f_ext, std::span<double>) const {
  // Dead load on the reference configuration: force per reference length q, total q L, half to
  // each node. The mass (rho A L) is conserved with NLGEOM, so the load does not depend on u.
  const double L = axial_reference(_ndim, in.X).L;
  const double per_length =
      line_load_intensity(_material, _area, load, magnitude, average(in.temperature), in.label);
  for (int a = 0; a < 2; ++a)
    for (int i = 0; i < _ndim; ++i)
      f_ext[a * _ndim + i] += 0.5 * per_length * L * load.direction[i];
}

bool TrussKernel::supports_output(ElemVar var) const {
  return var == ElemVar::S || var == ElemVar::E || var == ElemVar::SF;
}

void TrussKernel::recover(const ElementInput& in, ElementRecovery& out) const {
  const Axial a = axial(in);
  add_block(out, ElemVar::S, kS11, 1).values[0] = a.stress;
  add_block(out, ElemVar::E, kE11, 1).values[0] = a.strain;
  add_block(out, ElemVar::SF, kSF1, 1).values[0] = a.force;
}

std::unique_ptr<ElementKernel> make_truss_kernel(const KernelContext& ctx) {
  const Model& model = ctx.model;
  const SolidSection& sec = solid_section_of(ctx);
  const std::string entity = fmt::format("ELSET={}", sec.elset);
  if (!(sec.thickness > 0.0))
    throw InputError(sec.loc, entity,
                     fmt::format("the truss cross-section area {} is not positive; give the area "
                                 "on the data line",
                                 sec.thickness));
  const Material& mat = section_material(model, sec.material, sec.loc, entity);
  check_density_for_gravity(ctx, mat);
  return std::make_unique<TrussKernel>(ctx.type, mat, sec.thickness);
}

} // namespace gapfem
