#include "solver/analysis.hpp"

#include "common/error.hpp"
#include "common/log.hpp"
#include "fem/assembler.hpp"
#include "fem/discretization.hpp"
#include "linalg/kkt_solver.hpp"
#include "model/model.hpp"
#include "solver/diagnostics.hpp"
#include "solver/increment_control.hpp"
#include "solver/newton.hpp"
#include "solver/stabilization.hpp"
#include "solver/step_problem.hpp"
#include "solver/thermal_step.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <new>
#include <numeric>
#include <set>
#include <string>

namespace gapfem {

long peak_memory_kb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::atol(line.c_str() + 6);
  return 0;
}

namespace {
/// Newton's controls from a step's *CONTROLS.
NewtonControls newton_controls(const SolutionControls& sc, FactorReuse reuse) {
  NewtonControls c;
  for (int f = 0; f < kNumFields; ++f) {
    const SolutionControls::Field& in = sc.field[f];
    NewtonControls::Field& out = c.field[f];
    out.residual_ratio = in.residual;
    out.correction_ratio = in.correction;
    out.linear_ratio = in.linear;
    out.zero_flux_ratio = in.zero_flux;
    out.initial_flux = in.initial_flux;
    out.user_flux = in.user_flux;
  }
  c.divergence_check_after = sc.divergence_check_after;
  c.max_equilibrium_iterations = sc.max_iterations;
  c.max_severe_iterations = sc.max_severe_iterations;
  c.factor_reuse = reuse;
  return c;
}
} // namespace

struct Analysis::Impl {
  const Model& model;
  std::vector<ResultWriter*> writers;
  Discretization disc;
  Assembler assembler;
  KktSolver kkt;
  SolutionState st;
  LoadHistory history;
  RunStatistics stats;
  std::vector<StepSummary> summaries;
  /// warnings found while solving (they join the deck's in every results file and the summary)
  std::vector<std::string> solver_warnings;
  Stopwatch watch;
  bool has_temperature_dofs = false;
  AnalysisOptions options;

  Impl(const Model& m, std::vector<ResultWriter*> w, AnalysisOptions o)
      : model(m), writers(std::move(w)), disc(m),
        assembler(disc, o.threads > 0 ? o.threads : default_thread_count()), options(o) {
    const LocalIndex ns = disc.dofs().n_slots();
    st.u.assign(static_cast<std::size_t>(ns), 0.0);
    set_initial_temperatures(m, disc.dofs(), st.u);
    st.u_start = st.u;
    st.f_int = st.u;
    st.f_ext = st.u;
    st.T_initial = m.initial_temperature;
    st.T_initial.resize(static_cast<std::size_t>(m.mesh.n_nodes()), 0.0);
    st.T = st.T_start = st.T_initial;
    check_step_procedures(m);
    for (LocalIndex s = 0; s < ns; ++s) has_temperature_dofs |= disc.dofs().slot_is_temperature(s);
  }

  StepSummary run_step(int index);
  /// The sparsity pattern of a step's equations (elements and active constraint rows).
  std::shared_ptr<const SparsityPattern> step_pattern(const StepLoads& loads);
  /// Gap counts by type and status at the reference configuration (gapfem check).
  void initial_gap_status(ModelCheck& c);
  /// Is the stiffness at the committed state (step time t0) non-singular? Used to tell a limit
  /// point or crushed element (singular only in the increment) from a missing support.
  bool supported_at_last_converged(StepProblem& prob, double t0);
  /// Largest |damping force| of the gaps at the current state (0 when no gap has damping).
  double damping_peak(StepProblem& prob);
  /// IncrementInfo::gaps and gaps_closed from the committed state, for writers that want them.
  void gap_samples(StepProblem& prob, IncrementInfo& info);
  bool want_gap_samples = false;
  double step_damping_peak = 0.0;
  /// Automatic stabilization: M* (built once), and what CONTINUE=YES hands to the next step.
  std::shared_ptr<const std::vector<double>> unit_mass;
  Stabilization carried_stabilization;
  double carried_factor = 0.0;
  void write_frame(int index, StepProblem& prob, int increment, bool last, double dt);
  /// The *MONITOR value after a converged increment, when due.
  std::optional<double> monitor_value(const Step& step, int increment, bool last) const;
  /// Nodal vectors at *TRANSFORM nodes in their local systems; reactions from the multipliers of
  /// the boundary conditions given there.
  void to_local_systems(NodeResults& nr) const;
  StepChecks checks(StepProblem& prob);
};

Analysis::Analysis(const Model& model, std::vector<ResultWriter*> writers, AnalysisOptions options)
    : _impl(std::make_unique<Impl>(model, std::move(writers), options)) {}
Analysis::~Analysis() = default;

const std::vector<StepSummary>& Analysis::step_summaries() const {
  return _impl->summaries;
}

RunSummary Analysis::run() {
  Impl& m = *_impl;
  for (auto* w : m.writers) m.want_gap_samples |= w->wants_gap_samples();
  for (auto* w : m.writers) w->begin(m.model);
  RunSummary run;
  for (int i = 0; i < static_cast<int>(m.model.steps.size()); ++i) {
    StepSummary s;
    // Failures outside an increment (setting the step up) stop the run; the writers still close
    // their files, so job.results.json stays valid JSON with "completed": false.
    try {
      s = m.run_step(i);
    } catch (const AnalysisError& e) {
      s.converged = false;
      s.failure = e.what();
    } catch (const std::bad_alloc&) {
      s.converged = false;
      s.failure = "out of memory setting the step up; use a coarser mesh or run on a machine with "
                  "more memory";
    }
    s.step = m.model.steps[i].number;
    s.name = m.model.steps[i].name;
    m.summaries.push_back(s);
    if (!s.converged) {
      run.completed = false;
      run.failure = fmt::format("step {}: {}", s.step, s.failure);
      break;
    }
  }
  run.wall_seconds = m.watch.seconds();
  run.stats = m.stats;
  run.warnings = m.model.warnings;
  run.warnings.insert(run.warnings.end(), m.solver_warnings.begin(), m.solver_warnings.end());
  run.peak_memory_kb = peak_memory_kb();
  // Every writer closes its files, even after another failed (e.g. a full disk): the first
  // failure is the one reported.
  for (auto* w : m.writers) {
    try {
      w->end(m.model, run);
    } catch (const AnalysisError& e) {
      if (run.completed) run.failure = e.what();
      run.completed = false;
    }
  }
  if (!run.completed) throw AnalysisError(run.failure);
  return run;
}

bool Analysis::Impl::supported_at_last_converged(StepProblem& prob, double t0) {
  prob.begin_increment(t0, 0.0);
  try {
    const Evaluation ev = prob.evaluate();
    std::vector<double> du(prob.rhs().size()),
        dl(static_cast<std::size_t>(prob.constraints().n_rows()));
    KktOptions opt;
    opt.force_fresh = true;
    kkt.solve(prob.matrix(), prob.rhs(), prob.constraints(), du, dl, ev.symmetric, opt, &stats);
  } catch (const SingularSystem&) {
    return false;
  } catch (const ConvergenceFailure&) {
    return false;
  }
  return true;
}

void Analysis::Impl::to_local_systems(NodeResults& nr) const {
  if (model.transforms.empty()) return;
  const ConstraintSet& rows = disc.constraints();
  auto rotate = [](const std::array<double, 9>& Q, Vec3& v) {
    const Vec3 g = v;
    for (int i = 0; i < 3; ++i) v[i] = Q[3 * i] * g[0] + Q[3 * i + 1] * g[1] + Q[3 * i + 2] * g[2];
  };
  for (NodeId n = 0; n < static_cast<NodeId>(model.node_transform.size()); ++n) {
    const auto Q = model.node_axes(n);
    if (!Q) continue;
    nr.local_axes[n] = *Q;
    for (auto* v : {&nr.U, &nr.UR, &nr.CF, &nr.CM}) rotate(*Q, (*v)[n]);
    for (int d = 1; d <= 6; ++d) {
      const int r = rows.bc_row(n, d);
      const double reaction = r >= 0 && rows.active(r) ? -rows.mult_committed[r] : 0.0;
      (d <= 3 ? nr.RF[n][d - 1] : nr.RM[n][d - 4]) = reaction;
    }
  }
}

std::shared_ptr<const SparsityPattern> Analysis::Impl::step_pattern(const StepLoads& loads) {
  ScopedTimer t(&stats, TimeCategory::Assembly);
  std::vector<std::span<const LocalIndex>> lists;
  for (const auto& b : disc.blocks())
    for (std::size_t i = 0; i < b.size(); ++i) lists.push_back(b.element_eqs(i));
  // a constraint row couples its DOFs (the KKT augmentation C^T R C lies inside its block)
  const ConstraintSet& cs = disc.constraints();
  for (int r = 0; r < cs.n_rows(); ++r)
    if (cs.active(r)) lists.push_back(cs.row_eqs(r));
  return build_pattern(loads.equations().n_eq(), lists);
}

ModelCheck Analysis::check() {
  Impl& m = *_impl;
  ModelCheck c;
  c.dofs = m.disc.dofs().n_slots();
  for (int i = 0; i < static_cast<int>(m.model.steps.size()); ++i) {
    const Step& step = m.model.steps[i];
    StepLoads loads(m.model, m.disc, i, m.history, m.st.u_start, m.st.total_time);
    m.solver_warnings.insert(m.solver_warnings.end(), loads.warnings().begin(),
                             loads.warnings().end());
    m.disc.set_equations(loads.equations(), loads.local_bcs());
    const auto pattern = m.step_pattern(loads);
    auto cholmod = make_cholmod_solver();
    cholmod->analyze(*pattern);
    ModelCheck::StepInfo s;
    s.number = step.number;
    s.name = step.name;
    s.procedure = std::string(procedure_name(step.procedure));
    s.equations = loads.equations().n_eq();
    const ConstraintSet& cs = m.disc.constraints();
    for (int r = 0; r < cs.n_rows(); ++r) s.constraint_rows += cs.active(r) ? 1 : 0;
    s.factor_bytes = cholmod->factor_bytes();
    c.steps.push_back(s);
    if (i == 0) m.initial_gap_status(c);
  }
  return c;
}

void Analysis::Impl::initial_gap_status(ModelCheck& c) {
  // the gaps' own recovery at the reference configuration, before any load
  const std::vector<double> T0 = st.T_initial;
  const FieldView fields{st.u, st.u, T0, T0, T0, {}};
  StepContext ctx;
  ctx.space = model.space;
  ctx.model_size = model.model_size();
  ctx.constants = &model.constants;
  ElementRecovery rec;
  for (ElemId e = 0; e < model.mesh.n_elements(); ++e) {
    const auto& info = element_info(model.mesh.elem_types[e]);
    if (info.family != ElementFamily::Gap) continue;
    auto it = std::find_if(c.gaps.begin(), c.gaps.end(),
                           [&](const ModelCheck::GapInfo& g) { return g.type == info.name; });
    if (it == c.gaps.end()) it = c.gaps.insert(c.gaps.end(), {std::string(info.name)});
    ++it->total;
    rec.clear();
    assembler.recover(e, fields, ctx, rec);
    if (rec.gap && rec.gap->status != ContactStatus::Open)
      ++it->closed;
    else
      ++it->open;
  }
}

StepSummary Analysis::Impl::run_step(int index) {
  const Step& step = model.steps[index];
  StepLoads loads(model, disc, index, history, st.u_start, st.total_time);
  solver_warnings.insert(solver_warnings.end(), loads.warnings().begin(), loads.warnings().end());
  disc.set_equations(loads.equations(), loads.local_bcs());
  const std::shared_ptr<const SparsityPattern> pattern = step_pattern(loads);
  kkt.analyze(pattern);

  StepContext base;
  base.procedure = step.procedure;
  base.nlgeom = step.nlgeom;
  base.transient = !step.inc.steady_state && step.procedure != Procedure::Static;
  base.step_period = loads.period();
  base.space = model.space;
  base.model_size = model.model_size();
  base.constants = &model.constants;
  base.step_index = index;
  base.symmetric_only = step.symmetric_only;
  StepProblem prob(disc, assembler, loads, st, base, pattern);
  prob.set_unsymmetric_loads(step.unsymmetric);
  prob.set_statistics(&stats);
  prob.begin_increment(0.0, 0.0);
  prob.compute_stiffness_hints();
  const Stabilization* stab = nullptr;
  if (step.procedure == Procedure::Static)
    stab = step.stabilize.on ? &step.stabilize
                             : (carried_stabilization.on ? &carried_stabilization : nullptr);
  double stab_c0 = 0.0;
  if (stab) {
    if (!unit_mass)
      unit_mass = std::make_shared<const std::vector<double>>(
          unit_density_mass(disc, assembler, prob.fields(), prob.context()));
    if (step.stabilize.on) {
      const std::vector<double> diag =
          assembler.diagonal_stiffness(prob.fields(), prob.context(), /*skip_gaps=*/true);
      const double dt0 = step.inc.initial > 0 ? step.inc.initial : loads.period();
      stab_c0 = initial_stabilization_factor(*stab, dt0, *unit_mass, diag);
    } else {
      stab_c0 = carried_factor;
    }
    prob.set_stabilization(unit_mass, stab_c0);
    log::progress("  automatic stabilization: damping factor {:.4g}{}", stab_c0,
                  stab->allsdtol > 0 ? fmt::format(" (adaptive, ALLSDTOL {:.3g})", stab->allsdtol)
                                     : std::string());
  }

  // SHRINK fits take the element's own overclosure at the start of the step.
  if (!loads.shrink_elements().empty()) {
    prob.begin_increment(0.0, 0.0);
    ElementRecovery rec;
    for (ElemId e : loads.shrink_elements()) {
      assembler.recover(e, prob.fields(), prob.context(), rec);
      const double h = rec.gap ? rec.gap->clearance : 0.0;
      const_cast<StepLoads&>(loads).set_shrink_allowance(e, std::max(-h, 0.0));
    }
  }

  for (auto* w : writers) w->begin_step(model, index);
  log::progress("Step {} ({}){}: {} equations, {} elements", step.number,
                procedure_name(step.procedure), step.nlgeom ? ", NLGEOM" : "",
                loads.equations().n_eq(), model.mesh.n_elements());
  StepSummary sum;
  sum.step = step.number;
  sum.name = step.name;
  sum.procedure = std::string(procedure_name(step.procedure));
  IncrementRules rules = increment_rules(step.controls);
  if (fixed_transient_increments(step)) rules.growth = rules.shrink = 1.0;
  IncrementController ctrl(step.inc, step.max_increments, rules);
  HeatBalance heat(has_temperature_dofs && step.procedure != Procedure::Static, base.transient,
                   st.u_start);
  FluxHistory flux;
  const NewtonControls controls = newton_controls(step.controls, options.factor_reuse);
  step_damping_peak = 0.0;
  std::vector<double> converged_f_int, converged_f_ext;
  std::string last_problem;
  AttemptLog attempts_log;
  while (!ctrl.finished()) {
    if (ctrl.increment() >= step.max_increments) {
      sum.converged = false;
      sum.failure = fmt::format("the step needs more than {} increments; raise INC on *STEP "
                                "(step time reached {:.6g} of {:.6g})",
                                step.max_increments, ctrl.step_time(), ctrl.period());
      break;
    }
    const double t0 = ctrl.step_time();
    const double dt = ctrl.next();
    prob.begin_increment(t0, dt);
    NewtonResult res;
    // A failure no smaller increment can cure (the linear solver out of memory, an output file
    // that cannot be written) ends the step like a convergence failure, so the result files are
    // complete up to the last converged increment.
    try {
      res = solve_increment(prob, kkt, controls, flux, &stats);
    } catch (const AnalysisError& e) {
      sum.converged = false;
      sum.failure = e.what();
      break;
    } catch (const std::bad_alloc&) {
      sum.converged = false;
      sum.failure = fmt::format("out of memory at step time {:.6g} solving {} equations; use a "
                                "coarser mesh or run on a machine with more memory",
                                t0 + dt, loads.equations().n_eq());
      break;
    }
    ++stats.attempts;
    ++sum.attempts;
    sum.iterations += res.iterations;
    IncrementInfo info;
    info.step = step.number;
    info.increment = ctrl.increment() + 1;
    info.attempts = ctrl.attempt() + 1;
    info.iterations = res.iterations;
    info.severe_discontinuities = res.severe_iterations;
    info.step_time = t0 + dt;
    info.total_time = st.total_time + t0 + dt;
    info.dt = dt;
    info.converged = res.converged;
    info.residual_history = res.residual_history;
    // Transient heat transfer: DELTMX bounds the temperature change of an increment.
    double growth = 0.0;
    bool redo = false;
    if (res.converged && base.transient && step.inc.deltmx > 0.0) {
      const double dT =
          max_free_temperature_change(disc.dofs(), loads.equations(), st.u, st.u_start);
      const TemperatureAccuracy acc = deltmx_rule(dT, step.inc.deltmx, rules.deltmx_cutback);
      growth = acc.ratio;
      redo = acc.redo && ctrl.retry_smaller(acc.ratio);
      if (redo)
        log::progress("  increment {} attempt {}: temperature change {:.4g} exceeds DELTMX {:.4g}; "
                      "repeating it with a time increment of {:.4g}",
                      info.increment, info.attempts, dT, step.inc.deltmx, ctrl.next());
    }
    info.converged = res.converged && !redo;
    info.deltmx_exceeded = redo;
    // A converged increment is reported after its frame is written, so that what the .sta and
    // the terminal call converged is already in the result files (docs/results.md).
    if (!info.converged)
      for (auto* w : writers) w->increment(info);
    if (redo) continue;
    if (res.converged) {
      attempts_log.clear();
      prob.commit();
      if (stab)
        prob.set_stabilization(
            unit_mass,
            adapted_stabilization_factor(*stab, prob.stabilization_factor(), st.allsd, st.allie));
      converged_f_int = st.f_int;
      converged_f_ext = st.f_ext;
      for (int f = 0; f < kNumFields; ++f) flux.sum[f] += res.flux[f];
      ++flux.n;
      ctrl.accept(res.iterations - res.severe_iterations, growth);
      heat.add_increment(disc.dofs(), dt, prob.reactions(), st.f_ext);
      ++stats.increments;
      ++sum.increments;
      step_damping_peak = std::max(step_damping_peak, damping_peak(prob));
      write_frame(index, prob, ctrl.increment(), ctrl.finished(), dt);
      info.monitor = monitor_value(step, ctrl.increment(), ctrl.finished());
      if (want_gap_samples && disc.has_gaps()) gap_samples(prob, info);
      {
        ScopedTimer timer(&stats, TimeCategory::Output); // the JSON checkpoint is output time
        for (auto* w : writers) w->increment(info);
      }
      continue;
    }
    // Failed attempt: explain, cut back or stop.
    std::string kind = std::to_string(static_cast<int>(res.cause));
    if (res.singular) {
      const bool supported = supported_at_last_converged(prob, t0);
      last_problem =
          describe_singularity(model, disc, assembler, prob, res.singular_equations, supported);
      // A model without gaps whose stiffness is singular from the start cannot be cured by a
      // smaller increment; one that became singular in the increment may be (a limit point).
      if (!disc.has_gaps() && !supported) {
        sum.converged = false;
        sum.failure = last_problem;
        break;
      }
    } else if (!res.chattering.empty()) {
      last_problem = describe_chattering(model, res.chattering);
    } else {
      last_problem = res.reason;
      // repeats of one element's failure are one cause ("element 12: ...")
      if (res.cause == FailureCause::Element)
        kind += last_problem.substr(0, last_problem.find(':'));
    }
    const bool structural =
        res.singular || !res.chattering.empty() || res.cause == FailureCause::Element;
    attempts_log.add(info.increment, info.attempts, kind, last_problem, structural);
    if (stab && prob.stabilization_factor() < 1e3 * stab_c0) // more damping for the retry
      prob.set_stabilization(unit_mass, 2.0 * prob.stabilization_factor());
    log::progress("  increment {} attempt {} did not converge: {}", info.increment, info.attempts,
                  last_problem);
    if (!ctrl.reject()) {
      sum.converged = false;
      sum.failure = ctrl.failure() + ". " + attempts_log.summary();
      break;
    }
  }
  if (!sum.converged) {
    // Report the last converged state as the step's final frame, with the forces (reactions,
    // capacity terms) of its converged evaluation.
    prob.begin_increment(ctrl.step_time(), 0.0);
    if (!converged_f_int.empty()) {
      st.f_int = converged_f_int;
      st.f_ext = converged_f_ext;
    } else {
      try {
        prob.evaluate();
      } catch (const ConvergenceFailure&) {
      }
    }
    write_frame(index, prob, ctrl.increment(), true, 0.0);
  } else {
    loads.finish(ctrl.period(), prob.reactions(), disc.constraints(), history);
  }
  sum.checks = checks(prob);
  heat.finish(disc, prob.context(), st.u_start, prob.reactions(), st.f_ext, sum.checks);
  sum.checks.max_damping_force = std::max(sum.checks.max_damping_force, step_damping_peak);
  sum.checks.allie = st.allie;
  if (stab) {
    sum.checks.stabilized = true;
    sum.checks.stabilization_factor = prob.stabilization_factor();
    sum.checks.allsd = st.allsd;
    sum.checks.allie = st.allie;
    if (stab->allsdtol > 0 && st.allie > 0 && st.allsd > stab->allsdtol * st.allie)
      solver_warnings.push_back(
          fmt::format("step {}: the stabilization dissipated {:.3g} of the internal energy "
                      "(ALLSD {:.4g}, ALLIE {:.4g}), more than ALLSDTOL {:.3g}; check that the "
                      "damping does not change the answer",
                      step.number, st.allsd / st.allie, st.allsd, st.allie, stab->allsdtol));
  }
  carried_stabilization = stab && stab->carry ? *stab : Stabilization{};
  carried_factor = stab ? prob.stabilization_factor() : 0.0;
  for (auto* w : writers) w->end_step(model, index, sum);
  st.total_time += ctrl.step_time();
  return sum;
}

std::optional<double> Analysis::Impl::monitor_value(const Step& step, int increment,
                                                    bool last) const {
  if (!step.monitor) return std::nullopt;
  const DofMonitor& m = *step.monitor;
  if (!last && (m.frequency <= 0 || increment % m.frequency != 0)) return std::nullopt;
  DofType d{};
  if (!dof_from_abaqus(m.dof, d)) return std::nullopt;
  const LocalIndex s = disc.dofs().slot(m.node, d);
  if (s < 0) return std::nullopt; // the node does not carry the DOF: a blank column
  return st.u_start[static_cast<std::size_t>(s)];
}

void Analysis::Impl::write_frame(int index, StepProblem& prob, int increment, bool last,
                                 double dt) {
  const Step& step = model.steps[index];
  auto due = [&](int freq) { return freq > 0 && (increment % freq == 0 || last); };
  Frame fr;
  fr.step = step.number;
  fr.increment = increment;
  fr.step_time = prob.context().step_time;
  fr.total_time = prob.context().total_time;
  fr.dt = dt;
  fr.last_in_step = last;
  bool any = last;
  for (const auto& r : step.node_prints) {
    fr.node_print_due.push_back(due(r.frequency));
    any |= fr.node_print_due.back();
  }
  for (const auto& r : step.el_prints) {
    fr.el_print_due.push_back(due(r.frequency));
    any |= fr.el_print_due.back();
  }
  bool field_elements = false;
  if (step.field_outputs.empty()) {
    fr.field_due = last;
  } else {
    for (const auto& r : step.field_outputs) {
      fr.field_output_due.push_back(due(r.frequency));
      if (fr.field_output_due.back()) {
        fr.field_due = true;
        field_elements |= !r.elem_vars.empty();
      }
    }
  }
  any |= fr.field_due;
  for (const auto& r : step.file_outputs) {
    fr.file_output_due.push_back(due(r.frequency));
    any |= fr.file_output_due.back();
  }
  if (!any) return;
  ScopedTimer timer(&stats, TimeCategory::Output);

  const DofMap& dofs = disc.dofs();
  const NodeId nn = model.mesh.n_nodes();
  NodeResults& nr = fr.nodes;
  nr.U.assign(nn, Vec3{});
  nr.UR = nr.RF = nr.RM = nr.CF = nr.CM = nr.U;
  nr.NT.assign(nn, 0.0);
  nr.RFL = nr.CFL = nr.NT;
  nr.temperature_points = std::max(1, dofs.max_temperature_points());
  const std::size_t more = static_cast<std::size_t>(nr.temperature_points - 1);
  nr.NT_more.assign(more * static_cast<std::size_t>(nn), 0.0);
  nr.RFL_more = nr.CFL_more = nr.NT_more;
  nr.dof_mask.resize(nn);
  const std::vector<double> reaction = prob.reactions();
  const std::vector<double> cload = prob.concentrated_loads();
  for (LocalIndex s = 0; s < dofs.n_slots(); ++s) {
    const NodeId n = dofs.slot_node(s);
    const int d = static_cast<int>(dofs.slot_dof(s));
    const double u = st.u_start[s];
    if (d < 3) {
      nr.U[n][d] = u;
      nr.RF[n][d] = reaction[s];
      nr.CF[n][d] = cload[s];
      nr.any_displacement = true;
    } else if (d < 6) {
      nr.UR[n][d - 3] = u;
      nr.RM[n][d - 3] = reaction[s];
      nr.CM[n][d - 3] = cload[s];
      nr.any_rotation = true;
    } else if (d == static_cast<int>(DofType::NT)) {
      nr.NT[n] = u;
      nr.RFL[n] = reaction[s];
      nr.CFL[n] = cload[s];
      nr.any_temperature = true;
    } else { // DOF 12 … through a heat-transfer shell's thickness
      const std::size_t k = more * static_cast<std::size_t>(n) +
                            static_cast<std::size_t>(temperature_index(dofs.slot_dof(s)) - 1);
      nr.NT_more[k] = u;
      nr.RFL_more[k] = reaction[s];
      nr.CFL_more[k] = cload[s];
    }
  }
  for (NodeId n = 0; n < nn; ++n) nr.dof_mask[n] = dofs.mask(n);
  to_local_systems(nr);
  // Stress analyses report the predefined temperature field as NT.
  if (!nr.any_temperature && disc.has_temperature_field()) {
    nr.NT = st.T_start;
    nr.any_temperature = true;
    nr.nt_field.assign(static_cast<std::size_t>(nn), 0);
    for (const auto& b : disc.blocks())
      if (b.uses_temperature)
        for (ElemId e : b.elements)
          for (NodeId n : model.mesh.element_nodes(e)) nr.nt_field[n] = 1;
  }

  // Elements needed by the due requests (every element at the last frame).
  const ElemId ne = model.mesh.n_elements();
  std::vector<char> need(static_cast<std::size_t>(ne), last || field_elements ? 1 : 0);
  for (std::size_t k = 0; k < step.el_prints.size(); ++k) {
    if (!fr.el_print_due[k]) continue;
    const auto& r = step.el_prints[k];
    if (r.elset.empty())
      std::fill(need.begin(), need.end(), 1);
    else
      for (ElemId e : r.elements) need[e] = 1;
  }
  for (std::size_t k = 0; k < step.file_outputs.size(); ++k) {
    const auto& r = step.file_outputs[k];
    if (!fr.file_output_due[k] || !r.element) continue;
    if (r.set.empty())
      std::fill(need.begin(), need.end(), 1);
    else
      for (ElemId e : r.members) need[e] = 1;
  }
  fr.element_slot.assign(static_cast<std::size_t>(ne), -1);
  const FieldView fields = prob.fields();
  for (ElemId e = 0; e < ne; ++e) {
    if (!need[e]) continue;
    fr.element_slot[e] = static_cast<std::int32_t>(fr.elements.size());
    fr.elements.push_back({e, {}});
    assembler.recover(e, fields, prob.context(), fr.elements.back().data);
  }
  for (auto* w : writers) w->frame(model, index, fr);
}

double Analysis::Impl::damping_peak(StepProblem& prob) {
  bool any = false;
  for (const GapSection& g : model.gap_sections) any |= g.damping.given;
  if (!any) return 0.0;
  double peak = 0.0;
  ElementRecovery rec;
  const FieldView fields = prob.fields();
  for (auto& b : disc.blocks()) {
    if (element_info(b.type).family != ElementFamily::Gap) continue;
    for (std::size_t i = 0; i < b.size(); ++i) {
      assembler.recover(b.elements[i], fields, prob.context(), rec);
      if (rec.gap) peak = std::max(peak, std::abs(rec.gap->damping_force));
    }
  }
  return peak;
}

void Analysis::Impl::gap_samples(StepProblem& prob, IncrementInfo& info) {
  ScopedTimer timer(&stats, TimeCategory::Output);
  ElementRecovery rec;
  const FieldView fields = prob.fields();
  int closed = 0;
  for (auto& b : disc.blocks()) {
    if (element_info(b.type).family != ElementFamily::Gap) continue;
    for (std::size_t i = 0; i < b.size(); ++i) {
      assembler.recover(b.elements[i], fields, prob.context(), rec);
      if (!rec.gap) continue;
      info.gaps.push_back({b.elements[i], static_cast<float>(rec.gap->normal_force),
                           static_cast<float>(rec.gap->clearance), rec.gap->status});
      closed += rec.gap->status != ContactStatus::Open;
    }
  }
  info.gaps_closed = closed;
}

StepChecks Analysis::Impl::checks(StepProblem& prob) {
  StepChecks c;
  const FieldView fields = prob.fields();
  ElementRecovery rec;
  for (auto& b : disc.blocks()) c.hourglass |= b.kernel->has_artificial_energy();
  if (c.hourglass) // ALLAE and, to judge it, ALLSE of every continuum element
    for (auto& b : disc.blocks()) {
      const ElementTypeInfo& info = element_info(b.type);
      if (info.family != ElementFamily::Continuum || !info.displacement) continue;
      for (std::size_t i = 0; i < b.size(); ++i) {
        assembler.recover(b.elements[i], fields, prob.context(), rec);
        c.allae += rec.artificial_energy.value_or(0.0);
        c.allse += rec.strain_energy.value_or(0.0);
      }
    }
  for (auto& b : disc.blocks()) {
    if (element_info(b.type).family != ElementFamily::Gap || !element_info(b.type).displacement)
      continue;
    for (std::size_t i = 0; i < b.size(); ++i) {
      assembler.recover(b.elements[i], fields, prob.context(), rec);
      if (!rec.gap) continue;
      const GapRecord& g = *rec.gap;
      ++c.n_gaps;
      const Label label = model.element_label(b.elements[i]).key;
      switch (g.status) {
      case ContactStatus::Open:
        ++c.n_open;
        break;
      case ContactStatus::Closed:
        ++c.n_closed;
        break;
      case ContactStatus::Stick:
        ++c.n_stick;
        break;
      case ContactStatus::Slip:
        ++c.n_slip;
        break;
      }
      const double allowance = b.interference.empty() ? 0.0 : b.interference[i];
      const double pen = -(g.clearance + allowance);
      if (g.status != ContactStatus::Open && pen > c.max_penetration) {
        c.max_penetration = pen;
        c.max_penetration_elem = label;
      }
      if (g.status != ContactStatus::Open && -g.normal_force > c.max_tensile_force) {
        c.max_tensile_force = -g.normal_force;
        c.max_tensile_elem = label;
      }
      c.max_damping_force = std::max(c.max_damping_force, std::abs(g.damping_force));
    }
  }
  // Equilibrium: reactions + applied loads + forces of springs to ground.
  const DofMap& dofs = disc.dofs();
  const std::vector<double> reaction = prob.reactions();
  double scale = 0.0;
  for (LocalIndex s = 0; s < dofs.n_slots(); ++s) {
    const int d = static_cast<int>(dofs.slot_dof(s));
    if (d >= 3) continue;
    c.reaction_sum[d] += reaction[s];
    c.applied_sum[d] += st.f_ext[s];
    scale += std::abs(reaction[s]) + std::abs(st.f_ext[s]);
  }
  // reactions of boundary conditions in local systems: -lambda along each held local axis
  const ConstraintSet& rows = disc.constraints();
  for (NodeId n = 0; n < static_cast<NodeId>(model.node_transform.size()); ++n) {
    const auto Q = model.node_axes(n);
    if (!Q) continue;
    for (int d = 0; d < 3; ++d) {
      const int row = rows.bc_row(n, d + 1);
      if (row < 0 || !rows.active(row)) continue;
      const double R = -rows.mult_trial[row];
      for (int j = 0; j < 3; ++j) c.reaction_sum[j] += R * (*Q)[3 * d + j];
      scale += std::abs(R);
    }
  }
  std::array<double, 3> ground{};
  // the stabilization's viscous forces hold the model like springs to ground
  const auto fstab = prob.stabilization_forces();
  for (std::size_t k = 0; k < fstab.size(); ++k) {
    const int d = static_cast<int>(dofs.slot_dof(static_cast<LocalIndex>(k)));
    if (d >= 3 || fstab[k] == 0.0) continue;
    ground[d] += fstab[k];
    scale += std::abs(fstab[k]);
  }
  std::vector<double> r;
  std::vector<LocalIndex> slots;
  for (auto& b : disc.blocks()) {
    if (b.type != ElementType::SPRING1) continue;
    for (std::size_t i = 0; i < b.size(); ++i) {
      assembler.element_residual(b.elements[i], fields, prob.context(), r, slots);
      for (std::size_t k = 0; k < r.size(); ++k) {
        const int d = static_cast<int>(dofs.slot_dof(slots[k]));
        if (d < 3) {
          ground[d] += r[k];
          scale += std::abs(r[k]);
        }
      }
    }
  }
  double err2 = 0.0;
  for (int d = 0; d < 3; ++d) {
    const double e = c.reaction_sum[d] + c.applied_sum[d] - ground[d];
    err2 += e * e;
  }
  c.equilibrium_error = std::sqrt(err2);
  c.force_scale = scale;
  return c;
}

} // namespace gapfem
