// The response spectrum's summation rules (solver/modal_combination.hpp) against their limits and
// hand values:
// - CQC (Der Kiureghian): rho_ii = 1; for 5 % damping in both modes and a frequency ratio 0.9,
//   rho = 8 (0.05)(0.095)(0.9^1.5) / ((1 - 0.81)^2 + 4 (0.0025)(0.9)(1.81) + 4 (0.005)(0.81))
//   = 0.032445 / 0.06859 = 0.4730; well separated modes (ratio 1/3) hardly correlate (< 0.01),
//   so CQC tends to SRSS, and two modes of one frequency with the same sign add up (ABS).
// - ABS, SRSS, NRL (the largest in full plus the SRSS of the rest) of (3, -4, 1): 8, sqrt(26),
//   4 + sqrt(10).
// - TENP and GRP: modes 10 % apart or less count their absolute products (twice each pair for
//   TENP; GRP within a group starting at its lowest mode): omega (10, 10.5, 20), r (3, -4, 1):
//   TENP sqrt(26 + 2 (12)) = sqrt(50), GRP the same here (one group of two and one alone).
// - DSC without duration is Rosenblueth's correlation with damped frequencies, 1 at i = j.
#include "solver/modal_combination.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <vector>

namespace gapfem {
namespace {

TEST(ModalCombination, CqcCorrelationByHand) {
  EXPECT_NEAR(cqc_correlation(10.0, 10.0, 0.05, 0.05), 1.0, 1e-14);
  EXPECT_NEAR(cqc_correlation(10.0, 9.0, 0.05, 0.05), 0.032445 / 0.06859, 2e-4);
  EXPECT_LT(cqc_correlation(10.0, 30.0, 0.05, 0.05), 0.01);
  EXPECT_NEAR(cqc_correlation(10.0, 9.0, 0.05, 0.05), cqc_correlation(9.0, 10.0, 0.05, 0.05),
              1e-14);
}

TEST(ModalCombination, RulesOfThreeModes) {
  const std::vector<double> r{3.0, -4.0, 1.0}, w{10.0, 10.5, 20.0}, z{0.05, 0.05, 0.05};
  const ModalPeaks p{r, w, z};
  EXPECT_NEAR(combine_modes(ModalSum::Abs, p), 8.0, 1e-14);
  EXPECT_NEAR(combine_modes(ModalSum::Srss, p), std::sqrt(26.0), 1e-14);
  EXPECT_NEAR(combine_modes(ModalSum::Nrl, p), 4.0 + std::sqrt(10.0), 1e-14);
  EXPECT_NEAR(combine_modes(ModalSum::Tenp, p), std::sqrt(50.0), 1e-14);
  EXPECT_NEAR(combine_modes(ModalSum::Grp, p), std::sqrt(50.0), 1e-14);
  // CQC lies between SRSS-with-signs and ABS; its own double sum by hand
  const double r01 = cqc_correlation(10.0, 10.5, 0.05, 0.05),
               r02 = cqc_correlation(10.0, 20.0, 0.05, 0.05),
               r12 = cqc_correlation(10.5, 20.0, 0.05, 0.05);
  const double cqc = std::sqrt(26.0 + 2 * (3 * -4 * r01 + 3 * 1 * r02 + -4 * 1 * r12));
  EXPECT_NEAR(combine_modes(ModalSum::Cqc, p), cqc, 1e-12);
}

TEST(ModalCombination, CqcLimits) {
  const std::vector<double> r{2.0, 5.0}, same{10.0, 10.0}, apart{10.0, 100.0}, z{0.02, 0.02};
  EXPECT_NEAR(combine_modes(ModalSum::Cqc, {r, same, z}), 7.0, 1e-12);             // ABS
  EXPECT_NEAR(combine_modes(ModalSum::Cqc, {r, apart, z}), std::sqrt(29.0), 1e-3); // SRSS
}

TEST(ModalCombination, DscIsOneForAModeWithItself) {
  EXPECT_NEAR(dsc_correlation(10.0, 10.0, 0.05, 0.05, 0.0), 1.0, 1e-14);
  EXPECT_NEAR(dsc_correlation(10.0, 10.0, 0.05, 0.05, 20.0), 1.0, 1e-14);
  EXPECT_LT(dsc_correlation(10.0, 30.0, 0.05, 0.05, 0.0), 0.01);
}

} // namespace
} // namespace gapfem
