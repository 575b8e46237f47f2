#pragma once
/// @file parallel.hpp
/// The processes of a run. `mpirun -np N gapfem deck.inp` starts N processes that each read the
/// deck and run the same analysis; the linear systems are distributed over them (the PETSc
/// backend, `--solver mumps|iterative`), and rank 0 alone writes the job's files and the terminal.
/// A serial run (no mpirun) is one rank; a build without PETSc has only that.
///
/// MPI (through PETSc) is started only when it is needed: when the program was started by mpirun,
/// or when a PETSc solver is asked for. Everything here is safe to call before or without it.
#include <string>
#include <vector>

namespace gapfem::parallel {

/// True when this build has the PETSc backend (and MPI).
bool available();
/// Registers this layer's solver backends with linalg's registry (register_solver_backend):
/// "mumps" and "iterative" (PetscKktSolver), or, in a build without PETSc, the same names with
/// the reason they are unavailable. Idempotent; called by the solver and application layers.
void register_backends();
/// Start MPI and PETSc (once; later calls do nothing). `petsc_options` are PETSc's own command-line
/// options (`-ksp_rtol 1e-12`, `-inner_pc_type hypre`, …), inserted into its options database.
/// Throws std::runtime_error when the build has no PETSc.
void start(const std::vector<std::string>& petsc_options = {});
/// True once start() ran.
bool started();
/// This process's rank and the number of ranks (0 and 1 until start()).
int rank();
int size();
/// Stop every rank of the job with `exit_code` (a rank that failed alone must not leave the others
/// waiting in a collective call). Returns only when not started (serial).
void abort_job(int exit_code);
/// The end of the program on every rank: returns the exit status to return from main. When several
/// ranks run, they meet here; a rank that failed (exit_code != 0) waits at most a few seconds for
/// the others (which fail alike when the failure is the model's), then prints its `error` (ranks
/// other than 0 are otherwise silent) and stops the whole job with MPI_Abort, so that no rank is
/// left waiting in a collective call.
int finish(int exit_code, const std::string& error);
/// Collective reductions over all ranks (identity when serial).
double max_over_ranks(double v);
int max_over_ranks(int v);
/// Wait for every rank (nothing when serial).
void barrier();

/// The command line's PETSc options: arguments of the form `-name[ value]` whose name has a known
/// PETSc prefix (ksp_, pc_, mat_, inner_, log_view, …), removed from argv. gapfem's own options
/// start with `--` or are single letters, so they never collide.
std::vector<std::string> take_petsc_options(int& argc, char** argv);

} // namespace gapfem::parallel
