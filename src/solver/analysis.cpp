#include "solver/analysis.hpp"

#include "common/error.hpp"
#include "common/log.hpp"
#include "common/timer.hpp"
#include "fem/assembler.hpp"
#include "fem/discretization.hpp"
#include "fem/rigid_body_modes.hpp"
#include "linalg/kkt_solver.hpp"
#include "model/model.hpp"
#include "parallel/parallel.hpp"
#include "solver/analysis_impl.hpp"
#include "solver/diagnostics.hpp"
#include "solver/finite_check.hpp"
#include "solver/increment_control.hpp"
#include "solver/newton.hpp"
#include "solver/stabilization.hpp"
#include "solver/step_problem.hpp"
#include "solver/thermal_step.hpp"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <fmt/format.h>
#include <fstream>
#include <limits>
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

Analysis::Analysis(const Model& model, std::vector<ResultWriter*> writers, AnalysisOptions options)
    : _impl(std::make_unique<Impl>(model, std::move(writers), options)) {}
Analysis::~Analysis() = default;

const std::vector<StepSummary>& Analysis::step_summaries() const {
  return _impl->summaries;
}

namespace {
/// The backend the options name, from the registry (linalg's and parallel's backends).
std::unique_ptr<ConstrainedSolver> backend(const AnalysisOptions& o) {
  parallel::register_backends();
  const SolverBackend* b = find_solver_backend(o.solver);
  if (b && b->one_process && parallel::size() > 1)
    throw std::runtime_error(fmt::format("--solver {} solves on one process, but this run has "
                                         "several (mpirun): use --solver mumps or --solver "
                                         "iterative",
                                         o.solver));
  return make_constrained_solver(o.solver, o.kkt);
}
} // namespace

Analysis::Impl::Impl(const Model& m, std::vector<ResultWriter*> w, AnalysisOptions o)
    : model(m), writers(std::move(w)), disc(m, o.kernels),
      assembler(disc, o.threads > 0 ? o.threads : default_thread_count(o.ranks_here)),
      solver(backend(o)), options(std::move(o)) {
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
  kill_after_increments = options.kill_after_increments;
}

RunSummary Analysis::run() {
  Impl& m = *_impl;
  for (auto* w : m.writers) m.want_gap_samples |= w->wants_gap_samples();
  int first = 0;
  if (m.options.resume) {
    m.begin_resume();
    first = m.options.resume->record.step_index;
    m.resume_writers(first);
  } else {
    for (auto* w : m.writers) w->begin(m.model);
  }
  if (std::any_of(m.model.steps.begin(), m.model.steps.end(),
                  [](const Step& s) { return !s.recover_substructures.empty(); }))
    m.recoverer =
        std::make_unique<SubstructureRecoverer>(m.model, m.options.generation_deck_reader);
  m.open_restart_file();
  RunSummary run;
  for (int i = first; i < static_cast<int>(m.model.steps.size()); ++i) {
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
    const Evaluation ev = prob.evaluate(true);
    std::vector<double> du(prob.rhs().size()),
        dl(static_cast<std::size_t>(prob.constraints().n_rows()));
    KktOptions opt;
    opt.force_fresh = true;
    solver->solve(prob.matrix(), prob.rhs(), prob.constraints(), du, dl, ev.symmetric, opt, &stats);
  } catch (const SingularSystem&) {
    return false;
  } catch (const ConvergenceFailure&) {
    return false;
  }
  return true;
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
  for (const auto& pair : disc.matrix_terms().equation_pairs()) lists.push_back(pair);
  return build_pattern(loads.equations().n_eq(), lists);
}

ModelCheck Analysis::check(bool time_factorization) {
  Impl& m = *_impl;
  ModelCheck c;
  c.dofs = m.disc.dofs().n_slots();
  for (int i = 0; i < static_cast<int>(m.model.steps.size()); ++i) {
    const Step& step = m.model.steps[i];
    make_procedure(step, m)->check(step);
    StepLoads loads(m.model, m.disc, i, m.history, m.st.u_start, m.st.total_time);
    m.solver_warnings.insert(m.solver_warnings.end(), loads.warnings().begin(),
                             loads.warnings().end());
    m.disc.set_equations(loads.equations(), loads.local_bcs());
    const auto pattern = m.step_pattern(loads);
    m.solver->analyze(pattern);
    ModelCheck::StepInfo s;
    s.number = step.number;
    s.name = step.name;
    s.procedure = std::string(procedure_name(step.procedure));
    s.equations = loads.equations().n_eq();
    const ConstraintSet& cs = m.disc.constraints();
    for (int r = 0; r < cs.n_rows(); ++r) s.constraint_rows += cs.active(r) ? 1 : 0;
    s.factor_bytes = m.solver->factor_bytes_estimate();
    if (time_factorization && i == 0 && loads.equations().n_eq() > 0) {
      // the stiffness at the reference state, factorised on its own: the limit ratio's unit
      StepContext ctx;
      ctx.procedure = step.procedure;
      ctx.nlgeom = step.nlgeom;
      ctx.space = m.model.space;
      ctx.model_size = m.model.model_size();
      ctx.constants = &m.model.constants;
      ctx.step_number = step.number;
      StepProblem prob(m.disc, m.assembler, loads, m.st, ctx, pattern);
      prob.begin_increment(0.0, 0.0);
      prob.evaluate(true);
      // a model held by its gaps alone is singular here: a slightly stiffened diagonal costs the
      // same factorisation and completes it
      CsrMatrix K = prob.matrix();
      for (LocalIndex e = 0; e < K.n(); ++e) K.add(e, e, 1e-6 * std::abs(K.diagonal(e)) + 1e-300);
      // through the seam: the factorisation alone is timed (its symbolic analysis is not)
      s.factor_seconds = std::numeric_limits<double>::infinity();
      const ConstraintBlock no_rows;
      for (int k = 0; k < 2; ++k) {
        RunStatistics timed;
        try {
          m.solver->factorize(K, no_rows, true, &timed);
        } catch (const SingularSystem&) { // (a DOF without stiffness: still timed)
        }
        s.factor_seconds = std::min(s.factor_seconds, timed[TimeCategory::Factorization]);
      }
    }
    c.steps.push_back(s);
    if (i == 0) m.initial_gap_status(c);
  }
  return c;
}

void Analysis::Impl::initial_gap_status(ModelCheck& c) {
  // the gaps' own recovery at the reference configuration, before any load
  const std::vector<double> T0 = st.T_initial;
  const FieldView fields{st.u, st.u, T0, T0, T0, {}, {}, {}};
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
  StepRun r;
  r.index = index;
  r.step = &model.steps[index];
  const bool resuming = resume && resume->where.record.step_index == index;
  set_up_step(r, resuming ? resume.get() : nullptr);
  if (resuming) {
    r.ended_at_restart = resume->where.end_step && !r.ctrl->finished();
    resume.reset();
  }
  if (!r.proc->incremental()) {
    r.proc->run(r); // no increments (e.g. the reduction of the stiffness at the step start)
    r.sum.converged = true;
    for (auto* w : writers) w->end_step(model, r.index, r.sum);
    return r.sum;
  }
  increment_loop(r);
  return finish_step(r);
}

void Analysis::Impl::set_up_step(StepRun& r, PendingResume* from) {
  const Step& step = *r.step;
  r.proc = make_procedure(step, *this);
  r.u_step_start = from ? from->u_step_start : st.u_start;
  r.loads =
      std::make_unique<StepLoads>(model, disc, r.index, history, r.u_step_start, st.total_time);
  const StepLoads& loads = *r.loads;
  // a resumed step's warnings are in the record already
  if (!from)
    solver_warnings.insert(solver_warnings.end(), loads.warnings().begin(), loads.warnings().end());
  disc.set_equations(loads.equations(), loads.local_bcs());
  r.pattern = step_pattern(loads);
  solver->analyze(r.pattern);
  if (solver->wants_near_null_space())
    solver->set_near_null_space(rigid_body_modes(disc.dofs(), loads.equations(), model.mesh.coords,
                                                 model.space != ModelSpace::ThreeD));

  StepContext& base = r.base;
  base.procedure = step.procedure;
  base.perturbation = step.perturbation;
  base.nlgeom = step.nlgeom;
  base.step_period = loads.period();
  base.space = model.space;
  base.model_size = model.model_size();
  base.constants = &model.constants;
  base.step_index = r.index;
  base.step_number = step.number;
  base.direct = step.inc.direct;
  base.symmetric_only = step.symmetric_only;
  r.proc->configure(step, base);
  r.prob = std::make_unique<StepProblem>(disc, assembler, loads, st, base, r.pattern);
  StepProblem& prob = *r.prob;
  prob.set_integrator(r.proc->make_integrator(step, base));
  prob.set_unsymmetric_loads(step.unsymmetric);
  prob.set_statistics(&stats);
  prob.begin_increment(0.0, 0.0);
  if (!from) prob.compute_stiffness_hints(); // a resumed step has the record's
  r.proc->set_up(r, from != nullptr);

  // SHRINK fits take the element's own overclosure at the start of the step.
  if (!from && !loads.shrink_elements().empty()) {
    prob.begin_increment(0.0, 0.0);
    ElementRecovery rec;
    for (ElemId e : loads.shrink_elements()) {
      assembler.recover(e, prob.fields(), prob.context(), rec);
      const double h = rec.gap ? rec.gap->clearance : 0.0;
      r.loads->set_shrink_allowance(e, std::max(-h, 0.0));
    }
  }

  if (!from)
    for (auto* w : writers) w->begin_step(model, r.index);
  log::progress("Step {} ({}){}: {} equations, {} elements", step.number,
                procedure_name(step.procedure), step.nlgeom ? ", NLGEOM" : "",
                loads.equations().n_eq(), model.mesh.n_elements());
  r.sum.step = step.number;
  r.sum.name = step.name;
  r.sum.procedure = std::string(procedure_name(step.procedure));
  r.rules = increment_rules(step.controls);
  r.proc->adjust_rules(step, r.rules);
  r.ctrl = std::make_unique<IncrementController>(step.inc, step.max_increments, r.rules);
  r.controls = newton_controls(step.controls, options.factor_reuse);
  r.controls.residual_only = options.residual_only;
  step_damping_peak = 0.0;
  if (from) {
    restore_step(r);
    log::progress("  resuming at increment {} (step time {:.6g}) from {}", r.ctrl->increment(),
                  r.ctrl->step_time(), from->where.file.string());
  }
  r.proc->report_set_up(r);
}

void Analysis::Impl::increment_loop(StepRun& r) {
  const Step& step = *r.step;
  IncrementController& ctrl = *r.ctrl;
  StepProblem& prob = *r.prob;
  if (r.ended_at_restart) return;
  while (!ctrl.finished()) {
    if (ctrl.increment() >= step.max_increments) {
      r.sum.converged = false;
      r.sum.failure = fmt::format("the step needs more than {} increments; raise INC on *STEP "
                                  "(step time reached {:.6g} of {:.6g})",
                                  step.max_increments, ctrl.step_time(), ctrl.period());
      return;
    }
    const double t0 = ctrl.step_time();
    const double dt = ctrl.next();
    const auto guess =
        r.extrapolate ? r.predictor.guess(step.extrapolation, dt) : std::span<const double>{};
    prob.begin_increment(t0, dt, ctrl.increment() + 1, guess);
    if (!guess.empty()) log::debug("  first guess extrapolated from the last increments");
    NewtonResult res;
    // A failure no smaller increment can cure (the linear solver out of memory, an output file
    // that cannot be written) ends the step like a convergence failure, so the result files are
    // complete up to the last converged increment.
    try {
      res = solve_increment(prob, *solver, r.controls, r.flux, &stats);
    } catch (const AnalysisError& e) {
      r.sum.converged = false;
      r.sum.failure = e.what();
      return;
    } catch (const std::bad_alloc&) {
      r.sum.converged = false;
      r.sum.failure = fmt::format("out of memory at step time {:.6g} solving {} equations; use a "
                                  "coarser mesh or run on a machine with more memory",
                                  t0 + dt, r.loads->equations().n_eq());
      return;
    }
    ++stats.attempts;
    ++r.sum.attempts;
    r.sum.iterations += res.iterations;
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
    // An element's PNEWDT > 1 bounds the growth of the next increment, and so may the
    // procedure's accuracy check (transient heat transfer: DELTMX).
    double growth = std::isfinite(res.dt_ratio) && res.dt_ratio > 0.0 ? res.dt_ratio : 0.0;
    bool redo = false;
    if (res.converged) { // the procedure's accuracy check (e.g. DELTMX)
      const IncrementAccuracy acc = r.proc->check_accuracy(r, info, dt);
      if (acc.growth > 0.0) growth = growth > 0.0 ? std::min(growth, acc.growth) : acc.growth;
      redo = acc.redo;
      info.accuracy_check = acc.check;
    }
    info.converged = res.converged && !redo;
    info.deltmx_exceeded = redo;
    // A converged increment is reported after its frame is written, so that what the .sta and
    // the terminal call converged is already in the result files (docs/results.md).
    if (!info.converged)
      for (auto* w : writers) w->increment(info);
    if (redo) continue;
    if (res.converged) {
      accept_increment(r, res, info, dt, growth);
      continue;
    }
    if (!reject_attempt(r, res, info, t0)) return;
  }
}

void Analysis::Impl::accept_increment(StepRun& r, const NewtonResult& res, IncrementInfo& info,
                                      double dt, double growth) {
  IncrementController& ctrl = *r.ctrl;
  StepProblem& prob = *r.prob;
  const double t_prev = ctrl.step_time();
  r.last_t0 = t_prev;
  r.last_dt = dt;
  r.attempts_log.clear();
  // a converged state that overflowed somewhere stops the run before it is committed or written
  if (const std::string bad = first_non_finite_state(model, disc, st.u, prob.reactions());
      !bad.empty())
    throw AnalysisError(non_finite_message(ctrl.increment() + 1, bad));
  r.predictor.record(st.u, st.u_start, dt);
  r.extrapolate = true;
  prob.commit();
  r.proc->accepted(r, dt);
  r.converged_f_int = st.f_int;
  r.converged_f_ext = st.f_ext;
  for (int f = 0; f < kNumFields; ++f) r.flux.sum[f] += res.flux[f];
  ++r.flux.n;
  r.controls.nonlinear_step = res.iterations > 1;
  if (res.fresh_contraction > 0) r.controls.fresh_contraction = res.fresh_contraction;
  ctrl.accept(res.iterations - res.severe_iterations - res.refinements, growth);
  ++stats.increments;
  ++r.sum.increments;
  step_damping_peak = std::max(step_damping_peak, damping_peak(prob));
  write_frame(r.index, prob, ctrl.increment(), ctrl.finished(), dt);
  info.monitor = monitor_value(*r.step, ctrl.increment(), ctrl.finished());
  if (prob.integrator() && prob.integrator()->second_order()) info.energies = st.energies();
  history_sample(r.index, prob, ctrl.increment(), ctrl.finished(), info);
  if (want_gap_samples && disc.has_gaps()) gap_samples(prob, info);
  {
    ScopedTimer timer(&stats, TimeCategory::Output); // the JSON checkpoint is output time
    for (auto* w : writers) w->increment(info);
  }
  if (restart_due(r, t_prev)) write_restart(r);
  if (kill_after_increments > 0 && stats.increments == kill_after_increments) std::raise(SIGKILL);
}

bool Analysis::Impl::reject_attempt(StepRun& r, const NewtonResult& res, const IncrementInfo& info,
                                    double t0) {
  StepProblem& prob = *r.prob;
  std::string kind = std::to_string(static_cast<int>(res.cause));
  if (res.singular) {
    const bool supported = supported_at_last_converged(prob, t0);
    r.last_problem =
        describe_singularity(model, disc, assembler, prob, res.singular_equations, supported);
    // A model without gaps whose stiffness is singular from the start cannot be cured by a
    // smaller increment; one that became singular in the increment may be (a limit point).
    if (!disc.has_gaps() && !supported) {
      r.sum.converged = false;
      r.sum.failure = r.last_problem;
      return false;
    }
  } else if (!res.chattering.empty()) {
    r.last_problem = describe_chattering(model, res.chattering);
  } else {
    r.last_problem = res.reason;
    // repeats of one element's failure are one cause ("element 12: ...")
    if (res.cause == FailureCause::Element)
      kind += r.last_problem.substr(0, r.last_problem.find(':'));
  }
  const bool structural =
      res.singular || !res.chattering.empty() || res.cause == FailureCause::Element;
  r.attempts_log.add(info.increment, info.attempts, kind, r.last_problem, structural);
  r.extrapolate = false;
  r.proc->rejected(r);
  log::progress("  increment {} attempt {} did not converge: {}", info.increment, info.attempts,
                r.last_problem);
  if (!r.ctrl->reject(res.cause == FailureCause::Requested ? res.dt_ratio : 0.0)) {
    r.sum.converged = false;
    r.sum.failure = r.ctrl->failure() + ". " + r.attempts_log.summary();
    return false;
  }
  return true;
}

StepSummary Analysis::Impl::finish_step(StepRun& r) {
  const Step& step = *r.step;
  IncrementController& ctrl = *r.ctrl;
  StepProblem& prob = *r.prob;
  StepSummary& sum = r.sum;
  if (!sum.converged) {
    // Report the last converged state as the step's final frame, with the forces (reactions,
    // capacity terms) of its converged evaluation.
    prob.begin_increment(ctrl.step_time(), 0.0);
    if (!r.converged_f_int.empty()) {
      st.f_int = r.converged_f_int;
      st.f_ext = r.converged_f_ext;
    } else {
      try {
        prob.evaluate(false);
      } catch (const ConvergenceFailure&) {
      }
    }
    write_frame(r.index, prob, ctrl.increment(), true, 0.0);
  } else if (r.ended_at_restart) {
    // *RESTART, READ, END STEP: the step ends at the restart point, its loads as they are there
    log::progress("  step {} ends at step time {:.6g} (*RESTART, READ, END STEP)", step.number,
                  ctrl.step_time());
    write_frame(r.index, prob, ctrl.increment(), true, 0.0, /*repeat=*/true);
    r.loads->finish(ctrl.step_time(), prob.reactions(), disc.constraints(), history);
  } else {
    r.loads->finish(ctrl.period(), prob.reactions(), disc.constraints(), history);
  }
  sum.checks = checks(prob);
  sum.checks.max_damping_force = std::max(sum.checks.max_damping_force, step_damping_peak);
  sum.checks.allie = st.allie;
  // what a step hands to the next is its procedure's to say (a stabilization continued by
  // CONTINUE=YES, StaticProcedure); by default nothing
  carried_stabilization = Stabilization{};
  carried_stabilization_step = -1;
  carried_factor = 0.0;
  r.proc->finish(r);
  for (auto* w : writers) w->end_step(model, r.index, sum);
  st.total_time += ctrl.step_time();
  return sum;
}
} // namespace gapfem
