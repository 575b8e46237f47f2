#pragma once
/// @file types.hpp
/// Basic scalar, index and small-vector types used throughout gapfem.
#include <array>
#include <cstdint>
#include <string_view>

namespace gapfem {

using Real = double;
/// Local (per-process) indices: nodes, elements, equations. 32-bit by policy.
using LocalIndex = std::int32_t;
/// Global indices (reserved for a distributed backend).
using GlobalIndex = std::int64_t;
/// Node and element labels exactly as written in the deck (arbitrary positive integers).
using Label = std::int64_t;
/// Internal 0-based node index.
using NodeId = std::int32_t;
/// Internal 0-based element index.
using ElemId = std::int32_t;

using Vec3 = std::array<double, 3>;

/// Degrees of freedom, in Abaqus numbering 1..6 (displacements and rotations) and 11 (temperature).
/// The enumerator value is a compact bit index; use abaqus_number() for the deck number.
enum class DofType : std::uint8_t { U1 = 0, U2, U3, UR1, UR2, UR3, NT };
inline constexpr int kNumDofTypes = 7;

constexpr int abaqus_number(DofType d) {
  return d == DofType::NT ? 11 : static_cast<int>(d) + 1;
}
/// Deck DOF number (1..6, 11) to DofType; returns false for numbers gapfem does not know.
constexpr bool dof_from_abaqus(int number, DofType& out) {
  if (number >= 1 && number <= 6) {
    out = static_cast<DofType>(number - 1);
    return true;
  }
  if (number == 11) {
    out = DofType::NT;
    return true;
  }
  return false;
}
constexpr std::uint8_t dof_bit(DofType d) { return static_cast<std::uint8_t>(1u << static_cast<int>(d)); }

/// Which solution field a DOF belongs to (convergence checks are per field, as in Abaqus).
enum class Field : std::uint8_t { Displacement = 0, Rotation, Temperature };
inline constexpr int kNumFields = 3;
constexpr Field field_of(DofType d) {
  return d == DofType::NT ? Field::Temperature
                          : (static_cast<int>(d) >= 3 ? Field::Rotation : Field::Displacement);
}
constexpr std::string_view field_name(Field f) {
  return f == Field::Displacement ? "displacement" : f == Field::Rotation ? "rotation" : "temperature";
}

} // namespace gapfem
