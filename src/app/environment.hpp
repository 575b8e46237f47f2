#pragma once
/// @file environment.hpp
/// The GAPFEM_* environment switches (docs/performance.md, docs/robustness.md), read in one place,
/// the application layer, and passed down as options: nothing below src/app reads the
/// environment (scripts/check_layers.py checks it).
///
///   GAPFEM_FACTOR_REUSE=always|never   AnalysisOptions::factor_reuse (whole suites both ways)
///   GAPFEM_RESIDUAL_ONLY=0             assemble the tangent in every evaluation
///   GAPFEM_PENALTY_ROWS=0              force-law gaps' stiffness in K, not as compliant rows
///   GAPFEM_FRICTION_ROWS=0             elastic-slip friction's stiffness in K
///   GAPFEM_FACTOR_UPDATES=0            no Woodbury correction of a kept factor
///   GAPFEM_DENSE_MULTIPLIERS=0         no dense multiplier system (the Krylov path)
///   GAPFEM_THREADS=n                   assembly threads
///   GAPFEM_MEMORY_LIMIT=bytes          the memory the process may use (tests: a small machine)
///   GAPFEM_TEST_KILL_AFTER_INCREMENT=n SIGKILL after n converged increments (tests)
#include "solver/analysis.hpp"

namespace gapfem {

/// Applies the switches that are set to `o` (those not set leave it as it is), and the memory
/// limit to common/memory. The processes of an mpirun run on this machine (Open MPI's or MPICH's
/// local size) go to AnalysisOptions::ranks_here.
void apply_environment(AnalysisOptions& o);

/// True when mpirun (Open MPI, MPICH, PMIx) started this process.
bool launched_by_mpirun();

} // namespace gapfem
