#pragma once
// A brick mesh of nx x ny x nz hexahedra (unit cells) written two ways: "flat" (one mesh) and
// "split" at i = m into a left and a right part whose interface nodes are duplicated (the right
// part's nodes are numbered 10000 + the flat label). The constraint tests join the two parts with
// *EQUATION, *MPC, *TIE … and compare every node with the flat mesh.
#include "test_util.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <functional>
#include <string>

namespace gapfem::test {

struct SplitBlocks {
  int nx = 4, ny = 1, nz = 1, m = 2;
  std::string type = "C3D8";
  double size = 1.0; ///< cell edge

  int label(int i, int j, int k) const { return 1 + i + (nx + 1) * (j + (ny + 1) * k); }
  static constexpr int kRight = 10000;

  /// *NODE and *ELEMENT (ELSET=ALL) blocks; split: duplicated interface nodes.
  std::string mesh(bool split) const {
    std::string d = "*NODE, NSET=NALL\n";
    for (int k = 0; k <= nz; ++k)
      for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
          const int l = label(i, j, k);
          if (!split || i <= m)
            d += fmt::format("{}, {}, {}, {}\n", l, i * size, j * size, k * size);
          if (split && i >= m)
            d += fmt::format("{}, {}, {}, {}\n", kRight + l, i * size, j * size, k * size);
        }
    d += fmt::format("*ELEMENT, TYPE={}, ELSET=ALL\n", type);
    int e = 1;
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
          const int off = split && i >= m ? kRight : 0;
          const int c[8] = {label(i, j, k),
                            label(i + 1, j, k),
                            label(i + 1, j + 1, k),
                            label(i, j + 1, k),
                            label(i, j, k + 1),
                            label(i + 1, j, k + 1),
                            label(i + 1, j + 1, k + 1),
                            label(i, j + 1, k + 1)};
          d += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", e++, off + c[0], off + c[1],
                           off + c[2], off + c[3], off + c[4], off + c[5], off + c[6], off + c[7]);
        }
    return d;
  }
  /// Labels of the nodes on the plane i = const (left copy, or right copy when `right`).
  std::string plane(int i, bool right = false) const {
    std::string d;
    int n = 0;
    for (int k = 0; k <= nz; ++k)
      for (int j = 0; j <= ny; ++j) {
        d += fmt::format("{}{}", n == 0 ? "" : (n % 8 == 0 ? ",\n" : ", "),
                         (right ? kRight : 0) + label(i, j, k));
        ++n;
      }
    return d + "\n";
  }
  /// Label of node (i, j, k) in the split mesh (the left copy on the interface).
  int split_label(int i, int j, int k) const { return (i > m ? kRight : 0) + label(i, j, k); }
};

/// Largest |a - b| over the flat labels, with `b_label` mapping a flat label to the other deck's.
/// `get` reads one component set of a frame (U, NT, …) for a node.
inline void expect_same_nodes(const JobResult& a, const JobResult& b, const SplitBlocks& g,
                              double rel_tol) {
  const Frame& fa = last_frame(a);
  const Frame& fb = last_frame(b);
  const Model& ma = *a.model;
  const Model& mb = *b.model;
  double scale_u = 0.0, scale_t = 0.0;
  for (const Vec3& u : fa.nodes.U)
    scale_u = std::max({scale_u, std::abs(u[0]), std::abs(u[1]), std::abs(u[2])});
  for (double t : fa.nodes.NT) scale_t = std::max(scale_t, std::abs(t));
  int compared = 0;
  for (int k = 0; k <= g.nz; ++k)
    for (int j = 0; j <= g.ny; ++j)
      for (int i = 0; i <= g.nx; ++i) {
        const NodeId na = ma.mesh.find_node(g.label(i, j, k));
        for (const int lb : {g.split_label(i, j, k), SplitBlocks::kRight + g.label(i, j, k)}) {
          if (lb > SplitBlocks::kRight && i < g.m) continue;
          const NodeId nb = mb.mesh.find_node(lb);
          ASSERT_GE(na, 0);
          ASSERT_GE(nb, 0) << lb;
          if (!fa.nodes.U.empty())
            for (int c = 0; c < 3; ++c)
              EXPECT_NEAR(fa.nodes.U[na][c], fb.nodes.U[nb][c], rel_tol * scale_u)
                  << "node " << lb << " U" << c + 1;
          if (fa.nodes.any_temperature)
            EXPECT_NEAR(fa.nodes.NT[na], fb.nodes.NT[nb], rel_tol * scale_t) << "node " << lb;
          ++compared;
          if (i != g.m) break;
        }
      }
  EXPECT_GT(compared, 0);
  EXPECT_GT(scale_u + scale_t, 0.0);
}

} // namespace gapfem::test
