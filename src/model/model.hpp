#pragma once
/// @file model.hpp
/// The Model aggregate: mesh, sets, materials, sections, amplitudes and steps. Built once by the
/// input layer (io/inp/model_builder) and read-only afterwards.
#include "model/amplitude.hpp"
#include "model/constraints.hpp"
#include "model/material.hpp"
#include "model/mesh.hpp"
#include "model/section.hpp"
#include "model/spectrum.hpp"
#include "model/step.hpp"
#include "model/user_element.hpp"

#include <fmt/format.h>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gapfem {

/// A surface: element-based (*SURFACE, TYPE=ELEMENT: element faces, 1-based face numbers) or
/// node-based (TYPE=NODE: nodes with an area or weight each, default 1).
struct Surface {
  struct Face {
    ElemId elem = -1;
    int face = 0;
  };
  struct WeightedNode {
    NodeId node = -1;
    double area = 1.0;
  };
  std::string name;
  bool node_based = false;
  std::vector<Face> faces;
  std::vector<WeightedNode> nodes; ///< node-based surfaces
  SourceLocation loc;
};

/// *PHYSICAL CONSTANTS.
struct PhysicalConstants {
  std::optional<double> absolute_zero;
  std::optional<double> stefan_boltzmann;
  SourceLocation loc;
};

class UserCode;

struct Model {
  std::string heading;
  std::string job_name;
  std::vector<std::string> source_files; ///< indexed by SourceRef::file; [0] is the main deck

  Mesh mesh;
  ModelSpace space = ModelSpace::ThreeD;

  /// Sets by upper-case name; members sorted and unique.
  std::map<std::string, std::vector<NodeId>> nsets;
  std::map<std::string, std::vector<ElemId>> elsets;
  std::map<std::string, Surface> surfaces;

  std::vector<Material> materials;
  std::vector<SolidSection> solid_sections;
  std::vector<SectionControls> section_controls;
  std::vector<BeamSection> beam_sections;
  std::vector<ShellSection> shell_sections;
  /// *NODAL THICKNESS: per node (0 where not given; empty when the deck has none)
  std::vector<double> nodal_thickness;
  std::vector<SpringSection> spring_sections;
  std::vector<MassSection> mass_sections; ///< *MASS and *ROTARY INERTIA
  std::vector<GapSection> gap_sections;
  std::vector<PropertyRef> element_property; ///< per element
  /// *USER ELEMENT definitions (Mesh::elem_variant of a USER element indexes them) and the
  /// *UEL PROPERTY records (PropertyRef::Kind::User indexes them)
  std::vector<UserElementType> user_elements;
  std::vector<UelProperty> uel_properties;
  /// The compiled user subroutines (`gapfem --user`): set by the job before the analysis; null
  /// when none were given.
  std::shared_ptr<const UserCode> user_code;
  /// Substructure types used by Zn elements (Mesh::elem_variant indexes them) and their placing
  /// (*SUBSTRUCTURE PROPERTY; PropertyRef::Kind::Substructure indexes them)
  std::vector<SubstructureType> substructures;
  std::vector<SubstructureProperty> substructure_properties;
  /// *MATRIX INPUT matrices, and the stiffness terms *MATRIX ASSEMBLE adds to the model
  std::vector<MatrixInput> matrix_inputs;
  std::vector<MatrixTerm> matrix_terms;

  std::vector<Amplitude> amplitudes;
  std::vector<Spectrum> spectra; ///< *SPECTRUM (response spectrum analyses)
  /// Linear constraints (*EQUATION, *MPC, couplings, *TIE), one row each.
  std::vector<LinearConstraint> constraints;
  /// *TRANSFORM systems and, per node, the index of its system (-1: global); empty if none.
  std::vector<NodeTransform> transforms;
  std::vector<int> node_transform;
  /// The local axes of a transformed node (rows e1, e2, e3), nullopt for a global node.
  std::optional<std::array<double, 9>> node_axes(NodeId n) const {
    if (node_transform.empty() || node_transform[n] < 0) return std::nullopt;
    return local_axes(transforms[node_transform[n]], mesh.coords[n]);
  }

  /// *INITIAL CONDITIONS, TYPE=VELOCITY | ROTATING VELOCITY: velocities at the start of the
  /// analysis (a first step that is *DYNAMIC starts from them)
  struct InitialVelocity {
    NodeId node = -1;
    int dof = 1; ///< 1-6
    double value = 0.0;
    bool global = false; ///< in global directions (ROTATING VELOCITY), else the node's system
  };
  std::vector<InitialVelocity> initial_velocities;
  SourceLocation initial_velocity_loc;

  std::vector<double> initial_temperature; ///< per node (0 where not given)
  bool has_initial_temperature = false;
  /// some *TEMPERATURE gives through-section gradients (values 2, 3; shells and beams)
  bool has_temperature_gradients = false;
  PhysicalConstants constants;

  std::vector<Step> steps;
  /// *RESTART, READ: the steps before `restart_read->step` come from the old job's deck
  std::optional<RestartRead> restart_read;
  std::vector<std::string> warnings; ///< non-fatal input remarks, listed at the end of the run

  /// Deck location of an element's definition line.
  SourceLocation element_location(ElemId e) const;
  /// Part instances of an assembly deck (upper-case names); key_instance(k) = index + 1.
  std::vector<std::string> instances;

  /// The element type as the deck names it: "C3D8", or "U1" / "Z2" for the deck's own types.
  std::string_view element_type_name(ElemId e) const;
  /// Which fields an element carries: its type's, or for the deck's own types the DOFs the deck
  /// gives them (displacements or rotations 1-6; temperatures 11 …).
  struct ElementFields {
    bool displacement = false, temperature = false;
  };
  ElementFields element_fields(ElemId e) const;
  EntityLabel node_label(NodeId n) const { return {mesh.node_labels[n], &instances}; }
  EntityLabel element_label(ElemId e) const { return {mesh.elem_labels[e], &instances}; }
  EntityLabel label_of_key(Label key) const { return {key, &instances}; }
  /// Characteristic model size: the diagonal of the bounding box of all nodes (> 0 and finite,
  /// also for coordinates near the double range: at most the largest double).
  double model_size() const;
};

} // namespace gapfem
