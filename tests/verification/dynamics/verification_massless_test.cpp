// DOFs without mass in *DYNAMIC steps (docs/theory/dynamics.md §3). A DOF without mass takes the
// static equilibrium of its forces at every increment (a = 0 at the start, no inertia); a model
// in which no element has any mass has no inertia at all, which Abaqus/Standard solves the same
// way, and gapfem says so once (a forgotten *DENSITY).
// 1. A truss bar (E A / L = 2e9) without *DENSITY under a tip force rising linearly to 1: each
//    increment is the static solution u = F(t) L / (E A) (1e-12 relative), and the run warns
//    once that the step has no inertia.
// 2. The same bar with a point MASS at the tip and a massless middle node (two trusses): no such
//    warning, and the middle node sits at half the tip's displacement at every increment (the
//    static share of a massless node between two equal bars, 1e-12).
#include "test_util.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace gapfem {
namespace {

std::string bar(bool tip_mass) {
  return fmt::format(R"(*HEADING
A bar in a dynamic step
*NODE
1, 0., 0., 0.
2, 0.5, 0., 0.
3, 1., 0., 0.
*ELEMENT, TYPE=T3D2, ELSET=BAR
1, 1, 2
2, 2, 3
*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL
0.01
*MATERIAL, NAME=STEEL
*ELASTIC
2e11, 0.3
{}*BOUNDARY
1, 1, 3
2, 2, 3
3, 2, 3
*AMPLITUDE, NAME=RAMP
0., 0., 1., 1.
*STEP, INC=100
*DYNAMIC, DIRECT, ALPHA=0.
0.1, 1.
*CLOAD, AMPLITUDE=RAMP
3, 1, 1.
*NODE PRINT
U
*END STEP
)",
                     tip_mass ? "*ELEMENT, TYPE=MASS, ELSET=TIP\n9, 3\n*MASS, ELSET=TIP\n1e-3\n"
                              : "");
}

int massless_warnings(const JobResult& r) {
  int n = 0;
  for (const std::string& w : r.run.warnings)
    if (w.find("no element of the model has mass") != std::string::npos) ++n;
  return n;
}

TEST(VerificationMassless, AModelWithoutMassIsStaticAtEveryIncrementAndSaysSo) {
  const JobResult r = test::run_deck(bar(false));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  EXPECT_EQ(massless_warnings(r), 1);
  const LocalIndex tip = r.model->mesh.find_node(3);
  int checked = 0;
  for (const Frame& f : r.frames) {
    if (f.increment == 0) continue;
    const double u = f.step_time * 1.0 / 2e9; // F(t) L / (E A)
    EXPECT_NEAR(f.nodes.U.at(tip)[0], u, 1e-12 * u) << f.step_time;
    ++checked;
  }
  EXPECT_EQ(checked, 10);
}

TEST(VerificationMassless, AMasslessNodeBetweenMassesTakesItsStaticShare) {
  const JobResult r = test::run_deck(bar(true));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  EXPECT_EQ(massless_warnings(r), 0);
  const LocalIndex mid = r.model->mesh.find_node(2), tip = r.model->mesh.find_node(3);
  for (const Frame& f : r.frames) {
    const double ut = f.nodes.U.at(tip)[0];
    EXPECT_NEAR(f.nodes.U.at(mid)[0], 0.5 * ut, 1e-12 * std::abs(ut) + 1e-30) << f.step_time;
  }
}

} // namespace
} // namespace gapfem
