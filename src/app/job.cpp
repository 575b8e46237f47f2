#include "app/job.hpp"

#include "app/check.hpp"
#include "common/error.hpp"
#include "common/log.hpp"
#include "io/inp/reader.hpp"
#include "model/model.hpp"
#include "output/output_file.hpp"
#include "output/writers.hpp"
#include "solver/analysis.hpp"

#include <cstdlib>
#include <cstring>
#include <fmt/format.h>

namespace gapfem {
namespace {

/// Keeps every frame and increment in memory for the caller (tests, tools).
class MemoryWriter final : public ResultWriter {
 public:
  explicit MemoryWriter(JobResult& r, bool keep) : _r(r), _keep(keep) {}
  void increment(const IncrementInfo& info) override { _r.increments.push_back(info); }
  void frame(const Model&, int, const Frame& f) override {
    if (_keep || f.last_in_step) _r.frames.push_back(f);
  }
  void end_step(const Model&, int, const StepSummary& s) override { _r.steps.push_back(s); }

 private:
  JobResult& _r;
  bool _keep;
};

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

void require_steps(const Model& model, const std::filesystem::path& deck) {
  if (!model.steps.empty()) return;
  throw InputError(SourceLocation{deck.string(), 0, {}}, "",
                   "the deck defines no *STEP, so there is nothing to analyse; add a step, e.g. "
                   "*STEP / *STATIC / loads and boundary conditions / *END STEP");
}

void prepare_output(const std::filesystem::path& dir, const std::string& job) {
  namespace fs = std::filesystem;
  if (job.empty() || job == "." || job == ".." || job.find_first_of("/\\") != std::string::npos)
    throw InputError(SourceLocation{}, fmt::format("job name '{}'", job),
                     "a job name is a file name without a directory (job.dat, job.sta, ... are "
                     "written into the output directory); choose the directory with -o");
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw InputError(SourceLocation{}, fmt::format("output directory '{}'", dir.string()),
                     "it exists and is not a directory; choose another with -o");
  fs::create_directories(dir, ec);
  if (ec)
    throw InputError(SourceLocation{}, fmt::format("output directory '{}'", dir.string()),
                     fmt::format("cannot create it: {}; choose another with -o", ec.message()));
  // Probe before solving: a read-only or full directory is reported now, not after the analysis.
  const fs::path probe = dir / fmt::format(".{}.write-test", job);
  output::OutputFile f;
  try {
    f.open(probe);
    f.write("gapfem\n");
    f.close();
  } catch (const AnalysisError&) {
    fs::remove(probe, ec);
    throw InputError(SourceLocation{}, fmt::format("output directory '{}'", dir.string()),
                     fmt::format("cannot write into it: {}; free space there or choose another "
                                 "directory with -o",
                                 std::strerror(f.error_number())));
  }
  fs::remove(probe, ec);
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
  if (options.quiet || options.verbose) {
    previous_level = log::level();
    log::set_level(options.quiet ? log::Level::Warning : log::Level::Debug);
  }
  auto restore = [&] {
    if (previous_level) log::set_level(*previous_level);
  };

  std::shared_ptr<Model> model;
  try {
    ReadOptions ro;
    ro.ignore_unknown = options.ignore_unknown;
    model = std::make_shared<Model>(read_deck(options.deck, ro));
    model->job_name = job;
    require_steps(*model, options.deck);
    if (options.write_files) prepare_output(dir, job);
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
    writers = make_result_writers(wo);
  } else if (!options.quiet) {
    WriterOptions wo;
    wo.dat = wo.sta = wo.json = wo.vtu = wo.msg = wo.frd = wo.report = false;
    wo.terminal = true;
    writers = make_result_writers(wo);
  }
  MemoryWriter memory(result, options.keep_frames);
  std::vector<ResultWriter*> ptrs;
  for (auto& w : writers) ptrs.push_back(w.get());
  ptrs.push_back(&memory);

  try {
    AnalysisOptions aopt;
    aopt.factor_reuse = options.factor_reuse;
    // GAPFEM_FACTOR_REUSE=always|never overrides (used to run whole test suites both ways)
    if (const char* env = std::getenv("GAPFEM_FACTOR_REUSE")) {
      const std::string v(env);
      if (v == "always") aopt.factor_reuse = FactorReuse::Always;
      if (v == "never") aopt.factor_reuse = FactorReuse::Never;
    }
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
