#pragma once
/// @file step.hpp
/// One analysis step (*STEP … *END STEP): procedure, incrementation controls, the resolved loads
/// and boundary conditions active in the step, and the output requests.
#include "common/error.hpp"
#include "model/loads.hpp"
#include "model/output_request.hpp"
#include "model/section.hpp"

#include <string>
#include <vector>

namespace gapfem {

enum class Procedure : std::uint8_t { Static, HeatTransfer, CoupledTempDisp };
std::string_view procedure_name(Procedure p);

/// Time incrementation of *STATIC, *HEAT TRANSFER and *COUPLED TEMPERATURE-DISPLACEMENT.
struct Incrementation {
  double initial = 0.0; ///< 0: default (= period)
  double period = 1.0;
  double minimum = 0.0; ///< 0: default min(initial, 1e-5 * period)
  double maximum = 0.0; ///< 0: default (= period)
  bool direct = false;  ///< DIRECT: fixed increments of `initial`, no cut-backs
  bool steady_state = true; ///< heat transfer / coupled: STEADY STATE (true) or transient
  double deltmx = 0.0;  ///< transient: max temperature change per increment (0: none)
};

/// *CHANGE FRICTION, ELSET= followed by *FRICTION: new friction for some gap elements.
struct FrictionChange {
  std::vector<ElemId> elements;
  FrictionSpec friction;
  SourceLocation loc;
};

struct Step {
  int number = 0;
  std::string name;
  SourceLocation loc;
  Procedure procedure = Procedure::Static;
  bool nlgeom = false;
  int max_increments = 100;      ///< *STEP, INC=
  bool ramp_default = true;      ///< default amplitude variation: RAMP (true) or STEP
  /// *STEP, UNSYMM=YES: keep the unsymmetric load stiffness of follower loads (unsymmetric solver);
  /// by default its symmetric part is used, as in Abaqus/Standard
  bool unsymmetric = false;
  Incrementation inc;

  std::vector<BoundaryEntry> boundary;
  std::vector<NodalLoad> cloads; ///< *CLOAD (DOF 1-6) and *CFLUX (DOF 11)
  std::vector<DistributedLoad> dloads;
  std::vector<NodalTemperature> temperatures;
  std::vector<InterferenceEntry> interference;
  std::vector<FrictionChange> friction_changes;

  std::vector<NodePrintRequest> node_prints;
  std::vector<ElPrintRequest> el_prints;
  std::vector<FieldOutputRequest> field_outputs;
};

} // namespace gapfem
