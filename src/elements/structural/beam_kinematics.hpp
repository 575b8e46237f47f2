#pragma once
/// @file beam_kinematics.hpp
/// Generalised strains of the Timoshenko beams B21, B22, B31, B32, PIPE31, PIPE32 at one
/// integration point, templated on the scalar so the kernel differentiates them with Jets
/// (docs/theory/structural.md §3.2-3.3).
///
/// Order of the six strains (that of the SF/SM output): axial strain, shear strain along n2, shear
/// strain along n1, curvature about n1, curvature about n2, twist.
///
/// Small displacements: Gamma = Lambda0^T (u' - psi x X'), kappa = Lambda0^T psi'.
/// NLGEOM, geometrically exact (Simo-Reissner) with the objective interpolation of Crisfield and
/// Jelenic (1999): nodal rotations R_a; a reference rotation R_r, the shortest-arc midpoint of the
/// end nodes; local rotation vectors phi_a = log(R_r^T R_a) interpolated like the displacements;
/// at the point R = R_r exp(phi),
///   Gamma = Lambda0^T (R^T x' - X'),   kappa = Lambda0^T J_r(phi) phi'
/// with J_r the right Jacobian of the exponential map (kappa = axial(R^T R')). Lambda0 is the
/// reference triad (t, n1, n2) at the point and ' the derivative by reference arc length. Rigid
/// motions give zero strain exactly; the small-displacement strains are the linearisation.
#include "elements/structural/rotation.hpp"

#include <array>

namespace gapfem::beam {

using rotation::Quat;
using rotation::V3;

/// Reference geometry of one integration point (plain doubles).
struct BeamPoint {
  double weight = 0.0;            ///< quadrature weight times dS/dxi
  std::array<double, 3> N{};      ///< shape functions
  std::array<double, 3> dN{};     ///< their derivatives by reference arc length
  V3<double> dX{};                ///< dX/dS: the unit reference tangent
  std::array<V3<double>, 3> L0{}; ///< reference triad t, n1, n2
};

/// Nodal unknowns of an element in three-dimensional form (planar beams fill u3, psi1, psi2 with
/// constant zeros).
template <class T, int NN>
struct BeamNodal {
  std::array<V3<T>, NN> u{};   ///< displacements
  std::array<V3<T>, NN> psi{}; ///< rotation DOF values (small-displacement kinematics)
  std::array<Quat<T>, NN> q{}; ///< nodal rotations (NLGEOM)
};

template <class T>
using Strains = std::array<T, 6>;

/// Project a vector a onto the triad in the strain order: (t, n2, n1) for the forces, (n1, n2, t)
/// for the moments.
template <class T>
void project(const std::array<V3<double>, 3>& L0, const V3<T>& g, const V3<T>& k, Strains<T>& e) {
  e[0] = rotation::dot3(L0[0], g);
  e[1] = rotation::dot3(L0[2], g);
  e[2] = rotation::dot3(L0[1], g);
  e[3] = rotation::dot3(L0[1], k);
  e[4] = rotation::dot3(L0[2], k);
  e[5] = rotation::dot3(L0[0], k);
}

template <class T, int NN>
Strains<T> linear_strains(const BeamPoint& p, const BeamNodal<T, NN>& nv) {
  V3<T> du{}, psi{}, dpsi{};
  for (int a = 0; a < NN; ++a)
    for (int i = 0; i < 3; ++i) {
      du[i] += p.dN[a] * nv.u[a][i];
      psi[i] += p.N[a] * nv.psi[a][i];
      dpsi[i] += p.dN[a] * nv.psi[a][i];
    }
  const V3<T> c = rotation::cross3(psi, p.dX);
  V3<T> g;
  for (int i = 0; i < 3; ++i) g[i] = du[i] - c[i];
  Strains<T> e;
  project(p.L0, g, dpsi, e);
  return e;
}

/// The reference rotation and the local rotation vectors of the nodes (shared by all points).
template <class T, int NN>
struct LocalRotations {
  Quat<T> r;
  std::array<V3<T>, NN> phi;
};

template <class T, int NN>
LocalRotations<T, NN> local_rotations(const BeamNodal<T, NN>& nv) {
  LocalRotations<T, NN> lr;
  lr.r = rotation::quat_mid(nv.q[0], nv.q[NN - 1]);
  const Quat<T> rc = rotation::conj(lr.r);
  for (int a = 0; a < NN; ++a) lr.phi[a] = rotation::quat_log(rotation::quat_mul(rc, nv.q[a]));
  return lr;
}

template <class T, int NN>
Strains<T> nonlinear_strains(const BeamPoint& p, std::span<const V3<double>> X,
                             const BeamNodal<T, NN>& nv, const LocalRotations<T, NN>& lr) {
  V3<T> dx{}, phi{}, dphi{};
  for (int a = 0; a < NN; ++a)
    for (int i = 0; i < 3; ++i) {
      dx[i] += p.dN[a] * (X[a][i] + nv.u[a][i]);
      phi[i] += p.N[a] * lr.phi[a][i];
      dphi[i] += p.dN[a] * lr.phi[a][i];
    }
  const Quat<T> q = rotation::quat_mul(lr.r, rotation::quat_exp(phi));
  const V3<T> m = rotation::rotate(rotation::conj(q), dx); // R^T x'
  V3<T> g;
  for (int i = 0; i < 3; ++i) g[i] = m[i] - p.dX[i];
  const V3<T> k = rotation::right_jacobian(phi, dphi);
  Strains<T> e;
  project(p.L0, g, k, e);
  return e;
}

} // namespace gapfem::beam
