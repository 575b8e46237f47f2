// Material Rayleigh damping (*DAMPING, ALPHA=, BETA= in the *MATERIAL; docs/theory/dynamics.md,
// "Rayleigh damping") in free vibration, against closed forms.
//
// Every model starts from the static deflection under a tip force (step 1, *STATIC) and is
// released in step 2 (*DYNAMIC, DIRECT, ALPHA=0: the trapezoidal rule, no algorithmic damping, so
// all the decay measured is Rayleigh's). The truss mass is lumped (rho A L / 2 per node), so
// M, K and C = alpha M + beta K of the model are known by hand.
//
// Continuous closed form. A mode of frequency w with C = alpha M + beta K has the damping ratio
//     zeta = alpha / (2 w) + beta w / 2,
// poles s = -zeta w +- i w_d, w_d = w sqrt(1 - zeta^2), and from q(0) = q0, q'(0) = 0
//     q(t) = q0 (s1 e^{s2 t} - s2 e^{s1 t}) / (s1 - s2).
// Discrete closed form. For a linear system Newmark's average acceleration (beta = 1/4,
// gamma = 1/2) with consistent accelerations is the trapezoidal rule on x' = A x, x = (q, q'):
// x_{n+1} = (I - dt A / 2)^-1 (I + dt A / 2) x_n, whose eigenvalues are z = (1 + s dt/2) /
// (1 - s dt/2). So the computed history is exactly q_n = q0 (s1 z2^n - s2 z1^n) / (s1 - s2): the
// test holds it to 1e-9 of q0 (rounding of a few hundred linear solves). Rayleigh damping keeps
// the modes uncoupled (C is a combination of M and K), so a model's modal coordinates
// q_i = phi_i^T M u (M-normalised modes) each follow this with their own w_i and zeta_i.
// Measured decay and period. The poles are read back from the history itself (a two-pole
// recurrence q_{n+1} = p q_n - r q_{n-1} fitted by least squares, z = p/2 +- i sqrt(r - p^2/4),
// s = ln z / dt) and compared with the continuous zeta and w_d. The trapezoidal rule's
// ln z = s dt + (s dt)^3 / 12 + ... makes the measured s = s (1 - (w dt)^2 (1 + 2 i zeta) / 12):
// w_d off by eps = (w dt)^2 / 12 relative and zeta by 2 eps; the tolerances are 2 eps and 3 eps.
#include "test_util.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <numbers>

namespace gapfem {
namespace {

using test::run_deck;
using cplx = std::complex<double>;

/// A bar along x of `n_el` T3D2 of total length 1, E = 1000, A = 0.5, rho = 2, fixed at node 1,
/// tip force 5 in step 1, released in step 2 (trapezoidal rule, dt, `periods` long).
std::string bar_deck(int n_el, const std::string& damping, double dt, double period) {
  std::string nodes, elems;
  for (int i = 0; i <= n_el; ++i) nodes += fmt::format("{}, {}, 0., 0.\n", i + 1, double(i) / n_el);
  for (int e = 1; e <= n_el; ++e) elems += fmt::format("{}, {}, {}\n", e, e, e + 1);
  return fmt::format(R"(*HEADING
Rayleigh damping: a bar released from its static deflection
*NODE, NSET=ALL
{}*ELEMENT, TYPE=T3D2, ELSET=BAR
{}*MATERIAL, NAME=M
*ELASTIC
1000., 0.
*DENSITY
2.
{}*SOLID SECTION, ELSET=BAR, MATERIAL=M
0.5
*BOUNDARY
1, 1, 3
ALL, 2, 3
*STEP
*STATIC
1., 1.
*CLOAD
{}, 1, 5.
*END STEP
*STEP, INC=100000, AMPLITUDE=STEP
*DYNAMIC, DIRECT, ALPHA=0.
{}, {}
*CLOAD, OP=NEW
*NODE PRINT, FREQUENCY=1
U
*END STEP
)",
                     nodes, elems, damping, n_el + 1, dt, period);
}

/// The x displacements of every node at the end of each increment of step 2, and the static
/// deflection it starts from (as row 0).
std::vector<std::vector<double>> histories(const JobResult& r, int n_nodes) {
  std::vector<std::vector<double>> h;
  auto row = [&](const Frame& f) {
    std::vector<double> u;
    for (int a = 1; a <= n_nodes; ++a) u.push_back(test::U(r, f, a)[0]);
    return u;
  };
  h.push_back(row(test::last_frame(r, 1)));
  for (const Frame& f : r.frames)
    if (f.step == 2 && f.increment > 0) h.push_back(row(f));
  return h;
}

/// The poles s1 = -zeta w + i w_d, s2 = conj(s1) of a mode.
struct Poles {
  cplx s1, s2;
};
Poles poles(double w, double zeta) {
  const cplx s1(-zeta * w, w * std::sqrt(1.0 - zeta * zeta));
  return {s1, std::conj(s1)};
}

/// The trapezoidal rule's q_n from q(0) = q0, q'(0) = 0.
double discrete(const Poles& p, double q0, double dt, int n) {
  const cplx z1 = (1.0 + p.s1 * dt / 2.0) / (1.0 - p.s1 * dt / 2.0);
  const cplx z2 = (1.0 + p.s2 * dt / 2.0) / (1.0 - p.s2 * dt / 2.0);
  return (q0 * (p.s1 * std::pow(z2, n) - p.s2 * std::pow(z1, n)) / (p.s1 - p.s2)).real();
}

/// The damping ratio and damped frequency a history shows (module comment).
struct Measured {
  double zeta = 0.0, wd = 0.0;
};
Measured measure(const std::vector<double>& q, double dt) {
  Eigen::MatrixXd A(q.size() - 2, 2);
  Eigen::VectorXd b(q.size() - 2);
  for (std::size_t n = 1; n + 1 < q.size(); ++n) {
    A(n - 1, 0) = q[n];
    A(n - 1, 1) = -q[n - 1];
    b(n - 1) = q[n + 1];
  }
  const Eigen::Vector2d pr = A.colPivHouseholderQr().solve(b);
  const cplx z(pr(0) / 2.0, std::sqrt(pr(1) - pr(0) * pr(0) / 4.0));
  const cplx s = std::log(z) / dt;
  return {-s.real() / std::abs(s), s.imag()};
}

void expect_mode(const std::vector<double>& q, double w, double zeta, double dt,
                 const std::string& what) {
  SCOPED_TRACE(what);
  const Poles p = poles(w, zeta);
  for (std::size_t n = 0; n < q.size(); ++n)
    ASSERT_NEAR(q[n], discrete(p, q[0], dt, static_cast<int>(n)), 1e-9 * std::abs(q[0]))
        << "increment " << n;
  const double eps = w * dt * (w * dt) / 12.0;
  const Measured m = measure(q, dt);
  EXPECT_NEAR(m.zeta, zeta, 3.0 * eps * zeta);
  EXPECT_NEAR(m.wd, w * std::sqrt(1.0 - zeta * zeta), 2.0 * eps * w);
  // the decay is Rayleigh's, not the integrator's: without the damping it would be none
  EXPECT_GT(m.zeta, 0.5 * zeta);
}

// One DOF: the bar as one element, k = EA/L = 500, m = rho A L / 2 = 0.5 at the tip, w =
// sqrt(1000). ALPHA = 0.6 and BETA = 1e-3 give zeta = 0.6 / (2 w) + 1e-3 w / 2 = 0.00949 + 0.01581
// = 0.0253.
TEST(VerificationRayleigh, SdofDecayAndPeriodAreRayleighs) {
  const double w = std::sqrt(1000.0), T = 2.0 * std::numbers::pi / w, dt = T / 100.0;
  const double alpha = 0.6, beta = 1e-3, zeta = alpha / (2.0 * w) + beta * w / 2.0;
  const JobResult r =
      run_deck(bar_deck(1, fmt::format("*DAMPING, ALPHA={}, BETA={}\n", alpha, beta), dt, 4.0 * T));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  std::vector<double> q;
  for (const auto& u : histories(r, 2)) q.push_back(u[1]);
  ASSERT_EQ(q.size(), 401u);
  EXPECT_NEAR(q[0], 0.01, 1e-12); // F / k
  expect_mode(q, w, zeta, dt, "one DOF");
  for (const IncrementInfo& i : r.increments) EXPECT_LE(i.iterations, 1); // linear: one iteration
  // the energy output counts the damping: ALLVD grows, ETOTAL stays (trapezoidal rule: no
  // algorithmic dissipation; 1e-9 of the largest energy, the rounding of the sums)
  double allvd = 0.0;
  for (const Frame& f : r.frames) {
    if (f.step != 2 || f.increment == 0 || !f.energies) continue;
    EXPECT_NEAR(f.energies->etotal(), 0.0, 1e-9 * f.energies->scale()) << f.increment;
    EXPECT_GT(f.energies->allvd, allvd) << f.increment;
    allvd = f.energies->allvd;
  }
  EXPECT_GT(allvd, 0.5 * 0.5 * 500.0 * 0.01 * 0.01); // most of k u0^2 / 2 is gone after 4 periods
  // each part alone: mass-proportional zeta = alpha / (2 w), stiffness-proportional beta w / 2
  const JobResult ra = run_deck(bar_deck(1, "*DAMPING, ALPHA=0.6\n", dt, 4.0 * T));
  const JobResult rb = run_deck(bar_deck(1, "*DAMPING, BETA=1e-3\n", dt, 4.0 * T));
  ASSERT_EQ(ra.exit_code, 0) << ra.error;
  ASSERT_EQ(rb.exit_code, 0) << rb.error;
  std::vector<double> qa, qb;
  for (const auto& u : histories(ra, 2)) qa.push_back(u[1]);
  for (const auto& u : histories(rb, 2)) qb.push_back(u[1]);
  expect_mode(qa, w, alpha / (2.0 * w), dt, "ALPHA alone");
  expect_mode(qb, w, beta * w / 2.0, dt, "BETA alone");
}

// Two modes: the bar as 4 elements (k_e = 2000, nodal masses 0.25 and 0.125 at the tip). alpha
// and beta are chosen for zeta_1 = 0.02, zeta_2 = 0.05 at the model's own w_1, w_2 (computed here
// from M and K); the static deflection excites every mode, the modal coordinates phi_i^T M u are
// read from the computed displacements and each must decay with its own zeta_i.
TEST(VerificationRayleigh, TwoModesDecayWithTheirOwnDampingRatios) {
  const int ne = 4, nd = ne; // free DOFs: nodes 2..5, x
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(nd, nd), M = Eigen::MatrixXd::Zero(nd, nd);
  const double ke = 1000.0 * 0.5 * ne, me = 2.0 * 0.5 / ne;
  for (int e = 0; e < ne; ++e) { // element e joins DOF e-1 (node 1 fixed when e = 0) and e
    const int a = e - 1, b = e;
    K(b, b) += ke;
    M(b, b) += me / 2.0;
    if (a >= 0) {
      K(a, a) += ke;
      K(a, b) -= ke;
      K(b, a) -= ke;
      M(a, a) += me / 2.0;
    }
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(K, M);
  const double w1 = std::sqrt(eig.eigenvalues()(0)), w2 = std::sqrt(eig.eigenvalues()(1));
  const double z1 = 0.02, z2 = 0.05;
  // zeta_i = alpha / (2 w_i) + beta w_i / 2 for i = 1, 2
  const double beta = 2.0 * (z2 * w2 - z1 * w1) / (w2 * w2 - w1 * w1);
  const double alpha = 2.0 * w1 * z1 - beta * w1 * w1;
  ASSERT_GT(alpha, 0.0);
  ASSERT_GT(beta, 0.0);
  // whole increments only (a shorter last one would leave the closed form's fixed dt)
  const double dt = 2.0 * std::numbers::pi / w2 / 60.0;
  const double period = dt * std::ceil(3.0 * 2.0 * std::numbers::pi / w1 / dt);
  const JobResult r = run_deck(bar_deck(
      ne, fmt::format("*DAMPING, ALPHA={:.17g}, BETA={:.17g}\n", alpha, beta), dt, period));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto h = histories(r, ne + 1);
  ASSERT_GT(h.size(), 100u);
  std::vector<double> q1, q2;
  for (const auto& u : h) {
    const Eigen::Map<const Eigen::VectorXd> x(u.data() + 1, nd); // nodes 2..5
    q1.push_back(eig.eigenvectors().col(0).dot(M * x));
    q2.push_back(eig.eigenvectors().col(1).dot(M * x));
  }
  expect_mode(q1, w1, z1, dt, "mode 1");
  expect_mode(q2, w2, z2, dt, "mode 2");
  // the measured ratios differ as Rayleigh predicts (not one ratio for every mode)
  EXPECT_GT(measure(q2, dt).zeta, 2.0 * measure(q1, dt).zeta);
}

} // namespace
} // namespace gapfem
