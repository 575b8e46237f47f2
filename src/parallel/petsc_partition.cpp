// The iterative method's partition of A among the ranks: a graph partitioner (PT-Scotch through
// PETSc's MatPartitioning) chooses each rank's blocks (nodes, or equations), which are then
// numbered contiguously. See petsc_kkt_solver.hpp.
#include "common/log.hpp"
#include "parallel/parallel.hpp"
#include "parallel/petsc_detail.hpp"
#include "parallel/petsc_runtime.hpp"

#include <algorithm>
#include <numeric>

namespace gapfem {

using parallel::petsc_check;
using namespace petsc_detail;

namespace {
using PartitionH = Handle<MatPartitioning, MatPartitioningDestroy>;
using IsH = Handle<IS, ISDestroy>;

/// Edges between blocks that lie on different ranks (each counted once from either side), for
/// the log: the halo the Krylov method exchanges.
long cut_edges(const std::vector<std::vector<PetscInt>>& adjacency, PetscInt first,
               std::span<const PetscInt> rank_of) {
  long cut = 0;
  for (std::size_t b = 0; b < adjacency.size(); ++b)
    for (PetscInt c : adjacency[b]) cut += rank_of[first + static_cast<PetscInt>(b)] != rank_of[c];
  return cut;
}
} // namespace

std::vector<std::vector<PetscInt>> PetscKktSolver::Impl::block_adjacency(PetscInt first,
                                                                         PetscInt count) const {
  const SparsityPattern& pat = *pattern;
  std::vector<std::vector<PetscInt>> adjacency(static_cast<std::size_t>(count));
  for (PetscInt b = first; b < first + count; ++b) {
    auto& list = adjacency[b - first];
    for (int d = 0; d < block; ++d) {
      const LocalIndex i = eq_of(b * block + d);
      if (i < 0) continue;
      for (LocalIndex k = pat.row_ptr[i]; k < pat.row_ptr[i + 1]; ++k)
        if (const PetscInt c = row_of(pat.col[k]) / block; c != b) list.push_back(c);
    }
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return adjacency;
}

void PetscKktSolver::Impl::partition_blocks() {
  u_starts.clear();
  const int ranks = parallel::size();
  if (ranks < 2 || !pattern) return;
  if (pattern->n < kPartitionFrom) return; // the ranks' few couplings do not matter
  if (pad.empty()) {                       // equations are the blocks
    pad.resize(static_cast<std::size_t>(pattern->n));
    std::iota(pad.begin(), pad.end(), 0);
    unpad = pad;
  }
  const auto blocks = static_cast<PetscInt>(unpad.size() / static_cast<std::size_t>(block));
  const std::vector<int> split = KktLayout::split(static_cast<int>(blocks), ranks);
  const PetscInt first = split[parallel::rank()], count = split[parallel::rank() + 1] - first;
  const auto adjacency = block_adjacency(first, count);

  // the local rows of the block graph (MatCreateMPIAdj takes arrays from PetscMalloc)
  PetscInt* ia = nullptr;
  PetscInt* ja = nullptr;
  std::size_t edges = 0;
  for (const auto& list : adjacency) edges += list.size();
  petsc_check(PetscMalloc1(count + 1, &ia), "PetscMalloc1");
  petsc_check(PetscMalloc1(std::max<std::size_t>(edges, 1), &ja), "PetscMalloc1");
  ia[0] = 0;
  for (PetscInt b = 0; b < count; ++b) {
    std::copy(adjacency[b].begin(), adjacency[b].end(), ja + ia[b]);
    ia[b + 1] = ia[b] + static_cast<PetscInt>(adjacency[b].size());
  }
  MatH graph;
  petsc_check(MatCreateMPIAdj(PETSC_COMM_WORLD, count, blocks, ia, ja, nullptr, graph.out()),
              "MatCreateMPIAdj");
  PartitionH part;
  petsc_check(MatPartitioningCreate(PETSC_COMM_WORLD, part.out()), "MatPartitioningCreate");
  petsc_check(MatPartitioningSetAdjacency(part, graph), "MatPartitioningSetAdjacency");
#if defined(PETSC_HAVE_PTSCOTCH)
  petsc_check(MatPartitioningSetType(part, MATPARTITIONINGPTSCOTCH), "MatPartitioningSetType");
#elif defined(PETSC_HAVE_PARMETIS)
  petsc_check(MatPartitioningSetType(part, MATPARTITIONINGPARMETIS), "MatPartitioningSetType");
#else
  petsc_check(MatPartitioningSetType(part, MATPARTITIONINGCURRENT), "MatPartitioningSetType");
#endif
  petsc_check(MatPartitioningSetFromOptions(part), "MatPartitioningSetFromOptions");
  IsH target, all;
  petsc_check(MatPartitioningApply(part, target.out()), "MatPartitioningApply");
  petsc_check(ISAllGather(target, all.out()), "ISAllGather");
  const PetscInt* rank_of = nullptr;
  petsc_check(ISGetIndices(all, &rank_of), "ISGetIndices");
  const std::span<const PetscInt> owner(rank_of, static_cast<std::size_t>(blocks));

  // blocks renumbered rank by rank, in their order within each rank
  std::vector<PetscInt> starts(static_cast<std::size_t>(ranks) + 1, 0);
  for (PetscInt p : owner) ++starts[p + 1];
  const PetscInt fewest = *std::min_element(starts.begin() + 1, starts.end());
  const PetscInt most = *std::max_element(starts.begin() + 1, starts.end());
  std::partial_sum(starts.begin(), starts.end(), starts.begin());
  if (fewest == 0) { // a rank without rows: the contiguous blocks instead
    petsc_check(ISRestoreIndices(all, &rank_of), "ISRestoreIndices");
    return;
  }
  std::vector<PetscInt> next(starts.begin(), starts.end() - 1), moved(owner.size());
  for (PetscInt b = 0; b < blocks; ++b) moved[b] = next[owner[b]]++;
  long local_cut = cut_edges(adjacency, first, owner), cut = 0, plain_cut = 0;
  std::vector<PetscInt> contiguous(owner.size());
  for (int p = 0; p < ranks; ++p)
    std::fill(contiguous.begin() + split[p], contiguous.begin() + split[p + 1], p);
  long local_plain = cut_edges(adjacency, first, contiguous);
  MPI_Allreduce(&local_cut, &cut, 1, MPI_LONG, MPI_SUM, PETSC_COMM_WORLD);
  MPI_Allreduce(&local_plain, &plain_cut, 1, MPI_LONG, MPI_SUM, PETSC_COMM_WORLD);
  petsc_check(ISRestoreIndices(all, &rank_of), "ISRestoreIndices");

  for (LocalIndex& p : pad) p = static_cast<LocalIndex>(moved[p / block] * block + p % block);
  std::fill(unpad.begin(), unpad.end(), -1);
  for (std::size_t i = 0; i < pad.size(); ++i) unpad[pad[i]] = static_cast<LocalIndex>(i);
  u_starts.resize(starts.size());
  for (std::size_t p = 0; p < starts.size(); ++p) u_starts[p] = static_cast<int>(starts[p] * block);
  MatPartitioningType type = nullptr;
  petsc_check(MatPartitioningGetType(part, &type), "MatPartitioningGetType");
  log::debug("  partition ({}): {} blocks of {} over {} ranks, {} to {} a rank; {} couplings "
             "between ranks (contiguous blocks: {})",
             type, blocks, block, ranks, fewest, most, cut / 2, plain_cut / 2);
}

} // namespace gapfem
