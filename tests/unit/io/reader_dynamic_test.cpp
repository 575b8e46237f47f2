// *DYNAMIC (docs/theory/dynamics.md §2): the application's integrator and parameters, the
// default APPLICATION with and without contact, ALPHA/BETA/GAMMA, INITIAL, DIRECT and HAFTOL, and
// one clear message for each wrong combination.
#include "unit/io/reader_test_util.hpp"

#include <array>
#include <cmath>

namespace gapfem {
namespace {

using test::error_text;
using test::kTrussModel;
using test::read;

std::string dynamic(std::string_view keyword, std::string_view data = "0.01, 1.") {
  return std::string(kTrussModel) + "*STEP\n" + std::string(keyword) + "\n" + std::string(data) +
         "\n*END STEP\n";
}

/// The truss model with a GAPUNI: a model with contact.
std::string with_gap(std::string_view keyword) {
  std::string d = dynamic(keyword);
  const auto at = d.find("*STEP");
  d.insert(at, "*NODE\n900, 5., 5., 5.\n*ELEMENT, TYPE=GAPUNI, ELSET=GAPS\n900, 1, 900\n"
               "*GAP, ELSET=GAPS\n0.1, 1., 0., 0.\n");
  return d;
}

TEST(ReaderDynamic, ApplicationsAndTheirParameters) {
  using A = DynamicSettings::Application;
  const Model tf = read(dynamic("*DYNAMIC"));
  ASSERT_EQ(tf.steps.size(), 1u);
  const Step& s = tf.steps[0];
  EXPECT_EQ(s.procedure, Procedure::Dynamic);
  EXPECT_EQ(s.dynamic.application, A::TransientFidelity); // no contact
  EXPECT_TRUE(s.dynamic.hht);
  EXPECT_DOUBLE_EQ(s.dynamic.alpha, -0.05);
  EXPECT_DOUBLE_EQ(s.dynamic.beta, 0.275625);
  EXPECT_DOUBLE_EQ(s.dynamic.gamma, 0.55);
  EXPECT_TRUE(s.dynamic.initial_accelerations);
  EXPECT_FALSE(s.inc.direct);
  EXPECT_FALSE(s.dynamic.haftol);
  EXPECT_EQ(s.inc.initial, 0.01);
  EXPECT_EQ(s.inc.period, 1.0);

  const Model md = read(with_gap("*DYNAMIC")); // contact: MODERATE DISSIPATION
  EXPECT_EQ(md.steps[0].dynamic.application, A::ModerateDissipation);
  EXPECT_NEAR(md.steps[0].dynamic.alpha, 1.0 - std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(md.steps[0].dynamic.beta, 0.5, 1e-15);
  EXPECT_FALSE(md.steps[0].dynamic.initial_accelerations);

  const Model qs = read(dynamic("*DYNAMIC, APPLICATION=QUASI-STATIC, DIRECT"));
  EXPECT_FALSE(qs.steps[0].dynamic.hht);
  EXPECT_TRUE(qs.steps[0].inc.direct);

  const Model a = read(dynamic("*DYNAMIC, ALPHA=-0.2, INITIAL=NO, HAFTOL=0.5"));
  EXPECT_DOUBLE_EQ(a.steps[0].dynamic.alpha, -0.2);
  EXPECT_DOUBLE_EQ(a.steps[0].dynamic.beta, 0.36);
  EXPECT_DOUBLE_EQ(a.steps[0].dynamic.gamma, 0.7);
  EXPECT_FALSE(a.steps[0].dynamic.initial_accelerations);
  EXPECT_EQ(*a.steps[0].dynamic.haftol, 0.5);

  const Model bg = read(dynamic("*DYNAMIC, ALPHA=0., BETA=0.3, GAMMA=0.6"));
  EXPECT_DOUBLE_EQ(bg.steps[0].dynamic.beta, 0.3);
  EXPECT_DOUBLE_EQ(bg.steps[0].dynamic.gamma, 0.6);

  const Model ti = read(dynamic("*DYNAMIC, TIME INTEGRATOR=BWE"));
  EXPECT_FALSE(ti.steps[0].dynamic.hht);
}

// TYPE=ROTATING VELOCITY: v = w e x (x - a) about the axis from a to b, the rotational DOFs w e,
// a translation line after it superposed; TYPE=VELOCITY in the node's own system.
TEST(ReaderDynamic, InitialVelocities) {
  std::string d = dynamic("*DYNAMIC");
  d.insert(d.find("*STEP"), "*INITIAL CONDITIONS, TYPE=ROTATING VELOCITY\n2, 2., 0., 0., 0., "
                            "0., 0., 5.\n0.5, 0., 0.\n*INITIAL CONDITIONS, TYPE=VELOCITY\n1, 2, "
                            "-1.5\n");
  const Model m = read(d);
  std::array<double, 6> v2{};
  double v3 = 0.0;
  for (const auto& iv : m.initial_velocities) {
    if (m.node_label(iv.node).key == 2) v2[iv.dof - 1] += iv.value;
    if (m.node_label(iv.node).key == 1 && iv.dof == 2) v3 += iv.value;
  }
  const Vec3 x = m.mesh.coords[m.mesh.find_node(2)];
  EXPECT_DOUBLE_EQ(v2[0], -2.0 * x[1] + 0.5);
  EXPECT_DOUBLE_EQ(v2[1], 2.0 * x[0]);
  EXPECT_DOUBLE_EQ(v2[2], 0.0);
  EXPECT_DOUBLE_EQ(v2[5], 2.0);
  EXPECT_DOUBLE_EQ(v3, -1.5);
  std::string bad = dynamic("*DYNAMIC");
  bad.insert(bad.find("*STEP"),
             "*INITIAL CONDITIONS, TYPE=ROTATING VELOCITY\n2, 2., 1., 1., 1., 1., 1., 1.\n");
  EXPECT_CONTAINS(error_text(bad), "the axis points a and b coincide");
  std::string dof = dynamic("*DYNAMIC");
  dof.insert(dof.find("*STEP"), "*INITIAL CONDITIONS, TYPE=VELOCITY\n2, 7, 1.\n");
  EXPECT_CONTAINS(error_text(dof), "degree of freedom");
}

// IMPACT is in no Keywords Reference we could read; old decks asked with it for the impact
// conditions gapfem always applies to hard gaps: accepted with one warning, IMPACT=NO refused.
TEST(ReaderDynamic, ImpactAsksForWhatHardGapsAlwaysDo) {
  const Model m = read(with_gap("*DYNAMIC, IMPACT"));
  EXPECT_EQ(test::count_warnings(m, "always a fully plastic impact"), 1);
  EXPECT_EQ(test::count_warnings(read(with_gap("*DYNAMIC, IMPACT=YES")), "fully plastic"), 1);
  EXPECT_EQ(test::count_warnings(read(with_gap("*DYNAMIC")), "fully plastic"), 0);
}

TEST(ReaderDynamic, OneClearMessageForEachWrongCombination) {
  EXPECT_CONTAINS(error_text(dynamic("*DYNAMIC, ALPHA=0.1")), "ALPHA must lie between -0.5 and 0");
  EXPECT_CONTAINS(error_text(dynamic("*DYNAMIC, APPLICATION=QUASI-STATIC, ALPHA=-0.1")),
                  "ALPHA is a parameter of the Hilber-Hughes-Taylor integrator");
  EXPECT_CONTAINS(error_text(dynamic("*DYNAMIC, DIRECT, HAFTOL=0.1")),
                  "DIRECT (fixed increments) and HAFTOL (automatic increments) exclude each other");
  EXPECT_CONTAINS(error_text(dynamic("*DYNAMIC, HAFTOL=-1.")),
                  "the half-increment residual tolerance must be a positive force");
  EXPECT_CONTAINS(error_text(dynamic("*DYNAMIC, BETA=0.")), "make the integration unstable");
  EXPECT_CONTAINS(error_text(dynamic("*DYNAMIC, EXPLICIT")), "EXPLICIT");
  EXPECT_CONTAINS(error_text(dynamic("*DYNAMIC, IMPACT=NO")), "IMPACT=NO would let a hard gap");
  EXPECT_CONTAINS(error_text(dynamic("*DYNAMIC, APPLICATION=FAST")), "APPLICATION");
  EXPECT_CONTAINS(error_text(dynamic("*DYNAMIC", "2., 1.")),
                  "the initial increment 2 is larger than the time period 1");
}

} // namespace
} // namespace gapfem
