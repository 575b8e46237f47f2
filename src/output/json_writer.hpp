#pragma once
/// @file json_writer.hpp
/// job.results.json, schema "gapfem.results/1" (docs/results.md). The document
/// is streamed into job.results.json.part: each frame is formatted into a buffer and written in
/// large chunks. After every converged increment (and each step's end) the part with a closing
/// tail is published as job.results.json by output::ShadowDocument, at the cost of the bytes added
/// since the last publication: the file is at every moment one complete JSON document (a kill -9
/// or a full disk leaves the last one). end() publishes the final document and removes the part.
#include "common/timer.hpp"
#include "output/output_file.hpp"
#include "output/shadow_document.hpp"
#include "results/results.hpp"

#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace gapfem {

/// Writes the machine-readable results file (job.results.json).
class JsonWriter : public ResultWriter {
 public:
  /// `path`: the file to create; `job`: the job name recorded in the file.
  JsonWriter(std::filesystem::path path, std::string job);

  void begin(const Model& model) override;
  void begin_step(const Model& model, int step_index) override;
  void increment(const IncrementInfo& info) override;
  void frame(const Model& model, int step_index, const Frame& frame) override;
  void modes(const Model& model, int step_index, const EigenSummary& modes) override;
  void end_step(const Model& model, int step_index, const StepSummary& summary) override;
  void end(const Model& model, const RunSummary& summary) override;
  std::string_view restart_key() const override { return "json"; }
  void save_state(ArchiveWriter& out) override;
  void resume(const Model& model, int step_index, ArchiveReader& state,
              const ResumeFiles& from) override;

 private:
  /// `h`: a steady-state frame's imaginary part (its U and UR then also as imaginary part,
  /// amplitude and phase)
  void write_node(const Model& model, const NodeResults& r, NodeId n, bool& first,
                  const Frame::Harmonic* h = nullptr);
  void write_element(const Model& model, const ElementResult& res, bool& first);
  void close_step(const StepSummary* summary);
  /// Appends `]` closing the frames, then the step's status and checks (`unfinished`: the
  /// failure text when `summary` is null) and `}`.
  void append_step_end(fmt::memory_buffer& b, const StepSummary* summary,
                       std::string_view unfinished) const;
  /// Appends the end of the document after the steps: element types and the run summary.
  void append_tail(fmt::memory_buffer& b, const RunSummary& summary) const;
  /// Publishes the document so far, closed by a tail marking the run as not completed.
  void checkpoint();
  /// The print lists of a step's requests.
  void prepare_step(const Model& model, int step_index);
  /// What begin() and resume() share: the scratch marks and the list of all nodes.
  void prepare_model(const Model& model);
  /// Copies the part and `suffix` into the staging file and renames it over the final name.
  void publish(std::string_view suffix);
  std::filesystem::path part_path() const;

  std::filesystem::path _path;
  std::string _job;
  const Model* _model = nullptr;  ///< the model of begin() (names of instance entities)
  output::OutputFile _out;        ///< the document's body so far (job.results.json.part)
  output::ShadowDocument _shadow; ///< publishes body + tail as job.results.json
  double _publish_seconds = 0.0;  ///< wall time of the publications so far
  bool _failed = false;           ///< a write failed: the last published document stays
  Stopwatch _watch;
  RunStatistics _seen; ///< increments, attempts and iterations reported so far
  IncrementInfo _last; ///< the last converged increment
  bool _has_last = false;
  bool _step_open = false;
  bool _first_step = true;
  bool _first_frame = true;
  int _open_step_number = 0;
  /// Increment of the last frame written in the open step (-1: none): a step that stops early
  /// hands that increment over again as its final frame, which is then marked "repeated".
  int _last_increment = -1;
  /// The open dynamic step's energies per converged increment: increment, step time, total time,
  /// ALLKE, ALLIE, ALLVD, ALLFD, ALLKL, ALLWK, ETOTAL, ALLSE, ALLAE (the step's "history":
  /// docs/results.md)
  std::vector<std::array<double, 12>> _energy_history;
  /// The open step's *OUTPUT, HISTORY values: column names and one row per sample (increment,
  /// step time, total time, then the values)
  std::vector<std::string> _history_columns;
  std::vector<std::vector<double>> _history_rows;
  /// *FREQUENCY: the step's ",\"modes\":[…]" members, written with the step's end (empty else)
  std::string _modes_json;
  /// `,"history":{…}` of the open step (nothing when it has none).
  void append_history(fmt::memory_buffer& b) const;

  std::vector<std::vector<NodeId>> _node_lists;   ///< per *NODE PRINT of the step, by label
  std::vector<std::vector<ElemId>> _elem_lists;   ///< per *EL PRINT of the step
  std::vector<NodeId> _all_nodes;                 ///< every node, by label
  std::vector<std::uint8_t> _node_mark;           ///< scratch: nodes in the frame (per NodeId)
  std::vector<NodeId> _frame_nodes;               ///< scratch: nodes in the frame, by label
  std::vector<const ElementResult*> _frame_elems; ///< scratch: elements in the frame, by label
  std::vector<std::uint8_t> _elem_mark;
  /// ENER, ELSE, EVOL, COORD: written only in steps that request them (S, E, SF, … always)
  std::array<bool, kNumElemVars> _requested{};
  std::vector<double> _avg; ///< scratch: point averages

  /// Component names seen per element type and variable (for "element_types").
  struct TypeComponents {
    std::array<std::vector<std::string>, kNumElemVars> names; ///< indexed by ElemVar
    bool seen = false;
  };
  /// by (ElementType, type name): the library types in their order, then the deck's U1, Z1 …
  std::map<std::pair<int, std::string>, TypeComponents> _components;
  TypeComponents& components(const Model& model, ElemId e);
};

} // namespace gapfem
