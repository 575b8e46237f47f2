#pragma once
/// @file job.hpp
/// Running one deck end to end: read, build, analyse, write results. Used by the gapfem executable
/// and by the tests (which inspect the in-memory results).
#include "linalg/constrained_solver.hpp"
#include "linalg/factor_reuse.hpp"
#include "results/results.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace gapfem {

struct JobOptions {
  std::filesystem::path deck;
  std::filesystem::path output_dir; ///< default: the deck's directory
  std::string job_name;             ///< default: the deck's stem
  bool ignore_unknown = false;      ///< unknown keywords/parameters become warnings
  bool write_files = true;          ///< .dat, .sta, .results.json, ParaView
  bool write_vtu = true;
  /// --report-gaps: the gaps job.report.html plots (labels or element sets; empty: most loaded)
  std::vector<std::string> report_gaps;
  bool quiet = false;      ///< no terminal progress
  bool verbose = false;    ///< debug messages (Newton iterations, solver decisions)
  bool silent = false;     ///< nothing on the terminal, errors included (ranks other than 0)
  bool keep_frames = true; ///< keep every output frame in JobResult (tests)
  /// keep each step's last frame in JobResult (JobResult::step_end) even without keep_frames;
  /// the command line does not, which spares a copy of the largest frame (a 1M-equation model's
  /// nodal and element results) at the end of every step
  bool keep_step_ends = true;
  FactorReuse factor_reuse = FactorReuse::Auto; ///< --factor-reuse (docs/performance.md)
  /// residual-only evaluations while a factor is reused (GAPFEM_RESIDUAL_ONLY=0: off)
  bool residual_only = true;
  std::string solver = "cholmod"; ///< --solver: a registered backend's name (docs/parallel.md)
  /// --restart: continue this job from the last complete record of its job.res (docs/restart.md)
  bool restart = false;
  /// --oldjob: the job a deck with *RESTART, READ continues (a job name, found in the working or
  /// the output directory, or the path of its .res file)
  std::string oldjob;
  /// --user: the user's element code (a UEL in Fortran or C, a C++ element plugin, or a compiled
  /// .so), compiled in the job's scratch folder and loaded before the analysis
  std::filesystem::path user_code;
  /// `gapfem check --time-factorization`: also time one factorisation of step 1's stiffness
  bool time_factorization = false;
};

/// Exit statuses of gapfem (docs/conventions.md).
enum ExitStatus : int {
  kExitOk = 0,
  kExitInputError = 1,
  kExitNoConvergence = 2,
  kExitInternal = 3
};

struct JobResult {
  int exit_code = kExitOk;
  std::string error; ///< the message printed for a non-zero exit
  std::shared_ptr<const struct Model> model;
  std::vector<StepSummary> steps;
  std::vector<Frame> frames; ///< every frame written (when keep_frames)
  std::vector<IncrementInfo> increments;
  /// The modes of each *FREQUENCY step: (0-based step index, its table)
  std::vector<std::pair<int, EigenSummary>> modes;
  RunSummary run;

  /// The last frame of step `step` (1-based), or nullptr.
  const Frame* step_end(int step) const;
  /// Node / element lookups by deck label in a frame.
  static NodeId node(const Model& model, Label label);
};

JobResult run_job(const JobOptions& options);

/// Throws InputError when the model has no *STEP (nothing to analyse).
void require_steps(const struct Model& model, const std::filesystem::path& deck);

} // namespace gapfem
