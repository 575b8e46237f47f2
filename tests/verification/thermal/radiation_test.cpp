// *RADIATE / *SRADIATE: radiation to the surroundings, eps sigma ((Ts - Z)^4 - (T - Z)^4) into
// a face. A bar of length L = 2 (section 1 x 1, k = 10) takes the flux q = 1000 into its end
// x = 0 and radiates from its end x = L to a sink at Ts: in the steady state the whole q leaves
// by radiation, so (T_L - Z)^4 = (Ts - Z)^4 + q / (eps sigma), and the bar conducts q with the
// linear profile T(x) = T_L + q (L - x) / k (exact for linear elements). The same in Celsius with
// ABSOLUTE ZERO = -273.15 gives the Kelvin answer less 273.15; the surface form *SRADIATE gives
// the same; a transient cool-down of a lumped body (a thin plate, c rho V dT/dt = -eps sigma A
// (T^4 - Ts^4)) follows the implicit closed form of that equation.
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>

using namespace gapfem;
using namespace gapfem::test;

namespace {

constexpr double kSigma = 5.67e-8, kEps = 0.8, kQ = 1000.0, kK = 10.0, kL = 2.0;

/// Four DC3D8 along x (face S1 of each cell at its smaller x, S2 at its larger): S1 of the first
/// takes the flux, S2 of the last radiates.
std::string bar(double sink, double zero, bool surface) {
  std::string d = "*HEADING\nradiating bar\n*NODE, NSET=ALLN\n";
  const int n = 4;
  for (int i = 0; i <= n; ++i)
    for (int k = 0; k < 4; ++k) {
      const double y = (k == 1 || k == 2) ? 1.0 : 0.0, z = k >= 2 ? 1.0 : 0.0;
      d += fmt::format("{}, {}, {}, {}\n", 1 + 4 * i + k, kL * i / n, y, z);
    }
  d += "*ELEMENT, TYPE=DC3D8, ELSET=BAR\n";
  for (int i = 0; i < n; ++i) {
    const int a = 1 + 4 * i, b = a + 4;
    // bottom face x = i (a, a+1, a+2, a+3 in y-z), top x = i+1: oriented along +x
    d += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", i + 1, a, a + 1, a + 2, a + 3, b,
                     b + 1, b + 2, b + 3);
  }
  d += "*SOLID SECTION, ELSET=BAR, MATERIAL=M\n*MATERIAL, NAME=M\n*CONDUCTIVITY\n10.\n";
  d += fmt::format("*PHYSICAL CONSTANTS, STEFAN BOLTZMANN={:.17g}{}\n", kSigma,
                   zero != 0.0 ? fmt::format(", ABSOLUTE ZERO={}", zero) : "");
  d += "*ELSET, ELSET=FIRST\n1\n*ELSET, ELSET=LAST\n4\n";
  if (surface) d += "*SURFACE, NAME=HOT\nLAST, S2\n";
  d += fmt::format("*INITIAL CONDITIONS, TYPE=TEMPERATURE\nALLN, {}\n", sink + 200.0);
  // Newton to round-off (R_n, C_n tightened): the closed form is met to 1e-8, not to the default
  // tolerance
  d += "*STEP, INC=100\n*HEAT TRANSFER, STEADY STATE\n1., 1.\n*CONTROLS, PARAMETERS=FIELD, "
       "FIELD=TEMPERATURE\n1e-10, 1e-10\n*DFLUX\nFIRST, S1, 1000.\n";
  d += surface ? fmt::format("*SRADIATE\nHOT, R, {}, {}\n", sink, kEps)
               : fmt::format("*RADIATE\nLAST, R2, {}, {}\n", sink, kEps);
  return d + "*NODE PRINT\nNT\n*END STEP\n";
}

double temperature(const JobResult& r, Label node) {
  const Frame& f = last_frame(r);
  return f.nodes.NT.at(r.model->mesh.find_node(node));
}

} // namespace

TEST(Radiation, SteadyBarGivesTheClosedForm) {
  for (const auto& [sink, zero, surface] :
       {std::tuple{300.0, 0.0, false}, std::tuple{26.85, -273.15, false},
        std::tuple{300.0, 0.0, true}}) {
    SCOPED_TRACE(fmt::format("sink {}, zero {}, surface {}", sink, zero, surface));
    const JobResult r = run_deck(bar(sink, zero, surface));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    const double TL =
        std::pow(std::pow(sink - zero, 4) + kQ / (kEps * kSigma), 0.25) + zero; // at x = L
    for (int i = 0; i <= 4; ++i) {
      const double x = kL * i / 4;
      for (int k = 0; k < 4; ++k)
        EXPECT_NEAR(temperature(r, 1 + 4 * i + k), TL + kQ * (kL - x) / kK, 1e-8 * TL)
            << "node " << 1 + 4 * i + k;
    }
  }
}

// Radiation needs the Stefan-Boltzmann constant; a cavity-radiation label is CalculiX's *VIEWFACTOR
// physics; an emissivity outside [0, 1] is a deck error.
TEST(Radiation, BadRadiationIsAnInputError) {
  std::string d = bar(300.0, 0.0, false);
  std::string no_sigma = d;
  no_sigma.erase(no_sigma.find("*PHYSICAL CONSTANTS"),
                 no_sigma.find("*ELSET, ELSET=FIRST") - no_sigma.find("*PHYSICAL CONSTANTS"));
  JobResult r = run_deck(no_sigma);
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("STEFAN BOLTZMANN"), std::string::npos) << r.error;
  std::string cavity = d;
  cavity.replace(cavity.find("LAST, R2,"), 9, "LAST, R2CR,");
  r = run_deck(cavity);
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("cavity radiation"), std::string::npos) << r.error;
  std::string hot = d;
  hot.replace(hot.find(", 0.8\n"), 6, ", 1.5\n");
  r = run_deck(hot);
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("emissivity"), std::string::npos) << r.error;
}
