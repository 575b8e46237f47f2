// Gap elements between real structures: spec M2 (a propped B31 cantilever resting on a GAPUNI), a
// planar CPE4 block on GAPUNI supports, and an axisymmetric CAX4 ring shrunk onto a rigid shaft
// through GAPUNI elements (with and without *CONTACT INTERFERENCE), against closed forms.
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>

using namespace gapfem;
using namespace gapfem::test;

namespace {

// M2: nodes 1..10 at x = 0..9, clamped at node 1, pinned at node 10; GAPUNI from node 4 (x = 3) to
// ground node 20 one unit below, d = 0.5, closure direction (0,-1,0). Square RECT section a = b
// with E = 1e7, nu = 0.3 so that EI = 500 (a^4/12 = 5e-5).
std::string m2_deck(double fy) {
  const double a = std::pow(6e-4, 0.25);
  std::string d = "*NODE\n";
  for (int i = 1; i <= 10; ++i) d += fmt::format("{}, {}., 0., 0.\n", i, i - 1);
  d += "20, 3., -1., 0.\n*ELEMENT, TYPE=B31, ELSET=BEAM\n";
  for (int i = 1; i < 10; ++i) d += fmt::format("{}, {}, {}\n", i, i, i + 1);
  d += fmt::format(R"(*MATERIAL, NAME=M
*ELASTIC
1.E7, 0.3
*BEAM SECTION, ELSET=BEAM, MATERIAL=M, SECTION=RECT
{:.17g}, {:.17g}
0., 0., -1.
*ELEMENT, TYPE=GAPUNI, ELSET=G
101, 4, 20
*GAP, ELSET=G
0.5, 0., -1., 0., 1.
*BOUNDARY
1, 1, 6
10, 1, 3
20, 1, 3
*STEP
*STATIC
*CLOAD
4, 2, {}
*EL PRINT, ELSET=G
S, E
*END STEP
)",
                   a, a, fy);
  return d;
}

/// Flexibility at x = a of a propped cantilever (clamped at 0, pinned at L) with bending and
/// Timoshenko shear (force method on the cantilever; shear correction k = 0.85 of a rectangle, the
/// value B31 uses — docs/theory/structural.md).
double propped_flexibility() {
  const double EI = 500.0, L = 9.0, a = 3.0;
  const double A = std::sqrt(6e-4), G = 1e7 / 2.6, kGA = 0.85 * G * A;
  const double fLL = L * L * L / (3 * EI) + L / kGA;
  const double faL = a * a * (3 * L - a) / (6 * EI) + a / kGA;
  const double faa = a * a * a / (3 * EI) + a / kGA;
  return faa - faL * faL / fLL;
}

} // namespace

TEST(VerificationGapStructures, M2ProppedCantileverOpenAndClosed) {
  const double F = propped_flexibility();
  ASSERT_NEAR(F, 0.0073333, 5e-5) << "Euler-Bernoulli value of the spec plus a small shear part";
  {
    const JobResult r = run_deck(m2_deck(-50.0));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    const Frame& f = last_frame(r);
    EXPECT_NEAR(U(r, f, 4)[1], -50.0 * F, 1e-9);
    EXPECT_EQ(gap(r, f, 101).status, ContactStatus::Open);
    EXPECT_NEAR(gap(r, f, 101).clearance, 0.5 - 50.0 * F, 1e-9);
  }
  {
    const JobResult r = run_deck(m2_deck(-100.0));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    const Frame& f = last_frame(r);
    EXPECT_NEAR(U(r, f, 4)[1], -0.5, 1e-10);
    EXPECT_NEAR(gap(r, f, 101).normal_force, 100.0 - 0.5 / F, 1e-7); // 31.818 in the spec's E-B
  }
}

TEST(VerificationGapStructures, PlanarBlockOnGapSupports) {
  // One CPE4 unit square (thickness 1) on two GAPUNI supports (d = 0) under a top pressure p:
  // uniform plane-strain compression, sigma_yy = -p, sigma_xx = 0 → the top moves down by
  // p (1 - nu^2) / E; each support carries p/2.
  const double p = 10.0, E = 1e3, nu = 0.3;
  const JobResult r = run_deck(fmt::format(R"(*NODE
1, 0., 0.
2, 1., 0.
3, 1., 1.
4, 0., 1.
11, 0., -0.5
12, 1., -0.5
*ELEMENT, TYPE=CPE4, ELSET=B
1, 1, 2, 3, 4
*MATERIAL, NAME=M
*ELASTIC
{}, {}
*SOLID SECTION, ELSET=B, MATERIAL=M
1.
*ELEMENT, TYPE=GAPUNI, ELSET=G
101, 1, 11
102, 2, 12
*GAP, ELSET=G
0., 0., -1., 0., 1.
*BOUNDARY
11, 1, 2
12, 1, 2
1, 1, 1
*STEP
*STATIC
*DLOAD
1, P3, {}
*EL PRINT, ELSET=G
S, E
*END STEP
)",
                                           E, nu, p));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  ASSERT_EQ(r.model->space, ModelSpace::Planar);
  const Frame& f = last_frame(r);
  EXPECT_NEAR(U(r, f, 3)[1], -p * (1 - nu * nu) / E, 1e-12);
  EXPECT_NEAR(U(r, f, 2)[1], 0.0, 1e-12);
  EXPECT_NEAR(gap(r, f, 101).normal_force, p / 2, 1e-9);
  EXPECT_NEAR(gap(r, f, 102).normal_force, p / 2, 1e-9);
}

namespace {
// A ring, inner radius 1, outer 2, height 0.1, 20 CAX4 elements radially, plane strain (u_z = 0
// everywhere), shrunk onto a rigid shaft by an interference delta: GAPUNI from the two inner
// nodes to fixed shaft nodes at the same place, closure direction (-1, 0) (the ring moving inwards
// closes), d = -delta.
std::string ring_deck(double delta, const std::string& interference) {
  const int n = 20;
  std::string d = "*NODE\n";
  for (int i = 0; i <= n; ++i) {
    const double r = 1.0 + i * (1.0 / n);
    d += fmt::format("{}, {:.17g}, 0.\n{}, {:.17g}, 0.1\n", 1 + i, r, 101 + i, r);
  }
  d += "1001, 1., 0.\n1002, 1., 0.1\n*ELEMENT, TYPE=CAX4, ELSET=RING\n";
  for (int i = 0; i < n; ++i)
    d += fmt::format("{}, {}, {}, {}, {}\n", 1 + i, 1 + i, 2 + i, 102 + i, 101 + i);
  d += fmt::format(R"(*NSET, NSET=ALL, GENERATE
1, 21, 1
101, 121, 1
*MATERIAL, NAME=STEEL
*ELASTIC
2.E5, 0.3
*SOLID SECTION, ELSET=RING, MATERIAL=STEEL
*ELEMENT, TYPE=GAPUNI, ELSET=FIT
501, 1, 1001
502, 101, 1002
*GAP, ELSET=FIT
{}, -1., 0., 0., 1.
*BOUNDARY
ALL, 2, 2
1001, 1, 2
1002, 1, 2
*STEP
*STATIC
0.25, 1.
{}*NODE PRINT
U
*EL PRINT, ELSET=FIT
S, E
*END STEP
)",
                   -delta, interference);
  return d;
}
} // namespace

TEST(VerificationGapStructures, AxisymmetricShrinkFitOnRigidShaft) {
  // Lame, plane strain: u = A r + B / r, sigma_rr(b) = 0, u(a) = delta →
  // A = (1 - 2 nu) B / b^2, B = delta / ((1 - 2 nu) a / b^2 + 1 / a);
  // contact pressure p = E B (1/a^2 - 1/b^2) / (1 + nu); total force on the shaft p 2 pi a H.
  const double E = 2e5, nu = 0.3, a = 1.0, b = 2.0, H = 0.1, delta = 1e-3;
  const double B = delta / ((1 - 2 * nu) * a / (b * b) + 1 / a);
  const double A = (1 - 2 * nu) * B / (b * b);
  const double p = E * B * (1 / (a * a) - 1 / (b * b)) / (1 + nu);
  const double total = p * 2 * 3.141592653589793 * a * H;
  for (const std::string opt :
       {std::string(""), std::string("*CONTACT INTERFERENCE, TYPE=ELEMENT, SHRINK\nFIT\n")}) {
    SCOPED_TRACE(opt.empty() ? "resolved at once" : "SHRINK");
    const JobResult r = run_deck(ring_deck(delta, opt));
    ASSERT_EQ(r.exit_code, 0) << r.error;
    ASSERT_EQ(r.model->space, ModelSpace::Axisymmetric);
    const Frame& f = last_frame(r);
    EXPECT_NEAR(U(r, f, 1)[0], delta, 1e-12) << "the bore is pushed out exactly by delta";
    EXPECT_NEAR(U(r, f, 101)[0], delta, 1e-12);
    // outer radius: discretisation error of 20 linear elements is O(h^2) ~ 0.1%
    EXPECT_NEAR(U(r, f, 21)[0], A * b + B / b, 2e-3 * (A * b + B / b));
    const double force = gap(r, f, 501).normal_force + gap(r, f, 502).normal_force;
    EXPECT_NEAR(force, total, 5e-3 * total);
    if (!opt.empty()) {
      // SHRINK: the interference is removed linearly over the step, u(a) = delta t
      for (const Frame& fr : r.frames) EXPECT_NEAR(U(r, fr, 1)[0], delta * fr.step_time, 1e-12);
    }
  }
}

TEST(VerificationGapStructures, GapInputErrorsNameTheElementAndTheRemedy) {
  // coincident nodes without a direction
  const JobResult r1 = run_deck(R"(*NODE
1, 0., 0., 0.
2, 0., 0., 0.
*ELEMENT, TYPE=GAPUNI, ELSET=G
7, 1, 2
*GAP, ELSET=G
0.1
*BOUNDARY
2, 1, 3
*STEP
*STATIC
*END STEP
)");
  EXPECT_EQ(r1.exit_code, 1);
  EXPECT_NE(r1.error.find("element 7 (GAPUNI)"), std::string::npos) << r1.error;
  EXPECT_NE(r1.error.find("direction cosines"), std::string::npos) << r1.error;
  EXPECT_NE(r1.error.find("job.inp:5"), std::string::npos) << r1.error;
  // GAPSPHER with d < 0 and the nodes at the same centre
  const JobResult r2 = run_deck(R"(*NODE
1, 0., 0., 0.
2, 0., 0., 0.
*ELEMENT, TYPE=GAPSPHER, ELSET=G
8, 1, 2
*GAP, ELSET=G
-0.1
*BOUNDARY
2, 1, 3
*STEP
*STATIC
*END STEP
)");
  EXPECT_EQ(r2.exit_code, 1);
  EXPECT_NE(r2.error.find("element 8 (GAPSPHER)"), std::string::npos) << r2.error;
  EXPECT_NE(r2.error.find("its two nodes coincide and d < 0"), std::string::npos) << r2.error;
  EXPECT_NE(r2.error.find("move one node away from the other"), std::string::npos) << r2.error;
  // gap elements without *GAP
  const JobResult r3 = run_deck(R"(*NODE
1, 0., 0., 0.
2, 1., 0., 0.
*ELEMENT, TYPE=GAPUNI, ELSET=G
9, 1, 2
*STEP
*STATIC
*END STEP
)");
  EXPECT_EQ(r3.exit_code, 1);
  EXPECT_NE(r3.error.find("9"), std::string::npos) << r3.error;
  EXPECT_NE(r3.error.find("*GAP"), std::string::npos) << r3.error;
}

namespace {
// M2 with every beam layout: nodes at x = 0, h, 2h, … 9 (h = 1 for two-node, 0.5 for three-node
// elements, so x = 3 is an element end), planar decks without z. Loads and clearance scaled by
// `s`. The ends are held axially, so under NLGEOM the membrane force stiffens the beam by
// ~(w / r_g)^2 (r_g = a / sqrt(12) the radius of gyration): 0.3% at s = 0.01, 3e-5 at s = 0.001,
// where the linear closed form applies to 1e-4.
std::string m2_layout_deck(const std::string& type, double fy, double s, bool nlgeom) {
  const bool planar = type == "B21" || type == "B22";
  const bool three = type == "B22" || type == "B32";
  const int per = three ? 2 : 1, n = 9 * per + 1;
  const double a = std::pow(6e-4, 0.25);
  const char* z = planar ? "" : ", 0.";
  std::string d = "*NODE\n";
  for (int i = 1; i <= n; ++i) d += fmt::format("{}, {:.17g}, 0.{}\n", i, (i - 1.0) / per, z);
  d += fmt::format("100, 3., -1.{}\n*ELEMENT, TYPE={}, ELSET=BEAM\n", z, type);
  for (int i = 1, e = 1; i < n; i += per, ++e)
    d += three ? fmt::format("{}, {}, {}, {}\n", e, i, i + 1, i + 2)
               : fmt::format("{}, {}, {}\n", e, i, i + 1);
  const int gap_node = 3 * per + 1;
  d += fmt::format(R"(*MATERIAL, NAME=M
*ELASTIC
1.E7, 0.3
*BEAM SECTION, ELSET=BEAM, MATERIAL=M, SECTION=RECT
{:.17g}, {:.17g}
*ELEMENT, TYPE=GAPUNI, ELSET=G
101, {}, 100
*GAP, ELSET=G
{:.17g}, 0., -1.{}
*BOUNDARY
1, 1, 2
1, 6
{}, 1, 2
100, 1, 2
)",
                   a, a, gap_node, 0.5 * s, planar ? "" : ", 0.", n);
  if (!planar) d += fmt::format("1, 3, 5\n{}, 3\n{}, 4\n100, 3\n", n, n);
  d += fmt::format("*STEP{}\n*STATIC\n0.25, 1.\n*CLOAD\n{}, 2, {:.17g}\n*END STEP\n",
                   nlgeom ? ", NLGEOM" : "", gap_node, fy * s);
  return d;
}
} // namespace

TEST(VerificationGapStructures, M2WithEveryBeamLayoutLinearAndNlgeom) {
  const double F = propped_flexibility();
  for (const char* type : {"B31", "B32", "B21", "B22"})
    for (bool nlgeom : {false, true}) {
      SCOPED_TRACE(::testing::Message() << type << (nlgeom ? " NLGEOM" : ""));
      const double s = nlgeom ? 0.001 : 0.01, tol = nlgeom ? 1e-4 : 1e-9;
      const int gap_node = (std::string(type) == "B32" || std::string(type) == "B22") ? 7 : 4;
      {
        const JobResult r = run_deck(m2_layout_deck(type, -50.0, s, nlgeom));
        ASSERT_EQ(r.exit_code, 0) << r.error;
        const Frame& f = last_frame(r);
        EXPECT_NEAR(U(r, f, gap_node)[1], -50.0 * s * F, tol * 50.0 * s * F);
        EXPECT_EQ(gap(r, f, 101).status, ContactStatus::Open);
      }
      {
        const JobResult r = run_deck(m2_layout_deck(type, -100.0, s, nlgeom));
        ASSERT_EQ(r.exit_code, 0) << r.error;
        const Frame& f = last_frame(r);
        EXPECT_NEAR(U(r, f, gap_node)[1], -0.5 * s, 1e-10);
        const double force = (100.0 - 0.5 / F) * s;
        EXPECT_NEAR(gap(r, f, 101).normal_force, force, tol * force);
      }
    }
}
