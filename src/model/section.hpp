#pragma once
/// @file section.hpp
/// Section and property records that bind an element set to a material or a gap definition.
#include "common/error.hpp"
#include "common/types.hpp"
#include "model/element_types.hpp"
#include "model/table.hpp"

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace gapfem {

/// Hourglass control of the first-order reduced-integration solids (C3D8R, CPS4R, CPE4R, CAX4R
/// and their T twins); docs/theory/continuum.md, "Hourglass control".
enum class HourglassControl : std::uint8_t {
  Enhanced, ///< the incompatible-mode stiffness projected onto the hourglass modes (default)
  Stiffness ///< total stiffness: r_F G V (b:b) per hourglass mode, r_F = 0.005 (scaled)
};

/// *SECTION CONTROLS, NAME=, HOURGLASS=.
struct SectionControls {
  std::string name;
  HourglassControl hourglass = HourglassControl::Enhanced;
  double scale = 1.0; ///< displacement hourglass scaling factor (data line field 1)
  SourceLocation loc;
};

/// *SOLID SECTION: continuum, truss and heat-transfer elements.
struct SolidSection {
  std::string elset;
  int material = -1;
  int controls = -1;      ///< CONTROLS=: index into Model::section_controls, -1 for the defaults
  double thickness = 1.0; ///< plane thickness (CPS/CPE), truss cross-section area; 1 if not given
  bool thickness_given = false;
  SourceLocation loc;
};

/// One data line of *BEAM ADDED INERTIA (Keywords Reference): a mass per unit length at (x1, x2)
/// of the section's local axes with its rotary inertia per length about that centre of mass, given
/// in axes turned by `angle` (degrees) from local 1 toward local 2; I12 is the inertia tensor's
/// entry, -integral x1 x2 dm (Theory Guide, "Mass and inertia for Timoshenko beams").
struct BeamAddedInertia {
  double mass = 0.0;
  double x1 = 0.0, x2 = 0.0;
  double angle = 0.0;
  double I11 = 0.0, I22 = 0.0, I12 = 0.0;
  double alpha = 0.0;     ///< ALPHA of its keyword: C = alpha M_added (direct integration)
  double composite = 0.0; ///< COMPOSITE: for mode-based procedures only (not used by gapfem)
  SourceLocation loc;
};

/// *BEAM SECTION and *BEAM GENERAL SECTION (B21, B22, B31, B32, PIPE31, PIPE32).
struct BeamSection {
  /// library shapes (docs/theory/structural.md §3.1); General: SECTION=GENERAL of *BEAM GENERAL
  /// SECTION (A, I11, I12, I22, J given directly)
  enum class Shape { Rect, Circ, Pipe, Box, I, General, Hex, L, Trapezoid };
  std::string elset;
  int material = -1; ///< *BEAM SECTION; -1 for *BEAM GENERAL SECTION (constants below)
  Shape shape = Shape::Rect;
  /// RECT: a (local 1), b (local 2); CIRC: r; PIPE: r (outer), t; BOX: a, b, t1, t2, t3, t4;
  /// I: l, h, b1, b2, t1, t2, t3; GENERAL: A, I11, I12, I22, J; HEX: r, t; L: a, b, t1, t2;
  /// TRAPEZOID: a (bottom width), b (height), c (top width), d (origin above the bottom)
  std::vector<double> dims;
  Vec3 n1{0.0, 0.0, -1.0}; ///< approximate local 1-direction (Abaqus default (0,0,-1))
  bool n1_given = false;
  /// *BEAM GENERAL SECTION: linear elastic section, E, G and alpha from data line 3
  bool general = false;
  double E = 0.0, G = 0.0, alpha = 0.0;
  double density = 0.0; ///< DENSITY= of *BEAM GENERAL SECTION (0: none)
  /// *TRANSVERSE SHEAR STIFFNESS: K23 (shear along local 2), K13 (along local 1); 0 = default
  double k23 = 0.0, k13 = 0.0;
  /// *SECTION POINTS after *BEAM GENERAL SECTION: (x1, x2) of the points where S11 and E11 are
  /// reported (replacing the section's own points)
  std::vector<std::array<double, 2>> output_points;
  double slenderness = -1.0; ///< slenderness compensation factor given there (-1: default)
  /// *BEAM ADDED INERTIA after the section: each data line, summed into the element's mass
  std::vector<BeamAddedInertia> added_inertia;
  bool invalid = false; ///< its keyword had an error (reported): nothing more is checked
  SourceLocation loc;
};

/// *SHELL SECTION (S3, S3R, S4, S4R, S8R): a homogeneous elastic shell.
struct ShellSection {
  std::string elset;
  int material = -1;
  double thickness = 0.0; ///< data line field 1; with NODAL THICKNESS the nodal values
  int n_points = 5;       ///< Simpson points through the thickness (odd, >= 3)
  /// OFFSET=: position of the reference surface as a fraction of the thickness from the mid-surface
  /// (SPOS = 0.5: the top surface, SNEG = -0.5: the bottom)
  double offset = 0.0;
  bool nodal_thickness = false; ///< NODAL THICKNESS: thicknesses from *NODAL THICKNESS
  /// *TRANSVERSE SHEAR STIFFNESS after the section: K11, K22 (0 = default 5/6 G t)
  double k11 = 0.0, k22 = 0.0;
  bool invalid = false; ///< its keyword had an error (reported): nothing more is checked
  SourceLocation loc;
};

/// *SPRING (SPRING1, SPRING2, SPRINGA): linear stiffness, optionally temperature dependent; or
/// *DASHPOT (DASHPOT1, DASHPOT2, DASHPOTA, `dashpot`): the same record with the coefficient c
/// (force per relative velocity) in `stiffness`, or with NONLINEAR the force-velocity table.
struct SpringSection {
  std::string elset;
  int dof1 = 0;            ///< Abaqus DOF number at node 1 (SPRING1/SPRING2); 0 for SPRINGA
  int dof2 = 0;            ///< Abaqus DOF number at node 2 (SPRING2)
  PropertyTable stiffness; ///< k (dashpot: c); key temperature
  bool dashpot = false;    ///< *DASHPOT: a force per relative velocity, not per displacement
  bool nonlinear = false;  ///< NONLINEAR: F from `force` at `relative`
  /// NONLINEAR: the force at each relative velocity (*DASHPOT) or relative displacement
  /// (*SPRING), strictly ascending; constant outside
  std::vector<double> force, relative;
  /// ORIENTATION= (SPRING1/2, DASHPOT1/2): its name, and once resolved (model_validate.cpp) the
  /// local axes 1, 2, 3 as unit vectors in global coordinates. The data line's DOFs are then
  /// local: DOF i (i + 3) acts along (about) axes[(i - 1) % 3] at each node.
  std::string orientation;
  std::optional<std::array<Vec3, 3>> axes;
  SourceLocation loc;
};

/// *MASS (MASS elements: the mass on the translational DOFs) or *ROTARY INERTIA (ROTARYI: the
/// inertia tensor about the node, on the rotational DOFs), for an element set.
struct MassSection {
  std::string elset;
  bool rotary = false;
  double mass = 0.0;               ///< MASS
  std::array<double, 6> inertia{}; ///< ROTARYI: I11, I22, I33, I12, I13, I23 (global axes)
  double alpha = 0.0;     ///< ALPHA: mass-proportional damping, C = alpha M (direct integration)
  double composite = 0.0; ///< COMPOSITE: for mode-based procedures only (not used by gapfem)
  SourceLocation loc;
};

// ---------------------------------------------------------------- gap contact properties

enum class PressureOverclosure { Hard, Exponential, Linear, Tabular };
enum class ContactMethod { Direct, Penalty, AugmentedLagrange };

/// *SURFACE BEHAVIOR after *GAP (normal behaviour). Pressure means force/area (force if no area).
struct SurfaceBehavior {
  bool given = false;
  PressureOverclosure law = PressureOverclosure::Hard;
  ContactMethod method = ContactMethod::Direct;
  bool no_separation = false;
  double c0 = 0.0,
         p0 = 0.0;    ///< EXPONENTIAL: clearance at zero pressure, pressure at zero clearance
  double slope = 0.0; ///< LINEAR: pressure per unit overclosure
  std::vector<double> table_p, table_g; ///< TABULAR: pressure vs overclosure, ascending overclosure
  double penalty_stiffness = 0.0;       ///< PENALTY / AUGMENTED LAGRANGE stiffness; 0 = automatic
  double max_stiffness = 0.0;           ///< K_max (EXPONENTIAL), 0 = none
  SourceLocation loc;
};

/// *FRICTION after *GAP (isotropic Coulomb).
struct FrictionSpec {
  bool given = false;
  bool rough = false;
  bool lagrange = false;
  std::optional<double> elastic_slip; ///< ELASTIC SLIP= absolute
  double slip_tolerance = 0.005;      ///< SLIP TOLERANCE= fraction of characteristic length
  double taumax = std::numeric_limits<double>::infinity();
  /// Data lines: mu, slip rate, contact pressure, temperature (dependencies as tabulated).
  struct Row {
    double mu = 0, slip_rate = 0, pressure = 0, temperature = 0;
  };
  std::vector<Row> rows;
  int n_columns = 1; ///< how many of (mu, slip rate, pressure, temperature) the data lines use
  SourceLocation loc;
};

/// *CONTACT DAMPING after *GAP.
struct ContactDampingSpec {
  bool given = false;
  double coefficient = 0.0; ///< force per unit relative velocity (per area if an area is given)
  double clearance = 0.0;   ///< c0: damping zero for clearance >= c0, full at contact
  double fraction = 0.0;    ///< fraction of c0 over which the coefficient stays at full value
  double tangent_fraction = 0.0;
  SourceLocation loc;
};

/// *GAP CONDUCTANCE after *GAP.
struct GapConductanceSpec {
  bool given = false;
  bool pressure = false; ///< PRESSURE: k as a function of contact pressure instead of clearance
  struct Row {
    double k = 0, x = 0, temperature = 0, mass_flow = 0;
  };
  std::vector<Row> rows;
  bool temperature_dependent = false;
  SourceLocation loc;
};

/// *GAP RADIATION after *GAP.
struct GapRadiationSpec {
  bool given = false;
  double emissivity_a = 0.0, emissivity_b = 0.0;
  std::vector<double> view_factor, clearance; ///< F(d), clearance ascending
  SourceLocation loc;
};

/// *GAP HEAT GENERATION after *GAP.
struct GapHeatGenerationSpec {
  bool given = false;
  double eta = 1.0;      ///< fraction of dissipated energy converted to heat
  double fraction = 0.5; ///< f: share of node 1 (the rest to node 2)
  SourceLocation loc;
};

/// *GAP, ELSET=… and the sub-options that follow it.
struct GapSection {
  std::string elset;
  double d = 0.0;                ///< clearance / min or max separation
  Vec3 direction{0.0, 0.0, 0.0}; ///< GAPUNI/GAPUNIT direction, GAPCYL axis (as given)
  bool direction_given = false;  ///< some of fields 2-4 non-zero
  double area = 1.0;
  bool area_given = false;
  bool ccx_penalty = false;    ///< CalculiX field 6 given: penalty gap of ccx
  double ccx_stiffness = 1e12; ///< field 6
  double ccx_tension = 1e-3;   ///< field 7
  SurfaceBehavior behavior;
  FrictionSpec friction;
  ContactDampingSpec damping;
  GapConductanceSpec conductance; ///< clearance-dependent (or the only, PRESSURE) table
  /// a second *GAP CONDUCTANCE, PRESSURE after a clearance-dependent one: used while the gap is
  /// closed, the clearance table while it is open (docs/theory/gap_elements.md)
  GapConductanceSpec conductance_pressure;
  GapRadiationSpec radiation;
  GapHeatGenerationSpec heat_generation;
  SourceLocation loc;
};

/// Which property record an element uses.
struct PropertyRef {
  enum class Kind : std::uint8_t {
    None,
    Solid,
    Beam,
    Spring,
    Gap,
    Shell,
    User,
    Substructure,
    Mass
  };
  Kind kind = Kind::None;
  std::int32_t index = -1;
  friend bool operator==(const PropertyRef&, const PropertyRef&) = default;
};

} // namespace gapfem
