#include "output/msg_writer.hpp"

#include "model/model.hpp"

namespace gapfem {

MsgWriter::MsgWriter(std::filesystem::path path) : _path(std::move(path)) {}

MsgWriter::~MsgWriter() {
  restore();
}

void MsgWriter::restore() {
  if (!_previous) return;
  log::set_sink(std::move(*_previous));
  log::set_level(_terminal_level);
  _previous.reset();
}

void MsgWriter::line(std::string_view text) {
  if (_failed || !_out.is_open()) return;
  try {
    _out.write(text);
    _out.write("\n");
    _out.flush();
  } catch (const AnalysisError&) {
    _failed = true; // reported once by the analysis through the other writers' checks
    throw;
  }
}

void MsgWriter::begin(const Model& model) {
  _out.open(_path);
  line(fmt::format("gapfem {}: message file of job {}", GAPFEM_VERSION, model.job_name));
  for (const auto& w : model.warnings) line("warning: " + w);
  tee_log();
}

void MsgWriter::save_state(ArchiveWriter& a) {
  a.pod(static_cast<std::uint64_t>(_failed ? 0 : _out.position()));
}

void MsgWriter::resume(const Model&, int, ArchiveReader& a, const ResumeFiles& from) {
  _out.open_resumed(_path, from.file(".msg"), a.get<std::uint64_t>());
  tee_log();
}

void MsgWriter::tee_log() {
  // everything into the file, the terminal's share onwards
  _terminal_level = log::level();
  log::Sink previous = log::set_sink(nullptr);
  _previous = previous;
  log::set_sink([this, previous](log::Level lvl, std::string_view msg) {
    if (!_failed && _out.is_open()) {
      const char* prefix = lvl == log::Level::Warning ? "warning: "
                           : lvl == log::Level::Error ? "error: "
                                                      : "";
      try {
        _out.write(prefix);
        _out.write(msg);
        _out.write("\n");
        _out.maybe_flush();
      } catch (const AnalysisError&) {
        _failed = true; // a full disk: the other writers report it
      }
    }
    if (lvl >= _terminal_level && previous) previous(lvl, msg);
  });
  log::set_level(log::Level::Debug);
}

void MsgWriter::begin_step(const Model& model, int step_index) {
  const Step& st = model.steps[static_cast<std::size_t>(step_index)];
  line(fmt::format("\nSTEP {} {} ({})", st.number, st.name, procedure_name(st.procedure)));
}

void MsgWriter::increment(const IncrementInfo& info) {
  std::string residuals;
  for (double r : info.residual_history) residuals += fmt::format(" {:.3e}", r);
  line(fmt::format("  increment {} attempt {}: {} in {} iterations ({} severe), step time {:.6g}, "
                   "time increment {:.6g}; residuals:{}",
                   info.increment, info.attempts,
                   info.converged         ? "converged"
                   : info.deltmx_exceeded ? fmt::format("repeated ({})", info.accuracy_check)
                                          : std::string("not converged, cut back"),
                   info.iterations, info.severe_discontinuities, info.step_time, info.dt,
                   residuals));
}

void MsgWriter::end_step(const Model& model, int step_index, const StepSummary& summary) {
  line(fmt::format("STEP {}: {} after {} increments, {} attempts, {} iterations", summary.step,
                   summary.converged ? "completed" : "stopped: " + summary.failure,
                   summary.increments, summary.attempts, summary.iterations));
}

void MsgWriter::end(const Model& model, const RunSummary& summary) {
  restore();
  line(summary.completed ? "\nTHE ANALYSIS HAS COMPLETED SUCCESSFULLY"
                         : "\nTHE ANALYSIS HAS NOT BEEN COMPLETED: " + summary.failure);
  if (!_failed) _out.close();
}

} // namespace gapfem
