#pragma once
/// @file dat_writer.hpp
/// job.dat: Abaqus-style printed tables for *NODE PRINT and *EL PRINT, a
/// self-check block after every step and an analysis summary at the end
/// (docs/results.md describes the layout).
#include "output/nodal_average.hpp"
#include "output/output_file.hpp"
#include "results/results.hpp"

#include <filesystem>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace gapfem {

/// Writes the printed output file (job.dat).
class DatWriter : public ResultWriter {
 public:
  /// `path`: the file to create (truncated at begin()).
  explicit DatWriter(std::filesystem::path path);

  void begin(const Model& model) override;
  void begin_step(const Model& model, int step_index) override;
  void increment(const IncrementInfo& info) override;
  void frame(const Model& model, int step_index, const Frame& frame) override;
  void modes(const Model& model, int step_index, const EigenSummary& modes) override;
  void end_step(const Model& model, int step_index, const StepSummary& summary) override;
  void end(const Model& model, const RunSummary& summary) override;
  std::string_view restart_key() const override { return "dat"; }
  void save_state(ArchiveWriter& out) override;
  void resume(const Model& model, int step_index, ArchiveReader& state,
              const ResumeFiles& from) override;

  /// The step runs with fixed time increments: *STATIC, DIRECT, and transient heat transfer or
  /// coupled steps without DELTMX (the rule of fixed_transient_increments,
  /// solver/thermal_step.hpp). The step header then says "FIXED TIME INCREMENTS" instead of
  /// "AUTOMATIC TIME CONTROL".
  static bool fixed_increments(const Step& step);

 private:
  /// Perturbation steps (dat_writer_modes.cpp): the step's header (*FREQUENCY: what it extracts;
  /// *RESPONSE SPECTRUM: its spectra and rules), each mode's header.
  void write_perturbation_header(const Step& step);
  void write_mode_header(const Model& model, const Frame& frame);
  /// The print lists of a step's requests.
  void prepare_step(const Model& model, int step_index);
  void write_increment_header(const Model& model, int step_index, const Frame& frame,
                              bool repeated);
  /// *STEADY STATE DYNAMICS: the due U and UR tables again with the frame's imaginary part.
  void write_imaginary_tables(const Model& model, const Step& step, const Frame& frame,
                              const std::vector<bool>& node_due);
  void write_node_table(const Model& model, const Frame& frame, const NodePrintRequest& request,
                        const std::vector<NodeId>& nodes, NodeVar var);
  void write_element_tables(const Model& model, const Frame& frame, const ElPrintRequest& request,
                            const std::vector<ElemId>& elements);
  /// One warning per request, variable and element type that has no value for it.
  void warn_unavailable(const ElPrintRequest& request, ElemVar var, std::string_view type_name);
  void write_element_table(const Model& model, const Frame& frame, const ElPrintRequest& request,
                           std::span<const ElemId> group, ElemVar var);
  /// POSITION=AVERAGED AT NODES on continuum and heat-transfer elements: one row per node of the
  /// group, the values extrapolated and averaged over the group's elements (nodal_average.hpp).
  void write_nodal_table(const Model& model, const Frame& frame, const ElPrintRequest& request,
                         std::span<const ElemId> group, ElemVar var, const OutputBlock& first);
  /// MAXIMUM / MINIMUM rows (with the ELEMENT or NODE at which they occur) and TOTAL of a table.
  void write_column_summary(const Model& model, const ElPrintRequest& request, std::size_t nc,
                            std::string_view entity);
  /// The rows of a block with section points (shells, beams): PT and SEC columns.
  void write_section_rows(const OutputBlock& block, const ElPrintRequest& request, bool shell,
                          const EntityLabel& label, std::size_t ncols, bool at_points);
  void write_checks(const Model& model, int step_index, const StepSummary& summary);

  std::filesystem::path _path;
  output::OutputFile _out;
  std::vector<std::vector<NodeId>> _node_lists; ///< per *NODE PRINT of the current step, by label
  std::vector<std::vector<ElemId>> _elem_lists; ///< per *EL PRINT, grouped by type, by label
  /// The increment printed last in the current step and which requests were printed for it: a
  /// step that stops early hands its last converged increment over again as the final frame, and
  /// only the requests not printed yet for it are printed then.
  int _printed_increment = -1;
  double _printed_dt = 0.0;
  std::vector<bool> _printed_node, _printed_el;
  /// (request location, variable, element type name) already warned about: a variable those
  /// elements do not have is one warning per run, not one per increment
  std::set<std::tuple<std::string, int, std::string>> _unavailable;
  std::vector<double> _avg;               ///< scratch: point averages
  std::vector<double> _max, _min, _total; ///< scratch: column summaries
  std::vector<Label> _max_at, _min_at;
  output::NodalAverager _averager;
};

} // namespace gapfem
