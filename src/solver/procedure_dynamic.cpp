// *DYNAMIC steps: implicit direct integration as Abaqus/Standard does it (Hilber-Hughes-Taylor for
// APPLICATION=TRANSIENT FIDELITY and MODERATE DISSIPATION, backward Euler for QUASI-STATIC), the
// step starting from the committed velocities and accelerations (or the initial accelerations of
// INITIAL=YES). Theory and the parameters per application: docs/theory/dynamics.md.
#include "common/log.hpp"
#include "solver/analysis_impl.hpp"
#include "solver/procedures.hpp"

#include <algorithm>
#include <iterator>

namespace gapfem {

namespace {

/// The energy gain over a step, as a fraction of its largest energy, that draws a warning.
constexpr double kEnergyGainTolerance = 1e-3;

class DynamicProcedure final : public StepProcedure {
 public:
  using StepProcedure::StepProcedure;

  std::unique_ptr<TimeIntegrator> make_integrator(const Step& step,
                                                  const StepContext&) const override {
    const DynamicSettings& d = step.dynamic;
    if (!d.hht) return std::make_unique<BackwardEulerDynamic>();
    return std::make_unique<HilberHughesTaylor>(d.alpha, d.beta, d.gamma);
  }

  /// Without HAFTOL (and without DIRECT) nothing measures the accuracy: the increments never
  /// exceed the initial size (Newton's cut-backs allowed, and growth back to it after them as in
  /// a static step) rather than grow unchecked.
  void adjust_rules(const Step& step, IncrementRules& rules) const override {
    if (!step.inc.direct && !step.dynamic.haftol) rules.ceiling = step.inc.initial;
  }
  IncrementAccuracy check_accuracy(StepRun& r, const IncrementInfo& info, double dt) override;

  void set_up(StepRun& r, bool resuming) override {
    if (!resuming) { // a resumed step has the record's rates and history
      warn_if_massless(r);
      if (r.index == 0) initial_velocities(r.loads->prescribed());
      _amax = r.prob->start_dynamic_step(*_a.solver, r.step->dynamic.initial_accelerations);
    }
    _active = exact_rows_of(r.prob->constraints());
    if (!resuming) {
      recover_energies(r); // ALLSE's parts from the state the step starts at
      _etotal_start = _a.st.energies().etotal();
      _scale = _a.st.energies().scale();
    }
  }
  void accepted(StepRun& r, double dt) override;
  void rejected(StepRun&) override { _released.clear(); }
  void finish(StepRun& r) override;
  void save(ArchiveWriter& a, const StepRun&) const override {
    a.vec(_active);
    a.pod(_easy);
    a.pod(_lost);
    a.pod(_amax);
    a.pod(_etotal_start);
    a.pod(_scale);
  }
  void restore(ArchiveReader& in, StepRun&) override {
    in.vec(_active);
    in.pod(_easy);
    in.pod(_lost);
    in.pod(_amax);
    in.pod(_etotal_start);
    in.pod(_scale);
  }

  void report_set_up(const StepRun& r) const override {
    const DynamicSettings& d = r.step->dynamic;
    const TimeIntegrator* ti = r.prob->integrator();
    if (d.hht)
      log::progress("  {} (alpha {:.5g}, beta {:.5g}, gamma {:.5g}); initial accelerations {}",
                    ti->name(), d.alpha, d.beta, d.gamma,
                    d.initial_accelerations ? fmt::format("computed (largest {:.4g})", _amax)
                                            : std::string("zero"));
    else
      log::progress("  {}; initial accelerations {}", ti->name(),
                    d.initial_accelerations ? fmt::format("computed (largest {:.4g})", _amax)
                                            : std::string("zero"));
    const Step& step = *r.step;
    if (d.haftol)
      log::progress("  automatic increments: half-increment residual tolerance HAFTOL {:.4g}",
                    *d.haftol);
    else if (!step.inc.direct)
      log::progress("  increments at most {:.4g}, smaller only to converge (no HAFTOL to measure "
                    "accuracy; give HAFTOL for automatic increments or DIRECT to say fixed)",
                    step.inc.initial > 0 ? step.inc.initial : r.loads->period());
  }

 private:
  /// A model without any mass has no inertia: the step is a sequence of static solutions in time
  /// (only damping makes it time dependent). Abaqus/Standard solves it too; a user who forgot
  /// *DENSITY is told (DOFs without mass in a model with mass are normal: docs/theory/dynamics.md
  /// §3).
  void warn_if_massless(const StepRun& r) {
    for (const ElementBlock& b : _a.disc.blocks())
      if (b.kernel->has_mass()) return;
    _a.solver_warnings.push_back(fmt::format(
        "step {} (*DYNAMIC): no element of the model has mass (no *DENSITY in the materials of its "
        "elements, no MASS, ROTARY INERTIA or mass matrix), so the step has no inertia and each "
        "increment is a static solution at its time; give the materials *DENSITY for a dynamic "
        "response",
        r.step->number));
  }

  /// *INITIAL CONDITIONS, TYPE=VELOCITY / ROTATING VELOCITY into the committed velocities (the
  /// analysis's first step): a transformed node's components are in its own system.
  void initial_velocities(std::span<const std::uint8_t> prescribed) {
    const Model& m = _a.model;
    if (m.initial_velocities.empty()) return;
    SolutionState& st = _a.st;
    const DofMap& dofs = _a.disc.dofs();
    st.v_start.assign(st.u.size(), 0.0);
    for (const Model::InitialVelocity& iv : m.initial_velocities) {
      const auto axes = iv.global ? std::nullopt : m.node_axes(iv.node);
      const int base = iv.dof <= 3 ? 0 : 3, i = iv.dof - 1 - base;
      for (int j = 0; j < 3; ++j) { // v_global = Q^T v_local
        const double c = axes ? (*axes)[3 * i + j] : (i == j ? 1.0 : 0.0);
        if (c == 0.0) continue;
        const LocalIndex s = dofs.slot(iv.node, static_cast<DofType>(base + j));
        if (s >= 0) st.v_start[s] += c * iv.value;
      }
    }
    for (std::size_t s = 0; s < st.v_start.size() && s < prescribed.size(); ++s)
      if (prescribed[s]) st.v_start[s] = 0.0; // a boundary condition prescribes the motion there
    st.v = st.v_start;
  }

  double _amax = 0.0;
  double _etotal_start = 0.0; ///< ETOTAL at the step start
  double _scale = 0.0;        ///< the largest energy of the step so far
  std::vector<std::int64_t> released_rows(StepRun& r) const;
  /// At the committed state: ALLFD (the gaps' accumulated frictional dissipation), their contact
  /// damping work and ALLAE (the hourglass-controlled elements'), which ALLSE leaves out.
  void recover_energies(StepRun& r) const;
  double _lost = 0.0; ///< kinetic energy removed by impacts in the step
  int _easy = 0;      ///< consecutive increments with a half-increment residual below 0.75 HAFTOL
  std::vector<std::int64_t> _active;   ///< the exact constraint rows active at the last commit
  std::vector<std::int64_t> _released; ///< rows released at the start of this increment

  /// The multiplier ids of the exact rows of a constraint block, sorted.
  static std::vector<std::int64_t> exact_rows_of(const ConstraintBlock& C) {
    std::vector<std::int64_t> ids;
    for (int r = 0; r < C.n_rows(); ++r)
      if (C.compliance[r] == 0.0) ids.push_back(C.multiplier[r]);
    std::sort(ids.begin(), ids.end());
    return ids;
  }
};

/// An increment in which exact rows (hard gaps) became active is an impact: velocities and
/// accelerations are made compatible with them (StepProblem::impact; docs/theory/dynamics.md).
void DynamicProcedure::accepted(StepRun& r, double dt) {
  recover_energies(r);
  std::vector<std::int64_t> now = exact_rows_of(r.prob->constraints());
  std::vector<std::int64_t> closed; // the exact rows that became active: an impact
  std::set_difference(now.begin(), now.end(), _active.begin(), _active.end(),
                      std::back_inserter(closed));
  _active = std::move(now);
  if (!closed.empty()) {
    const double t = r.ctrl->step_time() + dt;
    const double lost = r.prob->impact(*_a.solver, t, closed);
    _lost += lost;
    log::debug("  impact at step time {:.6g}: kinetic energy {:.4g} removed", t, lost);
  } else if (!_released.empty()) {
    const double gained = r.prob->book_release();
    log::debug("  release: the increment's imbalance {:.4g} booked with the contacts (ALLKL)",
               gained);
  }
  _released.clear();
  _scale = std::max(_scale, _a.st.energies().scale());
}

void DynamicProcedure::recover_energies(StepRun& r) const {
  SolutionState& st = _a.st;
  const FieldView fields = r.prob->fields();
  ElementRecovery rec;
  double friction = 0.0, damping = 0.0, artificial = 0.0;
  for (const ElementBlock& b : _a.disc.blocks()) {
    const ElementTypeInfo& info = element_info(b.type);
    const bool gap = info.family == ElementFamily::Gap && info.displacement;
    if (!gap && !b.kernel->has_artificial_energy()) continue;
    for (std::size_t i = 0; i < b.size(); ++i) {
      _a.assembler.recover(b.elements[i], fields, r.prob->context(), rec);
      artificial += rec.artificial_energy.value_or(0.0);
      if (!rec.gap) continue;
      friction += rec.gap->dissipation;
      damping += rec.gap->damping_work;
    }
  }
  st.allfd = friction;
  st.contact_damping = damping;
  st.allae = artificial;
}

/// The step's energy balance (docs/theory/dynamics.md, "Energies"): ETOTAL's change over the step
/// against the largest energy of the step; the trapezoidal rule conserves, HHT with alpha < 0 and
/// backward Euler dissipate.
void DynamicProcedure::finish(StepRun& r) {
  StepChecks& c = r.sum.checks;
  c.dynamic = true;
  c.energies = _a.st.energies();
  c.energy_change = c.energies.etotal() - _etotal_start;
  c.energy_scale = std::max(_scale, c.energies.scale());
  const DynamicSettings& d = r.step->dynamic;
  c.conserving = d.hht && d.alpha == 0.0 && d.beta == 0.25 && d.gamma == 0.5;
  // the integrators conserve (trapezoidal) or dissipate: a gain beyond the tolerances means an
  // input that feeds energy the balance does not see, or an increment too large for the physics
  if (c.energy_scale > 0.0 && c.energy_change > kEnergyGainTolerance * c.energy_scale)
    _a.solver_warnings.push_back(fmt::format(
        "step {}: the energy balance ETOTAL grew by {:.3g} ({:.2e} of the largest energy {:.4g}) "
        "although the time integrator only conserves or dissipates energy; check the increment "
        "size (a smaller time increment or HAFTOL) and the loads' amplitudes",
        r.step->number, c.energy_change, c.energy_change / c.energy_scale, c.energy_scale));
}

/// The exact rows of gaps that the converged increment opened while they held a force at its
/// start (the gaps' normal and friction rows, sorted): HHT's trapezoid let that force work over
/// the opening; the release is put at the increment's start and the increment solved again
/// (StepProblem::release_contacts, docs/theory/dynamics.md "Impact").
std::vector<std::int64_t> DynamicProcedure::released_rows(StepRun& r) const {
  const std::vector<std::int64_t> now = exact_rows_of(r.prob->constraints());
  std::vector<std::int64_t> opened; // the normals that held a compressive force
  for (const std::int64_t m : _active)
    if (_a.disc.is_contact_normal(m) && _a.disc.multiplier_committed(m) > 0.0 &&
        !std::binary_search(now.begin(), now.end(), m))
      opened.push_back(m);
  std::vector<std::int64_t> rows;
  if (opened.empty()) return rows;
  for (const std::int64_t m : _active)
    if (std::binary_search(opened.begin(), opened.end(), _a.disc.contact_normal_of(m)))
      rows.push_back(m);
  return rows;
}

/// HAFTOL: the half-increment residual against the tolerance. Above it the increment is redone
/// with 0.85 HAFTOL / residual of its size; after three increments in a row below 0.75 HAFTOL the
/// next may grow by 0.8 HAFTOL / residual, at most 1.25 (docs/theory/dynamics.md).
IncrementAccuracy DynamicProcedure::check_accuracy(StepRun& r, const IncrementInfo& info,
                                                   double dt) {
  if (r.step->dynamic.hht && !_active.empty()) { // before HAFTOL: the increment is solved again
    const std::vector<std::int64_t> rows = released_rows(r);
    if (!rows.empty()) {
      // the rows released before in this increment stay released (without their forces, the
      // accelerations' solve gave them back a force, and they opened again: a cycle)
      std::vector<std::int64_t> all;
      std::set_union(_released.begin(), _released.end(), rows.begin(), rows.end(),
                     std::back_inserter(all));
      _released = std::move(all);
      r.prob->release_contacts(*_a.solver, info.step_time - dt, _released);
      log::debug("  increment {}: {} hard contact row(s) released at its start; solved again",
                 info.increment, rows.size());
      IncrementAccuracy out;
      out.redo = true;
      out.check = "hard contact released at the increment start";
      return out;
    }
  }
  const auto& haftol = r.step->dynamic.haftol;
  if (!haftol) return {};
  const double res = r.prob->half_increment_residual(info.step_time - dt, dt);
  IncrementAccuracy out;
  out.growth = 1.0;
  out.check = "HAFTOL exceeded";
  if (res < 0.0) return out; // backward Euler: no half-step rule
  const double ratio = res > 0.0 ? *haftol / res : 1e30;
  if (ratio < 1.0) {
    _easy = 0;
    out.redo = r.ctrl->retry_smaller(std::max(0.85 * ratio, 0.25));
    if (out.redo)
      log::progress("  increment {} attempt {}: half-increment residual {:.4g} exceeds HAFTOL "
                    "{:.4g}; repeating it with a time increment of {:.4g}",
                    info.increment, info.attempts, res, *haftol, r.ctrl->next());
    return out;
  }
  _easy = ratio > 1.0 / 0.75 ? _easy + 1 : 0;
  if (_easy >= 3) out.growth = std::min(1.25, 0.8 * ratio);
  return out;
}

} // namespace

std::unique_ptr<StepProcedure> make_dynamic_procedure(Analysis::Impl& a) {
  return std::make_unique<DynamicProcedure>(a);
}

} // namespace gapfem
