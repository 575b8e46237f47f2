// The constraint set (issue 44, item 8): an *EQUATION row over the slots of a model's DOF map, its
// equations per step, a boundary condition on its dependent DOF (an input error: *EQUATION rows do
// not yield), its multiplier stored after the elements' with a trial and a committed copy, and
// what the assembler makes of it: the constraint force C^T lambda and a row after the elements'.
#include "common/error.hpp"
#include "fem/assembler.hpp"
#include "io/inp/reader.hpp"
#include "model/model.hpp"

#include <gtest/gtest.h>
#include <memory>
#include <string>
#include <vector>

namespace gapfem {
namespace {

// Two trusses 1-2, 2-3 (U1-U3 at nodes 1-3), a GAPUNI 3-4 (three multipliers: normal and two
// friction) and the equation u2(node 1) - 2 u2(node 3) = 0 (the first term is the dependent DOF).
std::string deck(const std::string& equation) {
  return "*NODE\n1, 0., 0., 0.\n2, 3., 4., 0.\n3, 5., 4., 0.\n4, 6., 4., 0.\n5, 9., 9., 9.\n"
         "*ELEMENT, TYPE=T3D2, ELSET=T\n1, 1, 2\n2, 2, 3\n"
         "*SOLID SECTION, ELSET=T, MATERIAL=M\n0.5\n"
         "*MATERIAL, NAME=M\n*ELASTIC\n200., 0.3\n"
         "*ELEMENT, TYPE=GAPUNI, ELSET=G\n3, 3, 4\n*GAP, ELSET=G\n0.1, 1., 0., 0., 1.\n" +
         equation;
}
const std::string kEquation = "*EQUATION\n2\n1, 2, 1., 3, 2, -2.\n";

struct Fixture {
  std::shared_ptr<const Model> model;
  Discretization disc;
  explicit Fixture(const std::string& equation = kEquation)
      : model(std::make_shared<const Model>(read_deck_string(deck(equation), "constraints.inp"))),
        disc(*model) {}
  LocalIndex slot(NodeId n, DofType t) const { return disc.dofs().slot(n, t); }
  /// The equation map with the listed (node, DOF) slots prescribed.
  EquationMap equations(const std::vector<std::pair<NodeId, DofType>>& held) const {
    std::vector<std::uint8_t> prescribed(static_cast<std::size_t>(disc.dofs().n_slots()), 0);
    for (const auto& [n, d] : held)
      if (const LocalIndex s = slot(n, d); s >= 0) prescribed[s] = 1;
    return EquationMap::build(prescribed);
  }
  static std::vector<std::pair<NodeId, DofType>> node4() {
    return {{3, DofType::U1}, {3, DofType::U2}, {3, DofType::U3}};
  }
};

TEST(ConstraintSetUnit, EquationRowIsOverTheSlotsOfItsTerms) {
  Fixture fx;
  const ConstraintSet& cs = fx.disc.constraints();
  ASSERT_EQ(cs.n_rows(), 1);
  EXPECT_EQ(cs.source(0), 0);
  // nodes 1-4 carry U1-U3 (slots 0-11 in node order), node 5 nothing
  EXPECT_EQ(fx.disc.dofs().n_slots(), 12);
  EXPECT_EQ(fx.slot(0, DofType::U2), 1);
  EXPECT_EQ(fx.slot(2, DofType::U2), 7);
  EXPECT_EQ(std::vector<LocalIndex>(cs.row_slots(0).begin(), cs.row_slots(0).end()),
            (std::vector<LocalIndex>{1, 7}));
  EXPECT_EQ(std::vector<double>(cs.row_coeffs(0).begin(), cs.row_coeffs(0).end()),
            (std::vector<double>{1.0, -2.0}));
  // before any step: no equations, not active
  EXPECT_FALSE(cs.active(0));
  EXPECT_EQ(cs.row_eqs(0)[0], -1);
}

TEST(ConstraintSetUnit, RowEquationsFollowTheStepNumbering) {
  Fixture fx;
  const ConstraintSet& cs = fx.disc.constraints();
  // node 4 held: equations 0-8 are the slots 0-8, so the row's are 1 and 7
  fx.disc.set_equations(fx.equations(Fixture::node4()));
  EXPECT_TRUE(cs.active(0));
  EXPECT_EQ(std::vector<LocalIndex>(cs.row_eqs(0).begin(), cs.row_eqs(0).end()),
            (std::vector<LocalIndex>{1, 7}));
  // node 1's U1 held as well: everything after slot 0 moves down by one; the independent term's
  // DOF u2(node 3) held: its equation is -1 and the row still applies
  auto held = Fixture::node4();
  held.emplace_back(0, DofType::U1);
  held.emplace_back(2, DofType::U2);
  fx.disc.set_equations(fx.equations(held));
  EXPECT_TRUE(cs.active(0));
  EXPECT_EQ(std::vector<LocalIndex>(cs.row_eqs(0).begin(), cs.row_eqs(0).end()),
            (std::vector<LocalIndex>{0, -1}));
}

// *EQUATION eliminates its first DOF and does not yield to boundary conditions
// (LinearConstraint::yields_to_bc false): a step holding u2(node 1) is an input error that names
// the DOF.
TEST(ConstraintSetUnit, BoundaryConditionOnTheDependentDofIsAnInputError) {
  Fixture fx;
  auto held = Fixture::node4();
  held.emplace_back(0, DofType::U2);
  try {
    fx.disc.set_equations(fx.equations(held));
    FAIL() << "a prescribed dependent DOF was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("DOF 2 is the constraint's dependent DOF"),
              std::string::npos)
        << e.what();
  }
}

/// The message of the InputError that building the fixture with `equation` throws ("" if none).
std::string input_error(const std::string& equation) {
  try {
    Fixture fx(equation);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ConstraintSetUnit, TermOnADofNoElementCarriesIsAnInputError) {
  // node 5 has no element: it carries no DOF
  EXPECT_NE(
      input_error("*EQUATION\n2\n1, 2, 1., 5, 2, -1.\n").find("no element at this node has DOF 2"),
      std::string::npos);
  // nor does a truss node carry rotations
  EXPECT_NE(
      input_error("*EQUATION\n2\n1, 4, 1., 2, 1, -1.\n").find("no element at this node has DOF 4"),
      std::string::npos);
}

// The multipliers: the gap's 3 first (block by block), then one per constraint row.
TEST(ConstraintSetUnit, MultipliersComeAfterTheElementsWithTrialAndCommittedCopies) {
  Fixture fx;
  Discretization& disc = fx.disc;
  disc.set_equations(fx.equations(Fixture::node4()));
  EXPECT_EQ(disc.constraint_multiplier_offset(), 3);
  EXPECT_EQ(disc.n_multipliers(), 4);
  ConstraintSet& cs = disc.constraints();
  ASSERT_EQ(cs.mult_trial.size(), 1u);
  EXPECT_EQ(&disc.multiplier_trial(3), &cs.mult_trial[0]);
  // multiplier 0 is the gap's normal multiplier
  ElementBlock* gap = nullptr;
  for (auto& b : disc.blocks())
    if (b.type == ElementType::GAPUNI) gap = &b;
  ASSERT_NE(gap, nullptr);
  EXPECT_EQ(&disc.multiplier_trial(0), &gap->mult_trial[0]);
  // a trial change is undone by a revert...
  disc.multiplier_trial(3) = 2.5;
  EXPECT_EQ(cs.mult_committed[0], 0.0);
  disc.reset_trial();
  EXPECT_EQ(cs.mult_trial[0], 0.0);
  // ... and kept by a commit, which a later revert returns to
  disc.multiplier_trial(3) = 2.5;
  disc.commit();
  EXPECT_EQ(cs.mult_committed[0], 2.5);
  disc.multiplier_trial(3) = -9.0;
  disc.reset_trial();
  EXPECT_EQ(cs.mult_trial[0], 2.5);
}

// With lambda = 2.5 and u2(node 1) = -0.02, u2(node 3) = 0.07, u3x = 0.2 (the gap overclosed by
// 0.1): the constraint force C^T lambda is +2.5 on u2(node 1) and -5 on u2(node 3); the rows are
// the gap's (multiplier 0) then the equation's, g = -0.02 - 2 x 0.07 = -0.16, multiplier 3 + 0.
TEST(ConstraintSetUnit, AssemblerAddsConstraintForcesAndRowsAfterTheElements) {
  Fixture fx;
  Discretization& disc = fx.disc;
  disc.set_equations(fx.equations(Fixture::node4()));
  disc.multiplier_trial(3) = 2.5;
  std::vector<double> u(12, 0.0);
  u[fx.slot(0, DofType::U2)] = -0.02;
  u[fx.slot(2, DofType::U2)] = 0.07;
  u[fx.slot(2, DofType::U1)] = 0.2;
  // the trusses' forces are the same in both assemblies below: the difference is C^T lambda
  FieldView fields;
  fields.u = u;
  fields.u_start = u;
  StepContext ctx;
  ctx.dt = 1.0;
  Assembler assembler(disc);
  ConstraintBlock C;
  std::vector<double> f(12, 0.0), f0(12, 0.0);
  assembler.assemble(fields, ctx, f, nullptr, &C);
  disc.reset_trial(); // the committed multiplier is 0: the same forces without the constraint's
  assembler.assemble(fields, ctx, f0, nullptr, nullptr);
  for (LocalIndex s = 0; s < 12; ++s) {
    const double extra = s == fx.slot(0, DofType::U2)   ? 2.5
                         : s == fx.slot(2, DofType::U2) ? -5.0
                                                        : 0.0;
    EXPECT_NEAR(f[s] - f0[s], extra, 1e-12) << "slot " << s;
  }
  ASSERT_EQ(C.n_rows(), 2);
  EXPECT_EQ(C.multiplier, (std::vector<std::int64_t>{0, 3}));
  EXPECT_EQ(C.row_ptr, (std::vector<LocalIndex>{0, 1, 3}));
  EXPECT_EQ(C.col, (std::vector<LocalIndex>{6, 1, 7}));
  EXPECT_EQ(C.val, (std::vector<double>{1.0, 1.0, -2.0}));
  EXPECT_NEAR(C.g[0], 0.1, 1e-15);
  EXPECT_NEAR(C.g[1], -0.16, 1e-15);
  EXPECT_EQ(C.compliance[1], 0.0);
}

} // namespace
} // namespace gapfem
