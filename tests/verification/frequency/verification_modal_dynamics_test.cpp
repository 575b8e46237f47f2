// *STEADY STATE DYNAMICS and *MODAL DYNAMIC against closed forms (docs/theory/modal_dynamics.md).
// SDOF: m = 1 (MASS) on k = 100 (SPRING1), omega_n = 10, f_n = 1.5915494309, F = 1 along x,
// modal damping zeta = 0.05 (one mode: exact). With u(t) = Re(U e^{i Omega t}):
//   U = (F / k) (1 - r^2 - 2 i zeta r) / D,  D = (1 - r^2)^2 + (2 zeta r)^2,  r = Omega / omega_n;
// at resonance U = -i F / (2 zeta k) = -0.1 i (amplitude 0.1, phase -90 degrees).
// Two masses (k1 = 1000 ground-1, k2 = 500 1-2, m1 = 2, m2 = 1; the frequency test's): the
// modal response with both modes equals the direct solve (K - Omega^2 M + i Omega C) U = F with
// C = M Phi diag(2 zeta_k omega_k / m_k) Phi^T M (zeta 0.02, 0.05), computed here by a complex
// 2 x 2 solve at each reported frequency.
// Base motion: a base acceleration a_g moves the held DOFs; the relative response of the SDOF is
// that of the load -m a_g.
// Modal dynamic, SDOF from rest: a step load F (a constant amplitude) gives
//   u(t) = F / k [1 - e^{-zeta omega t} (cos omega_d t + zeta / sqrt(1 - zeta^2) sin omega_d t)],
// a ramp F t / t_r to t_r = 0.5 then F: u = F / (k t_r) [R(t) - R(t - t_r)], R(s) = 0 for s <= 0,
//   R(s) = s - 2 zeta / omega + e^{-zeta omega s} (2 zeta / omega cos omega_d s
//          - (1 - 2 zeta^2) / omega_d sin omega_d s);
// the exact integration of a piecewise-linear load reproduces both to rounding (1e-8 F / k), and
// the spring's force (*EL PRINT S: the element output of the response) is k u.
#include "test_util.hpp"
#include "verification/frequency/two_masses.hpp"

#include <cmath>
#include <complex>
#include <fmt/format.h>
#include <gtest/gtest.h>

namespace gapfem {
namespace {

using Complex = std::complex<double>;
constexpr double kPi = 3.14159265358979323846;

std::string sdof(const std::string& model_extra, const std::string& step) {
  return "*HEADING\nSDOF\n*NODE\n1, 0., 0., 0.\n*ELEMENT, TYPE=SPRING1, ELSET=K\n1, 1\n"
         "*SPRING, ELSET=K\n1\n100.\n*ELEMENT, TYPE=MASS, ELSET=M\n2, 1\n*MASS, ELSET=M\n1.\n"
         "*BOUNDARY\n1, 2, 3\n" +
         model_extra + "*STEP\n*FREQUENCY\n1\n*END STEP\n" + step;
}

std::vector<const Frame*> frames_of(const JobResult& r, int step) {
  std::vector<const Frame*> out;
  for (const Frame& f : r.frames)
    if (f.step == step) out.push_back(&f);
  return out;
}

Complex sdof_response(double f, double force = 1.0) {
  const double r = 2 * kPi * f / 10.0, zeta = 0.05;
  return force / 100.0 / Complex(1 - r * r, 2 * zeta * r);
}

Complex harmonic_u(const JobResult& r, const Frame& f, Label node, int c) {
  const NodeId n = r.model->mesh.find_node(node);
  return {f.nodes.U.at(n)[c], f.harmonic->U.at(n)[c]};
}

TEST(VerificationModalDynamics, SdofSteadyStateOverARange) {
  const JobResult r = test::run_deck(
      sdof("", "*STEP\n*STEADY STATE DYNAMICS, INTERVAL=RANGE, FREQUENCY SCALE=LINEAR\n0.5, 3.0, "
               "6, 1.\n*MODAL DAMPING\n1, 1, 0.05\n*CLOAD\n1, 1, 1.\n*END STEP\n"));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto fr = frames_of(r, 2);
  ASSERT_EQ(fr.size(), 6u);
  for (std::size_t j = 0; j < fr.size(); ++j) {
    ASSERT_TRUE(fr[j]->harmonic.has_value());
    const double f = fr[j]->harmonic->frequency;
    EXPECT_NEAR(f, 0.5 + 0.5 * j, 1e-12);
    const Complex want = sdof_response(f), got = harmonic_u(r, *fr[j], 1, 0);
    EXPECT_NEAR(std::abs(got - want), 0.0, 1e-9 * std::abs(want)) << "f " << f;
  }
}

TEST(VerificationModalDynamics, EigenfrequencyIntervalsHitTheResonance) {
  const JobResult r = test::run_deck(
      sdof("", "*STEP\n*STEADY STATE DYNAMICS\n1.0, 2.0, 3\n*MODAL DAMPING\n1, 1, 0.05\n*CLOAD\n1, "
               "1, 1.\n*END STEP\n"));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto fr = frames_of(r, 2);
  // [1, f_n] and [f_n, 2] with 3 points each, f_n shared: 5 points
  ASSERT_EQ(fr.size(), 5u);
  const double fn = 10.0 / (2 * kPi);
  EXPECT_NEAR(fr[2]->harmonic->frequency, fn, 1e-9 * fn);
  const Complex u = harmonic_u(r, *fr[2], 1, 0);
  EXPECT_NEAR(u.real(), 0.0, 1e-9);
  EXPECT_NEAR(u.imag(), -0.1, 1e-9);
  for (const Frame* f : fr) {
    const Complex want = sdof_response(f->harmonic->frequency);
    EXPECT_NEAR(std::abs(harmonic_u(r, *f, 1, 0) - want), 0.0, 1e-9 * std::abs(want));
  }
}

TEST(VerificationModalDynamics, TwoMassesEqualTheDirectComplexSolve) {
  const std::string deck = std::string("*HEADING\nTwo masses\n") + test::kTwoMassesModel + R"(*STEP
*FREQUENCY
2
*END STEP
*STEP
*STEADY STATE DYNAMICS, INTERVAL=RANGE, FREQUENCY SCALE=LINEAR
1., 6., 11
*MODAL DAMPING
1, 1, 0.02
2, 2, 0.05
*CLOAD
2, 1, 1.
*END STEP
)";
  const JobResult r = test::run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto fr = frames_of(r, 2);
  ASSERT_EQ(fr.size(), 11u);
  // modes: lambda 250 (phi (0.5, 1), m 1.5), 1000 (phi (1, -1), m 3)
  const double w1 = std::sqrt(250.0), w2 = std::sqrt(1000.0);
  const double phi[2][2] = {{0.5, 1.0}, {1.0, -1.0}}, mk[2] = {1.5, 3.0},
               c[2] = {2 * 0.02 * w1, 2 * 0.05 * w2};
  const double M[2] = {2.0, 1.0};
  double C[2][2] = {};
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) C[i][j] += M[i] * phi[k][i] * c[k] / mk[k] * phi[k][j] * M[j];
  for (const Frame* f : fr) {
    const double W = 2 * kPi * f->harmonic->frequency;
    const Complex a11(1500.0 - W * W * 2.0, W * C[0][0]), a12(-500.0, W * C[0][1]),
        a21(-500.0, W * C[1][0]), a22(500.0 - W * W, W * C[1][1]);
    const Complex det = a11 * a22 - a12 * a21;
    const Complex u1 = -a12 / det, u2 = a11 / det; // F = (0, 1)
    const double scale = std::abs(u1) + std::abs(u2);
    EXPECT_NEAR(std::abs(harmonic_u(r, *f, 1, 0) - u1), 0.0, 1e-9 * scale);
    EXPECT_NEAR(std::abs(harmonic_u(r, *f, 2, 0) - u2), 0.0, 1e-9 * scale);
  }
}

TEST(VerificationModalDynamics, BaseAccelerationIsTheLoadMinusMassTimesIt) {
  // the mass (node 2) on a spring to the held node 1, the base: Gamma_x = 1 (unit mass), the
  // base acceleration 2 (SCALE): the relative response of the load -2
  const std::string deck = R"(*HEADING
On a moving base
*NODE
1, 0., 0., 0.
2, 1., 0., 0.
*ELEMENT, TYPE=SPRING2, ELSET=K
1, 1, 2
*SPRING, ELSET=K
1, 1
100.
*ELEMENT, TYPE=MASS, ELSET=M
2, 2
*MASS, ELSET=M
1.
*BOUNDARY
1, 1, 3
2, 2, 3
*STEP
*FREQUENCY
1
*END STEP
*STEP
*STEADY STATE DYNAMICS, INTERVAL=RANGE, FREQUENCY SCALE=LINEAR
0.5, 3.0, 6, 1.
*MODAL DAMPING
1, 1, 0.05
*BASE MOTION, DOF=1, SCALE=2.
*END STEP
)";
  const JobResult r = test::run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto fr = frames_of(r, 2);
  ASSERT_EQ(fr.size(), 6u);
  for (const Frame* f : fr) {
    const Complex want = sdof_response(f->harmonic->frequency, -2.0);
    EXPECT_NEAR(std::abs(harmonic_u(r, *f, 2, 0) - want), 0.0, 1e-9 * std::abs(want));
    EXPECT_EQ(harmonic_u(r, *f, 1, 0), Complex(0.0, 0.0)); // the base: relative motion 0
  }
}

TEST(VerificationModalDynamics, StepAndRampLoadsAreIntegratedExactly) {
  const double zeta = 0.05, w = 10.0, wd = w * std::sqrt(1 - zeta * zeta);
  const auto step_u = [&](double t) {
    return 0.01 *
           (1 - std::exp(-zeta * w * t) *
                    (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t)));
  };
  const auto R = [&](double s) {
    if (s <= 0) return 0.0;
    return s - 2 * zeta / w +
           std::exp(-zeta * w * s) *
               (2 * zeta / w * std::cos(wd * s) - (1 - 2 * zeta * zeta) / wd * std::sin(wd * s));
  };
  const auto ramp_u = [&](double t) { return 0.01 / 0.5 * (R(t) - R(t - 0.5)); };
  for (const bool ramp : {false, true}) {
    const std::string amp = ramp ? "*AMPLITUDE, NAME=A\n0., 0., 0.5, 1., 100., 1.\n"
                                 : "*AMPLITUDE, NAME=A\n0., 1., 100., 1.\n";
    const JobResult r = test::run_deck(
        sdof(amp, "*STEP\n*MODAL DYNAMIC\n0.01, 2.\n*MODAL DAMPING\n1, 1, 0.05\n*CLOAD, "
                  "AMPLITUDE=A\n1, 1, 1.\n*NODE PRINT, FREQUENCY=10\nU\n*EL PRINT, "
                  "ELSET=K, FREQUENCY=10\nS\n*END STEP\n"));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    const auto fr = frames_of(r, 2);
    ASSERT_EQ(fr.size(), 20u);
    for (const Frame* f : fr) {
      const double t = f->step_time;
      const double want = ramp ? ramp_u(t) : step_u(t);
      EXPECT_NEAR(test::U(r, *f, 1)[0], want, 1e-8 * 0.01) << "t " << t << (ramp ? " ramp" : "");
      const ElementResult* e = f->element(r.model->mesh.find_element(1));
      const OutputBlock* S = e ? e->data.find(ElemVar::S) : nullptr;
      ASSERT_NE(S, nullptr) << "t " << t;
      EXPECT_NEAR(S->values[0], 100.0 * want, 1e-6 * 1.0) << "t " << t;
    }
    for (const std::string& w : r.run.warnings)
      EXPECT_EQ(w.find("element output"), std::string::npos) << w;
  }
}

TEST(VerificationModalDynamics, ModeBasedStepWithoutFrequencyStepIsAClearError) {
  const std::string deck = "*HEADING\nno modes\n*NODE\n1, 0., 0., 0.\n*ELEMENT, TYPE=SPRING1, "
                           "ELSET=K\n1, 1\n*SPRING, ELSET=K\n1\n100.\n*ELEMENT, TYPE=MASS, "
                           "ELSET=M\n2, 1\n*MASS, ELSET=M\n1.\n*BOUNDARY\n1, 2, 3\n*STEP\n*STEADY "
                           "STATE DYNAMICS\n1., 2.\n*CLOAD\n1, 1, 1.\n*END STEP\n";
  const JobResult r = test::run_deck(deck);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.error.find("no *FREQUENCY step comes before it"), std::string::npos) << r.error;
}

} // namespace
} // namespace gapfem
