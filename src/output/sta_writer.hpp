#pragma once
/// @file sta_writer.hpp
/// job.sta: one line per increment attempt in the Abaqus status-file layout,
/// flushed after every line so that `tail -f job.sta` follows the run.
#include "output/output_file.hpp"
#include "output/results.hpp"

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

 private:
  std::filesystem::path _path;
  output::OutputFile _out;
};

} // namespace gapfem
