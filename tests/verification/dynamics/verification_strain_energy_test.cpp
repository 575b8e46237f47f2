// ALLSE and ALLAE in *DYNAMIC steps (docs/theory/dynamics.md, "Energies"): ALLSE, the recoverable
// strain energy, is ALLIE less ALLAE (the hourglass controls' artificial energy) and the gaps'
// contact damping work. Checked against an independent oracle, the elements' own energies: a
// linear elastic cantilever of C3D8R (hourglass-controlled) or C3D8 bricks, 4 x 1 x 1, given a
// tip load that rises over the step and then rings. For a linear material the trapezoidal work
// of the element forces is the stored energy 1/2 u.K u whatever path and integrator, so at the
// step end ALLSE equals the sum over the elements of 1/2 eps : C : eps at their integration
// points and ALLAE the sum of their hourglass energies (the step-end hourglass check, recovered
// from the state: StepChecks::allse, allae), to 1e-9; ALLSE + ALLAE = ALLIE. With full
// integration ALLAE = 0 and ALLSE = ALLIE.
#include "test_util.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace gapfem {
namespace {

std::string cantilever(const char* type, const char* integrator) {
  std::string nodes, elements;
  const int nx = 4;
  for (int i = 0; i <= nx; ++i) // node ids: 1 + 4 i + corner
    for (int c = 0; c < 4; ++c)
      nodes += fmt::format("{}, {}., {}., {}.\n", 1 + 4 * i + c, i, c == 1 || c == 2 ? 1 : 0,
                           c >= 2 ? 1 : 0);
  for (int i = 0; i < nx; ++i) {
    const int a = 1 + 4 * i, b = a + 4; // x = i and x = i + 1 faces: (y, z) = 00, 10, 11, 01
    elements += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", i + 1, a, b, b + 1, a + 1,
                            a + 3, b + 3, b + 2, a + 2);
  }
  return fmt::format(R"(*HEADING
A ringing cantilever of bricks
*NODE
{}*ELEMENT, TYPE={}, ELSET=BEAM
{}*NSET, NSET=ROOT, GENERATE
1, 4, 1
*NSET, NSET=TIP, GENERATE
17, 20, 1
*SOLID SECTION, ELSET=BEAM, MATERIAL=STEEL
*MATERIAL, NAME=STEEL
*ELASTIC
1000., 0.3
*DENSITY
1.
*AMPLITUDE, NAME=RISE
0., 0., 0.5, 1., 10., 1.
*BOUNDARY
ROOT, 1, 3
*STEP, INC=1000
*DYNAMIC, DIRECT, {}
0.05, 1.
*CLOAD, AMPLITUDE=RISE
TIP, 3, -0.25
TIP, 2, 0.1
*END STEP
)",
                     nodes, type, elements, integrator);
}

void expect_strain_energy_of_the_elements(const char* type, const char* integrator) {
  const JobResult r = test::run_deck(cantilever(type, integrator));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  ASSERT_TRUE(r.frames.back().energies.has_value());
  const Energies& e = *r.frames.back().energies;
  const StepChecks& c = r.steps.back().checks;
  ASSERT_GT(e.allie, 0.0);
  EXPECT_NEAR(e.allse + e.allae, e.allie, 1e-12 * e.allie);
  if (c.hourglass) {
    EXPECT_GT(c.allae, 1e-3 * c.allse); // the bending does excite the hourglass modes
    EXPECT_NEAR(e.allae, c.allae, 1e-9 * e.allie);
    EXPECT_NEAR(e.allse, c.allse, 1e-9 * e.allie);
  } else {
    EXPECT_EQ(e.allae, 0.0);
    EXPECT_NEAR(e.allse, e.allie, 1e-12 * e.allie);
  }
}

TEST(VerificationStrainEnergy, ReducedBricksTrapezoidalRule) {
  expect_strain_energy_of_the_elements("C3D8R", "ALPHA=0.");
}

TEST(VerificationStrainEnergy, ReducedBricksModerateDissipation) {
  expect_strain_energy_of_the_elements("C3D8R", "APPLICATION=MODERATE DISSIPATION");
}

TEST(VerificationStrainEnergy, FullIntegrationBricksHaveNoArtificialEnergy) {
  expect_strain_energy_of_the_elements("C3D8", "APPLICATION=TRANSIENT FIDELITY");
}

} // namespace
} // namespace gapfem
