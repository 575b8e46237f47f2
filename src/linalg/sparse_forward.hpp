#pragma once
/// @file sparse_forward.hpp
/// Forward solves L Y = U with a CHOLMOD supernodal factor for sparse right-hand sides: a column
/// of U with a few entries has a Y column that is non-zero only on the elimination-tree paths
/// from its rows to the root, so only those supernodes are visited (Gilbert and Peierls's
/// observation, by supernodes). The columns of one call are solved together, with the BLAS's
/// triangular solve and product per supernode over the columns that reach it.
/// Used to form the Woodbury correction of linalg/low_rank_correction.hpp at a fraction of the
/// cost of dense forward solves.
#include "common/types.hpp"

#include <cholmod.h>
#include <vector>

namespace gapfem {

class SparseForwardSolver {
 public:
  /// The supernodal structure of L (its tree of supernodes); L must stay alive and unchanged.
  explicit SparseForwardSolver(const cholmod_factor& L);
  /// One sparse right-hand side in, its solution out (rows ascending, in the factor's ordering).
  struct Column {
    std::vector<LocalIndex> rows;
    std::vector<double> vals;
  };
  /// Y = L^-1 U, column by column (rhs[j] in, out[j] out).
  void solve(const std::vector<Column>& rhs, std::vector<Column>& out);

 private:
  const cholmod_factor& _L;
  std::vector<int> _col_super;           ///< column -> its supernode
  std::vector<int> _parent;              ///< supernode -> parent supernode (-1: a root)
  std::vector<int> _stamp;               ///< per supernode: the last column that marked it
  std::vector<std::vector<int>> _active; ///< per supernode: the columns that reach it
  std::vector<double> _dense;            ///< n x block, zero outside the visited rows
};

} // namespace gapfem
