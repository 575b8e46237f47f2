#include "elements/gap/mechanical_gap.hpp"

#include "elements/gap/gap_response.hpp"
#include "elements/reference_scale.hpp"
#include "model/model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>
#include <string_view>
#include <unordered_map>

namespace gapfem {
namespace {
constexpr std::array<std::string_view, 3> kSNames = {"S11", "S12", "S13"};
constexpr std::array<std::string_view, 3> kENames = {"E11", "E12", "E13"};
constexpr std::array<std::string_view, 1> kHflNames = {"HFL1"};

ContactStatus status_of(double v) {
  return static_cast<ContactStatus>(static_cast<int>(v + 0.5));
}
bool closed(ContactStatus s) {
  return s != ContactStatus::Open;
}

/// Diameter (largest node distance) of an element, from its reference coordinates.
double element_diameter(const Model& m, ElemId e) {
  const auto nodes = m.mesh.element_nodes(e);
  double d = 0.0;
  for (std::size_t a = 0; a < nodes.size(); ++a)
    for (std::size_t b = a + 1; b < nodes.size(); ++b) {
      const Vec3& x = m.mesh.coords[nodes[a]];
      const Vec3& y = m.mesh.coords[nodes[b]];
      d = std::max(d, std::sqrt((x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
                                (x[2] - y[2]) * (x[2] - y[2])));
    }
  return d;
}
} // namespace

MechanicalGapKernel::MechanicalGapKernel(const KernelContext& ctx)
    : _type(ctx.type), _section(ctx.model.gap_sections.at(ctx.property.index)),
      _law(make_normal_law(_section)) {
  const Model& model = ctx.model;
  const bool planar = model.space != ModelSpace::ThreeD;
  _dim = planar ? 2 : 3;
  _dofs = {DofType::U1, DofType::U2};
  if (!planar) _dofs.push_back(DofType::U3);
  if (_type == ElementType::GAPUNIT) _dofs.push_back(DofType::NT);
  _per_node = static_cast<int>(_dofs.size());
  _length_scale = model.model_size();
  _base.d = _section.d;
  const Eigen::Vector3d dir(_section.direction[0], _section.direction[1], _section.direction[2]);
  switch (_type) {
  case ElementType::GAPCYL:
    _base.shape = GapShape::Cyl;
    _base.a = dir.normalized();
    break;
  case ElementType::GAPSPHER:
    _base.shape = GapShape::Sph;
    break;
  default:
    _base.shape = GapShape::Uni;
    _computed_direction = !_section.direction_given || dir.norm() == 0.0;
    if (!_computed_direction) _base.n = dir.normalized();
    break;
  }
  if (_type == ElementType::GAPUNIT) _thermal.emplace(_section, model.constants);
  // Normal behaviour.
  const SurfaceBehavior& b = _section.behavior;
  _no_separation = b.given && b.no_separation;
  if (_law) {
    _mode = NormalMode::Force;
    _compliant_rows = ctx.options.penalty_rows;
  } else if (b.given && b.method == ContactMethod::AugmentedLagrange) {
    _mode = NormalMode::Augmented;
    _augmented_k = b.penalty_stiffness * _section.area;
  }
  _slip_rows = ctx.options.friction_rows;
  // Friction laws: the section's, then every *CHANGE FRICTION that touches this block.
  std::unordered_map<ElemId, LocalIndex> index;
  for (std::size_t i = 0; i < ctx.elements.size(); ++i)
    index[ctx.elements[i]] = static_cast<LocalIndex>(i);
  _friction_schedule.assign(ctx.elements.size(), {});
  if (_section.friction.given) {
    _section_friction = 0;
    _friction.emplace_back(_section.friction, _section.area);
  }
  for (int s = 0; s < static_cast<int>(model.steps.size()); ++s)
    for (const FrictionChange& fc : model.steps[s].friction_changes) {
      int law = -1;
      for (ElemId e : fc.elements) {
        auto it = index.find(e);
        if (it == index.end()) continue;
        if (law < 0) {
          law = static_cast<int>(_friction.size());
          _friction.emplace_back(fc.friction, _section.area);
        }
        _friction_schedule[it->second].emplace_back(s, law);
      }
    }
  // Line search for elastic-slip friction on rotating gaps only: on a fixed direction the stick
  // predictor's step lands exactly on the stick solution (the stick branch is linear), on a
  // curved gap its large k_s e force would also rotate the contact frame (step_limit()).
  if (_base.shape != GapShape::Uni)
    for (const FrictionLaw& f : _friction) _penalty_friction |= !f.lagrange();
  // Characteristic length per element: mean diameter of the non-gap elements at its nodes, else
  // the distance between its nodes, else 1e-3 of the model size. A substructure spans a whole
  // part, so its diameter says nothing of the mesh at the node: it does not count.
  _lc.assign(ctx.elements.size(), 0.0);
  std::unordered_map<NodeId, std::vector<ElemId>> attached;
  for (ElemId e : ctx.elements)
    for (NodeId n : model.mesh.element_nodes(e)) attached[n];
  for (ElemId e = 0; e < model.mesh.n_elements(); ++e) {
    const ElementFamily family = element_info(model.mesh.elem_types[e]).family;
    if (family == ElementFamily::Gap || family == ElementFamily::Substructure) continue;
    for (NodeId n : model.mesh.element_nodes(e)) {
      auto it = attached.find(n);
      if (it != attached.end()) it->second.push_back(e);
    }
  }
  for (std::size_t i = 0; i < ctx.elements.size(); ++i) {
    double sum = 0.0;
    int count = 0;
    for (NodeId n : model.mesh.element_nodes(ctx.elements[i]))
      for (ElemId e : attached[n]) {
        const double d = element_diameter(model, e);
        if (d > 0) {
          sum += d;
          ++count;
        }
      }
    double lc = count > 0 ? sum / count : element_diameter(model, ctx.elements[i]);
    if (!(lc > 0)) lc = 1e-3 * _length_scale;
    _lc[i] = lc;
  }
}

GapGeometryParams MechanicalGapKernel::params_for(const ElementInput& in) const {
  GapGeometryParams p = _base;
  if (_computed_direction) {
    const Eigen::Vector3d d(in.X[1][0] - in.X[0][0], in.X[1][1] - in.X[0][1],
                            in.X[1][2] - in.X[0][2]);
    const double len = d.norm();
    p.n = len > 0 ? Eigen::Vector3d(d / len) : Eigen::Vector3d::UnitX();
  }
  return p;
}

GapGeometry MechanicalGapKernel::geometry(const ElementInput& in, std::span<const double> u,
                                          std::span<const double> state) const {
  const GapGeometryParams p = params_for(in);
  Eigen::Vector3d u1 = Eigen::Vector3d::Zero(), u2 = Eigen::Vector3d::Zero();
  for (int k = 0; k < _dim; ++k) {
    u1[k] = u[k];
    u2[k] = u[_per_node + k];
  }
  const Eigen::Vector3d X1(in.X[0][0], in.X[0][1], in.X[0][2]);
  const Eigen::Vector3d X2(in.X[1][0], in.X[1][1], in.X[1][2]);
  Eigen::Vector3d fallback(state[GapStateLayout::direction], state[GapStateLayout::direction + 1],
                           state[GapStateLayout::direction + 2]);
  if (fallback.squaredNorm() == 0.0)
    fallback = (p.shape == GapShape::Cyl ? p.a : Eigen::Vector3d::UnitZ()).unitOrthogonal();
  return gap_geometry(p, (X1 + u1) - (X2 + u2), u2 - u1, fallback, _length_scale);
}

const FrictionLaw* MechanicalGapKernel::friction_for(const ElementInput& in) const {
  int law = _section_friction;
  const int step = in.ctx ? in.ctx->step_index : 0;
  for (const auto& [s, l] : _friction_schedule[in.block_index])
    if (s <= step) law = l;
  return law >= 0 ? &_friction[law] : nullptr;
}

double MechanicalGapKernel::augmented_stiffness(const ElementInput& in) const {
  if (_augmented_k > 0) return _augmented_k;
  return kAugmentedAutomaticFactor * in.stiffness_hint;
}

std::string MechanicalGapKernel::validate(const ElementInput& in) const {
  const Eigen::Vector3d d(in.X[1][0] - in.X[0][0], in.X[1][1] - in.X[0][1],
                          in.X[1][2] - in.X[0][2]);
  // (lengths by hypot, reference_scale.hpp: nodes 1e300 apart do not coincide)
  if (_base.shape == GapShape::Uni && _computed_direction &&
      point_distance(in.X[0], in.X[1]) <= 1e-12 * _length_scale)
    return "the two nodes coincide and *GAP gives no direction, so the contact direction cannot be "
           "computed; give the direction cosines (fields 2-4 of the *GAP data line)";
  if (_base.shape == GapShape::Cyl && _dim == 2 && std::abs(std::abs(_base.a.z()) - 1.0) > 1e-12)
    return "in a two-dimensional model a GAPCYL axis must be the z-axis (0, 0, 1)";
  if (_base.shape != GapShape::Uni && _base.d < 0) {
    Eigen::Vector3d r = -d;
    if (_base.shape == GapShape::Cyl) r -= _base.a * _base.a.dot(r);
    if (std::hypot(r.x(), r.y(), r.z()) <= 1e-12 * _length_scale)
      return _base.shape == GapShape::Cyl
                 ? "its first node lies on the axis line through its second node and d < 0, so "
                   "the gap starts closed with no contact direction; move the first node off "
                   "that axis or give a positive d"
                 : "its two nodes coincide and d < 0, so the gap starts closed with no contact "
                   "direction; move one node away from the other or give a positive d";
  }
  return {};
}

void MechanicalGapKernel::initialize(const ElementInput& in) const {
  const GapGeometry G = geometry(in, in.u, in.state);
  in.state[GapStateLayout::status] =
      static_cast<double>(G.h <= 0.0 ? ContactStatus::Closed : ContactStatus::Open);
  if (!G.degenerate)
    for (int k = 0; k < 3; ++k) in.state[GapStateLayout::direction + k] = G.c[k];
}

void MechanicalGapKernel::evaluate(const ElementInput& in, ElementOutput& out) const {
  Response R;
  respond(in, in.state, in.multipliers, &out, R);
}

double MechanicalGapKernel::step_limit(const ElementInput& in, std::span<const double> du) const {
  // An elastic-slip gap slipping along m whose correction would carry its elastic slip past the
  // far side of the stick band: stop where the slip along m reaches zero. The slip is linear in
  // the displacements (the basis is frozen over the increment), so the fraction is exact.
  const auto& st = in.state;
  if (status_of(st[GapStateLayout::status]) != ContactStatus::Slip) return 1.0;
  const FrictionLaw* fl = friction_for(in);
  const Eigen::Vector2d m(st[GapStateLayout::slip_dir], st[GapStateLayout::slip_dir + 1]);
  if (!fl || fl->lagrange() || m.squaredNorm() == 0.0) return 1.0;
  Response R;
  Local L;
  setup(in, st, R, L);
  Eigen::Vector2d de = Eigen::Vector2d::Zero();
  for (int a = 0; a < 2; ++a)
    for (int i = 0; i < L.nd; ++i) de[a] += L.ds[a][i] * du[i];
  const double gamma = fl->elastic_slip(_lc[in.block_index]);
  const double em = (R.slip - L.plastic_start).dot(m), dm = de.dot(m);
  if (em <= 0.0 || dm >= 0.0 || em + dm >= -gamma) return 1.0;
  return em / -dm;
}

bool MechanicalGapKernel::augment(const ElementInput& in) const {
  if (_mode != NormalMode::Augmented) return false;
  Response R;
  std::array<double, GapStateLayout::size> st{};
  std::copy(in.state.begin(), in.state.end(), st.begin());
  std::array<double, 3> mult{in.multipliers[0], in.multipliers[1], in.multipliers[2]};
  respond(in, st, mult, nullptr, R);
  double& lambda = in.state[GapStateLayout::lambda_aug];
  double* previous = &in.state[GapStateLayout::aug_previous]; // lambda, g, valid
  if (!closed(R.status)) {
    // Uzawa update max(lambda^ + K g, 0) of an open gap: it forgets its multiplier, so it
    // re-engages at zero clearance rather than at the clearance lambda^/K
    previous[2] = 0.0;
    if (lambda == 0.0) return false;
    lambda = 0.0;
    return true;
  }
  // The constraint must be met to the tolerance in both senses: a penetration (g > 0), and a
  // positive clearance (g < 0) at which the gap still carries the force lambda^ + K g > 0 because
  // its multiplier is left over from a heavier load (unloading): that force must go, and the gap
  // opens or re-settles at g = 0.
  const double tolerance = 1e-3 * _lc[in.block_index];
  if (std::abs(R.g) <= tolerance) {
    previous[2] = 0.0; // the committed state never carries a stale secant
    return false;
  }
  // Uzawa: lambda^ <- lambda^ + K g (= F_N). It contracts the error only by k_s/(k_s + K), k_s the
  // stiffness of the structure at the gap, which is slow for a soft penalty. From the second
  // augmentation of the increment on, the secant of (lambda^, g) over the last two augmentations
  // estimates dg/dlambda^ = -1/(k_s + K) and the update lambda^ - g / (dg/dlambda^) reaches g = 0
  // (exactly for a gap whose neighbours do not change). It is used only while it points the same
  // way as Uzawa, reaches further, and the overclosure decreases.
  double next = R.normal_force;
  if (previous[2] == 1.0) {
    const double dlambda = lambda - previous[0];
    const double dg = R.g - previous[1];
    if (dlambda != 0.0 && std::abs(R.g) < std::abs(previous[1])) {
      const double slope = dg / dlambda; // < 0 for a stable gap
      if (slope < 0.0) {
        const double secant = lambda - R.g / slope;
        const double uzawa_step = next - lambda, secant_step = secant - lambda;
        if (secant_step * uzawa_step > 0.0 && std::abs(secant_step) > std::abs(uzawa_step))
          next = secant;
      }
    }
  }
  previous[0] = lambda;
  previous[1] = R.g;
  previous[2] = 1.0;
  lambda = _no_separation ? next : std::max(next, 0.0);
  return true;
}

void MechanicalGapKernel::recover(const ElementInput& in, ElementRecovery& out) const {
  Response R;
  std::array<double, GapStateLayout::size> st{};
  std::copy(in.state.begin(), in.state.end(), st.begin());
  std::array<double, 3> mult{in.multipliers[0], in.multipliers[1], in.multipliers[2]};
  respond(in, st, mult, nullptr, R);
  GapRecord rec;
  rec.status = status_of(in.state[GapStateLayout::status]); // as decided by the last evaluation
  rec.clearance = R.geom.h;
  rec.area = _section.area;
  rec.normal_force = closed(rec.status) || _mode == NormalMode::Force ? R.normal_force : 0.0;
  // damping acts on the motion of the increment: report the value stored when it converged
  rec.damping_force = in.state[GapStateLayout::damping];
  rec.pressure = rec.normal_force / _section.area;
  for (int a = 0; a < 2; ++a) {
    rec.slip[a] = R.slip[a];
    rec.friction_force[a] = closed(rec.status) ? R.friction[a] : 0.0;
    rec.shear[a] = rec.friction_force[a] / _section.area;
  }
  rec.dissipation = in.state[GapStateLayout::dissipation];
  rec.damping_work = in.state[GapStateLayout::damping_work];
  for (int k = 0; k < 3; ++k) {
    rec.direction[k] = R.geom.c[k];
    rec.t1[k] = R.t1[k];
    rec.t2[k] = R.t2[k];
  }
  if (_thermal) {
    rec.thermal = true;
    rec.heat_flux = R.heat.q;
    rec.heat_flow = R.heat.q * _section.area;
    rec.conductance = R.heat.conductance;
    out.blocks.push_back(OutputBlock{ElemVar::HFL, kHflNames, 1, {R.heat.q}});
  }
  out.blocks.push_back(
      OutputBlock{ElemVar::S, kSNames, 1, {rec.pressure, rec.shear[0], rec.shear[1]}});
  out.blocks.push_back(
      OutputBlock{ElemVar::E, kENames, 1, {rec.clearance, rec.slip[0], rec.slip[1]}});
  out.gap = rec;
}

std::unique_ptr<ElementKernel> make_gap_kernel(const KernelContext& ctx) {
  switch (ctx.type) {
  case ElementType::GAPUNI:
  case ElementType::GAPCYL:
  case ElementType::GAPSPHER:
  case ElementType::GAPUNIT:
    return std::make_unique<MechanicalGapKernel>(ctx);
  case ElementType::DGAP:
    return std::make_unique<DgapKernel>(ctx);
  default:
    throw InternalError("not a gap element type");
  }
}

} // namespace gapfem
