#pragma once
/// @file substructure_recovery.hpp
/// The internal results of used substructures (*SUBSTRUCTURE PATH; docs/substructures.md), as the
/// analysis recovers them into Frame::substructures (solver/substructure_recovery), written to
/// <job>_<Zn>_<element>.results.json: one complete document, rewritten after every frame that
/// holds them.
#include "results/results.hpp"

#include <filesystem>
#include <map>
#include <string>

namespace gapfem {

class SubstructureRecoveryWriter final : public ResultWriter {
 public:
  SubstructureRecoveryWriter(std::filesystem::path directory, std::string job);
  ~SubstructureRecoveryWriter() override;
  void begin(const Model& model) override;
  void frame(const Model& model, int step_index, const Frame& frame) override;
  void end(const Model& model, const RunSummary& summary) override;

 private:
  /// One substructure element's document so far.
  struct Document {
    RecoveredSubstructure head; ///< the element's names and notes (its last frame's)
    fmt::memory_buffer frames;  ///< the frames so far, comma separated
    std::filesystem::path file;
  };
  void write(const Document& d) const;

  std::filesystem::path _dir;
  std::string _job;
  std::map<ElemId, Document> _documents;
};

} // namespace gapfem
