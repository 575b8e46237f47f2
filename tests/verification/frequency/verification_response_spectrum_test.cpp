// *RESPONSE SPECTRUM on the modes of a *FREQUENCY step (docs/theory/frequency.md §6), by hand on
// the two masses on springs of verification_frequency_test.cpp (k1 = 1000, k2 = 500, m1 = 2,
// m2 = 1: lambda = 250, 1000; shapes (0.5, 1) and (1, -1) with participation 4/3 and 1/3 in X).
// A mode's peak at a DOF is phi Gamma S_d, S_d = S_a / omega^2, whatever the normalisation:
//   node 2: mode 1 (1)(4/3) S_a / 250 = 5.3333e-3 S_a, mode 2 (-1)(1/3) S_a / 1000 = -3.3333e-4 S_a
//   node 1: mode 1 (0.5)(4/3) S_a / 250 = 2.6667e-3 S_a, mode 2 (1)(1/3) S_a / 1000 = 3.3333e-4 S_a
// 1. A flat spectrum S_a = 10 (one damping curve): ABS and SRSS of those; CQC with 5 % damping
//    (*MODAL DAMPING), frequency ratio 2: rho = 8 (0.05)(0.15) 2^1.5 / (9 + 0.1 + 0.08) = 0.018487,
//    node 2: sqrt(r1^2 + r2^2 + 2 rho r1 r2).
// 2. Interpolation: S_a = f^2 given at 1 and 10 cycles/time is exact in log-log; S_a between two
//    damping curves (20 at 2 %, 10 at 10 %) is linear in damping: 16.25 at 5 %; TYPE=G scales by G.
// 3. Directions: an excitation along (1, 1, 0) (normalised) sees Gamma / sqrt(2); a second line
//    along Y adds nothing to this X-only model (SRSS over the directions).
// 4. Errors: no *FREQUENCY step before; a mode number beyond those extracted.
#include "test_util.hpp"
#include "verification/frequency/two_masses.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>

namespace gapfem {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string deck(const std::string& spectrum, const std::string& step) {
  return fmt::format("*HEADING\nTwo masses on springs, a response spectrum\n{}"
                     R"({}*STEP
*FREQUENCY
2
*END STEP
*STEP
{}*END STEP
)",
                     test::kTwoMassesModel, spectrum, step);
}

const char* kFlat = "*SPECTRUM, NAME=FLAT\n10., 0.1, 0.05\n10., 100., 0.05\n";

double peak(const JobResult& r, Label node) {
  const Frame& f = test::last_frame(r, 2);
  return test::U(r, f, node)[0];
}

struct Modal {
  double r1, r2; // per unit S_a at node 2 (or node 1)
};
constexpr Modal kNode2{4.0 / 3.0 / 250.0, -1.0 / 3.0 / 1000.0};
constexpr Modal kNode1{0.5 * 4.0 / 3.0 / 250.0, 1.0 / 3.0 / 1000.0};

TEST(VerificationResponseSpectrum, FlatSpectrumAbsSrssCqcByHand) {
  const double Sa = 10.0;
  {
    const JobResult r = test::run_deck(deck(kFlat, "*RESPONSE SPECTRUM\nFLAT, 1., 0., 0.\n"));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    EXPECT_NEAR(peak(r, 2), Sa * (std::abs(kNode2.r1) + std::abs(kNode2.r2)), 1e-12);
    EXPECT_NEAR(peak(r, 1), Sa * (kNode1.r1 + kNode1.r2), 1e-12);
  }
  {
    const JobResult r =
        test::run_deck(deck(kFlat, "*RESPONSE SPECTRUM, SUM=SRSS\nFLAT, 1., 0., 0.\n"));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    EXPECT_NEAR(peak(r, 2), Sa * std::hypot(kNode2.r1, kNode2.r2), 1e-12);
  }
  // the damping of both modes by their numbers, or of every mode (blank numbers, CalculiX's way)
  for (const char* damping : {"1, 2, 0.05", ",, 0.05"}) {
    const JobResult r = test::run_deck(deck(
        kFlat, fmt::format("*RESPONSE SPECTRUM, SUM=CQC\nFLAT, 1., 0., 0.\n*MODAL DAMPING\n{}\n",
                           damping)));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    const double rho = 8 * 0.05 * 0.15 * std::pow(2.0, 1.5) / (9 + 0.1 + 0.08);
    const double a = Sa * kNode2.r1, b = Sa * kNode2.r2;
    EXPECT_NEAR(peak(r, 2), std::sqrt(a * a + b * b + 2 * rho * a * b), 1e-12) << damping;
  }
}

TEST(VerificationResponseSpectrum, InterpolationInFrequencyAndDamping) {
  const double w1 = std::sqrt(250.0), w2 = std::sqrt(1000.0);
  const double f1 = w1 / (2 * kPi), f2 = w2 / (2 * kPi);
  {
    const JobResult r = test::run_deck(deck("*SPECTRUM, NAME=SQUARE\n1., 1., 0.\n100., 10., 0.\n",
                                            "*RESPONSE SPECTRUM, SUM=SRSS\nSQUARE, 1., 0., 0.\n"));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    EXPECT_NEAR(peak(r, 2), std::hypot(f1 * f1 * kNode2.r1, f2 * f2 * kNode2.r2), 1e-12);
  }
  {
    const JobResult r = test::run_deck(deck(
        "*SPECTRUM, NAME=TWO\n20., 0.1, 0.02\n20., 100., 0.02\n10., 0.1, 0.1\n10., 100., 0.1\n",
        "*RESPONSE SPECTRUM\nTWO, 1., 0., 0.\n*MODAL DAMPING\n1, 2, 0.05\n"));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    EXPECT_NEAR(peak(r, 2), 16.25 * (std::abs(kNode2.r1) + std::abs(kNode2.r2)), 1e-12);
  }
  {
    const JobResult r =
        test::run_deck(deck("*SPECTRUM, NAME=GEE, TYPE=G, G=9.81\n0.5, 0.1, 0.\n0.5, 100., 0.\n",
                            "*RESPONSE SPECTRUM\nGEE, 1., 0., 0.\n"));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    EXPECT_NEAR(peak(r, 2), 0.5 * 9.81 * (std::abs(kNode2.r1) + std::abs(kNode2.r2)), 1e-12);
  }
}

TEST(VerificationResponseSpectrum, DirectionsCombine) {
  const double Sa = 10.0, full = Sa * (std::abs(kNode2.r1) + std::abs(kNode2.r2));
  {
    const JobResult r = test::run_deck(deck(kFlat, "*RESPONSE SPECTRUM\nFLAT, 1., 1., 0.\n"));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    EXPECT_NEAR(peak(r, 2), full / std::sqrt(2.0), 1e-12);
  }
  for (const char* comp : {"SRSS", "ALGEBRAIC"}) {
    const JobResult r = test::run_deck(
        deck(kFlat, fmt::format("*RESPONSE SPECTRUM, COMP={}\nFLAT, 1., 0., 0.\nFLAT, 0., 1., 0.\n",
                                comp)));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    EXPECT_NEAR(peak(r, 2), full, 1e-12) << comp;
  }
}

TEST(VerificationResponseSpectrum, ClearErrors) {
  const std::string alone = R"(*HEADING
A spectrum without modes
*NODE
1, 0., 0., 0.
*ELEMENT, TYPE=SPRING1, ELSET=K1
1, 1
*SPRING, ELSET=K1
1
1000.
*ELEMENT, TYPE=MASS, ELSET=M1
3, 1
*MASS, ELSET=M1
2.
*BOUNDARY
1, 2, 3
*SPECTRUM, NAME=FLAT
10., 0.1, 0.05
*STEP
*RESPONSE SPECTRUM
FLAT, 1., 0., 0.
*END STEP
)";
  const JobResult r = test::run_deck(alone);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.error.find("no *FREQUENCY step comes before it"), std::string::npos) << r.error;
  const JobResult r2 = test::run_deck(
      deck(kFlat, "*RESPONSE SPECTRUM\nFLAT, 1., 0., 0.\n*SELECT EIGENMODES\n1, 3\n"));
  EXPECT_EQ(r2.exit_code, 1);
  EXPECT_NE(r2.error.find("names mode 3, but the *FREQUENCY step 1 extracted 2 modes"),
            std::string::npos)
      << r2.error;
}

} // namespace
} // namespace gapfem
