#pragma once
/// @file sta_writer.hpp
/// job.sta: one line per increment attempt in the Abaqus status-file layout,
/// flushed after every line so that `tail -f job.sta` follows the run.
#include "output/output_file.hpp"
#include "results/results.hpp"

#include <filesystem>

namespace gapfem {

/// Writes the status file (job.sta).
class StaWriter : public ResultWriter {
 public:
  /// `path`: the file to create (truncated at begin()).
  explicit StaWriter(std::filesystem::path path);

  void begin(const Model& model) override;
  void increment(const IncrementInfo& info) override;
  void end(const Model& model, const RunSummary& summary) override;
  std::string_view restart_key() const override { return "sta"; }
  void save_state(ArchiveWriter& out) override;
  void resume(const Model& model, int step_index, ArchiveReader& state,
              const ResumeFiles& from) override;

  /// The character after the attempt number: ' ' converged, 'U' not converged (cut back, as in
  /// Abaqus), 'D' converged but repeated smaller because a temperature changed by more than DELTMX.
  static char attempt_marker(const IncrementInfo& info);

 private:
  std::filesystem::path _path;
  output::OutputFile _out;
};

} // namespace gapfem
