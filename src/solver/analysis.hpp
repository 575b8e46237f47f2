#pragma once
/// @file analysis.hpp
/// Runs all steps of a model: per step the equation numbering, sparsity pattern and symbolic
/// factorisation, the increment loop (Newton + automatic incrementation), output frames and the
/// self-checks; carries the committed state, load history and contact status between steps.
#include "linalg/factor_reuse.hpp"
#include "output/results.hpp"

#include <memory>
#include <vector>

namespace gapfem {

struct Model;

struct AnalysisOptions {
  int threads = 0;                              ///< 0: default_thread_count()
  FactorReuse factor_reuse = FactorReuse::Auto; ///< see KktSolver
};

class Analysis {
 public:
  Analysis(const Model& model, std::vector<ResultWriter*> writers, AnalysisOptions options = {});
  ~Analysis();
  /// Run every step. Returns the run summary; throws AnalysisError when a step cannot be completed
  /// (after the writers received the last converged state and the failed step's summary).
  RunSummary run();
  const std::vector<StepSummary>& step_summaries() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> _impl;
};

/// Peak resident memory of this process in kB (VmHWM), 0 if unknown.
long peak_memory_kb();

} // namespace gapfem
