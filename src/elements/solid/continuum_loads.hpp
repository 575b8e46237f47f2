#pragma once
/// @file continuum_loads.hpp
/// Equivalent nodal forces of distributed loads on continuum elements (face pressure, body forces),
/// shared by the stress/displacement and (later) the coupled temperature-displacement elements.
/// Not on the hot path: sizes are dynamic, scratch is small and on the stack.
#include "common/types.hpp"
#include "elements/element_kernel.hpp"
#include "elements/material/solid_law.hpp"
#include "fe/shape_functions.hpp"
#include "model/material.hpp"

#include <span>

namespace gapfem {

/// Geometry and DOF layout of one element for load integration.
struct LoadGeometry {
  Kinematics kin = Kinematics::ThreeD;
  Shape cell = Shape::Hex8;
  std::span<const Vec3> X;   ///< reference coordinates
  std::span<const double> u; ///< displacements at the element's DOFs (node-major)
  int dofs_per_node = 3;     ///< stride of u, f and tangent per node (>= displacement DOFs)
  double thickness = 1.0;    ///< plane elements
};

/// CENTRIF: the body force rho omega^2 r per reference volume, r the distance vector from the
/// axis (through `point` along unit `axis`) of the current position X + u (`follower`, NLGEOM:
/// -df/du = -rho omega^2 (I - a a^T) N_a N_b dV is added to `tangent`) or of X. Plane elements
/// need the axis normal to their plane, axisymmetric ones the symmetry axis (InputError
/// otherwise, naming `label`).
void continuum_centrifugal(const LoadGeometry& g, double rho_omega2, const Vec3& point,
                           const Vec3& axis, bool follower, std::span<double> f,
                           std::span<double> tangent, const SourceLocation& loc,
                           const std::string& label);

/// Pressure p on face `face` (1-based, Abaqus numbering); positive pressure pushes into the
/// element. With `follower` the load acts on the current face (X + u) and -df/du is added to
/// `tangent` (row-major, n_dofs x n_dofs); otherwise the reference face carries it and tangent is
/// untouched. Plane elements: per unit thickness times the thickness; axisymmetric: around 2*pi*r.
void continuum_face_pressure(const LoadGeometry& g, int face, double p, bool follower,
                             std::span<double> f, std::span<double> tangent);

/// Body force b (per unit reference volume, `density_at(T)` already applied by the caller when the
/// load is GRAV) integrated with the shape functions over the reference volume.
void continuum_body_force(const LoadGeometry& g, const Vec3& b, std::span<double> f);

/// The distributed loads of a stress/displacement continuum element: face pressure (a follower
/// load under NLGEOM), GRAV (needs the material's density, at the element's mean temperature) and
/// BX/BY/BZ body forces; other kinds add nothing.
void continuum_distributed_load(const LoadGeometry& g, const ElementInput& in,
                                const DistributedLoad& ld, double magnitude, const Material& mat,
                                std::span<double> f, std::span<double> tangent);

/// Volume (3-D), area x thickness (plane) or 2*pi*r-weighted area (axisymmetric) of the reference
/// element; used by the tests and for density-weighted loads.
double continuum_reference_volume(const LoadGeometry& g);

} // namespace gapfem
