// The discretization (issue 44, item 8): the DOF map of a mixed model (a beam's six DOFs, a
// truss's three), the element blocks' gather lists, and the model-owned history of a gap block
// with its committed and trial copies: an evaluation writes the trial copy only, a revert
// (reset_trial) restores the committed one bit for bit, a commit copies trial to committed.
#include "fem/assembler.hpp"
#include "io/inp/reader.hpp"
#include "model/model.hpp"

#include <gtest/gtest.h>
#include <memory>
#include <string>
#include <vector>

namespace gapfem {
namespace {

const std::string kMaterial = "*MATERIAL, NAME=M\n*ELASTIC\n200., 0.3\n";

// A B31 beam 1-2 along x and a T3D2 truss 2-3 along y, node 4 on no element.
TEST(DiscretizationUnit, DofMapOfAMixedModelHasWhatTheElementsNeed) {
  const Model model = read_deck_string(
      "*NODE\n1, 0., 0., 0.\n2, 2., 0., 0.\n3, 2., 3., 0.\n4, 5., 5., 5.\n"
      "*ELEMENT, TYPE=B31, ELSET=B\n1, 1, 2\n"
      "*BEAM SECTION, ELSET=B, MATERIAL=M, SECTION=RECT\n0.2, 0.3\n0., 0., 1.\n"
      "*ELEMENT, TYPE=T3D2, ELSET=T\n2, 2, 3\n*SOLID SECTION, ELSET=T, MATERIAL=M\n0.5\n" +
          kMaterial,
      "mixed.inp");
  const Discretization disc(model);
  const DofMap& d = disc.dofs();
  // node 1: U1-U3, UR1-UR3 (slots 0-5); node 2 the same (6-11); node 3 U1-U3 (12-14); node 4 none
  ASSERT_EQ(d.n_slots(), 15);
  const DofType all[6] = {DofType::U1,  DofType::U2,  DofType::U3,
                          DofType::UR1, DofType::UR2, DofType::UR3};
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(d.slot(0, all[k]), k);
    EXPECT_EQ(d.slot(1, all[k]), 6 + k);
    EXPECT_EQ(d.slot(2, all[k]), k < 3 ? 12 + k : -1);
    EXPECT_EQ(d.slot(3, all[k]), -1);
    EXPECT_EQ(d.slot_node(6 + k), 1);
    EXPECT_EQ(d.slot_dof(6 + k), all[k]);
  }
  EXPECT_FALSE(d.has(2, DofType::UR1));
  EXPECT_FALSE(d.has(0, DofType::NT));
  EXPECT_EQ(d.mask(3), 0u);
  // the blocks' gather lists, in the kernels' node_dofs order
  ASSERT_EQ(disc.blocks().size(), 2u);
  const ElementBlock& beam = disc.blocks()[disc.locate(model.mesh.find_element(1)).first];
  const ElementBlock& truss = disc.blocks()[disc.locate(model.mesh.find_element(2)).first];
  EXPECT_EQ(beam.type, ElementType::B31);
  EXPECT_EQ(beam.n_dofs, 12);
  EXPECT_EQ(truss.n_dofs, 6);
  std::vector<LocalIndex> beam_slots(12);
  for (LocalIndex k = 0; k < 12; ++k) beam_slots[k] = k;
  EXPECT_EQ(std::vector<LocalIndex>(beam.element_slots(0).begin(), beam.element_slots(0).end()),
            beam_slots);
  EXPECT_EQ(std::vector<LocalIndex>(truss.element_slots(0).begin(), truss.element_slots(0).end()),
            (std::vector<LocalIndex>{6, 7, 8, 12, 13, 14}));
  EXPECT_EQ(disc.n_multipliers(), 0);
  EXPECT_FALSE(disc.has_gaps());
}

// Two trusses and a GAPUNI 3-4 of clearance 0.1 along x (as in assembler_test.cpp): u3x = 0.2
// overcloses it by 0.1, so an evaluation from the open committed state closes it.
struct GapModel {
  std::shared_ptr<const Model> model;
  Discretization disc;
  Assembler assembler;
  std::vector<double> u;
  StepContext ctx;
  GapModel()
      : model(std::make_shared<const Model>(read_deck_string(
            "*NODE\n1, 0., 0., 0.\n2, 3., 4., 0.\n3, 5., 4., 0.\n4, 6., 4., 0.\n"
            "*ELEMENT, TYPE=T3D2, ELSET=T\n1, 1, 2\n2, 2, 3\n"
            "*SOLID SECTION, ELSET=T, MATERIAL=M\n0.5\n" +
                kMaterial +
                "*ELEMENT, TYPE=GAPUNI, ELSET=G\n3, 3, 4\n*GAP, ELSET=G\n0.1, 1., 0., 0., 1.\n",
            "gap.inp"))),
        disc(*model), assembler(disc) {
    std::vector<std::uint8_t> prescribed(static_cast<std::size_t>(disc.dofs().n_slots()), 0);
    for (LocalIndex s = 9; s < 12; ++s) prescribed[s] = 1; // node 4
    disc.set_equations(EquationMap::build(prescribed));
    u.assign(prescribed.size(), 0.0);
    u[disc.dofs().slot(2, DofType::U1)] = 0.2;
    ctx.dt = 1.0;
  }
  ElementBlock& gap() { return disc.blocks()[disc.locate(model->mesh.find_element(3)).first]; }
  AssemblyResult evaluate() {
    FieldView f;
    f.u = u;
    f.u_start = u;
    std::vector<double> r(u.size(), 0.0);
    ConstraintBlock C;
    return assembler.assemble(f, ctx, r, nullptr, &C);
  }
};

constexpr int kStatus = 0; // GapStateLayout::status
const double kOpen = static_cast<double>(ContactStatus::Open);
const double kClosed = static_cast<double>(ContactStatus::Closed);

TEST(DiscretizationUnit, GapHistoryStartsInitializedAndCommitted) {
  GapModel m;
  ElementBlock& g = m.gap();
  ASSERT_EQ(g.size(), 1u);
  EXPECT_EQ(g.n_mult, 3);
  EXPECT_EQ(g.mult_offset, 0);
  ASSERT_EQ(g.state_committed.size(), static_cast<std::size_t>(g.n_state));
  // h = 0.1 > 0: open; the closure direction (history 1-3) is the given one
  EXPECT_EQ(g.state_committed[kStatus], kOpen);
  EXPECT_EQ(g.state_committed[1], 1.0);
  EXPECT_EQ(g.state_committed[2], 0.0);
  EXPECT_EQ(g.state_trial, g.state_committed);
  EXPECT_EQ(g.mult_trial, std::vector<double>(3, 0.0));
  EXPECT_EQ(g.mult_committed, g.mult_trial);
  EXPECT_TRUE(m.disc.has_gaps());
}

TEST(DiscretizationUnit, EvaluationWritesTrialAndRevertRestoresCommittedBitForBit) {
  GapModel m;
  ElementBlock& g = m.gap();
  const std::vector<double> state0 = g.state_committed, mult0 = g.mult_committed;
  EXPECT_EQ(m.evaluate().status_changes, 1);
  EXPECT_EQ(g.state_trial[kStatus], kClosed);
  EXPECT_EQ(g.state_committed, state0); // the committed copy is never written by an evaluation
  EXPECT_EQ(g.mult_committed, mult0);
  g.mult_trial[0] = 123.0; // as a Newton update would
  m.disc.reset_trial();
  EXPECT_EQ(g.state_trial, state0);
  EXPECT_EQ(g.mult_trial, mult0);
  // from the reverted state the same evaluation changes the status again
  EXPECT_EQ(m.evaluate().status_changes, 1);
}

TEST(DiscretizationUnit, CommitCopiesTrialToCommitted) {
  GapModel m;
  ElementBlock& g = m.gap();
  m.evaluate();
  g.mult_trial[0] = 4.0; // the contact force of the converged iteration
  m.disc.commit();
  EXPECT_EQ(g.state_committed, g.state_trial);
  EXPECT_EQ(g.mult_committed, g.mult_trial);
  EXPECT_EQ(g.state_committed[kStatus], kClosed);
  EXPECT_EQ(g.mult_committed[0], 4.0);
  const std::vector<double> state1 = g.state_committed, mult1 = g.mult_committed;
  // the next attempt starts closed with lambda 4; a tension (-1) opens the gap in trial only
  g.mult_trial[0] = -1.0;
  EXPECT_EQ(m.evaluate().status_changes, 1);
  EXPECT_EQ(g.state_trial[kStatus], kOpen);
  EXPECT_EQ(g.mult_trial[0], 0.0);
  EXPECT_EQ(g.state_committed, state1);
  // save_trial / restore_trial bring back exactly this trial state after a revert
  std::vector<double> saved;
  m.disc.save_trial(saved);
  const std::vector<double> open_state = g.state_trial, open_mult = g.mult_trial;
  m.disc.reset_trial();
  EXPECT_EQ(g.state_trial, state1);
  EXPECT_EQ(g.mult_trial, mult1);
  m.disc.restore_trial(saved);
  EXPECT_EQ(g.state_trial, open_state);
  EXPECT_EQ(g.mult_trial, open_mult);
}

} // namespace
} // namespace gapfem
