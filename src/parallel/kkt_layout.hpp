#pragma once
/// @file kkt_layout.hpp
/// Which rows of the bordered system [K D; C -E] each rank owns. The n equations and the m
/// constraint rows are each split in contiguous blocks as PETSc splits a vector
/// (PetscSplitOwnership: the first n % size ranks get one more); rank p's rows of the bordered
/// system are its equations followed by its constraint rows, so the bordered system's global
/// numbering interleaves the ranks: equation i of rank p is row l_p + i, constraint row r of rank p
/// is row u_{p+1} + r.
#include "parallel/parallel.hpp"

#include <algorithm>
#include <vector>

namespace gapfem {

struct KktLayout {
  int n = 0, m = 0; ///< equations, constraint rows
  int rank = 0, size = 1;
  std::vector<int> u{0, 0}, l{0, 0}; ///< first equation / constraint row of each rank, size + 1

  KktLayout() = default;
  /// `block`: the equations are split in whole blocks of that many (nodal blocks; n a multiple).
  KktLayout(int n_equations, int n_rows, int this_rank = parallel::rank(),
            int n_ranks = parallel::size(), int block = 1)
      : n(n_equations), m(n_rows), rank(this_rank), size(n_ranks),
        u(split(n_equations, n_ranks, block)), l(split(n_rows, n_ranks)) {}

  /// Equations split at the given first equation of each rank (size + 1 entries).
  KktLayout(std::vector<int> u_starts, int n_rows, int this_rank = parallel::rank(),
            int n_ranks = parallel::size())
      : n(u_starts.back()), m(n_rows), rank(this_rank), size(n_ranks), u(std::move(u_starts)),
        l(split(n_rows, n_ranks)) {}

  static std::vector<int> split(int count, int ranks, int block = 1) {
    std::vector<int> start(static_cast<std::size_t>(ranks) + 1, 0);
    const int blocks = count / block;
    for (int p = 0; p < ranks; ++p)
      start[p + 1] = start[p] + block * (blocks / ranks + (p < blocks % ranks));
    return start;
  }
  int u0() const { return u[rank]; }
  int u1() const { return u[rank + 1]; }
  int l0() const { return l[rank]; }
  int l1() const { return l[rank + 1]; }
  int u_local() const { return u1() - u0(); }
  int l_local() const { return l1() - l0(); }
  /// Row of the bordered system of equation i / constraint row r.
  int kkt_u(int i) const { return i + l[owner(u, i)]; }
  int kkt_l(int r) const { return r + u[owner(l, r) + 1]; }

 private:
  static int owner(const std::vector<int>& start, int i) {
    return static_cast<int>(std::upper_bound(start.begin(), start.end(), i) - start.begin()) - 1;
  }
};

} // namespace gapfem
