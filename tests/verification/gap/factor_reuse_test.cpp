// Factor reuse (KktSolver: stale factor with exact low-rank contact-row corrections) changes the
// path of the Newton iterations, never the converged answer: a block of C3D8 on a GAPUNI
// foundation (bench/gen_block.py, NLGEOM, graded clearances) solved with reuse forced on every
// iteration and with reuse switched off gives the same closed set and the same ground reactions.
#include "test_util.hpp"

#include <cmath>
#include <cstdlib>
#include <gtest/gtest.h>

using namespace gapfem;
using namespace gapfem::test;

namespace {
JobResult run_block(FactorReuse reuse) {
  const auto deck = test_dir() / "reuse_block.inp";
  const std::string cmd = "python3 '" + std::string(GAPFEM_SOURCE_DIR) +
                          "/bench/gen_block.py' --nx 8 --nz 6 --dmax 2e-4 --pressure 10 -o '" +
                          deck.string() + "' 2>/dev/null";
  if (std::system(cmd.c_str()) != 0) throw std::runtime_error("deck generator failed: " + cmd);
  JobOptions o;
  o.deck = deck;
  o.write_files = false;
  o.quiet = true;
  o.factor_reuse = reuse;
  return run_job(o);
}
} // namespace

TEST(FactorReuse, StaleFactorGivesTheSameAnswerAsFullNewton) {
  if (std::getenv("GAPFEM_FACTOR_REUSE"))
    GTEST_SKIP() << "GAPFEM_FACTOR_REUSE overrides the modes this test compares";
  const JobResult full = run_block(FactorReuse::Never);
  const JobResult reuse = run_block(FactorReuse::Always);
  ASSERT_EQ(full.exit_code, 0) << full.error;
  ASSERT_EQ(reuse.exit_code, 0) << reuse.error;
  EXPECT_LT(reuse.run.stats.factorizations, full.run.stats.factorizations);
  const Frame& a = last_frame(full);
  const Frame& b = last_frame(reuse);
  int closed_a = 0, closed_b = 0, mismatched = 0;
  double max_rf = 0.0, max_diff = 0.0, max_u = 0.0, max_du = 0.0;
  const Mesh& mesh = full.model->mesh;
  for (ElemId e = 0; e < mesh.n_elements(); ++e) {
    const ElementResult* ea = a.element(e);
    const ElementResult* eb = b.element(e);
    if (!ea || !ea->data.gap) continue;
    ASSERT_TRUE(eb && eb->data.gap);
    const GapRecord& ga = *ea->data.gap;
    const GapRecord& gb = *eb->data.gap;
    const bool ca = ga.status != ContactStatus::Open, cb = gb.status != ContactStatus::Open;
    closed_a += ca;
    closed_b += cb;
    mismatched += ca != cb;
    max_rf = std::max(max_rf, std::abs(ga.normal_force));
    max_diff = std::max(max_diff, std::abs(ga.normal_force - gb.normal_force));
  }
  for (NodeId n = 0; n < mesh.n_nodes(); ++n) {
    const auto& ua = a.nodes.U.at(n);
    const auto& ub = b.nodes.U.at(n);
    for (int k = 0; k < 3; ++k) {
      max_u = std::max(max_u, std::abs(ua[k]));
      max_du = std::max(max_du, std::abs(ua[k] - ub[k]));
    }
  }
  EXPECT_GT(closed_a, 0);
  EXPECT_LT(closed_a, 81) << "the graded clearances must leave part of the foundation open";
  EXPECT_EQ(mismatched, 0);
  EXPECT_EQ(closed_a, closed_b);
  // both runs stop at the Abaqus residual tolerance (0.5% of the average force); measured
  // differences are far below it
  EXPECT_LE(max_diff, 1e-3 * max_rf);
  EXPECT_LE(max_du, 1e-3 * max_u);
}
