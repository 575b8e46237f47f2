#pragma once
/// @file terminal_writer.hpp
/// Progress on the terminal through gapfem::log: a line per increment attempt,
/// a line per step and a final summary (wall time, counts, time split,
/// warnings). Never writes to std::cout itself.
#include "results/results.hpp"

namespace gapfem {

/// Reports the run's progress through log::progress / log::info.
class TerminalWriter : public ResultWriter {
 public:
  void begin(const Model& model) override;
  void begin_step(const Model& model, int step_index) override;
  void increment(const IncrementInfo& info) override;
  void end_step(const Model& model, int step_index, const StepSummary& summary) override;
  void end(const Model& model, const RunSummary& summary) override;
};

} // namespace gapfem
