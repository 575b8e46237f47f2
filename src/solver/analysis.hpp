#pragma once
/// @file analysis.hpp
/// Runs all steps of a model: per step the equation numbering, sparsity pattern and symbolic
/// factorisation, the increment loop (Newton + automatic incrementation), output frames and the
/// self-checks; carries the committed state, load history and contact status between steps.
#include "elements/element_kernel.hpp"
#include "linalg/constrained_solver.hpp"
#include "results/results.hpp"
#include "solver/restart_file.hpp"
#include "solver/substructure_recovery.hpp"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gapfem {

struct Model;

struct AnalysisOptions {
  int threads = 0;       ///< assembly threads; 0: default_thread_count(ranks_here)
  int ranks_here = 1;    ///< the run's processes on this machine (they share its cores)
  KernelOptions kernels; ///< how the element kernels formulate (penalty and friction rows)
  KktTuning kkt;         ///< how the serial solver works (factor updates, dense multipliers)
  /// tests of durable results: the process kills itself (SIGKILL) after this many converged
  /// increments (GAPFEM_TEST_KILL_AFTER_INCREMENT; -1: never)
  long kill_after_increments = -1;
  FactorReuse factor_reuse = FactorReuse::Auto; ///< see KktSolver
  /// evaluate the residual alone while the solver reuses its factor (NewtonControls::residual_only)
  bool residual_only = true;
  std::string solver = "cholmod"; ///< the constrained-system solver's backend (by name)
  /// Restart (docs/restart.md): where the records of steps with *RESTART, WRITE go (job.res;
  /// empty: none are written) and the header naming the deck (the fingerprint is filled in).
  std::filesystem::path restart_file;
  RestartHeader restart_header;
  /// Continue from a restart record instead of starting from the beginning.
  struct Resume {
    std::filesystem::path file; ///< the restart file holding the record
    RestartRecordInfo record;
    std::uint64_t fingerprint = 0; ///< the model fingerprint in that file's header
    bool end_step = false;         ///< *RESTART, READ, END STEP: the step ends at the record
    ResumeFiles files;             ///< the result files to continue
  };
  std::optional<Resume> resume;
  /// *SUBSTRUCTURE PATH: reads a substructure's generation deck again for its stresses (the
  /// application layer gives io's reader; empty: recovered displacements only)
  DeckReader generation_deck_reader;
  /// Where a *SUBSTRUCTURE GENERATE step writes its library file (empty: nowhere; tests)
  std::filesystem::path output_dir;
};

/// What `gapfem check` reports: the model as the analysis sees it before solving.
struct ModelCheck {
  struct StepInfo {
    int number = 0;
    std::string name, procedure;
    LocalIndex equations = 0;
    int constraint_rows = 0; ///< active linear-constraint rows (*EQUATION, ties, couplings …)
    std::size_t factor_bytes = 0; ///< CHOLMOD's symbolic estimate of the factor of K
    /// check(true), step 1: wall time of one CHOLMOD factorisation of K at the reference state
    /// (the best of two), the unit of the limit ratio (docs/performance.md)
    double factor_seconds = 0.0;
  };
  struct GapInfo {
    std::string type;
    int total = 0, open = 0, closed = 0; ///< status of the reference configuration
  };
  std::vector<StepInfo> steps;
  std::vector<GapInfo> gaps;
  LocalIndex dofs = 0; ///< active nodal DOFs
};

class Discretization;
/// A fingerprint of a model as the analysis sees it (mesh, elements, DOFs, history sizes,
/// constraint rows, steps): restart records and substructure files fit only the model it names.
std::uint64_t model_fingerprint(const Model& model, const Discretization& disc);

class Analysis {
 public:
  Analysis(const Model& model, std::vector<ResultWriter*> writers, AnalysisOptions options = {});
  ~Analysis();
  /// Run every step. Returns the run summary; throws AnalysisError when a step cannot be completed
  /// (after the writers received the last converged state and the failed step's summary).
  RunSummary run();
  const std::vector<StepSummary>& step_summaries() const;
  /// Everything up to solving (element checks, procedures, each step's loads, equations and
  /// symbolic factorisation) without solving; throws InputError as run() would.
  ModelCheck check(bool time_factorization = false);

  /// The run's state (solver/analysis_impl.hpp, not a public header); named here so that the
  /// step procedures (solver/procedure.hpp) can work on it.
  struct Impl;

 private:
  std::unique_ptr<Impl> _impl;
};

/// Peak resident memory of this process in kB (VmHWM), 0 if unknown.
long peak_memory_kb();

} // namespace gapfem
