#pragma once
/// @file frd_writer.hpp
/// job.frd: CalculiX's ASCII results format (long format), which its viewer cgx reads, written for
/// the *NODE FILE / *EL FILE requests of the deck (docs/results.md, "The .frd file"). The file
/// holds the nodes, the elements and, per due frame, one dataset per variable; element variables
/// are extrapolated to the nodes and averaged (output/nodal_average.hpp). Nothing is written when
/// no step asks for file output.
#include "output/nodal_average.hpp"
#include "output/output_file.hpp"
#include "results/results.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace gapfem {

/// frd element type (1 he8, 2 pe6, 3 te4, 4 he20, 5 pe15, 6 te10, 7 tr3, 8 tr6, 9 qu4, 10 qu8,
/// 11 be2, 12 be3) of an element, or 0 when the format has none (one-node springs and gaps).
int frd_element_type(ElementType type);
/// Position in the Abaqus connectivity of the node cgx expects at `frd_index` (the mid-side nodes
/// of the vertical edges come before those of the top face in he20 and pe15).
int frd_node_from_abaqus(ElementType type, int frd_index);

class FrdWriter : public ResultWriter {
 public:
  FrdWriter(std::filesystem::path path, std::string job);

  void begin(const Model& model) override;
  void frame(const Model& model, int step_index, const Frame& frame) override;
  void end(const Model& model, const RunSummary& summary) override;
  std::string_view restart_key() const override { return "frd"; }
  void save_state(ArchiveWriter& out) override;
  void resume(const Model& model, int step_index, ArchiveReader& state,
              const ResumeFiles& from) override;

 private:
  struct Block;
  void write_block(const Frame& frame, const Block& block, const std::vector<NodeId>& nodes);
  void node_blocks(const Model& model, const Frame& frame, const std::vector<NodeVar>& vars,
                   const std::vector<std::vector<char>>& masks, bool global);
  void element_blocks(const Model& model, const Frame& frame, const std::vector<ElemVar>& vars,
                      const std::vector<std::vector<char>>& masks);
  long long node_number(NodeId n) const;

  std::filesystem::path _path;
  std::string _job;
  output::OutputFile _out;
  const Model* _model = nullptr;
  bool _flat = true; ///< no part instances: nodes and elements keep their deck numbers
  int _datasets = 0, _frames = 0;
  output::NodalAverager _averager;
};

} // namespace gapfem
