#include "elements/gap/mechanical_gap.hpp"

#include "model/model.hpp"

#include <fmt/format.h>

#include <cmath>

namespace gapfem {
namespace {
constexpr std::array<std::string_view, 3> kSNames = {"S11", "S12", "S13"};
constexpr std::array<std::string_view, 3> kENames = {"E11", "E12", "E13"};

ContactStatus status_of(double v) { return static_cast<ContactStatus>(static_cast<int>(v + 0.5)); }
} // namespace

MechanicalGapKernel::MechanicalGapKernel(const KernelContext& ctx)
    : _type(ctx.type), _section(ctx.model.gap_sections.at(ctx.property.index)),
      _law(make_normal_law(_section)) {
  const bool planar = ctx.model.space != ModelSpace::ThreeD;
  _dim = planar ? 2 : 3;
  _dofs = {DofType::U1, DofType::U2};
  if (!planar) _dofs.push_back(DofType::U3);
  if (_type == ElementType::GAPUNIT) _dofs.push_back(DofType::NT);
  _per_node = static_cast<int>(_dofs.size());
  _length_scale = ctx.model.model_size();
  _base.d = _section.d;
  const Eigen::Vector3d dir(_section.direction[0], _section.direction[1], _section.direction[2]);
  switch (_type) {
  case ElementType::GAPCYL:
    _base.shape = GapShape::Cyl;
    _base.a = dir.normalized();
    break;
  case ElementType::GAPSPHER: _base.shape = GapShape::Sph; break;
  default:
    _base.shape = GapShape::Uni;
    _computed_direction = !_section.direction_given || dir.norm() == 0.0;
    if (!_computed_direction) _base.n = dir.normalized();
    break;
  }
}

GapGeometryParams MechanicalGapKernel::params_for(const ElementInput& in) const {
  GapGeometryParams p = _base;
  if (_computed_direction) {
    const Eigen::Vector3d d(in.X[1][0] - in.X[0][0], in.X[1][1] - in.X[0][1], in.X[1][2] - in.X[0][2]);
    const double len = d.norm();
    p.n = len > 0 ? Eigen::Vector3d(d / len) : Eigen::Vector3d::UnitX();
  }
  return p;
}

void MechanicalGapKernel::kinematics(const ElementInput& in, Local& L) const {
  L.params = params_for(in);
  L.u1.setZero();
  L.u2.setZero();
  for (int k = 0; k < _dim; ++k) {
    L.u1[k] = in.u[k];
    L.u2[k] = in.u[_per_node + k];
  }
  const Eigen::Vector3d X1(in.X[0][0], in.X[0][1], in.X[0][2]);
  const Eigen::Vector3d X2(in.X[1][0], in.X[1][1], in.X[1][2]);
  Eigen::Vector3d fallback(in.state[GapStateLayout::direction], in.state[GapStateLayout::direction + 1],
                           in.state[GapStateLayout::direction + 2]);
  if (fallback.squaredNorm() == 0.0) {
    // any direction normal to the axis (cylinder) or X (sphere)
    const Eigen::Vector3d a = L.params.shape == GapShape::Cyl ? L.params.a : Eigen::Vector3d::UnitZ();
    fallback = a.unitOrthogonal();
  }
  L.geom = gap_geometry(L.params, (X1 + L.u1) - (X2 + L.u2), L.u2 - L.u1, fallback, _length_scale);
}

std::string MechanicalGapKernel::validate(const ElementInput& in) const {
  const Eigen::Vector3d d(in.X[1][0] - in.X[0][0], in.X[1][1] - in.X[0][1], in.X[1][2] - in.X[0][2]);
  if (_base.shape == GapShape::Uni && _computed_direction && d.norm() <= 1e-12 * _length_scale)
    return "the two nodes coincide and *GAP gives no direction, so the contact direction cannot be "
           "computed; give the direction cosines (fields 2-4 of the *GAP data line)";
  if (_base.shape == GapShape::Cyl && _dim == 2 && std::abs(std::abs(_base.a.z()) - 1.0) > 1e-12)
    return "in a two-dimensional model a GAPCYL axis must be the z-axis (0, 0, 1)";
  if (_base.shape != GapShape::Uni && _base.d < 0) {
    Eigen::Vector3d r = -d;
    if (_base.shape == GapShape::Cyl) r -= _base.a * _base.a.dot(r);
    if (r.norm() <= 1e-12 * _length_scale)
      return fmt::format("the nodes lie on the {} of the gap with d < 0, so the gap is closed with an "
                         "undefined contact direction; offset node 1 from node 2",
                         _base.shape == GapShape::Cyl ? "same axis line" : "same centre");
  }
  return {};
}

void MechanicalGapKernel::initialize(const ElementInput& in) const {
  Local L;
  kinematics(in, L);
  in.state[GapStateLayout::status] =
      static_cast<double>(L.geom.h <= 0.0 ? ContactStatus::Closed : ContactStatus::Open);
  if (!L.geom.degenerate)
    for (int k = 0; k < 3; ++k) in.state[GapStateLayout::direction + k] = L.geom.c[k];
}

void MechanicalGapKernel::evaluate(const ElementInput& in, ElementOutput& out) const {
  Local L;
  kinematics(in, L);
  const GapGeometry& G = L.geom;
  const int nd = 2 * _per_node;
  // dg/du with g = -(h + v): node 1 gets +c, node 2 gets -c (dh/dx1 = -c).
  std::array<double, 8> dg{};
  for (int k = 0; k < _dim; ++k) {
    dg[k] = G.c[k];
    dg[_per_node + k] = -G.c[k];
  }
  const double g = -(G.h + in.interference);
  const ContactStatus previous = status_of(in.state[GapStateLayout::status]);
  ContactStatus status = previous;
  double force = 0.0, stiffness = 0.0;
  if (_law) {
    _law->force(g, force, stiffness);
    status = g > 0 ? ContactStatus::Closed : ContactStatus::Open;
  } else {
    double& lambda = in.multipliers[0];
    const double close_tol = 1e-12 * _length_scale;
    if (previous == ContactStatus::Open && g > close_tol) {
      status = ContactStatus::Closed;
    } else if (previous != ContactStatus::Open && lambda < 0.0) {
      status = ContactStatus::Open;
    }
    if (status == ContactStatus::Open) lambda = 0.0;
    if (status != previous) out.status_changes = 1;
    force = lambda;
    if (status != ContactStatus::Open) out.add_constraint(0, g, {dg.data(), static_cast<std::size_t>(nd)});
  }
  in.state[GapStateLayout::status] = static_cast<double>(status);
  if (!G.degenerate)
    for (int k = 0; k < 3; ++k) in.state[GapStateLayout::direction + k] = G.c[k];
  if (force == 0.0 && stiffness == 0.0) return;
  // residual: force * dg/du ; tangent: dF/dg dg dg^T + force d2g/du2 with d2g/du2 = -[[H,-H],[-H,H]]
  for (int i = 0; i < nd; ++i) out.residual[i] += force * dg[i];
  if (!out.want_tangent) return;
  for (int i = 0; i < nd; ++i)
    for (int j = 0; j < nd; ++j) out.tangent[i * nd + j] += stiffness * dg[i] * dg[j];
  if (_base.shape != GapShape::Uni && !G.degenerate && force != 0.0)
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        const double sign = (a == b) ? 1.0 : -1.0;
        for (int i = 0; i < _dim; ++i)
          for (int j = 0; j < _dim; ++j)
            out.tangent[(a * _per_node + i) * nd + b * _per_node + j] -= force * sign * G.H(i, j);
      }
}

void MechanicalGapKernel::recover(const ElementInput& in, ElementRecovery& out) const {
  Local L;
  kinematics(in, L);
  const GapGeometry& G = L.geom;
  GapRecord rec;
  rec.status = status_of(in.state[GapStateLayout::status]);
  rec.clearance = G.h;
  rec.area = _section.area;
  if (_law) {
    double dF = 0.0;
    _law->force(-(G.h + in.interference), rec.normal_force, dF);
  } else {
    rec.normal_force = rec.status == ContactStatus::Open ? 0.0 : in.multipliers[0];
  }
  rec.pressure = rec.normal_force / _section.area;
  Eigen::Vector3d t1, t2;
  slip_basis(G.c, t1, t2);
  for (int k = 0; k < 3; ++k) {
    rec.direction[k] = G.c[k];
    rec.t1[k] = t1[k];
    rec.t2[k] = t2[k];
  }
  OutputBlock S{ElemVar::S, kSNames, 1, {rec.pressure, rec.shear[0] / 1.0, rec.shear[1]}};
  OutputBlock E{ElemVar::E, kENames, 1, {rec.clearance, rec.slip[0], rec.slip[1]}};
  out.blocks.push_back(std::move(S));
  out.blocks.push_back(std::move(E));
  out.gap = rec;
}

std::unique_ptr<ElementKernel> make_gap_kernel(const KernelContext& ctx) {
  const auto& sec = ctx.model.gap_sections.at(ctx.property.index);
  const SourceLocation loc = ctx.model.element_location(ctx.elements.empty() ? -1 : ctx.elements[0]);
  auto unsupported = [&](const SourceLocation& where, std::string_view what) {
    throw InputError(where.empty() ? sec.loc : where, "*GAP, ELSET=" + sec.elset,
                     fmt::format("{} is not available in this build", what));
  };
  if (sec.behavior.given) unsupported(sec.behavior.loc, "*SURFACE BEHAVIOR after *GAP");
  if (sec.friction.given) unsupported(sec.friction.loc, "*FRICTION after *GAP");
  if (sec.damping.given) unsupported(sec.damping.loc, "*CONTACT DAMPING after *GAP");
  switch (ctx.type) {
  case ElementType::GAPUNI:
  case ElementType::GAPCYL:
  case ElementType::GAPSPHER: return std::make_unique<MechanicalGapKernel>(ctx);
  default:
    throw InputError(loc, std::string(element_info(ctx.type).name),
                     "thermal gap elements (GAPUNIT, DGAP) arrive with the thermal procedures");
  }
}

} // namespace gapfem
