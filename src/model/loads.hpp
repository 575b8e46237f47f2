#pragma once
/// @file loads.hpp
/// History data of one step, fully resolved by the model builder: the complete set of boundary
/// conditions and loads active in the step (after OP=MOD/NEW and propagation from earlier steps).
#include "common/error.hpp"
#include "common/types.hpp"

#include <cstdint>
#include <vector>

namespace gapfem {

/// *BOUNDARY, TYPE=: what the value prescribes (docs/theory/dynamics.md, "Base motion").
enum class BoundaryType : std::uint8_t {
  Displacement, ///< the DOF's value (the default)
  Velocity,     ///< its time derivative; the displacement follows by exact integration
  Acceleration  ///< its second time derivative (*DYNAMIC steps only)
};

/// *BOUNDARY entry: prescribed value of one DOF.
struct BoundaryEntry {
  NodeId node = -1;
  DofType dof = DofType::U1;
  BoundaryType type = BoundaryType::Displacement;
  double value = 0.0;
  int amplitude = -1;      ///< index into Model::amplitudes, -1: the step's default variation
  bool fixed = false;      ///< *BOUNDARY, FIXED: hold the value reached at the start of the step
  bool propagated = false; ///< carried over unchanged from the previous step (held constant)
  SourceLocation loc;
};

/// *CLOAD (DOF 1-6) or *CFLUX (DOF 11) entry.
struct NodalLoad {
  NodeId node = -1;
  DofType dof = DofType::U1;
  double value = 0.0;
  int amplitude = -1;
  bool propagated = false;
  /// *CLOAD, IMAGINARY in a *STEADY STATE DYNAMICS step: the load's imaginary part
  bool imaginary = false;
  SourceLocation loc;
};

enum class DistLoadKind : std::uint8_t {
  Pressure,    ///< P (beams/2-D edges, DSLOAD P) or Pn on face n: pressure on a face
  Gravity,     ///< GRAV: magnitude g, direction vector; force = rho * g * dir per volume
  BodyForce,   ///< BX, BY, BZ: force per unit volume in a global direction (direction = unit axis)
  BodyFlux,    ///< BF: heat per unit volume per time
  SurfaceFlux, ///< Sn / DSFLUX S: heat flux into face n per area
  Film,        ///< Fn / SFILM F: film coefficient h (magnitude), sink temperature
  /// Rn / SRADIATE R: emissivity (magnitude), sink temperature; the flux into the face is
  /// eps sigma ((T_sink - Z)^4 - (T - Z)^4) with *PHYSICAL CONSTANTS' sigma and Z
  Radiation,
  /// beams: force per unit reference length; face 1/2: P1/P2 along the section's n1/n2, face 0:
  /// PX/PY/PZ along the global axis in `direction`
  LineLoad,
  /// PIPE31/PIPE32: PI (face 1, internal) or PE (face 2, external) pressure, closed-end condition;
  /// HPI/HPE (`hydrostatic`) the same with a pressure varying linearly with height
  PipePressure,
  /// CENTRIF: magnitude omega^2 (angular velocity squared); the axis runs through `point` along
  /// `direction` (unit); force rho omega^2 r per volume, r the distance vector from the axis at
  /// the current position (NLGEOM, with its load stiffness) or the reference one
  Centrifugal,
};

/// *DLOAD / *DSLOAD / *DFLUX / *DSFLUX / *FILM / *SFILM entry, per element (and face).
struct DistributedLoad {
  ElemId elem = -1;
  DistLoadKind kind = DistLoadKind::Pressure;
  int face = 0;           ///< 1-based face (Pn, Sn, Fn, surface faces), 0: body or whole element
  double magnitude = 0.0; ///< pressure, g, body force, flux, film coefficient
  Vec3 direction{0.0, 0.0, 0.0}; ///< GRAV, BX/BY/BZ direction, CENTRIF axis (unit vector)
  Vec3 point{0.0, 0.0, 0.0};     ///< CENTRIF: a point of the rotation axis
  double sink_temperature = 0.0; ///< Film, Radiation
  double stefan_boltzmann = 0.0; ///< Radiation: *PHYSICAL CONSTANTS, STEFAN BOLTZMANN=
  double absolute_zero = 0.0;    ///< Radiation: *PHYSICAL CONSTANTS, ABSOLUTE ZERO=
  double diameter = 0.0;         ///< PI/PE: effective diameter (0: the section's)
  /// HPI/HPE: p = magnitude (z0 - z) / (z0 - z1) at height z (global Z; Y in planar models),
  /// zero beyond the zero-pressure height z0 (on the side away from z1)
  bool hydrostatic = false;
  double z0 = 0.0, z1 = 0.0;
  int amplitude = -1;      ///< magnitude amplitude (film: sink temperature amplitude)
  int film_amplitude = -1; ///< film coefficient amplitude
  bool propagated = false;
  SourceLocation loc;
};

/// *TEMPERATURE entry: prescribed nodal temperature (predefined field) in a stress analysis.
struct NodalTemperature {
  NodeId node = -1;
  double value = 0.0;
  /// values 2 and 3 of the data line: shells dT/dn through the thickness (and 0); beams dT/dx2,
  /// dT/dx1 in the section's local directions (Abaqus TEMPERATURE=GRADIENT(S))
  std::array<double, 2> gradient{0.0, 0.0};
  int amplitude = -1;
  bool propagated = false;
  SourceLocation loc;
};

/// *CONTACT INTERFERENCE, TYPE=ELEMENT entry (one gap element).
struct InterferenceEntry {
  ElemId elem = -1;
  double allowance = 0.0;  ///< v: allowable interference at amplitude 1
  bool shrink = false;     ///< SHRINK: v = the element's own initial overclosure
  int amplitude = -1;      ///< -1: ramp from 1 at step start to 0 at step end
  bool propagated = false; ///< carried over unchanged from the previous step
  SourceLocation loc;
};

} // namespace gapfem
