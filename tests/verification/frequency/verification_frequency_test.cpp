// *FREQUENCY against closed forms (docs/theory/frequency.md).
// 1. Two masses on springs, by hand: k1 = 1000 (ground to mass 1), k2 = 500 (mass 1 to mass 2),
//    m1 = 2, m2 = 1. det(K - lambda M) = 2 lambda^2 - 2500 lambda + 500000 = 0: lambda = 250 and
//    1000. Mode 1: (1500 - 500) phi1 = 500 phi2, phi = (0.5, 1) with its largest entry 1; its
//    generalized mass 2 (0.25) + 1 = 1.5, participation in X (2 (0.5) + 1) / 1.5 = 4/3, effective
//    mass (4/3)^2 1.5 = 8/3. Mode 2: phi = (1, -1), m = 3, Gamma = (2 - 1) / 3 = 1/3, effective
//    mass 1/3. The effective masses add up to m1 + m2 = 3 (every mode found). NORMALIZATION=MASS:
//    m = 1, the same Gamma^2 m.
// 2. A bar of n T3D2 elements (lumped mass rho A h / 2 per node), fixed at one end: the chain's
//    exact eigenvalues lambda_k = 4 E / (rho h^2) sin^2(theta_k / 2), theta_k = (2k - 1) pi / (2n)
//    (u_j = sin(j theta) solves every interior row, and the free end's half mass is the mirror
//    image u_{n+1} = u_{n-1}), 1e-9. n = 20 (the dense route) and n = 600 (Lanczos), and a
//    request by maximum frequency gets exactly the eigenvalues below it.
// 3. A B21 cantilever (L = 1000, RECT 5 x 5, 100 elements) with a GAPUNI stop under its tip:
//    pushed onto the stop (closed, step 1), its modes are the propped cantilever's
//    (beta L = 3.926602, 7.068583); after the push is removed (the gap opens, step 3) the
//    cantilever's (1.875104, 4.694091): omega = (beta L)^2 sqrt(E I / (rho A L^4)), 1e-3 (the
//    mesh's and Timoshenko's share, slenderness 1/200, measured below 3e-4). The open gap adds
//    nothing.
// 4. A string of n T3D2 trusses (fixed ends, z held) stretched by delta = 1e-4 L in a static
//    NLGEOM step (held transversely there; the *FREQUENCY step's own boundary conditions free
//    it): its transverse modes are those of a chain of masses rho A h on a string of
//    tension N = E A delta / L: lambda_k = 4 N / (rho A h^2) sin^2(k pi / (2 n)) (1e-3: the strain
//    measure and the stretched length change N and h by O(1e-4)). Without NLGEOM the base state
//    has no initial stress: the transverse DOFs have no stiffness and come out as rigid-body
//    modes (eigenvalues near zero), reported, not an error.
// 5. Friction in the perturbation (Abaqus: closed points stick when friction is present): mass 1
//    (m = 1) pressed onto a GAPUNI stop (N = 10, mu = 0.3), mass 2 (m = 1) on a spring k = 100 to
//    it along x. LAGRANGE friction holds mass 1: lambda = k / m2 = 100, whether the base state
//    sticks (a pull of 1 < mu N) or slips (a pull of 5 against a ground spring of 1000 on mass 1:
//    the slip of the base state does not free it). Elastic slip (ELASTIC SLIP = 1e-3): the stick
//    stiffness mu N / gamma = 3000 on mass 1, K = [3100 -100; -100 100]: lambda =
//    (3200 - sqrt(3200^2 - 4 x 300000)) / 2 = 96.67036.
#include "test_util.hpp"
#include "verification/frequency/two_masses.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>

namespace gapfem {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string two_masses(const char* normalization) {
  return fmt::format("*HEADING\nTwo masses on springs\n{}"
                     R"(*STEP
*FREQUENCY{}
2
*NODE PRINT
U
*END STEP
)",
                     test::kTwoMassesModel, normalization);
}

const EigenSummary& modes_of(const JobResult& r, int step_index = 0) {
  for (const auto& [index, m] : r.modes)
    if (index == step_index) return m;
  throw std::runtime_error("no modes for that step");
}

TEST(VerificationFrequency, TwoMassesOnSpringsByHand) {
  const JobResult r = test::run_deck(two_masses(""));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const EigenSummary& m = modes_of(r);
  ASSERT_EQ(m.modes.size(), 2u);
  EXPECT_NEAR(m.modes[0].eigenvalue, 250.0, 1e-9 * 250.0);
  EXPECT_NEAR(m.modes[1].eigenvalue, 1000.0, 1e-9 * 1000.0);
  EXPECT_NEAR(m.modes[0].generalized_mass, 1.5, 1e-12);
  EXPECT_NEAR(m.modes[0].participation[0], 4.0 / 3.0, 1e-12);
  EXPECT_NEAR(m.modes[0].effective_mass[0], 8.0 / 3.0, 1e-12);
  EXPECT_NEAR(m.modes[1].generalized_mass, 3.0, 1e-12);
  EXPECT_NEAR(m.modes[1].participation[0], 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(m.modes[1].effective_mass[0], 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(m.total_effective_mass[0], 3.0, 1e-12);
  EXPECT_NEAR(m.model_mass[0], 3.0, 1e-12);
  for (int i = 1; i < 6; ++i) EXPECT_NEAR(m.modes[0].participation[i], 0.0, 1e-12);
  EXPECT_NEAR(m.modes[0].frequency(), std::sqrt(250.0) / (2 * kPi), 1e-12);
  // the frames: one per mode, the shape normalised to its largest entry
  ASSERT_EQ(r.frames.size(), 2u);
  const Frame& f1 = r.frames[0];
  ASSERT_TRUE(f1.mode.has_value());
  EXPECT_EQ(f1.mode->mode, 1);
  EXPECT_NEAR(test::U(r, f1, 1)[0], 0.5, 1e-12);
  EXPECT_NEAR(test::U(r, f1, 2)[0], 1.0, 1e-12);
  EXPECT_NEAR(test::U(r, r.frames[1], 1)[0], 1.0, 1e-12);
  EXPECT_NEAR(test::U(r, r.frames[1], 2)[0], -1.0, 1e-12);
}

TEST(VerificationFrequency, MassNormalizationGivesUnitGeneralizedMass) {
  const JobResult r = test::run_deck(two_masses(", NORMALIZATION=MASS"));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const EigenSummary& m = modes_of(r);
  ASSERT_EQ(m.modes.size(), 2u);
  for (const ModeInfo& mi : m.modes) EXPECT_NEAR(mi.generalized_mass, 1.0, 1e-12);
  EXPECT_NEAR(m.modes[0].effective_mass[0], 8.0 / 3.0, 1e-12);
  EXPECT_NEAR(m.modes[1].effective_mass[0], 1.0 / 3.0, 1e-12);
  // phi = (0.5, 1) / sqrt(1.5)
  EXPECT_NEAR(test::U(r, r.frames[0], 2)[0], 1.0 / std::sqrt(1.5), 1e-12);
}

/// A fixed-free bar of n T3D2 elements along x (E = 2e11, rho = 7800, A = 1e-4, L = 1).
std::string bar(int n, const std::string& frequency_line) {
  std::string d = "*HEADING\nA bar\n*NODE, NSET=ALL\n";
  for (int i = 0; i <= n; ++i) d += fmt::format("{}, {:.17g}, 0., 0.\n", i + 1, double(i) / n);
  d += "*ELEMENT, TYPE=T3D2, ELSET=BAR\n";
  for (int i = 1; i <= n; ++i) d += fmt::format("{}, {}, {}\n", i, i, i + 1);
  d += "*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL\n1e-4\n*MATERIAL, NAME=STEEL\n*ELASTIC\n"
       "2e11, 0.3\n*DENSITY\n7800.\n*BOUNDARY\nALL, 2, 3\n1, 1, 1\n*STEP\n*FREQUENCY\n" +
       frequency_line + "\n*END STEP\n";
  return d;
}

double chain_eigenvalue(int n, int k) {
  const double h = 1.0 / n, theta = (2 * k - 1) * kPi / (2 * n);
  const double s = std::sin(theta / 2);
  return 4 * 2e11 / (7800.0 * h * h) * s * s;
}

TEST(VerificationFrequency, LumpedBarIsTheExactChain) {
  for (int n : {20, 600}) {
    const int count = n == 20 ? 19 : 8; // the dense route takes nearly all
    const JobResult r = test::run_deck(bar(n, std::to_string(count)));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    const EigenSummary& m = modes_of(r);
    ASSERT_EQ(static_cast<int>(m.modes.size()), count);
    for (int k = 1; k <= count; ++k) {
      const double exact = chain_eigenvalue(n, k);
      EXPECT_NEAR(m.modes[k - 1].eigenvalue, exact, 1e-9 * exact) << "n " << n << " mode " << k;
      // participation of each mode in X, and the whole chain's mass rho A L less the fixed node's
    }
    EXPECT_NEAR(m.model_mass[0], 7800.0 * 1e-4 * (1.0 - 0.5 / n), 1e-12);
  }
}

TEST(VerificationFrequency, ModeShapesCarryTheirStresses) {
  // *EL PRINT, S in a frequency step: each mode's element output is the stress of its shape,
  // E (phi_b - phi_a) / h on every T3D2 of the chain
  std::string deck = bar(20, "3");
  deck.insert(deck.find("*END STEP"), "*EL PRINT\nS\n");
  const JobResult r = test::run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  ASSERT_EQ(r.frames.size(), 3u);
  for (const Frame& f : r.frames)
    for (int e = 1; e <= 20; ++e) {
      const ElementResult* res = f.element(r.model->mesh.find_element(e));
      ASSERT_NE(res, nullptr);
      const OutputBlock* s = res->data.find(ElemVar::S);
      ASSERT_NE(s, nullptr);
      const double want = 2e11 * (test::U(r, f, e + 1)[0] - test::U(r, f, e)[0]) / (1.0 / 20);
      EXPECT_NEAR(s->values.at(0), want, 1e-6 * 2e11 * 20 + 1e-9 * std::abs(want)) << e;
    }
}

TEST(VerificationFrequency, AMaximumFrequencyGetsEveryEigenvalueBelowIt) {
  const int n = 600;
  // between modes 5 and 6
  const double f5 = std::sqrt(chain_eigenvalue(n, 5)) / (2 * kPi),
               f6 = std::sqrt(chain_eigenvalue(n, 6)) / (2 * kPi);
  const JobResult r = test::run_deck(bar(n, fmt::format(", , {:.17g}", 0.5 * (f5 + f6))));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const EigenSummary& m = modes_of(r);
  ASSERT_EQ(m.modes.size(), 5u);
  EXPECT_NEAR(m.modes[4].eigenvalue, chain_eigenvalue(n, 5), 1e-9 * chain_eigenvalue(n, 5));
  // a minimum frequency: the eigenvalues above it
  const JobResult r2 = test::run_deck(bar(n, fmt::format("3, {:.17g}", 0.5 * (f5 + f6))));
  ASSERT_EQ(r2.exit_code, 0) << r2.error;
  const EigenSummary& m2 = modes_of(r2);
  ASSERT_EQ(m2.modes.size(), 3u);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(m2.modes[k].eigenvalue, chain_eigenvalue(n, 6 + k),
                1e-9 * chain_eigenvalue(n, 6 + k));
}

/// The B21 cantilever over a GAPUNI stop at its tip (clearance 1): steps static, frequency,
/// static (push removed), frequency.
std::string propped_cantilever() {
  const int n = 100;
  std::string d = "*HEADING\nA cantilever on a stop\n*NODE, NSET=ALL\n";
  for (int i = 0; i <= n; ++i) d += fmt::format("{}, {:.17g}, 0.\n", i + 1, 1000.0 * i / n);
  d += "500, 1000., -5.\n*ELEMENT, TYPE=B21, ELSET=BEAM\n";
  for (int i = 1; i <= n; ++i) d += fmt::format("{}, {}, {}\n", i, i, i + 1);
  d += fmt::format(R"(*ELEMENT, TYPE=GAPUNI, ELSET=STOP
900, {}, 500
*GAP, ELSET=STOP
1., 0., -1.
*BEAM SECTION, ELSET=BEAM, MATERIAL=STEEL, SECTION=RECT
5., 5.
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*DENSITY
7.85e-9
*BOUNDARY
1, 1, 2
1, 6, 6
500, 1, 2
*STEP
*STATIC
*CLOAD
{}, 2, -1.
*END STEP
*STEP
*FREQUENCY
2
*END STEP
*STEP
*STATIC
*CLOAD, OP=NEW
*END STEP
*STEP
*FREQUENCY
2
*END STEP
)",
                   n + 1, n + 1);
  return d;
}

TEST(VerificationFrequency, AClosedStopPropsTheCantileverAndAnOpenOneAddsNothing) {
  const JobResult r = test::run_deck(propped_cantilever());
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const double E = 210000.0, rho = 7.85e-9, A = 25.0, I = 625.0 / 12.0, L = 1000.0;
  const double unit = std::sqrt(E * I / (rho * A * L * L * L * L));
  const auto omega = [&](double bl) { return bl * bl * unit; };
  const EigenSummary& closed = modes_of(r, 1);
  ASSERT_EQ(closed.modes.size(), 2u);
  EXPECT_NEAR(closed.modes[0].circular(), omega(3.926602), 1e-3 * omega(3.926602));
  EXPECT_NEAR(closed.modes[1].circular(), omega(7.068583), 1e-3 * omega(7.068583));
  const EigenSummary& open = modes_of(r, 3);
  ASSERT_EQ(open.modes.size(), 2u);
  EXPECT_NEAR(open.modes[0].circular(), omega(1.875104), 1e-3 * omega(1.875104));
  EXPECT_NEAR(open.modes[1].circular(), omega(4.694091), 1e-3 * omega(4.694091));
}

/// A string of n T3D2 along x: held transversely while its right end is pulled by 1e-4 (step 1),
/// then free transversely in the *FREQUENCY step (its *BOUNDARY, OP=NEW), z held throughout.
std::string string_deck(int n, bool nlgeom) {
  std::string d = "*HEADING\nA string\n*NODE, NSET=ALL\n";
  for (int i = 0; i <= n; ++i) d += fmt::format("{}, {:.17g}, 0., 0.\n", i + 1, double(i) / n);
  d += "*ELEMENT, TYPE=T3D2, ELSET=BAR\n";
  for (int i = 1; i <= n; ++i) d += fmt::format("{}, {}, {}\n", i, i, i + 1);
  d += fmt::format(R"(*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL
1e-4
*MATERIAL, NAME=STEEL
*ELASTIC
2e11, 0.3
*DENSITY
7800.
*BOUNDARY
ALL, 2, 3
1, 1, 1
*STEP{}
*STATIC
*BOUNDARY
{}, 1, 1, 1e-4
*END STEP
*STEP
*FREQUENCY
4
*BOUNDARY, OP=NEW
ALL, 3, 3
1, 1, 2
{}, 1, 2
*END STEP
)",
                   nlgeom ? ", NLGEOM" : "", n + 1, n + 1);
  return d;
}

TEST(VerificationFrequency, TensionStiffensAStringOnlyWithNlgeom) {
  const int n = 30;
  const JobResult r = test::run_deck(string_deck(n, true));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const EigenSummary& m = modes_of(r, 1);
  ASSERT_EQ(m.modes.size(), 4u);
  const double N = 2e11 * 1e-4 * 1e-4, h = 1.0 / n;
  for (int k = 1; k <= 4; ++k) {
    const double s = std::sin(k * kPi / (2 * n));
    const double exact = 4 * N / (7800.0 * 1e-4 * h * h) * s * s;
    EXPECT_NEAR(m.modes[k - 1].eigenvalue, exact, 1e-3 * exact) << "mode " << k;
  }
  EXPECT_EQ(m.rigid_body_modes, 0);
  const JobResult lin = test::run_deck(string_deck(n, false));
  ASSERT_EQ(lin.exit_code, 0) << lin.error;
  const EigenSummary& ml = modes_of(lin, 1);
  ASSERT_EQ(ml.modes.size(), 4u);
  EXPECT_EQ(ml.rigid_body_modes, 4);
  for (const ModeInfo& mi : ml.modes) EXPECT_LT(std::abs(mi.frequency()), 1e-3);
}

std::string friction_deck(const char* friction, double pull, bool ground_spring) {
  return fmt::format(
      R"(*HEADING
A mass on a gap with friction and a mass on a spring
*NODE
1, 0., 0., 0.
2, 1., 0., 0.
3, 0., -1., 0.
*ELEMENT, TYPE=MASS, ELSET=M
11, 1
12, 2
*MASS, ELSET=M
1.
*ELEMENT, TYPE=SPRING2, ELSET=K
13, 1, 2
*SPRING, ELSET=K
1, 1
100.
{}*ELEMENT, TYPE=GAPUNI, ELSET=G
14, 1, 3
*GAP, ELSET=G
0., 0., -1., 0.
*FRICTION{}
0.3
*BOUNDARY
3, 1, 3
1, 3, 3
2, 2, 3
*STEP
*STATIC
*CLOAD
1, 2, -10.
2, 1, {}
*END STEP
*STEP
*FREQUENCY
1
*END STEP
)",
      ground_spring ? "*ELEMENT, TYPE=SPRING1, ELSET=KG\n15, 1\n*SPRING, ELSET=KG\n1\n1000.\n" : "",
      friction, pull);
}

TEST(VerificationFrequency, ClosedGapsWithFrictionStickInThePerturbation) {
  struct Case {
    const char* friction;
    double pull;
    bool ground;
    const char* base_status;
    double lambda;
  };
  const double elastic = (3200.0 - std::sqrt(3200.0 * 3200.0 - 4 * 300000.0)) / 2;
  for (const Case& c : {Case{", LAGRANGE", 1.0, false, "stick", 100.0},
                        Case{", LAGRANGE", 5.0, true, "slip", 100.0},
                        Case{", ELASTIC SLIP=1e-3", 1.0, false, "stick", elastic}}) {
    const JobResult r = test::run_deck(friction_deck(c.friction, c.pull, c.ground));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    ASSERT_FALSE(r.steps.empty());
    const StepChecks& base = r.steps[0].checks;
    EXPECT_EQ(std::string(c.base_status) == "stick" ? base.n_stick : base.n_slip, 1)
        << c.friction << " pull " << c.pull;
    const EigenSummary& m = modes_of(r, 1);
    ASSERT_EQ(m.modes.size(), 1u);
    EXPECT_NEAR(m.modes[0].eigenvalue, c.lambda, 1e-9 * c.lambda) << c.friction << " " << c.pull;
  }
}

TEST(VerificationFrequency, MoreModesThanTheModelHasIsAClearError) {
  const std::string deck = two_masses("");
  std::string more = deck;
  more.replace(more.find("*FREQUENCY\n2"), 12, "*FREQUENCY\n3");
  const JobResult r = test::run_deck(more);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.error.find("3 eigenvalues were asked for, but the model has only 2"),
            std::string::npos)
      << r.error;
}

} // namespace
} // namespace gapfem
