#pragma once
/// @file beam_mass.hpp
/// The mass of the beams and pipes (docs/theory/dynamics.md, "Mass of each element type"), as
/// Abaqus/Standard forms it for Timoshenko beams with the exact rotary inertia (its default;
/// Theory Guide, "Mass and inertia for Timoshenko beams"): per unit length the section's mass
/// rho A, its first moment S = rho (Q1 n1 + Q2 n2) about the node (the section origin) and its
/// inertia tensor about the node, in the section's axes (t, n1, n2)
///     J = rho [[I11 + I22, 0, 0], [0, I11, -I12], [0, -I12, I22]]
/// (I11 = integral x2^2 dA, I22 = integral x1^2 dA, I12 = integral x1 x2 dA), so that the kinetic
/// energy of the section is 1/2 rho A |v|^2 + v . (w x S) + 1/2 w . J w (v the node's velocity,
/// w the angular velocity). The 6 x 6 block per length is [[rho A 1, -[S x]], [[S x], J]].
/// Two-node elements lump it at the nodes (integral N_a ds each), three-node elements keep it
/// consistent (integral N_a N_b ds, three Gauss points: exact for straight elements). A pipe's
/// mass is its wall's: Abaqus has no contents option on *BEAM SECTION; contents, insulation and
/// attached equipment come with *BEAM ADDED INERTIA (added_section_inertia), whose mass per length,
/// first and second moments add to the section's (Theory Guide: "the combined beam mass").
#include "elements/structural/beam_element.hpp"
#include "elements/structural/rotation.hpp"
#include "model/section.hpp"

#include <array>
#include <cmath>
#include <span>

namespace gapfem::beam {

/// The section's own inertia per length: density rho over its area.
inline SectionInertia section_inertia(const BeamSectionProperties& s, double rho) {
  return {rho * s.A, rho * s.Q1, rho * s.Q2, rho * s.I11, rho * s.I22, rho * s.I12};
}

/// One data line of *BEAM ADDED INERTIA as an inertia about the node: the mass m at d = (x1, x2)
/// with its rotary inertia about that centre of mass given in axes turned by the angle a from
/// local 1 toward local 2, as the tensor [[I11, I12], [I12, I22]] (I12 = -integral xi1 xi2 dm,
/// the Theory Guide's sign). Turned into the section axes, T = R [[I11, I12], [I12, I22]] R^T
/// with R's columns (cos a, sin a) and (-sin a, cos a); moved to the node by the parallel-axis
/// theorem: J11 = T11 + m x2^2, J22 = T22 + m x1^2, J12 = -T12 + m x1 x2 (J12 the product
/// integral x1 x2 dm, the opposite sign of the tensor's entry). The inertia about the beam's axis
/// is then J11 + J22 = I11 + I22 + m |d|^2 (the Theory Guide's I33 = I11 + I22).
inline SectionInertia added_section_inertia(const BeamAddedInertia& a) {
  const double pi = std::acos(-1.0);
  const double c = std::cos(a.angle * pi / 180.0), s = std::sin(a.angle * pi / 180.0);
  const double T11 = c * c * a.I11 - 2.0 * c * s * a.I12 + s * s * a.I22;
  const double T22 = s * s * a.I11 + 2.0 * c * s * a.I12 + c * c * a.I22;
  const double T12 = c * s * (a.I11 - a.I22) + (c * c - s * s) * a.I12;
  return {a.mass,
          a.mass * a.x1,
          a.mass * a.x2,
          T11 + a.mass * a.x2 * a.x2,
          T22 + a.mass * a.x1 * a.x1,
          -T12 + a.mass * a.x1 * a.x2};
}

/// The mass per unit length of an inertia about the section's origin, in global axes for the
/// section triad L0 = (t, n1, n2): a 6 x 6 row-major block on (u1 u2 u3 ur1 ur2 ur3).
inline std::array<double, 36> section_mass_per_length(const SectionInertia& si,
                                                      const std::array<Vec3, 3>& L0) {
  std::array<double, 36> m{};
  const double Jl[3][3] = {
      {si.J11 + si.J22, 0.0, 0.0}, {0.0, si.J11, -si.J12}, {0.0, -si.J12, si.J22}};
  Vec3 S{};
  for (int i = 0; i < 3; ++i) S[i] = si.S1 * L0[1][i] + si.S2 * L0[2][i];
  for (int i = 0; i < 3; ++i) {
    m[6 * i + i] = si.m;
    for (int j = 0; j < 3; ++j) {
      double J = 0.0;
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) J += L0[k][i] * Jl[k][l] * L0[l][j];
      m[6 * (3 + i) + 3 + j] = J;
    }
  }
  // [S x] (the cross-product matrix): the rotations' rows, and its transpose -[S x] in the
  // translations' rows
  const double Sx[3][3] = {{0.0, -S[2], S[1]}, {S[2], 0.0, -S[0]}, {-S[1], S[0], 0.0}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      m[6 * (3 + i) + j] = Sx[i][j];
      m[6 * i + 3 + j] = Sx[j][i];
    }
  return m;
}

/// The section of density rho alone (as before *BEAM ADDED INERTIA).
inline std::array<double, 36> section_mass_per_length(const BeamSectionProperties& s, double rho,
                                                      const std::array<Vec3, 3>& L0) {
  return section_mass_per_length(section_inertia(s, rho), L0);
}

/// Adds the element mass to M (kN x kN row-major, kN = NN x dofs per node; planar beams: DOFs
/// u1 u2 ur3 of the three-dimensional block). Reference geometry: the mass does not change with
/// the deformation (the rotary inertia is not turned with the section under NLGEOM, as for the
/// point inertias: docs/conventions.md).
template <int NN, bool Planar>
void add_beam_mass(std::span<const Vec3> X, const Vec3& n1a, const SectionInertia& si,
                   std::span<double> M) {
  constexpr int kDpn = Planar ? 3 : 6;
  constexpr int kN = NN * kDpn;
  constexpr std::array<int, 3> kPlane{0, 1, 5}; // u1, u2, ur3 in the 6-DOF block
  const double g = std::sqrt(0.6);
  const double xis[3] = {-g, 0.0, g}, ws[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  for (int q = 0; q < 3; ++q) {
    std::array<double, 3> N{}, dN{};
    line_shape<NN>(xis[q], N, dN);
    Vec3 d{};
    for (int a = 0; a < NN; ++a)
      for (int i = 0; i < 3; ++i) d[i] += dN[a] * X[a][i];
    const double jac = std::hypot(d[0], d[1], d[2]);
    const Vec3 t{d[0] / jac, d[1] / jac, d[2] / jac};
    Vec3 n2 = rotation::cross3(t, n1a);
    const double n2n = std::hypot(n2[0], n2[1], n2[2]);
    for (double& c : n2) c /= n2n;
    const std::array<Vec3, 3> L0{t, rotation::cross3(n2, t), n2};
    const std::array<double, 36> m = section_mass_per_length(si, L0);
    const double w = ws[q] * jac;
    for (int a = 0; a < NN; ++a)
      for (int b = 0; b < NN; ++b) {
        // two nodes: lumped (the row sums of the consistent matrix, all on the diagonal block)
        if (NN == 2 && b != a) continue;
        const double c = NN == 2 ? w * N[a] : w * N[a] * N[b];
        for (int i = 0; i < kDpn; ++i)
          for (int j = 0; j < kDpn; ++j) {
            const int mi = Planar ? kPlane[i] : i, mj = Planar ? kPlane[j] : j;
            M[(a * kDpn + i) * kN + b * kDpn + j] += c * m[6 * mi + mj];
          }
      }
  }
}

} // namespace gapfem::beam
