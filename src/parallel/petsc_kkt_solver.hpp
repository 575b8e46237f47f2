#pragma once
/// @file petsc_kkt_solver.hpp
/// The PETSc backend of the solver seam (`--solver mumps|iterative`, and every `mpirun` run).
///
/// Every rank holds the whole model and assembles the same K and constraint rows (the analysis is
/// replicated); each rank hands PETSc its own block of rows (PETSc's default contiguous split of
/// the equations, and of the constraint rows), so the matrices, the factor and the Krylov vectors
/// are distributed. The solution is gathered back to every rank, which then all take the same
/// Newton step. Decisions that could differ between ranks (the preconditioner's reuse) follow
/// quantities every rank computes alike (iteration counts), never timers.
///
/// The bordered system, with the multipliers scaled by s = mean |diag K| so that both blocks have
/// the same magnitude (dl = s dl'):
///
///     [ K    s D   ] [du ]   [  b   ]
///     [ s C  -s²E  ] [dl'] = [ -s g ]
///
/// * Mumps: the whole matrix goes to MUMPS: LDL^T with 2x2 pivots (symmetric indefinite) when
///   D = C^T and K is symmetric, LU otherwise. A later system whose constraint rows have the same
///   pattern refactorises numerically on the same analysis; the identical system reuses the factor.
/// * Iterative: first the rows that need no iteration leave the system exactly (RowElimination:
///   a row fixing one equation, such as a gap to a fixed node along an axis, fixes that equation;
///   a compliant row's multiplier is substituted). When no row is left and K is symmetric, CG with
///   one AMG cycle as preconditioner solves K' du = b' (GMRES for the rest of the step if CG
///   finds the cycle indefinite). Where every equation is a translation, A is numbered by nodes
///   (block size 3, NearNullSpace::padded) so that GAMG aggregates nodes. Otherwise the remaining
///   exact constraints are kept as constraints (no penalty): K is augmented to A = K + C^T R C (R_r
///   ~ 100 x the stiffness along the row, as KktSolver does; D becomes D - C^T R E so the solution
///   is unchanged), and right-preconditioned GMRES solves the bordered system with the block
///   upper-triangular preconditioner [A  sD'; 0  -S], where A^-1 is one AMG cycle (GAMG; options
///   prefix `inner_`) and S = s²(E + (1 - RE)/(R + ks)) is the diagonal estimate of the Schur
///   complement that the augmentation makes accurate (within 1% for exact rows). The AMG hierarchy
///   is rebuilt only when the iterations it takes grow to twice (plus 5) those after it was built;
///   GMRES iterates on the true matrix, so a reused hierarchy costs iterations, never accuracy.
///   Default tolerance: relative residual 1e-10 (`-ksp_rtol`).
#include "linalg/constrained_solver.hpp"

#include <memory>

namespace gapfem {

class PetscKktSolver final : public ConstrainedSolver {
 public:
  enum class Method { Mumps, Iterative };
  explicit PetscKktSolver(Method method);
  ~PetscKktSolver() override;
  std::string_view name() const override;
  void analyze(std::shared_ptr<const SparsityPattern> pattern) override;
  void forget_factor() override;
  bool wants_near_null_space() const override;
  void set_near_null_space(NearNullSpace modes) override;
  /// MUMPS's factor of the bordered system (either method), with its own matrix.
  std::unique_ptr<ConstrainedFactor> factorize(const CsrMatrix& K, const ConstraintBlock& C,
                                               bool symmetric,
                                               RunStatistics* stats = nullptr) override;
  /// SLEPc's Krylov-Schur over the ranks (petsc_slepc_krylov.hpp).
  std::unique_ptr<KrylovEigenSolver> krylov_eigen_solver() const override;
  /// The serial backend's symbolic estimate (CHOLMOD's), as the memory check uses it.
  std::size_t factor_bytes_estimate() override;
  KktStatistics solve(CsrMatrix& K, std::span<const double> b, const ConstraintBlock& C,
                      std::span<double> du, std::span<double> dl, bool symmetric,
                      const KktOptions& options, RunStatistics* stats = nullptr) override;

 private:
  struct Impl;
  class Factor;
  std::unique_ptr<Impl> _impl;
};

} // namespace gapfem
