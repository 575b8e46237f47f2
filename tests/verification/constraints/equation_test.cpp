// *EQUATION (issue 12): two blocks whose interface nodes are duplicated and joined by equations
// u(right) - u(left) = 0 give the answer of the merged (flat) mesh to 1e-10, for displacements
// (with a gap element closing, small and large displacements), temperatures (DOF 11, heat
// transfer) and a coupled temperature-displacement step; a linear model takes one Newton
// iteration and one factorisation over several increments; bad equations are input errors.
#include "verification/constraints/split_blocks.hpp"

#include <gtest/gtest.h>

using namespace gapfem;
using namespace gapfem::test;

namespace {

/// The equations joining the split interface: DOFs `dofs`, node sets L-IF and R-IF.
std::string interface_equations(std::initializer_list<int> dofs) {
  std::string d;
  for (int dof : dofs) d += fmt::format("2\nR-IF, {0}, 1., L-IF, {0}, -1.\n", dof);
  return "*EQUATION\n" + d;
}

std::string interface_sets(const SplitBlocks& g) {
  return "*NSET, NSET=L-IF\n" + g.plane(g.m) + "*NSET, NSET=R-IF\n" + g.plane(g.m, true);
}

/// Mechanical deck: the x = 0 face clamped, the far face pulled and sheared; a GAPUNI from one
/// far corner to a fixed node closes (clearance 0.002 against a deflection in -z).
std::string mechanical(const SplitBlocks& g, bool split, bool nlgeom) {
  std::string d = "*HEADING\nblocks\n" + g.mesh(split);
  const int tip = split ? g.split_label(g.nx, 0, 0) : g.label(g.nx, 0, 0);
  d += fmt::format("*NODE\n90000, {}, 0., -0.002\n", g.nx * g.size);
  d += fmt::format("*ELEMENT, TYPE=GAPUNI, ELSET=GAPS\n90001, {}, 90000\n", tip);
  d += "*GAP, ELSET=GAPS\n0.002, 0., 0., -1.\n";
  d += "*NSET, NSET=CLAMP\n" + g.plane(0) + "*NSET, NSET=FAR\n" + g.plane(g.nx, split);
  if (split) d += interface_sets(g) + interface_equations({1, 2, 3});
  d += "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*SOLID SECTION, ELSET=ALL, MATERIAL=M\n";
  d += fmt::format("*STEP{}\n*STATIC\n0.5, 1.\n*BOUNDARY\nCLAMP, 1, 3\n90000, 1, 3\n*CLOAD\n"
                   "FAR, 1, 2.\nFAR, 2, 0.5\nFAR, 3, -0.4\n*END STEP\n",
                   nlgeom ? ", NLGEOM" : "");
  return d;
}

} // namespace

TEST(Equation, JoinedBlocksGiveTheMergedMeshAnswer) {
  SplitBlocks g;
  g.nx = 4;
  g.ny = 2;
  g.nz = 1;
  g.m = 2;
  for (bool nlgeom : {false, true}) {
    const JobResult flat = run_deck_exact(mechanical(g, false, nlgeom), "flat");
    const JobResult split = run_deck_exact(mechanical(g, true, nlgeom), "split");
    ASSERT_EQ(flat.exit_code, 0) << flat.error;
    ASSERT_EQ(split.exit_code, 0) << split.error;
    EXPECT_EQ(split.model->constraints.size(), 3u * (g.ny + 1) * (g.nz + 1));
    expect_same_nodes(flat, split, g, 1e-10);
    const GapRecord& gf = gap(flat, last_frame(flat), 90001);
    const GapRecord& gs = gap(split, last_frame(split), 90001);
    EXPECT_NE(gf.status, ContactStatus::Open) << "the test needs the gap closed";
    EXPECT_NEAR(gs.normal_force, gf.normal_force, 1e-10 * std::abs(gf.normal_force));
  }
}

TEST(Equation, LinearModelTakesOneIterationAndOneFactorisation) {
  SplitBlocks g;
  std::string d = "*HEADING\nlinear\n" + g.mesh(true) + "*NSET, NSET=CLAMP\n" + g.plane(0) +
                  "*NSET, NSET=FAR\n" + g.plane(g.nx, true) + interface_sets(g) +
                  interface_equations({1, 2, 3}) +
                  "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*SOLID SECTION, ELSET=ALL, "
                  "MATERIAL=M\n*STEP\n*STATIC, DIRECT\n0.25, 1.\n*BOUNDARY\nCLAMP, 1, 3\n"
                  "*CLOAD\nFAR, 2, 0.5\n*END STEP\n";
  const JobResult r = run_deck(d);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  ASSERT_EQ(r.increments.size(), 4u);
  for (const IncrementInfo& inc : r.increments) EXPECT_EQ(inc.iterations, 1);
  EXPECT_EQ(r.run.stats.factorizations, 1) << "constant constraint rows keep the factor";
}

TEST(Equation, TemperatureDofJoinsHeatConduction) {
  SplitBlocks g;
  g.type = "DC3D8";
  auto deck = [&](bool split) {
    std::string d = "*HEADING\nheat\n" + g.mesh(split) + "*NSET, NSET=HOT\n" + g.plane(0) +
                    "*NSET, NSET=FAR\n" + g.plane(g.nx, split);
    if (split) d += interface_sets(g) + interface_equations({11});
    d += "*MATERIAL, NAME=M\n*CONDUCTIVITY\n4.\n*SOLID SECTION, ELSET=ALL, MATERIAL=M\n"
         "*STEP\n*HEAT TRANSFER, STEADY STATE\n*BOUNDARY\nHOT, 11, 11, 100.\n*CFLUX\n"
         "FAR, 11, -3.\n*END STEP\n";
    return d;
  };
  const JobResult flat = run_deck(deck(false), false, "flat");
  const JobResult split = run_deck(deck(true), false, "split");
  ASSERT_EQ(flat.exit_code, 0) << flat.error;
  ASSERT_EQ(split.exit_code, 0) << split.error;
  expect_same_nodes(flat, split, g, 1e-10);
  // closed form: 4 far nodes each take 3 out of a 1 x 1 bar of length 4 and k = 4:
  // T(L) = 100 - q L / k = 100 - 12 * 4 / 4
  EXPECT_NEAR(last_frame(split).nodes.NT[split.model->mesh.find_node(g.split_label(4, 0, 0))], 88.0,
              1e-9);
}

TEST(Equation, CoupledTemperatureDisplacementStep) {
  SplitBlocks g;
  g.type = "C3D8T";
  auto deck = [&](bool split) {
    std::string d = "*HEADING\ncoupled\n" + g.mesh(split) + "*NSET, NSET=CLAMP\n" + g.plane(0) +
                    "*NSET, NSET=FAR\n" + g.plane(g.nx, split);
    if (split) d += interface_sets(g) + interface_equations({1, 2, 3, 11});
    d += "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*EXPANSION\n1.E-4\n*CONDUCTIVITY\n4.\n"
         "*SOLID SECTION, ELSET=ALL, MATERIAL=M\n*INITIAL CONDITIONS, TYPE=TEMPERATURE\n"
         "NALL, 20.\n*STEP\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n*BOUNDARY\n"
         "CLAMP, 1, 3\nCLAMP, 11, 11, 120.\n*CFLUX\nFAR, 11, -2.\n*CLOAD\nFAR, 3, -0.1\n"
         "*END STEP\n";
    return d;
  };
  const JobResult flat = run_deck(deck(false), false, "flat");
  const JobResult split = run_deck(deck(true), false, "split");
  ASSERT_EQ(flat.exit_code, 0) << flat.error;
  ASSERT_EQ(split.exit_code, 0) << split.error;
  expect_same_nodes(flat, split, g, 1e-10);
}

TEST(Equation, BadEquationsAreInputErrors) {
  SplitBlocks g;
  const std::string head = "*HEADING\nbad\n" + g.mesh(true) + interface_sets(g) +
                           "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*SOLID SECTION, ELSET=ALL, "
                           "MATERIAL=M\n";
  auto error_of = [&](const std::string& model, const std::string& step = "") {
    const JobResult r = run_deck(head + model + "*STEP\n*STATIC\n" + step + "*END STEP\n");
    EXPECT_EQ(r.exit_code, kExitInputError) << model;
    return r.error;
  };
  auto has = [](const std::string& text, const std::string& what) {
    return text.find(what) != std::string::npos;
  };
  // the same dependent DOF in two equations: both lines of the dependent terms named
  std::string e = error_of("*EQUATION\n2\n10003, 1, 1., 3, 1, -1.\n2\n10003, 1, 1., 2, 1, -1.\n");
  EXPECT_TRUE(has(e, "job.inp:")) << e;
  EXPECT_TRUE(has(e, "node 10003")) << e;
  EXPECT_TRUE(has(e, "job.inp:45: *EQUATION: node 10003: DOF 1 is already the dependent DOF of "
                     "the constraint at "))
      << e;
  EXPECT_TRUE(has(e, "job.inp:43 (*EQUATION)")) << e;
  // a boundary condition on the dependent DOF
  e = error_of("*EQUATION\n2\n10003, 2, 1., 3, 2, -1.\n", "*BOUNDARY\n10003, 2, 2, 0.1\n");
  EXPECT_TRUE(has(e, "node 10003: DOF 2 has a boundary condition and is the dependent")) << e;
  EXPECT_TRUE(has(e, "job.inp:43 (*EQUATION)")) << e;
  // zero first coefficient, node set sizes, a DOF the node does not carry, a missing term
  EXPECT_TRUE(has(error_of("*EQUATION\n2\n10003, 1, 0., 3, 1, -1.\n"),
                  "the first term's coefficient must not be zero"));
  EXPECT_TRUE(has(error_of("*NSET, NSET=TWO\n1, 2\n*EQUATION\n2\nR-IF, 1, 1., TWO, 1, -1.\n"),
                  "must hold the same number of nodes"));
  EXPECT_TRUE(has(error_of("*EQUATION\n2\n10003, 4, 1., 3, 4, -1.\n"),
                  "no element at this node has DOF 4"));
  // a term on a line of its own is named by that line
  EXPECT_TRUE(has(error_of("*EQUATION\n2\n10003, 1, 1.\n3, 4, -1.\n"),
                  "job.inp:44: *EQUATION: node 3: no element at this node has DOF 4"));
  EXPECT_TRUE(has(error_of("*EQUATION\n3\n10003, 1, 1., 3, 1, -1.\n"),
                  "the equation has 3 terms but the data ends after 2"));
  EXPECT_TRUE(has(error_of("*EQUATION\n2\n10003, 1, 1., 10003, 1, -1.\n"), "appears twice"));
  EXPECT_TRUE(has(error_of("*EQUATION\n2\n10003, 1, 1., 77, 1, -1.\n"), "77"));
}

TEST(Equation, ConstraintRowsKeepTheFactorReusable) {
  // the gap closes in the course of the step; the equations' rows never change, so the joined
  // model factorises no more often than the merged one (factor reuse on every system)
  SplitBlocks g;
  g.ny = 2;
  long factorizations[2] = {0, 0};
  for (bool split : {false, true}) {
    JobOptions o;
    o.deck = write_deck(mechanical(g, split, false), split ? "split" : "flat");
    o.write_files = false;
    o.quiet = true;
    o.factor_reuse = FactorReuse::Always;
    const JobResult r = run_job(o);
    ASSERT_EQ(r.exit_code, 0) << r.error;
    factorizations[split] = r.run.stats.factorizations;
    EXPECT_LT(r.run.stats.factorizations, r.run.stats.iterations) << "reused at least once";
  }
  EXPECT_EQ(factorizations[1], factorizations[0]);
}
