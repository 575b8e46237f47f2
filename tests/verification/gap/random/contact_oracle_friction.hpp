#pragma once
// The incremental stick/slip problem of LinearOracle (contact_oracle.hpp): one tangential direction
// (x) per gap, normal forces known from the normal problem. See contact_oracle.hpp for the rules.
#include "contact_oracle.hpp"

namespace gapfem::test::random_contact {

inline bool LinearOracle::solve_friction(const Eigen::VectorXd& f, const Eigen::VectorXd& up,
                                         OracleState& next) {
  const int nf = static_cast<int>(_free.size());
  std::vector<int> T; // free x DOFs (positions in _free)
  for (int r = 0; r < nf; ++r)
    if (_free[r] % 3 == 0) T.push_back(r);
  const int nt = static_cast<int>(T.size());
  Eigen::MatrixXd K(nt, nt);
  Eigen::VectorXd fx(nt);
  for (int a = 0; a < nt; ++a) {
    fx[a] = f[T[a]];
    for (int b = 0; b < nt; ++b) K(a, b) = _K(_free[T[a]], _free[T[b]]);
  }
  const int m = static_cast<int>(_m.gaps.size());
  // slip s_i(x) = b_i . x + sigma_i (t = e_x: node 1 minus node 2)
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(m, nt);
  Eigen::VectorXd sigma(m);
  for (int i = 0; i < m; ++i) {
    const GapDef& g = _m.gaps[i];
    const int d1 = 3 * g.n1, d2 = 3 * g.n2;
    for (int a = 0; a < nt; ++a) {
      if (_free[T[a]] == d1) B(i, a) += 1.0;
      if (_free[T[a]] == d2) B(i, a) -= 1.0;
    }
    sigma[i] = _state.gaps[i].slip - (_state.u[d1] - _state.u[d2]) + (up[d1] - up[d2]);
  }
  // gaps with friction acting in this increment
  std::vector<int> fr;
  std::vector<double> crit(static_cast<std::size_t>(m), 0.0),
      gamma(static_cast<std::size_t>(m), 0.0), p0(static_cast<std::size_t>(m), 0.0);
  const double fscale = std::max(1.0, f.cwiseAbs().maxCoeff());
  for (int i = 0; i < m; ++i) {
    const GapDef& g = _m.gaps[i];
    p0[i] = _state.gaps[i].closed ? _state.gaps[i].plastic : _state.gaps[i].slip;
    if (g.friction == FrictionKind::None || !next.gaps[i].closed) continue;
    if (next.gaps[i].normal_force < 1e-9 * fscale) return false; // closed at zero force: degenerate
    crit[i] = g.mu * next.gaps[i].normal_force;
    gamma[i] = g.friction == FrictionKind::ElasticSlip     ? g.elastic_slip
               : g.friction == FrictionKind::SlipTolerance ? g.slip_tolerance * _lc[i]
                                                           : 0.0;
    fr.push_back(i);
  }
  const int nc = static_cast<int>(fr.size());
  std::vector<int> mode(static_cast<std::size_t>(nc));
  for (int j = 0; j < nc; ++j) {
    const OracleGap& s0 = _state.gaps[fr[j]];
    mode[j] = s0.closed ? s0.mode : 0;
  }
  Eigen::VectorXd x(nt), tau(nc), s(nc);
  // solve for the given modes; returns the consistency of each gap (0 consistent, else new mode +
  // 2)
  auto solve = [&](const std::vector<int>& md) {
    std::vector<int> lag; // Lagrange-stick gaps (multiplier unknowns)
    Eigen::MatrixXd S = K;
    Eigen::VectorXd rhs = fx;
    for (int j = 0; j < nc; ++j) {
      const int i = fr[j];
      const bool lagrange = gamma[i] == 0.0;
      if (md[j] != 0) {
        rhs -= md[j] * crit[i] * B.row(i).transpose();
      } else if (lagrange) {
        lag.push_back(j);
      } else {
        const double k = crit[i] / gamma[i];
        S += k * B.row(i).transpose() * B.row(i);
        rhs -= k * (sigma[i] - p0[i]) * B.row(i).transpose();
      }
    }
    const int nl = static_cast<int>(lag.size());
    Eigen::MatrixXd Z = Eigen::MatrixXd::Zero(nt + nl, nt + nl);
    Eigen::VectorXd z(nt + nl);
    Z.topLeftCorner(nt, nt) = S;
    z.head(nt) = rhs;
    for (int l = 0; l < nl; ++l) {
      const int i = fr[lag[l]];
      Z.block(0, nt + l, nt, 1) = B.row(i).transpose();
      Z.block(nt + l, 0, 1, nt) = B.row(i);
      z[nt + l] = p0[i] - sigma[i];
    }
    const Eigen::VectorXd sol = Z.fullPivLu().solve(z);
    x = sol.head(nt);
    std::vector<int> verdict(static_cast<std::size_t>(nc), 0);
    int l = 0;
    for (int j = 0; j < nc; ++j) {
      const int i = fr[j];
      s[j] = B.row(i).dot(x) + sigma[i];
      const double e = s[j] - p0[i];
      const bool lagrange = gamma[i] == 0.0;
      const double tol = 1e-11;
      if (md[j] != 0) {
        tau[j] = md[j] * crit[i];
        const double reach = lagrange ? 0.0 : gamma[i];
        if (md[j] * e < reach - tol * (reach + 1e-3)) verdict[j] = 2; // back to stick
      } else {
        tau[j] = lagrange ? sol[nt + l++] : crit[i] / gamma[i] * e;
        if (std::abs(tau[j]) > crit[i] * (1 + 1e-11))
          verdict[j] = 2 + (lagrange ? (tau[j] > 0 ? 1 : -1) : (e > 0 ? 1 : -1));
      }
    }
    return verdict;
  };
  auto consistent = [](const std::vector<int>& v) {
    return std::all_of(v.begin(), v.end(), [](int k) { return k == 0; });
  };
  bool found = false;
  for (int it = 0; it < 60 && !found; ++it) {
    const std::vector<int> v = solve(mode);
    if (consistent(v)) {
      found = true;
      break;
    }
    for (int j = 0; j < nc; ++j)
      if (v[j] != 0) mode[j] = v[j] - 2;
  }
  if (!found) { // every combination of stick / slip+ / slip-
    std::vector<int> md(static_cast<std::size_t>(nc), 0);
    long total = 1;
    for (int j = 0; j < nc; ++j) total *= 3;
    for (long code = 0; code < total && !found; ++code) {
      long c = code;
      for (int j = 0; j < nc; ++j, c /= 3) md[j] = static_cast<int>(c % 3) - 1;
      if (consistent(solve(md))) {
        found = true;
        mode = md;
      }
    }
    if (!found) throw std::runtime_error("oracle: no consistent stick/slip state");
    solve(mode);
  }
  // the answer: x DOFs, slips, stick points, friction forces
  for (int a = 0; a < nt; ++a) next.u[_free[T[a]]] = x[a];
  for (int i = 0; i < m; ++i) {
    OracleGap& g = next.gaps[i];
    g.slip = B.row(i).dot(x) + sigma[i];
    g.friction = 0.0;
    g.mode = 0;
    g.plastic = g.closed ? p0[i] : g.slip;
  }
  next.stiffest_stick = 0.0;
  for (int j = 0; j < nc; ++j) {
    const int i = fr[j];
    OracleGap& g = next.gaps[i];
    if (gamma[i] > 0) next.stiffest_stick = std::max(next.stiffest_stick, crit[i] / gamma[i]);
    g.friction = tau[j];
    g.mode = mode[j];
    if (mode[j] != 0) g.plastic = s[j] - mode[j] * gamma[i];
    // on the stick/slip boundary the status is not compared
    const double e = s[j] - p0[i];
    if (gamma[i] > 0)
      g.degenerate |= std::abs(std::abs(e) - gamma[i]) < 1e-7 * gamma[i];
    else
      g.degenerate |= (mode[j] == 0 && std::abs(std::abs(tau[j]) - crit[i]) < 1e-7 * crit[i]) ||
                      (mode[j] != 0 && std::abs(e) < 1e-12);
  }
  return true;
}

} // namespace gapfem::test::random_contact
