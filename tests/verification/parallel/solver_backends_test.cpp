// The PETSc backends (`--solver mumps|iterative`, issue 17) against the CHOLMOD backend as the
// oracle: every deck must converge to the same answer, displacements, rotations, temperatures,
// reactions and gap forces to 1e-8 of their scales. CHOLMOD runs with a fresh factor in every
// Newton iteration (FactorReuse::Never), as the PETSc backends take exact Newton steps: the
// iterates then differ only by round-off (MUMPS) or by the Krylov tolerance 1e-10 (iterative).
// Randomised gap networks (exact and penalty contact, friction, GAPCYL/GAPSPHER under NLGEOM) with
// tight convergence controls, the examples, the structural verification decks, a body held only by
// closed gaps (K singular, the bordered system not) and a singular model, whose diagnosis must name
// the same nodes as with CHOLMOD.
#include "parallel/parallel.hpp"
#include "test_util.hpp"
#include "verification/gap/random/random_generators.hpp"
#include "verification/gap/same_answer.hpp"
#include "verification/parallel/slab_deck.hpp"

#include <filesystem>
#include <gtest/gtest.h>

using namespace gapfem;
using namespace gapfem::test;
using namespace gapfem::test::random_contact;

namespace {

#define REQUIRE_PETSC()                                                                            \
  if (!parallel::available())                                                                      \
  GTEST_SKIP() << "this build has no PETSc (petsc-dev): the mumps and iterative backends are "     \
                  "not tested"

JobResult run_file(const std::filesystem::path& deck, const std::string& backend) {
  JobOptions o;
  o.deck = deck;
  o.write_files = false;
  o.quiet = true;
  o.solver = backend;
  o.factor_reuse = backend == "cholmod" ? FactorReuse::Never : FactorReuse::Auto;
  return run_job(o);
}
JobResult run_text(const std::string& text, const std::string& backend) {
  return run_file(write_deck(text, std::string(backend)), backend);
}

/// The deck with each PETSc backend against CHOLMOD; returns how many iteration histories were
/// identical.
int compare_backends(const std::string& text, double tol, double k_max, const std::string& tag) {
  const JobResult oracle = run_text(text, "cholmod");
  int same = 0;
  for (const char* b : {"mumps", "iterative"})
    same += expect_same(oracle, run_text(text, b), tol, k_max, tag + " with " + std::string(b));
  return same;
}

double max_penalty(const ModelDef& m) {
  double k = 0.0;
  for (const GapDef& g : m.gaps) k = std::max(k, g.penalty);
  return k;
}
/// A T3D2 truss from node 1 to node 2 along x (x held at node 1), resting on `gaps` GAPUNI
/// (1: under node 1; 2: under both) of clearance d to ground nodes 11, 12 below; y is free, so K
/// alone is singular. `loads` are *CLOAD lines.
std::string truss_on_gaps(int gaps, double d, const std::string& loads) {
  std::string deck = "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n11, 0., -1., 0.\n";
  if (gaps == 2) deck += "12, 1., -1., 0.\n";
  deck += R"(*ELEMENT, TYPE=T3D2, ELSET=T
1, 1, 2
*MATERIAL, NAME=S
*ELASTIC
2.E5, 0.3
*SOLID SECTION, ELSET=T, MATERIAL=S
1.
*ELEMENT, TYPE=GAPUNI, ELSET=G
10, 1, 11
)";
  if (gaps == 2) deck += "11, 2, 12\n";
  deck += fmt::format("*GAP, ELSET=G\n{}, 0., -1., 0.\n*BOUNDARY\n11, 1, 3\n", d);
  if (gaps == 2) deck += "12, 1, 3\n";
  return deck + "1, 1, 1\n1, 3, 3\n2, 3, 3\n*STEP\n*STATIC\n*CLOAD\n" + loads + "*END STEP\n";
}

void tighten(ModelDef& m) {
  m.tight_controls = true;
  m.residual_tolerance = 1e-8;
}

} // namespace

TEST(SolverBackends, RandomExactAndPenaltyNetworks) {
  REQUIRE_PETSC();
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    ModelDef m = network_model(seed, seed % 3 == 0 ? NormalMethod::Penalty : NormalMethod::Direct);
    tighten(m);
    compare_backends(write_deck(m), 1e-8, max_penalty(m), m.tag);
  }
}

TEST(SolverBackends, RandomFrictionNetworksAndRadialUnits) {
  REQUIRE_PETSC();
  // Coulomb friction with the generator's own controls (tightened, some stick/slip histories do
  // not converge at all): the answers to 1e-6, what their residual tolerance determines
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const ModelDef m = friction_model(seed);
    compare_backends(write_deck(m), 1e-6, max_penalty(m), m.tag);
  }
  // GAPCYL/GAPSPHER under NLGEOM, without friction (with it the answer depends on the path): to
  // 1e-7, what the residual tolerance leaves the softest spring (PenaltyRows explains)
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    ModelDef m = radial_model(seed, false);
    tighten(m);
    compare_backends(write_deck(m), 1e-7, max_penalty(m), m.tag);
  }
}

TEST(SolverBackends, ExamplesAndStructuralDecks) {
  REQUIRE_PETSC();
  const std::filesystem::path src = GAPFEM_SOURCE_DIR;
  // the examples: beams on friction supports, an axisymmetric shrink fit, a fuel pin (thermal
  // gaps, GAPUNIT), a pipe elbow on GAPCYL guides; beams, shells and trusses under NLGEOM, a
  // thermal gradient, and the constraints of an Abaqus/CAE assembly
  const char* decks[] = {"examples/02_shrink_fit/shrink_fit.inp",
                         "examples/03_fuel_pin/fuel_pin.inp",
                         "examples/04_pipe_elbow/pipe_elbow.inp",
                         "tests/verification/structural/truss_nlgeom.inp",
                         "tests/verification/structural/beam_planar_load.inp",
                         "tests/verification/structural/shell_scordelis_lo.inp",
                         "tests/verification/structural/thermal_gradient.inp",
                         "tests/verification/assembly/cae_constraints.inp"};
  for (const char* deck : decks) {
    const JobResult oracle = run_file(src / deck, "cholmod");
    ASSERT_EQ(oracle.exit_code, 0) << deck << ": " << oracle.error;
    for (const char* b : {"mumps", "iterative"})
      expect_same(oracle, run_file(src / deck, b), 1e-8, 0.0,
                  std::string(deck) + " with " + std::string(b));
  }
  // friction on the supports: the stick/slip path is set by the Newton tolerance (5e-3 of the
  // flux), so the full-Newton paths are compared to 1e-5
  const JobResult oracle =
      run_file(src / "examples/01_pipe_on_supports/pipe_on_supports.inp", "cholmod");
  for (const char* b : {"mumps", "iterative"})
    expect_same(oracle, run_file(src / "examples/01_pipe_on_supports/pipe_on_supports.inp", b),
                1e-5, 0.0, "pipe on supports with " + std::string(b));
}

TEST(SolverBackends, ALinearProblemTakesOneIteration) {
  REQUIRE_PETSC();
  // a cantilever of C3D8 with an open gap: one Newton iteration, whichever backend
  std::string deck = "*NODE\n";
  for (int i = 0; i <= 10; ++i)
    for (int k = 0; k < 4; ++k)
      deck += fmt::format("{}, {}, {}, {}\n", 1 + i * 4 + k, 0.1 * i, 0.1 * (k % 2), 0.1 * (k / 2));
  deck += "99, 1.0, 0., -0.5\n*ELEMENT, TYPE=C3D8, ELSET=B\n";
  for (int i = 0; i < 10; ++i) {
    const int a = 1 + 4 * i, b = a + 4;
    deck += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", i + 1, a, b, b + 1, a + 1, a + 2,
                        b + 2, b + 3, a + 3);
  }
  deck += R"(*MATERIAL, NAME=S
*ELASTIC
2.E5, 0.3
*SOLID SECTION, ELSET=B, MATERIAL=S
*ELEMENT, TYPE=GAPUNI, ELSET=G
100, 41, 99
*GAP, ELSET=G
0.3, 0., 0., -1.
*BOUNDARY
1, 1, 3
2, 1, 3
3, 1, 3
4, 1, 3
99, 1, 3
*STEP
*STATIC
*CLOAD
41, 3, -1.
*END STEP
)";
  for (const char* b : {"mumps", "iterative"}) {
    const JobResult r = run_text(deck, b);
    ASSERT_EQ(r.exit_code, 0) << r.error;
    EXPECT_EQ(r.run.stats.iterations, 1) << b;
  }
}

TEST(SolverBackends, ABodyHeldOnlyByClosedGaps) {
  REQUIRE_PETSC();
  // a free truss pushed onto two closed gaps: K alone is singular, the bordered system is not
  // (MUMPS pivots across it; the iterative method's augmentation makes A definite)
  const std::string deck = truss_on_gaps(2, 0.0, "1, 2, -10.\n2, 2, -30.\n2, 1, 100.\n");
  compare_backends(deck, 1e-8, 0.0, "truss on two gaps");
  const JobResult r = run_text(deck, "iterative");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  EXPECT_NEAR(gap(r, last_frame(r), 11).normal_force, 30.0, 1e-8);
}

TEST(SolverBackends, ASlabOnGapsAggregatesNodes) {
  REQUIRE_PETSC();
  // 1,443 equations, all translations: the iterative backend numbers A by nodes (padding the
  // symmetry planes' prescribed DOFs) and every gap row fixes its equation (CG on K' alone)
  compare_backends(slab_on_gaps(12, 2), 1e-8, 0.0, "slab on gaps");
}

TEST(SolverBackends, ASingularModelIsDiagnosedAsWithCholmod) {
  REQUIRE_PETSC();
  // the same truss with one gap open: a rigid-body mode the diagnosis names by its nodes
  const std::string deck = truss_on_gaps(1, 0.1, "2, 2, -30.\n");
  const JobResult oracle = run_text(deck, "cholmod");
  ASSERT_NE(oracle.exit_code, 0);
  for (const char* b : {"mumps", "iterative"}) {
    const JobResult r = run_text(deck, b);
    EXPECT_EQ(r.exit_code, oracle.exit_code) << b << ": " << r.error;
    EXPECT_EQ(r.error, oracle.error) << b;
  }
}

TEST(SolverBackends, WhereTheKrylovMethodFailsTheStepIsFactorisedIfTheFactorFits) {
  REQUIRE_PETSC();
  // a beam rolled up into a circle by an end moment: GAMG is no preconditioner for the large
  // rotations of its NLGEOM tangent, the Krylov method fails, and MUMPS solves the rest of the
  // step: CHOLMOD's answer
  const std::filesystem::path deck =
      std::filesystem::path(GAPFEM_SOURCE_DIR) / "tests/verification/structural/beam_rollup_2d.inp";
  const JobResult oracle = run_file(deck, "cholmod");
  ASSERT_EQ(oracle.exit_code, 0) << oracle.error;
  // (its reactions are zero in theory, a pure end moment M = 628: they compare at the round-off
  // of the force scale M/L, through k_max = 1e3 per unit of displacement)
  expect_same(oracle, run_file(deck, "iterative"), 1e-8, 1e3, "beam roll-up");
  // ... unless that factor cannot fit: then the run stops with a sentence that says so
  ::setenv("GAPFEM_MEMORY_LIMIT", "1", 1);
  const JobResult r = run_file(deck, "iterative");
  ::unsetenv("GAPFEM_MEMORY_LIMIT");
  EXPECT_EQ(r.exit_code, kExitNoConvergence);
  EXPECT_NE(r.error.find("did not converge"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("would need about"), std::string::npos) << r.error;
}
