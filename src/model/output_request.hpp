#pragma once
/// @file output_request.hpp
/// Output requests, turned into typed ids once, in the input layer.
#include "common/error.hpp"
#include "common/types.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gapfem {

/// Node variables. V, VR (velocities) and A, AR (accelerations) exist in *DYNAMIC steps only: a
/// request for them in another step writes nothing (the deck gets a warning).
enum class NodeVar : std::uint8_t { U, UR, RF, RM, CF, CM, NT, RFL, CFL, V, VR, A, AR };
inline constexpr std::size_t kNumNodeVars = 13;
/// V, VR, A, AR: the rates of a dynamic step.
constexpr bool is_rate_var(NodeVar v) {
  return v == NodeVar::V || v == NodeVar::VR || v == NodeVar::A || v == NodeVar::AR;
}
enum class ElemVar : std::uint8_t {
  S,   ///< stress (gaps: S11 contact pressure, S12/S13 friction shear)
  E,   ///< strain (gaps: E11 clearance, E12/E13 accumulated slip)
  SF,  ///< section forces and moments (beams), axial force (trusses), spring force
  HFL, ///< heat flux (gaps: HFL1 across the gap)
  /// element nodal forces (user elements, substructures): per element node, the force the element
  /// exerts on it (its internal force vector), one component per DOF (NFORC1 … NFORC6, NFORC11 …)
  NFORC,
  ENER,  ///< energy densities at the integration points (SENER: the elastic strain energy density)
  ELSE,  ///< the element's elastic strain energy (whole element)
  EVOL,  ///< the element's volume, current under NLGEOM (whole element)
  COORD, ///< the coordinates of the integration points, current under NLGEOM
};
inline constexpr std::size_t kNumElemVars = 9;
/// A whole-element variable: one value per element, printed without a point number.
constexpr bool is_whole_element_var(ElemVar v) {
  return v == ElemVar::ELSE || v == ElemVar::EVOL;
}

std::optional<NodeVar> node_var_from_name(std::string_view name);
std::optional<ElemVar> elem_var_from_name(std::string_view name);
std::string_view node_var_name(NodeVar v);
std::string_view elem_var_name(ElemVar v);

/// *NODE PRINT
struct NodePrintRequest {
  std::string nset; ///< empty: all nodes
  std::vector<NodeId> nodes;
  int frequency = 1; ///< every n-th increment (0: never except the last increment of the step)
  std::vector<NodeVar> vars;
  bool totals = false;
  bool totals_only = false; ///< TOTALS=ONLY: the column totals without the rows and summary
  bool summary = true;
  /// GLOBAL=YES: vectors in global components also at *TRANSFORM nodes (default: local system)
  bool global = false;
  SourceLocation loc;
};

enum class ElPosition : std::uint8_t { IntegrationPoints, Centroidal, Averaged };

/// *EL PRINT
struct ElPrintRequest {
  std::string elset; ///< empty: all elements
  std::vector<ElemId> elements;
  int frequency = 1;
  std::vector<ElemVar> vars;
  bool totals = false;
  bool totals_only = false; ///< TOTALS=ONLY: the column totals without the rows and summary
  bool summary = true;
  ElPosition position = ElPosition::IntegrationPoints;
  /// section points to print (1-based, a data line of numbers); empty: Abaqus's default, the
  /// bottom and top (SNEG, SPOS) of shells and every section point of beams
  std::vector<int> section_points;
  SourceLocation loc;
};

/// *MONITOR: one degree of freedom whose value the .sta file shows after converged increments.
struct DofMonitor {
  NodeId node = -1;
  int dof = 0;       ///< Abaqus DOF number: 1-6, 11 (temperature)
  int frequency = 1; ///< every n-th increment (and the last of each step)
  SourceLocation loc;
};

/// *RESTART, WRITE: when a step writes restart records into job.res (docs/restart.md).
struct RestartWrite {
  int frequency = 0;       ///< every n-th increment (and the last of the step)
  int number_interval = 0; ///< at n evenly spaced step times (the first increment at or past each)
  bool overlay = false;    ///< keep only the latest record
  SourceLocation loc;
  bool on() const { return frequency > 0 || number_interval > 0; }
};

/// *RESTART, READ: the deck continues an earlier job (gapfem deck.inp --oldjob OLD).
struct RestartRead {
  int step = 0;          ///< STEP= (0: the last step with restart data)
  int increment = 0;     ///< INC= (0: the last increment of that step with restart data)
  bool end_step = false; ///< END STEP: the step ends at the restart point
  SourceLocation loc;
};

/// *OUTPUT, FIELD with its *NODE OUTPUT / *ELEMENT OUTPUT: drives ParaView (VTU) frames.
struct FieldOutputRequest {
  int frequency = 1; ///< every n-th increment; the last increment of a step is always written
  std::vector<NodeVar> node_vars; ///< every variable requested, on any set
  std::vector<ElemVar> elem_vars;
  /// A variable of a *NODE OUTPUT / *ELEMENT OUTPUT line with NSET= / ELSET=: written on that
  /// set only (NaN elsewhere) unless another line asks for it on the whole model.
  std::vector<std::pair<NodeVar, std::vector<NodeId>>> node_sets;
  std::vector<std::pair<ElemVar, std::vector<ElemId>>> elem_sets;
  /// variables asked for on the whole model (no NSET= / ELSET=)
  std::vector<NodeVar> node_vars_everywhere;
  std::vector<ElemVar> elem_vars_everywhere;
  SourceLocation loc;
};

/// *OUTPUT, HISTORY: values over time after every n-th increment of the step, written as the
/// step's history (job.results.json "history", the report's charts; docs/results.md): the
/// whole-model energies (*ENERGY OUTPUT, or VARIABLE=PRESELECT/ALL as Abaqus preselects them),
/// node variables at a node set's nodes (*NODE OUTPUT, NSET=) and element variables averaged
/// over each element's points (*ELEMENT OUTPUT, ELSET=).
struct HistoryOutputRequest {
  int frequency = 1; ///< every n-th increment; the last increment of a step is always written
  bool energies = false;
  std::vector<std::pair<NodeVar, std::vector<NodeId>>> node_vars;
  std::vector<std::pair<ElemVar, std::vector<ElemId>>> elem_vars;
  SourceLocation loc;
};

/// *NODE FILE / *EL FILE: results written to job.frd, CalculiX's results format that its viewer
/// cgx reads (docs/results.md, "The .frd file"). Element variables are written at the nodes,
/// extrapolated and averaged (output/nodal_average.hpp).
struct FileOutputRequest {
  bool element = false; ///< *EL FILE (else *NODE FILE)
  int frequency = 1;    ///< every n-th increment; the last increment of a step is always written
  std::vector<NodeVar> node_vars;
  std::vector<ElemVar> elem_vars;
  std::string set;                   ///< NSET= / ELSET=; empty: the whole model
  std::vector<std::int32_t> members; ///< the set's nodes or elements (empty with no set)
  bool global = false; ///< *NODE FILE, GLOBAL=YES: global components at *TRANSFORM nodes
  SourceLocation loc;
};

} // namespace gapfem
