#pragma once
/// @file element_kernel.hpp
/// The element contract. A kernel sees only local data (reference coordinates, local DOF values,
/// its own history and multipliers) and returns residual and tangent together in one pass. It never
/// touches global numbering or the global matrix: the assembler gathers and scatters.
///
/// Sign conventions (docs/conventions.md):
///   residual r_e = f_int - f_body(element-generated)  + sum_i lambda_i * dg_i/du
///   tangent  K_e = d r_e / d u_e  (row-major, n_dofs x n_dofs), including lambda_i * d2g_i/du2
///   constraint rows g_i(u) = 0 with multipliers lambda_i (Lagrange-multiplier "extra variables").
/// External loads (distributed) come from load(): f_ext positive in the load direction.
///
/// Operators for time integration and eigenproblems (OpenSees's getTangentStiff / getDamp /
/// getMass): on request (ElementOutput::want_mass, want_damping) a kernel also returns
///   mass    M_e = d(inertia force) / d(acceleration)   (n_dofs x n_dofs, row-major)
///   damping C_e = d(damping force) / d(velocity)       (n_dofs x n_dofs, row-major)
/// The residual and tangent above are the static ones (no M a, no C v): the assembler adds M a + C
/// v and weighs K, C and M as the step's time integrator says (fem/assembler.hpp, OperatorWeights).
/// A kernel whose rate term comes from a nonlinear stored quantity (the heat capacity, E(T)) adds
/// that term itself, with the integrator's coefficients (StepContext::rates), and says so
/// (ElementKernel::damping_in_residual); its damping block is then the operator's linearisation.
#include "common/error.hpp"
#include "common/types.hpp"
#include "elements/rate_coefficients.hpp"
#include "model/element_types.hpp"
#include "model/loads.hpp"
#include "model/mesh.hpp"
#include "model/output_request.hpp"
#include "model/section.hpp"
#include "model/step.hpp"

#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace gapfem {

struct Model;
struct PhysicalConstants;

/// What every element evaluation in one assembly pass shares.
struct StepContext {
  Procedure procedure = Procedure::Static;
  /// a linear perturbation about the base state (*FREQUENCY, *BUCKLE, a static perturbation
  /// step): contact status and friction frozen there (gap_response.cpp)
  bool perturbation = false;
  bool nlgeom = false;
  bool transient = false; ///< transient heat transfer / coupled step
  double step_time = 0.0; ///< step time at the end of the increment being solved
  double step_period = 1.0;
  double total_time = 0.0; ///< total time at the end of the increment
  double dt = 0.0;         ///< increment size
  ModelSpace space = ModelSpace::ThreeD;
  double model_size = 1.0; ///< bounding-box diagonal, for tolerances
  int step_index = 0;      ///< 0-based index of the current step in Model::steps
  int step_number = 1;     ///< the step's number (KSTEP of a UEL)
  int increment = 1;       ///< the increment being solved, 1-based (KINC of a UEL)
  bool direct = false;     ///< fixed incrementation (*STATIC, DIRECT and the like)
  /// *STEP, UNSYMM=NO: the assembler keeps only the symmetric part of every element tangent (and
  /// the constraint rows as their own columns), so the symmetric solver is used throughout
  bool symmetric_only = false;
  const PhysicalConstants* constants = nullptr;
  /// The step's time integrator's coefficients (set by the step problem for every increment;
  /// undefined in static steps). Kernels read them through rate_coefficients(), never dt.
  RateCoefficients rates;
};

/// The rate coefficients a kernel uses: the step integrator's (StepContext::rates) or, for a
/// context made without one (an element test, a one-off evaluation), backward Euler over dt in a
/// transient step; none otherwise.
inline RateCoefficients rate_coefficients(const StepContext& ctx) {
  if (ctx.rates.defined()) return ctx.rates;
  return ctx.transient ? RateCoefficients::backward_euler(ctx.dt) : RateCoefficients{};
}

/// Local data of one element.
struct ElementInput {
  ElemId elem = -1;
  EntityLabel label;               ///< the element as the deck names it (for messages)
  LocalIndex block_index = 0;      ///< position of the element in its block
  std::span<const Vec3> X;         ///< reference coordinates of the element's nodes
  std::span<const double> u;       ///< trial total values of the local DOFs (node-major)
  std::span<const double> u_start; ///< values at the start of the increment (committed)
  /// Trial velocity and acceleration of the local DOFs (node-major, like u; from the integrator's
  /// map, StepContext::rates) and their committed values: given in steps whose integrator defines
  /// them to kernels whose mass or damping operator the assembler applies; empty otherwise (static
  /// steps, a kernel that integrates its own rates), and a (a_start) empty in first-order steps
  std::span<const double> v, a, v_start, a_start;
  std::span<const double>
      temperature; ///< predefined nodal temperatures now (stress elements), or empty
  std::span<const double> temperature_start; ///< … at the start of the increment
  /// predefined through-section temperature gradients now, 2 per node (NodalTemperature::gradient),
  /// or empty when the model has none
  std::span<const double> temperature_gradient;
  std::span<const double>
      initial_temperature; ///< *INITIAL CONDITIONS temperatures (thermal-strain reference)
  std::span<const double> state_start; ///< committed history (n_state)
  std::span<double> state;             ///< trial history, written by evaluate()
  std::span<double> multipliers;       ///< trial Lagrange multipliers (n_multipliers)
  /// per local DOF: 1 when it is an unknown of the step, 0 when prescribed (empty: all free).
  /// Constraint rows acting only on prescribed DOFs cannot be enforced by the solver.
  std::span<const std::uint8_t> free;
  double interference = 0.0; ///< gap elements: allowable interference v(t) now
  /// gap elements: representative stiffness of the elements connected to the gap's nodes
  /// (mean diagonal stiffness of their displacement DOFs), for automatic penalty stiffnesses
  double stiffness_hint = 0.0;
  const StepContext* ctx = nullptr;
};

/// What one evaluation returns. The caller sizes the spans and zeroes residual and tangent.
struct ElementOutput {
  std::span<double> residual; ///< n_dofs
  std::span<double> tangent;  ///< n_dofs * n_dofs, row-major
  bool want_tangent = true;
  /// On request only (ElementKernel::has_mass / has_damping): the mass block d(inertia force) /
  /// d(acceleration) and the damping block d(damping force) / d(velocity), n_dofs x n_dofs,
  /// row-major, zeroed by the caller. Empty (and not to be written) when not wanted.
  std::span<double> mass;
  bool want_mass = false;
  std::span<double> damping;
  bool want_damping = false;

  // Active constraint rows (gap contact, Lagrange friction). Capacity n_multipliers.
  int n_constraints = 0;
  std::span<int> constraint_slot;     ///< which multiplier of the element each row belongs to
  std::span<double> constraint_value; ///< g_i(u); the solver drives it to 0
  /// per row: 0 (exact) or 1/k (compliant: the multiplier is a force of stiffness k; the row is
  /// C du - dl / k + g = 0, see ConstraintBlock::compliance)
  std::span<double> constraint_compliance;
  std::span<double> constraint_coeff; ///< row-major n_multipliers x n_dofs: dg_i/du
  /// d(residual)/d(lambda_i) per row when it differs from dg_i/du (e.g. friction forces that depend
  /// on the normal multiplier); same layout as constraint_coeff; used only if has_columns
  std::span<double> constraint_column;
  bool has_columns = false;

  int status_changes = 0; ///< contact status flips decided in this evaluation
  /// a force law's gap (penalty, softened contact) opened or closed: no severe discontinuity,
  /// but a kink the Newton iteration crossed (`-v` prints the count: it is why such decks
  /// converge linearly while gaps still open and close)
  int branch_changes = 0;
  /// a status change in this evaluation altered the tangent itself, not only the constraint rows
  /// (a penalty or augmented gap in the matrix opened or closed, a gap started or stopped
  /// slipping): a solver reusing an older factor must see the new matrix
  bool stiffness_changed = false;
  bool unsymmetric = false; ///< tangent is not symmetric (friction slip, coupled terms)
  bool friction = false;    ///< a closed gap with friction: its stick/slip path is sensitive
  /// The ratio of a new to the current time increment the element asks for (a UEL's PNEWDT):
  /// below 1 the increment is abandoned and tried again that much smaller; above 1 it bounds the
  /// growth of the next one. Infinity: no request.
  double dt_ratio = std::numeric_limits<double>::infinity();

  void add_constraint(int slot, double value, std::span<const double> coeff,
                      double compliance = 0.0) {
    const auto n = residual.size();
    constraint_slot[n_constraints] = slot;
    constraint_value[n_constraints] = value;
    constraint_compliance[n_constraints] = compliance;
    for (std::size_t i = 0; i < n; ++i) {
      constraint_coeff[n_constraints * n + i] = coeff[i];
      if (!constraint_column.empty()) constraint_column[n_constraints * n + i] = coeff[i];
    }
    ++n_constraints;
  }
};

/// Contact status of a gap (reported; the kernels keep their own encoding in state).
enum class ContactStatus : std::uint8_t { Open, Closed, Stick, Slip };
std::string_view contact_status_name(ContactStatus s);

/// The per-gap output record (JSON "gap", *EL PRINT S/E for gaps, self-checks).
struct GapRecord {
  ContactStatus status = ContactStatus::Open;
  double clearance = 0.0;    ///< h (E11)
  double normal_force = 0.0; ///< compressive force, >= 0 for hard contact
  double pressure = 0.0;     ///< normal_force / area (S11)
  Vec3 direction{}, t1{}, t2{};
  std::array<double, 2> slip{};           ///< accumulated slip E12, E13
  std::array<double, 2> shear{};          ///< S12, S13 (force/area)
  std::array<double, 2> friction_force{}; ///< friction forces in t1, t2
  double damping_force = 0.0;
  double dissipation = 0.0;  ///< accumulated frictional dissipation
  double damping_work = 0.0; ///< accumulated work of the contact damping forces
  bool thermal = false;
  double heat_flux = 0.0; ///< HFL1: per area, positive from node 1 to node 2
  double heat_flow = 0.0; ///< heat_flux * area
  double conductance = 0.0;
  double area = 1.0;
};

/// One requested output quantity of one element: `n_points` rows of `names.size()` components.
struct OutputBlock {
  ElemVar var = ElemVar::S;
  std::span<const std::string_view> names; ///< component names, e.g. S11 S22 S33 S12 S13 S23
  int n_points = 0;
  std::vector<double> values; ///< n_points * names.size()
  /// points through the section at each integration point (shells, beams): point p is
  /// integration point p / section_points, section point p % section_points (both 0-based)
  int section_points = 1;
};

/// Everything an element can report for output. Kernels fill what they support.
struct ElementRecovery {
  std::vector<OutputBlock> blocks;
  std::optional<GapRecord> gap;
  /// hourglass-controlled elements: the energy of their hourglass forces (ALLAE)
  std::optional<double> artificial_energy;
  /// continuum elements: the elastic strain energy 1/2 (E - eps_th) : C : (E - eps_th) over the
  /// element (ALLSE; St. Venant-Kirchhoff under NLGEOM), hourglass energy excluded
  std::optional<double> strain_energy;
  void clear() {
    blocks.clear();
    gap.reset();
    artificial_energy.reset();
    strain_energy.reset();
  }
  const OutputBlock* find(ElemVar v) const {
    for (const auto& b : blocks)
      if (b.var == v) return &b;
    return nullptr;
  }
};

/// The kernel of one element block (one element type with one property). Kernels are immutable
/// after construction and may be called concurrently for different elements.
class ElementKernel {
 public:
  virtual ~ElementKernel() = default;
  virtual ElementType type() const = 0;
  /// Nodes per element: the type's; the deck's own types (USER, SUBSTRUCTURE) override it.
  virtual int n_nodes() const { return element_info(type()).n_nodes; }
  /// DOFs carried at local node `local_node` (in the order they appear in u and residual).
  virtual std::span<const DofType> node_dofs(int local_node) const = 0;
  int n_dofs() const {
    int n = 0;
    for (int a = 0; a < n_nodes(); ++a) n += static_cast<int>(node_dofs(a).size());
    return n;
  }
  virtual int n_state() const { return 0; }
  virtual int n_multipliers() const { return 0; }
  /// Operators (docs/conventions.md, "Mass and damping"): does evaluate() fill ElementOutput::mass
  /// (resp. damping) when asked? Every kernel in the tree states what it has, massless ones
  /// included (a gap, a spring, a UEL say false on purpose, with the reason in their header).
  virtual bool has_mass() const { return false; }
  virtual bool has_damping() const { return false; }
  /// True when evaluate() itself adds the damping forces and their tangent (with the integrator's
  /// coefficients, StepContext::rates) because they come from a nonlinear stored quantity (the
  /// heat capacity: rate of E(T)); the assembler then never adds C v or c C for this kernel.
  virtual bool damping_in_residual() const { return false; }
  /// Does recover() report an artificial (hourglass) energy (ALLAE)?
  virtual bool has_artificial_energy() const { return false; }
  /// Does the element read the predefined temperature field (thermal strain in stress elements)?
  virtual bool uses_temperature_field() const { return false; }

  /// Check the element's geometry before the analysis; return an empty string if fine, otherwise a
  /// sentence the user can act on (the caller adds file, line and label).
  virtual std::string validate(const ElementInput& in) const { return {}; }
  /// Write the initial history into in.state (called once before the first step).
  virtual void initialize(const ElementInput& in) const {}
  /// Residual and tangent at the trial state; writes the trial history.
  virtual void evaluate(const ElementInput& in, ElementOutput& out) const = 0;
  /// Eigenvalue buckling's differential stiffness (docs/theory/buckling.md): K (n_dofs x n_dofs,
  /// row-major) += the initial-stress matrix of the NLGEOM tangent at in.u with the stress change
  /// the local perturbation du makes (dS/du du) in place of the stress. False: the kernel does not
  /// provide it, and the assembler differentiates the element's NLGEOM tangent along du instead
  /// (which adds the initial-displacement matrix of du, of the order of the strain).
  virtual bool stress_stiffness(const ElementInput& in, std::span<const double> du,
                                std::span<double> K) const {
    return false;
  }
  /// Augmented Lagrange: at a converged state, update the element's multiplier estimate when its
  /// constraint is not yet met to its tolerance. Returns true when something changed (the Newton
  /// iteration then continues).
  virtual bool augment(const ElementInput& in) const { return false; }
  /// Line-search hook: the largest fraction (0, 1] of the Newton correction `du` (local DOFs) the
  /// element accepts from its trial state. Elements whose response is nonsmooth along the step
  /// (a frictional gap whose slip would reverse past its whole stick band) return less.
  virtual bool limits_steps() const { return false; }
  virtual double step_limit(const ElementInput& in, std::span<const double> du) const {
    return 1.0;
  }

  /// Can the element carry this distributed load on this face (0 = body)?
  virtual bool supports_load(DistLoadKind kind, int face) const { return false; }
  /// Equivalent nodal load of a distributed load with the given current magnitude: adds to f_ext
  /// (n_dofs) and, when the load depends on the solution (follower pressure, film), adds
  /// -d f_ext / du to tangent.
  virtual void load(const ElementInput& in, const DistributedLoad& load, double magnitude,
                    double sink_temperature, std::span<double> f_ext,
                    std::span<double> tangent) const {}

  /// Heat stored in the element between in.u_start and in.u: the change of its internal energy
  /// (heat capacity), the quantity whose rate the capacity terms of the residual carry. 0 for
  /// elements without heat capacity. Used by the heat balance of transient steps.
  virtual double stored_heat(const ElementInput& in) const { return 0.0; }

  /// Which element output variables the element has.
  virtual bool supports_output(ElemVar var) const { return false; }
  /// Fill the output quantities at the current (converged) state.
  virtual void recover(const ElementInput& in, ElementRecovery& out) const {}
};

/// How kernels formulate what they compute, never what (docs/performance.md). Set by the
/// application layer from the GAPFEM_* environment (app/environment.cpp) and passed down through
/// AnalysisOptions and the Discretization.
struct KernelOptions {
  /// force-law gaps (penalty, softened contact) emit compliant constraint rows; off: their
  /// stiffness goes into K (GAPFEM_PENALTY_ROWS=0)
  bool penalty_rows = true;
  /// elastic-slip friction on a fixed slip plane as compliant rows (GAPFEM_FRICTION_ROWS=0: off)
  bool friction_rows = true;
};

/// What a kernel factory receives.
struct KernelContext {
  const Model& model;
  ElementType type;
  PropertyRef property;
  std::span<const ElemId> elements; ///< the block's elements, for per-element precomputation
  /// USER / SUBSTRUCTURE: which of the deck's types (Mesh::elem_variant); -1 otherwise
  std::int32_t variant = -1;
  KernelOptions options{};
};

/// Element type + property → kernel; InputError for unsupported combinations.
std::unique_ptr<ElementKernel> make_element_kernel(const KernelContext& ctx);

// Family factories (elements/<family>/…), called by make_element_kernel.
std::unique_ptr<ElementKernel> make_continuum_kernel(const KernelContext& ctx);
std::unique_ptr<ElementKernel> make_structural_kernel(const KernelContext& ctx);
std::unique_ptr<ElementKernel> make_gap_kernel(const KernelContext& ctx);
std::unique_ptr<ElementKernel> make_heat_kernel(const KernelContext& ctx);
std::unique_ptr<ElementKernel> make_user_kernel(const KernelContext& ctx);
std::unique_ptr<ElementKernel> make_substructure_kernel(const KernelContext& ctx);

} // namespace gapfem
