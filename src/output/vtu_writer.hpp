#pragma once
/// @file vtu_writer.hpp
/// ParaView output: one VTK UnstructuredGrid file (job_<step>_<inc>.vtu, raw
/// appended binary data, UInt64 block headers) per field frame, and the
/// collection job.pvd listing them by total time.
#include "output/output_file.hpp"
#include "output/vtu_cell_data.hpp"
#include "results/results.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace gapfem {

/// VTK cell type of an element with `n_nodes` nodes (1 vertex, 3 line, 5
/// triangle, 9 quad, 10 tetra, 12 hexahedron, 24 quadratic tetra), or 0 when
/// there is no matching VTK cell.
int vtk_cell_type(ElementType type, int n_nodes);
/// Position in the Abaqus connectivity of the node that VTK expects at position
/// `vtk_index`. Abaqus and VTK order the nodes of every supported element the
/// same way (corners, then C3D10 mid-edge nodes on edges 1-2, 2-3, 3-1, 1-4,
/// 2-4, 3-4), so this is the identity; it is kept as the single place to change
/// should an element with a different order be added.
int vtk_node_from_abaqus(ElementType type, int vtk_index);

/// Writes ParaView files for the frames with Frame::field_due.
class VtuWriter : public ResultWriter {
 public:
  /// Files go to `directory` and are named after `job`.
  VtuWriter(std::filesystem::path directory, std::string job);

  void begin(const Model& model) override;
  void frame(const Model& model, int step_index, const Frame& frame) override;
  std::string_view restart_key() const override { return "vtu"; }
  void save_state(ArchiveWriter& out) override;
  void resume(const Model& model, int step_index, ArchiveReader& state,
              const ResumeFiles& from) override;

 private:
  struct PvdEntry {
    double time = 0.0;
    std::string file;
  };
  void write_pvd();
  void write_pvd(const std::string& name, const std::vector<PvdEntry>& entries);
  /// A *FREQUENCY step's modes: job_step<N>_modes.pvd, the mode number as the time (ParaView
  /// steps through the modes); they stay out of job.pvd, whose times are the analysis's.
  void write_modes_pvd(int step);
  /// Cells and labels of the model (once).
  void build_topology(const Model& model);

  std::filesystem::path _dir;
  std::string _job;
  std::vector<PvdEntry> _entries;
  std::vector<PvdEntry> _mode_entries; ///< of the *FREQUENCY step being written

  // topology, built once in begin()
  std::vector<std::int32_t> _connectivity;
  std::vector<std::int64_t> _offsets;
  std::vector<std::uint8_t> _cell_types;
  std::vector<std::int32_t> _type_ids; ///< ElementType value per cell
  /// with part instances: the element's label in its part and its instance (1-based; 0 for the
  /// assembly level), and the same for the nodes
  std::vector<Label> _elem_local, _node_local;
  std::vector<std::int32_t> _elem_instance, _node_instance;
  bool _has_gaps = false;
  std::string _type_legend; ///< " 6=C3D8 15=GAPUNI": the element_type ids present in the model

  output::VtuCellData _cells; ///< per-frame cell data (reused)
};

} // namespace gapfem
