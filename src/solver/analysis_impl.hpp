#pragma once
/// @file analysis_impl.hpp
/// Inside Analysis (not a public header): the state carried through the run and the objects of
/// the step being run. analysis.cpp runs the steps in stages (set up, increment loop, finish),
/// analysis_output.cpp builds output frames and the step self-checks, analysis_restart.cpp saves
/// and restores restart records (docs/restart.md).
#include "common/log.hpp"
#include "fem/assembler.hpp"
#include "fem/discretization.hpp"
#include "linalg/constrained_solver.hpp"
#include "model/model.hpp"
#include "solver/analysis.hpp"
#include "solver/diagnostics.hpp"
#include "solver/extrapolation.hpp"
#include "solver/increment_control.hpp"
#include "solver/modal_basis.hpp"
#include "solver/newton.hpp"
#include "solver/procedure.hpp"
#include "solver/restart_file.hpp"
#include "solver/stabilization.hpp"
#include "solver/step_problem.hpp"
#include "solver/thermal_step.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gapfem {

/// The objects of the step being run, shared by run_step's stages.
struct StepRun {
  int index = 0;
  const Step* step = nullptr;
  std::unique_ptr<StepLoads> loads;
  std::shared_ptr<const SparsityPattern> pattern;
  StepContext base;
  std::unique_ptr<StepProblem> prob;
  /// What the step's procedure adds to the stages (solver/procedure.hpp)
  std::unique_ptr<StepProcedure> proc;
  StepSummary sum;
  IncrementRules rules;
  std::unique_ptr<IncrementController> ctrl;
  FluxHistory flux;
  NewtonControls controls;
  std::vector<double> converged_f_int, converged_f_ext;
  std::string last_problem;
  AttemptLog attempts_log;
  /// The solution at the step start (kept when the step writes restart data: StepLoads needs it)
  std::vector<double> u_step_start;
  /// The last converged increment [t0, t0 + dt]: a resumed step starts at that state.
  double last_t0 = 0.0, last_dt = 0.0;
  bool ended_at_restart = false; ///< *RESTART, READ, END STEP: the step ends where it resumed
  /// The first guess of each increment (*STEP, EXTRAPOLATION); an attempt after a failed one
  /// starts from the last converged state instead (the guess may have been what failed).
  IncrementPredictor predictor;
  bool extrapolate = true;
};

/// A restart record being resumed: its payload and the reader positioned in it.
struct PendingResume {
  AnalysisOptions::Resume where;
  std::string payload;
  std::unique_ptr<ArchiveReader> in;
  std::vector<double> u_step_start;
};

struct Analysis::Impl {
  const Model& model;
  std::vector<ResultWriter*> writers;
  Discretization disc;
  Assembler assembler;
  std::unique_ptr<ConstrainedSolver> solver; ///< the backend (make_constrained_solver)
  SolutionState st;
  LoadHistory history;
  RunStatistics stats;
  std::vector<StepSummary> summaries;
  /// warnings found while solving (they join the deck's in every results file and the summary)
  std::vector<std::string> solver_warnings;
  Stopwatch watch;
  bool has_temperature_dofs = false;
  AnalysisOptions options;

  Impl(const Model& m, std::vector<ResultWriter*> w, AnalysisOptions o);

  // ---------------------------------------------------------------- steps (analysis.cpp)
  StepSummary run_step(int index);
  /// Loads, equations, pattern, problem, stabilization and controls of a step; from `resume`'s
  /// record instead of the step start when given.
  void set_up_step(StepRun& r, PendingResume* resume);
  /// The increments until the step ends or fails (sets r.sum.converged / failure).
  void increment_loop(StepRun& r);
  /// One converged attempt: commit, output, restart record.
  void accept_increment(StepRun& r, const NewtonResult& res, IncrementInfo& info, double dt,
                        double growth);
  /// A failed attempt: explain it, cut back or stop. False: the step stops.
  bool reject_attempt(StepRun& r, const NewtonResult& res, const IncrementInfo& info, double t0);
  /// After the loop: the final frame, load history, checks and the writers' end_step.
  StepSummary finish_step(StepRun& r);
  /// The sparsity pattern of a step's equations (elements and active constraint rows).
  std::shared_ptr<const SparsityPattern> step_pattern(const StepLoads& loads);
  /// Gap counts by type and status at the reference configuration (gapfem check).
  void initial_gap_status(ModelCheck& c);
  /// *SUBSTRUCTURE GENERATE (substructure_generate.cpp): reduce the stiffness onto the retained
  /// DOFs and write the substructure library file.
  void generate_substructure(StepRun& r);
  /// Is the stiffness at the committed state (step time t0) non-singular? Used to tell a limit
  /// point or crushed element (singular only in the increment) from a missing support.
  bool supported_at_last_converged(StepProblem& prob, double t0);

  // ---------------------------------------------------------------- output (analysis_output.cpp)
  /// Largest |damping force| of the gaps at the current state (0 when no gap has damping).
  double damping_peak(StepProblem& prob);
  /// IncrementInfo::gaps and gaps_closed from the committed state, for writers that want them.
  void gap_samples(StepProblem& prob, IncrementInfo& info);
  void write_frame(int index, StepProblem& prob, int increment, bool last, double dt,
                   bool repeat = false);
  std::optional<Frame> frame_due(const Step& step, const StepProblem& prob, int increment,
                                 bool last, double dt, bool repeat, bool& field_elements) const;
  void frame_nodes(StepProblem& prob, Frame& fr);
  /// A perturbation's node output (a mode shape, a response spectrum's peaks): U and UR from the
  /// values per DOF slot, the forces and temperatures zero.
  void perturbation_nodes(std::span<const double> slots, Frame& fr) const;
  /// *OUTPUT, HISTORY after a converged increment (analysis_history.cpp): the due requests'
  /// values into info (their columns named at the step's first sample).
  void history_sample(int step_index, StepProblem& prob, int increment, bool last,
                      IncrementInfo& info);
  std::shared_ptr<const std::vector<std::string>> history_columns; ///< of history_step
  int history_step = -1;
  void frame_elements(const Step& step, StepProblem& prob, bool field_elements, Frame& fr);
  /// A perturbation's element output (a mode shape, a static perturbation): per element needed,
  /// the change of its recovered values (stress, strain, section forces) along du (per slot) at
  /// the committed state, per unit of du (linear perturbation; no gap records or energies).
  void perturbation_elements(const Step& step, StepProblem& prob, std::span<const double> du,
                             bool field_elements, Frame& fr);
  /// Per element: does a request due in this frame (or its being the step's last) need it.
  std::vector<char> elements_needed(const Step& step, bool field_elements, const Frame& fr) const;
  /// The *MONITOR value after a converged increment, when due.
  std::optional<double> monitor_value(const Step& step, int increment, bool last) const;
  /// Nodal vectors at *TRANSFORM nodes in their local systems; reactions from the multipliers of
  /// the boundary conditions given there.
  void to_local_systems(NodeResults& nr) const;
  /// The self-checks after a step: hourglass energies, gap states, equilibrium.
  StepChecks checks(StepProblem& prob);
  void hourglass_checks(StepProblem& prob, StepChecks& c);
  void gap_checks(StepProblem& prob, StepChecks& c);
  void equilibrium_checks(StepProblem& prob, StepChecks& c);
  /// Net forces of elements and matrix terms that may hold the model to ground.
  void grounded_forces(StepProblem& prob, std::array<long double, 3>& ground, long double& scale);

  /// The modes of the last *FREQUENCY step, the basis of the mode-based steps after it (null
  /// before one; not part of restart records)
  std::shared_ptr<const ModalBasis> modal_basis;

  bool want_gap_samples = false;
  /// *SUBSTRUCTURE PATH: the libraries of the substructures the steps recover (none: nullptr)
  std::unique_ptr<SubstructureRecoverer> recoverer;
  double step_damping_peak = 0.0;
  /// Automatic stabilization: M* (built once), and what CONTINUE=YES hands to the next step.
  std::shared_ptr<const std::vector<double>> unit_mass;
  Stabilization carried_stabilization;
  int carried_stabilization_step = -1; ///< the step whose STABILIZE is carried (-1: none)
  double carried_factor = 0.0;

  // ---------------------------------------------------------------- restart (analysis_restart.cpp)
  RestartFileWriter restart_out;
  std::unique_ptr<PendingResume> resume;
  long kill_after_increments = -1; ///< GAPFEM_TEST_KILL_AFTER_INCREMENT (tests)
  /// Mesh, DOFs and element storage of the model: a record fits only the model that wrote it.
  std::uint64_t fingerprint() const;
  /// Open job.res when a step asks for restart data (continuing it when resuming from it).
  void open_restart_file();
  /// Load the record to resume and restore the run-level state (solution, element history,
  /// multipliers, load history, statistics, earlier steps' summaries).
  void begin_resume();
  /// The step-level state of the record (increment controller, sums, stabilization).
  void restore_step(StepRun& r);
  /// The writers continue their files from the record (instead of begin/begin_step).
  void resume_writers(int index);
  /// After a converged increment: is a record due? (t_prev: the step time before it)
  bool restart_due(const StepRun& r, double t_prev) const;
  void write_restart(StepRun& r);
};

} // namespace gapfem
