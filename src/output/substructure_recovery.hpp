#pragma once
/// @file substructure_recovery.hpp
/// Recovery of the internal results of used substructures (*SUBSTRUCTURE PATH; docs/
/// substructures.md): at every frame with field output (and at the end of each step) the
/// retained DOFs' values of a named Zn element are turned back into the substructure's own
/// directions, its internal displacements recovered from them, u_I = -K_II^-1 K_IR u_R (the
/// library's recovery data), and, when its generation deck can be read again, its elements'
/// stresses and strains computed. Written to <job>_<Zn>_<element>.results.json.
#include "output/results.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace gapfem {

class SubstructureRecoveryWriter final : public ResultWriter {
 public:
  SubstructureRecoveryWriter(std::filesystem::path directory, std::string job);
  ~SubstructureRecoveryWriter() override;
  void begin(const Model& model) override;
  void frame(const Model& model, int step_index, const Frame& frame) override;
  void end(const Model& model, const RunSummary& summary) override;

  struct Recovered; ///< one substructure element's recovery (data and its document so far)

 private:
  void write(const Recovered& r) const;

  std::filesystem::path _dir;
  std::string _job;
  std::vector<std::unique_ptr<Recovered>> _elements;
};

} // namespace gapfem
