// The near null space handed to the AMG (`--solver iterative`): rigid-body modes over the free
// equations, and the nodal numbering that lets GAMG aggregate nodes (NearNullSpace::padded).
#include "fem/rigid_body_modes.hpp"
#include "parallel/kkt_layout.hpp"

#include <gtest/gtest.h>

using namespace gapfem;

namespace {

constexpr DofMask kTranslations =
    dof_bit(DofType::U1) | dof_bit(DofType::U2) | dof_bit(DofType::U3);

EquationMap equations(const DofMap& dofs, const std::vector<std::pair<NodeId, DofType>>& fixed) {
  std::vector<std::uint8_t> prescribed(static_cast<std::size_t>(dofs.n_slots()), 0);
  for (const auto& [n, d] : fixed) prescribed[dofs.slot(n, d)] = 1;
  return EquationMap::build(prescribed);
}

} // namespace

TEST(RigidBodyModes, TranslationsOnlyGiveNodalBlocksPaddedWherePrescribed) {
  // node 0 free, node 1 held in y, node 2 held entirely (no block), node 3 free
  const DofMap dofs(std::vector<DofMask>(4, kTranslations));
  const EquationMap eqs =
      equations(dofs, {{1, DofType::U2}, {2, DofType::U1}, {2, DofType::U2}, {2, DofType::U3}});
  const std::vector<Vec3> x{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const NearNullSpace modes = rigid_body_modes(dofs, eqs, x, false);
  ASSERT_EQ(eqs.n_eq(), 8);
  EXPECT_EQ(modes.count, 6);
  EXPECT_EQ(modes.block_size, 3);
  // node 0: 0 1 2; node 1: 3 (x), 5 (z); node 3 is the third block: 6 7 8
  EXPECT_EQ(modes.padded, (std::vector<LocalIndex>{0, 1, 2, 3, 5, 6, 7, 8}));
  // the rotation about z moves node 1 (x = 1) along y only: its x and z entries are 0
  const double* rz = modes.vectors.data() + 5 * 8;
  EXPECT_EQ(rz[3], 0.0);
  EXPECT_EQ(rz[4], 0.0);
  for (int e = 0; e < 3; ++e) EXPECT_EQ(rz[e], 0.0); // node 0 sits on the axis
  // the rotation about x moves node 3 (z = 1) along -y, the largest motion: -1 after scaling
  const double* rx = modes.vectors.data() + 3 * 8;
  // (node 3's equations are 5, 6, 7)
  EXPECT_EQ(rx[6], -1.0);
  EXPECT_EQ(rx[5], 0.0);
  EXPECT_EQ(rx[7], 0.0);
}

TEST(RigidBodyModes, RotationsOrTemperaturesKeepEquationsAsTheyAre) {
  std::vector<DofMask> masks(2, kTranslations);
  masks[1] |= dof_bit(DofType::UR1);
  const DofMap dofs(masks);
  const EquationMap eqs = equations(dofs, {});
  const std::vector<Vec3> x{{0, 0, 0}, {1, 0, 0}};
  const NearNullSpace modes = rigid_body_modes(dofs, eqs, x, false);
  EXPECT_EQ(modes.block_size, 1);
  EXPECT_TRUE(modes.padded.empty());
}

TEST(KktLayout, NodalBlocksAreNeverSplitBetweenRanks) {
  for (int ranks = 1; ranks <= 5; ++ranks) {
    const std::vector<int> start = KktLayout::split(3 * 7, ranks, 3);
    ASSERT_EQ(start.back(), 21);
    for (int p = 0; p <= ranks; ++p) EXPECT_EQ(start[p] % 3, 0) << ranks << " ranks";
    for (int p = 0; p < ranks; ++p) EXPECT_LE(start[p + 1] - start[p], 3 * (7 / ranks + 1));
  }
  EXPECT_EQ(KktLayout::split(10, 3), (std::vector<int>{0, 4, 7, 10}));
}
