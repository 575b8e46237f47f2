#pragma once
/// @file beam_loads.hpp
/// Distributed loads on beams (force per unit reference length): GRAV (rho A g), BX/BY/BZ (b A),
/// PX/PY/PZ in global directions, P1/P2 along the section's n1/n2. Without NLGEOM two-node beams
/// also get the fixed-end moments q L^2 / 12, which make the prismatic element exact for uniform
/// loads (docs/theory/structural.md §3.4); under NLGEOM the loads are the interpolation's
/// consistent nodal forces, and P1/P2 follow the rotation of the section (with their load
/// stiffness), as Abaqus's beam loads do.
#include "elements/structural/beam_element.hpp"
#include "elements/structural/structural_common.hpp"

namespace gapfem::beam {

/// Which distributed loads a beam takes (face: 0 body/global, 1 P1, 2 P2; pipes: PI, PE).
bool beam_supports_load(DistLoadKind kind, int face, bool planar, bool pipe);

/// The axial force a PI/PE load of magnitude p puts on the pipe's axis (closed-end condition):
/// the end-cap thrust p pi D^2 / 4 (PI: +, D the effective inner diameter; PE: -, outer) less
/// nu A (sigma_r + sigma_theta) (the wall's Poisson response to the pressure), docs §3.4.
double pipe_axial_force(const BeamSectionProperties& s, const DistributedLoad& load, double p,
                        double nu);

struct BeamLoadInput {
  const BeamData& b;
  const BeamGeometry& g;
  const DistributedLoad& load;
  double magnitude = 0.0;
  const ElementInput& in;
  bool nlgeom = false;
  bool planar = false;
};

/// Load per unit reference length at integration point p for loads of fixed direction.
Vec3 dead_intensity(const BeamLoadInput& li, int p);

/// Fixed-direction loads (and P1/P2 without NLGEOM).
template <int NN, int Dpn>
void dead_line_load(const BeamLoadInput& li, std::span<double> f) {
  const int ndir = li.planar ? 2 : 3;
  Vec3 q0{};
  for (int p = 0; p < li.g.n_points; ++p) {
    const BeamPoint& bp = li.g.pts[p];
    const Vec3 q = dead_intensity(li, p);
    if (p == 0) q0 = q;
    for (int a = 0; a < NN; ++a)
      for (int i = 0; i < ndir; ++i) f[a * Dpn + i] += bp.weight * bp.N[a] * q[i];
  }
  if (NN != 2 || li.nlgeom) return;
  // fixed-end moments of the prismatic beam: node A m1 = -q2 L^2/12, m2 = +q1 L^2/12 about n1, n2
  // (a rotation theta_1 about n1 moves the axis by -theta_1 along n2), node B the opposite
  const auto& L0 = li.g.pts[0].L0;
  const double c = li.g.length * li.g.length / 12.0;
  const double m1 = -structural::dot(q0, L0[2]) * c, m2 = structural::dot(q0, L0[1]) * c;
  for (int j = li.planar ? 2 : 0; j < 3; ++j) {
    const double mj = m1 * L0[1][j] + m2 * L0[2][j];
    const int r = li.planar ? 2 : 3 + j;
    f[r] += mj;
    f[Dpn + r] -= mj;
  }
}

/// P1/P2 under NLGEOM: dirs[p] is the current direction of the load at point p as a Jet of the
/// element's DOFs; adds the nodal forces and -d f / du to the tangent.
template <int NN, int Dpn, class J>
void follower_line_load(const BeamLoadInput& li, const std::array<rotation::V3<J>, 2>& dirs,
                        std::span<double> f, std::span<double> tangent) {
  constexpr int kN = NN * Dpn;
  const int ndir = li.planar ? 2 : 3;
  for (int p = 0; p < li.g.n_points; ++p) {
    const BeamPoint& bp = li.g.pts[p];
    for (int a = 0; a < NN; ++a)
      for (int i = 0; i < ndir; ++i) {
        const double c = bp.weight * bp.N[a] * li.magnitude;
        const int r = a * Dpn + i;
        f[r] += c * dirs[p][i].v;
        if (tangent.empty()) continue;
        for (int j = 0; j < kN; ++j) tangent[r * kN + j] -= c * dirs[p][i].g[j];
      }
  }
}

} // namespace gapfem::beam
