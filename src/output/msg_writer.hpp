#pragma once
/// @file msg_writer.hpp
/// job.msg, the message file: the run's whole log at the most detailed level, whatever the
/// terminal shows (docs/results.md). It holds the Newton iterations with their residuals, the
/// solver's notes, cut-backs and warnings, and one line per increment attempt. While the run
/// goes on, it tees gapfem's log: every message goes to the file, and those at or above the
/// terminal's level also go on to the terminal.
#include "common/log.hpp"
#include "output/output_file.hpp"
#include "results/results.hpp"

#include <filesystem>
#include <optional>

namespace gapfem {

class MsgWriter : public ResultWriter {
 public:
  explicit MsgWriter(std::filesystem::path path);
  ~MsgWriter() override;

  void begin(const Model& model) override;
  void begin_step(const Model& model, int step_index) override;
  void increment(const IncrementInfo& info) override;
  void end_step(const Model& model, int step_index, const StepSummary& summary) override;
  void end(const Model& model, const RunSummary& summary) override;
  std::string_view restart_key() const override { return "msg"; }
  void save_state(ArchiveWriter& out) override;
  void resume(const Model& model, int step_index, ArchiveReader& state,
              const ResumeFiles& from) override;

 private:
  void line(std::string_view text);
  void restore();
  /// Tee the log into the file (everything) and the terminal (its share).
  void tee_log();

  std::filesystem::path _path;
  output::OutputFile _out;
  std::optional<log::Sink> _previous; ///< the sink before begin() (restored by end())
  log::Level _terminal_level = log::Level::Info;
  bool _failed = false; ///< a write failed: the file is left as it is, the log goes on
};

} // namespace gapfem
