// A substructure's reduced mass (*SUBSTRUCTURE GENERATE, MASS MATRIX=YES; solver/substructure_mass
// and docs/theory/dynamics.md §8):
// - three T3D2 in a row (EA/L = k = 2e4 each, rho A L = m = 7.8e-3), node 1 fixed, reduced to DOF 1
//   of the end node 4: the static mode is u2 = u4/3, u3 = 2 u4/3, so by hand the reduced stiffness
//   is k/3 and the reduced mass T^T M T = m/2 + m (1/9 + 4/9) = 19 m / 18 (lumped masses m/2 at
//   the ends and m at nodes 2, 3); read back from the library to 1e-12 (a few dense operations);
// - Guyan is exact when the interior is massless: the same bar without density and a point MASS
//   M0 = 0.5 at node 4, reduced to node 4's DOF 1, used in a *DYNAMIC step (trapezoidal rule,
//   alpha = 0) under a suddenly applied force F = 100, gives the full model's history to 1e-10 of
//   its peak (the same SDOF assembled two ways) and the rule's discrete closed form
//   u_n = F/k' (1 - cos(n theta)), theta = 2 atan(w dt / 2), w = sqrt(k'/M0), k' = k/3, to 1e-9;
// - a library without MASS MATRIX=YES is massless (its kernel says so).
#include "model/substructure_file.hpp"
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>

namespace gapfem {
namespace {

namespace fs = std::filesystem;

constexpr double kK = 2e4, kM0 = 0.5, kF = 100.0, kDt = 1e-3;

JobResult run_in(const fs::path& dir, const std::string& name, const std::string& deck) {
  std::ofstream(dir / (name + ".inp")) << deck;
  JobOptions o;
  o.deck = dir / (name + ".inp");
  o.quiet = true;
  o.write_vtu = false;
  o.factor_reuse = FactorReuse::Never;
  return run_job(o);
}

/// Nodes 1-4 at x = 0, 100, 200, 300, three T3D2 (A = 10, E = 2e5), U2 and U3 held; with
/// `density` the material's, with `point_mass` a MASS element M0 at node 4.
std::string bar(bool density, bool point_mass) {
  std::string d = "*NODE\n1, 0., 0., 0.\n2, 100., 0., 0.\n3, 200., 0., 0.\n4, 300., 0., 0.\n"
                  "*ELEMENT, TYPE=T3D2, ELSET=BAR\n1, 1, 2\n2, 2, 3\n3, 3, 4\n"
                  "*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL\n10.\n"
                  "*MATERIAL, NAME=STEEL\n*ELASTIC\n200000., 0.3\n";
  if (density) d += "*DENSITY\n7.8e-9\n";
  if (point_mass) d += "*ELEMENT, TYPE=MASS, ELSET=M0\n10, 4\n*MASS, ELSET=M0\n0.5\n";
  return d + "*BOUNDARY\n1, 1, 3\n2, 2, 3\n3, 2, 3\n4, 2, 3\n";
}

std::string generation(bool density, bool point_mass, bool mass_matrix) {
  return "*HEADING\nbar reduced to its end\n" + bar(density, point_mass) +
         fmt::format("*STEP\n*SUBSTRUCTURE GENERATE, TYPE=Z1{}\n*RETAINED NODAL DOFS\n4, 1\n"
                     "*END STEP\n",
                     mass_matrix ? ", MASS MATRIX=YES" : "");
}

const char* kDynamicStep = R"(*AMPLITUDE, NAME=CONST
0., 1., 1., 1.
*STEP, INC=1000
*DYNAMIC, DIRECT, ALPHA=0.
0.001, 0.04
*CLOAD, AMPLITUDE=CONST
4, 1, 100.
*NODE PRINT, FREQUENCY=1
U
*END STEP
)";

std::vector<double> history(const JobResult& r) {
  std::vector<double> h;
  for (const Frame& f : r.frames)
    if (f.increment > 0) h.push_back(test::U(r, f, 4)[0]);
  return h;
}

TEST(SubstructureMass, GuyanMassOfABarByHand) {
  const fs::path dir = test::test_dir();
  const JobResult g = run_in(dir, "gen", generation(true, false, true));
  ASSERT_EQ(g.exit_code, 0) << g.error;
  const SubstructureLibrary lib = read_substructure_file(dir / "gen_Z1.sub", false);
  ASSERT_EQ(lib.type.stiffness.size(), 1u);
  ASSERT_EQ(lib.type.mass.size(), 1u);
  const double m = 7.8e-9 * 10.0 * 100.0;
  EXPECT_NEAR(lib.type.stiffness[0], kK / 3.0, 1e-12 * kK);
  EXPECT_NEAR(lib.type.mass[0], 19.0 * m / 18.0, 1e-12 * m);
  // without MASS MATRIX=YES: no mass in the library
  const JobResult g2 = run_in(dir, "plain", generation(true, false, false));
  ASSERT_EQ(g2.exit_code, 0) << g2.error;
  EXPECT_TRUE(read_substructure_file(dir / "plain_Z1.sub", false).type.mass.empty());
}

TEST(SubstructureMass, DynamicStepMatchesTheFullModelWhereGuyanIsExact) {
  const fs::path dir = test::test_dir();
  const JobResult g = run_in(dir, "gen", generation(false, true, true));
  ASSERT_EQ(g.exit_code, 0) << g.error;
  const JobResult full = run_in(dir, "full", "*HEADING\nfull\n" + bar(false, true) + kDynamicStep);
  const JobResult used = run_in(dir, "used",
                                "*HEADING\nused\n*NODE\n4, 300., 0., 0.\n"
                                "*ELEMENT, TYPE=Z1, ELSET=SUB, FILE=gen\n1000, 4\n"
                                "*SUBSTRUCTURE PROPERTY, ELSET=SUB\n0., 0., 0.\n" +
                                    std::string(kDynamicStep));
  ASSERT_EQ(full.exit_code, 0) << full.error;
  ASSERT_EQ(used.exit_code, 0) << used.error;
  const auto a = history(full), b = history(used);
  ASSERT_EQ(a.size(), 40u);
  ASSERT_EQ(b.size(), a.size());
  const double k = kK / 3.0, theta = 2.0 * std::atan(std::sqrt(k / kM0) * kDt / 2.0);
  for (std::size_t n = 0; n < a.size(); ++n) {
    const double closed = kF / k * (1.0 - std::cos((n + 1) * theta));
    EXPECT_NEAR(b[n], a[n], 1e-10 * 2.0 * kF / k) << n + 1;
    EXPECT_NEAR(b[n], closed, 1e-9 * kF / k) << n + 1;
  }
}

} // namespace
} // namespace gapfem
