// Deck-level verification of the heat-transfer shells DS3, DS4 and DS8 through gapfem::run_job:
// conduction through the wall with a film, a body flux between two held faces (the parabola),
// conduction along a strip, a transient uniform heating, a shell on a brick sharing its SNEG
// temperature, the NT11 … columns of job.dat, and the input errors. Every closed form is derived
// next to its check.
#include "app/job.hpp"
#include "model/model.hpp"
#include "test_util.hpp"

#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>
#include <numbers>
#include <sstream>
#include <string>

namespace gapfem::test {
namespace {

/// DOF 11 + k of node n from a DOF-11 vector and its "more" vector (NodeResults::NT_more …).
double at_point(const Frame& f, const std::vector<double>& first, const std::vector<double>& more,
                NodeId n, int k) {
  if (k == 0) return first.at(n);
  const auto P = static_cast<std::size_t>(f.nodes.temperature_points);
  return more.at((P - 1) * static_cast<std::size_t>(n) + static_cast<std::size_t>(k - 1));
}
/// Temperature DOF 11 + k of a node (by index) in a frame.
double NTi(const Frame& f, NodeId n, int k) {
  return at_point(f, f.nodes.NT, f.nodes.NT_more, n, k);
}
/// Temperature DOF 11 + k of a node (by label) in a frame, and its reaction flux.
double NTk(const JobResult& r, const Frame& f, Label node, int k) {
  return NTi(f, r.model->mesh.find_node(node), k);
}
double RFLk(const JobResult& r, const Frame& f, Label node, int k) {
  return at_point(f, f.nodes.RFL, f.nodes.RFL_more, r.model->mesh.find_node(node), k);
}

/// An nx x ny grid of `type` (DS4 or DS8; DS3: each square cut in two) over [0, a] x [0, b] in
/// the plane z = 0, nodes numbered row by row (DS8: on the 2nx+1 x 2ny+1 grid, centres unused).
std::string plate(const std::string& type, int nx, int ny, double a, double b) {
  const bool quad8 = type == "DS8";
  const int mx = quad8 ? 2 * nx : nx, my = quad8 ? 2 * ny : ny;
  auto id = [&](int i, int j) { return j * (mx + 1) + i + 1; };
  std::string s = "*NODE, NSET=NALL\n";
  for (int j = 0; j <= my; ++j)
    for (int i = 0; i <= mx; ++i) {
      if (quad8 && i % 2 == 1 && j % 2 == 1) continue;
      s += fmt::format("{}, {:.17g}, {:.17g}, 0\n", id(i, j), a * i / mx, b * j / my);
    }
  s += fmt::format("*ELEMENT, TYPE={}, ELSET=PLATE\n", type);
  int e = 1;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if (quad8) {
        const int I = 2 * i, J = 2 * j;
        s += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", e++, id(I, J), id(I + 2, J),
                         id(I + 2, J + 2), id(I, J + 2), id(I + 1, J), id(I + 2, J + 1),
                         id(I + 1, J + 2), id(I, J + 1));
      } else if (type == "DS3") {
        s += fmt::format("{}, {}, {}, {}\n", e++, id(i, j), id(i + 1, j), id(i + 1, j + 1));
        s += fmt::format("{}, {}, {}, {}\n", e++, id(i, j), id(i + 1, j + 1), id(i, j + 1));
      } else {
        s += fmt::format("{}, {}, {}, {}, {}\n", e++, id(i, j), id(i + 1, j), id(i + 1, j + 1),
                         id(i, j + 1));
      }
    }
  s += "*NSET, NSET=X0\n";
  for (int j = 0; j <= my; ++j) s += fmt::format("{}\n", id(0, j));
  s += "*NSET, NSET=XA\n";
  for (int j = 0; j <= my; ++j) s += fmt::format("{}\n", id(mx, j));
  return s;
}

constexpr const char* kMaterial = "*MATERIAL, NAME=M\n*CONDUCTIVITY\n50.0\n"
                                  "*DENSITY\n8000.0\n*SPECIFIC HEAT\n500.0\n";

// Wall of thickness t = 0.02, k = 50, held at 100 on its SNEG side (DOF 11 of every node), a
// film h = 500 to a sink at 20 on its SPOS side. Steady 1-D conduction through the thickness:
// q = (100 - 20) / (t / k + 1 / h) = 80 / 0.0024 = 33333.3 per area; T(SPOS) = 20 + q / h =
// 86.667, linear in between, so the piecewise-quadratic shell with 5 points is exact at every
// point: NT1k = 100 - (100 - 86.667) k / 4. The support supplies the heat the film takes away:
// sum RFL = q A with A = 1 x 0.5. The in-plane flux is zero, HFL3 = q (along +n, SNEG to SPOS).
TEST(HeatShellVerification, WallConductionWithFilmIsLinearThroughTheThickness) {
  for (const std::string type : {"DS3", "DS4", "DS8"}) {
    const std::string deck = plate(type, 2, 2, 1.0, 0.5) +
                             "*SHELL SECTION, ELSET=PLATE, MATERIAL=M\n0.02, 5\n" + kMaterial +
                             "*STEP\n*HEAT TRANSFER, STEADY STATE\n1.0, 1.0\n"
                             "*BOUNDARY\nNALL, 11, 11, 100.0\n"
                             "*FILM\nPLATE, FPOS, 20.0, 500.0\n"
                             "*NODE PRINT\nNT, RFL\n*EL PRINT\nHFL\n*END STEP\n";
    const JobResult r = run_deck(deck);
    ASSERT_EQ(r.exit_code, 0) << type << ": " << r.error;
    const Frame& f = last_frame(r);
    ASSERT_EQ(f.nodes.temperature_points, 5);
    const double q = 80.0 / (0.02 / 50.0 + 1.0 / 500.0), Ttop = 20.0 + q / 500.0;
    double sum = 0.0;
    for (NodeId n = 0; n < r.model->mesh.n_nodes(); ++n)
      for (int k = 0; k < 5; ++k)
        EXPECT_NEAR(NTi(f, n, k), 100.0 - (100.0 - Ttop) * k / 4.0, 1e-8) << type << n << k;
    for (NodeId n = 0; n < r.model->mesh.n_nodes(); ++n) sum += f.nodes.RFL[n];
    EXPECT_NEAR(sum, q * 0.5, 1e-8 * q) << type;
    const OutputBlock* b = f.element(0)->data.find(ElemVar::HFL);
    ASSERT_NE(b, nullptr);
    for (int p = 0; p < b->n_points; ++p) {
      EXPECT_NEAR(b->values[3 * p], 0.0, 1e-8 * q);
      EXPECT_NEAR(b->values[3 * p + 2], q, 1e-8 * q) << type << p;
    }
  }
}

// Body flux r = 2e6 in a plate of thickness t = 0.01 held at 0 on both sides (DOFs 11 and 13 with
// 3 points, 11 and 15 with 5), k = 50: -k T'' = r gives the parabola T(z) = r z (t - z) / (2 k)
// from the SNEG side, which the quadratic interpolation holds exactly: T = r t^2 / (8 k) = 0.5 at
// the middle, 3/8 of it at the quarter points. Each side takes half the heat: RFL = -r A t / 2.
TEST(HeatShellVerification, BodyFluxBetweenHeldSidesIsTheParabola) {
  for (int P : {3, 5}) {
    const std::string deck = plate("DS8", 1, 1, 1.0, 1.0) +
                             fmt::format("*SHELL SECTION, ELSET=PLATE, MATERIAL=M\n0.01, {}\n", P) +
                             kMaterial +
                             "*STEP\n*HEAT TRANSFER, STEADY STATE\n1.0, 1.0\n"
                             "*BOUNDARY\n" +
                             fmt::format("NALL, 11, 11, 0.0\nNALL, {0}, {0}, 0.0\n", 10 + P) +
                             "*DFLUX\nPLATE, BF, 2.0e6\n*END STEP\n";
    const JobResult r = run_deck(deck);
    ASSERT_EQ(r.exit_code, 0) << r.error;
    const Frame& f = last_frame(r);
    const double mid = 2.0e6 * 1e-4 / (8.0 * 50.0);
    double bottom = 0.0, top = 0.0;
    for (NodeId n = 0; n < r.model->mesh.n_nodes(); ++n) {
      const Label l = r.model->mesh.node_labels[n];
      EXPECT_NEAR(NTk(r, f, l, (P - 1) / 2), mid, 1e-10) << P;
      if (P == 5) {
        EXPECT_NEAR(NTk(r, f, l, 1), 0.75 * mid, 1e-10);
        EXPECT_NEAR(NTk(r, f, l, 3), 0.75 * mid, 1e-10);
      }
      bottom += RFLk(r, f, l, 0);
      top += RFLk(r, f, l, P - 1);
    }
    EXPECT_NEAR(bottom, -0.5 * 2.0e6 * 0.01, 1e-6);
    EXPECT_NEAR(top, -0.5 * 2.0e6 * 0.01, 1e-6);
  }
}

// A strip 1 x 0.2, t = 0.004, k = 50, held at 0 at x = 0 and at 100 at x = 1 on all its
// temperatures: linear along x, HFL1 = -k 100 / 1 = -5000 at every point, and the heat through
// the strip k t w dT / L = 50 * 0.004 * 0.2 * 100 = 4 leaves at x = 0 (RFL sum -4) and enters at
// x = 1 (+4).
TEST(HeatShellVerification, ConductionAlongAStrip) {
  for (int P : {1, 3}) {
    const std::string deck =
        plate("DS4", 4, 1, 1.0, 0.2) +
        fmt::format("*SHELL SECTION, ELSET=PLATE, MATERIAL=M\n0.004, {}\n", P) + kMaterial +
        "*STEP\n*HEAT TRANSFER, STEADY STATE\n1.0, 1.0\n*BOUNDARY\n" +
        fmt::format("X0, 11, {0}, 0.0\nXA, 11, {0}, 100.0\n", 10 + P) +
        "*EL PRINT\nHFL\n*END STEP\n";
    const JobResult r = run_deck(deck);
    ASSERT_EQ(r.exit_code, 0) << r.error;
    const Frame& f = last_frame(r);
    EXPECT_NEAR(NTk(r, f, 2, P - 1), 25.0, 1e-9);
    EXPECT_NEAR(NTk(r, f, 7, 0), 25.0, 1e-9);
    double in = 0.0, out = 0.0;
    for (Label n : {1, 6})
      for (int k = 0; k < P; ++k) out += RFLk(r, f, n, k);
    for (Label n : {5, 10})
      for (int k = 0; k < P; ++k) in += RFLk(r, f, n, k);
    EXPECT_NEAR(out, -4.0, 1e-9);
    EXPECT_NEAR(in, 4.0, 1e-9);
    const OutputBlock* b = f.element(2)->data.find(ElemVar::HFL);
    ASSERT_NE(b, nullptr);
    for (int p = 0; p < b->n_points; ++p) EXPECT_NEAR(b->values[3 * p], -5000.0, 1e-7);
  }
}

// An insulated plate (no boundary condition) heated by BF r = 4e5 for 10 s from 20: every point
// rises at r / (rho c) = 0.1 per second (backward Euler is exact for a linear history), so T = 21
// everywhere, and the step's heat balance closes: stored heat = r V t = 4e5 * 0.5 * 0.01 * 10.
TEST(HeatShellVerification, TransientUniformHeatingStoresTheHeat) {
  const std::string deck = plate("DS4", 2, 2, 1.0, 0.5) +
                           "*SHELL SECTION, ELSET=PLATE, MATERIAL=M\n0.01, 3\n" + kMaterial +
                           "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 20.0\n"
                           "*STEP\n*HEAT TRANSFER\n2.0, 10.0\n"
                           "*DFLUX\nPLATE, BF, 4.0e5\n*END STEP\n";
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  for (Label n : {1, 5, 9})
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(NTk(r, f, n, k), 21.0, 1e-9);
  const StepChecks& c = r.steps.back().checks;
  EXPECT_NEAR(c.stored_heat, 4e5 * 0.5 * 0.01 * 10.0, 1e-6);
  EXPECT_LT(c.heat_balance_error, 1e-9 * c.heat_scale);
}

// A DC3D8 brick (k1 = 50, height 0.1) whose top nodes are the DS4 shell's nodes: the shell's DOF
// 11 (its SNEG side) is the brick's temperature there. Bottom of the brick at 0, SPOS side of the
// shell (t = 0.02, k2 = 5, 3 points) takes q = 1000 in (*DFLUX SPOS): the two conduct in series,
// T(brick top) = q L1 / k1 = 2, T(SPOS) = 2 + q t / k2 = 6, and the middle point 4.
TEST(HeatShellVerification, ShellOnABrickSharesItsSnegTemperature) {
  const std::string deck = "*NODE, NSET=NALL\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 0\n4, 0, 1, 0\n"
                           "5, 0, 0, 0.1\n6, 1, 0, 0.1\n7, 1, 1, 0.1\n8, 0, 1, 0.1\n"
                           "*ELEMENT, TYPE=DC3D8, ELSET=BRICK\n1, 1, 2, 3, 4, 5, 6, 7, 8\n"
                           "*ELEMENT, TYPE=DS4, ELSET=SKIN\n2, 5, 6, 7, 8\n"
                           "*SOLID SECTION, ELSET=BRICK, MATERIAL=M\n"
                           "*SHELL SECTION, ELSET=SKIN, MATERIAL=S\n0.02, 3\n"
                           "*MATERIAL, NAME=M\n*CONDUCTIVITY\n50.0\n"
                           "*MATERIAL, NAME=S\n*CONDUCTIVITY\n5.0\n"
                           "*STEP\n*HEAT TRANSFER, STEADY STATE\n1.0, 1.0\n"
                           "*BOUNDARY\n1, 11, 11, 0.0\n2, 11, 11, 0.0\n3, 11, 11, 0.0\n"
                           "4, 11, 11, 0.0\n*DFLUX\nSKIN, SPOS, 1000.0\n*END STEP\n";
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  for (Label n : {5, 6, 7, 8}) {
    EXPECT_NEAR(NTk(r, f, n, 0), 2.0, 1e-9);
    EXPECT_NEAR(NTk(r, f, n, 1), 4.0, 1e-9);
    EXPECT_NEAR(NTk(r, f, n, 2), 6.0, 1e-9);
  }
  double sum = 0.0;
  for (Label n : {1, 2, 3, 4}) sum += f.nodes.RFL[r.model->mesh.find_node(n)];
  EXPECT_NEAR(sum, -1000.0, 1e-8);
}

// job.dat prints one column per temperature DOF (NT11 … NT15); a solid node in the same table
// leaves the further columns blank. The surface-based *SFILM on an SNEG side and a *CFLUX on DOF
// 13 act where they say.
TEST(HeatShellVerification, DatFileHasOneColumnPerTemperatureAndSurfaceLoadsWork) {
  const std::string deck = plate("DS4", 1, 1, 1.0, 1.0) +
                           "*SURFACE, NAME=BOT\nPLATE, SNEG\n"
                           "*SHELL SECTION, ELSET=PLATE, MATERIAL=M\n0.02, 5\n" +
                           kMaterial +
                           "*STEP\n*HEAT TRANSFER, STEADY STATE\n1.0, 1.0\n"
                           "*BOUNDARY\nNALL, 15, 15, 0.0\n*SFILM\nBOT, F, 100.0, 1000.0\n"
                           "*CFLUX\n1, 13, 0.0\n*NODE PRINT\nNT\n*END STEP\n";
  const auto dir = test_dir();
  const JobResult r = run_deck(deck, true);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  // film on SNEG (h = 1000, sink 100), SPOS held at 0, t/k = 4e-4: q = 100 / (1e-3 + 4e-4)
  const double q = 100.0 / (1.0 / 1000.0 + 0.02 / 50.0);
  EXPECT_NEAR(NTk(r, f, 1, 0), q * 0.02 / 50.0, 1e-8);
  std::ifstream in(dir / "job.dat");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string dat = ss.str();
  EXPECT_NE(dat.find("NT11        NT12        NT13        NT14        NT15"), std::string::npos)
      << dat.substr(0, 3000);
}

// Coupled S4RT strip 1 x 0.1 (10 x 1 elements), t = 0.01, alpha = 1e-5, initial temperature 0;
// its SNEG side held at 0 and its SPOS side at 100 (DOFs 11 and 13 of every node; 3 points), one
// node held in all six DOFs and nothing else. Steady conduction gives T linear through the
// thickness: mean 50 and gradient g = 1e4 along +n. A free plate under a linear temperature
// through its thickness deforms without stress: membrane strain alpha * 50 in both directions and
// the isotropic curvature kappa = alpha g = 0.1 that bends the hot SPOS side outwards, so from the
// held node at the origin u1 = 5e-4 x, u2 = 5e-4 y and w = -kappa (x^2 + y^2) / 2 (toward -n = -z
// for this node order). The stresses vanish.
TEST(HeatShellVerification, CoupledPlateBendsFreelyUnderAThroughThicknessGradient) {
  for (const std::string type : {"S4RT", "S8RT"}) {
    std::string deck = plate(type == "S4RT" ? "DS4" : "DS8", 10, 1, 1.0, 0.1);
    const auto at = deck.find("TYPE=DS");
    deck.replace(at, 8, "TYPE=" + type);
    deck += "*SHELL SECTION, ELSET=PLATE, MATERIAL=M\n0.01, 3\n"
            "*MATERIAL, NAME=M\n*ELASTIC\n2.0e11, 0.3\n*EXPANSION\n1.0e-5\n*CONDUCTIVITY\n50.0\n"
            "*STEP\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n1.0, 1.0\n"
            "*BOUNDARY\n1, 1, 6\nNALL, 11, 11, 0.0\nNALL, 13, 13, 100.0\n"
            "*EL PRINT\nS\n*END STEP\n";
    const JobResult r = run_deck(deck);
    ASSERT_EQ(r.exit_code, 0) << type << ": " << r.error;
    const Frame& f = last_frame(r);
    for (NodeId n = 0; n < r.model->mesh.n_nodes(); ++n) {
      const Vec3& X = r.model->mesh.coords[n];
      const Vec3& u = f.nodes.U[n];
      EXPECT_NEAR(u[0], 5e-4 * X[0], 1e-8) << type << " node " << n;
      EXPECT_NEAR(u[1], 5e-4 * X[1], 1e-8) << type << " node " << n;
      EXPECT_NEAR(u[2], -0.05 * (X[0] * X[0] + X[1] * X[1]), 1e-9) << type << " node " << n;
      EXPECT_NEAR(NTi(f, n, 1), 50.0, 1e-9);
    }
    const OutputBlock* s = f.element(4)->data.find(ElemVar::S);
    ASSERT_NE(s, nullptr);
    for (double v : s->values) EXPECT_NEAR(v, 0.0, 1e-3 * 2.0e11 * 1e-5 * 50.0) << type;
  }
}

// A DS4 plate (1 x 1, t = 0.02, k = 5, 3 points) on four DGAP elements (area 0.25 each, gap
// conductance 1000 per area) to ground nodes held at 0, its SPOS side held at 100. Every node is
// alike, so the field is uniform along the plate and each node is a 1-D series of the shell's
// thickness and its gap: q = 100 / (t / k + 1 / k_g) = 100 / 0.005 = 20000 per area, T(SNEG) = q /
// k_g = 20 (the DGAP acts on the shell's DOF 11), the middle point 60, and every gap carries
// q 0.25 = 5000 from the shell to the ground.
TEST(HeatShellVerification, ShellOnThermalGapsConductsInSeries) {
  const std::string deck = "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 0\n4, 0, 1, 0\n"
                           "11, 0, 0, -0.1\n12, 1, 0, -0.1\n13, 1, 1, -0.1\n14, 0, 1, -0.1\n"
                           "*NSET, NSET=GROUND\n11, 12, 13, 14\n*NSET, NSET=SKIN\n1, 2, 3, 4\n"
                           "*ELEMENT, TYPE=DS4, ELSET=PLATE\n1, 1, 2, 3, 4\n"
                           "*ELEMENT, TYPE=DGAP, ELSET=G\n21, 11, 1\n22, 12, 2\n23, 13, 3\n"
                           "24, 14, 4\n*GAP, ELSET=G\n0., , , , 0.25\n"
                           "*GAP CONDUCTANCE\n1000., 0.\n1000., 1.\n"
                           "*SHELL SECTION, ELSET=PLATE, MATERIAL=M\n0.02, 3\n"
                           "*MATERIAL, NAME=M\n*CONDUCTIVITY\n5.0\n"
                           "*STEP\n*HEAT TRANSFER, STEADY STATE\n1.0, 1.0\n"
                           "*BOUNDARY\nGROUND, 11, 11, 0.0\nSKIN, 13, 13, 100.0\n"
                           "*EL PRINT, ELSET=G\nHFL\n*END STEP\n";
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  for (Label n : {1, 2, 3, 4}) {
    EXPECT_NEAR(NTk(r, f, n, 0), 20.0, 1e-9);
    EXPECT_NEAR(NTk(r, f, n, 1), 60.0, 1e-9);
  }
  for (Label g : {21, 22, 23, 24}) {
    const ElementResult* e = f.element(r.model->mesh.find_element(g));
    ASSERT_TRUE(e && e->data.gap);
    EXPECT_NEAR(std::abs(e->data.gap->heat_flow), 5000.0, 1e-7) << g;
  }
  double sum = 0.0;
  for (Label n : {11, 12, 13, 14}) sum += f.nodes.RFL[r.model->mesh.find_node(n)];
  EXPECT_NEAR(sum, -20000.0, 1e-6);
}

// Transient conduction through the thickness: a DS4 wall of thickness L = 0.02 (k = 50, rho c =
// 4e6, diffusivity a = 1.25e-5), initially at 0, its SNEG side held at 100 from t = 0 and its SPOS
// side insulated. The slab solution (separation of variables, x from the held side):
//   T(x, t) = 100 [1 - sum_n 4 / ((2n+1) pi) sin((2n+1) pi x / (2L)) exp(-(2n+1)^2 pi^2 a t /
//   (4L^2))]
// At t = 8 s (a t / L^2 = 0.25) the insulated side is at 100 (1 - 4/pi e^{-pi^2/16} + 4/(3 pi)
// e^{-9 pi^2/16} - ...) = 31.45;
// the shell with 9 points and 0.05 s increments (backward Euler) is within 1 % of it, and so is its
// middle point.
TEST(HeatShellVerification, TransientConductionThroughTheThicknessMatchesTheSlabSolution) {
  const std::string deck = plate("DS4", 1, 1, 1.0, 1.0) +
                           "*SHELL SECTION, ELSET=PLATE, MATERIAL=M\n0.02, 9\n" + kMaterial +
                           "*AMPLITUDE, NAME=ON\n0., 1., 100., 1.\n"
                           "*STEP, INC=1000\n*HEAT TRANSFER\n0.05, 8.0\n"
                           "*BOUNDARY, AMPLITUDE=ON\nNALL, 11, 11, 100.0\n*END STEP\n";
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  const double a = 50.0 / (8000.0 * 500.0), L = 0.02, t = 8.0;
  auto exact = [&](double x) {
    double s = 0.0;
    for (int n = 0; n < 50; ++n) {
      const double m = (2 * n + 1) * std::numbers::pi;
      s += 4.0 / m * std::sin(m * x / (2.0 * L)) * std::exp(-m * m * a * t / (4.0 * L * L));
    }
    return 100.0 * (1.0 - s);
  };
  EXPECT_NEAR(exact(L), 31.45, 0.01); // the closed form itself
  for (Label n : {1, 2, 3, 4}) {
    EXPECT_NEAR(NTk(r, f, n, 8), exact(L), 0.01 * exact(L));
    EXPECT_NEAR(NTk(r, f, n, 4), exact(0.5 * L), 0.01 * exact(0.5 * L));
  }
}

TEST(HeatShellVerification, InputErrors) {
  auto error_of = [](const std::string& deck) {
    const JobResult r = run_deck(deck);
    EXPECT_EQ(r.exit_code, 1) << deck;
    return r.error;
  };
  const std::string mesh = plate("DS4", 1, 1, 1.0, 1.0);
  const std::string step = "*STEP\n*HEAT TRANSFER, STEADY STATE\n1.0, 1.0\n";
  // a pressure needs displacements
  EXPECT_NE(error_of(mesh + "*SHELL SECTION, ELSET=PLATE, MATERIAL=M\n0.01, 3\n" + kMaterial +
                     step + "*DLOAD\nPLATE, P, 1.0\n*END STEP\n")
                .find("displacement"),
            std::string::npos);
  // SNEG names a shell's side, not a brick's face
  const std::string brick = "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 0\n4, 0, 1, 0\n"
                            "5, 0, 0, 1\n6, 1, 0, 1\n7, 1, 1, 1\n8, 0, 1, 1\n"
                            "*ELEMENT, TYPE=DC3D8, ELSET=B\n1, 1, 2, 3, 4, 5, 6, 7, 8\n"
                            "*SOLID SECTION, ELSET=B, MATERIAL=M\n";
  EXPECT_NE(error_of(brick + kMaterial + step + "*DFLUX\nB, SNEG, 1.0\n*END STEP\n")
                .find("side of a heat-transfer shell"),
            std::string::npos);
  // one section point is for heat-transfer shells only
  const std::string s4r = "*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 0\n4, 0, 1, 0\n"
                          "*ELEMENT, TYPE=S4R, ELSET=S\n1, 1, 2, 3, 4\n"
                          "*SHELL SECTION, ELSET=S, MATERIAL=E\n0.01, 1\n"
                          "*MATERIAL, NAME=E\n*ELASTIC\n2e11, 0.3\n";
  EXPECT_NE(error_of(s4r + "*STEP\n*STATIC\n*BOUNDARY\n1, 1, 6\n*END STEP\n")
                .find("at least 3 section points"),
            std::string::npos);
  // an even number of points
  EXPECT_NE(error_of(mesh + "*SHELL SECTION, ELSET=PLATE, MATERIAL=M\n0.01, 4\n" + kMaterial +
                     step + "*END STEP\n")
                .find("odd number"),
            std::string::npos);
  // no conductivity
  EXPECT_NE(error_of(mesh +
                     "*SHELL SECTION, ELSET=PLATE, MATERIAL=E\n0.01, 3\n"
                     "*MATERIAL, NAME=E\n*ELASTIC\n2e11, 0.3\n" +
                     step + "*END STEP\n")
                .find("CONDUCTIVITY"),
            std::string::npos);
  // a static step
  EXPECT_NE(error_of(mesh + "*SHELL SECTION, ELSET=PLATE, MATERIAL=M\n0.01, 3\n" + kMaterial +
                     "*STEP\n*STATIC\n*END STEP\n")
                .find("is a heat-transfer element and cannot be used in a *STATIC step"),
            std::string::npos);
  // a flux on DOF 14 of a 3-point shell
  EXPECT_NE(error_of(mesh + "*SHELL SECTION, ELSET=PLATE, MATERIAL=M\n0.01, 3\n" + kMaterial +
                     step + "*CFLUX\n1, 14, 5.0\n*END STEP\n")
                .find("DOF 14"),
            std::string::npos);
}

} // namespace
} // namespace gapfem::test
