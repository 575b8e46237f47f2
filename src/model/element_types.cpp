#include "model/element_types.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <array>
#include <cctype>

namespace gapfem {
namespace {
using F = ElementFamily;
using S = SpaceRequirement;
using P = PlaneKind;
constexpr std::array<ElementTypeInfo, 102> kInfo = {{
    {ElementType::SPRING1, "SPRING1", 1, F::Spring, S::Any, P::None, true, false},
    {ElementType::SPRING2, "SPRING2", 2, F::Spring, S::Any, P::None, true, false},
    {ElementType::SPRINGA, "SPRINGA", 2, F::Spring, S::Any, P::None, true, false},
    {ElementType::T2D2, "T2D2", 2, F::Truss, S::Planar, P::None, true, false, Shape::Line2},
    {ElementType::T3D2, "T3D2", 2, F::Truss, S::ThreeD, P::None, true, false, Shape::Line2},
    {ElementType::B31, "B31", 2, F::Beam, S::ThreeD, P::None, true, false, Shape::Line2},
    {ElementType::C3D8, "C3D8", 8, F::Continuum, S::ThreeD, P::None, true, false, Shape::Hex8},
    {ElementType::C3D4, "C3D4", 4, F::Continuum, S::ThreeD, P::None, true, false, Shape::Tet4},
    {ElementType::C3D10, "C3D10", 10, F::Continuum, S::ThreeD, P::None, true, false, Shape::Tet10},
    {ElementType::CPS3, "CPS3", 3, F::Continuum, S::Planar, P::PlaneStress, true, false,
     Shape::Tri3},
    {ElementType::CPS4, "CPS4", 4, F::Continuum, S::Planar, P::PlaneStress, true, false,
     Shape::Quad4},
    {ElementType::CPE3, "CPE3", 3, F::Continuum, S::Planar, P::PlaneStrain, true, false,
     Shape::Tri3},
    {ElementType::CPE4, "CPE4", 4, F::Continuum, S::Planar, P::PlaneStrain, true, false,
     Shape::Quad4},
    {ElementType::CAX3, "CAX3", 3, F::Continuum, S::Axisymmetric, P::Axisymmetric, true, false,
     Shape::Tri3},
    {ElementType::CAX4, "CAX4", 4, F::Continuum, S::Axisymmetric, P::Axisymmetric, true, false,
     Shape::Quad4},
    {ElementType::GAPUNI, "GAPUNI", 2, F::Gap, S::Any, P::None, true, false},
    {ElementType::GAPCYL, "GAPCYL", 2, F::Gap, S::Any, P::None, true, false},
    {ElementType::GAPSPHER, "GAPSPHER", 2, F::Gap, S::Any, P::None, true, false},
    {ElementType::GAPUNIT, "GAPUNIT", 2, F::Gap, S::Any, P::None, true, true},
    {ElementType::DGAP, "DGAP", 2, F::Gap, S::Any, P::None, false, true},
    {ElementType::DC1D2, "DC1D2", 2, F::HeatTransfer, S::Any, P::None, false, true, Shape::Line2},
    {ElementType::DC2D3, "DC2D3", 3, F::HeatTransfer, S::Planar, P::None, false, true, Shape::Tri3},
    {ElementType::DC2D4, "DC2D4", 4, F::HeatTransfer, S::Planar, P::None, false, true,
     Shape::Quad4},
    {ElementType::DCAX3, "DCAX3", 3, F::HeatTransfer, S::Axisymmetric, P::Axisymmetric, false, true,
     Shape::Tri3},
    {ElementType::DCAX4, "DCAX4", 4, F::HeatTransfer, S::Axisymmetric, P::Axisymmetric, false, true,
     Shape::Quad4},
    {ElementType::DC3D4, "DC3D4", 4, F::HeatTransfer, S::ThreeD, P::None, false, true, Shape::Tet4},
    {ElementType::DC3D8, "DC3D8", 8, F::HeatTransfer, S::ThreeD, P::None, false, true, Shape::Hex8},
    {ElementType::DC3D10, "DC3D10", 10, F::HeatTransfer, S::ThreeD, P::None, false, true,
     Shape::Tet10},
    {ElementType::T2D2T, "T2D2T", 2, F::Truss, S::Planar, P::None, true, true, Shape::Line2},
    {ElementType::T3D2T, "T3D2T", 2, F::Truss, S::ThreeD, P::None, true, true, Shape::Line2},
    {ElementType::CPS4T, "CPS4T", 4, F::Continuum, S::Planar, P::PlaneStress, true, true,
     Shape::Quad4},
    {ElementType::CPE4T, "CPE4T", 4, F::Continuum, S::Planar, P::PlaneStrain, true, true,
     Shape::Quad4},
    {ElementType::CAX4T, "CAX4T", 4, F::Continuum, S::Axisymmetric, P::Axisymmetric, true, true,
     Shape::Quad4},
    {ElementType::C3D4T, "C3D4T", 4, F::Continuum, S::ThreeD, P::None, true, true, Shape::Tet4},
    {ElementType::C3D8T, "C3D8T", 8, F::Continuum, S::ThreeD, P::None, true, true, Shape::Hex8},
    {ElementType::C3D20, "C3D20", 20, F::Continuum, S::ThreeD, P::None, true, false, Shape::Hex20},
    {ElementType::C3D20R, "C3D20R", 20, F::Continuum, S::ThreeD, P::None, true, false,
     Shape::Hex20},
    {ElementType::C3D15, "C3D15", 15, F::Continuum, S::ThreeD, P::None, true, false,
     Shape::Wedge15},
    {ElementType::C3D6, "C3D6", 6, F::Continuum, S::ThreeD, P::None, true, false, Shape::Wedge6},
    {ElementType::CPS8, "CPS8", 8, F::Continuum, S::Planar, P::PlaneStress, true, false,
     Shape::Quad8},
    {ElementType::CPS8R, "CPS8R", 8, F::Continuum, S::Planar, P::PlaneStress, true, false,
     Shape::Quad8},
    {ElementType::CPE8, "CPE8", 8, F::Continuum, S::Planar, P::PlaneStrain, true, false,
     Shape::Quad8},
    {ElementType::CPE8R, "CPE8R", 8, F::Continuum, S::Planar, P::PlaneStrain, true, false,
     Shape::Quad8},
    {ElementType::CAX8, "CAX8", 8, F::Continuum, S::Axisymmetric, P::Axisymmetric, true, false,
     Shape::Quad8},
    {ElementType::CAX8R, "CAX8R", 8, F::Continuum, S::Axisymmetric, P::Axisymmetric, true, false,
     Shape::Quad8},
    {ElementType::CPS6, "CPS6", 6, F::Continuum, S::Planar, P::PlaneStress, true, false,
     Shape::Tri6},
    {ElementType::CPE6, "CPE6", 6, F::Continuum, S::Planar, P::PlaneStrain, true, false,
     Shape::Tri6},
    {ElementType::CAX6, "CAX6", 6, F::Continuum, S::Axisymmetric, P::Axisymmetric, true, false,
     Shape::Tri6},
    {ElementType::DC3D20, "DC3D20", 20, F::HeatTransfer, S::ThreeD, P::None, false, true,
     Shape::Hex20},
    {ElementType::DC3D15, "DC3D15", 15, F::HeatTransfer, S::ThreeD, P::None, false, true,
     Shape::Wedge15},
    {ElementType::DC3D6, "DC3D6", 6, F::HeatTransfer, S::ThreeD, P::None, false, true,
     Shape::Wedge6},
    {ElementType::DC2D8, "DC2D8", 8, F::HeatTransfer, S::Planar, P::None, false, true,
     Shape::Quad8},
    {ElementType::DC2D6, "DC2D6", 6, F::HeatTransfer, S::Planar, P::None, false, true, Shape::Tri6},
    {ElementType::DCAX8, "DCAX8", 8, F::HeatTransfer, S::Axisymmetric, P::Axisymmetric, false, true,
     Shape::Quad8},
    {ElementType::DCAX6, "DCAX6", 6, F::HeatTransfer, S::Axisymmetric, P::Axisymmetric, false, true,
     Shape::Tri6},
    {ElementType::C3D20T, "C3D20T", 20, F::Continuum, S::ThreeD, P::None, true, true, Shape::Hex20},
    {ElementType::C3D20RT, "C3D20RT", 20, F::Continuum, S::ThreeD, P::None, true, true,
     Shape::Hex20},
    {ElementType::C3D6T, "C3D6T", 6, F::Continuum, S::ThreeD, P::None, true, true, Shape::Wedge6},
    {ElementType::CPS8T, "CPS8T", 8, F::Continuum, S::Planar, P::PlaneStress, true, true,
     Shape::Quad8},
    {ElementType::CPS8RT, "CPS8RT", 8, F::Continuum, S::Planar, P::PlaneStress, true, true,
     Shape::Quad8},
    {ElementType::CPE8T, "CPE8T", 8, F::Continuum, S::Planar, P::PlaneStrain, true, true,
     Shape::Quad8},
    {ElementType::CPE8RT, "CPE8RT", 8, F::Continuum, S::Planar, P::PlaneStrain, true, true,
     Shape::Quad8},
    {ElementType::CAX8T, "CAX8T", 8, F::Continuum, S::Axisymmetric, P::Axisymmetric, true, true,
     Shape::Quad8},
    {ElementType::CAX8RT, "CAX8RT", 8, F::Continuum, S::Axisymmetric, P::Axisymmetric, true, true,
     Shape::Quad8},
    {ElementType::C3D8I, "C3D8I", 8, F::Continuum, S::ThreeD, P::None, true, false, Shape::Hex8},
    {ElementType::CPS4I, "CPS4I", 4, F::Continuum, S::Planar, P::PlaneStress, true, false,
     Shape::Quad4},
    {ElementType::CPE4I, "CPE4I", 4, F::Continuum, S::Planar, P::PlaneStrain, true, false,
     Shape::Quad4},
    {ElementType::CAX4I, "CAX4I", 4, F::Continuum, S::Axisymmetric, P::Axisymmetric, true, false,
     Shape::Quad4},
    {ElementType::C3D8R, "C3D8R", 8, F::Continuum, S::ThreeD, P::None, true, false, Shape::Hex8},
    {ElementType::CPS4R, "CPS4R", 4, F::Continuum, S::Planar, P::PlaneStress, true, false,
     Shape::Quad4},
    {ElementType::CPE4R, "CPE4R", 4, F::Continuum, S::Planar, P::PlaneStrain, true, false,
     Shape::Quad4},
    {ElementType::CAX4R, "CAX4R", 4, F::Continuum, S::Axisymmetric, P::Axisymmetric, true, false,
     Shape::Quad4},
    {ElementType::C3D8RT, "C3D8RT", 8, F::Continuum, S::ThreeD, P::None, true, true, Shape::Hex8},
    {ElementType::CPS4RT, "CPS4RT", 4, F::Continuum, S::Planar, P::PlaneStress, true, true,
     Shape::Quad4},
    {ElementType::CPE4RT, "CPE4RT", 4, F::Continuum, S::Planar, P::PlaneStrain, true, true,
     Shape::Quad4},
    {ElementType::CAX4RT, "CAX4RT", 4, F::Continuum, S::Axisymmetric, P::Axisymmetric, true, true,
     Shape::Quad4},
    // three-node beams number their nodes end, middle, end (no reference cell: see vtu_writer)
    {ElementType::B32, "B32", 3, F::Beam, S::ThreeD, P::None, true, false},
    {ElementType::B21, "B21", 2, F::Beam, S::Planar, P::None, true, false, Shape::Line2},
    {ElementType::B22, "B22", 3, F::Beam, S::Planar, P::None, true, false},
    {ElementType::PIPE31, "PIPE31", 2, F::Beam, S::ThreeD, P::None, true, false, Shape::Line2},
    {ElementType::PIPE32, "PIPE32", 3, F::Beam, S::ThreeD, P::None, true, false},
    {ElementType::S4, "S4", 4, F::Shell, S::ThreeD, P::None, true, false, Shape::Quad4},
    {ElementType::S4R, "S4R", 4, F::Shell, S::ThreeD, P::None, true, false, Shape::Quad4},
    {ElementType::S3, "S3", 3, F::Shell, S::ThreeD, P::None, true, false, Shape::Tri3},
    {ElementType::S3R, "S3R", 3, F::Shell, S::ThreeD, P::None, true, false, Shape::Tri3},
    {ElementType::S8R, "S8R", 8, F::Shell, S::ThreeD, P::None, true, false, Shape::Quad8},
    {ElementType::B32R, "B32R", 3, F::Beam, S::ThreeD, P::None, true, false},
    {ElementType::S8, "S8", 8, F::Shell, S::ThreeD, P::None, true, false, Shape::Quad8},
    {ElementType::DS3, "DS3", 3, F::Shell, S::ThreeD, P::None, false, true, Shape::Tri3},
    {ElementType::DS4, "DS4", 4, F::Shell, S::ThreeD, P::None, false, true, Shape::Quad4},
    {ElementType::DS8, "DS8", 8, F::Shell, S::ThreeD, P::None, false, true, Shape::Quad8},
    {ElementType::S3RT, "S3RT", 3, F::Shell, S::ThreeD, P::None, true, true, Shape::Tri3},
    {ElementType::S4T, "S4T", 4, F::Shell, S::ThreeD, P::None, true, true, Shape::Quad4},
    {ElementType::S4RT, "S4RT", 4, F::Shell, S::ThreeD, P::None, true, true, Shape::Quad4},
    {ElementType::S8RT, "S8RT", 8, F::Shell, S::ThreeD, P::None, true, true, Shape::Quad8},
    // the DOFs of these are the deck's (Model::element_fields)
    {ElementType::MASS, "MASS", 1, F::Mass, S::Any, P::None, true, false},
    {ElementType::ROTARYI, "ROTARYI", 1, F::Mass, S::Any, P::None, true, false},
    {ElementType::DASHPOT1, "DASHPOT1", 1, F::Spring, S::Any, P::None, true, false},
    {ElementType::DASHPOT2, "DASHPOT2", 2, F::Spring, S::Any, P::None, true, false},
    {ElementType::DASHPOTA, "DASHPOTA", 2, F::Spring, S::Any, P::None, true, false},
    {ElementType::USER, "U", 0, F::User, S::Any, P::None, false, false},
    {ElementType::SUBSTRUCTURE, "Z", 0, F::Substructure, S::Any, P::None, false, false},
}};
} // namespace

const ElementTypeInfo& element_info(ElementType type) {
  const auto idx = static_cast<std::size_t>(type);
  FE_CHECK(idx < kInfo.size() && kInfo[idx].type == type, "element info table out of order");
  return kInfo[idx];
}

bool info_reduced(const ElementTypeInfo& info) {
  if (info.family != ElementFamily::Continuum || !info.displacement || !info.cell ||
      !shape_quadratic(*info.cell))
    return false;
  const std::string_view n = info.name;
  return n.ends_with('R') || n.ends_with("RT");
}

std::optional<ElementType> element_type_from_name(std::string_view name) {
  std::string upper;
  for (char c : name)
    if (!std::isspace(static_cast<unsigned char>(c)))
      upper.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  for (const auto& info : kInfo)
    if (info.name == upper && info.n_nodes > 0) return info.type;
  return std::nullopt;
}

std::span<const ElementTypeInfo> all_element_types() {
  return kInfo;
}

std::string_view model_space_name(ModelSpace s) {
  switch (s) {
  case ModelSpace::ThreeD:
    return "three-dimensional";
  case ModelSpace::Planar:
    return "two-dimensional (planar)";
  case ModelSpace::Axisymmetric:
    return "axisymmetric";
  }
  return "?";
}

} // namespace gapfem
