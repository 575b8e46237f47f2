// Residual and tangent of the mechanical gap kernel from the quantities of one evaluation
// (gap_response.cpp): normal force (law, multiplier, damping) along dg, friction along the
// friction directions q_a, the geometric stiffness of rotating gaps and of the projected friction,
// the multiplier columns, and GAPUNIT heat transfer.
#include "elements/gap/gap_response.hpp"

namespace gapfem {

void MechanicalGapKernel::assemble(const ElementInput& in, ElementOutput& out, const Response& R,
                                   const Local& L) const {
  const int nd = L.nd;
  auto res = [&](const GapVec& v, double a) {
    for (int i = 0; i < nd; ++i) out.residual[i] += a * v[i];
  };
  auto tan = [&](const GapVec& a, const GapVec& b, double f) {
    if (!out.want_tangent || f == 0.0) return;
    for (int i = 0; i < nd; ++i)
      for (int j = 0; j < nd; ++j) out.tangent[i * nd + j] += f * a[i] * b[j];
  };
  // adds sign(a, b) M to the (node a, node b) blocks of the displacement DOFs
  auto node_blocks = [&](const Eigen::Matrix3d& M) {
    if (!out.want_tangent) return;
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        const double sign = (a == b) ? 1.0 : -1.0;
        for (int i = 0; i < _dim; ++i)
          for (int j = 0; j < _dim; ++j)
            out.tangent[(a * _per_node + i) * nd + b * _per_node + j] += sign * M(i, j);
      }
  };
  const GapGeometry& G = R.geom;
  const double normal_total = L.FN + L.Fd;
  res(L.dg, normal_total);
  tan(L.dg, L.dg, L.dFN_dg + L.dFd_du);
  // friction: r += f_a q_a (the forces of Lagrange stick are its multipliers); the slip, and with
  // it the force, moves with d s_a / d u = ds_a
  Eigen::Vector2d f = R.friction + L.td;
  out.friction = out.friction || L.fl != nullptr;
  for (int a = 0; a < 2; ++a) res(L.q[a], f[a]);
  for (int a = 0; a < 2; ++a) {
    for (int b = 0; b < 2; ++b)
      tan(L.q[a], L.ds[b], (L.friction_rows ? 0.0 : L.dtau_ds(a, b)) + (a == b ? L.dtd : 0.0));
    // tangential damping coefficient depends on h: d/du = -dcoef_dh_t * dslip_a * dg
    tan(L.q[a], L.dg, -L.dcoef_dh_t * L.dslip[a]);
  }
  if (L.friction_rows && L.projected) {
    // the stick forces act along q_a, not along their rows ds_a: the rows get their own columns
    out.has_columns = true;
    for (int c = 0; c < out.n_constraints; ++c) {
      const int slot = out.constraint_slot[c];
      if (slot == 0) continue;
      for (int i = 0; i < nd; ++i) out.constraint_column[c * nd + i] = L.q[slot - 1][i];
    }
  }
  if (!L.friction_rows && L.dtau_dN.squaredNorm() > 0) {
    if (L.lagrange_normal) {
      // the friction force depends on the normal multiplier: d r / d lambda_N = dg + q dtau/dN
      out.has_columns = true;
      int row = -1;
      for (int c = 0; c < out.n_constraints; ++c)
        if (out.constraint_slot[c] == 0) row = c;
      if (row >= 0)
        for (int i = 0; i < nd; ++i)
          out.constraint_column[row * nd + i] +=
              L.dtau_dN[0] * L.q[0][i] + L.dtau_dN[1] * L.q[1][i];
    } else if (L.dFN_dg != 0.0) {
      for (int a = 0; a < 2; ++a) tan(L.q[a], L.dg, L.dtau_dN[a] * L.dFN_dg);
      out.unsymmetric = true;
    }
  }
  // The tangent block itself (not the multiplier columns, which the constrained solver handles
  // apart) is unsymmetric only where friction acts along q_a but moves with ds_a (a projected,
  // rotating gap), where the slip tangent is (slip-rate dependence), and where the tangential
  // damping depends on the clearance. A GAPUNI with constant mu keeps a symmetric K: its friction
  // couples to the normal force only through the normal multiplier's column.
  const bool slip_terms = L.fl && !L.friction_rows && L.dtau_ds.squaredNorm() > 0.0;
  if ((L.projected && (slip_terms || L.dtd != 0.0)) ||
      (slip_terms && L.dtau_ds(0, 1) != L.dtau_ds(1, 0)) ||
      (L.dcoef_dh_t != 0.0 && L.dslip.squaredNorm() > 0.0))
    out.unsymmetric = true;
  if (G.degenerate || _base.shape == GapShape::Uni) return;
  // geometric stiffness of the rotating direction (GAPCYL, GAPSPHER): d(c)/dx1 = -H
  if (normal_total != 0.0) node_blocks(-normal_total * G.H);
  // and of the projection of the friction force v = f_a t_a on the plane normal to c:
  // d(P v)/dx1 = (c.v) H + c (H v)^T
  const Eigen::Vector3d v = f[0] * R.t1 + f[1] * R.t2;
  if (v.squaredNorm() > 0.0) {
    node_blocks(G.c.dot(v) * G.H + G.c * (G.H * v).transpose());
    out.unsymmetric = true;
  }
  (void)in;
}

void MechanicalGapKernel::assemble_heat(ElementOutput& out, const Response& R,
                                        const Local& L) const {
  // conduction/radiation: node 1 loses A q, node 2 gains it; frictional heat enters both nodes
  const int nd = L.nd, iT1 = L.iT1, iT2 = L.iT2;
  const double A = _section.area;
  const GapThermalModel::Flux& q = R.heat;
  out.residual[iT1] += A * q.q - L.w1 * R.heat_rate;
  out.residual[iT2] += -A * q.q - L.w2 * R.heat_rate;
  out.unsymmetric = true;
  if (!out.want_tangent) return;
  auto add = [&](int row, int col, double v) { out.tangent[row * nd + col] += v; };
  add(iT1, iT1, A * q.dq_dTa);
  add(iT1, iT2, A * q.dq_dTb);
  add(iT2, iT1, -A * q.dq_dTa);
  add(iT2, iT2, -A * q.dq_dTb);
  // d q / d u through the clearance (dh/du = -dg) and the contact pressure p = F_N / A
  const double pressure_factor = L.is_closed && L.FN > 0 ? q.dq_dp / A : 0.0;
  // d(heat rate)/du through the slip and the normal force
  GapVec dD = GapVec::Zero();
  for (int i = 0; i < nd; ++i) dD[i] = L.dD_de[0] * L.ds[0][i] + L.dD_de[1] * L.ds[1][i];
  for (int j = 0; j < nd; ++j) {
    double dqj = -A * q.dq_dh * L.dg[j];
    if (!L.lagrange_normal) dqj += A * pressure_factor * L.dFN_dg * L.dg[j];
    const double dD_j = dD[j] + (L.lagrange_normal ? 0.0 : L.dD_dN * L.dFN_dg * L.dg[j]);
    add(iT1, j, dqj - L.w1 * L.eta_dt * dD_j);
    add(iT2, j, -dqj - L.w2 * L.eta_dt * dD_j);
  }
  if (L.lagrange_normal && (pressure_factor != 0.0 || L.dD_dN != 0.0)) {
    // the flux depends on the normal multiplier: its column gets the temperature rows
    out.has_columns = true;
    int row = -1;
    for (int c = 0; c < out.n_constraints; ++c)
      if (out.constraint_slot[c] == 0) row = c;
    if (row >= 0) {
      out.constraint_column[row * nd + iT1] += A * pressure_factor - L.w1 * L.eta_dt * L.dD_dN;
      out.constraint_column[row * nd + iT2] += -A * pressure_factor - L.w2 * L.eta_dt * L.dD_dN;
    }
  }
}

} // namespace gapfem
