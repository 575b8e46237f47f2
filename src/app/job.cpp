#include "app/job.hpp"

#include "app/check.hpp"
#include "app/environment.hpp"
#include "app/job_files.hpp"
#include "app/user_code.hpp"
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

JobResult run_job(const JobOptions& given) {
  JobOptions options = given;
  options.deck = resolve_deck(given.deck);
  JobResult result;
  Stopwatch watch;
  const std::string job =
      options.job_name.empty() ? options.deck.stem().string() : options.job_name;
  std::filesystem::path dir = options.output_dir;
  if (dir.empty()) dir = options.deck.has_parent_path() ? options.deck.parent_path() : ".";
  std::optional<log::Level> previous_level;
  if (options.quiet || options.verbose || options.silent) {
    previous_level = log::level();
    log::set_level(options.silent  ? log::Level::Quiet
                   : options.quiet ? log::Level::Warning
                                   : log::Level::Debug);
  }
  auto restore = [&] {
    if (previous_level) log::set_level(*previous_level);
  };

  std::shared_ptr<Model> model;
  std::optional<AnalysisOptions::Resume> resume;
  JobLock lock; // held until every writer is gone (declared before them)
  try {
    ReadOptions ro;
    ro.ignore_unknown = options.ignore_unknown;
    if (!options.oldjob.empty())
      ro.restart_base = [&](const RestartRead& req) {
        const std::filesystem::path file = oldjob_file(options.oldjob, dir);
        RestartIndex idx;
        try {
          idx = read_restart_index(file);
        } catch (const RestartDataError& e) {
          throw InputError(req.loc, "READ",
                           fmt::format("--oldjob {}: {}", options.oldjob, e.what()));
        }
        AnalysisOptions::Resume r;
        r.file = file;
        r.record = choose_record(idx, req, file);
        r.fingerprint = idx.header.fingerprint;
        r.end_step = req.end_step;
        r.files = {file.has_parent_path() ? file.parent_path() : ".", idx.header.job};
        resume = r;
        return ReadOptions::RestartBase{idx.header.deck, r.record.step_index + 1};
      };
    model = std::make_shared<Model>(read_deck(options.deck, ro));
    model->job_name = job;
    require_steps(*model, options.deck);
    if (!options.oldjob.empty() && !model->restart_read)
      throw InputError(SourceLocation{options.deck.string(), 0, {}}, "--oldjob",
                       "the deck has no *RESTART, READ, so there is nothing to continue; add "
                       "*RESTART, READ (with STEP= and INC= of the restart point) or run without "
                       "--oldjob");
    if (options.write_files) {
      prepare_output(dir, job);
      lock = JobLock::take(dir, job); // before the restart file is read: --restart respects it
    }
    if (options.restart) resume = own_restart_point(*model, options.deck, dir, job);
    if (!options.user_code.empty())
      model->user_code = load_user_code(
          options.user_code, dir / (job + ".scratch" +
                                    (parallel::rank() > 0 ? fmt::format(".rank{}", parallel::rank())
                                                          : std::string())));
  } catch (const InputError& e) {
    result.exit_code = kExitInputError;
    result.error = e.what();
    log::error("{}", e.what());
    restore();
    return result;
  }
  result.model = model;

  std::vector<std::unique_ptr<ResultWriter>> writers;
  if (options.write_files) {
    WriterOptions wo;
    wo.directory = dir;
    wo.job = job;
    wo.vtu = options.write_vtu;
    wo.report_gaps = options.report_gaps;
    wo.terminal = !options.quiet;
    wo.substructure_recovery =
        std::any_of(model->steps.begin(), model->steps.end(),
                    [](const Step& s) { return !s.recover_substructures.empty(); });
    writers = make_result_writers(wo);
  } else if (!options.quiet) {
    WriterOptions wo;
    wo.dat = wo.sta = wo.json = wo.vtu = wo.msg = wo.frd = wo.report = false;
    wo.terminal = true;
    writers = make_result_writers(wo);
  }
  MemoryWriter memory(result, options.keep_frames, options.keep_step_ends);
  std::vector<ResultWriter*> ptrs;
  for (auto& w : writers) ptrs.push_back(w.get());
  ptrs.push_back(&memory);

  try {
    AnalysisOptions aopt;
    aopt.factor_reuse = options.factor_reuse;
    aopt.residual_only = options.residual_only;
    aopt.solver = options.solver;
    aopt.restart_header.job = job;
    if (options.write_files) {
      aopt.output_dir = dir;
      aopt.restart_file = dir / (job + ".res");
      std::error_code ec;
      aopt.restart_header.deck = std::filesystem::absolute(options.deck, ec).string();
      aopt.restart_header.job = job;
    }
    aopt.resume = resume;
    aopt.generation_deck_reader = [](const std::filesystem::path& deck) {
      return std::make_unique<Model>(read_deck(deck)); // *SUBSTRUCTURE PATH: its stresses
    };
    apply_environment(aopt); // the GAPFEM_* switches (app/environment.hpp)
    Analysis analysis(*model, ptrs, aopt);
    result.run = analysis.run();
    result.exit_code = kExitOk;
    if (options.write_files && !options.quiet)
      log::info("Results: {}/{}.dat, {}.sta, {}.results.json{}", dir.string(), job, job, job,
                options.write_vtu ? fmt::format(", {}.pvd", job) : "");
  } catch (const InputError& e) {
    result.exit_code = kExitInputError;
    result.error = e.what();
    log::error("{}", e.what());
  } catch (const RestartDataError& e) {
    result.exit_code = kExitInputError;
    result.error = fmt::format("restart: {}", e.what());
    log::error("{}", result.error);
  } catch (const AnalysisError& e) {
    result.exit_code = kExitNoConvergence;
    result.error = e.what();
    log::error("{}", e.what());
  } catch (const std::exception& e) {
    result.exit_code = kExitInternal;
    result.error = fmt::format("internal error: {}", e.what());
    log::error("{}", result.error);
  }
  result.run.wall_seconds = watch.seconds();
  restore();
  return result;
}

} // namespace gapfem
