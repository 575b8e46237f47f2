#pragma once
/// @file kernel_harness.hpp
/// The one test harness of the element kernels (issue 44, item 8). A `KernelProbe`
/// (kernel_probe.hpp) holds the local data of one element and evaluates any ElementKernel on it;
/// the checks every kernel family runs on it:
///
/// - `expect_fd_tangent`: the tangent (and the constraint rows' coefficients and multiplier
///   columns, where the kernel emits rows) against central differences of the residual (and of
///   the row values);
/// - `expect_fd_load_stiffness`: the same for the load stiffness that `load()` returns;
/// - `expect_revert_is_exact`: evaluate at a trial state, abandon another attempt, revert
///   (trial = committed) and evaluate again: residual, tangent, rows and history are identical to
///   the bit;
/// - `expect_rigid_body_invariance`: a rigid motion changes nothing it must not.
///
/// Each check reports one failure (gtest, non-fatal) naming the worst entry with its row and
/// column and how many entries fail, so a broken kernel reads as one sentence per check.
///
/// Which rigid motions each family supports (RigidBodyOptions says which one a call makes;
/// "small": an infinitesimal rotation field w x X superposed, residual and tangent unchanged;
/// "finite": the deformed state turned by R, residual and tangent turn with it; "from the
/// reference": the undeformed state turned, residual compared):
///
///   continuum 3-D, full/quadratic/incompatible (and T twins),  translation; small; finite
///   T3D2, SPRINGA, user elements with an objective law
///   plane stress/strain, T2D2, planar SPRINGA                  in-plane translation; about z
///   first-order reduced C3D8R/CPS4R/CPE4R, ENHANCED hourglass  translation; small; from the
///   control (the default; STIFFNESS: finite)                   reference (K_hg u is linear in u
///                                                              on the reference configuration:
///                                                              it does not turn with the body)
///   axisymmetric (CAX*)                                        translation along z; no rotation
///   beams, shells (rotational DOFs)                            translation; small; from the
///                                                              reference (rotation DOFs are
///                                                              increments on committed
///                                                              quaternions)
///   gaps                                                       translation; no rotation (a given
///                                                              direction is fixed in space, a
///                                                              computed one is history)
///   SPRING2                                                    translation if both DOFs are the
///                                                              same; no rotation
///   SPRING1                                                    none (grounded)
///   heat transfer (DC*, DS*, DGAP)                             `frame`: the element itself moved
///                                                              and turned, r and K unchanged
///                                                              (DCAX: along z only)
#include "unit/elements/kernel_probe.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace gapfem::test {

namespace detail {

inline constexpr double kEps = std::numeric_limits<double>::epsilon();

/// Collects what a check found and reports it as one gtest failure: the worst entry of each kind
/// (row, column, both values and the tolerance) and how many entries failed.
class Findings {
 public:
  explicit Findings(std::string check) : _check(std::move(check)) {}
  /// One entry of a matrix `what`: `ratio` = |error| / tolerance, > 1 fails.
  void entry(const std::string& what, double ratio, const std::string& detail) {
    Kind& k = kind(what);
    ++k.checked;
    if (!(ratio <= 1.0)) ++k.failed; // NaN fails too
    if (!(ratio <= k.worst)) {
      k.worst = ratio;
      k.detail = detail;
    }
  }
  /// A problem that is not one entry.
  void note(const std::string& text) { _notes.push_back(text); }
  /// Worst ratio over every entry of every kind.
  double worst() const {
    double w = 0.0;
    for (const Kind& k : _kinds) w = std::max(w, k.worst);
    return w;
  }
  int failures() const {
    int f = static_cast<int>(_notes.size());
    for (const Kind& k : _kinds) f += k.failed;
    return f;
  }
  /// Reports everything found (one non-fatal failure) and returns whether all passed.
  bool report() const {
    std::ostringstream msg;
    for (const Kind& k : _kinds)
      if (k.failed > 0)
        msg << "\n  " << k.what << ": " << k.failed << " of " << k.checked
            << " entries fail; worst " << k.detail;
    for (const std::string& n : _notes) msg << "\n  " << n;
    if (msg.str().empty()) return true;
    ADD_FAILURE() << _check << ":" << msg.str();
    return false;
  }

 private:
  struct Kind {
    std::string what;
    int checked = 0, failed = 0;
    double worst = 0.0;
    std::string detail;
  };
  Kind& kind(const std::string& what) {
    for (Kind& k : _kinds)
      if (k.what == what) return k;
    _kinds.push_back(Kind{what});
    return _kinds.back();
  }
  std::string _check;
  std::vector<Kind> _kinds;
  std::vector<std::string> _notes;
};

/// |error| / tolerance (0 / 0 = 0).
inline double ratio(double err, double tol) {
  if (tol > 0.0) return err / tol;
  return err == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
}

inline std::string fmt_entry(const std::string& name, std::size_t i, std::size_t j) {
  return name + "(" + std::to_string(i) + "," + std::to_string(j) + ")";
}

} // namespace detail

/// Steps and tolerances of the central-difference checks.
///
/// Step: h_j = cbrt(eps) * s_j with s_j = max(base, |u_j|), base = `length` for displacements,
/// `rotation` for rotations, `temperature` for temperatures and other scalars. This balances the
/// truncation error h^2/6 |r'''| against the rounding error eps |r| / h when r varies on the scale
/// s_j (MFEM tests/unit/fem/test_calcdshape.cpp), both then ~ eps^(2/3) ~ 4e-11 relative.
///
/// Tolerance of an entry (i, j): the difference is taken at h and at 2h; D(h) - D(2h) = -3 c h^2
/// up to O(h^4), so T = |D(h) - D(2h)| / 3 estimates the truncation error of D(h) itself (exact for
/// a residual cubic in u_j; Richardson). The rounding error of D(h) is at most `round_off` eps F_i
/// / h_j with F_i = max(|r_i|, max_k |K_ik| s_k), the size of the forces row i is made of. The
/// entry passes when |K_ij - D(h)| <= 2 T + round_off eps F_i / h_j. A difference that cannot
/// resolve the entry (T above `resolution` F_i / s_j: a kink within 2h, or a step too large for
/// the residual's curvature) fails as inconclusive rather than passing on a loose tolerance.
struct FdOptions {
  double length = 0.0;      ///< scale of displacements; 0: the element's size
  double rotation = 1.0;    ///< scale of rotations (radians)
  double temperature = 1.0; ///< least scale of temperatures and other scalar DOFs
  /// rounding allowance: the residual's entries carry the rounding of this many operations
  double round_off = 100.0;
  /// largest truncation error (relative to the entry's scale F_i / s_j) that still makes a test;
  /// the kernels' suites see at most 8e-9, so no entry is ever allowed more than ~1e-7 of its
  /// scale (the tightest of the tolerances the families' own checkers used)
  double resolution = 5e-8;
  bool rows = true;     ///< check the constraint rows and multiplier columns too
  bool symmetry = true; ///< a tangent the kernel does not call unsymmetric must be symmetric
};

/// What a central-difference check measured.
struct FdReport {
  KernelResult base; ///< the evaluation at the probe's data
  std::size_t n = 0;
  std::vector<double> fd; ///< the central differences at h, n x n row-major
  double worst = 0.0;     ///< largest |analytic - difference| / tolerance
  int failures = 0;
  double fd_at(std::size_t i, std::size_t j) const { return fd[i * n + j]; }
};

/// The step scale s_j of every DOF of the probe (see FdOptions).
inline std::vector<double> fd_scales(KernelProbe& p, const FdOptions& o) {
  const double L = o.length > 0.0 ? o.length : p.size();
  std::vector<double> s;
  for (int a = 0; a < p.kernel->n_nodes(); ++a)
    for (DofType d : p.kernel->node_dofs(a)) {
      const double base = d <= DofType::U3 ? L : d <= DofType::UR3 ? o.rotation : o.temperature;
      s.push_back(std::max(base, std::abs(p.u[s.size()])));
    }
  return s;
}

namespace detail {

/// Central differences of vector functions at steps h and 2h: f1 = (f(x+h) - f(x-h)) / (2h) with
/// the steps as represented, f2 likewise at 2h.
struct Central {
  std::vector<double> f1, f2;
  double h = 0.0;
};
template <class At>
Central central(At&& at, double x, double h) {
  const double xp = x + h, xm = x - h, xp2 = x + 2.0 * h, xm2 = x - 2.0 * h;
  const std::vector<double> p = at(xp), m = at(xm), p2 = at(xp2), m2 = at(xm2);
  Central c;
  c.h = 0.5 * (xp - xm);
  c.f1.resize(p.size());
  c.f2.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    c.f1[i] = (p[i] - m[i]) / (xp - xm);
    c.f2[i] = (p2[i] - m2[i]) / (xp2 - xm2);
  }
  return c;
}

/// Judges entry (i, j) of `name`: analytic `a` against the differences (FdOptions explains).
inline void judge(Findings& found, const std::string& name, std::size_t i, std::size_t j, double a,
                  const Central& c, std::size_t k, double F, double s, const FdOptions& o) {
  const double d1 = c.f1[k], d2 = c.f2[k];
  const double trunc = std::abs(d1 - d2) / 3.0;
  const double rounding = o.round_off * kEps * F / c.h;
  const double err = std::abs(a - d1);
  std::ostringstream d;
  d.precision(10);
  if (trunc > o.resolution * F / s + rounding) {
    d << fmt_entry(name, i, j) << ": the central difference cannot resolve it (" << d1
      << " at h = " << c.h << ", " << d2 << " at 2h): a kink within 2h or a step too large";
    found.entry(name + " (unresolved)", std::numeric_limits<double>::infinity(), d.str());
    return;
  }
  const double tol = 2.0 * trunc + rounding;
  d << fmt_entry(name, i, j) << " = " << a << ", central difference " << d1 << " (h = " << c.h
    << "): |difference| " << err << " > tolerance " << tol << " (truncation " << trunc
    << ", rounding " << rounding << ")";
  found.entry(name, ratio(err, tol), d.str());
}

/// How an evaluation's status compares with the base one ("" when the same).
inline std::string status_change(const KernelResult& base, const KernelResult& x) {
  std::ostringstream d;
  if (x.n_constraints != base.n_constraints)
    d << x.n_constraints << " rows instead of " << base.n_constraints;
  else
    for (int r = 0; r < x.n_constraints; ++r)
      if (x.slot[r] != base.slot[r] || (x.compliance[r] == 0.0) != (base.compliance[r] == 0.0))
        d << "row " << r << " changed its multiplier or kind";
  if (x.status_changes != base.status_changes)
    d << (d.str().empty() ? "" : ", ") << x.status_changes << " status changes instead of "
      << base.status_changes;
  if (x.branch_changes != base.branch_changes)
    d << (d.str().empty() ? "" : ", ") << x.branch_changes << " branch changes instead of "
      << base.branch_changes;
  return d.str();
}

} // namespace detail

/// Central differences of the residual against the tangent, at the probe's trial data.
///
/// Every evaluation starts from the probe's trial history and multipliers as they are when the
/// check is called (so the kernel sees the same status each time); the probe is left as one
/// evaluation at u leaves it. Compliant rows (a force law as a row of compliance 1/k whose
/// multiplier is the force) are condensed into the tangent as c c^T / compliance, which is what
/// the residual's differences see. With `rows`, each exact row's coefficients are checked against
/// the differences of its value and d r / d lambda (the row's column, or its coefficients)
/// against differences in its multiplier. A tangent the kernel does not call unsymmetric must be
/// symmetric to the rounding of its rows. A difference that changes the element's status (its
/// rows, status or branch changes) fails: the state is too close to a switch for the check.
inline FdReport expect_fd_tangent(KernelProbe& p, const FdOptions& o = {}) {
  using detail::kEps;
  const auto keep_state = p.state;
  const auto keep_mult = p.mult;
  auto run = [&](bool tangent) {
    p.state = keep_state;
    p.mult = keep_mult;
    return p.evaluate(tangent);
  };
  const KernelResult base = run(true);
  const std::size_t n = base.n;
  detail::Findings found("the tangent against central differences");
  // the tangent the residual's differences see: compliant rows condensed
  std::vector<double> K = base.K;
  for (int row = 0; row < base.n_constraints; ++row)
    if (base.compliance[row] > 0.0)
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
          K[i * n + j] += base.dr_dlambda(row, i) * base.c(row, j) / base.compliance[row];
  const std::vector<double> s = fd_scales(p, o);
  std::vector<double> F(n, 0.0); // the size of the forces each row is made of
  for (std::size_t i = 0; i < n; ++i) {
    F[i] = std::abs(base.r[i]);
    for (std::size_t k = 0; k < n; ++k) F[i] = std::max(F[i], std::abs(K[i * n + k]) * s[k]);
  }
  std::vector<int> exact; // the exact rows
  if (o.rows)
    for (int row = 0; row < base.n_constraints; ++row)
      if (base.compliance[row] == 0.0) exact.push_back(row);
  std::vector<double> G(exact.size(), 0.0); // the size of each exact row's terms
  for (std::size_t e = 0; e < exact.size(); ++e) {
    G[e] = std::abs(base.g[exact[e]]);
    for (std::size_t k = 0; k < n; ++k) G[e] = std::max(G[e], std::abs(base.c(exact[e], k)) * s[k]);
  }
  FdReport report;
  report.base = base;
  report.n = n;
  report.fd.assign(n * n, 0.0);
  const double h_rel = std::cbrt(kEps);
  for (std::size_t j = 0; j < n; ++j) {
    std::string changed;
    auto at = [&](double value) {
      const double keep = p.u[j];
      p.u[j] = value;
      const KernelResult x = run(false);
      p.u[j] = keep;
      const std::string why = detail::status_change(base, x);
      if (!why.empty() && changed.empty()) changed = why;
      std::vector<double> f = x.r;
      for (int row : exact) f.push_back(x.n_constraints == base.n_constraints ? x.g[row] : 0.0);
      return f;
    };
    const detail::Central c = detail::central(at, p.u[j], h_rel * s[j]);
    if (!changed.empty()) {
      found.note("moving u_" + std::to_string(j) + " by up to 2h changes the element's status (" +
                 changed + "): choose a state further from the switch");
      continue;
    }
    for (std::size_t i = 0; i < n; ++i) {
      report.fd[i * n + j] = c.f1[i];
      detail::judge(found, "K", i, j, K[i * n + j], c, i, F[i], s[j], o);
    }
    for (std::size_t e = 0; e < exact.size(); ++e)
      detail::judge(found, "dg/du", static_cast<std::size_t>(exact[e]), j, base.c(exact[e], j), c,
                    n + e, G[e], s[j], o);
  }
  // d r / d lambda of every exact row
  for (int row : exact) {
    const auto slot = static_cast<std::size_t>(base.slot[row]);
    auto at = [&](double value) {
      auto mult = keep_mult;
      mult[slot] = value;
      p.state = keep_state;
      p.mult = mult;
      return p.evaluate(false).r;
    };
    const double s_l = std::max(1.0, std::abs(keep_mult[slot]));
    const detail::Central c = detail::central(at, keep_mult[slot], h_rel * s_l);
    for (std::size_t i = 0; i < n; ++i)
      detail::judge(found, "dr/dlambda", static_cast<std::size_t>(row), i, base.dr_dlambda(row, i),
                    c, i, F[i], s_l, o);
  }
  if (o.symmetry && !base.unsymmetric)
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < i; ++j) {
        const double tol = o.round_off * kEps * (F[i] / s[j] + F[j] / s[i]);
        const double err = std::abs(base.k(i, j) - base.k(j, i));
        std::ostringstream d;
        d << detail::fmt_entry("K", i, j) << " = " << base.k(i, j) << " but K(" << j << "," << i
          << ") = " << base.k(j, i) << " (tolerance " << tol << ")";
        found.entry("symmetry of a tangent not called unsymmetric", detail::ratio(err, tol),
                    d.str());
      }
  p.state = keep_state;
  p.mult = keep_mult;
  p.evaluate();
  report.worst = found.worst();
  report.failures = found.failures();
  found.report();
  return report;
}

/// Central differences of the equivalent nodal load of `load` against the load stiffness
/// (-d f_ext / du) that load() returns, at the probe's trial data; steps and tolerances as
/// expect_fd_tangent.
inline FdReport expect_fd_load_stiffness(KernelProbe& p, const DistributedLoad& load,
                                         double magnitude, double sink = 0.0,
                                         const FdOptions& o = {}) {
  std::vector<double> K;
  const std::vector<double> f0 = p.load(load, magnitude, sink, &K);
  const std::size_t n = f0.size();
  const std::vector<double> s = fd_scales(p, o);
  std::vector<double> F(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    F[i] = std::abs(f0[i]);
    for (std::size_t k = 0; k < n; ++k) F[i] = std::max(F[i], std::abs(K[i * n + k]) * s[k]);
  }
  detail::Findings found("the load stiffness against central differences");
  FdReport report;
  report.n = n;
  report.fd.assign(n * n, 0.0);
  for (std::size_t j = 0; j < n; ++j) {
    auto at = [&](double value) {
      const double keep = p.u[j];
      p.u[j] = value;
      std::vector<double> f = p.load(load, magnitude, sink);
      p.u[j] = keep;
      for (double& v : f) v = -v; // the stiffness is -d f_ext / du
      return f;
    };
    const detail::Central c = detail::central(at, p.u[j], std::cbrt(detail::kEps) * s[j]);
    for (std::size_t i = 0; i < n; ++i) {
      report.fd[i * n + j] = c.f1[i];
      detail::judge(found, "load stiffness", i, j, K[i * n + j], c, i, F[i], s[j], o);
    }
  }
  report.worst = found.worst();
  report.failures = found.failures();
  found.report();
  return report;
}

namespace detail {

/// Bitwise comparison of two arrays (NaN equal to the same NaN, -0 unequal to +0).
template <class T>
void same_bits(Findings& found, const std::string& what, const std::vector<T>& a,
               const std::vector<T>& b) {
  if (a.size() != b.size()) {
    found.note(what + ": " + std::to_string(b.size()) + " values instead of " +
               std::to_string(a.size()));
    return;
  }
  for (std::size_t i = 0; i < a.size(); ++i) {
    bool same = true;
    if constexpr (std::is_same_v<T, double>)
      same = std::bit_cast<std::uint64_t>(a[i]) == std::bit_cast<std::uint64_t>(b[i]);
    else
      same = a[i] == b[i];
    if (!same) {
      std::ostringstream d;
      d.precision(17);
      d << what << "[" << i << "] = " << b[i] << " the second time, " << a[i] << " the first";
      found.note(d.str());
      return;
    }
  }
}

/// Everything one evaluation returned, entry by entry.
inline void same_result(Findings& found, const KernelResult& a, const KernelResult& b) {
  same_bits(found, "residual", a.r, b.r);
  same_bits(found, "tangent", a.K, b.K);
  same_bits(found, "constraint rows", std::vector<int>{a.n_constraints},
            std::vector<int>{b.n_constraints});
  same_bits(found, "row multipliers", a.slot, b.slot);
  same_bits(found, "row values", a.g, b.g);
  same_bits(found, "row compliances", a.compliance, b.compliance);
  same_bits(found, "row coefficients", a.coeff, b.coeff);
  same_bits(found, "row columns", a.column, b.column);
  same_bits(found, "flags (columns, unsymmetric, stiffness changed, friction)",
            std::vector<int>{a.has_columns, a.unsymmetric, a.stiffness_changed, a.friction},
            std::vector<int>{b.has_columns, b.unsymmetric, b.stiffness_changed, b.friction});
  same_bits(found, "status and branch changes",
            std::vector<int>{a.status_changes, a.branch_changes},
            std::vector<int>{b.status_changes, b.branch_changes});
  same_bits(found, "time-increment request", std::vector<double>{a.dt_ratio},
            std::vector<double>{b.dt_ratio});
}

} // namespace detail

/// The abandoned attempt of expect_revert_is_exact.
struct RevertOptions {
  /// its trial values; empty: the increment reversed, u0 - (u - u0), plus 1 % of each DOF's
  /// scale (so that it differs from u even where u = u0)
  std::vector<double> other_u;
  int iterations = 2; ///< evaluations in it (the solver moves the multipliers in between)
};

/// A cut-back discards an attempt exactly: evaluate from the committed history at u (trial =
/// committed), abandon another attempt (evaluations at other values, the multipliers moved as a
/// solver would), revert (trial = committed) and evaluate at u again. The residual, tangent, rows,
/// flags, trial history and trial multipliers must be identical to the bit, and the committed data
/// untouched. The probe is left as the first evaluation left it. This is what fails when a kernel
/// keeps hidden mutable data (a `mutable` cache, a static) or writes into committed history.
inline void expect_revert_is_exact(KernelProbe& p, const RevertOptions& o = {}) {
  detail::Findings found("revert, then evaluate again");
  const auto committed_u = p.u0;
  const auto committed_state = p.state0;
  const auto committed_mult = p.mult0;
  const auto u = p.u;
  p.revert();
  const KernelResult first = p.evaluate();
  const auto state_first = p.state;
  const auto mult_first = p.mult;
  // the abandoned attempt
  std::vector<double> other = o.other_u;
  if (other.empty()) {
    const std::vector<double> s = fd_scales(p, FdOptions{});
    other.resize(u.size());
    for (std::size_t j = 0; j < u.size(); ++j)
      other[j] = p.u0[j] - (u[j] - p.u0[j]) + 0.01 * s[j] * std::sin(1.0 + 3.0 * j);
  }
  p.u = other;
  for (int it = 0; it < o.iterations; ++it) {
    const KernelResult x = p.evaluate();
    for (int row = 0; row < x.n_constraints; ++row) {
      double& l = p.mult[static_cast<std::size_t>(x.slot[row])];
      l += 0.5 * (1.0 + std::abs(l));
    }
    for (std::size_t j = 0; j < p.u.size(); ++j) p.u[j] += 0.5 * (other[j] - u[j]);
  }
  p.u = u;
  p.revert();
  const KernelResult second = p.evaluate();
  detail::same_result(found, first, second);
  detail::same_bits(found, "trial history", state_first, p.state);
  detail::same_bits(found, "trial multipliers", mult_first, p.mult);
  detail::same_bits(found, "committed values (u_start)", committed_u, p.u0);
  detail::same_bits(found, "committed history", committed_state, p.state0);
  detail::same_bits(found, "committed multipliers", committed_mult, p.mult0);
  found.report();
}

/// The rigid motion of expect_rigid_body_invariance.
struct RigidBodyOptions {
  /// translation, in element sizes; components on DOFs the element lacks are dropped
  Vec3 translation{0.31, -0.17, 0.23};
  /// also rotate (which rotation follows from the context, see the table at the top); elements
  /// that carry only some translations of a node (SPRING2, a spring on DOF 1) cannot rotate
  bool rotate = true;
  double angle = 0.7;          ///< radians
  Vec3 axis{0.6, -0.48, 0.64}; ///< 3-D rotation axis (2-D: z)
  /// move the element itself (X) instead of its body (u): for elements without displacements
  /// (heat transfer), whose residual must not depend on where the element is
  bool frame = false;
  /// NLGEOM: turn the reference state (displacements zero) rather than the deformed one, for
  /// elements whose forces turn with the body only from there (see the table at the top); the
  /// residual alone is compared
  bool from_reference = false;
  /// rounding allowance: the residual carries the rounding of this many operations on coordinates
  double round_off = 1000.0;
};

/// A rigid motion changes nothing it must not (the table at the top of this file: which families
/// support which motion). Translation: residual, tangent and row values unchanged. Rotation:
/// small strain, an infinitesimal rotation field w x X (rotations += w) leaves the residual and
/// tangent unchanged; NLGEOM, the deformed state turned by R: the residual turns (R r per node)
/// and the tangent too (P K P^T); with rotational DOFs from the reference state only, where the
/// residual must stay zero; `frame`: the element itself moved, r and K unchanged (scalar DOFs) or
/// turned. Every evaluation starts from the probe's trial history, as in expect_fd_tangent.
///
/// Tolerance: a residual computed from coordinates of size |x| rounds at eps |x| |K| per
/// operation; the allowance is round_off eps (|K| |x| + |r|), and round_off eps |K| (1 + |x| / L)
/// for the tangent (|x| the largest coordinate in play, L the element size).
inline void expect_rigid_body_invariance(KernelProbe& p, const RigidBodyOptions& o = {}) {
  using detail::kEps;
  detail::Findings found("rigid-body invariance");
  const int nn = p.kernel->n_nodes();
  struct NodeDofs {
    std::array<int, 3> t{-1, -1, -1}, r{-1, -1, -1};
  };
  std::vector<NodeDofs> dofs(static_cast<std::size_t>(nn));
  int k = 0;
  bool three = false, rotations = false, partial = false;
  for (int a = 0; a < nn; ++a) {
    for (DofType d : p.kernel->node_dofs(a)) {
      const int c = static_cast<int>(d);
      if (d <= DofType::U3) dofs[a].t[c] = k;
      if (d >= DofType::UR1 && d <= DofType::UR3) dofs[a].r[c - 3] = k;
      ++k;
    }
    three |= dofs[a].t[2] >= 0 || dofs[a].r[0] >= 0 || dofs[a].r[1] >= 0;
    rotations |= dofs[a].r[0] >= 0 || dofs[a].r[1] >= 0 || dofs[a].r[2] >= 0;
  }
  const ElementTypeInfo& info = element_info(p.kernel->type());
  const bool axisymmetric = p.ctx.space == ModelSpace::Axisymmetric ||
                            info.plane == PlaneKind::Axisymmetric ||
                            info.space == SpaceRequirement::Axisymmetric;
  const bool frame_3d = o.frame && info.space != SpaceRequirement::Planar &&
                        p.ctx.space == ModelSpace::ThreeD && info.plane == PlaneKind::None;
  const bool planar = o.frame ? !frame_3d : !three;
  const int dim = planar ? 2 : 3;
  for (int a = 0; a < nn; ++a) {
    int carried = 0;
    for (int i = 0; i < dim; ++i) carried += dofs[a].t[i] >= 0;
    partial |= carried > 0 && carried < dim;
  }
  const auto keep_state = p.state;
  const auto keep_mult = p.mult;
  const auto keep_u = p.u;
  const auto keep_X = p.X;
  auto run = [&] {
    p.state = keep_state;
    p.mult = keep_mult;
    return p.evaluate();
  };
  const KernelResult base = run();
  const std::size_t n = base.n;
  const double L = p.size();
  // the largest coordinate in play (reference and current, before and after the motion)
  auto coordinate_size = [&] {
    double x = L;
    for (int a = 0; a < nn; ++a) {
      Vec3 y = p.X[a];
      x = std::max(x, std::hypot(y[0], y[1], y[2]));
      for (int i = 0; i < 3; ++i)
        if (dofs[a].t[i] >= 0) y[i] += p.u[dofs[a].t[i]];
      x = std::max(x, std::hypot(y[0], y[1], y[2]));
    }
    return x;
  };
  const double x_before = coordinate_size();
  auto largest = [](const std::vector<double>& v) {
    double m = 0.0;
    for (double x : v) m = std::max(m, std::abs(x));
    return m;
  };
  // compares a moved evaluation with the one before the motion, `ref`: the expectation is
  // P r, P K P^T (P = identity when `turn` is null)
  auto compare = [&](const std::string& motion, const KernelResult& moved,
                     const Eigen::Matrix3d* turn, bool tangent, const KernelResult& ref) {
    const double x = std::max(x_before, coordinate_size());
    const double kmax = largest(ref.K), rmax = largest(ref.r), cmax = largest(ref.coeff);
    Eigen::MatrixXd P =
        Eigen::MatrixXd::Identity(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    if (turn)
      for (int a = 0; a < nn; ++a)
        for (const auto& triple : {dofs[a].t, dofs[a].r})
          for (int i = 0; i < dim; ++i)
            for (int j = 0; j < dim; ++j)
              if (triple[i] >= 0 && triple[j] >= 0) P(triple[i], triple[j]) = (*turn)(i, j);
    const Eigen::VectorXd r0 = Eigen::Map<const Eigen::VectorXd>(ref.r.data(), n);
    const Eigen::VectorXd want = P * r0;
    const double tol_r = o.round_off * kEps * (kmax * x + rmax);
    for (std::size_t i = 0; i < n; ++i) {
      const double err = std::abs(moved.r[i] - want[static_cast<Eigen::Index>(i)]);
      std::ostringstream d;
      d << "r(" << i << ") = " << moved.r[i] << " after the " << motion << ", expected "
        << want[static_cast<Eigen::Index>(i)] << " (tolerance " << tol_r << ")";
      found.entry("residual after the " + motion, detail::ratio(err, tol_r), d.str());
    }
    if (tangent && !ref.K.empty()) {
      const Eigen::MatrixXd K0 =
          Eigen::Map<const Eigen::Matrix<double, -1, -1, Eigen::RowMajor>>(ref.K.data(), n, n);
      const Eigen::MatrixXd wantK = P * K0 * P.transpose();
      const double tol_k = o.round_off * kEps * kmax * (1.0 + x / L);
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) {
          const double w = wantK(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
          const double err = std::abs(moved.k(i, j) - w);
          std::ostringstream d;
          d << detail::fmt_entry("K", i, j) << " = " << moved.k(i, j) << " after the " << motion
            << ", expected " << w << " (tolerance " << tol_k << ")";
          found.entry("tangent after the " + motion, detail::ratio(err, tol_k), d.str());
        }
    }
    if (moved.n_constraints != ref.n_constraints) {
      found.note("the " + motion + " changed the number of constraint rows");
    } else if (!turn) {
      const double tol_g = o.round_off * kEps * (cmax * x + 1.0);
      for (int row = 0; row < ref.n_constraints; ++row) {
        const double err = std::abs(moved.g[row] - ref.g[row]);
        std::ostringstream d;
        d << "g(" << row << ") = " << moved.g[row] << " after the " << motion << ", " << ref.g[row]
          << " before (tolerance " << tol_g << ")";
        found.entry("row values after the " + motion, detail::ratio(err, tol_g), d.str());
      }
    }
  };
  // translation
  Vec3 c{};
  for (int i = 0; i < 3; ++i) c[i] = o.translation[i] * L;
  if (axisymmetric) c = {0.0, c[1], 0.0};
  if (planar) c[2] = 0.0;
  if (o.frame) {
    for (Vec3& x : p.X)
      for (int i = 0; i < 3; ++i) x[i] += c[i];
  } else {
    for (int a = 0; a < nn; ++a)
      for (int i = 0; i < 3; ++i)
        if (dofs[a].t[i] >= 0) p.u[dofs[a].t[i]] += c[i];
  }
  compare(o.frame ? "translation of the element" : "translation", run(), nullptr, true, base);
  p.u = keep_u;
  p.X = keep_X;
  // rotation
  if (o.rotate && !axisymmetric) {
    Eigen::Vector3d axis(o.axis[0], o.axis[1], o.axis[2]);
    if (planar) axis = Eigen::Vector3d::UnitZ();
    axis.normalize();
    const Eigen::Matrix3d R = Eigen::AngleAxisd(o.angle, axis).toRotationMatrix();
    const Eigen::Vector3d w = o.angle * axis;
    auto vec = [](const Vec3& v) { return Eigen::Vector3d(v[0], v[1], v[2]); };
    auto get = [&](const std::array<int, 3>& t, const std::vector<double>& v) {
      Eigen::Vector3d x = Eigen::Vector3d::Zero();
      for (int i = 0; i < 3; ++i)
        if (t[i] >= 0) x[i] = v[t[i]];
      return x;
    };
    auto put = [&](const std::array<int, 3>& t, const Eigen::Vector3d& x) {
      for (int i = 0; i < 3; ++i)
        if (t[i] >= 0) p.u[t[i]] = x[i];
    };
    const Eigen::Vector3d cc = vec(c);
    if (partial) {
      found.note("cannot rotate an element that carries only some translations of a node: "
                 "call with rotate = false");
    } else if (o.frame) {
      if (rotations) {
        found.note("a frame rotation of an element with rotational DOFs is not supported");
      } else {
        for (int a = 0; a < nn; ++a) {
          const Eigen::Vector3d x = R * vec(keep_X[a]) + cc;
          p.X[a] = {x[0], x[1], x[2]};
          put(dofs[a].t, R * get(dofs[a].t, keep_u));
        }
        compare("rotation of the element", run(), &R, true, base);
      }
    } else if (!p.ctx.nlgeom) {
      for (int a = 0; a < nn; ++a) {
        put(dofs[a].t, get(dofs[a].t, keep_u) + w.cross(vec(p.X[a])));
        put(dofs[a].r, get(dofs[a].r, keep_u) + w);
      }
      compare("infinitesimal rotation", run(), nullptr, true, base);
    } else if (rotations || o.from_reference) {
      // from the reference state: displacements and rotations zero, other DOFs (temperatures)
      // as they are
      bool committed_zero = true;
      std::vector<double> reference = keep_u;
      for (int a = 0; a < nn; ++a)
        for (const auto& triple : {dofs[a].t, dofs[a].r})
          for (int i : triple)
            if (i >= 0) {
              committed_zero &= p.u0[i] == 0.0;
              reference[i] = 0.0;
            }
      if (rotations && !committed_zero) {
        found.note("a finite rotation of an element with rotational DOFs is checked from the "
                   "reference state: u_start must be zero (no committed rotations)");
      } else {
        p.u = reference;
        const KernelResult ref = run();
        if (rotations && largest(ref.r) > o.round_off * kEps * largest(ref.K) * x_before)
          found.note("the residual at the reference state is not zero: a finite rotation of an "
                     "element with rotational DOFs is checked without loads");
        for (int a = 0; a < nn; ++a) {
          put(dofs[a].t, R * vec(p.X[a]) + cc - vec(p.X[a]));
          put(dofs[a].r, w);
        }
        // only the residual is compared: the conjugate moments of a rotation vector do not
        // simply turn, nor does a stiffness fixed on the reference configuration (hourglass)
        compare("finite rotation from the reference state", run(), &R, false, ref);
      }
    } else {
      for (int a = 0; a < nn; ++a) {
        const Eigen::Vector3d X = vec(p.X[a]);
        put(dofs[a].t, R * (X + get(dofs[a].t, keep_u)) + cc - X);
      }
      compare("finite rotation", run(), &R, true, base);
    }
    p.u = keep_u;
    p.X = keep_X;
  }
  p.state = keep_state;
  p.mult = keep_mult;
  p.evaluate();
  found.report();
}

} // namespace gapfem::test
