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

/// Degrees of freedom, in Abaqus numbering 1..6 (displacements and rotations), 11 (temperature,
/// or the first temperature through a heat-transfer shell's thickness) and 12..25 (the further
/// temperatures through a shell's thickness, DOF 11 at SNEG, the last at SPOS). The enumerator
/// value is a compact bit index; use abaqus_number() for the deck number.
enum class DofType : std::uint8_t { U1 = 0, U2, U3, UR1, UR2, UR3, NT };
/// Temperatures through a shell's thickness: DOFs 11 .. 11 + kMaxTemperaturePoints - 1.
inline constexpr int kMaxTemperaturePoints = 15;
inline constexpr int kNumDofTypes = 6 + kMaxTemperaturePoints;
/// Which DOFs a node carries: bit dof_bit(d) per DofType.
using DofMask = std::uint32_t;
static_assert(kNumDofTypes <= 32, "DofMask holds one bit per DOF type");

/// Temperature point k (0-based) through the thickness: DOF 11 + k.
constexpr DofType temperature_dof(int k) {
  return static_cast<DofType>(static_cast<int>(DofType::NT) + k);
}
constexpr bool is_temperature(DofType d) {
  return d >= DofType::NT;
}
/// 0 for DOF 11, k for DOF 11 + k (temperature DOFs only).
constexpr int temperature_index(DofType d) {
  return static_cast<int>(d) - static_cast<int>(DofType::NT);
}
constexpr int abaqus_number(DofType d) {
  return is_temperature(d) ? 11 + temperature_index(d) : static_cast<int>(d) + 1;
}
/// Largest deck DOF number gapfem knows.
inline constexpr int kMaxAbaqusDof = 10 + kMaxTemperaturePoints;
/// Deck DOF number (1..6, 11..25) to DofType; returns false for numbers gapfem does not know.
constexpr bool dof_from_abaqus(int number, DofType& out) {
  if (number >= 1 && number <= 6) {
    out = static_cast<DofType>(number - 1);
    return true;
  }
  if (number >= 11 && number <= kMaxAbaqusDof) {
    out = temperature_dof(number - 11);
    return true;
  }
  return false;
}
constexpr DofMask dof_bit(DofType d) {
  return DofMask{1} << static_cast<int>(d);
}
/// All temperature bits.
inline constexpr DofMask kTemperatureBits =
    ((DofMask{1} << kNumDofTypes) - 1u) & ~((DofMask{1} << static_cast<int>(DofType::NT)) - 1u);

/// Which solution field a DOF belongs to (convergence checks are per field, as in Abaqus).
enum class Field : std::uint8_t { Displacement = 0, Rotation, Temperature };
inline constexpr int kNumFields = 3;
constexpr Field field_of(DofType d) {
  return is_temperature(d) ? Field::Temperature
                           : (static_cast<int>(d) >= 3 ? Field::Rotation : Field::Displacement);
}
constexpr std::string_view field_name(Field f) {
  return f == Field::Displacement ? "displacement"
         : f == Field::Rotation   ? "rotation"
                                  : "temperature";
}

} // namespace gapfem
