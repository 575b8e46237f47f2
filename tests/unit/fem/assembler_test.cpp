// The assembler on models small enough to assemble by hand (issue 44, item 8): two trusses and a
// GAPUNI, whose internal forces, tangent, constraint rows, loads and diagonal are derived in the
// comments from the element formulas (linear truss: N = EA/L n.(u_b - u_a), r_a = -N n, r_b = N n,
// K_e = EA/L [n n^T, -n n^T; -n n^T, n n^T]; GAPUNI: overclosure g = -(d + n.(u_b - u_a)), force
// lambda dg/du with dg/du_a = n, dg/du_b = -n), and a long chain assembled with 1 and 2 threads.
#include "fem/assembler.hpp"
#include "io/inp/reader.hpp"
#include "linalg/csr_matrix.hpp"
#include "model/model.hpp"
#include "unit/dense_inserter.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <string>
#include <vector>

namespace gapfem {
namespace {

using test::DenseInserter;

// Truss 1 from node 1 (0,0,0) to node 2 (3,4,0): L = 5, n1 = (0.6, 0.8, 0), EA/L = 200 x 0.5 / 5
// = 20. Truss 2 from node 2 to node 3 (5,4,0): L = 2, n2 = (1,0,0), EA/L = 200 x 0.5 / 2 = 50.
// GAPUNI from node 3 to node 4 (6,4,0): clearance 0.1 along n = (1,0,0), hard contact.
// Density 2: a gravity g = 10 weighs rho A g = 10 per length.
std::string two_truss_gap_deck(const std::string& behavior = "") {
  return "*NODE\n1, 0., 0., 0.\n2, 3., 4., 0.\n3, 5., 4., 0.\n4, 6., 4., 0.\n"
         "*ELEMENT, TYPE=T3D2, ELSET=T\n1, 1, 2\n2, 2, 3\n"
         "*SOLID SECTION, ELSET=T, MATERIAL=M\n0.5\n"
         "*MATERIAL, NAME=M\n*ELASTIC\n200., 0.3\n*DENSITY\n2.\n"
         "*ELEMENT, TYPE=GAPUNI, ELSET=G\n3, 3, 4\n*GAP, ELSET=G\n0.1, 1., 0., 0., 1.\n" +
         behavior;
}

/// The model, its discretization (node 4 prescribed, nodes 1-3 free: equations 0-8 in slot
/// order) and the trial displacements of the hand computation.
struct TwoTrussGap {
  std::shared_ptr<const Model> model;
  Discretization disc;
  std::vector<double> u;
  StepContext ctx;

  explicit TwoTrussGap(const std::string& behavior = "", const KernelOptions& options = {})
      : model(std::make_shared<const Model>(
            read_deck_string(two_truss_gap_deck(behavior), "assembler.inp"))),
        disc(*model, options) {
    const DofMap& d = disc.dofs();
    std::vector<std::uint8_t> prescribed(static_cast<std::size_t>(d.n_slots()), 0);
    for (DofType t : {DofType::U1, DofType::U2, DofType::U3})
      if (const LocalIndex s = slot(3, t); s >= 0) prescribed[s] = 1;
    disc.set_equations(EquationMap::build(prescribed));
    u.assign(static_cast<std::size_t>(d.n_slots()), 0.0);
    // u(1) = (0.01, -0.02, 0.03), u(2) = (0.04, 0.05, -0.01), u(3) = (0.2, 0.07, 0.02), u(4) = 0
    const double values[3][3] = {{0.01, -0.02, 0.03}, {0.04, 0.05, -0.01}, {0.2, 0.07, 0.02}};
    for (NodeId n = 0; n < 3; ++n)
      for (int i = 0; i < 3; ++i) u[slot(n, static_cast<DofType>(i))] = values[n][i];
    ctx.space = model->space;
    ctx.model_size = model->model_size();
    ctx.dt = 1.0;
  }
  LocalIndex slot(NodeId n, DofType t) const { return disc.dofs().slot(n, t); }
  /// Equation of (node, direction 0-2): nodes 0-2 are free, 3 DOFs each, in slot order.
  static LocalIndex eq(NodeId n, int i) { return 3 * n + i; }
  FieldView fields() const {
    FieldView f;
    f.u = u;
    f.u_start = u;
    return f;
  }
  std::size_t n_slots() const { return u.size(); }
  ElementBlock& gap_block() {
    for (auto& b : disc.blocks())
      if (b.type == ElementType::GAPUNI) return b;
    throw std::runtime_error("no gap block");
  }
};

// Truss 1: delta = n1.(u2 - u1) = 0.6 x 0.03 + 0.8 x 0.07 = 0.074, N1 = 20 x 0.074 = 1.48:
//   r(1) = -N1 n1 = (-0.888, -1.184, 0), r(2) = (0.888, 1.184, 0).
// Truss 2: delta = u3x - u2x = 0.16, N2 = 50 x 0.16 = 8: r(2) += (-8, 0, 0), r(3) = (8, 0, 0).
// Gap: h = 0.1 + (u4x - u3x) = -0.1, overclosed by g = 0.1: it closes (committed open) with its
// trial multiplier 0, so it adds no force; its row is dg/du = +1 on u3x (u4x is prescribed).
const double kForce[4][3] = {
    {-0.888, -1.184, 0.0}, {0.888 - 8.0, 1.184, 0.0}, {8.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};

/// The tangent over equations 0-8 (nodes 1-3): truss 1's 20 n1 n1^T = [7.2 9.6; 9.6 12.8] in the
/// x-y block of nodes 1 and 2 (minus off the diagonal blocks), truss 2's 50 on x of nodes 2 and 3;
/// the hard gap adds nothing to K (its force is the multiplier's).
std::vector<double> hand_tangent() {
  std::vector<double> K(81, 0.0);
  auto add_truss = [&](int a, int b, const double kk[2][2]) {
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        K[(3 * a + i) * 9 + 3 * a + j] += kk[i][j];
        K[(3 * b + i) * 9 + 3 * b + j] += kk[i][j];
        K[(3 * a + i) * 9 + 3 * b + j] -= kk[i][j];
        K[(3 * b + i) * 9 + 3 * a + j] -= kk[i][j];
      }
  };
  const double k1[2][2] = {{7.2, 9.6}, {9.6, 12.8}};
  const double k2[2][2] = {{50.0, 0.0}, {0.0, 0.0}};
  add_truss(0, 1, k1);
  add_truss(1, 2, k2);
  return K;
}

TEST(AssemblerUnit, InternalForceAndTangentAreTheHandScatteredElementSums) {
  TwoTrussGap m;
  ASSERT_EQ(m.n_slots(), 12u);
  DenseInserter K(9);
  ConstraintBlock C;
  std::vector<double> f(m.n_slots(), 99.0); // overwritten
  ASSERT_EQ(m.disc.blocks().size(), 2u);
  Assembler assembler(m.disc);
  const AssemblyResult res = assembler.assemble(m.fields(), m.ctx, f, &K, &C);
  for (NodeId n = 0; n < 4; ++n)
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(f[m.slot(n, static_cast<DofType>(i))], kForce[n][i], 1e-12)
          << "node " << n + 1 << " direction " << i + 1;
  const std::vector<double> expected = hand_tangent();
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j)
      EXPECT_NEAR(K.at(i, j), expected[i * 9 + j], 1e-12) << "K(" << i << ", " << j << ")";
  // the gap closed in this evaluation: one status change, one row
  EXPECT_EQ(res.status_changes, 1);
  ASSERT_EQ(res.changed.size(), 1u);
  EXPECT_EQ(m.model->element_label(res.changed[0]).str(), "3");
  // its row: g = 0.1, coefficient +1 on u3x (node 3 = equation 6), u4x prescribed (dropped); its
  // multiplier is the gap's normal one, the first of all (the block's offset 0, slot 0)
  ASSERT_EQ(C.n_rows(), 1);
  EXPECT_EQ(C.row_ptr, (std::vector<LocalIndex>{0, 1}));
  EXPECT_EQ(C.col, (std::vector<LocalIndex>{TwoTrussGap::eq(2, 0)}));
  EXPECT_EQ(C.val, (std::vector<double>{1.0}));
  EXPECT_NEAR(C.g[0], 0.1, 1e-15);
  EXPECT_EQ(C.compliance[0], 0.0);
  EXPECT_EQ(C.multiplier[0], 0);
  EXPECT_FALSE(C.has_columns());
}

// A gap closed at the increment start with multiplier 7 stays closed (g > 0, lambda > 0) and
// pushes its nodes apart: r(3) += 7 dg/du3 = (7, 0, 0), r(4) += 7 dg/du4 = (-7, 0, 0).
TEST(AssemblerUnit, ClosedGapAddsItsMultiplierForce) {
  TwoTrussGap m;
  ElementBlock& gap = m.gap_block();
  gap.state_committed[0] = static_cast<double>(ContactStatus::Closed); // GapStateLayout::status
  gap.mult_committed[0] = 7.0;
  m.disc.reset_trial();
  Assembler assembler(m.disc);
  DenseInserter K(9);
  ConstraintBlock C;
  std::vector<double> f(m.n_slots(), 0.0);
  const AssemblyResult res = assembler.assemble(m.fields(), m.ctx, f, &K, &C);
  EXPECT_EQ(res.status_changes, 0);
  EXPECT_NEAR(f[m.slot(2, DofType::U1)], 8.0 + 7.0, 1e-12);
  EXPECT_NEAR(f[m.slot(3, DofType::U1)], -7.0, 1e-12);
  EXPECT_NEAR(f[m.slot(1, DofType::U1)], kForce[1][0], 1e-12);
  ASSERT_EQ(C.n_rows(), 1);
  EXPECT_EQ(C.val, (std::vector<double>{1.0}));
  EXPECT_NEAR(C.g[0], 0.1, 1e-15);
  // the tangent is the trusses' alone still
  const std::vector<double> expected = hand_tangent();
  for (std::size_t k = 0; k < expected.size(); ++k) EXPECT_NEAR(K.A[k], expected[k], 1e-12) << k;
}

// Without a matrix (the residual-only passes) the forces, rows and trial history are those of the
// full assembly, bit for bit.
TEST(AssemblerUnit, ResidualOnlyGivesTheSameForcesAndRows) {
  TwoTrussGap m;
  Assembler assembler(m.disc);
  DenseInserter K(9);
  ConstraintBlock C1, C2;
  std::vector<double> f1(m.n_slots(), 0.0), f2(m.n_slots(), 0.0);
  assembler.assemble(m.fields(), m.ctx, f1, &K, &C1);
  const std::vector<double> trial1 = m.gap_block().state_trial;
  m.disc.reset_trial();
  const std::vector<double> K_before = K.A;
  const AssemblyResult res = assembler.assemble(m.fields(), m.ctx, f2, nullptr, &C2);
  EXPECT_EQ(f1, f2);
  EXPECT_EQ(m.gap_block().state_trial, trial1);
  EXPECT_EQ(res.status_changes, 1);
  EXPECT_EQ(C1.col, C2.col);
  EXPECT_EQ(C1.val, C2.val);
  EXPECT_EQ(C1.g, C2.g);
  EXPECT_EQ(C1.multiplier, C2.multiplier);
  EXPECT_EQ(K.A, K_before);
  // one element's residual, alone, is its share of f: truss 2 gives (-8, 0, 0, 8, 0, 0)
  std::vector<double> r;
  std::vector<LocalIndex> slots;
  m.disc.reset_trial();
  assembler.element_residual(m.model->mesh.find_element(2), m.fields(), m.ctx, r, slots);
  ASSERT_EQ(r.size(), 6u);
  EXPECT_EQ(slots, (std::vector<LocalIndex>{m.slot(1, DofType::U1), m.slot(1, DofType::U2),
                                            m.slot(1, DofType::U3), m.slot(2, DofType::U1),
                                            m.slot(2, DofType::U2), m.slot(2, DofType::U3)}));
  const double r2[6] = {-8.0, 0.0, 0.0, 8.0, 0.0, 0.0};
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(r[k], r2[k], 1e-12) << k;
}

// Gravity g = 10 along -z on both trusses: rho A g = 2 x 0.5 x 10 = 10 per length, half of q L
// to each node: truss 1 (L = 5) 25 per node, truss 2 (L = 2) 10 per node. So f_ext(z) gains
// node 1 -25, node 2 -35, node 3 -10; a dead load has no tangent, K stays as it was.
TEST(AssemblerUnit, DistributedLoadsAddTheirEquivalentNodalForces) {
  TwoTrussGap m;
  Assembler assembler(m.disc);
  std::vector<DistributedLoad> loads(2);
  for (int e = 0; e < 2; ++e) {
    loads[e].elem = m.model->mesh.find_element(e + 1);
    loads[e].kind = DistLoadKind::Gravity;
    loads[e].magnitude = 10.0;
    loads[e].direction = {0.0, 0.0, -1.0};
  }
  const std::vector<ActiveLoad> active{{&loads[0], 10.0, 0.0}, {&loads[1], 10.0, 0.0}};
  std::vector<double> f_ext(m.n_slots(), 1.0); // added to
  DenseInserter K(9);
  std::fill(K.A.begin(), K.A.end(), 3.0);
  assembler.assemble_loads(active, m.fields(), m.ctx, f_ext, &K);
  const double z[4] = {-25.0, -35.0, -10.0, 0.0};
  for (NodeId n = 0; n < 4; ++n) {
    EXPECT_EQ(f_ext[m.slot(n, DofType::U1)], 1.0);
    EXPECT_EQ(f_ext[m.slot(n, DofType::U2)], 1.0);
    EXPECT_NEAR(f_ext[m.slot(n, DofType::U3)], 1.0 + z[n], 1e-12) << "node " << n + 1;
  }
  for (double k : K.A) EXPECT_EQ(k, 3.0);
}

// The diagonal |K_ii| per slot: trusses node 1 (7.2, 12.8, 0), node 2 (7.2 + 50, 12.8, 0), node 3
// (50, 0, 0); a hard gap adds nothing; a linear pressure law of slope 1000 (area 1) carried in the
// tangent (penalty_rows off) adds k dg dg^T: 1000 on u3x and on u4x, unless gaps are skipped.
TEST(AssemblerUnit, DiagonalStiffnessWithAndWithoutGaps) {
  const double trusses[4][3] = {{7.2, 12.8, 0.0}, {57.2, 12.8, 0.0}, {50.0, 0.0, 0.0}, {0, 0, 0}};
  auto expect_diag = [&](const TwoTrussGap& m, const std::vector<double>& d, double gap) {
    ASSERT_EQ(d.size(), m.n_slots());
    for (NodeId n = 0; n < 4; ++n)
      for (int i = 0; i < 3; ++i) {
        const double g = (i == 0 && n >= 2) ? gap : 0.0;
        EXPECT_NEAR(d[m.slot(n, static_cast<DofType>(i))], trusses[n][i] + g, 1e-12)
            << "node " << n + 1 << " direction " << i + 1;
      }
  };
  TwoTrussGap hard;
  Assembler a_hard(hard.disc);
  expect_diag(hard, a_hard.diagonal_stiffness(hard.fields(), hard.ctx, false), 0.0);
  expect_diag(hard, a_hard.diagonal_stiffness(hard.fields(), hard.ctx, true), 0.0);
  // the evaluation leaves no trial history behind (the gap would have closed)
  EXPECT_EQ(hard.gap_block().state_trial, hard.gap_block().state_committed);
  // nor a changed trial multiplier: a negative one (a gap pulled open in the iteration) that the
  // kernel would project to 0 is the same after the estimate
  std::fill(hard.gap_block().mult_trial.begin(), hard.gap_block().mult_trial.end(), -3.0);
  a_hard.diagonal_stiffness(hard.fields(), hard.ctx, false);
  for (double l : hard.gap_block().mult_trial) EXPECT_EQ(l, -3.0);

  TwoTrussGap soft("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1000.\n",
                   KernelOptions{.penalty_rows = false, .friction_rows = true});
  Assembler a_soft(soft.disc);
  expect_diag(soft, a_soft.diagonal_stiffness(soft.fields(), soft.ctx, false), 1000.0);
  expect_diag(soft, a_soft.diagonal_stiffness(soft.fields(), soft.ctx, true), 0.0);
  // and in the assembled tangent: K(u3x, u3x) = 50 + 1000, the force F = 1000 x 0.1 = 100 pushes
  // node 3 back: f(u3x) = 8 + 100, f(u4x) = -100
  DenseInserter K(9);
  std::vector<double> f(soft.n_slots(), 0.0);
  a_soft.assemble(soft.fields(), soft.ctx, f, &K, nullptr);
  EXPECT_NEAR(K.at(TwoTrussGap::eq(2, 0), TwoTrussGap::eq(2, 0)), 1050.0, 1e-9);
  EXPECT_NEAR(f[soft.slot(2, DofType::U1)], 108.0, 1e-9);
  EXPECT_NEAR(f[soft.slot(3, DofType::U1)], -100.0, 1e-9);
}

// ------------------------------------------------------------------------------------ threads

/// A zig-zag chain of `n` trusses in space: one block large enough (>= 2000) to be split.
std::string chain_deck(int n) {
  std::string s = "*NODE\n";
  for (int i = 1; i <= n + 1; ++i)
    s += std::to_string(i) + ", " + std::to_string(i) + ", " + std::to_string((i % 2) * 0.5) +
         ", " + std::to_string((i % 3) * 0.3) + "\n";
  s += "*ELEMENT, TYPE=T3D2, ELSET=T\n";
  for (int i = 1; i <= n; ++i)
    s += std::to_string(i) + ", " + std::to_string(i) + ", " + std::to_string(i + 1) + "\n";
  return s + "*SOLID SECTION, ELSET=T, MATERIAL=M\n0.5\n*MATERIAL, NAME=M\n*ELASTIC\n200., 0.3\n";
}

// With 2 threads the block is cut in two chunks that write separate lanes and force arrays,
// merged in thread order; every node of a chain gets at most two element contributions, one from
// each side, in the same order either way, so 1 and 2 threads agree bit for bit (and two runs with
// 2 threads agree with each other).
TEST(AssemblerUnit, OneAndTwoThreadsAssembleTheSameBits) {
  const Model model = read_deck_string(chain_deck(2400), "chain.inp");
  Discretization disc(model);
  const auto n = static_cast<std::size_t>(disc.dofs().n_slots());
  ASSERT_EQ(disc.blocks().size(), 1u);
  ASSERT_GE(disc.blocks()[0].size(), 2000u);
  // node 1 held: the rest free
  std::vector<std::uint8_t> prescribed(n, 0);
  prescribed[0] = prescribed[1] = prescribed[2] = 1;
  const EquationMap eqmap = EquationMap::build(prescribed);
  disc.set_equations(eqmap);
  std::vector<std::span<const LocalIndex>> element_eqs;
  const ElementBlock& block = disc.blocks()[0];
  for (std::size_t i = 0; i < block.size(); ++i) element_eqs.push_back(block.element_eqs(i));
  const auto pattern = build_pattern(eqmap.n_eq(), element_eqs);
  std::vector<double> u(n);
  for (std::size_t k = 0; k < n; ++k) u[k] = 1e-3 * std::sin(0.7 * static_cast<double>(k));
  FieldView fields;
  fields.u = u;
  fields.u_start = u;
  StepContext ctx;
  ctx.nlgeom = true; // a geometric stiffness too: every entry of the node blocks is nonzero
  auto run = [&](int threads) {
    Assembler assembler(disc, threads);
    EXPECT_EQ(assembler.threads(), threads);
    CsrMatrix A(pattern);
    CsrInserter K(A);
    std::vector<double> f(n, 0.0);
    assembler.assemble(fields, ctx, f, &K, nullptr);
    return std::pair{std::vector<double>(A.values().begin(), A.values().end()), f};
  };
  const auto [A1, f1] = run(1);
  const auto [A2, f2] = run(2);
  const auto [A2b, f2b] = run(2);
  double largest = 0.0;
  for (double a : A1) largest = std::max(largest, std::abs(a));
  EXPECT_GT(largest, 0.0);
  EXPECT_EQ(A1, A2);
  EXPECT_EQ(f1, f2);
  EXPECT_EQ(A2, A2b);
  EXPECT_EQ(f2, f2b);
}

} // namespace
} // namespace gapfem
