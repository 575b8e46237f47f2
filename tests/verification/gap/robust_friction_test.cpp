// Robust contact (issue 11), part 1: friction histories that used to stop, with closed forms.
// One node pressed against ground through a gap (normal load N = 100 after step 1) and pulled
// tangentially by a spring (k = 100) whose far end is driven by *BOUNDARY: stick from zero
// pressure (step 1), stick to slip (step 2), slip reversed to stick (step 3), opening (step 4).
// The same history on GAPUNI in 3-D, planar and axisymmetric models, on GAPCYL (inside a tube,
// pressed radially, slipping axially), on GAPUNIT in coupled steps and on GAPSPHER (inside a
// sphere: the slider follows the surface, so only the Coulomb bound is checked), for every
// elastic slip from 1e-9 to 1e-1 of the node spacing and for LAGRANGE, with Abaqus's default
// controls and with tight ones: every step converges without a cut-back and matches the closed
// form.
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>

using namespace gapfem;
using namespace gapfem::test;

namespace {

enum class Variant { Gapuni3d, GapuniPlanar, GapuniAxisymmetric, Gapcyl, Gapspher, Gapunit };

std::string variant_name(Variant v) {
  switch (v) {
  case Variant::Gapuni3d:
    return "GAPUNI 3-D";
  case Variant::GapuniPlanar:
    return "GAPUNI planar";
  case Variant::GapuniAxisymmetric:
    return "GAPUNI axisymmetric";
  case Variant::Gapcyl:
    return "GAPCYL";
  case Variant::Gapspher:
    return "GAPSPHER";
  case Variant::Gapunit:
    return "GAPUNIT";
  }
  return "";
}

constexpr double kMu = 0.3, kSpring = 100.0, kNormal = 100.0;
constexpr double kDrive[] = {0.2, 0.6, 0.55, 0.55}; // driver position at the end of steps 1-4

/// Node 1 (the slider) at the origin, ground node 2, driver node 3 on a SPRING2 (DOF 1, k = 100);
/// normal spring k_n = 1 on DOF 2 (holds the node when the gap opens). `friction` is the
/// *FRICTION block.
std::string history_deck(Variant v, const std::string& friction, bool tight) {
  const bool planar = v == Variant::GapuniPlanar || v == Variant::GapuniAxisymmetric;
  const bool radial = v == Variant::Gapcyl || v == Variant::Gapspher;
  const bool coupled = v == Variant::Gapunit;
  std::string d = "*NODE\n1, 0., 0., 0.\n";
  // GAPUNI: ground one unit below, closing downwards; GAPCYL/GAPSPHER: node 1 sits on the wall
  // of a tube (axis x) or sphere of radius 0.1 around node 2 at (0, -0.1, 0), pressed outwards
  // (+y)
  if (radial)
    d += "2, 0., -0.1, 0.\n";
  else
    d += "2, 0., -1., 0.\n";
  d += "3, 1., 0., 0.\n";
  if (v == Variant::GapuniAxisymmetric)
    d += "11, 1., 1., 0.\n12, 2., 1., 0.\n13, 2., 2., 0.\n14, 1., 2., 0.\n";
  if (v == Variant::GapuniPlanar) d += "4, 0., 1., 0.\n";
  const std::string type = v == Variant::Gapcyl     ? "GAPCYL"
                           : v == Variant::Gapspher ? "GAPSPHER"
                           : coupled                ? "GAPUNIT"
                                                    : "GAPUNI";
  d += fmt::format("*ELEMENT, TYPE={}, ELSET=G\n10, 1, 2\n*GAP, ELSET=G\n", type);
  if (v == Variant::Gapcyl)
    d += "0.1, 1., 0., 0., 1.\n"; // axis x: the slip along x is axial
  else if (v == Variant::Gapspher)
    d += "0.1, , , , 1.\n";
  else
    d += "0., 0., -1., 0., 1.\n";
  d += friction + "\n";
  if (coupled) d += "*GAP CONDUCTANCE\n1., 0.\n1., 1.\n";
  d += fmt::format("*ELEMENT, TYPE=SPRING2, ELSET=ST\n20, 1, 3\n*SPRING, ELSET=ST\n1, 1\n{}\n",
                   kSpring);
  if (v == Variant::GapuniPlanar) {
    // the normal spring as a truss (a planar element makes the model planar)
    d += "*ELEMENT, TYPE=T2D2, ELSET=TN\n21, 1, 4\n*SOLID SECTION, ELSET=TN, MATERIAL=MT\n1.\n"
         "*MATERIAL, NAME=MT\n*ELASTIC\n1., 0.3\n";
  } else {
    d += "*ELEMENT, TYPE=SPRING1, ELSET=SN\n21, 1\n*SPRING, ELSET=SN\n2\n1.\n";
  }
  if (v == Variant::GapuniAxisymmetric) // a fixed CAX4 makes the model axisymmetric
    d += "*ELEMENT, TYPE=CAX4, ELSET=DUMMY\n30, 11, 12, 13, 14\n*SOLID SECTION, ELSET=DUMMY, "
         "MATERIAL=MD\n*MATERIAL, NAME=MD\n*ELASTIC\n1000., 0.3\n";
  if (radial || v == Variant::Gapuni3d || coupled)
    d += "*ELEMENT, TYPE=SPRING1, ELSET=SZ\n22, 1\n*SPRING, ELSET=SZ\n3\n1.\n";
  const int last = planar ? 2 : 3;
  d += fmt::format("*BOUNDARY\n2, 1, {0}\n3, 1, 1\n", last);
  if (v == Variant::GapuniPlanar) d += "4, 1, 2\n";
  if (v == Variant::GapuniAxisymmetric) d += "11, 1, 2\n12, 1, 2\n13, 1, 2\n14, 1, 2\n";
  if (coupled) d += "1, 11, 11, 0.\n2, 11, 11, 0.\n";
  // the normal load: towards the ground (GAPUNI: -y) or outwards against the wall (radial: +y);
  // step 4 pulls the node off (by 10 from the ground, by 0.05 into the tube or sphere)
  const double sign = radial ? 1.0 : -1.0;
  const double normal[] = {kNormal, kNormal, kNormal, radial ? -0.05 : -10.0};
  const std::string procedure =
      coupled ? "*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n" : "*STATIC\n";
  // tight: residuals to 1e-7 of the time-averaged force, for the comparison with the closed form
  // (the default R_n = 0.005 accepts an elastic-slip stick force off by up to 0.5 %)
  const std::string controls = tight ? "*CONTROLS, PARAMETERS=FIELD\n1e-7, 1e-6\n" : "";
  for (int s = 0; s < 4; ++s)
    d += fmt::format("*STEP{}, INC=200\n{}0.25, 1.\n{}*CLOAD\n1, 2, {}\n*BOUNDARY\n3, 1, 1, {}\n"
                     "*EL PRINT\nS, E\n*END STEP\n",
                     radial ? ", NLGEOM" : "", procedure, controls, sign * normal[s], kDrive[s]);
  return d;
}

/// The closed form of the history: slider position x and friction force (positive resists a
/// slip along +x) at the end of each step. gamma = 0: exact stick (LAGRANGE).
struct Expected {
  double x, friction;
  bool open = false;
};
std::array<Expected, 4> closed_form(double gamma, double N) {
  std::array<Expected, 4> e{};
  const double crit = kMu * N;
  auto stick = [&](double drive, double p) { // k (drive - x) = k_s (x - p)
    if (gamma == 0.0) return p;
    const double ks = crit / gamma;
    return (kSpring * drive + ks * p) / (kSpring + ks);
  };
  // step 1: N and the drive ramp together, stick throughout (k d t <= mu N t)
  double x = stick(kDrive[0], 0.0);
  e[0] = {x, kSpring * (kDrive[0] - x)};
  // step 2: sticks until the spring reaches mu N, then slips: the spring holds mu N
  x = kDrive[1] - crit / kSpring;
  const double p = x - gamma; // stick point behind the slider by the elastic slip
  e[1] = {x, crit};
  // step 3: the drive moves back by 0.05: stick again, the friction drops to the spring force
  x = stick(kDrive[2], p);
  e[2] = {x, kSpring * (kDrive[2] - x)};
  // step 4: open, no friction: the spring pulls the slider to the driver
  e[3] = {kDrive[3], 0.0, true};
  return e;
}

void check_history(Variant v, const std::string& friction, double gamma, bool tight) {
  SCOPED_TRACE(variant_name(v) + ": " + friction + (tight ? " (tight controls)" : ""));
  const JobResult r = run_deck(history_deck(v, friction, tight));
  ASSERT_EQ(r.exit_code, 0) << r.error << "\n" << history_deck(v, friction, tight);
  for (const IncrementInfo& inc : r.increments)
    EXPECT_TRUE(inc.converged) << "step " << inc.step << " increment " << inc.increment
                               << " was cut back";
  const double N = kNormal;
  if (v == Variant::Gapspher) {
    // on a sphere the slider moves along the surface (no closed form): convergence above and
    // the Coulomb bound here
    for (int s = 1; s <= 4; ++s) {
      const GapRecord& g = gap(r, last_frame(r, s), 10);
      EXPECT_LE(std::hypot(g.friction_force[0], g.friction_force[1]),
                kMu * g.normal_force * (1 + 1e-9) + 1e-12);
    }
    return;
  }
  const auto expected = closed_form(gamma, N);
  for (int s = 1; s <= 4; ++s) {
    const Frame& f = last_frame(r, s);
    const GapRecord& g = gap(r, f, 10);
    const double x = U(r, f, 1)[0];
    const Expected& e = expected[s - 1];
    // default controls: the residual may be 0.5 % of the average force (~ N), so the friction
    // force may be off by that, and the position by that over the spring
    const double ftol = tight ? 1e-6 * N : 5e-3 * N;
    EXPECT_NEAR(x, e.x, tight ? 1e-8 : ftol / kSpring) << "step " << s;
    EXPECT_EQ(g.status == ContactStatus::Open, e.open) << "step " << s;
    if (!e.open) {
      EXPECT_NEAR(g.normal_force, N, ftol) << "step " << s;
      EXPECT_NEAR(g.friction_force[0], e.friction, ftol) << "step " << s;
      EXPECT_EQ(g.status, s == 2 ? ContactStatus::Slip : ContactStatus::Stick) << "step " << s;
    } else {
      EXPECT_EQ(g.friction_force[0], 0.0);
    }
  }
}

} // namespace

TEST(RobustFriction, StickSlipReversalAndOpeningForEveryElasticSlipWithoutCutBacks) {
  for (Variant v : {Variant::Gapuni3d, Variant::GapuniPlanar, Variant::GapuniAxisymmetric,
                    Variant::Gapcyl, Variant::Gapspher, Variant::Gapunit}) {
    for (bool tight : {false, true}) {
      for (int k = -9; k <= -1; ++k) {
        const double gamma = std::pow(10.0, k); // node spacing 1
        check_history(v, fmt::format("*FRICTION, ELASTIC SLIP={}\n{}", gamma, kMu), gamma, tight);
      }
      check_history(v, fmt::format("*FRICTION, LAGRANGE\n{}", kMu), 0.0, tight);
    }
    if (::testing::Test::HasFailure()) return;
  }
}
