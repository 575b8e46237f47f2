/// @file analysis_restart.cpp
/// Restart records (docs/restart.md): what a converged increment leaves behind so that the run
/// can continue from it exactly, and how a run picks it up again.
#include "common/error.hpp"
#include "solver/analysis_impl.hpp"

#include <cmath>
#include <fmt/format.h>
#include <map>

namespace gapfem {
namespace {

constexpr std::uint32_t kPayloadVersion =
    8; // 3: the procedure's state last; 4: rates; 5: energies;
// 6: a UEL element keeps one more history value (the step in which its damping was found zero);
// 7: the velocities of the damping forces after an impact (SolutionState::v_damp), ALLAE and the
// gaps' contact damping work (ALLSE), a gap's damping work in its history; 8: the modes a
// *FREQUENCY step kept (ModalBasis)

template <typename T>
void read_sized(ArchiveReader& in, std::vector<T>& v, std::size_t expected, const char* what) {
  in.vec(v);
  if (v.size() != expected)
    throw RestartDataError(fmt::format("the restart record's {} do not fit this model", what));
}

void save_history(ArchiveWriter& a, const LoadHistory& h) {
  a.pod(static_cast<std::uint64_t>(h.nodal.size()));
  for (const auto& [k, v] : h.nodal) {
    a.pod(k.first);
    a.pod(k.second);
    a.pod(v);
  }
  a.pod(static_cast<std::uint64_t>(h.distributed.size()));
  for (const auto& [k, v] : h.distributed) {
    a.pod(std::get<0>(k));
    a.pod(std::get<1>(k));
    a.pod(std::get<2>(k));
    a.pod(v.first);
    a.pod(v.second);
  }
  a.vec(h.temperature);
  a.vec(h.temperature_gradient);
  a.vec(h.prescribed);
  a.vec(h.reaction);
  a.pod(static_cast<std::uint64_t>(h.local_reaction.size()));
  for (const auto& [k, v] : h.local_reaction) {
    a.pod(k.first);
    a.pod(k.second);
    a.pod(v);
  }
}

void load_history(ArchiveReader& in, LoadHistory& h) {
  h = LoadHistory{};
  for (auto n = in.get<std::uint64_t>(); n > 0; --n) {
    const auto node = in.get<NodeId>();
    const auto dof = in.get<int>();
    h.nodal[{node, dof}] = in.get<double>();
  }
  for (auto n = in.get<std::uint64_t>(); n > 0; --n) {
    const auto e = in.get<ElemId>();
    const auto a = in.get<int>();
    const auto b = in.get<int>();
    const auto mag = in.get<double>();
    h.distributed[{e, a, b}] = {mag, in.get<double>()};
  }
  in.vec(h.temperature);
  in.vec(h.temperature_gradient);
  in.vec(h.prescribed);
  in.vec(h.reaction);
  for (auto n = in.get<std::uint64_t>(); n > 0; --n) {
    const auto node = in.get<NodeId>();
    const auto dof = in.get<int>();
    h.local_reaction[{node, dof}] = in.get<double>();
  }
}

} // namespace

std::uint64_t Analysis::Impl::fingerprint() const {
  return model_fingerprint(model, disc);
}

std::uint64_t model_fingerprint(const Model& model, const Discretization& disc) {
  ArchiveWriter a;
  const Mesh& mesh = model.mesh;
  a.vec(mesh.node_labels);
  a.vec(mesh.coords);
  a.vec(mesh.elem_labels);
  a.vec(mesh.elem_types);
  a.vec(mesh.conn);
  a.pod(disc.dofs().n_slots());
  for (const ElementBlock& b : disc.blocks()) {
    a.pod(static_cast<std::uint64_t>(b.size()));
    a.pod(b.n_state);
    a.pod(b.n_mult);
    a.vec(b.elements);
  }
  a.pod(disc.constraints().n_rows());
  // not the number of steps: a restart deck continues the old job with steps of its own
  // (job.cpp checks that the restart point is one of its steps)
  return fnv1a(a.data());
}

namespace {

/// The modes a *FREQUENCY step kept for the mode-based steps after it (none: a 0).
void save_modal_basis(ArchiveWriter& a, const ModalBasis* b) {
  a.pod(static_cast<std::uint8_t>(b ? 1 : 0));
  if (!b) return;
  a.pod(b->step_number);
  a.pod(b->n_slots);
  a.vec(b->omega2);
  a.vec(b->shapes);
  std::vector<double> gamma;
  for (const auto& g : b->participation) gamma.insert(gamma.end(), g.begin(), g.end());
  a.vec(gamma);
}

std::shared_ptr<const ModalBasis> load_modal_basis(ArchiveReader& in, LocalIndex n_slots) {
  if (in.get<std::uint8_t>() == 0) return nullptr;
  auto b = std::make_shared<ModalBasis>();
  in.pod(b->step_number);
  in.pod(b->n_slots);
  in.vec(b->omega2);
  in.vec(b->shapes);
  std::vector<double> gamma;
  in.vec(gamma);
  const std::size_t m = b->omega2.size();
  if (b->n_slots != n_slots || b->shapes.size() != m * static_cast<std::size_t>(n_slots) ||
      gamma.size() != 6 * m)
    throw RestartDataError("the restart record's modes do not fit the model");
  for (std::size_t k = 0; k < m; ++k) {
    std::array<double, 6> g{};
    std::copy(gamma.begin() + static_cast<std::ptrdiff_t>(6 * k),
              gamma.begin() + static_cast<std::ptrdiff_t>(6 * k + 6), g.begin());
    b->participation.push_back(g);
  }
  return b;
}

} // namespace

void Analysis::Impl::open_restart_file() {
  if (options.restart_file.empty()) return;
  const bool wanted = std::any_of(model.steps.begin(), model.steps.end(),
                                  [](const Step& s) { return s.restart.on(); });
  if (!wanted) return;
  RestartHeader header = options.restart_header;
  header.fingerprint = fingerprint();
  std::error_code ec;
  if (options.resume &&
      (options.resume->file == options.restart_file ||
       std::filesystem::equivalent(options.resume->file, options.restart_file, ec)))
    restart_out.resume(options.restart_file, header, options.resume->record.end);
  else
    restart_out.create(options.restart_file, header);
}

void Analysis::Impl::begin_resume() {
  const AnalysisOptions::Resume& where = *options.resume;
  if (where.fingerprint != fingerprint())
    throw InputError(SourceLocation{where.file.string(), 0, {}}, "",
                     "this restart file was written for another model (its mesh, elements or "
                     "constraints differ from the deck's); restart with the deck that wrote it, "
                     "changing only the steps after the restart point");
  resume = std::make_unique<PendingResume>();
  resume->where = where;
  resume->payload = read_restart_payload(where.file, where.record);
  resume->in = std::make_unique<ArchiveReader>(resume->payload);
  ArchiveReader& in = *resume->in;
  if (in.get<std::uint32_t>() != kPayloadVersion)
    throw RestartDataError("the restart record was written by another version of gapfem");

  in.pod(stats);
  summaries.resize(in.get<std::uint64_t>());
  for (auto& s : summaries) load(in, s);
  in.strings(solver_warnings);
  in.pod(carried_stabilization_step);
  in.pod(carried_factor);
  if (carried_stabilization_step >= static_cast<int>(model.steps.size()))
    throw RestartDataError("the restart record's stabilization does not fit this model");
  carried_stabilization = carried_stabilization_step >= 0
                              ? model.steps[carried_stabilization_step].stabilize
                              : Stabilization{};

  const std::size_t ns = static_cast<std::size_t>(disc.dofs().n_slots());
  const std::size_t nn = static_cast<std::size_t>(model.mesh.n_nodes());
  read_sized(in, st.u, ns, "solution values");
  read_sized(in, st.u_start, ns, "solution values");
  read_sized(in, st.T, nn, "temperatures");
  read_sized(in, st.T_start, nn, "temperatures");
  in.vec(st.G);
  read_sized(in, st.T_initial, nn, "temperatures");
  read_sized(in, st.f_int, ns, "forces");
  read_sized(in, st.f_ext, ns, "forces");
  in.pod(st.total_time);
  in.pod(st.allie);
  in.pod(st.allsd);
  in.vec(st.f_elem_start);
  for (double* e : {&st.allke, &st.allvd, &st.allwk, &st.allkl, &st.allcw, &st.allfd, &st.allae,
                    &st.contact_damping})
    in.pod(*e);
  for (auto* f : {&st.f_damp_start, &st.f_ext_start, &st.f_other_start}) {
    in.vec(*f);
    if (!f->empty() && f->size() != ns)
      throw RestartDataError("the restart record's forces do not fit the model");
  }
  for (auto* r : {&st.v_start, &st.a_start, &st.r_start, &st.r_prev, &st.v_damp}) { // dynamic steps
    in.vec(*r);
    if (!r->empty() && r->size() != ns)
      throw RestartDataError("the restart record's velocities do not fit the model");
  }
  st.v = st.v_start;
  st.a = st.a_start;

  for (ElementBlock& b : disc.blocks()) {
    read_sized(in, b.state_committed, b.state_trial.size(), "element states");
    read_sized(in, b.mult_committed, b.mult_trial.size(), "element multipliers");
    read_sized(in, b.stiffness_hint, b.stiffness_hint.size(), "element stiffnesses");
    b.state_trial = b.state_committed;
    b.mult_trial = b.mult_committed;
  }
  ConstraintSet& cs = disc.constraints();
  read_sized(in, cs.mult_committed, cs.mult_trial.size(), "constraint multipliers");
  cs.mult_trial = cs.mult_committed;
  load_history(in, history);
  read_sized(in, resume->u_step_start, ns, "solution values");
  modal_basis = load_modal_basis(in, static_cast<LocalIndex>(ns));
}

void Analysis::Impl::resume_writers(int index) {
  ArchiveReader& in = *resume->in;
  std::map<std::string, std::string, std::less<>> saved;
  for (auto n = in.get<std::uint64_t>(); n > 0; --n) {
    std::string key = in.str();
    saved[std::move(key)] = in.str();
  }
  for (auto* w : writers) {
    const auto it = saved.find(w->restart_key());
    if (w->restart_key().empty() || it == saved.end()) {
      w->begin(model);
      w->begin_step(model, index);
      continue;
    }
    ArchiveReader state(it->second);
    w->resume(model, index, state, resume->where.files);
  }
}

void Analysis::Impl::restore_step(StepRun& r) {
  ArchiveReader& in = *resume->in;
  for (auto n = in.get<std::uint64_t>(); n > 0; --n) {
    const auto e = in.get<ElemId>();
    r.loads->set_shrink_allowance(e, in.get<double>());
  }
  load(in, r.sum);
  r.ctrl->restore(in);
  in.pod(r.flux);
  in.pod(step_damping_peak);
  in.pod(r.last_t0);
  in.pod(r.last_dt);
  r.predictor.restore(in, st.u.size());
  r.proc->restore(in, r);
  // the state after the record's increment (its loads, temperatures and interference)
  r.prob->begin_increment(r.last_t0, r.last_dt);
  if (!in.at_end()) throw RestartDataError("the restart record holds more than gapfem expects");
  r.converged_f_int = st.f_int;
  r.converged_f_ext = st.f_ext;
}

// A restart point is one on every process of an mpirun job, though rank 0 alone writes the file:
// the factor is dropped there on every rank (write_restart), as the ranks factor together.
bool Analysis::Impl::restart_due(const StepRun& r, double t_prev) const {
  const RestartWrite& w = r.step->restart;
  if (!w.on()) return false;
  if (r.ctrl->finished()) return true;
  if (w.frequency > 0) return r.ctrl->increment() % w.frequency == 0;
  // NUMBER INTERVAL=n: the first increment at or past each of the n marks of the step period
  const double n = w.number_interval, period = r.ctrl->period();
  auto mark = [&](double t) { return std::floor(t * n / period * (1.0 + 1e-12)); };
  return mark(r.ctrl->step_time()) > mark(t_prev);
}

void Analysis::Impl::write_restart(StepRun& r) {
  // With a deterministic reuse policy the run after a restart point starts with a fresh factor,
  // as a restarted run does, so the two repeat each other to the last digit. With Auto the reuse
  // decisions depend on measured times anyway: the factor is kept (a record costs no extra
  // factorisation), and a restarted run may take another, equally converged Newton path. Every
  // rank of an mpirun job drops it, also those that write no file: the ranks build MUMPS's factor
  // and the iterative method's preconditioner together, and rank 0 alone dropping its part left
  // it waiting for the others in the next factorisation (tests/verification/restart/
  // dynamic_restart_test.cpp).
  if (options.factor_reuse != FactorReuse::Auto) solver->forget_factor();
  if (!restart_out.active()) return;
  ScopedTimer timer(&stats, TimeCategory::Output);
  ArchiveWriter a;
  a.pod(kPayloadVersion);
  a.pod(stats);
  a.pod(static_cast<std::uint64_t>(summaries.size()));
  for (const auto& s : summaries) save(a, s);
  a.strings(solver_warnings);
  a.pod(carried_stabilization_step);
  a.pod(carried_factor);

  a.vec(st.u);
  a.vec(st.u_start);
  a.vec(st.T);
  a.vec(st.T_start);
  a.vec(st.G);
  a.vec(st.T_initial);
  a.vec(st.f_int);
  a.vec(st.f_ext);
  a.pod(st.total_time);
  a.pod(st.allie);
  a.pod(st.allsd);
  a.vec(st.f_elem_start);
  for (const double e :
       {st.allke, st.allvd, st.allwk, st.allkl, st.allcw, st.allfd, st.allae, st.contact_damping})
    a.pod(e);
  for (const auto* f : {&st.f_damp_start, &st.f_ext_start, &st.f_other_start}) a.vec(*f);
  for (const auto* v : {&st.v_start, &st.a_start, &st.r_start, &st.r_prev, &st.v_damp}) a.vec(*v);
  for (const ElementBlock& b : disc.blocks()) {
    a.vec(b.state_committed);
    a.vec(b.mult_committed);
    a.vec(b.stiffness_hint);
  }
  a.vec(disc.constraints().mult_committed);
  save_history(a, history);
  a.vec(r.u_step_start);
  save_modal_basis(a, modal_basis.get());

  std::uint64_t keyed = 0;
  for (auto* w : writers) keyed += w->restart_key().empty() ? 0 : 1;
  a.pod(keyed);
  for (auto* w : writers) {
    if (w->restart_key().empty()) continue;
    ArchiveWriter sub;
    w->save_state(sub);
    a.str(w->restart_key());
    a.str(sub.data());
  }

  const auto& shrink = r.loads->shrink_elements();
  a.pod(static_cast<std::uint64_t>(shrink.size()));
  for (ElemId e : shrink) {
    a.pod(e);
    a.pod(r.loads->shrink_allowance(e));
  }
  save(a, r.sum);
  r.ctrl->save(a);
  a.pod(r.flux);
  a.pod(step_damping_peak);
  a.pod(r.last_t0);
  a.pod(r.last_dt);
  r.predictor.save(a);
  r.proc->save(a, r);

  RestartRecordInfo info;
  info.step = r.step->number;
  info.step_index = r.index;
  info.increment = r.ctrl->increment();
  info.step_time = r.ctrl->step_time();
  info.total_time = st.total_time + r.ctrl->step_time();
  info.step_end = r.ctrl->finished();
  restart_out.write(info, a.data(), r.step->restart.overlay);
  log::debug("  restart data written: step {} increment {} ({})", info.step, info.increment,
             restart_out.path().string());
}

} // namespace gapfem
