#include "elements/gap/mechanical_gap.hpp"

#include "model/model.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <unordered_map>

namespace gapfem {
namespace {
constexpr std::array<std::string_view, 3> kSNames = {"S11", "S12", "S13"};
constexpr std::array<std::string_view, 3> kENames = {"E11", "E12", "E13"};
constexpr std::array<std::string_view, 1> kHflNames = {"HFL1"};
constexpr int kMaxDofs = 8;
using VecN = Eigen::Matrix<double, kMaxDofs, 1>;

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

/// Everything one evaluation computes (for the residual, the output record and augmentation).
struct MechanicalGapKernel::Response {
  GapGeometry geom;
  Eigen::Vector3d t1, t2;
  ContactStatus status = ContactStatus::Open;
  double g = 0.0;             ///< overclosure -(h + v)
  double normal_force = 0.0;  ///< contact force (compression > 0)
  double damping_force = 0.0; ///< normal damping force (compression > 0)
  Eigen::Vector2d slip = Eigen::Vector2d::Zero();
  Eigen::Vector2d friction = Eigen::Vector2d::Zero();
  Eigen::Vector2d tangential_damping = Eigen::Vector2d::Zero();
  double dissipation = 0.0;
  GapThermalModel::Flux heat; ///< GAPUNIT conduction/radiation
  double heat_rate = 0.0;     ///< frictional heating rate eta * dissipation / dt
};

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
  } else if (b.given && b.method == ContactMethod::AugmentedLagrange) {
    _mode = NormalMode::Augmented;
    _augmented_k = b.penalty_stiffness * _section.area;
  }
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
  // Characteristic length per element: mean diameter of the non-gap elements at its nodes, else
  // the distance between its nodes, else 1e-3 of the model size.
  _lc.assign(ctx.elements.size(), 0.0);
  std::unordered_map<NodeId, std::vector<ElemId>> attached;
  for (ElemId e : ctx.elements)
    for (NodeId n : model.mesh.element_nodes(e)) attached[n];
  for (ElemId e = 0; e < model.mesh.n_elements(); ++e) {
    if (element_info(model.mesh.elem_types[e]).family == ElementFamily::Gap) continue;
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
  if (_base.shape == GapShape::Uni && _computed_direction && d.norm() <= 1e-12 * _length_scale)
    return "the two nodes coincide and *GAP gives no direction, so the contact direction cannot be "
           "computed; give the direction cosines (fields 2-4 of the *GAP data line)";
  if (_base.shape == GapShape::Cyl && _dim == 2 && std::abs(std::abs(_base.a.z()) - 1.0) > 1e-12)
    return "in a two-dimensional model a GAPCYL axis must be the z-axis (0, 0, 1)";
  if (_base.shape != GapShape::Uni && _base.d < 0) {
    Eigen::Vector3d r = -d;
    if (_base.shape == GapShape::Cyl) r -= _base.a * _base.a.dot(r);
    if (r.norm() <= 1e-12 * _length_scale)
      return fmt::format(
          "the nodes lie on the {} of the gap with d < 0, so the gap is closed with an "
          "undefined contact direction; offset node 1 from node 2",
          _base.shape == GapShape::Cyl ? "same axis line" : "same centre");
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

void MechanicalGapKernel::respond(const ElementInput& in, std::span<double> st,
                                  std::span<double> mult, ElementOutput* out, Response& R) const {
  const int nd = 2 * _per_node;
  const auto& s0 = in.state_start;
  R.geom = geometry(in, in.u, st);
  const GapGeometry& G = R.geom;
  // Slip basis frozen over the increment: from the closure direction at its start.
  Eigen::Vector3d c0(s0[GapStateLayout::direction], s0[GapStateLayout::direction + 1],
                     s0[GapStateLayout::direction + 2]);
  if (c0.squaredNorm() == 0.0) c0 = G.c;
  slip_basis(c0, R.t1, R.t2);
  VecN dg = VecN::Zero(), ds1 = VecN::Zero(), ds2 = VecN::Zero();
  Eigen::Vector2d dslip = Eigen::Vector2d::Zero();
  for (int k = 0; k < _dim; ++k) {
    dg[k] = G.c[k];
    dg[_per_node + k] = -G.c[k];
    ds1[k] = R.t1[k];
    ds1[_per_node + k] = -R.t1[k];
    ds2[k] = R.t2[k];
    ds2[_per_node + k] = -R.t2[k];
    const double du_rel =
        (in.u[k] - in.u_start[k]) - (in.u[_per_node + k] - in.u_start[_per_node + k]);
    dslip[0] += R.t1[k] * du_rel;
    dslip[1] += R.t2[k] * du_rel;
  }
  // Can the solver enforce a row with these coefficients (does it touch a free DOF)?
  auto enforceable = [&](const VecN& row) {
    if (in.free.empty()) return true;
    for (int i = 0; i < nd; ++i)
      if (in.free[i] && row[i] != 0.0) return true;
    return false;
  };
  const Eigen::Vector2d slip_start(s0[GapStateLayout::slip], s0[GapStateLayout::slip + 1]);
  const Eigen::Vector2d plastic_start(s0[GapStateLayout::plastic], s0[GapStateLayout::plastic + 1]);
  R.slip = slip_start + dslip;
  R.g = -(G.h + in.interference);
  const ContactStatus previous = status_of(st[GapStateLayout::status]);
  const bool was_closed = closed(previous);
  const bool update = out != nullptr;
  const double hint = in.stiffness_hint;
  const double dt = in.ctx ? in.ctx->dt : 0.0;

  // ---------------------------------------------------------------- normal behaviour
  double FN = 0.0, dFN_dg = 0.0;
  bool lagrange_normal = false, is_closed = false;
  switch (_mode) {
  case NormalMode::Direct: {
    double lambda = mult[0];
    is_closed = was_closed;
    if (!enforceable(dg)) {
      // both ends prescribed: the geometry alone decides, the force is not determined
      is_closed = R.g > 1e-12 * _length_scale || (_no_separation && was_closed);
      lambda = 0.0;
    } else if (!was_closed && R.g > 1e-12 * _length_scale) {
      is_closed = true;
    } else if (was_closed && lambda < 0.0 && !_no_separation) {
      is_closed = false;
    }
    if (!is_closed) lambda = 0.0;
    if (update) mult[0] = lambda;
    FN = lambda;
    lagrange_normal = is_closed;
    break;
  }
  case NormalMode::Force: {
    if (_no_separation && was_closed && R.g < 0) {
      _law->force(-R.g, hint, FN, dFN_dg); // bilateral once closed: mirrored law
      FN = -FN;
    } else {
      _law->force(R.g, hint, FN, dFN_dg);
    }
    is_closed = FN > 0 || (_no_separation && was_closed);
    break;
  }
  case NormalMode::Augmented: {
    const double k = augmented_stiffness(in);
    const double trial = st[GapStateLayout::lambda_aug] + k * R.g;
    if (trial > 0 || (_no_separation && was_closed)) {
      FN = trial;
      dFN_dg = k;
      is_closed = true;
    }
    break;
  }
  }
  R.normal_force = FN;
  ContactStatus status = is_closed ? ContactStatus::Closed : ContactStatus::Open;

  // ---------------------------------------------------------------- friction
  const FrictionLaw* fl = is_closed ? friction_for(in) : nullptr;
  // An open gap carries no friction, and one that closes starts from none (its friction
  // multipliers are not left over from an earlier contact).
  if (update && (!is_closed || !was_closed)) mult[1] = mult[2] = 0.0;
  Eigen::Vector2d plastic = is_closed ? plastic_start : R.slip; // open: the stick point follows
  Eigen::Matrix2d dtau_ds = Eigen::Matrix2d::Zero();
  Eigen::Vector2d dtau_dN = Eigen::Vector2d::Zero();
  const int iT1 = _per_node - 1, iT2 = 2 * _per_node - 1; // GAPUNIT temperature DOFs
  const double temperature = _thermal ? 0.5 * (in.u[iT1] + in.u[iT2])
                             : in.temperature.empty()
                                 ? 0.0
                                 : 0.5 * (in.temperature[0] + in.temperature[1]);
  // d(dissipation of the increment)/d(elastic slip) and /d(normal force), for frictional heating
  Eigen::Vector2d dD_de = Eigen::Vector2d::Zero();
  double dD_dN = 0.0;
  bool friction_rows = false;
  bool predicted_stick = false; // penalty friction: stick predicted after a slip reversal
  if (fl) {
    const double FNc = std::max(FN, 0.0);
    if (fl->lagrange()) {
      // Exact stick with two multipliers; slip with the critical force along the slip direction,
      // mu at the slip rate of the increment |dslip| / dt (stick: rate 0).
      double dcrit = 0.0, dcrit_drate = 0.0;
      const double rate = dt > 0 ? dslip.norm() / dt : 0.0;
      const double crit = fl->critical_force(FNc, rate, temperature, &dcrit, &dcrit_drate);
      const double crit0 =
          rate > 0 ? fl->critical_force(FNc, 0.0, temperature) : crit; // static, for breaking stick
      const Eigen::Vector2d e = R.slip - plastic_start;
      Eigen::Vector2d m(st[GapStateLayout::slip_dir], st[GapStateLayout::slip_dir + 1]);
      const bool was_slip = previous == ContactStatus::Slip;
      bool slipping = was_slip;
      const double slip_tol = 1e-12 * _length_scale;
      if (fl->rough()) {
        slipping = false;
      } else if (!enforceable(ds1) && !enforceable(ds2)) {
        // the tangential motion is prescribed: any relative motion is slip
        slipping = e.norm() > slip_tol;
        if (slipping) m = e / e.norm();
      } else if (!was_closed && e.norm() > slip_tol) {
        // Closing in this iteration after moving tangentially since the start of the increment:
        // a stick row would pull the gap back to where it was (its stick point) with a friction
        // force that zero normal force cannot hold, and the normal force then turns to tension
        // and reopens it. Start slipping along the motion instead; the next iteration sticks if
        // the slip reverses (the converged state is the same: stick or slip is decided by the
        // conditions below).
        slipping = true;
        m = e / e.norm();
      } else if (!was_slip) {
        const Eigen::Vector2d lt(mult[1], mult[2]);
        if (lt.norm() > crit0 * (1.0 + 1e-9) + 1e-300 && previous == ContactStatus::Stick) {
          slipping = true;
          m = lt / lt.norm();
        }
      } else if (e.norm() > slip_tol) {
        if (e.dot(m) < 0)
          slipping = false; // slip reversed: stick again
        else
          m = e / e.norm();
      }
      if (!slipping) {
        status = ContactStatus::Stick;
        friction_rows = true;
        R.friction = Eigen::Vector2d(mult[1], mult[2]);
        if (out) {
          out->add_constraint(1, e[0], {ds1.data(), static_cast<std::size_t>(nd)});
          out->add_constraint(2, e[1], {ds2.data(), static_cast<std::size_t>(nd)});
        }
      } else {
        status = ContactStatus::Slip;
        if (m.squaredNorm() == 0.0) m = Eigen::Vector2d(1.0, 0.0);
        R.friction = crit * m;
        dtau_dN = dcrit * m;
        const double en = e.norm();
        if (en > 1e-12 * _length_scale && e.dot(m) > 0)
          dtau_ds = (crit / en) * (Eigen::Matrix2d::Identity() - m * m.transpose());
        const double dn = dslip.norm();
        if (dt > 0 && dn > 0 && dcrit_drate != 0.0)
          dtau_ds += m * (dcrit_drate / dt) * (dslip / dn).transpose();
        plastic = R.slip;
        R.dissipation = R.friction.dot(plastic - plastic_start);
        dD_de = R.friction; // D = crit |e| along m
        dD_dN = e.norm() * dcrit;
        if (update) {
          mult[1] = R.friction[0];
          mult[2] = R.friction[1];
        }
      }
      if (update) {
        st[GapStateLayout::slip_dir] = m[0];
        st[GapStateLayout::slip_dir + 1] = m[1];
      }
    } else {
      // stick predictor: the slip direction of the previous iteration, if it slipped
      const Eigen::Vector2d m_prev(st[GapStateLayout::slip_dir], st[GapStateLayout::slip_dir + 1]);
      const bool was_slip = previous == ContactStatus::Slip && m_prev.squaredNorm() > 0.0;
      const FrictionResponse fr =
          fl->penalty(R.slip, dslip, plastic_start, FNc, dt, temperature,
                      fl->elastic_slip(_lc[in.block_index]), was_slip ? &m_prev : nullptr);
      R.friction = fr.force;
      dtau_ds = fr.dforce_dslip;
      dtau_dN = fr.dforce_dnormal;
      plastic = fr.plastic_slip;
      R.dissipation = fr.dissipation;
      predicted_stick = fr.predicted_stick;
      if (FNc > 0) status = fr.slipping ? ContactStatus::Slip : ContactStatus::Stick;
      if (FNc <= 0.0 && lagrange_normal) {
        // Closed at zero force (a gap that closes in this iteration, or starts closed unloaded):
        // friction has no stiffness yet, and a tangential motion held only by friction would be
        // singular. The tangent (not the force) takes the attached elements' stiffness, so the
        // first step does not slide the gap freely; the next iteration has the normal force.
        dtau_ds = std::max(hint, 0.0) * Eigen::Matrix2d::Identity();
      }
      if (update) {
        const Eigen::Vector2d m =
            fr.slipping ? Eigen::Vector2d(fr.force.normalized()) : Eigen::Vector2d::Zero();
        st[GapStateLayout::slip_dir] = m[0];
        st[GapStateLayout::slip_dir + 1] = m[1];
      }
      if (fr.slipping) {
        // D = crit (|e| - gamma) with e the trial elastic slip
        const double gamma = fl->elastic_slip(_lc[in.block_index]);
        double dcrit = 0.0;
        fl->critical_force(FNc, dt > 0 ? dslip.norm() / dt : 0.0, temperature, &dcrit);
        dD_de = fr.force;
        dD_dN = ((R.slip - plastic_start).norm() - gamma) * dcrit;
      }
    }
    if (FN <= 0.0) dtau_dN.setZero();
  }

  // ---------------------------------------------------------------- contact damping
  const ContactDampingSpec& dmp = _section.damping;
  double Fd = 0.0, dFd_du_factor = 0.0;
  Eigen::Vector2d td = Eigen::Vector2d::Zero();
  double dtd = 0.0, dcoef_dh_t = 0.0;
  if (dmp.given && dt > 0) {
    const GapGeometry G0 = geometry(in, in.u_start, s0);
    const double h = G.h + in.interference;
    const double area = _section.area_given ? _section.area : 1.0;
    double coef = 0.0, dcoef = 0.0;
    const double full = dmp.fraction * dmp.clearance;
    if (h <= full) {
      coef = dmp.coefficient;
    } else if (h < dmp.clearance) {
      const double w = dmp.clearance - full;
      coef = dmp.coefficient * (dmp.clearance - h) / w;
      dcoef = -dmp.coefficient / w;
    }
    coef *= area;
    dcoef *= area;
    const double hdot = (G.h - G0.h) / dt;
    Fd = -coef * hdot;                        // compressive when closing
    dFd_du_factor = coef / dt + dcoef * hdot; // dFd/du = factor * dg (dh/du = -dg)
    const double ct = dmp.tangent_fraction * coef;
    td = ct * dslip / dt;
    dtd = ct / dt;
    dcoef_dh_t = dmp.tangent_fraction * dcoef / dt;
  }
  R.damping_force = Fd;
  R.tangential_damping = td;

  // ---------------------------------------------------------------- GAPUNIT heat transfer
  double w1 = 0.0, w2 = 0.0, eta_dt = 0.0;
  if (_thermal) {
    const double pressure = std::max(FN, 0.0) / _section.area;
    R.heat = _thermal->flux(in.u[iT1], in.u[iT2], G.h, is_closed ? pressure : 0.0, is_closed);
    if (const auto& hg = _thermal->heat_generation(); hg && dt > 0) {
      w1 = hg->fraction();
      w2 = 1.0 - hg->fraction();
      eta_dt = hg->eta() / dt;
      R.heat_rate = eta_dt * R.dissipation;
    }
  }

  if (!update) {
    R.status = status;
    return;
  }
  // ---------------------------------------------------------------- state
  // Status changes that alter the set of constraint rows make severe-discontinuity iterations:
  // open <-> closed with exact normal contact, stick <-> slip with exact (Lagrange) friction.
  const bool normal_changed = closed(status) != closed(previous);
  const bool friction_changed = fl && fl->lagrange() && closed(status) && closed(previous) &&
                                status != previous && previous != ContactStatus::Closed;
  if ((_mode == NormalMode::Direct && normal_changed) || friction_changed || predicted_stick)
    out->status_changes = 1;
  R.status = status;
  st[GapStateLayout::status] = static_cast<double>(status);
  if (!G.degenerate)
    for (int k = 0; k < 3; ++k) st[GapStateLayout::direction + k] = G.c[k];
  st[GapStateLayout::slip] = R.slip[0];
  st[GapStateLayout::slip + 1] = R.slip[1];
  st[GapStateLayout::plastic] = plastic[0];
  st[GapStateLayout::plastic + 1] = plastic[1];
  st[GapStateLayout::dissipation] = s0[GapStateLayout::dissipation] + R.dissipation;
  st[GapStateLayout::damping] = Fd;
  st[GapStateLayout::damping + 1] = td[0];
  st[GapStateLayout::damping + 2] = td[1];
  if (lagrange_normal) out->add_constraint(0, R.g, {dg.data(), static_cast<std::size_t>(nd)});

  // ---------------------------------------------------------------- residual and tangent
  auto res = [&](const VecN& v, double a) {
    for (int i = 0; i < nd; ++i) out->residual[i] += a * v[i];
  };
  auto tan = [&](const VecN& a, const VecN& b, double f) {
    if (!out->want_tangent || f == 0.0) return;
    for (int i = 0; i < nd; ++i)
      for (int j = 0; j < nd; ++j) out->tangent[i * nd + j] += f * a[i] * b[j];
  };
  const double normal_total = FN + Fd;
  res(dg, normal_total);
  tan(dg, dg, dFN_dg + dFd_du_factor);
  // friction: r += tau_a ds_a (friction forces of Lagrange stick come with the multipliers)
  const std::array<const VecN*, 2> ds = {&ds1, &ds2};
  for (int a = 0; a < 2; ++a) res(*ds[a], R.friction[a] + td[a]);
  for (int a = 0; a < 2; ++a) {
    for (int b = 0; b < 2; ++b)
      tan(*ds[a], *ds[b], (friction_rows ? 0.0 : dtau_ds(a, b)) + (a == b ? dtd : 0.0));
    // tangential damping coefficient depends on h: d/du = -dcoef_dh_t * dslip_a * dg
    tan(*ds[a], dg, -dcoef_dh_t * dslip[a]);
  }
  if (!friction_rows && dtau_dN.squaredNorm() > 0) {
    if (lagrange_normal) {
      // the friction force depends on the normal multiplier: d r / d lambda_N = dg + ds dtau/dN
      out->has_columns = true;
      const int row = out->n_constraints - 1; // the normal row was added last
      for (int i = 0; i < nd; ++i)
        out->constraint_column[row * nd + i] += dtau_dN[0] * ds1[i] + dtau_dN[1] * ds2[i];
      out->unsymmetric = true;
    } else {
      for (int a = 0; a < 2; ++a) tan(*ds[a], dg, dtau_dN[a] * dFN_dg);
    }
  }
  if (fl && !friction_rows &&
      (dtau_ds(0, 1) != dtau_ds(1, 0) || dtau_dN.squaredNorm() > 0 ||
       status == ContactStatus::Slip))
    out->unsymmetric = true;
  // geometric stiffness of the rotating direction (GAPCYL, GAPSPHER)
  if (out->want_tangent && _base.shape != GapShape::Uni && !G.degenerate && normal_total != 0.0)
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        const double sign = (a == b) ? 1.0 : -1.0;
        for (int i = 0; i < _dim; ++i)
          for (int j = 0; j < _dim; ++j)
            out->tangent[(a * _per_node + i) * nd + b * _per_node + j] -=
                normal_total * sign * G.H(i, j);
      }
  if (!_thermal) return;
  // conduction/radiation: node 1 loses A q, node 2 gains it; frictional heat enters both nodes
  const double A = _section.area;
  const GapThermalModel::Flux& q = R.heat;
  out->residual[iT1] += A * q.q - w1 * R.heat_rate;
  out->residual[iT2] += -A * q.q - w2 * R.heat_rate;
  out->unsymmetric = true;
  if (!out->want_tangent) return;
  auto add = [&](int row, int col, double v) { out->tangent[row * nd + col] += v; };
  add(iT1, iT1, A * q.dq_dTa);
  add(iT1, iT2, A * q.dq_dTb);
  add(iT2, iT1, -A * q.dq_dTa);
  add(iT2, iT2, -A * q.dq_dTb);
  // d q / d u through the clearance (dh/du = -dg) and the contact pressure p = F_N / A
  const double pressure_factor = is_closed && FN > 0 ? q.dq_dp / A : 0.0;
  // d(heat rate)/du through the slip and the normal force
  VecN dD = VecN::Zero();
  for (int i = 0; i < nd; ++i) dD[i] = dD_de[0] * ds1[i] + dD_de[1] * ds2[i];
  for (int j = 0; j < nd; ++j) {
    double dqj = -A * q.dq_dh * dg[j];
    if (!lagrange_normal) dqj += A * pressure_factor * dFN_dg * dg[j];
    const double dD_j = dD[j] + (lagrange_normal ? 0.0 : dD_dN * dFN_dg * dg[j]);
    add(iT1, j, dqj - w1 * eta_dt * dD_j);
    add(iT2, j, -dqj - w2 * eta_dt * dD_j);
  }
  if (lagrange_normal && (pressure_factor != 0.0 || dD_dN != 0.0)) {
    // the flux depends on the normal multiplier: its column gets the temperature rows
    out->has_columns = true;
    int row = -1;
    for (int c = 0; c < out->n_constraints; ++c)
      if (out->constraint_slot[c] == 0) row = c;
    if (row >= 0) {
      out->constraint_column[row * nd + iT1] += A * pressure_factor - w1 * eta_dt * dD_dN;
      out->constraint_column[row * nd + iT2] += -A * pressure_factor - w2 * eta_dt * dD_dN;
    }
  }
}

void MechanicalGapKernel::evaluate(const ElementInput& in, ElementOutput& out) const {
  Response R;
  respond(in, in.state, in.multipliers, &out, R);
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
