#pragma once
/// @file step.hpp
/// One analysis step (*STEP … *END STEP): procedure, incrementation controls, the resolved loads
/// and boundary conditions active in the step, and the output requests.
#include "common/error.hpp"
#include "model/loads.hpp"
#include "model/output_request.hpp"
#include "model/section.hpp"
#include "model/substructure.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace gapfem {

enum class Procedure : std::uint8_t {
  Static,
  HeatTransfer,
  CoupledTempDisp,
  SubstructureGenerate, ///< *SUBSTRUCTURE GENERATE: a linear reduction, no increments
  Dynamic,              ///< *DYNAMIC: implicit direct integration (HHT or backward Euler)
  Frequency,            ///< *FREQUENCY: natural frequencies about the base state (perturbation)
  ResponseSpectrum,     ///< *RESPONSE SPECTRUM: peak response from the modes of a *FREQUENCY step
  Buckle,               ///< *BUCKLE: eigenvalue buckling about the base state (perturbation)
  SteadyStateDynamics,  ///< *STEADY STATE DYNAMICS: harmonic response on the modes
  ModalDynamic          ///< *MODAL DYNAMIC: transient response on the modes
};
std::string_view procedure_name(Procedure p);
/// Does the procedure evaluate the elements as a linear perturbation about the base state (the
/// end of the last general step), their status frozen there: the eigenfrequency extraction and
/// eigenvalue buckling (a *STATIC step with *STEP, PERTURBATION is one too: Step::perturbation).
/// The steps of every perturbation procedure (also the mode-based ones, which work on the modes
/// alone) are marked Step::perturbation and leave the base state as it was for the next general
/// step.
constexpr bool is_perturbation(Procedure p) {
  return p == Procedure::Frequency || p == Procedure::Buckle;
}
/// Does the procedure work on the modes of an earlier *FREQUENCY step (a mode-based procedure)?
constexpr bool is_mode_based(Procedure p) {
  return p == Procedure::ResponseSpectrum || p == Procedure::SteadyStateDynamics ||
         p == Procedure::ModalDynamic;
}
/// Does the procedure use the elements' mass (dynamic response, eigenmodes)?
constexpr bool uses_mass(Procedure p) {
  return p == Procedure::Dynamic || p == Procedure::Frequency;
}
/// Does the procedure solve for temperatures (heat transfer, coupled temperature-displacement)?
constexpr bool is_thermal(Procedure p) {
  return p == Procedure::HeatTransfer || p == Procedure::CoupledTempDisp;
}

/// Time incrementation of *STATIC, *HEAT TRANSFER and *COUPLED TEMPERATURE-DISPLACEMENT.
struct Incrementation {
  double initial = 0.0; ///< 0: default (= period)
  double period = 1.0;
  double minimum = 0.0;     ///< 0: default min(initial, 1e-5 * period)
  double maximum = 0.0;     ///< 0: default (= period)
  bool direct = false;      ///< DIRECT: fixed increments of `initial`, no cut-backs
  bool steady_state = true; ///< heat transfer / coupled: STEADY STATE (true) or transient
  double deltmx = 0.0;      ///< transient: max temperature change per increment (0: none)
};

/// *STEP, EXTRAPOLATION: how the first guess of an increment is formed from the increments before
/// it in the step (Abaqus/Standard's default: LINEAR, 100% of the previous increment's solution
/// scaled by the ratio of the time increments). Theory: docs/theory/extrapolation.md.
enum class Extrapolation : std::uint8_t {
  Linear,    ///< u_n + (dt / dt_n) du_n
  Parabolic, ///< the parabola through the last three converged states (linear until there are)
  None       ///< EXTRAPOLATION=NO: each increment starts at the last converged state
};

/// *CONTROLS: Abaqus/Standard's solution controls (defaults as in Abaqus). They stay in effect in
/// later steps until changed or reset (*CONTROLS, RESET).
struct SolutionControls {
  /// PARAMETERS=FIELD, per field (displacement, rotation, temperature)
  struct Field {
    double residual = 0.005;    ///< R_n
    double correction = 0.01;   ///< C_n
    double initial_flux = 1e-2; ///< q~_0
    double user_flux = 0.0;     ///< q~_u (> 0: replaces the time-averaged flux)
    double zero_flux = 1e-5;    ///< epsilon: zero-flux criterion relative to q~_0
    double linear = 1e-8;       ///< epsilon_l: convergence of a linear increment in one iteration
  };
  std::array<Field, 3> field{};
  /// PARAMETERS=TIME INCREMENTATION
  int divergence_check_after = 4; ///< I_0 (8 with ANALYSIS=DISCONTINUOUS)
  int max_iterations = 16;        ///< I_C
  int hard_iterations = 10;       ///< I_L
  int easy_iterations = 4;        ///< I_G
  int max_attempts = 5;           ///< I_A
  int max_severe_iterations = 12; ///< I_S (Abaqus: 12, 50 with ANALYSIS=DISCONTINUOUS)
  double cutback = 0.25;          ///< D_f
  double shrink = 0.75;           ///< D_B
  double deltmx_cutback = 0.85;   ///< D_A
  double growth = 1.5;            ///< D_D
};

/// *DYNAMIC (implicit direct integration, docs/theory/dynamics.md): the application and the
/// integrator's parameters as Abaqus/Standard resolves them.
struct DynamicSettings {
  enum class Application : std::uint8_t { TransientFidelity, ModerateDissipation, QuasiStatic };
  Application application = Application::TransientFidelity;
  /// Hilber-Hughes-Taylor (TRANSIENT FIDELITY, MODERATE DISSIPATION) or backward Euler
  bool hht = true;
  double alpha = -0.05, beta = 0.275625, gamma = 0.55;
  /// INITIAL=YES: accelerations at the step start from the equation of motion; NO: zero
  bool initial_accelerations = true;
  /// HAFTOL: the half-increment residual tolerance (force) of automatic incrementation; without
  /// it (and without DIRECT) the increments keep their size unless Newton needs a cut-back
  std::optional<double> haftol;
  SourceLocation loc;
};

/// *FREQUENCY (natural frequency extraction, docs/theory/frequency.md): what the data line and
/// the parameters ask for.
struct FrequencySettings {
  enum class Solver : std::uint8_t { Lanczos, Subspace, Ams };
  Solver solver = Solver::Lanczos; ///< EIGENSOLVER= (all run gapfem's shift-invert Lanczos)
  /// Number of eigenvalues requested; 0 (blank): all in the frequency range
  int count = 0;
  std::optional<double> min_frequency, max_frequency; ///< cycles per time
  std::optional<double> shift;                        ///< the shift point, cycles per time
  bool mass_normalized = false; ///< NORMALIZATION=MASS (default DISPLACEMENT: largest entry 1)
  SourceLocation loc;
};

/// *BUCKLE (eigenvalue buckling, docs/theory/buckling.md): what the data line and the parameters
/// ask for. Eigenvalues are load multipliers of the step's perturbation loads.
struct BuckleSettings {
  enum class Solver : std::uint8_t { Subspace, Lanczos };
  Solver solver = Solver::Subspace; ///< EIGENSOLVER= (both run gapfem's Lanczos)
  int count = 0;                    ///< eigenvalues requested (0: all in the range, Lanczos)
  std::optional<double> min_eigenvalue, max_eigenvalue; ///< the range of interest
  int vectors = 0, iterations = 0; ///< SUBSPACE: vectors used and iterations (accepted, unused)
  SourceLocation loc;
};

/// *STEADY STATE DYNAMICS (mode-based harmonic response, docs/theory/modal_dynamics.md): the
/// frequency ranges of the data lines and how points are spread over them.
struct SteadyStateSettings {
  enum class Interval : std::uint8_t { Eigenfrequency, Range, Spread };
  Interval interval = Interval::Eigenfrequency; ///< INTERVAL=
  bool logarithmic = true;                      ///< FREQUENCY SCALE=LOGARITHMIC (else LINEAR)
  struct Range {
    double lower = 0.0, upper = 0.0; ///< cycles per time
    int points = 20;                 ///< points per interval (Abaqus's default 20)
    std::optional<double> bias;      ///< bias parameter (default 3, RANGE 1)
    double scale = 1.0;              ///< frequency scale multiplier
  };
  std::vector<Range> ranges;
  SourceLocation loc;
};

/// *MODAL DYNAMIC (mode-based transient response): fixed time increments over a period.
struct ModalDynamicSettings {
  double dt = 0.0, period = 0.0;
  bool continue_previous = false; ///< CONTINUE=YES (refused: the initial modal state is zero)
  SourceLocation loc;
};

/// *BASE MOTION in a mode-based step: the motion of the base (the nodes the base state's
/// boundary conditions hold) along one DOF, by an amplitude.
struct BaseMotion {
  enum class Type : std::uint8_t { Acceleration, Velocity, Displacement };
  Type type = Type::Acceleration;
  DofType dof = DofType::U1;
  int amplitude = -1; ///< index into Model::amplitudes (-1: constant 1)
  double scale = 1.0;
  bool imaginary = false; ///< *STEADY STATE DYNAMICS: the imaginary part
  SourceLocation loc;
};

/// The summation rules of *RESPONSE SPECTRUM, SUM= (solver/modal_combination.hpp).
enum class ModalSum { Abs, Srss, Cqc, Nrl, Tenp, Dsc, Grp };

/// *MODAL DAMPING in a mode-based step: fractions of critical damping by mode ranges or by
/// frequency, or Rayleigh factors by mode ranges (docs/theory/frequency.md §6). Modes it does not
/// name have no damping.
struct ModalDamping {
  enum class Kind { Fraction, Rayleigh };
  Kind kind = Kind::Fraction;
  bool by_frequency = false; ///< DEFINITION=FREQUENCY RANGE: (frequency, fraction) points
  struct Range {
    int first = 1, last = 1;        ///< modes (1-based), by mode numbers
    double zeta = 0.0;              ///< fraction of critical damping
    double alpha = 0.0, beta = 0.0; ///< Rayleigh: zeta = alpha / (2 omega) + beta omega / 2
    double frequency = 0.0;         ///< by frequency: the point's frequency (cycles/time)
  };
  std::vector<Range> ranges;
  SourceLocation loc;
  /// The damping fraction of mode k (1-based) of circular frequency omega.
  double fraction(int k, double omega) const;
};

/// *RESPONSE SPECTRUM: the spectra along their directions and the rules that combine the modes
/// and the directions.
struct ResponseSpectrumSettings {
  bool algebraic = false; ///< COMP=ALGEBRAIC (else SRSS over the directions)
  ModalSum sum = ModalSum::Abs;
  struct Direction {
    int spectrum = -1; ///< index into Model::spectra
    std::array<double, 3> cosines{};
    double scale = 1.0;
    double duration = 0.0; ///< DSC: the event's duration (0: none given)
  };
  std::vector<Direction> directions;
  SourceLocation loc;
};

/// *CHANGE FRICTION, ELSET= followed by *FRICTION: new friction for some gap elements.
struct FrictionChange {
  std::vector<ElemId> elements;
  FrictionSpec friction;
  SourceLocation loc;
};

/// *STATIC, STABILIZE: Abaqus/Standard's automatic stabilization, viscous forces
/// f_v = c M* (u - u_start) / dt with M* the lumped mass matrix of unit density.
struct Stabilization {
  bool on = false;
  double fraction = 2e-4;       ///< dissipated energy fraction (STABILIZE=value)
  std::optional<double> factor; ///< FACTOR=: the damping factor c itself
  double allsdtol = 0.05;       ///< adaptive: the largest ALLSD / ALLIE (0: c stays constant)
  bool carry = false;           ///< CONTINUE=YES: the next step keeps the damping factor
  SourceLocation loc;
};

struct Step {
  int number = 0;
  std::string name;
  SourceLocation loc;
  Procedure procedure = Procedure::Static;
  bool nlgeom = false;
  int max_increments = 100; ///< *STEP, INC=
  bool ramp_default = true; ///< default amplitude variation: RAMP (true) or STEP
  /// *STEP, UNSYMM=YES: keep the unsymmetric load stiffness of follower loads (unsymmetric solver);
  /// by default its symmetric part is used, as in Abaqus/Standard
  bool unsymmetric = false;
  /// *STEP, UNSYMM=NO: symmetric tangents only (friction, coupled terms): the symmetric solver
  /// throughout, at the price of more iterations
  bool symmetric_only = false;
  Extrapolation extrapolation = Extrapolation::Linear; ///< *STEP, EXTRAPOLATION=
  Incrementation inc;
  SolutionControls controls;
  Stabilization stabilize;
  DynamicSettings dynamic;                   ///< *DYNAMIC steps
  FrequencySettings frequency;               ///< *FREQUENCY steps
  ResponseSpectrumSettings spectrum;         ///< *RESPONSE SPECTRUM steps
  BuckleSettings buckle;                     ///< *BUCKLE steps
  SteadyStateSettings steady_state;          ///< *STEADY STATE DYNAMICS steps
  ModalDynamicSettings modal_dynamic;        ///< *MODAL DYNAMIC steps
  std::vector<BaseMotion> base_motions;      ///< *BASE MOTION (mode-based steps)
  std::optional<ModalDamping> modal_damping; ///< *MODAL DAMPING of a mode-based step
  /// *SELECT EIGENMODES: the modes (1-based) a mode-based step uses; empty: all of them
  std::vector<int> selected_modes;
  /// *STEP, PERTURBATION, or a perturbation procedure (*FREQUENCY): the step works about the base
  /// state and leaves it unchanged; its loads and boundary conditions do not carry on
  bool perturbation = false;

  std::vector<BoundaryEntry> boundary;
  std::vector<NodalLoad> cloads; ///< *CLOAD (DOF 1-6) and *CFLUX (DOF 11)
  std::vector<DistributedLoad> dloads;
  std::vector<NodalTemperature> temperatures;
  std::vector<InterferenceEntry> interference;
  std::vector<FrictionChange> friction_changes;

  std::vector<NodePrintRequest> node_prints;
  std::vector<ElPrintRequest> el_prints;
  std::vector<FieldOutputRequest> field_outputs;
  std::vector<HistoryOutputRequest> history_outputs; ///< *OUTPUT, HISTORY
  std::vector<FileOutputRequest> file_outputs;       ///< *NODE FILE / *EL FILE (job.frd)
  /// *MONITOR in effect in this step (given in it, in an earlier step or in the model data)
  std::optional<DofMonitor> monitor;
  /// *RESTART, WRITE in effect in this step (given in it, in an earlier step or the model data)
  RestartWrite restart;
  /// *SUBSTRUCTURE GENERATE (procedure SubstructureGenerate)
  std::optional<SubstructureGeneration> generation;
  /// *SUBSTRUCTURE PATH: the substructure (Zn) elements whose internal results are recovered
  std::vector<ElemId> recover_substructures;
};

} // namespace gapfem
