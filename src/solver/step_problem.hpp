#pragma once
/// @file step_problem.hpp
/// Adapts the discretization, the assembler and a step's loads to the NonlinearProblem interface:
/// evaluation at the trial state of the current increment, corrections, reactions.
#include "common/timer.hpp"
#include "fem/assembler.hpp"
#include "linalg/constrained_solver.hpp"
#include "results/results.hpp"
#include "solver/nonlinear_problem.hpp"
#include "solver/step_loads.hpp"
#include "solver/time_integrator.hpp"

#include <memory>

namespace gapfem {

/// The solution and its history: slot-sized displacement/temperature vectors and node-sized
/// predefined temperatures, each with a trial and a committed copy.
struct SolutionState {
  std::vector<double> u, u_start;   ///< per slot: trial, committed
  std::vector<double> T, T_start;   ///< predefined temperature per node: trial, committed
  std::vector<double> G;            ///< its through-section gradients now, 2 per node (or empty)
  std::vector<double> T_initial;    ///< per node
  std::vector<double> f_int, f_ext; ///< per slot, at the last evaluation
  /// Velocity and acceleration per slot, trial and committed: kept only while the step's
  /// integrator needs them (TimeIntegrator::needs_rate_history; empty otherwise, read as zero).
  /// The trial rates are formed at commit; a cut-back starts again from the committed ones.
  std::vector<double> v, a, v_start, a_start;
  double total_time = 0.0; ///< total time at the start of the current step
  /// Energies since the analysis start (Abaqus's names): ALLIE the work of the element forces,
  /// ALLSD the energy dissipated by automatic stabilization; and the element forces (without the
  /// stabilization) per slot at the last committed state, for ALLIE's trapezoidal rule.
  double allie = 0.0, allsd = 0.0;
  std::vector<double> f_elem_start;
  /// The other energies since the analysis start (results.hpp, Energies; accounted at each commit
  /// in step_problem_energy.cpp): ALLKE at the last commit, ALLVD, ALLWK, ALLKL, and the work of
  /// the constraint and contact forces (part of the reported ALLIE), ALLFD (the gaps' friction,
  /// part of that work, taken out of the reported ALLIE); and per slot at the last commit the
  /// damping forces C v, the external loads, and f_ext - f_int (the constraint forces at free
  /// slots; the reactions, physical forces M a + I + C v - P, at prescribed ones).
  double allke = 0.0, allvd = 0.0, allwk = 0.0, allkl = 0.0, allcw = 0.0, allfd = 0.0;
  std::vector<double> f_damp_start, f_ext_start, f_other_start;
  /// ALLIE's parts that are not recoverable strain energy, at the last commit (dynamic steps,
  /// DynamicProcedure::accepted): the hourglass forces' energy ALLAE and the gaps' accumulated
  /// contact damping work.
  double allae = 0.0, contact_damping = 0.0;
  /// The reported energies (ALLIE = the element and constraint work less ALLFD; ALLSE = ALLIE
  /// less ALLAE and the contact damping work).
  Energies energies() const {
    const double ie = allie + allcw - allfd;
    return {allke, ie, allvd, allsd, allfd, allwk, allkl, ie - allae - contact_damping, allae};
  }
  /// HHT (dynamic steps): the non-inertial residual R = I - P + L per slot at the committed
  /// state (time_integrator.hpp); empty outside dynamic steps.
  std::vector<double> r_start;
  std::vector<double> r_prev; ///< R one committed increment earlier (the half-step residual)
  /// After an impact: the velocities before its projection, whose damping forces R(t) and the
  /// energies' start forces hold (StepProblem::impact); empty when those are v_start's.
  std::vector<double> v_damp;
};

/// What restarting the dynamics at a state found (StepProblem::restart_dynamics).
struct DynamicRestart {
  double amax = 0.0;           ///< the largest acceleration
  double energy_lost = 0.0;    ///< kinetic energy removed by the velocity projection
  double kinetic_energy = 0.0; ///< 1/2 v.M v before it (0 when M was not assembled)
  /// the work of the prescribed DOFs' impulses at the impact (a stop on a moving support gives
  /// what it hits its velocity): ALLWK's share; the kinetic energy changes by it less energy_lost
  double support_work = 0.0;
};

class StepProblem final : public NonlinearProblem {
 public:
  StepProblem(Discretization& disc, Assembler& assembler, const StepLoads& loads,
              SolutionState& state, const StepContext& base,
              std::shared_ptr<const SparsityPattern> pattern);
  StepProblem(const StepProblem&) = delete; // _Kin points into _K
  StepProblem& operator=(const StepProblem&) = delete;

  /// Start an attempt of the increment [t0, t0 + dt] (step time): trial := committed plus the
  /// guessed increment `guess` (per slot, may be empty: solver/extrapolation.hpp), prescribed
  /// values, temperatures and interference at t0 + dt.
  void begin_increment(double t0, double dt, int increment = 0, std::span<const double> guess = {});
  /// Accept the trial state (and add the increment's energies to ALLIE and ALLSD).
  void commit();
  /// Keep the unsymmetric stiffness of follower loads (*STEP, UNSYMM=YES).
  void set_unsymmetric_loads(bool on);
  /// Where assembly time is accounted.
  void set_statistics(RunStatistics* stats) { _stats = stats; }
  /// The step's time integrator (make_time_integrator from the context by default: backward Euler
  /// in transient steps, none in static ones); null: quasi-static. Kernels get its coefficients
  /// (StepContext::rates) and the assembler its weights from the next begin_increment on.
  void set_integrator(std::unique_ptr<TimeIntegrator> integrator);
  const TimeIntegrator* integrator() const { return _integrator.get(); }
  /// The start of a dynamic step (step_problem_dynamic.cpp): the non-inertial residual R(0) at
  /// the committed state and, with `initial_accelerations`, the accelerations of M a + R(0) = 0
  /// on the DOFs with mass (the active exact constraint rows held, C a = 0), factorised by
  /// `solver`; without them the committed accelerations stand (zero after a static step).
  /// Returns the largest |a| found (0 without).
  double start_dynamic_step(ConstrainedSolver& solver, bool initial_accelerations);
  /// A fully plastic impact at the committed state (step time t), after an increment in which
  /// exact constraint rows (hard gaps; their multiplier ids `new_rows`, sorted) became active:
  /// the velocities are projected with the mass onto C v + given_v = 0 (the contacting points
  /// take a common normal velocity, a moving support's included), the accelerations made
  /// consistent (M a + R = 0, C a + given_a = 0, R with the damping forces of the velocities
  /// before the impact) with the rows' forces that hold it, and HHT's history R(t) reset to
  /// -M a. Returns the kinetic energy the impact removed (ALLKL: the projection's loss and the
  /// closing rows' work over the increment). The increment's forces (frame, checks) are kept.
  double impact(ConstrainedSolver& solver, double t, std::span<const std::int64_t> new_rows);
  /// A release of hard contacts put at the increment's start t (step time), before the increment
  /// is solved again: an increment opened gaps that held a force at its start, and HHT's
  /// trapezoid let that force fall linearly to 0 over the opening, working on it (energy the
  /// real contact, whose force is 0 when it separates, never gives). The rows `rows` (multiplier
  /// ids, sorted: the gaps' normal and friction rows) lose their forces at the committed state
  /// and the accelerations are solved again without them (the other contacts unilateral, as after
  /// an impact), HHT's history R(t) and the energies' start forces with them.
  void release_contacts(ConstrainedSolver& solver, double t, std::span<const std::int64_t> rows);
  /// After the committed increment that followed a release (and had no impact): HHT's imbalance
  /// over it (ETOTAL's change; the trapezoidal rule's is 0 to rounding), which the jump of the
  /// released force at its start makes, is booked with the contact events in ALLKL, as an
  /// impact's is (docs/theory/dynamics.md, §5). Returns it.
  double book_release();
  /// The half-increment residual of the converged increment [t0, t0 + dt] (Abaqus Theory Guide,
  /// "Implicit dynamic analysis"): the largest component over the free equations of
  ///   M a + (1 + alpha) R - alpha/2 (R(t0) + R(t0 - dt_prev))
  /// at t0 + dt/2, the state there from the integrator's midpoint rule; zero to second order
  /// when the increment's states interpolate linearly. The trial state and the last evaluation
  /// are left as they were. Negative when the integrator has no midpoint rule.
  double half_increment_residual(double t0, double dt);

  /// A linear perturbation about the committed state (step_problem_perturbation.cpp): the
  /// tangent stiffness there (stress and load stiffness included), the mass, and the constraint
  /// rows the state holds (closed hard gaps, sticking friction, MPCs, ties; compliant rows of
  /// penalty gaps), each as the elements give them at the state (docs/theory/frequency.md).
  struct PerturbationOperators {
    CsrMatrix K, M;
    ConstraintBlock C;
  };
  PerturbationOperators perturbation_operators(bool with_mass = true);
  /// The perturbation of a *BUCKLE or static perturbation step about the committed state: its
  /// loads' change over the step (the given loads at their full value) and the change of its
  /// prescribed values, as the right sides of K du = b, C du - E dl = -g with C the rows of
  /// perturbation_operators(): per equation b (the forces, less the stiffness times the
  /// prescribed perturbation), per row of `C` g, per slot the prescribed perturbation.
  struct PerturbationLoad {
    std::vector<double> b, g, prescribed;
    bool any = false; ///< some load or prescribed value changes
  };
  PerturbationLoad perturbation_load(const ConstraintBlock& C);
  /// The differential stiffness K_Delta of the perturbation du (per slot) about the committed
  /// state (Abaqus's eigenvalue buckling, docs/theory/buckling.md): the change of the NLGEOM
  /// tangent along du per unit of du (the initial stress of the perturbation's stresses; central
  /// difference), plus, with `load_stiffness`, the load stiffness of the step's perturbation
  /// loads. Same pattern as perturbation_operators().K.
  CsrMatrix differential_stiffness(std::span<const double> du, bool load_stiffness);

  /// Automatic stabilization: the damping operator c M* (M* a unit-density lumped mass, per slot,
  /// on the free translational slots) with velocities by backward Euler in the step's time,
  /// whatever the step's own integrator: forces c m (u - u_start) / dt; c = 0 switches it off.
  void set_stabilization(std::shared_ptr<const std::vector<double>> mass, double c);
  double stabilization_factor() const { return _stab_c; }
  /// Dynamic steps: the inertia forces M a (weighted as in the residual) plus HHT's history term
  /// per slot at the last evaluation, which the element and external forces balance (empty
  /// outside dynamic steps).
  std::span<const double> inertial_forces() const { return _f_dyn; }
  /// Dynamic steps: the inertia forces M a alone per slot at the last evaluation (empty outside).
  std::span<const double> inertia_forces() const {
    return _f_dyn.empty() ? std::span<const double>{} : std::span<const double>(_inertia);
  }
  /// The stabilization forces per slot at the last evaluation (empty when off).
  std::span<const double> stabilization_forces() const { return _f_stab; }

  Evaluation evaluate(bool tangent) override;
  Evaluation assemble_tangent() override;
  CsrMatrix& matrix() override { return _K; }
  std::span<const double> rhs() const override { return _rhs; }
  const ConstraintBlock& constraints() const override { return _C; }
  void apply(std::span<const double> du, std::span<const double> dl) override;
  Field equation_field(LocalIndex eq) const override;
  std::array<double, kNumFields> increment_max() const override;
  double constraint_tolerance() const override { return _constraint_tol; }
  int augment() override;
  bool operators_as_before() const override { return _operators_as_before; }
  double step_limit(std::span<const double> du, std::span<const double> dl) override;
  /// Representative stiffness of the non-gap elements at every gap element's DOFs (mean diagonal
  /// of their displacement DOFs), stored for the kernels' automatic penalty stiffnesses.
  void compute_stiffness_hints();

  FieldView fields() const;
  const EquationMap& equations() const { return _loads.equations(); }
  /// Per slot: 1 where the step prescribes the value (a boundary condition).
  std::span<const std::uint8_t> prescribed() const { return _loads.prescribed(); }
  const StepContext& context() const { return _ctx; }
  /// The reactions at prescribed slots (0 elsewhere), at the last evaluation: f_int - f_ext, in
  /// dynamic steps the physical M a + I + C v - P (HHT's weights taken out).
  std::vector<double> reactions() const;
  /// Concentrated loads per slot at the end of the current increment.
  std::vector<double> concentrated_loads() const;

 private:
  /// Stabilization forces into f_int and their tangent into K (after the assembly).
  void add_stabilization(AssemblyResult& ar, bool tangent);
  /// The integrator's coefficients and weights for an increment of size dt, and the rate vectors
  /// sized (or dropped) as it needs them.
  void begin_rates(double dt);
  /// R(t) at the committed state and, on request, the accelerations of M a + R = 0 and the
  /// velocities projected onto the active exact rows (start_dynamic_step, impact).
  /// `impact`: the contacts unilateral in the accelerations' solve (impact_accelerations);
  /// `released`: rows (multiplier ids, sorted) left out of it, their forces already zero.
  DynamicRestart restart_dynamics(ConstrainedSolver& solver, double t, bool accelerations,
                                  bool project_velocities, bool impact,
                                  std::span<const std::int64_t> released = {});
  double project_velocities_onto(ConstrainedFactor& factor, const ConstraintBlock& C,
                                 const std::vector<bool>& massive, double& support_work);
  /// M a + R - released = 0, C a + given_a = 0 (l: the rows' forces added to R's); a and R(t)
  /// := -M a at the DOFs with mass. Returns the largest |a|.
  double consistent_accelerations(ConstrainedFactor& factor, const ConstraintBlock& C,
                                  const std::vector<bool>& massive, std::vector<double>& l,
                                  std::span<const double> released = {});
  /// After an impact: consistent accelerations with unilateral contacts (a gap that would pull
  /// separates with its friction rows), the rows' forces that hold them becoming the committed
  /// multipliers.
  double impact_accelerations(ConstrainedSolver& solver, ConstrainedFactor& factor,
                              const ConstraintBlock& C, const std::vector<bool>& massive,
                              double token);
  /// The exact rows of C that keep says.
  static ConstraintBlock select_rows(const ConstraintBlock& C, const std::vector<bool>& keep);
  /// The damping forces at the committed velocities (every element's, driven DOFs' prescribed
  /// velocities included) into R(t) and the damping forces' start, and the driven DOFs' inertia
  /// coupling (_driven_inertia) for the accelerations' solve (restart_dynamics). False when
  /// nothing moves.
  bool add_rate_forces();
  /// The velocities whose damping forces the committed state holds (SolutionState::v_damp).
  std::span<const double> damped_velocities() const {
    return _s.v_damp.empty() ? std::span<const double>(_s.v_start) : _s.v_damp;
  }
  /// One residual assembly whose rate maps are v = fv.v_start, a = fv.a_start (every element sees
  /// those rates, none the prescribed trial ones): f, and the operators' M a and C v per slot.
  void assemble_at_rates(FieldView fv, const OperatorWeights& w, std::vector<double>& f,
                         std::vector<double>& Ma, std::vector<double>& Cv);
  /// After an impact: the energies' start forces at the state it left, so the next increment's
  /// trapezoids start from the forces the accelerations were solved with: the elements' (the
  /// rows' new multipliers), the damping forces of the velocities before the projection
  /// (v_before, as R(t) of the accelerations' solve), the constraint forces and reactions that
  /// balance M a + I + C v - P
  void reset_energy_start_forces(std::span<const double> v_before);
  /// The forces of the rows of boundary conditions in local systems per slot (C^T lambda, as in
  /// f_int; empty when the step has none) and the slots they hold (`held`, 1 there): their
  /// reactions, ALLWK's.
  std::vector<double> local_bc_forces(std::vector<std::uint8_t>& held) const;
  /// HHT's history term: history_weight() R(t) into f_int (after the assembly).
  void add_rate_history();
  /// R(t + dt) = f_int - f_ext - history term - inertia_weight() M a at a converged state.
  void commit_rate_history();

  Discretization& _disc;
  Assembler& _asm;
  const StepLoads& _loads;
  SolutionState& _s;
  StepContext _ctx;
  std::unique_ptr<TimeIntegrator> _integrator;
  OperatorWeights _weights;   ///< of the current increment (K alone without an integrator)
  BackwardEuler _pseudo_time; ///< the stabilization's viscous forces
  CsrMatrix _K;
  CsrInserter _Kin; ///< the assembler writes _K through it
  ConstraintBlock _C;
  std::vector<double> _rhs;
  std::vector<ActiveLoad> _active;
  std::vector<double> _du_slots; ///< a Newton correction per slot (step_limit)
  /// the trial histories before the last evaluation without tangent (assemble_tangent)
  std::vector<double> _trial_before;
  bool _trial_saved = false;
  double _constraint_tol;
  /// ETOTAL before the last increment's works were added (account_energies): an impact moves
  /// that increment's imbalance into ALLKL (impact)
  double _etotal_before = 0.0;
  bool _unsymmetric_loads = false;
  /// 1 at the slots of base motion (StepLoads::mark_motion), empty without: their trial rates
  /// are the prescribed ones (in _s.v, _s.a during an increment), which the elements see
  std::vector<std::uint8_t> _rate_given;
  /// M a_p per slot of the driven DOFs' accelerations at a dynamic restart (add_rate_forces;
  /// empty when none): a consistent mass's coupling of free DOFs to the base motion
  std::vector<double> _driven_inertia;
  std::shared_ptr<const std::vector<double>> _stab_mass;
  double _stab_c = 0.0;
  std::vector<double> _f_stab;
  /// The energies of a committed increment into the solution state (step_problem_energy.cpp).
  void account_energies();

  std::vector<double> _inertia;        ///< M a per slot at the last evaluation (HHT's history)
  std::vector<double> _damping_forces; ///< C v of the damping operators (dynamic steps)
  std::vector<double> _momentum;       ///< M v per slot at the last evaluation (dynamic steps)
  bool _operators_as_before = false;   ///< operators_as_before() of the current increment
  std::vector<double> _f_dyn;          ///< inertial_forces()
  RunStatistics* _stats = nullptr;
};

} // namespace gapfem
