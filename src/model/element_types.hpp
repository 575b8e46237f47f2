#pragma once
/// @file element_types.hpp
/// The element types gapfem knows, with their static properties (nodes, family, model space).
#include "common/types.hpp"
#include "model/cell_shape.hpp"

#include <optional>
#include <span>
#include <string_view>

namespace gapfem {

enum class ElementType : std::uint8_t {
  // structural
  SPRING1,
  SPRING2,
  SPRINGA,
  T2D2,
  T3D2,
  B31,
  // continuum stress/displacement
  C3D8,
  C3D4,
  C3D10,
  CPS3,
  CPS4,
  CPE3,
  CPE4,
  CAX3,
  CAX4,
  // gap contact
  GAPUNI,
  GAPCYL,
  GAPSPHER,
  GAPUNIT,
  DGAP,
  // heat transfer
  DC1D2,
  DC2D3,
  DC2D4,
  DCAX3,
  DCAX4,
  DC3D4,
  DC3D8,
  DC3D10,
  // coupled temperature-displacement
  T2D2T,
  T3D2T,
  CPS4T,
  CPE4T,
  CAX4T,
  C3D4T,
  C3D8T,
  // added with the quadratic and wedge elements (ids are stable: new types go last)
  C3D20,
  C3D20R,
  C3D15,
  C3D6,
  CPS8,
  CPS8R,
  CPE8,
  CPE8R,
  CAX8,
  CAX8R,
  CPS6,
  CPE6,
  CAX6,
  DC3D20,
  DC3D15,
  DC3D6,
  DC2D8,
  DC2D6,
  DCAX8,
  DCAX6,
  C3D20T,
  C3D20RT,
  C3D6T,
  CPS8T,
  CPS8RT,
  CPE8T,
  CPE8RT,
  CAX8T,
  CAX8RT,
  C3D8I,
  CPS4I,
  CPE4I,
  CAX4I,
  C3D8R,
  CPS4R,
  CPE4R,
  CAX4R,
  C3D8RT,
  CPS4RT,
  CPE4RT,
  CAX4RT,
  B32,
  B21,
  B22,
  PIPE31,
  PIPE32,
  // shells (DOFs 1-6 per node)
  S4,
  S4R,
  S3,
  S3R,
  S8R,
  // CalculiX's names: B32 with reduced integration (gapfem's B32 already uses two points) and the
  // fully integrated eight-node shell
  B32R,
  S8,
  // heat-transfer shells (DOFs 11, 12, … through the thickness)
  DS3,
  DS4,
  DS8,
  // coupled temperature-displacement shells (DOFs 1-6 and 11, 12, …)
  S3RT,
  S4T,
  S4RT,
  S8RT,
  // point inertias (*MASS, *ROTARY INERTIA)
  MASS,
  ROTARYI,
  // dashpots (*DASHPOT): a force per relative velocity, like SPRING1, SPRING2, SPRINGA
  DASHPOT1,
  DASHPOT2,
  DASHPOTA,
  // elements the deck defines: user elements U1, U2, … (*USER ELEMENT) and substructures Z1, …
  // (*SUBSTRUCTURE GENERATE); their nodes, DOFs and names come from the model
  // (Mesh::elem_variant, Model::user_elements / Model::substructures)
  USER,
  SUBSTRUCTURE,
};

enum class ElementFamily : std::uint8_t {
  Spring,
  Truss,
  Beam,
  Continuum,
  Gap,
  HeatTransfer,
  Shell,
  User,         ///< *USER ELEMENT (linear matrix or UEL)
  Substructure, ///< a reduced linear part (Zn)
  Mass          ///< MASS, ROTARYI: a point inertia (*MASS, *ROTARY INERTIA)
};

/// Which model space an element type requires.
enum class SpaceRequirement : std::uint8_t { Any, Planar, Axisymmetric, ThreeD };

/// The space the whole model lives in (decided from its elements).
enum class ModelSpace : std::uint8_t { ThreeD, Planar, Axisymmetric };

/// Plane/axisymmetric kinematics of a continuum element.
enum class PlaneKind : std::uint8_t { None, PlaneStress, PlaneStrain, Axisymmetric };

struct ElementTypeInfo {
  ElementType type;
  std::string_view name;
  int n_nodes; ///< 0 for USER and SUBSTRUCTURE: their node count is the model's (per variant)
  ElementFamily family;
  SpaceRequirement space;
  PlaneKind plane;
  bool displacement; ///< carries displacement DOFs
  bool temperature;  ///< carries DOF 11
  /// The reference cell (continuum, heat-transfer and two-node line elements whose faces or ends
  /// carry surfaces and loads); nullopt for springs and gaps.
  std::optional<Shape> cell = std::nullopt;
};

const ElementTypeInfo& element_info(ElementType type);
/// True for the quadratic reduced-integration continuum types (C3D20R, CPS8R, … and their T twins),
/// which keep zero-energy modes; the first-order ones (C3D8R, …) have hourglass control.
bool info_reduced(const ElementTypeInfo& info);
/// Case-insensitive lookup of an Abaqus element type name; nullopt if gapfem does not know it.
std::optional<ElementType> element_type_from_name(std::string_view name);
std::span<const ElementTypeInfo> all_element_types();
std::string_view model_space_name(ModelSpace s);

} // namespace gapfem
