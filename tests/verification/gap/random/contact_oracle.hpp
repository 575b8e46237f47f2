#pragma once
// An oracle for the random gap models (random_models.hpp), written for the test and independent of
// gapfem's solver: it assembles its own stiffness (dense), and
//  - frictionless GAPUNI networks: solves the linear complementarity problem of the contact set
//    exactly with Murty's least-index principal pivoting (finite for the P-matrix of a positive
//    definite stiffness), so the answer is the unique one that satisfies every condition;
//  - friction with one tangential direction (normal along y, slip along x, stiffness decoupled in
//    x and y): the normal LCP gives the normal forces, then the backward-Euler stick/slip problem
//    of each increment (the increments gapfem took) is solved by an active-set iteration over
//    {stick, slip+, slip-} per gap, falling back to enumerating every combination; the answer is
//    accepted only when every gap satisfies its stick or slip condition (the incremental problem
//    is strictly convex, so that answer is unique);
//  - GAPCYL/GAPSPHER units (one node on springs, one centre node): the constrained minimum of the
//    spring energy on the cylinder or sphere by a one-dimensional root search on the multiplier.
// The elastic-slip rule is Abaqus's penalty friction: stick force k_s e with k_s = mu N / gamma,
// e = s - s_p, slip when |k_s e| > mu N (s_p <- s - gamma sign e); LAGRANGE: e = 0 in stick.
#include "random_models.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

namespace gapfem::test::random_contact {

/// One gap's state in the oracle's solution.
struct OracleGap {
  bool closed = false;
  double normal_force = 0.0; ///< compressive, >= 0
  double clearance = 0.0;    ///< h
  double slip = 0.0;         ///< accumulated slip along the tangential direction (E12)
  double plastic = 0.0;      ///< stick point
  double friction = 0.0;     ///< friction force along the tangential direction
  int mode = 0;              ///< 0 stick (or no friction), +1/-1 slipping
  bool degenerate = false;   ///< on a status boundary: statuses are not compared
};

struct OracleState {
  Eigen::VectorXd u; ///< 3 per node
  std::vector<OracleGap> gaps;
  /// How much the answer moves per unit shift of the closed gaps' clearances (infinity norms, for
  /// the same contact set): bounds the difference between augmented Lagrange, which closes gaps
  /// only to a tolerance, and exact contact.
  double clearance_to_u = 0.0, clearance_to_force = 0.0;
  /// The largest elastic-slip stick stiffness mu N / gamma in the answer: the round-off of its
  /// force, ~ eps k_s |u|, sets how closely two solvers can agree.
  double stiffest_stick = 0.0;
};

/// Murty's least-index method for w = q + M z >= 0, z >= 0, w.z = 0 (M a P-matrix).
inline Eigen::VectorXd solve_lcp(const Eigen::MatrixXd& M, const Eigen::VectorXd& q, double tol) {
  const int m = static_cast<int>(q.size());
  std::vector<char> active(static_cast<std::size_t>(m), 0);
  Eigen::VectorXd z = Eigen::VectorXd::Zero(m);
  for (int it = 0; it < 100000; ++it) {
    std::vector<int> A;
    for (int i = 0; i < m; ++i)
      if (active[i]) A.push_back(i);
    z.setZero();
    if (!A.empty()) {
      Eigen::MatrixXd MA(A.size(), A.size());
      Eigen::VectorXd qA(A.size());
      for (std::size_t r = 0; r < A.size(); ++r) {
        qA[r] = q[A[r]];
        for (std::size_t c = 0; c < A.size(); ++c) MA(r, c) = M(A[r], A[c]);
      }
      const Eigen::VectorXd zA = MA.partialPivLu().solve(-qA);
      for (std::size_t r = 0; r < A.size(); ++r) z[A[r]] = zA[r];
    }
    const Eigen::VectorXd w = q + M * z;
    int bad = -1;
    for (int i = 0; i < m && bad < 0; ++i)
      if ((active[i] && z[i] < -tol) || (!active[i] && w[i] < -tol)) bad = i;
    if (bad < 0) return z;
    active[bad] = !active[bad];
  }
  throw std::runtime_error("oracle: LCP pivoting did not terminate");
}

/// Exact solution of the linear random models (GAPUNI, springs, trusses) along a load history.
class LinearOracle {
 public:
  explicit LinearOracle(const ModelDef& m) : _m(m) {
    const int nn = static_cast<int>(m.nodes.size());
    _K = Eigen::MatrixXd::Zero(3 * nn, 3 * nn);
    for (const auto& s : m.springs1) _K(3 * s.node + s.dof, 3 * s.node + s.dof) += s.k;
    for (const auto& s : m.springs2) {
      const int a = 3 * s.a + s.dof, b = 3 * s.b + s.dof;
      _K(a, a) += s.k;
      _K(b, b) += s.k;
      _K(a, b) -= s.k;
      _K(b, a) -= s.k;
    }
    for (const auto& t : m.trusses) {
      const Eigen::Vector3d dX = m.nodes[t.b].X - m.nodes[t.a].X;
      const double L = dX.norm();
      const Eigen::Matrix3d k = (t.EA / L) * (dX / L) * (dX / L).transpose();
      _K.block<3, 3>(3 * t.a, 3 * t.a) += k;
      _K.block<3, 3>(3 * t.b, 3 * t.b) += k;
      _K.block<3, 3>(3 * t.a, 3 * t.b) -= k;
      _K.block<3, 3>(3 * t.b, 3 * t.a) -= k;
    }
    for (int i = 0; i < nn; ++i)
      for (int k = 0; k < m.active_dofs(); ++k)
        if (m.nodes[i].free) _free.push_back(3 * i + k);
    for (std::size_t i = 0; i < m.gaps.size(); ++i) _normal.push_back(gap_normal(i));
    _state.u = Eigen::VectorXd::Zero(3 * nn);
    _state.gaps.assign(m.gaps.size(), {});
    for (std::size_t i = 0; i < m.gaps.size(); ++i) {
      _state.gaps[i].closed = m.gaps[i].d <= 0.0; // gapfem starts a gap with h <= 0 closed
      _lc.push_back(characteristic_length(i));
    }
  }

  const OracleState& state() const { return _state; }
  double characteristic_length(std::size_t gap) const;
  /// Advance to `fraction` of step `step` (0-based) from the current state (one increment).
  /// Returns false when the answer is degenerate (a gap closed at zero force carrying friction).
  bool advance(int step, double fraction);

 private:
  Eigen::Vector3d gap_normal(std::size_t i) const {
    const GapDef& g = _m.gaps[i];
    if (g.dir_given) return g.dir.normalized();
    const Eigen::Vector3d d = _m.nodes[g.n2].X - _m.nodes[g.n1].X;
    return d.normalized();
  }
  /// Displacements of all nodes for free-DOF values x and prescribed values up.
  Eigen::VectorXd full(const Eigen::VectorXd& x, const Eigen::VectorXd& up) const {
    Eigen::VectorXd u = up;
    for (std::size_t k = 0; k < _free.size(); ++k) u[_free[k]] = x[k];
    return u;
  }
  bool solve_friction(const Eigen::VectorXd& f, const Eigen::VectorXd& up, OracleState& next);

  const ModelDef& _m;
  Eigen::MatrixXd _K;
  std::vector<int> _free;
  std::vector<Eigen::Vector3d> _normal;
  std::vector<double> _lc;
  OracleState _state;
};

inline double LinearOracle::characteristic_length(std::size_t gap) const {
  // the kernel's rule: mean diameter of the non-gap elements at the gap's nodes (SPRING1 has none)
  const GapDef& g = _m.gaps[gap];
  double sum = 0.0;
  int n = 0;
  auto visit = [&](int node) {
    for (const auto& s : _m.springs2)
      if (s.a == node || s.b == node) {
        sum += (_m.nodes[s.a].X - _m.nodes[s.b].X).norm();
        ++n;
      }
    for (const auto& t : _m.trusses)
      if (t.a == node || t.b == node) {
        sum += (_m.nodes[t.a].X - _m.nodes[t.b].X).norm();
        ++n;
      }
  };
  visit(g.n1);
  visit(g.n2);
  if (n > 0) return sum / n;
  return (_m.nodes[g.n1].X - _m.nodes[g.n2].X).norm();
}

inline bool LinearOracle::advance(int step, double fraction) {
  const int nn = static_cast<int>(_m.nodes.size());
  const int nf = static_cast<int>(_free.size());
  const StepDef& st = _m.steps[step];
  const StepDef* prev = step > 0 ? &_m.steps[step - 1] : nullptr;
  Eigen::VectorXd fall = Eigen::VectorXd::Zero(3 * nn), up = Eigen::VectorXd::Zero(3 * nn);
  for (int i = 0; i < nn; ++i) {
    const Eigen::Vector3d f0 = prev ? prev->load[i] : Eigen::Vector3d::Zero();
    const Eigen::Vector3d u0 = prev ? prev->motion[i] : Eigen::Vector3d::Zero();
    const Eigen::Vector3d f = f0 + fraction * (st.load[i] - f0);
    const Eigen::Vector3d u = u0 + fraction * (st.motion[i] - u0);
    for (int k = 0; k < 3; ++k) {
      if (_m.nodes[i].free && k < _m.active_dofs()) fall[3 * i + k] = f[k];
      if (!_m.nodes[i].free) up[3 * i + k] = u[k];
    }
  }
  // reduced system K_ff x = f_f - K_fp u_p (+ contact)
  Eigen::MatrixXd Kf(nf, nf);
  Eigen::VectorXd ff(nf);
  const Eigen::VectorXd Kup = _K * up;
  for (int r = 0; r < nf; ++r) {
    ff[r] = fall[_free[r]] - Kup[_free[r]];
    for (int c = 0; c < nf; ++c) Kf(r, c) = _K(_free[r], _free[c]);
  }
  // gap rows h = c + a.x
  const int m = static_cast<int>(_m.gaps.size());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(m, nf);
  Eigen::VectorXd c(m), compliance = Eigen::VectorXd::Zero(m);
  for (int i = 0; i < m; ++i) {
    const GapDef& g = _m.gaps[i];
    const Eigen::Vector3d& n = _normal[i];
    double ci = g.d;
    for (int k = 0; k < 3; ++k) {
      ci += n[k] * (up[3 * g.n2 + k] - up[3 * g.n1 + k]);
      for (int r = 0; r < nf; ++r) {
        if (_free[r] == 3 * g.n2 + k) A(i, r) += n[k];
        if (_free[r] == 3 * g.n1 + k) A(i, r) -= n[k];
      }
    }
    c[i] = ci;
    if (g.normal == NormalMethod::Penalty) compliance[i] = 1.0 / g.penalty;
  }
  const auto lu = Kf.llt();
  const Eigen::VectorXd x0 = lu.solve(ff);
  const Eigen::MatrixXd KiAt = lu.solve(A.transpose());
  Eigen::MatrixXd M = A * KiAt;
  M.diagonal() += compliance;
  const Eigen::VectorXd q = c + A * x0;
  const double scale = std::max(1.0, q.cwiseAbs().maxCoeff());
  const Eigen::VectorXd lambda = solve_lcp(M, q, 1e-13 * scale);
  Eigen::VectorXd x = x0 + KiAt * lambda;
  OracleState next = _state;
  const Eigen::VectorXd h = c + A * x;
  const double fscale = std::max(1.0, ff.cwiseAbs().maxCoeff());
  for (int i = 0; i < m; ++i) {
    OracleGap& g = next.gaps[i];
    g.normal_force = lambda[i];
    g.clearance = h[i];
    g.closed = lambda[i] > 0.0 || (_m.gaps[i].normal == NormalMethod::Direct && h[i] <= 0.0);
    g.degenerate = std::abs(lambda[i]) < 1e-9 * fscale && std::abs(h[i]) < 1e-9 * scale;
  }
  next.u = full(x, up);
  std::vector<int> act;
  for (int i = 0; i < m; ++i)
    if (next.gaps[i].closed && _m.gaps[i].normal != NormalMethod::Penalty) act.push_back(i);
  next.clearance_to_u = next.clearance_to_force = 0.0;
  if (!act.empty()) {
    const int na = static_cast<int>(act.size());
    Eigen::MatrixXd Maa(na, na), KiAa(nf, na);
    for (int a = 0; a < na; ++a) {
      KiAa.col(a) = KiAt.col(act[a]);
      for (int b = 0; b < na; ++b) Maa(a, b) = M(act[a], act[b]);
    }
    const Eigen::MatrixXd inv = Maa.inverse();
    next.clearance_to_force = inv.cwiseAbs().rowwise().sum().maxCoeff();
    next.clearance_to_u = (KiAa * inv).cwiseAbs().rowwise().sum().maxCoeff();
  }
  bool friction = false;
  for (const auto& g : _m.gaps) friction |= g.friction != FrictionKind::None;
  if (friction && !solve_friction(ff + A.transpose() * lambda, up, next)) return false;
  _state = next;
  return true;
}

} // namespace gapfem::test::random_contact

#include "contact_oracle_friction.hpp"
