#pragma once
/// @file structural_common.hpp
/// Small helpers shared by the spring, truss and beam kernels: 3-vector algebra, nodal temperature
/// averages, temperature-dependent property lookups, the axial two-node kinematics used by SPRINGA
/// and the trusses, and the output component names. Everything here is allocation-free.
#include "common/types.hpp"
#include "elements/element_kernel.hpp"
#include "model/material.hpp"
#include "model/table.hpp"

#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <string_view>

namespace gapfem::structural {

// ----------------------------------------------------------------------------- 3-vector algebra

/// a - b
inline Vec3 sub(const Vec3& a, const Vec3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
/// a . b
inline double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
/// a x b
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
/// |a|
inline double norm(const Vec3& a) {
  return std::sqrt(dot(a, a));
}
/// s * a
inline Vec3 scale(double s, const Vec3& a) {
  return {s * a[0], s * a[1], s * a[2]};
}

// ------------------------------------------------------------------------- temperature lookups

/// Average of the nodal predefined temperatures, or nullopt when the element gets no temperature
/// field (then temperature-dependent data are taken from the first table row).
inline std::optional<double> average(std::span<const double> nodal) {
  if (nodal.empty()) return std::nullopt;
  double s = 0.0;
  for (double t : nodal) s += t;
  return s / static_cast<double>(nodal.size());
}

/// Single-valued table at temperature T, or its first row when T is not known.
double table_value(const PropertyTable& table, std::optional<double> T);

/// Young's modulus and Poisson's ratio at T (first row of *ELASTIC when T is not known).
void elastic_at(const Material& material, std::optional<double> T, double& E, double& nu);

/// Thermal strain of the element from its average current and initial temperatures; zero without
/// a temperature field or without *EXPANSION.
double element_thermal_strain(const Material& material, const ElementInput& in);

/// Whether a material's response depends on the predefined temperature field.
bool material_uses_temperature(const Material& material);

/// Magnitude of the force per unit reference length of a GRAV (rho A g) or BX/BY/BZ (b A) load on a
/// line element of cross-section `area`; multiply by load.direction for the vector. Throws
/// InputError naming the load and the element when GRAV meets a material without *DENSITY.
double line_load_intensity(const Material& material, double area, const DistributedLoad& load,
                           double magnitude, std::optional<double> T, const EntityLabel& label);

// -------------------------------------------------------------------------------------- mass

/// Lumped translational mass (docs/conventions.md, "Mass and damping"): node a's mass m[a] on the
/// diagonal of M (n x n row-major, n = nodes x dofs_per_node) at its first `ndir` DOFs (the
/// translations). Rotational DOFs get no mass: gapfem's beams and shells have no rotary inertia.
inline void add_nodal_mass(std::span<const double> m, int dofs_per_node, int ndir,
                           std::span<double> M) {
  const auto n = m.size() * static_cast<std::size_t>(dofs_per_node);
  for (std::size_t a = 0; a < m.size(); ++a)
    for (int i = 0; i < ndir; ++i) {
      const std::size_t r = a * dofs_per_node + i;
      M[r * n + r] += m[a];
    }
}

// ------------------------------------------------------------------ axial two-node kinematics

/// Kinematics of a straight two-node member whose force acts along its axis (SPRINGA, T2D2,
/// T3D2). `ndim` translational DOFs per node (2 or 3), node-major in u.
struct AxialKinematics {
  int ndim = 3;
  double L = 0.0;     ///< reference length
  double l = 0.0;     ///< current length (= L + delta without NLGEOM)
  Vec3 n{};           ///< unit axis: current with NLGEOM, reference otherwise
  double delta = 0.0; ///< elongation: l - L (NLGEOM) or n0 . (u2 - u1)
};

/// Reference length and direction of the member (L may be 0: validate() checks it).
AxialKinematics axial_reference(int ndim, std::span<const Vec3> X);
/// Kinematics at displacement u.
AxialKinematics axial_kinematics(int ndim, std::span<const Vec3> X, std::span<const double> u,
                                 bool nlgeom);

/// Residual and tangent of an axial member with axial force N and dN/d(length): r = N [-n; n],
/// K = dN/dl [n n^T blocks] (+ N/l (I - n n^T) blocks with NLGEOM: the geometric stiffness).
void axial_assemble(const AxialKinematics& kin, bool nlgeom, double N, double dN_dl,
                    ElementOutput& out);
/// Eigenvalue buckling's initial-stress matrix of an axial member
/// (ElementKernel::stress_stiffness): the geometric part of the NLGEOM tangent above with the axial
/// force's change dN in place of N, K += dN / l (I - n n^T) blocks [+ -; - +] (K: 2 ndim square,
/// row-major).
void axial_stress_stiffness(const AxialKinematics& kin, double dN, std::span<double> K);
/// The change of an axial member's length along du (2 ndim entries): n . (du_2 - du_1).
double axial_stretch(const AxialKinematics& kin, std::span<const double> du);

// ------------------------------------------------------------------------------ output names

/// One-component blocks (springs, trusses).
inline constexpr std::array<std::string_view, 1> kS11{"S11"};
inline constexpr std::array<std::string_view, 1> kE11{"E11"};
inline constexpr std::array<std::string_view, 1> kSF1{"SF1"};
/// Beam section points: axial stress/strain and torsional shear.
inline constexpr std::array<std::string_view, 2> kBeamS{"S11", "S12"};
inline constexpr std::array<std::string_view, 2> kBeamE{"E11", "E12"};
/// Beam section forces and moments (Abaqus names).
inline constexpr std::array<std::string_view, 6> kBeamSF{"SF1", "SF2", "SF3", "SM1", "SM2", "SM3"};
/// Pipe section points: axial, hoop and torsional shear stress/strain.
inline constexpr std::array<std::string_view, 3> kPipeS{"S11", "S22", "S12"};
inline constexpr std::array<std::string_view, 3> kPipeE{"E11", "E22", "E12"};
/// Planar beams: axial force, shear force along n2, in-plane bending moment.
inline constexpr std::array<std::string_view, 3> kBeamSF2D{"SF1", "SF2", "SM1"};

/// Append an output block with `n_points` rows of `names.size()` values.
OutputBlock& add_block(ElementRecovery& out, ElemVar var, std::span<const std::string_view> names,
                       int n_points);

} // namespace gapfem::structural
