// Deck-level verification of heat transfer and coupled temperature-displacement analyses through
// gapfem::run_job: steady conduction with flux, film and body-flux boundary conditions, transient
// conduction into a semi-infinite body against the erfc solution, DELTMX incrementation, heat
// balances, coupled thermal expansion, and radial conduction in axisymmetric and plane models.
// Every closed form is derived next to its check.
#include "app/job.hpp"
#include "model/model.hpp"
#include "test_util.hpp"

#include <array>
#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <numbers>
#include <string>
#include <vector>

namespace gapfem::test {
namespace {

double NT(const JobResult& r, const Frame& f, Label node) {
  return f.nodes.NT.at(r.model->mesh.find_node(node));
}
double RFL(const JobResult& r, const Frame& f, Label node) {
  return f.nodes.RFL.at(r.model->mesh.find_node(node));
}
const OutputBlock& block(const JobResult& r, const Frame& f, Label elem, ElemVar v) {
  const ElementResult* e = f.element(r.model->mesh.find_element(elem));
  if (!e || !e->data.find(v)) throw std::runtime_error("no output block");
  return *e->data.find(v);
}

/// Nodes 1..n+1 at x = i L / n and n two-node elements of `type` (DC1D2 or T3D2T).
std::string line_mesh(int n, double L, const std::string& type) {
  std::string s = "*NODE, NSET=NALL\n";
  for (int i = 0; i <= n; ++i) s += fmt::format("{}, {:.17g}, 0, 0\n", i + 1, L * i / n);
  s += fmt::format("*ELEMENT, TYPE={}, ELSET=BAR\n", type);
  for (int i = 1; i <= n; ++i) s += fmt::format("{}, {}, {}\n", i, i, i + 1);
  return s;
}

/// A bar of n bricks along x with a 1 x 1 cross-section: nodes 4i+1..4i+4 at x_i (y, z corners
/// (0,0), (1,0), (1,1), (0,1)); face S6 of element 1 is the end x = 0, face S4 of element n the
/// end x = L. Node sets X0 and XL hold the end nodes.
std::string brick_bar(int n, double L, const std::string& type) {
  std::string s = "*NODE, NSET=NALL\n";
  const double yz[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i = 0; i <= n; ++i)
    for (int c = 0; c < 4; ++c)
      s += fmt::format("{}, {:.17g}, {}, {}\n", 4 * i + c + 1, L * i / n, yz[c][0], yz[c][1]);
  // Abaqus order: face 1-2-3-4 at z = 0 counter-clockwise seen from +z ... with xi along x,
  // eta along y, zeta along z.
  auto id = [](int i, int c) { return 4 * i + c + 1; };
  s += fmt::format("*ELEMENT, TYPE={}, ELSET=BAR\n", type);
  for (int i = 0; i < n; ++i)
    s += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", i + 1, id(i, 0), id(i + 1, 0),
                     id(i + 1, 1), id(i, 1), id(i, 3), id(i + 1, 3), id(i + 1, 2), id(i, 2));
  s += fmt::format("*NSET, NSET=X0\n1, 2, 3, 4\n*NSET, NSET=XL\n{}, {}, {}, {}\n", id(n, 0),
                   id(n, 1), id(n, 2), id(n, 3));
  return s;
}

// ---------------------------------------------------------------------------------- steady

// DC1D2 bar, L = 1, area A = 2, k = 5: T = 100 at x = 0, CFLUX Q = 30 into x = L. Steady 1-D
// conduction: Q = k A dT/dx, so T(x) = 100 + Q x / (k A) = 100 + 3 x (linear elements are exact),
// HFL1 = -k dT/dx = -15 (heat flows towards x = 0), and the support takes the heat out: RFL = -30.
TEST(ThermalVerification, SteadyLinkWithConcentratedFlux) {
  const std::string deck = line_mesh(4, 1.0, "DC1D2") +
                           "*SOLID SECTION, ELSET=BAR, MATERIAL=M\n2.0\n"
                           "*MATERIAL, NAME=M\n*CONDUCTIVITY\n5.0\n"
                           "*STEP\n*HEAT TRANSFER, STEADY STATE\n1.0, 1.0\n"
                           "*BOUNDARY\n1, 11, 11, 100.0\n*CFLUX\n5, 11, 30.0\n"
                           "*NODE PRINT\nNT, RFL\n*EL PRINT\nHFL\n*END STEP\n";
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  for (int i = 0; i <= 4; ++i) EXPECT_NEAR(NT(r, f, i + 1), 100.0 + 3.0 * i / 4.0, 1e-10);
  EXPECT_NEAR(RFL(r, f, 1), -30.0, 1e-10);
  for (Label e = 1; e <= 4; ++e)
    for (double q : block(r, f, e, ElemVar::HFL).values) EXPECT_NEAR(q, -15.0, 1e-10);
  // A linear problem converges in one iteration.
  EXPECT_EQ(r.steps[0].iterations, 1);
  const StepChecks& c = r.steps[0].checks;
  EXPECT_TRUE(c.thermal);
  EXPECT_NEAR(c.reaction_flux_sum, -30.0, 1e-10);
  EXPECT_NEAR(c.applied_flux_sum, 30.0, 1e-10);
  EXPECT_EQ(c.stored_heat, 0.0);
  EXPECT_LE(c.heat_balance_error, 1e-12 * c.heat_scale);
}

// DC1D2 bar with body flux r = 12 per volume, k = 3, A = 1, L = 2, both ends at T = 10:
// k T'' + r = 0 gives T = 10 + r x (L - x) / (2 k). Linear elements with the consistent load are
// nodally exact for this 1-D problem, so the nodal values match to round-off.
TEST(ThermalVerification, SteadyLinkWithBodyFlux) {
  const std::string deck = line_mesh(8, 2.0, "DC1D2") +
                           "*SOLID SECTION, ELSET=BAR, MATERIAL=M\n"
                           "*MATERIAL, NAME=M\n*CONDUCTIVITY\n3.0\n"
                           "*STEP\n*HEAT TRANSFER, STEADY STATE\n"
                           "*BOUNDARY\n1, 11, 11, 10.0\n9, 11, 11, 10.0\n*DFLUX\nBAR, BF, 12.0\n"
                           "*END STEP\n";
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  for (int i = 0; i <= 8; ++i) {
    const double x = 2.0 * i / 8.0;
    EXPECT_NEAR(NT(r, f, i + 1), 10.0 + 12.0 * x * (2.0 - x) / 6.0, 1e-9) << "node " << i + 1;
  }
  // Half the generated heat r A L = 24 leaves at each end.
  EXPECT_NEAR(RFL(r, f, 1), -12.0, 1e-9);
  EXPECT_NEAR(RFL(r, f, 9), -12.0, 1e-9);
  EXPECT_LE(r.steps[0].checks.heat_balance_error, 1e-12 * r.steps[0].checks.heat_scale);
}

// DC3D8 bar (1 x 1 section, L = 2, k = 4) held at 100 at x = 0 and cooled by a film h = 10,
// T_sink = 20 on the end x = L: series resistances L/k + 1/h = 0.6, so the flux is
// q = (100 - 20) / 0.6 = 133.33, T(x) = 100 - q x / k, the end is at 100 - q L / k = 33.33, and
// HFL1 = q everywhere. The second step replaces the film by a surface flux of 50 into the end
// (DFLUX S4): T(x) = 100 + 50 x / k, HFL1 = -50.
TEST(ThermalVerification, SteadyBrickBarWithFilmThenSurfaceFlux) {
  const std::string deck = brick_bar(5, 2.0, "DC3D8") +
                           "*SOLID SECTION, ELSET=BAR, MATERIAL=M\n"
                           "*MATERIAL, NAME=M\n*CONDUCTIVITY\n4.0\n"
                           "*STEP\n*HEAT TRANSFER, STEADY STATE\n"
                           "*BOUNDARY\nX0, 11, 11, 100.0\n*FILM\n5, F4, 20.0, 10.0\n"
                           "*EL PRINT\nHFL\n*END STEP\n"
                           "*STEP\n*HEAT TRANSFER, STEADY STATE\n"
                           "*FILM, OP=NEW\n*DFLUX\n5, S4, 50.0\n*END STEP\n";
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const double q = 80.0 / 0.6;
  const Frame& f1 = last_frame(r, 1);
  for (int i = 0; i <= 5; ++i)
    for (int c = 1; c <= 4; ++c)
      EXPECT_NEAR(NT(r, f1, 4 * i + c), 100.0 - q * (2.0 * i / 5.0) / 4.0, 1e-9);
  for (Label e = 1; e <= 5; ++e) {
    const OutputBlock& b = block(r, f1, e, ElemVar::HFL);
    ASSERT_EQ(b.names.size(), 3u);
    for (int p = 0; p < b.n_points; ++p) {
      EXPECT_NEAR(b.values[3 * p], q, 1e-9);
      EXPECT_NEAR(b.values[3 * p + 1], 0.0, 1e-9);
      EXPECT_NEAR(b.values[3 * p + 2], 0.0, 1e-9);
    }
  }
  // Heat balance of step 1: the support supplies q (RFL sum), the film takes it (applied -q).
  const StepChecks& c1 = r.steps[0].checks;
  EXPECT_NEAR(c1.reaction_flux_sum, q, 1e-9);
  EXPECT_NEAR(c1.applied_flux_sum, -q, 1e-9);
  const Frame& f2 = last_frame(r, 2);
  for (int i = 0; i <= 5; ++i)
    EXPECT_NEAR(NT(r, f2, 4 * i + 1), 100.0 + 50.0 * (2.0 * i / 5.0) / 4.0, 1e-9);
  EXPECT_NEAR(r.steps[1].checks.reaction_flux_sum, -50.0, 1e-9);
}

/// A structured nx x ny mesh of DC2D4 (or DC2D3: each quad split along its 1-3 diagonal) on
/// [0, 1]^2 with perturbed interior nodes; node set EDGE holds the boundary nodes.
std::string planar_patch(int nx, int ny, const std::string& type, double thickness,
                         std::vector<std::array<double, 2>>& xy) {
  xy.clear();
  std::string s = "*NODE, NSET=NALL\n", edge = "*NSET, NSET=EDGE\n";
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      double x = static_cast<double>(i) / nx, y = static_cast<double>(j) / ny;
      const bool boundary = i == 0 || j == 0 || i == nx || j == ny;
      if (!boundary) {
        x += 0.2 / nx * std::sin(1.0 + 3 * i + 5 * j);
        y += 0.2 / ny * std::cos(2.0 + 7 * i + j);
      }
      xy.push_back({x, y});
      const int id = static_cast<int>(xy.size());
      s += fmt::format("{}, {:.17g}, {:.17g}\n", id, x, y);
      if (boundary) edge += fmt::format("{}\n", id);
    }
  auto id = [&](int i, int j) { return 1 + i + (nx + 1) * j; };
  s += fmt::format("*ELEMENT, TYPE={}, ELSET=PLATE\n", type);
  int e = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (type == "DC2D3")
        s += fmt::format("{}, {}, {}, {}\n{}, {}, {}, {}\n", e + 1, a, b, c, e + 2, a, c, d),
            e += 2;
      else
        s += fmt::format("{}, {}, {}, {}, {}\n", ++e, a, b, c, d);
    }
  return s + edge + fmt::format("*SOLID SECTION, ELSET=PLATE, MATERIAL=M\n{}\n", thickness);
}

// Patch test on distorted meshes: with the boundary nodes held at the linear field
// T = 10 + 3 x - 2 y (a solution of the steady heat equation), every interior node takes the
// exact value and every integration point reports HFL = -k grad T = (-6, 4) (k = 2), to round-off.
TEST(ThermalVerification, SteadyPatchTestOnDistortedMeshes) {
  for (const std::string type : {"DC2D4", "DC2D3"}) {
    std::vector<std::array<double, 2>> xy;
    std::string deck = planar_patch(3, 3, type, 0.5, xy) +
                       "*MATERIAL, NAME=M\n*CONDUCTIVITY\n2.0\n"
                       "*STEP\n*HEAT TRANSFER, STEADY STATE\n*BOUNDARY\n";
    for (std::size_t n = 0; n < xy.size(); ++n) {
      const double x = xy[n][0], y = xy[n][1];
      if (x == 0.0 || y == 0.0 || x == 1.0 || y == 1.0)
        deck += fmt::format("{}, 11, 11, {:.17g}\n", n + 1, 10.0 + 3.0 * x - 2.0 * y);
    }
    deck += "*EL PRINT\nHFL\n*END STEP\n";
    const JobResult r = run_deck(deck, false, type);
    ASSERT_EQ(r.exit_code, 0) << r.error;
    const Frame& f = last_frame(r);
    for (std::size_t n = 0; n < xy.size(); ++n)
      EXPECT_NEAR(NT(r, f, static_cast<Label>(n + 1)), 10.0 + 3.0 * xy[n][0] - 2.0 * xy[n][1],
                  1e-10)
          << type << " node " << n + 1;
    for (const ElementResult& er : f.elements) {
      const OutputBlock* b = er.data.find(ElemVar::HFL);
      ASSERT_NE(b, nullptr);
      for (int p = 0; p < b->n_points; ++p) {
        EXPECT_NEAR(b->values[2 * p], -6.0, 1e-9) << type;
        EXPECT_NEAR(b->values[2 * p + 1], 4.0, 1e-9) << type;
      }
    }
  }
}

// ---------------------------------------------------------------------------------- transient

/// Semi-infinite body (a long DC1D2 rod, L = 1 with 200 elements, k = rho c = 1 so alpha = 1)
/// initially at 0 whose surface x = 0 is raised to 100 at t = 0. Exact:
/// T = 100 erfc(x / (2 sqrt(alpha t))). At t = 0.01 the disturbance reaches ~4 sqrt(alpha t) = 0.4,
/// well inside the rod. Returns the largest nodal error at t = 0.01 with n_inc fixed increments.
double semi_infinite_error(int n_inc, JobResult* keep = nullptr) {
  const double t_end = 0.01;
  std::string deck = line_mesh(200, 1.0, "DC1D2") +
                     "*SOLID SECTION, ELSET=BAR, MATERIAL=M\n1.0\n"
                     "*MATERIAL, NAME=M\n*CONDUCTIVITY\n1.0\n*DENSITY\n1.0\n*SPECIFIC HEAT\n1.0\n"
                     "*STEP, INC=1000\n*HEAT TRANSFER\n" +
                     fmt::format("{:.17g}, {:.17g}\n", t_end / n_inc, t_end) +
                     "*BOUNDARY\n1, 11, 11, 100.0\n*END STEP\n";
  JobResult r = run_deck(deck, false, fmt::format("semi_{}", n_inc));
  EXPECT_EQ(r.exit_code, 0) << r.error;
  if (r.exit_code != 0) return 1e9;
  EXPECT_EQ(r.steps[0].increments, n_inc); // no DELTMX: fixed increments
  const Frame& f = last_frame(r);
  EXPECT_NEAR(f.step_time, t_end, 1e-15);
  double err = 0.0;
  for (int i = 0; i <= 200; ++i) {
    const double x = i / 200.0;
    const double exact = 100.0 * std::erfc(x / (2.0 * std::sqrt(t_end)));
    err = std::max(err, std::abs(NT(r, f, i + 1) - exact));
  }
  if (keep) *keep = std::move(r);
  return err;
}

// Backward Euler is first order in time: halving the increment should about halve the error once
// the time error dominates the spatial one (h = 0.005 against a profile width 0.2: the spatial
// error is ~0.01 degrees). Each halving must cut the error by at least 35% (first order gives
// 50%), and the finest run must be within 1% of the 100-degree step.
TEST(ThermalVerification, TransientSemiInfiniteConductionConvergesInTime) {
  std::vector<double> err;
  for (int n : {5, 10, 20, 40}) err.push_back(semi_infinite_error(n));
  for (std::size_t i = 1; i < err.size(); ++i)
    EXPECT_LT(err[i], 0.65 * err[i - 1])
        << "n_inc doubling " << i << ": " << err[i - 1] << " -> " << err[i];
  EXPECT_LT(err.back(), 1.0);
}

// Heat balance of the transient run: the heat that entered through the prescribed surface (RFL
// integrated over the increments) equals the heat stored, rho c integral(T - 0) dV, to solver
// round-off (each increment is linear and converges in one iteration).
TEST(ThermalVerification, TransientHeatBalanceCloses) {
  JobResult r;
  semi_infinite_error(10, &r);
  ASSERT_EQ(r.exit_code, 0);
  const StepChecks& c = r.steps[0].checks;
  EXPECT_TRUE(c.thermal);
  EXPECT_GT(c.stored_heat, 0.0);
  EXPECT_EQ(c.applied_flux_sum, 0.0);
  EXPECT_NEAR(c.reaction_flux_sum, c.stored_heat, 1e-9 * c.heat_scale);
  // Lumped nodal storage: sum over nodes of V_a T_a (rho c = 1, A = 1).
  const Frame& f = last_frame(r);
  double stored = 0.0;
  for (int i = 0; i <= 200; ++i)
    stored += (i == 0 || i == 200 ? 0.5 : 1.0) / 200.0 * NT(r, f, i + 1);
  EXPECT_NEAR(c.stored_heat, stored, 1e-12);
  // The exact heat entering a semi-infinite body: 100 * 2 sqrt(t / pi) (k = rho c = 1); the
  // backward Euler run with 10 increments stores it to within 5%.
  EXPECT_NEAR(c.stored_heat, 200.0 * std::sqrt(0.01 / std::numbers::pi), 0.05 * c.stored_heat);
}

// An insulated DC3D8 cube (V = 1) with uniform body flux r = 6, rho c = 3 (rho = 2, c = 1.5),
// initially at 20: every point heats at r / (rho c) = 2 per unit time, so at t = 2 the whole cube
// is at 24 exactly (lumped capacity, uniform load: no spatial or time error), the applied heat is
// r V t = 12 and all of it is stored. Temperature-dependent conductivity does not matter (no
// gradient) but makes the step nonlinear in form; DELTMX = 1 must keep every increment's rise at
// or below 1 degree.
TEST(ThermalVerification, InsulatedCubeWithBodyFluxStoresAllHeat) {
  const std::string deck = brick_bar(1, 1.0, "DC3D8") +
                           "*SOLID SECTION, ELSET=BAR, MATERIAL=M\n"
                           "*MATERIAL, NAME=M\n*CONDUCTIVITY\n1.0, 0.\n3.0, 100.\n"
                           "*DENSITY\n2.0\n*SPECIFIC HEAT\n1.5\n"
                           "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 20.0\n"
                           "*STEP, INC=100\n*HEAT TRANSFER, DELTMX=1.0\n0.1, 2.0\n"
                           "*DFLUX\nBAR, BF, 6.0\n*NODE PRINT\nNT\n*END STEP\n";
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  for (int n = 1; n <= 8; ++n) EXPECT_NEAR(NT(r, f, n), 24.0, 1e-9);
  const StepChecks& c = r.steps[0].checks;
  EXPECT_NEAR(c.applied_flux_sum, 12.0, 1e-9);
  EXPECT_NEAR(c.stored_heat, 12.0, 1e-9);
  EXPECT_EQ(c.reaction_flux_sum, 0.0);
  EXPECT_LE(c.heat_balance_error, 1e-9);
  // DELTMX: the rise per increment is 2 dt <= 1, so dt <= 0.5; the increments grow from 0.1.
  double dt_max = 0.0;
  for (const IncrementInfo& i : r.increments)
    if (i.converged) dt_max = std::max(dt_max, i.dt);
  EXPECT_LE(dt_max, 0.5 * (1.0 + 1e-12));
  EXPECT_GT(dt_max, 0.1);
  double previous = 20.0;
  for (const Frame& fr : r.frames) {
    if (fr.step != 1) continue;
    const double now = fr.nodes.NT[0];
    EXPECT_LE(now - previous, 1.0 + 1e-9) << "increment " << fr.increment;
    previous = now;
  }
}

// A nonlinear transient: DC2D4 plate (thickness 0.5) with temperature-dependent conductivity and
// capacity (tables over 0..200), initially at 20, one edge raised to 150 and the opposite edge
// cooled by a film (h = 5, sink 0), DELTMX = 8. The heat balance integrates the fluxes of the
// converged increments: RFL + films = stored heat, up to the Newton residuals left at convergence
// (quadratic convergence leaves them far below the 0.5% criterion; 1e-6 of the heat moved is
// required), and the stored heat agrees with rho c integral E(T) dV from the final temperatures
// (computed by the kernels with the same lumping).
TEST(ThermalVerification, NonlinearTransientHeatBalanceCloses) {
  std::vector<std::array<double, 2>> xy;
  std::string deck = planar_patch(4, 2, "DC2D4", 0.5, xy) +
                     "*MATERIAL, NAME=M\n*CONDUCTIVITY\n1.0, 0.\n3.0, 200.\n"
                     "*DENSITY\n2.0, 0.\n1.5, 200.\n*SPECIFIC HEAT\n1.0, 0.\n2.0, 200.\n"
                     "*NSET, NSET=LEFT, GENERATE\n1, 11, 5\n"
                     "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 20.0\n"
                     "*STEP, INC=400\n*HEAT TRANSFER, DELTMX=8.0\n0.01, 1.0\n"
                     "*BOUNDARY\nLEFT, 11, 11, 150.0\n*FILM\n4, F2, 0.0, 5.0\n8, F2, 0.0, 5.0\n"
                     "*END STEP\n";
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const StepChecks& c = r.steps[0].checks;
  EXPECT_GT(c.stored_heat, 0.0);
  EXPECT_LT(c.applied_flux_sum, 0.0); // the film cools
  EXPECT_LE(c.heat_balance_error, 1e-6 * c.heat_scale)
      << "RFL " << c.reaction_flux_sum << " applied " << c.applied_flux_sum << " stored "
      << c.stored_heat;
  EXPECT_GT(r.steps[0].increments, 5);
}

// DELTMX on the semi-infinite problem: the first increment at the surface jump overshoots a
// DELTMX of 10 and is repeated smaller (Abaqus: 0.85 DELTMX / dT_max times the size); afterwards
// the increments grow while every accepted increment changes no free node by more than DELTMX.
TEST(ThermalVerification, DeltmxControlsTheIncrements) {
  const std::string deck =
      line_mesh(100, 1.0, "DC1D2") +
      "*SOLID SECTION, ELSET=BAR, MATERIAL=M\n1.0\n"
      "*MATERIAL, NAME=M\n*CONDUCTIVITY\n1.0\n*DENSITY\n1.0\n*SPECIFIC HEAT\n1.0\n"
      "*STEP, INC=500\n*HEAT TRANSFER, DELTMX=10.0\n1e-3, 0.02\n"
      "*BOUNDARY\n1, 11, 11, 100.0\n*NODE PRINT\nNT\n*END STEP\n";
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  int redone = 0;
  double dt_first = 0.0, dt_last = 0.0;
  for (const IncrementInfo& i : r.increments) {
    if (!i.converged) {
      ++redone;
      EXPECT_TRUE(i.deltmx_exceeded); // Newton converged; DELTMX asked for the repetition
    }
    if (i.converged && dt_first == 0.0) dt_first = i.dt;
    if (i.converged) dt_last = i.dt;
  }
  EXPECT_GE(redone, 1);
  EXPECT_LT(dt_first, 1e-3);
  EXPECT_GT(dt_last, 2.0 * dt_first);
  std::vector<double> previous(101, 0.0);
  for (const Frame& fr : r.frames) {
    double change = 0.0;
    for (int n = 2; n <= 101; ++n) { // node 1 carries the boundary condition
      const double T = NT(r, fr, n);
      change = std::max(change, std::abs(T - previous[n - 1]));
      previous[n - 1] = T;
    }
    EXPECT_LE(change, 10.0 * (1.0 + 1e-9)) << "increment " << fr.increment;
  }
  EXPECT_NEAR(last_frame(r).step_time, 0.02, 1e-12);
}

// ---------------------------------------------------------------------------------- coupled

constexpr double kE = 2.0e5, kNu = 0.3, kAlpha = 1.0e-5;

std::string coupled_material() {
  return fmt::format("*MATERIAL, NAME=M\n*ELASTIC\n{}, {}\n*EXPANSION\n{}\n*CONDUCTIVITY\n50.0\n"
                     "*DENSITY\n7.8e-9\n*SPECIFIC HEAT\n4.6e8\n",
                     kE, kNu, kAlpha);
}

// C3D8T bar 4 x 1 x 1 heated uniformly from the initial 20 to 120 (all NT prescribed), on
// symmetry supports (x = 0: U1, y = 0: U2, z = 0: U3): a free thermal expansion, so U1 at x = L is
// alpha L dT = 4e-3 and the stress is zero. Step 2 also holds x = L: uniaxial restraint, so
// S11 = -E alpha dT = -200 and the lateral stresses stay zero.
TEST(ThermalVerification, CoupledBarFreeThenRestrainedExpansion) {
  std::string deck = brick_bar(4, 4.0, "C3D8T") + "*SOLID SECTION, ELSET=BAR, MATERIAL=M\n" +
                     coupled_material() +
                     "*NSET, NSET=Y0, GENERATE\n1, 17, 4\n4, 20, 4\n"
                     "*NSET, NSET=Z0, GENERATE\n1, 17, 4\n2, 18, 4\n"
                     "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 20.0\n"
                     "*STEP\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n"
                     "*BOUNDARY\nX0, 1, 1\nY0, 2, 2\nZ0, 3, 3\nNALL, 11, 11, 120.0\n"
                     "*EL PRINT\nS\n*END STEP\n"
                     "*STEP\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n"
                     "*BOUNDARY\nXL, 1, 1, 0.0\n*END STEP\n";
  // Corner c of each section (label 4i + c): c = 1 (y, z) = (0, 0), 2 (1, 0), 3 (1, 1), 4 (0, 1);
  // Y0 holds c = 1, 4 and Z0 c = 1, 2 of every section.
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f1 = last_frame(r, 1);
  for (Label n = 17; n <= 20; ++n) EXPECT_NEAR(U(r, f1, n)[0], kAlpha * 4.0 * 100.0, 1e-12);
  for (Label e = 1; e <= 4; ++e)
    for (double s : block(r, f1, e, ElemVar::S).values) EXPECT_NEAR(s, 0.0, 1e-6);
  const Frame& f2 = last_frame(r, 2);
  for (Label e = 1; e <= 4; ++e) {
    const OutputBlock& s = block(r, f2, e, ElemVar::S);
    for (int p = 0; p < s.n_points; ++p) {
      EXPECT_NEAR(s.values[6 * p + 0], -kE * kAlpha * 100.0, 1e-6);
      for (int c = 1; c < 6; ++c) EXPECT_NEAR(s.values[6 * p + c], 0.0, 1e-6);
    }
  }
  // The coupled tangent is unsymmetric; the steps are linear and converge in one iteration.
  EXPECT_EQ(r.steps[0].iterations, 1);
}

// T3D2T truss (area 0.5) fixed at both ends, initially at 20, with both end temperatures held at
// 70 in a steady coupled step: NT = 70 everywhere and S11 = -E alpha dT = -100.
TEST(ThermalVerification, CoupledTrussRestrainedHeating) {
  const std::string deck = line_mesh(3, 3.0, "T3D2T") +
                           "*SOLID SECTION, ELSET=BAR, MATERIAL=M\n0.5\n" + coupled_material() +
                           "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 20.0\n"
                           "*STEP\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n"
                           "*BOUNDARY\n1, 1, 3\n4, 1, 3\n2, 2, 3\n3, 2, 3\n1, 11, 11, 70.0\n"
                           "4, 11, 11, 70.0\n*END STEP\n";
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  for (Label n = 1; n <= 4; ++n) EXPECT_NEAR(NT(r, f, n), 70.0, 1e-9);
  for (Label e = 1; e <= 3; ++e)
    EXPECT_NEAR(block(r, f, e, ElemVar::S).values[0], -kE * kAlpha * 50.0, 1e-8);
  // The compressed truss pushes on its supports; the support at x = L pushes back with
  // RF1 = -E alpha dT A = -50.
  EXPECT_NEAR(RF(r, f, 4)[0], -kE * kAlpha * 50.0 * 0.5, 1e-8);
}

// Transient coupled step: a T3D2T rod (10 elements, L = 1, area 1) free to expand from x = 0,
// initially at 20, with its end x = 0 raised to 120 (DELTMX = 15). Each truss has the constant
// strain alpha (T_mean - 20) of its mean temperature (no axial force), so the tip moves by
// alpha sum_e L_e ((T_a + T_b)/2 - 20), computed here from the printed temperatures; the heat
// balance closes as in pure heat transfer.
TEST(ThermalVerification, CoupledTransientRodExpandsWithItsTemperature) {
  const std::string deck = line_mesh(10, 1.0, "T3D2T") +
                           "*SOLID SECTION, ELSET=BAR, MATERIAL=M\n1.0\n"
                           "*MATERIAL, NAME=M\n*ELASTIC\n2.0e5, 0.3\n*EXPANSION\n1.0e-5\n"
                           "*CONDUCTIVITY\n1.0\n*DENSITY\n1.0\n*SPECIFIC HEAT\n1.0\n"
                           "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 20.0\n"
                           "*STEP, INC=200\n*COUPLED TEMPERATURE-DISPLACEMENT, DELTMX=15.0\n"
                           "0.001, 0.05\n"
                           "*BOUNDARY\n1, 1, 1\nNALL, 2, 3\n1, 11, 11, 120.0\n*END STEP\n";
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  double tip = 0.0;
  for (int e = 1; e <= 10; ++e)
    tip += 1.0e-5 * 0.1 * (0.5 * (NT(r, f, e) + NT(r, f, e + 1)) - 20.0);
  EXPECT_GT(tip, 0.0);
  EXPECT_NEAR(U(r, f, 11)[0], tip, 1e-12 + 1e-9 * tip);
  for (Label e = 1; e <= 10; ++e) EXPECT_NEAR(block(r, f, e, ElemVar::S).values[0], 0.0, 1e-6);
  EXPECT_GT(NT(r, f, 2), 20.0);
  const StepChecks& c = r.steps[0].checks;
  EXPECT_GT(c.stored_heat, 0.0);
  EXPECT_LE(c.heat_balance_error, 1e-9 * c.heat_scale);
  EXPECT_GT(r.steps[0].increments, 3);
}

/// Radial mesh of `type` (CAX4T or CPE4T) on a <= r <= b, 0 <= z <= 0.1 with n elements. Planar
/// models use the same strip as a slab.
std::string radial_strip(int n, double a, double b, const std::string& type) {
  std::string s = "*NODE, NSET=NALL\n";
  for (int i = 0; i <= n; ++i) {
    const double x = a + (b - a) * i / n;
    s += fmt::format("{}, {:.17g}, 0\n{}, {:.17g}, 0.1\n", 2 * i + 1, x, 2 * i + 2, x);
  }
  s += fmt::format("*ELEMENT, TYPE={}, ELSET=STRIP\n", type);
  for (int i = 0; i < n; ++i)
    s += fmt::format("{}, {}, {}, {}, {}\n", i + 1, 2 * i + 1, 2 * i + 3, 2 * i + 4, 2 * i + 2);
  s += fmt::format("*NSET, NSET=INNER\n1, 2\n*NSET, NSET=OUTER\n{}, {}\n", 2 * n + 1, 2 * n + 2);
  s += "*NSET, NSET=BOTTOM, GENERATE\n" + fmt::format("1, {}, 2\n", 2 * n + 1);
  return s;
}

/// Largest nodal error of steady radial conduction in a thick cylinder (CAX4T), a = 1, b = 2,
/// T(a) = 100, T(b) = 0: T(r) = 100 (1 - ln(r/a) / ln(b/a)).
double cylinder_error(int n, double* heat = nullptr) {
  std::string deck = radial_strip(n, 1.0, 2.0, "CAX4T") +
                     "*SOLID SECTION, ELSET=STRIP, MATERIAL=M\n" + coupled_material() +
                     "*STEP\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n"
                     "*BOUNDARY\nBOTTOM, 2, 2\nINNER, 11, 11, 100.0\nOUTER, 11, 11, 0.0\n"
                     "*END STEP\n";
  const JobResult r = run_deck(deck, false, fmt::format("cyl_{}", n));
  EXPECT_EQ(r.exit_code, 0) << r.error;
  if (r.exit_code != 0) return 1e9;
  const Frame& f = last_frame(r);
  double err = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double x = 1.0 + static_cast<double>(i) / n;
    const double exact = 100.0 * (1.0 - std::log(x) / std::log(2.0));
    err = std::max(
        {err, std::abs(NT(r, f, 2 * i + 1) - exact), std::abs(NT(r, f, 2 * i + 2) - exact)});
  }
  if (heat) *heat = RFL(r, f, 1) + RFL(r, f, 2);
  return err;
}

// Radial conduction is not reproduced exactly by linear elements; the error falls as h^2 (ratio 4
// per halving; at least 3 is required; 0.0019 -> 0.00048 degrees observed) and the heat entering
// at the inner face approaches Q = 2 pi k H dT / ln(b/a) = 2 pi 50 0.1 100 / ln 2 (relative error
// of O(h^2) ~ 1e-4 on the 40-element strip, 3e-5 observed; 1e-3 required).
TEST(ThermalVerification, CoupledAxisymmetricRadialConduction) {
  double heat = 0.0;
  const double e20 = cylinder_error(20);
  const double e40 = cylinder_error(40, &heat);
  EXPECT_LT(e40, e20 / 3.0) << e20 << " -> " << e40;
  EXPECT_LT(e40, 0.05);
  const double Q = 2.0 * std::numbers::pi * 50.0 * 0.1 * 100.0 / std::log(2.0);
  EXPECT_NEAR(heat, Q, 1e-3 * Q);
}

// CPE4T slab 1 <= x <= 2 (thickness 1 in z by default): linear conduction between T = 100 and a
// film h = 25 to T_sink = 0 on the right edge: resistances L/k + 1/h = 0.02 + 0.04, so
// q = 100 / 0.06 per area, T(x) = 100 - q (x - 1) / k, nodally exact; the plane-strain slab is
// free to expand in x (U1 fixed on the left edge only, U2 on the bottom).
TEST(ThermalVerification, CoupledPlaneStrainSlabWithFilm) {
  std::string deck = radial_strip(5, 1.0, 2.0, "CPE4T") +
                     "*SOLID SECTION, ELSET=STRIP, MATERIAL=M\n" + coupled_material() +
                     "*STEP\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n"
                     "*BOUNDARY\nINNER, 1, 1\nBOTTOM, 2, 2\nINNER, 11, 11, 100.0\n"
                     "*FILM\n5, F2, 0.0, 25.0\n*END STEP\n";
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  const double q = 100.0 / 0.06;
  for (int i = 0; i <= 5; ++i) EXPECT_NEAR(NT(r, f, 2 * i + 1), 100.0 - q * (i / 5.0) / 50.0, 1e-9);
  // Heat entering over the left edge of height 0.1 and unit thickness: q * 0.1.
  EXPECT_NEAR(RFL(r, f, 1) + RFL(r, f, 2), q * 0.1, 1e-9);
}

// ---------------------------------------------------------------------------------- errors

TEST(ThermalVerification, StressElementInHeatTransferStepIsAnInputError) {
  const std::string deck = brick_bar(1, 1.0, "C3D8") +
                           "*SOLID SECTION, ELSET=BAR, MATERIAL=M\n"
                           "*MATERIAL, NAME=M\n*ELASTIC\n1.0, 0.3\n"
                           "*STEP\n*HEAT TRANSFER, STEADY STATE\n*END STEP\n";
  const JobResult r = run_deck(deck);
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("cannot be used in a *HEAT TRANSFER step"), std::string::npos) << r.error;
}

// A steady model with a flux but no temperature anywhere held has no solution: the run stops with
// the no-convergence status and a sentence about the temperature, not about rigid-body motion.
TEST(ThermalVerification, FloatingSteadyTemperatureIsExplained) {
  const std::string deck = line_mesh(2, 1.0, "DC1D2") +
                           "*SOLID SECTION, ELSET=BAR, MATERIAL=M\n"
                           "*MATERIAL, NAME=M\n*CONDUCTIVITY\n1.0\n"
                           "*STEP\n*HEAT TRANSFER, STEADY STATE\n*CFLUX\n3, 11, 2.0\n*END STEP\n";
  const JobResult r = run_deck(deck);
  EXPECT_EQ(r.exit_code, kExitNoConvergence);
  EXPECT_NE(r.error.find("nothing fixes the temperature level"), std::string::npos) << r.error;
}

TEST(ThermalVerification, HeatElementInStaticStepIsAnInputError) {
  const std::string deck = line_mesh(1, 1.0, "DC1D2") + "*SOLID SECTION, ELSET=BAR, MATERIAL=M\n"
                                                        "*MATERIAL, NAME=M\n*CONDUCTIVITY\n1.0\n"
                                                        "*STEP\n*STATIC\n*END STEP\n";
  const JobResult r = run_deck(deck);
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("cannot be used in a *STATIC step"), std::string::npos) << r.error;
}

} // namespace
} // namespace gapfem::test
