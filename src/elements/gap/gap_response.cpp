// One evaluation of the mechanical gap kernel, stage by stage: setup (geometry, slip basis and
// slip), normal behaviour (multiplier, force law or augmented Lagrange), friction (LAGRANGE rows or
// elastic-slip return map, with the stick predictor), contact damping, GAPUNIT heat, then the
// trial state, constraint rows, residual and tangent. docs/theory/gap_elements.md has the
// equations.
#include "elements/gap/gap_response.hpp"

#include <algorithm>
#include <cmath>

namespace gapfem {
namespace {

ContactStatus status_of(double v) {
  return static_cast<ContactStatus>(static_cast<int>(v + 0.5));
}
bool closed(ContactStatus s) {
  return s != ContactStatus::Open;
}

} // namespace

bool MechanicalGapKernel::enforceable(const ElementInput& in, const Local& L,
                                      const GapVec& row) const {
  if (in.free.empty()) return true;
  for (int i = 0; i < L.nd; ++i)
    if (in.free[i] && row[i] != 0.0) return true;
  return false;
}

void MechanicalGapKernel::setup(const ElementInput& in, std::span<const double> st, Response& R,
                                Local& L) const {
  L.nd = 2 * _per_node;
  const auto& s0 = in.state_start;
  R.geom = geometry(in, in.u, st);
  const GapGeometry& G = R.geom;
  // Slip basis frozen over the increment: from the closure direction at its start.
  Eigen::Vector3d c0(s0[GapStateLayout::direction], s0[GapStateLayout::direction + 1],
                     s0[GapStateLayout::direction + 2]);
  if (c0.squaredNorm() == 0.0) c0 = G.c;
  slip_basis(c0, R.t1, R.t2);
  // The friction forces act in the current tangent plane: on a rotating gap (GAPCYL, GAPSPHER)
  // the frozen basis is projected on it, so that friction never pushes along the contact normal
  // (docs/theory/gap_elements.md §6.4).
  L.projected = _base.shape != GapShape::Uni && !G.degenerate;
  const Eigen::Matrix3d P =
      L.projected ? Eigen::Matrix3d(Eigen::Matrix3d::Identity() - G.c * G.c.transpose())
                  : Eigen::Matrix3d::Identity();
  const Eigen::Vector3d pt[2] = {P * R.t1, P * R.t2};
  const Eigen::Vector3d* t[2] = {&R.t1, &R.t2};
  L.dg.setZero();
  for (int a = 0; a < 2; ++a) L.ds[a].setZero(), L.q[a].setZero();
  L.dslip.setZero();
  for (int k = 0; k < _dim; ++k) {
    L.dg[k] = G.c[k];
    L.dg[_per_node + k] = -G.c[k];
    const double du_rel =
        (in.u[k] - in.u_start[k]) - (in.u[_per_node + k] - in.u_start[_per_node + k]);
    for (int a = 0; a < 2; ++a) {
      L.ds[a][k] = (*t[a])[k];
      L.ds[a][_per_node + k] = -(*t[a])[k];
      L.q[a][k] = pt[a][k];
      L.q[a][_per_node + k] = -pt[a][k];
      L.dslip[a] += (*t[a])[k] * du_rel;
    }
  }
  L.slip_start = {s0[GapStateLayout::slip], s0[GapStateLayout::slip + 1]};
  L.plastic_start = {s0[GapStateLayout::plastic], s0[GapStateLayout::plastic + 1]};
  R.slip = L.slip_start + L.dslip;
  R.g = -(G.h + in.interference);
  L.previous = status_of(st[GapStateLayout::status]);
  L.was_closed = closed(L.previous);
  L.perturbation = in.ctx && in.ctx->perturbation;
  L.hint = in.stiffness_hint;
  L.dt = in.ctx ? in.ctx->dt : 0.0;
  L.iT1 = _per_node - 1;
  L.iT2 = 2 * _per_node - 1;
  L.temperature = _thermal                 ? 0.5 * (in.u[L.iT1] + in.u[L.iT2])
                  : in.temperature.empty() ? 0.0
                                           : 0.5 * (in.temperature[0] + in.temperature[1]);
}

void MechanicalGapKernel::normal(const ElementInput& in, std::span<double> st,
                                 std::span<double> mult, Response& R, Local& L) const {
  switch (_mode) {
  case NormalMode::Direct: {
    double lambda = mult[0];
    L.is_closed = L.was_closed;
    if (!enforceable(in, L, L.dg)) {
      // both ends prescribed: the geometry alone decides, the force is not determined
      L.is_closed = R.g > 1e-12 * _length_scale || (_no_separation && L.was_closed);
      lambda = 0.0;
    } else if (L.perturbation) {
      // the base state's status, frozen: a closed gap holds in tension too (bilateral); a first
      // step's base state is the initial one, where an overclosed gap is closed
      L.is_closed = L.was_closed || R.g > 1e-12 * _length_scale;
    } else if (!L.was_closed && R.g > 1e-12 * _length_scale) {
      L.is_closed = true;
    } else if (L.was_closed && lambda < 0.0 && !_no_separation) {
      L.is_closed = false;
    }
    if (!L.is_closed) lambda = 0.0;
    if (L.update) mult[0] = lambda;
    L.FN = lambda;
    L.lagrange_normal = L.is_closed;
    break;
  }
  case NormalMode::Force: {
    if (_no_separation && L.was_closed && R.g < 0) {
      _law->force(-R.g, L.hint, L.FN, L.dFN_dg); // bilateral once closed: mirrored law
      L.FN = -L.FN;
    } else {
      _law->force(R.g, L.hint, L.FN, L.dFN_dg);
    }
    L.is_closed = L.FN > 0 || (_no_separation && L.was_closed);
    // Penalty as a compliant row (docs/theory/gap_elements.md): the law's slope F' leaves the
    // tangent for a row dg.du - dlambda / F' = 0 whose multiplier is the force F itself.
    // Eliminating the multiplier gives back the tangent term F' dg dg^T, so the Newton iterates are
    // those of the force law; but a gap that opens or closes now changes a row, not the matrix, and
    // the solver keeps its factor (the rows are a low-rank correction).
    if (_compliant_rows && L.dFN_dg > 0 &&
        L.dFN_dg >= kRowFraction * _law->stiffness_scale(L.hint) && enforceable(in, L, L.dg)) {
      L.compliant_row = true;
      L.lagrange_normal = true;
      L.row_compliance = 1.0 / L.dFN_dg;
      L.dFN_dg = 0.0;
      if (L.update) mult[0] = L.FN;
    }
    break;
  }
  case NormalMode::Augmented: {
    const double k = augmented_stiffness(in);
    const double trial = st[GapStateLayout::lambda_aug] + k * R.g;
    if (trial > 0 || (_no_separation && L.was_closed)) {
      L.FN = trial;
      L.dFN_dg = k;
      L.is_closed = true;
    }
    break;
  }
  }
  R.normal_force = L.FN;
  L.status = L.is_closed ? ContactStatus::Closed : ContactStatus::Open;
}

void MechanicalGapKernel::friction(const ElementInput& in, std::span<double> st,
                                   std::span<double> mult, ElementOutput* out, Response& R,
                                   Local& L) const {
  L.fl = L.is_closed ? friction_for(in) : nullptr;
  // An open gap carries no friction, and one that closes starts from none (its friction
  // multipliers are not left over from an earlier contact).
  if (L.update && (!L.is_closed || !L.was_closed)) mult[1] = mult[2] = 0.0;
  L.plastic = L.is_closed ? L.plastic_start : R.slip; // open: the stick point follows
  if (!L.fl) return;
  if (L.fl->lagrange())
    friction_lagrange(in, st, mult, out, R, L);
  else
    friction_penalty(in, st, R, L);
  if (L.FN <= 0.0) L.dtau_dN.setZero();
}

void MechanicalGapKernel::friction_lagrange(const ElementInput& in, std::span<double> st,
                                            std::span<double> mult, ElementOutput* out, Response& R,
                                            Local& L) const {
  // Exact stick with two multipliers; slip with the critical force along the slip direction, mu
  // at the slip rate of the increment |dslip| / dt (stick: rate 0).
  const FrictionLaw& fl = *L.fl;
  const double FNc = std::max(L.FN, 0.0);
  double dcrit = 0.0, dcrit_drate = 0.0;
  const double rate = L.dt > 0 ? L.dslip.norm() / L.dt : 0.0;
  const double crit = fl.critical_force(FNc, rate, L.temperature, &dcrit, &dcrit_drate);
  const double crit0 =
      rate > 0 ? fl.critical_force(FNc, 0.0, L.temperature) : crit; // static, for breaking stick
  const Eigen::Vector2d e = R.slip - L.plastic_start;
  Eigen::Vector2d m(st[GapStateLayout::slip_dir], st[GapStateLayout::slip_dir + 1]);
  const bool was_slip = L.previous == ContactStatus::Slip;
  bool slipping = was_slip;
  const double slip_tol = 1e-12 * _length_scale;
  const double slip_small = 1e-6 * _lc[in.block_index];
  if (fl.rough() || L.perturbation) { // a perturbation: closed points stick (Abaqus)
    slipping = false;
  } else if (!enforceable(in, L, L.ds[0]) && !enforceable(in, L, L.ds[1])) {
    // the tangential motion is prescribed: any relative motion is slip
    slipping = e.norm() > slip_tol;
    if (slipping) m = e / e.norm();
  } else if (!L.was_closed && e.norm() > slip_tol) {
    // Closing in this iteration after moving tangentially since the start of the increment: a
    // stick row would pull the gap back to where it was (its stick point) with a friction force
    // that zero normal force cannot hold, and the normal force then turns to tension and reopens
    // it. Start slipping along the motion instead; the next iteration sticks if the slip reverses
    // (the converged state is the same: stick or slip is decided by the conditions below).
    slipping = true;
    m = e / e.norm();
  } else if (!was_slip) {
    const Eigen::Vector2d lt(mult[1], mult[2]);
    if (lt.norm() > crit0 * (1.0 + 1e-9) + 1e-300 && L.previous == ContactStatus::Stick) {
      slipping = true;
      m = lt / lt.norm();
    }
  } else if (e.norm() > slip_tol) {
    // A slip that turns against its direction sticks again (the stick step lands on the stick
    // solution, which the next iteration accepts or breaks). A significant slip sets the
    // direction; a slip below slip_small (right after stick breaks, e is mostly drift across the
    // slip and its own direction is noise) keeps the direction of the broken stick force.
    if (e.dot(m) < 0)
      slipping = false;
    else if (e.norm() > slip_small)
      m = e / e.norm();
  }
  if (!slipping) {
    L.status = ContactStatus::Stick;
    L.friction_rows = true;
    R.friction = Eigen::Vector2d(mult[1], mult[2]);
    if (out) {
      const auto nd = static_cast<std::size_t>(L.nd);
      out->add_constraint(1, e[0], {L.ds[0].data(), nd});
      out->add_constraint(2, e[1], {L.ds[1].data(), nd});
    }
  } else {
    L.status = ContactStatus::Slip;
    if (m.squaredNorm() == 0.0) m = Eigen::Vector2d(1.0, 0.0);
    R.friction = crit * m;
    L.dtau_dN = dcrit * m;
    // d(crit m)/de of m = e/|e|, with |e| bounded below by slip_small: right after stick breaks
    // the slip has no stiffness across it, and the drift would turn the direction at random
    L.dtau_ds =
        (crit / std::max(e.norm(), slip_small)) * (Eigen::Matrix2d::Identity() - m * m.transpose());
    const double dn = L.dslip.norm();
    if (L.dt > 0 && dn > 0 && dcrit_drate != 0.0)
      L.dtau_ds += m * (dcrit_drate / L.dt) * (L.dslip / dn).transpose();
    L.plastic = R.slip;
    R.dissipation = R.friction.dot(L.plastic - L.plastic_start);
    L.dD_de = R.friction; // D = crit |e| along m
    L.dD_dN = e.norm() * dcrit;
    if (L.update) {
      mult[1] = R.friction[0];
      mult[2] = R.friction[1];
    }
  }
  if (L.update) {
    st[GapStateLayout::slip_dir] = m[0];
    st[GapStateLayout::slip_dir + 1] = m[1];
  }
}

void MechanicalGapKernel::friction_penalty(const ElementInput& in, std::span<double> st,
                                           Response& R, Local& L) const {
  const FrictionLaw& fl = *L.fl;
  const double FNc = std::max(L.FN, 0.0);
  const double gamma = fl.elastic_slip(_lc[in.block_index]);
  // stick predictor: the slip direction of the previous iteration, if it slipped
  const Eigen::Vector2d m_prev(st[GapStateLayout::slip_dir], st[GapStateLayout::slip_dir + 1]);
  const bool was_slip = L.previous == ContactStatus::Slip && m_prev.squaredNorm() > 0.0;
  // a perturbation sticks (Abaqus): the stick branch at the base state's stick point
  const FrictionResponse fr =
      L.perturbation ? fl.penalty(L.plastic_start, Eigen::Vector2d::Zero(), L.plastic_start, FNc,
                                  L.dt, L.temperature, gamma, nullptr)
                     : fl.penalty(R.slip, L.dslip, L.plastic_start, FNc, L.dt, L.temperature, gamma,
                                  was_slip ? &m_prev : nullptr);
  R.friction = fr.force;
  L.dtau_ds = fr.dforce_dslip;
  L.dtau_dN = fr.dforce_dnormal;
  L.plastic = fr.plastic_slip;
  R.dissipation = fr.dissipation;
  L.predicted_stick = fr.predicted_stick;
  if (FNc > 0) L.status = fr.slipping ? ContactStatus::Slip : ContactStatus::Stick;
  if (FNc <= 0.0 && L.lagrange_normal && !L.compliant_row) {
    // Closed at zero force (a gap that closes in this iteration, or starts closed unloaded):
    // friction has no stiffness yet, and a tangential motion held only by friction would be
    // singular. The tangent (not the force) takes the attached elements' stiffness, so the first
    // step does not slide the gap freely; the next iteration has the normal force.
    L.dtau_ds = std::max(L.hint, 0.0) * Eigen::Matrix2d::Identity();
  }
  if (L.update) {
    const Eigen::Vector2d m =
        fr.slipping ? Eigen::Vector2d(fr.force.normalized()) : Eigen::Vector2d::Zero();
    st[GapStateLayout::slip_dir] = m[0];
    st[GapStateLayout::slip_dir + 1] = m[1];
  }
  if (fr.slipping) {
    // D = crit (|e| - gamma) with e the trial elastic slip
    double dcrit = 0.0;
    fl.critical_force(FNc, L.dt > 0 ? L.dslip.norm() / L.dt : 0.0, L.temperature, &dcrit);
    L.dD_de = fr.force;
    L.dD_dN = ((R.slip - L.plastic_start).norm() - gamma) * dcrit;
  }
}

void MechanicalGapKernel::slip_rows(const ElementInput& in, std::span<double> mult,
                                    const Response& R, Local& L) const {
  // Only elastic-slip friction on a fixed slip plane (the rows' columns are the rows themselves;
  // a projected, rotating gap's friction acts along q_a, and Lagrange friction keeps its
  // multipliers for its own stick rows).
  if (!_slip_rows || !L.fl || L.fl->lagrange() || L.projected || !L.is_closed) return;
  L.slip_in_rows = true;
  if (L.update) mult[1] = mult[2] = 0.0;
  // The symmetric slip tangent S = sum_k s_k e_k e_k^T: a row along e_k (in the slip basis) with
  // compliance 1/s_k, its multiplier the friction force along e_k. Stick (k I, or the attached
  // stiffness at zero force) keeps the slip basis itself, so its rows stay the same rows from
  // iteration to iteration; slip has one row, across the slip direction.
  const Eigen::Matrix2d S = 0.5 * (L.dtau_ds + L.dtau_ds.transpose());
  Eigen::Matrix2d E = Eigen::Matrix2d::Identity();
  Eigen::Vector2d s = S.diagonal();
  if (S(0, 1) != 0.0) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(S);
    E = es.eigenvectors();
    s = es.eigenvalues();
  }
  const double smax = s.cwiseAbs().maxCoeff();
  if (!(smax > 0)) return;
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector2d e = E.col(k);
    if (s[k] > kRowFraction * smax) {
      const GapVec v = e[0] * L.ds[0] + e[1] * L.ds[1];
      if (!enforceable(in, L, v)) continue;
      const int j = L.n_slip_rows++;
      L.slip_row[j] = v;
      L.slip_row_compliance[j] = 1.0 / s[k];
      if (L.update) mult[1 + j] = e.dot(R.friction);
    }
    L.dtau_ds -= s[k] * e * e.transpose();
  }
  // what is left is round-off or the slip-rate term (unsymmetric): kept in the tangent
  if (L.dtau_ds.cwiseAbs().maxCoeff() <= 1e-12 * smax) L.dtau_ds.setZero();
}

void MechanicalGapKernel::damping(const ElementInput& in, Response& R, Local& L) const {
  const ContactDampingSpec& dmp = _section.damping;
  if (dmp.given && L.dt > 0) {
    const GapGeometry G0 = geometry(in, in.u_start, in.state_start);
    const double h = R.geom.h + in.interference;
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
    const double hdot = (R.geom.h - G0.h) / L.dt;
    L.closure = G0.h - R.geom.h;
    L.Fd = -coef * hdot;                   // compressive when closing
    L.dFd_du = coef / L.dt + dcoef * hdot; // dFd/du = factor * dg (dh/du = -dg)
    const double ct = dmp.tangent_fraction * coef;
    L.td = ct * L.dslip / L.dt;
    L.dtd = ct / L.dt;
    L.dcoef_dh_t = dmp.tangent_fraction * dcoef / L.dt;
  }
  R.damping_force = L.Fd;
  R.tangential_damping = L.td;
}

void MechanicalGapKernel::heat(const ElementInput& in, Response& R, Local& L) const {
  if (!_thermal) return;
  const double pressure = std::max(L.FN, 0.0) / _section.area;
  R.heat =
      _thermal->flux(in.u[L.iT1], in.u[L.iT2], R.geom.h, L.is_closed ? pressure : 0.0, L.is_closed);
  if (const auto& hg = _thermal->heat_generation(); hg && L.dt > 0) {
    L.w1 = hg->fraction();
    L.w2 = 1.0 - hg->fraction();
    L.eta_dt = hg->eta() / L.dt;
    R.heat_rate = L.eta_dt * R.dissipation;
  }
}

void MechanicalGapKernel::store(const ElementInput& in, std::span<double> st, ElementOutput& out,
                                Response& R, const Local& L) const {
  // Status changes that alter the set of constraint rows make severe-discontinuity iterations:
  // open <-> closed with exact normal contact, stick <-> slip with exact (Lagrange) friction, and
  // a stick predicted after a slip reversal (its force is not a converged one).
  const bool normal_changed = closed(L.status) != closed(L.previous);
  const bool friction_changed = L.fl && L.fl->lagrange() && closed(L.status) &&
                                closed(L.previous) && L.status != L.previous &&
                                L.previous != ContactStatus::Closed;
  if ((_mode == NormalMode::Direct && normal_changed) || friction_changed || L.predicted_stick)
    out.status_changes = 1;
  else if (normal_changed)
    out.branch_changes = 1;
  // open/closed changes only rows with exact or compliant-row normal contact, stick changes only
  // rows with Lagrange friction; slip terms, augmented and in-matrix penalties, and GAPUNIT's
  // conductance live in the tangent
  const bool normal_rows =
      _mode == NormalMode::Direct || (_mode == NormalMode::Force && _compliant_rows);
  const bool friction_rows =
      !L.fl || L.slip_in_rows ||
      (L.fl->lagrange() && L.status != ContactStatus::Slip && L.previous != ContactStatus::Slip);
  if (L.status != L.previous && !(normal_rows && friction_rows && !_thermal))
    out.stiffness_changed = true;
  const auto& s0 = in.state_start;
  st[GapStateLayout::status] = static_cast<double>(L.status);
  if (!R.geom.degenerate)
    for (int k = 0; k < 3; ++k) st[GapStateLayout::direction + k] = R.geom.c[k];
  st[GapStateLayout::slip] = R.slip[0];
  st[GapStateLayout::slip + 1] = R.slip[1];
  st[GapStateLayout::plastic] = L.plastic[0];
  st[GapStateLayout::plastic + 1] = L.plastic[1];
  st[GapStateLayout::dissipation] = s0[GapStateLayout::dissipation] + R.dissipation;
  st[GapStateLayout::damping] = L.Fd;
  st[GapStateLayout::damping + 1] = L.td[0];
  st[GapStateLayout::damping + 2] = L.td[1];
  // the damping forces' work over the increment, by the trapezoidal rule as the energies book it
  st[GapStateLayout::damping_work] =
      s0[GapStateLayout::damping_work] + 0.5 * (s0[GapStateLayout::damping] + L.Fd) * L.closure +
      0.5 * (s0[GapStateLayout::damping + 1] + L.td[0]) * L.dslip[0] +
      0.5 * (s0[GapStateLayout::damping + 2] + L.td[1]) * L.dslip[1];
  for (int j = 0; j < L.n_slip_rows; ++j)
    out.add_constraint(1 + j, 0.0, {L.slip_row[j].data(), static_cast<std::size_t>(L.nd)},
                       L.slip_row_compliance[j]);
  // an exact row drives the overclosure to 0; a compliant row's multiplier is already the law's
  // force at this state, so its value is 0 (the row only carries the linearisation)
  if (L.lagrange_normal)
    out.add_constraint(0, L.compliant_row ? 0.0 : R.g,
                       {L.dg.data(), static_cast<std::size_t>(L.nd)}, L.row_compliance);
}

void MechanicalGapKernel::respond(const ElementInput& in, std::span<double> st,
                                  std::span<double> mult, ElementOutput* out, Response& R) const {
  Local L;
  L.update = out != nullptr;
  setup(in, st, R, L);
  normal(in, st, mult, R, L);
  friction(in, st, mult, out, R, L);
  if (out) slip_rows(in, mult, R, L);
  damping(in, R, L);
  heat(in, R, L);
  R.status = L.status;
  if (!out) return;
  store(in, st, *out, R, L);
  assemble(in, *out, R, L);
  if (_thermal) assemble_heat(*out, R, L);
}

} // namespace gapfem
