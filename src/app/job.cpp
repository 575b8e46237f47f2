#include "app/job.hpp"

#include "app/abaqus_utilities.hpp"
#include "app/check.hpp"
#include "app/environment.hpp"
#include "app/job_files.hpp"
#include "app/user_code_loader.hpp"
#include "common/error.hpp"
#include "common/log.hpp"
#include "io/inp/reader.hpp"
#include "model/model.hpp"
#include "output/output_file.hpp"
#include "output/writers.hpp"
#include "parallel/parallel.hpp"
#include "solver/analysis.hpp"
#include "solver/restart_file.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fmt/format.h>

namespace gapfem {
namespace {

/// Keeps every frame and increment in memory for the caller (tests, tools).
class MemoryWriter final : public ResultWriter {
 public:
  MemoryWriter(JobResult& r, bool keep, bool keep_step_ends)
      : _r(r), _keep(keep), _keep_step_ends(keep_step_ends) {}
  void increment(const IncrementInfo& info) override { _r.increments.push_back(info); }
  void frame(const Model&, int, const Frame& f) override {
    if (_keep || (_keep_step_ends && f.last_in_step)) _r.frames.push_back(f);
  }
  void end_step(const Model&, int, const StepSummary& s) override { _r.steps.push_back(s); }
  void modes(const Model&, int step_index, const EigenSummary& m) override {
    _r.modes.emplace_back(step_index, m);
  }

 private:
  JobResult& _r;
  bool _keep, _keep_step_ends;
};

/// "step 1 increments 2, 4; step 2 increments 1" (the records of a restart file).
std::string available_records(const RestartIndex& idx) {
  std::string out;
  int step = -1;
  for (const RestartRecordInfo& r : idx.records) {
    if (r.step != step) {
      out += fmt::format(
          "{}step {} increment{} {}", out.empty() ? "" : "; ", r.step,
          std::count_if(idx.records.begin(), idx.records.end(),
                        [&](const RestartRecordInfo& o) { return o.step == r.step; }) > 1
              ? "s"
              : "",
          r.increment);
      step = r.step;
    } else {
      out += fmt::format(", {}", r.increment);
    }
  }
  return out.empty() ? "none" : out;
}

/// The restart file --oldjob names: a .res path, or a job name looked up in the working
/// directory and then in the output directory.
std::filesystem::path oldjob_file(const std::string& oldjob, const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  fs::path p(oldjob);
  if (p.extension() != ".res") p += ".res";
  std::error_code ec;
  if (fs::exists(p, ec) || p.has_parent_path()) return p;
  return dir / p;
}

/// The record a *RESTART, READ asks for (InputError at the keyword naming what there is).
RestartRecordInfo choose_record(const RestartIndex& idx, const RestartRead& req,
                                const std::filesystem::path& file) {
  const std::string have =
      fmt::format("'{}' holds restart data for {}", file.string(), available_records(idx));
  if (idx.records.empty())
    throw InputError(req.loc, "READ",
                     fmt::format("'{}' holds no complete restart record (the old job stopped "
                                 "before its first *RESTART, WRITE point)",
                                 file.string()));
  if (req.step == 0) return idx.records.back();
  const RestartRecordInfo* found = nullptr;
  for (const RestartRecordInfo& r : idx.records)
    if (r.step == req.step && (req.increment == 0 || r.increment == req.increment)) found = &r;
  if (!found)
    throw InputError(req.loc,
                     req.increment ? fmt::format("STEP={}, INC={}", req.step, req.increment)
                                   : fmt::format("STEP={}", req.step),
                     fmt::format("there is no such restart point: {}", have));
  return *found;
}

} // namespace

const Frame* JobResult::step_end(int step) const {
  for (auto it = frames.rbegin(); it != frames.rend(); ++it)
    if (it->step == step && it->last_in_step) return &*it;
  return nullptr;
}

NodeId JobResult::node(const Model& model, Label label) {
  return model.mesh.find_node(label);
}

std::filesystem::path resolve_deck(const std::filesystem::path& deck) {
  std::error_code ec;
  if (deck.has_extension() || std::filesystem::exists(deck, ec)) return deck;
  std::filesystem::path inp = deck;
  inp += ".inp";
  return std::filesystem::exists(inp, ec) ? inp : deck;
}

namespace {
/// --restart: the last complete record of the job's own restart file.
AnalysisOptions::Resume own_restart_point(const Model& model, const std::filesystem::path& deck,
                                          const std::filesystem::path& dir,
                                          const std::string& job) {
  const SourceLocation at{deck.string(), 0, {}};
  AnalysisOptions::Resume r;
  r.file = dir / (job + ".res");
  RestartIndex idx;
  try {
    idx = read_restart_index(r.file);
  } catch (const RestartDataError& e) {
    throw InputError(at, "--restart",
                     fmt::format("{}; --restart needs the restart file a *RESTART, WRITE of this "
                                 "job wrote (run without --restart to start afresh)",
                                 e.what()));
  }
  if (idx.records.empty())
    throw InputError(at, "--restart",
                     fmt::format("'{}' holds no complete restart record (the job stopped before "
                                 "its first *RESTART, WRITE point); run without --restart",
                                 r.file.string()));
  if (idx.header.job != job)
    throw InputError(at, "--restart",
                     fmt::format("'{}' was written by job '{}', not '{}'", r.file.string(),
                                 idx.header.job, job));
  r.record = idx.records.back();
  r.fingerprint = idx.header.fingerprint;
  r.files = {dir, job};
  if (r.record.step_index >= static_cast<int>(model.steps.size()))
    throw InputError(at, "--restart",
                     fmt::format("the restart point is in step {}, but the deck has {} step(s)",
                                 r.record.step, model.steps.size()));
  log::info("Restarting job {} at step {} increment {} (total time {:.6g})", job, r.record.step,
            r.record.increment, r.record.total_time);
  return r;
}
} // namespace

void require_steps(const Model& model, const std::filesystem::path& deck) {
  if (!model.steps.empty()) return;
  throw InputError(SourceLocation{deck.string(), 0, {}}, "",
                   "the deck defines no *STEP, so there is nothing to analyse; add a step, e.g. "
                   "*STEP / *STATIC / loads and boundary conditions / *END STEP");
}

namespace {

/// Sets the log level a job asks for and gives the previous one back when the job ends.
class ScopedLogLevel {
 public:
  explicit ScopedLogLevel(const JobOptions& o) {
    if (!o.quiet && !o.verbose && !o.silent) return;
    _previous = log::level();
    log::set_level(o.silent  ? log::Level::Quiet
                   : o.quiet ? log::Level::Warning
                             : log::Level::Debug);
  }
  ~ScopedLogLevel() {
    if (_previous) log::set_level(*_previous);
  }
  ScopedLogLevel(const ScopedLogLevel&) = delete;
  ScopedLogLevel& operator=(const ScopedLogLevel&) = delete;

 private:
  std::optional<log::Level> _previous;
};

/// What a job is set up with before anything is solved.
struct JobSetup {
  JobOptions options;
  std::string job;
  std::filesystem::path dir;
  std::shared_ptr<Model> model;
  std::optional<AnalysisOptions::Resume> resume;
  JobLock lock; ///< held until the job ends (JobSetup outlives the writers)
};

/// --oldjob: the record a *RESTART, READ asks for, as the reader needs it.
ReadOptions::RestartBase restart_base(JobSetup& s, const RestartRead& req) {
  const std::filesystem::path file = oldjob_file(s.options.oldjob, s.dir);
  RestartIndex idx;
  try {
    idx = read_restart_index(file);
  } catch (const RestartDataError& e) {
    throw InputError(req.loc, "READ", fmt::format("--oldjob {}: {}", s.options.oldjob, e.what()));
  }
  AnalysisOptions::Resume r;
  r.file = file;
  r.record = choose_record(idx, req, file);
  r.fingerprint = idx.header.fingerprint;
  r.end_step = req.end_step;
  r.files = {file.has_parent_path() ? file.parent_path() : ".", idx.header.job};
  s.resume = r;
  return ReadOptions::RestartBase{idx.header.deck, r.record.step_index + 1};
}

/// Reads the deck, prepares and locks the output directory, finds the restart point and loads
/// the user's code: InputError (exit 1) for anything wrong, before anything is solved.
void set_up(JobSetup& s) {
  const JobOptions& o = s.options;
  ReadOptions ro;
  ro.ignore_unknown = o.ignore_unknown;
  if (!o.oldjob.empty())
    ro.restart_base = [&s](const RestartRead& req) { return restart_base(s, req); };
  s.model = std::make_shared<Model>(read_deck(o.deck, ro));
  s.model->job_name = s.job;
  require_steps(*s.model, o.deck);
  if (!o.oldjob.empty() && !s.model->restart_read)
    throw InputError(SourceLocation{o.deck.string(), 0, {}}, "--oldjob",
                     "the deck has no *RESTART, READ, so there is nothing to continue; add "
                     "*RESTART, READ (with STEP= and INC= of the restart point) or run without "
                     "--oldjob");
  if (o.write_files) {
    prepare_output(s.dir, s.job);
    s.lock = JobLock::take(s.dir, s.job); // before the restart file is read: --restart too
  }
  if (o.restart) s.resume = own_restart_point(*s.model, o.deck, s.dir, s.job);
  if (!o.user_code.empty()) {
    const std::string rank =
        parallel::rank() > 0 ? fmt::format(".rank{}", parallel::rank()) : std::string();
    set_abaqus_job(s.job, s.dir); // what GETJOBNAME and GETOUTDIR return
    s.model->user_code = load_user_code(o.user_code, s.dir / (s.job + ".scratch" + rank));
  }
}

/// The result files' writers (or the terminal's alone when no files are written).
std::vector<std::unique_ptr<ResultWriter>> writers_for(const JobSetup& s) {
  const JobOptions& o = s.options;
  WriterOptions wo;
  if (!o.write_files) {
    if (o.quiet) return {};
    wo.dat = wo.sta = wo.json = wo.vtu = wo.msg = wo.frd = wo.report = false;
    wo.terminal = true;
    return make_result_writers(wo);
  }
  wo.directory = s.dir;
  wo.job = s.job;
  wo.vtu = o.write_vtu;
  wo.report_gaps = o.report_gaps;
  wo.terminal = !o.quiet;
  wo.substructure_recovery =
      std::any_of(s.model->steps.begin(), s.model->steps.end(),
                  [](const Step& st) { return !st.recover_substructures.empty(); });
  return make_result_writers(wo);
}

AnalysisOptions analysis_options(const JobSetup& s) {
  const JobOptions& o = s.options;
  AnalysisOptions a;
  a.factor_reuse = o.factor_reuse;
  a.residual_only = o.residual_only;
  a.solver = o.solver;
  a.restart_header.job = s.job;
  if (o.write_files) {
    a.output_dir = s.dir;
    a.restart_file = s.dir / (s.job + ".res");
    std::error_code ec;
    a.restart_header.deck = std::filesystem::absolute(o.deck, ec).string();
  }
  a.resume = s.resume;
  a.generation_deck_reader = [](const std::filesystem::path& deck) {
    return std::make_unique<Model>(read_deck(deck)); // *SUBSTRUCTURE PATH: its stresses
  };
  apply_environment(a); // the GAPFEM_* switches (app/environment.hpp)
  return a;
}

/// Records a failure in `result` with its exit status and prints it.
void fail(JobResult& result, int code, std::string message) {
  result.exit_code = code;
  result.error = std::move(message);
  log::error("{}", result.error);
}

/// Runs the analysis; every exception becomes the exit status of its kind.
void analyse(const JobSetup& s, const std::vector<ResultWriter*>& writers, JobResult& result) {
  try {
    Analysis analysis(*s.model, writers, analysis_options(s));
    result.run = analysis.run();
    result.exit_code = kExitOk;
    if (s.options.write_files && !s.options.quiet)
      log::info("Results: {}/{}.dat, {}.sta, {}.results.json{}", s.dir.string(), s.job, s.job,
                s.job, s.options.write_vtu ? fmt::format(", {}.pvd", s.job) : "");
  } catch (const InputError& e) {
    fail(result, kExitInputError, e.what());
  } catch (const RestartDataError& e) {
    fail(result, kExitInputError, fmt::format("restart: {}", e.what()));
  } catch (const AnalysisError& e) {
    fail(result, kExitNoConvergence, e.what());
  } catch (const std::exception& e) {
    fail(result, kExitInternal, fmt::format("internal error: {}", e.what()));
  }
}

} // namespace

JobResult run_job(const JobOptions& given) {
  Stopwatch watch;
  JobSetup s;
  s.options = given;
  s.options.deck = resolve_deck(given.deck);
  s.job = s.options.job_name.empty() ? s.options.deck.stem().string() : s.options.job_name;
  s.dir = s.options.output_dir;
  if (s.dir.empty()) s.dir = s.options.deck.has_parent_path() ? s.options.deck.parent_path() : ".";
  const ScopedLogLevel level(s.options);
  JobResult result;
  try {
    set_up(s);
  } catch (const InputError& e) {
    fail(result, kExitInputError, e.what());
    return result;
  }
  result.model = s.model;
  const std::vector<std::unique_ptr<ResultWriter>> writers = writers_for(s);
  MemoryWriter memory(result, s.options.keep_frames, s.options.keep_step_ends);
  std::vector<ResultWriter*> ptrs;
  for (const auto& w : writers) ptrs.push_back(w.get());
  ptrs.push_back(&memory);
  analyse(s, ptrs, result);
  result.run.wall_seconds = watch.seconds();
  return result;
}

} // namespace gapfem
