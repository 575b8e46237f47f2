#include "elements/gap/gap_thermal.hpp"

#include "model/model.hpp"

#include <array>

namespace gapfem {
namespace {
constexpr std::array<std::string_view, 1> kHflNames = {"HFL1"};
} // namespace

GapThermalModel::GapThermalModel(const GapSection& s, const PhysicalConstants& constants) {
  if (s.conductance.given) _conductance.emplace(s.conductance);
  if (s.conductance_pressure.given) _conductance_closed.emplace(s.conductance_pressure);
  if (s.radiation.given) _radiation.emplace(s.radiation, constants);
  if (s.heat_generation.given) _heat.emplace(s.heat_generation);
}

GapThermalModel::Flux GapThermalModel::flux(double Ta, double Tb, double h, double p,
                                            bool closed) const {
  Flux f;
  const GapConductanceLaw* law = (_conductance_closed && closed) ? &*_conductance_closed
                                 : _conductance                  ? &*_conductance
                                                                 : nullptr;
  if (law) {
    const bool by_pressure = law->pressure_dependent();
    const GapFluxValue c = law->conduction(Ta, Tb, by_pressure ? p : h);
    f.q += c.q;
    f.dq_dTa += c.dq_dTa;
    f.dq_dTb += c.dq_dTb;
    (by_pressure ? f.dq_dp : f.dq_dh) += c.dq_dx;
    f.conductance = law->evaluate(by_pressure ? p : h, 0.5 * (Ta + Tb)).k;
  }
  if (_radiation) {
    const GapFluxValue r = _radiation->evaluate(Ta, Tb, h);
    f.q += r.q;
    f.dq_dTa += r.dq_dTa;
    f.dq_dTb += r.dq_dTb;
    f.dq_dh += r.dq_dx;
  }
  return f;
}

DgapKernel::DgapKernel(const KernelContext& ctx)
    : _section(ctx.model.gap_sections.at(ctx.property.index)),
      _thermal(_section, ctx.model.constants) {}

void DgapKernel::evaluate(const ElementInput& in, ElementOutput& out) const {
  // h = d: no displacements in a heat-transfer analysis; the contact pressure is zero.
  const double A = _section.area;
  const GapThermalModel::Flux f =
      _thermal.flux(in.u[0], in.u[1], _section.d, 0.0, _section.d <= 0.0);
  out.residual[0] += A * f.q;
  out.residual[1] -= A * f.q;
  if (out.want_tangent) {
    out.tangent[0] += A * f.dq_dTa;
    out.tangent[1] += A * f.dq_dTb;
    out.tangent[2] -= A * f.dq_dTa;
    out.tangent[3] -= A * f.dq_dTb;
  }
  out.unsymmetric = f.dq_dTa != -f.dq_dTb;
}

void DgapKernel::recover(const ElementInput& in, ElementRecovery& out) const {
  const GapThermalModel::Flux f =
      _thermal.flux(in.u[0], in.u[1], _section.d, 0.0, _section.d <= 0.0);
  GapRecord rec;
  rec.status = _section.d > 0 ? ContactStatus::Open : ContactStatus::Closed;
  rec.clearance = _section.d;
  rec.area = _section.area;
  rec.thermal = true;
  rec.heat_flux = f.q;
  rec.heat_flow = f.q * _section.area;
  rec.conductance = f.conductance;
  out.blocks.push_back(OutputBlock{ElemVar::HFL, kHflNames, 1, {f.q}});
  out.gap = rec;
}

} // namespace gapfem
