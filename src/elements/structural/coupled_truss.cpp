#include "elements/structural/coupled_truss.hpp"

#include "elements/heat/heat_kernel.hpp"
#include "elements/structural/structural_common.hpp"
#include "elements/structural/structural_factory.hpp"
#include "model/model.hpp"

#include <fmt/format.h>

namespace gapfem {

using namespace structural;

namespace {
constexpr std::array<DofType, 3> kDofs2T{DofType::U1, DofType::U2, DofType::NT};
constexpr std::array<DofType, 4> kDofs3T{DofType::U1, DofType::U2, DofType::U3, DofType::NT};
constexpr std::array<std::string_view, 1> kHfl1{"HFL1"};

ElementType mechanical_type(ElementType t) {
  return t == ElementType::T2D2T ? ElementType::T2D2 : ElementType::T3D2;
}
} // namespace

CoupledTrussKernel::CoupledTrussKernel(ElementType type, const Material& material, double area,
                                       HeatMaterial heat, InitialTemperatures initial)
    : _type(type), _ndim(type == ElementType::T2D2T ? 2 : 3), _material(material), _area(area),
      _mech(mechanical_type(type), material, area), _heat(std::move(heat), area),
      _initial(std::move(initial)) {}

std::span<const DofType> CoupledTrussKernel::node_dofs(int) const {
  if (_ndim == 2) return kDofs2T;
  return kDofs3T;
}

void CoupledTrussKernel::split(const ElementInput& in, Local& l) const {
  const int npn = _ndim + 1;
  for (int a = 0; a < 2; ++a) {
    for (int i = 0; i < _ndim; ++i) {
      l.u[a * _ndim + i] = in.u[a * npn + i];
      l.u0[a * _ndim + i] = in.u_start.empty() ? l.u[a * _ndim + i] : in.u_start[a * npn + i];
    }
    l.T[a] = in.u[a * npn + _ndim];
    l.T0[a] = in.u_start.empty() ? l.T[a] : in.u_start[a * npn + _ndim];
  }
  const auto n = static_cast<std::size_t>(2 * _ndim);
  l.in = in;
  l.in.u = std::span<const double>(l.u.data(), n);
  l.in.u_start = std::span<const double>(l.u0.data(), n);
  l.in.temperature = l.T;
  l.in.temperature_start = l.T0;
  l.in.initial_temperature = _initial.of(in.block_index, l.zeros);
}

std::string CoupledTrussKernel::validate(const ElementInput& in) const {
  Local l;
  split(in, l);
  std::string msg = _mech.validate(l.in);
  return msg.empty() ? _heat.validate(in.X) : msg;
}

void CoupledTrussKernel::evaluate(const ElementInput& in, ElementOutput& out) const {
  Local l;
  split(in, l);
  const int nm = 2 * _ndim, nd = 2 * (_ndim + 1);
  const bool want_K = out.want_tangent && out.tangent.size() == static_cast<std::size_t>(nd * nd);
  std::array<double, 6> rm{};
  std::array<double, 36> Km{};
  ElementOutput mo;
  mo.residual = std::span<double>(rm.data(), nm);
  mo.tangent = want_K ? std::span<double>(Km.data(), nm * nm) : std::span<double>{};
  mo.want_tangent = want_K;
  _mech.evaluate(l.in, mo);
  for (int i = 0; i < nm; ++i) out.residual[slot(i)] += rm[i];
  if (want_K) {
    for (int i = 0; i < nm; ++i)
      for (int j = 0; j < nm; ++j) out.tangent[slot(i) * nd + slot(j)] += Km[i * nm + j];
    // Coupling: d N / d T_b = 1/2 A [E' (eps - eps_th) - E eps_th'] at the mean temperature.
    const double Tm = 0.5 * (l.T[0] + l.T[1]);
    std::array<double, 2> v{}, dv{};
    _material.elastic.evaluate(Tm, v, dv);
    const TrussKernel::Axial ax = _mech.axial(l.in);
    const double eps_th = element_thermal_strain(_material, l.in);
    const double dN_dT =
        0.5 * _area *
        (dv[0] * (ax.strain - eps_th) - v[0] * _material.thermal_strain_derivative(Tm));
    const AxialKinematics kin = axial_kinematics(_ndim, in.X, l.in.u, in.ctx && in.ctx->nlgeom);
    for (int a = 0; a < 2; ++a)
      for (int i = 0; i < _ndim; ++i) {
        const double sign = a == 0 ? -1.0 : 1.0;
        for (int b = 0; b < 2; ++b)
          out.tangent[slot(a * _ndim + i) * nd + b * (_ndim + 1) + _ndim] +=
              sign * kin.n[i] * dN_dT;
      }
    out.unsymmetric |= dN_dT != 0.0 || mo.unsymmetric;
  }
  out.unsymmetric |= _heat.add_internal(in.X, l.T, l.T0, in.ctx, layout(), out.residual,
                                        want_K ? out.tangent : std::span<double>{});
  if (out.want_damping) _heat.add_capacity_block(in.X, l.T, layout(), out.damping);
  if (out.want_mass) {
    const double half = 0.5 * table_value(_material.density, 0.5 * (l.T[0] + l.T[1])) * _area *
                        axial_reference(_ndim, in.X).L;
    const std::array<double, 2> m{half, half};
    add_nodal_mass(m, _ndim + 1, _ndim, out.mass);
  }
}

double CoupledTrussKernel::stored_heat(const ElementInput& in) const {
  Local l;
  split(in, l);
  return _heat.stored_heat(in.X, l.T, l.T0);
}

bool CoupledTrussKernel::supports_load(DistLoadKind kind, int face) const {
  // Thermal loads on the link: BF per volume and (with a reader that accepts S1/S2, F1/F2 on
  // trusses) the ends; mechanical: GRAV, BX/BY/BZ.
  return _heat.supports_load(kind, face) || _mech.supports_load(kind, face);
}

void CoupledTrussKernel::load(const ElementInput& in, const DistributedLoad& ld, double magnitude,
                              double sink, std::span<double> f_ext,
                              std::span<double> tangent) const {
  Local l;
  split(in, l);
  const int nd = 2 * (_ndim + 1);
  const bool with_K = tangent.size() == static_cast<std::size_t>(nd * nd);
  if (_heat.supports_load(ld.kind, ld.face)) {
    _heat.add_load(in.X, l.T, ld, magnitude, sink, layout(), f_ext,
                   with_K ? tangent : std::span<double>{});
    return;
  }
  const int nm = 2 * _ndim;
  std::array<double, 6> fm{};
  _mech.load(l.in, ld, magnitude, sink, std::span<double>(fm.data(), nm), {});
  for (int i = 0; i < nm; ++i) f_ext[slot(i)] += fm[i];
}

bool CoupledTrussKernel::supports_output(ElemVar var) const {
  return var == ElemVar::HFL || _mech.supports_output(var);
}

void CoupledTrussKernel::recover(const ElementInput& in, ElementRecovery& out) const {
  Local l;
  split(in, l);
  _mech.recover(l.in, out);
  OutputBlock& b = add_block(out, ElemVar::HFL, kHfl1, Heat::NQ);
  _heat.heat_flux(in.X, l.T, b.values);
}

std::unique_ptr<ElementKernel> make_coupled_truss_kernel(const KernelContext& ctx) {
  const SolidSection& sec = solid_section_of(ctx);
  const std::string entity = fmt::format("ELSET={}", sec.elset);
  if (!(sec.thickness > 0.0))
    throw InputError(sec.loc, entity,
                     fmt::format("the truss cross-section area {} is not positive; give the area "
                                 "on the data line",
                                 sec.thickness));
  const Material& mat = section_material(ctx.model, sec.material, sec.loc, entity);
  check_density_for_gravity(ctx, mat);
  return std::make_unique<CoupledTrussKernel>(
      ctx.type, mat, sec.thickness, heat_material_for(ctx, mat), block_initial_temperatures(ctx));
}

} // namespace gapfem
