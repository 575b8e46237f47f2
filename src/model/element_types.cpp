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
constexpr std::array<ElementTypeInfo, 35> kInfo = {{
    {ElementType::SPRING1, "SPRING1", 1, F::Spring, S::Any, P::None, true, false},
    {ElementType::SPRING2, "SPRING2", 2, F::Spring, S::Any, P::None, true, false},
    {ElementType::SPRINGA, "SPRINGA", 2, F::Spring, S::Any, P::None, true, false},
    {ElementType::T2D2, "T2D2", 2, F::Truss, S::Planar, P::None, true, false},
    {ElementType::T3D2, "T3D2", 2, F::Truss, S::ThreeD, P::None, true, false},
    {ElementType::B31, "B31", 2, F::Beam, S::ThreeD, P::None, true, false},
    {ElementType::C3D8, "C3D8", 8, F::Continuum, S::ThreeD, P::None, true, false},
    {ElementType::C3D4, "C3D4", 4, F::Continuum, S::ThreeD, P::None, true, false},
    {ElementType::C3D10, "C3D10", 10, F::Continuum, S::ThreeD, P::None, true, false},
    {ElementType::CPS3, "CPS3", 3, F::Continuum, S::Planar, P::PlaneStress, true, false},
    {ElementType::CPS4, "CPS4", 4, F::Continuum, S::Planar, P::PlaneStress, true, false},
    {ElementType::CPE3, "CPE3", 3, F::Continuum, S::Planar, P::PlaneStrain, true, false},
    {ElementType::CPE4, "CPE4", 4, F::Continuum, S::Planar, P::PlaneStrain, true, false},
    {ElementType::CAX3, "CAX3", 3, F::Continuum, S::Axisymmetric, P::Axisymmetric, true, false},
    {ElementType::CAX4, "CAX4", 4, F::Continuum, S::Axisymmetric, P::Axisymmetric, true, false},
    {ElementType::GAPUNI, "GAPUNI", 2, F::Gap, S::Any, P::None, true, false},
    {ElementType::GAPCYL, "GAPCYL", 2, F::Gap, S::Any, P::None, true, false},
    {ElementType::GAPSPHER, "GAPSPHER", 2, F::Gap, S::Any, P::None, true, false},
    {ElementType::GAPUNIT, "GAPUNIT", 2, F::Gap, S::Any, P::None, true, true},
    {ElementType::DGAP, "DGAP", 2, F::Gap, S::Any, P::None, false, true},
    {ElementType::DC1D2, "DC1D2", 2, F::HeatTransfer, S::Any, P::None, false, true},
    {ElementType::DC2D3, "DC2D3", 3, F::HeatTransfer, S::Planar, P::None, false, true},
    {ElementType::DC2D4, "DC2D4", 4, F::HeatTransfer, S::Planar, P::None, false, true},
    {ElementType::DCAX3, "DCAX3", 3, F::HeatTransfer, S::Axisymmetric, P::Axisymmetric, false,
     true},
    {ElementType::DCAX4, "DCAX4", 4, F::HeatTransfer, S::Axisymmetric, P::Axisymmetric, false,
     true},
    {ElementType::DC3D4, "DC3D4", 4, F::HeatTransfer, S::ThreeD, P::None, false, true},
    {ElementType::DC3D8, "DC3D8", 8, F::HeatTransfer, S::ThreeD, P::None, false, true},
    {ElementType::DC3D10, "DC3D10", 10, F::HeatTransfer, S::ThreeD, P::None, false, true},
    {ElementType::T2D2T, "T2D2T", 2, F::Truss, S::Planar, P::None, true, true},
    {ElementType::T3D2T, "T3D2T", 2, F::Truss, S::ThreeD, P::None, true, true},
    {ElementType::CPS4T, "CPS4T", 4, F::Continuum, S::Planar, P::PlaneStress, true, true},
    {ElementType::CPE4T, "CPE4T", 4, F::Continuum, S::Planar, P::PlaneStrain, true, true},
    {ElementType::CAX4T, "CAX4T", 4, F::Continuum, S::Axisymmetric, P::Axisymmetric, true, true},
    {ElementType::C3D4T, "C3D4T", 4, F::Continuum, S::ThreeD, P::None, true, true},
    {ElementType::C3D8T, "C3D8T", 8, F::Continuum, S::ThreeD, P::None, true, true},
}};
} // namespace

const ElementTypeInfo& element_info(ElementType type) {
  const auto idx = static_cast<std::size_t>(type);
  FE_CHECK(idx < kInfo.size() && kInfo[idx].type == type, "element info table out of order");
  return kInfo[idx];
}

std::optional<ElementType> element_type_from_name(std::string_view name) {
  std::string upper;
  for (char c : name)
    if (!std::isspace(static_cast<unsigned char>(c)))
      upper.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  for (const auto& info : kInfo)
    if (info.name == upper) return info.type;
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
