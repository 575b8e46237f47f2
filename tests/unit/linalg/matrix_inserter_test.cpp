// The MatSet-style inserter: lanes written in any order merge to the sum of what was added, in a
// fixed order (bitwise reproducible); idle lanes cost nothing; and the constrained-solver seam
// gives the KKT backend.
#include "fem/dof_map.hpp"
#include "linalg/constrained_solver.hpp"
#include "linalg/matrix_inserter.hpp"

#include <gtest/gtest.h>
#include <random>

using namespace gapfem;

namespace {

std::shared_ptr<SparsityPattern> random_pattern(int n, int elements, std::mt19937& rng,
                                                std::vector<std::vector<LocalIndex>>& elems) {
  std::uniform_int_distribution<int> node(0, n - 1);
  for (int e = 0; e < elements; ++e) {
    std::vector<LocalIndex> eq;
    for (int k = 0; k < 4; ++k) eq.push_back(node(rng));
    if (e % 5 == 0) eq[1] = -1; // a prescribed DOF is skipped
    elems.push_back(eq);
  }
  std::vector<std::span<const LocalIndex>> spans(elems.begin(), elems.end());
  return build_pattern(n, spans);
}

} // namespace

TEST(MatrixInserter, LanesMergeToTheSumOfTheBlocks) {
  std::mt19937 rng(7);
  std::vector<std::vector<LocalIndex>> elems;
  const auto pattern = random_pattern(40, 120, rng, elems);
  std::uniform_real_distribution<double> val(-1.0, 1.0);
  std::vector<std::vector<double>> blocks;
  for (std::size_t e = 0; e < elems.size(); ++e) {
    std::vector<double> b(16);
    for (double& v : b) v = val(rng);
    blocks.push_back(b);
  }
  // element e goes to lane e % lanes; a stale value in the target is cleared by set_zero
  auto assemble = [&](int lanes) {
    CsrMatrix A(pattern);
    A.values()[0] = 123.0;
    CsrInserter ins(A);
    ins.set_zero();
    ins.open(lanes);
    for (std::size_t e = 0; e < elems.size(); ++e)
      ins.add(static_cast<int>(e % static_cast<std::size_t>(lanes)), elems[e], elems[e], blocks[e]);
    ins.close();
    return A;
  };
  const CsrMatrix ref = assemble(1); // one lane, element order
  const CsrMatrix A = assemble(3), B = assemble(3);
  for (std::size_t k = 0; k < ref.values().size(); ++k) {
    EXPECT_NEAR(A.values()[k], ref.values()[k], 1e-13) << k;
    EXPECT_EQ(A.values()[k], B.values()[k]) << "the same lanes give bitwise the same matrix";
  }
}

TEST(MatrixInserter, ReopenedLanesStartFromZero) {
  std::mt19937 rng(3);
  std::vector<std::vector<LocalIndex>> elems;
  const auto pattern = random_pattern(10, 10, rng, elems);
  CsrMatrix A(pattern);
  CsrInserter ins(A);
  const std::vector<double> ones(16, 1.0);
  for (int round = 0; round < 3; ++round) {
    ins.set_zero();
    ins.open(2);
    ins.add(1, elems[0], elems[0], ones); // lane 1's private values must not accumulate
    ins.close();
  }
  CsrMatrix ref(pattern);
  ref.add_block(elems[0], elems[0], ones);
  for (std::size_t k = 0; k < ref.values().size(); ++k) EXPECT_EQ(A.values()[k], ref.values()[k]);
}

TEST(ConstrainedSolver, TheSerialBackendIsCholmod) {
  const auto s = make_constrained_solver("cholmod");
  EXPECT_EQ(s->name(), "cholmod");
}

TEST(EquationMap, ASerialRunOwnsEveryEquation) {
  const std::vector<std::uint8_t> prescribed{0, 1, 0, 0, 1};
  const EquationMap m = EquationMap::build(prescribed);
  ASSERT_EQ(m.n_eq(), 3);
  EXPECT_EQ(m.n_owned, 3);
  EXPECT_TRUE(m.ghost_global.empty());
  for (LocalIndex e = 0; e < m.n_eq(); ++e) {
    EXPECT_TRUE(m.owned(e));
    EXPECT_EQ(m.global(e), e);
  }
}
