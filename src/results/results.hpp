#pragma once
/// @file results.hpp
/// What the analysis hands to the result writers: frames (the committed state at an output point),
/// step summaries with self-checks, and the run summary. Writers format; they never compute
/// physics.
#include "common/archive.hpp"
#include "common/timer.hpp"
#include "common/types.hpp"
#include "elements/element_kernel.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gapfem {

struct Model;

/// Nodal values of all nodes (index = NodeId). Vectors are sized n_nodes; entries of nodes that do
/// not carry a DOF are zero, and `has_*` tell which nodes carry which field.
struct NodeResults {
  std::vector<Vec3> U, UR, RF, RM, CF, CM;
  /// Velocities (V, VR) and accelerations (A, AR) of a *DYNAMIC step, sized n_nodes like U and UR
  /// (zero at nodes without the DOF; local systems at *TRANSFORM nodes like U); empty in steps
  /// without them, whose writers then leave them out.
  std::vector<Vec3> V, VR, A, AR;
  std::vector<double> NT, RFL, CFL;
  /// Heat-transfer shells carry temperatures at points through their thickness (DOFs 11, 12, …):
  /// NT/RFL/CFL above hold DOF 11; the further points 12 … 10 + temperature_points are in the
  /// *_more vectors, (temperature_points - 1) values per node (empty when temperature_points <= 1)
  int temperature_points = 1;
  std::vector<double> NT_more, RFL_more, CFL_more;
  /// Number of temperature DOFs node n carries (0, 1, or up to temperature_points).
  int temperatures_at(NodeId n) const {
    return n >= 0 && static_cast<std::size_t>(n) < dof_mask.size()
               ? std::popcount(dof_mask[n] & kTemperatureBits)
               : 0;
  }
  std::vector<DofMask> dof_mask; ///< per node: bit dof_bit(DofType) set when the DOF is active
  /// Nodes with a *TRANSFORM: their vectors above are in the local system with these axes (rows
  /// e1, e2, e3), as Abaqus reports them; the VTU writer turns them back to global components.
  std::map<NodeId, std::array<double, 9>> local_axes;
  /// Stress analyses with a predefined temperature field (*TEMPERATURE, *INITIAL CONDITIONS): NT
  /// holds the field; nt_field[n] is 1 at the nodes of elements that read it (the only nodes that
  /// report NT), and there is no RFL or CFL. Empty when the model solves for temperatures.
  std::vector<std::uint8_t> nt_field;
  bool any_rotation = false;
  bool any_temperature = false; ///< temperature DOFs, or a predefined field (nt_field)
  bool any_displacement = false;
  /// Global components of a vector `v` given at `n`: Q^T v at a *TRANSFORM node, v elsewhere.
  Vec3 global(NodeId n, const Vec3& v) const {
    const auto it = local_axes.find(n);
    if (it == local_axes.end()) return v;
    const auto& Q = it->second;
    Vec3 g{};
    for (int j = 0; j < 3; ++j) g[j] = Q[j] * v[0] + Q[3 + j] * v[1] + Q[6 + j] * v[2];
    return g;
  }
};

/// One element's output at a frame.
struct ElementResult {
  ElemId elem = -1;
  ElementRecovery data;
};

/// Whole-model energies since the analysis start, Abaqus's names (docs/theory/dynamics.md,
/// "Energies"): kinetic ALLKE = 1/2 v.M v; internal ALLIE (the work of the element, contact and
/// constraint forces, friction's dissipation taken out); viscous ALLVD (the damping operators:
/// Rayleigh, dashpots, point-mass ALPHA); stabilization ALLSD; frictional ALLFD (the gaps');
/// external work ALLWK (loads and the reactions of prescribed motion); kinetic energy lost at
/// impacts ALLKL. Parts of ALLIE (not in ETOTAL again): ALLSE, the recoverable strain energy
/// (ALLIE less ALLAE and the gaps' contact damping work), and ALLAE, the hourglass controls'
/// artificial strain energy.
struct Energies {
  double allke = 0.0, allie = 0.0, allvd = 0.0, allsd = 0.0, allfd = 0.0, allwk = 0.0, allkl = 0.0;
  double allse = 0.0, allae = 0.0;
  /// ETOTAL = ALLKE + ALLIE + ALLVD + ALLSD + ALLFD + ALLKL - ALLWK: constant (zero from a
  /// state at rest) when energy is conserved; HHT's numerical dissipation lowers it.
  double etotal() const { return allke + allie + allvd + allsd + allfd + allkl - allwk; }
  /// The largest magnitude of the terms, for judging ETOTAL.
  double scale() const {
    double m = 0.0;
    for (double e : {allke, allie, allvd, allsd, allfd, allwk, allkl}) m = std::max(m, std::abs(e));
    return m;
  }
};

/// Self-checks after each step (.dat block, terminal summary, JSON "checks").
struct StepChecks {
  int n_gaps = 0, n_open = 0, n_closed = 0, n_stick = 0, n_slip = 0;
  double max_penetration = 0.0; ///< max(-h) over closed gaps beyond the interference allowance
  Label max_penetration_elem = 0;
  double max_tensile_force = 0.0; ///< max tension carried by a closed gap (hard contact: 0)
  Label max_tensile_elem = 0;
  std::array<double, 3> reaction_sum{}; ///< sum of reaction forces RF
  std::array<double, 3> applied_sum{};  ///< sum of applied concentrated + distributed loads
  double equilibrium_error = 0.0;       ///< |RF_sum + applied_sum| (translational)
  double force_scale = 0.0;             ///< for judging equilibrium_error
  /// equilibrium_error / force_scale, formed in extended precision so that loads up to the double
  /// range never make it overflow (0 when force_scale is 0: see has_force_scale)
  double relative_equilibrium = 0.0;
  bool has_force_scale() const { return force_scale > 0.0; }
  /// Heat balance (heat transfer and coupled steps, solver/thermal_step.hpp): transient steps
  /// integrate the fluxes over the step (heat), steady-state steps give the fluxes at its end.
  bool thermal = false;
  double reaction_flux_sum = 0.0, applied_flux_sum = 0.0, stored_heat = 0.0,
         heat_balance_error = 0.0;
  double heat_scale = 0.0; ///< sum of |RFL| + |applied| (+ |stored|), for judging the error
  double relative_heat_balance = 0.0; ///< heat_balance_error / heat_scale (extended precision)
  double max_damping_force = 0.0;     ///< largest gap damping force in any increment of the step
  /// Automatic stabilization (*STATIC, STABILIZE): the damping factor at the step end and the
  /// energies since the analysis start, as Abaqus reports them (ALLSD dissipated by the
  /// stabilization, ALLIE the internal energy)
  bool stabilized = false;
  double stabilization_factor = 0.0, allsd = 0.0, allie = 0.0;
  /// Hourglass-controlled elements (C3D8R, CPS4R, ...): at the step end ALLAE, the energy of their
  /// hourglass forces, and ALLSE, the elastic strain energy of all continuum elements
  bool hourglass = false;
  double allae = 0.0, allse = 0.0;
  /// Dynamic steps: the energies at the step end and the balance over the step: the change of
  /// ETOTAL from the step start (energy_change; > 0: energy was gained), judged against the
  /// largest energy of the step (energy_scale), and the integrator's expected dissipation
  /// (none for the trapezoidal rule: conserving)
  bool dynamic = false;
  Energies energies;
  double energy_change = 0.0, energy_scale = 0.0;
  bool conserving = false; ///< trapezoidal rule (alpha = 0, beta = 1/4, gamma = 1/2)
};

/// One substructure element's internal results at a frame (*SUBSTRUCTURE PATH): recovered by the
/// analysis (solver/substructure_recovery), written by SubstructureRecoveryWriter.
struct RecoveredSubstructure {
  ElemId elem = -1;
  std::string label, type;   ///< the Zn element's label and its substructure type ("Z1")
  std::string library, deck; ///< the library file and the deck that generated it
  bool stresses = false;     ///< the generation model was read: its elements' S and E follow
  std::string note;          ///< why there are no stresses ("" when there are)
  /// U1-3, UR1-3 and NT of every node of the substructure, by its label in the generation deck
  std::map<Label, std::array<double, 7>> nodes;
  struct Element {
    std::string label, type;
    std::vector<std::pair<ElemVar, std::vector<double>>> averages; ///< S and E over the points
  };
  std::vector<Element> elements;
};

/// The committed state at one output point, with what is due at this point.
/// One eigenmode of a *FREQUENCY step (docs/theory/frequency.md): the eigenvalue omega^2, the
/// generalized mass phi^T M phi, and per direction (X, Y, Z translations, rotations about the X,
/// Y, Z axes through the origin) the participation factor Gamma = phi^T M T / m and the effective
/// mass Gamma^2 m.
struct ModeInfo {
  int mode = 0;
  double eigenvalue = 0.0;
  double generalized_mass = 0.0;
  std::array<double, 6> participation{}, effective_mass{};
  /// omega in radians per time (0 for a negative eigenvalue)
  double circular() const { return eigenvalue > 0.0 ? std::sqrt(eigenvalue) : 0.0; }
  /// cycles per time
  double frequency() const { return circular() / (2.0 * 3.14159265358979323846); }
};

/// The modes of a *FREQUENCY (or *BUCKLE) step, with the model's mass per direction (what the
/// effective masses add up to when every mode is extracted) and how they were found.
struct EigenSummary {
  std::vector<ModeInfo> modes;
  std::array<double, 6> total_effective_mass{};
  std::array<double, 6> model_mass{}; ///< T^T M T of the free DOFs per direction
  bool rotations = false;             ///< the model has rotational DOFs
  bool mass_normalized = false;       ///< NORMALIZATION=MASS (else the largest entry is 1)
  double shift = 0.0;                 ///< the Lanczos shift, omega^2
  int rigid_body_modes = 0;           ///< eigenvalues near zero
  /// *BUCKLE: the eigenvalues are load multipliers (no frequencies, masses or participation)
  bool buckling = false;
};

struct Frame {
  int step = 0;
  int increment = 0;
  double step_time = 0.0, total_time = 0.0, dt = 0.0;
  bool last_in_step = false;
  std::optional<Energies> energies; ///< dynamic steps: the whole-model energies at the frame
  /// *FREQUENCY steps: the mode this frame shows (its U, UR the mode shape; increment = mode)
  std::optional<ModeInfo> mode;
  /// *STEADY STATE DYNAMICS steps: the excitation frequency (cycles per time) of this frame,
  /// whose nodes.U and UR hold the real part of the harmonic response and these its imaginary
  /// part (sized like nodes.U; the amplitude is |re + i im|, the phase atan2(im, re))
  struct Harmonic {
    double frequency = 0.0;
    std::vector<Vec3> U, UR;
  };
  std::optional<Harmonic> harmonic;
  NodeResults nodes;
  /// Element output for the elements needed by the due requests (all elements at the last frame).
  std::vector<ElementResult> elements;
  std::vector<std::int32_t> element_slot; ///< per ElemId: index into `elements` or -1

  std::vector<bool> node_print_due; ///< per Step::node_prints
  std::vector<bool> el_print_due;   ///< per Step::el_prints
  bool field_due = false;           ///< ParaView frame due
  /// per Step::field_outputs: due in this frame (empty when the step has no *OUTPUT, FIELD:
  /// the frame at the end of the step then holds every variable)
  std::vector<bool> field_output_due;
  std::vector<bool> file_output_due; ///< per Step::file_outputs (job.frd)
  /// The step's *SUBSTRUCTURE PATH elements, recovered when field output is due or the step ends
  std::vector<RecoveredSubstructure> substructures;

  const ElementResult* element(ElemId e) const {
    if (e < 0 || e >= static_cast<ElemId>(element_slot.size()) || element_slot[e] < 0)
      return nullptr;
    return &elements[element_slot[e]];
  }
};

/// One gap's state after a converged increment (IncrementInfo::gaps).
struct GapSample {
  ElemId elem = -1;
  float force = 0.0f;     ///< normal force (compressive positive)
  float clearance = 0.0f; ///< h
  ContactStatus status = ContactStatus::Open;
};

struct IncrementInfo {
  int step = 0, increment = 0, attempts = 0, iterations = 0, severe_discontinuities = 0;
  double step_time = 0.0, total_time = 0.0, dt = 0.0;
  bool converged = true;
  /// Newton converged, but the procedure repeats the increment (converged is then false): its
  /// accuracy check failed (the temperature change exceeded DELTMX, the half-increment residual
  /// HAFTOL: repeated smaller), or a *DYNAMIC increment released hard contacts (repeated with
  /// the release at its start)
  bool deltmx_exceeded = false;
  const char* accuracy_check = "DELTMX exceeded"; ///< why it is repeated (deltmx_exceeded)
  /// *MONITOR: the monitored DOF's value after a converged increment (none when not due or the
  /// node does not carry the DOF)
  std::optional<double> monitor;
  /// max over fields of residual / time-averaged flux after each Newton iteration
  std::vector<double> residual_history;
  /// After a converged increment of a model with gaps, when a writer wants_gap_samples(): the
  /// gaps that are closed (closed, stick or slip) and every gap's state (else -1 and empty).
  int gaps_closed = -1;
  std::vector<GapSample> gaps;
  /// Dynamic steps: the whole-model energies after the increment.
  std::optional<Energies> energies;
  /// *OUTPUT, HISTORY due after the increment: the step's column names (one object for the
  /// whole step) and their values (docs/results.md, "History output"); null when not due.
  std::shared_ptr<const std::vector<std::string>> history_columns;
  std::vector<double> history;
};

struct StepSummary {
  int step = 0;
  std::string name;
  std::string procedure;
  bool converged = true;
  std::string failure; ///< reason when not converged
  int increments = 0;
  int attempts = 0;
  int iterations = 0;
  StepChecks checks;
};

/// A step summary in a restart record.
inline void save(ArchiveWriter& a, const StepSummary& s) {
  a.pod(s.step);
  a.str(s.name);
  a.str(s.procedure);
  a.pod(s.converged);
  a.str(s.failure);
  a.pod(s.increments);
  a.pod(s.attempts);
  a.pod(s.iterations);
  a.pod(s.checks);
}
inline void load(ArchiveReader& a, StepSummary& s) {
  a.pod(s.step);
  a.str(s.name);
  a.str(s.procedure);
  a.pod(s.converged);
  a.str(s.failure);
  a.pod(s.increments);
  a.pod(s.attempts);
  a.pod(s.iterations);
  a.pod(s.checks);
}

struct RunSummary {
  bool completed = true;
  std::string failure;
  double wall_seconds = 0.0;
  RunStatistics stats;
  std::vector<std::string> warnings;
  long peak_memory_kb = 0;
};

/// A restarted job's result files (docs/restart.md): those of the job that wrote the restart
/// data, cut (the same job) or copied (a new job) up to the restart point, then continued.
struct ResumeFiles {
  std::filesystem::path directory;
  std::string job;
  std::filesystem::path file(std::string_view suffix) const {
    return directory / (job + std::string(suffix));
  }
};

/// Receives the committed state at output points. Implementations: .dat, .sta, JSON, VTU.
class ResultWriter {
 public:
  virtual ~ResultWriter() = default;
  /// Does the writer read IncrementInfo::gaps (one sample per gap and converged increment)?
  virtual bool wants_gap_samples() const { return false; }
  virtual void begin(const Model& model) {}
  virtual void begin_step(const Model& model, int step_index) {}
  virtual void increment(const IncrementInfo& info) {}
  virtual void frame(const Model& model, int step_index, const Frame& frame) {}
  /// A *FREQUENCY step's eigenvalues, participation factors and effective masses, before its
  /// frames (one per mode).
  virtual void modes(const Model& model, int step_index, const EigenSummary& modes) {}
  virtual void end_step(const Model& model, int step_index, const StepSummary& summary) {}
  virtual void end(const Model& model, const RunSummary& summary) {}

  /// Restart (docs/restart.md). The name of the writer's state in a restart record; empty: the
  /// writer keeps no state (it is simply begun again).
  virtual std::string_view restart_key() const { return {}; }
  /// Save what resume() needs to continue the files from this point (after an increment()).
  virtual void save_state(ArchiveWriter&) {}
  /// Instead of begin(): continue in step `step_index` from a state save_state() wrote in the
  /// job `from`.
  virtual void resume(const Model& model, int step_index, ArchiveReader& state,
                      const ResumeFiles& from) {
    begin(model);
  }
};

} // namespace gapfem
