#pragma once
/// @file beam_element.hpp
/// What the beam kernels share outside their templated energy: the block's data (material,
/// section, orientation), the reference geometry of the integration points, and the output of
/// section forces and section-point stresses.
#include "elements/element_kernel.hpp"
#include "elements/material/solid_law.hpp"
#include "elements/reference_scale.hpp"
#include "elements/structural/beam_fibres.hpp"
#include "elements/structural/beam_kinematics.hpp"
#include "elements/structural/beam_section.hpp"
#include "model/material.hpp"

#include <cmath>
#include <fmt/format.h>
#include <memory>
#include <span>
#include <string>

namespace gapfem::beam {

/// Inertia per unit length about the node (the section's origin) in the section axes (t, n1, n2):
/// the mass m, its first moments S1 = integral x1 dm, S2 = integral x2 dm and its second moments
/// J11 = integral x2^2 dm, J22 = integral x1^2 dm, J12 = integral x1 x2 dm (a section of density
/// rho: rho A, rho Q1, rho Q2, rho I11, rho I22, rho I12). Sums of them are sums of masses.
struct SectionInertia {
  double m = 0.0, S1 = 0.0, S2 = 0.0, J11 = 0.0, J22 = 0.0, J12 = 0.0;
  SectionInertia& operator+=(const SectionInertia& o) {
    m += o.m;
    S1 += o.S1;
    S2 += o.S2;
    J11 += o.J11;
    J22 += o.J22;
    J12 += o.J12;
    return *this;
  }
  SectionInertia scaled(double c) const {
    return {c * m, c * S1, c * S2, c * J11, c * J22, c * J12};
  }
  bool empty() const { return m == 0.0 && J11 == 0.0 && J22 == 0.0 && J12 == 0.0; }
};

/// Everything a beam block's kernel evaluates with.
struct BeamData {
  ElementType type = ElementType::B31;
  Material material; ///< of *BEAM SECTION, or made from the constants of *BEAM GENERAL SECTION
  BeamSectionProperties section;
  Vec3 n1a{0.0, 0.0, -1.0};  ///< approximate n1 direction
  double slenderness = -1.0; ///< SCF of *TRANSVERSE SHEAR STIFFNESS (-1: gapfem's default)
  bool pipe = false;         ///< PIPE31/PIPE32
  /// The material's solid law when the section is integrated at its fibres; null for the
  /// pre-integrated elastic section (the built-in elastic law, and every GENERAL section)
  std::shared_ptr<const SolidLaw> law;
  BeamFibres fibres; ///< the section integration points (with `law` only)
  /// *BEAM ADDED INERTIA: its data lines summed (beam_mass.hpp, added_section_inertia), and the
  /// sum of each line times its keyword's ALPHA (the damping C = sum alpha_k M_k)
  SectionInertia added, added_damping;
};

/// The block's data from its section; InputError for wrong combinations.
BeamData beam_data(const KernelContext& ctx);

/// Reference geometry of the element's integration points.
struct BeamGeometry {
  int n_points = 1;
  std::array<BeamPoint, 2> pts{};
  double length = 0.0; ///< reference arc length
};

/// Shape functions (Abaqus node order: end, [middle,] end) and d/dxi at xi.
template <int NN>
void line_shape(double xi, std::array<double, 3>& N, std::array<double, 3>& dN) {
  if constexpr (NN == 2) {
    N = {0.5 * (1.0 - xi), 0.5 * (1.0 + xi), 0.0};
    dN = {-0.5, 0.5, 0.0};
  } else {
    N = {0.5 * xi * (xi - 1.0), 1.0 - xi * xi, 0.5 * xi * (xi + 1.0)};
    dN = {xi - 0.5, -2.0 * xi, xi + 0.5};
  }
}

/// Geometry with one point (two nodes) or two Gauss points (three nodes). When `why` is given,
/// a degenerate element (zero length, folded, n1 along the axis) sets the sentence to report.
template <int NN>
BeamGeometry beam_geometry(std::span<const Vec3> X, const Vec3& n1a, double size,
                           std::string* why) {
  using rotation::cross3;
  using rotation::dot3;
  BeamGeometry g;
  g.n_points = NN == 2 ? 1 : 2;
  const double xg = 1.0 / std::sqrt(3.0);
  const double xis[2] = {NN == 2 ? 0.0 : -xg, xg};
  const double w = NN == 2 ? 2.0 : 1.0;
  auto tangent = [&](double xi, std::array<double, 3>& N, std::array<double, 3>& dN) {
    line_shape<NN>(xi, N, dN);
    Vec3 d{};
    for (int a = 0; a < NN; ++a)
      for (int i = 0; i < 3; ++i) d[i] += dN[a] * X[a][i];
    return d;
  };
  if (why != nullptr) {
    // on the nodes scaled to an extent near 1 (reference_scale.hpp): no product of coordinates
    // overflows or underflows, so nodes 1e300 apart do not "coincide"
    const double f = unit_scale(X);
    std::array<Vec3, NN> Xs{};
    for (int a = 0; a < NN; ++a)
      for (int i = 0; i < 3; ++i) Xs[a][i] = f * X[a][i];
    const Vec3 c{Xs[NN - 1][0] - Xs[0][0], Xs[NN - 1][1] - Xs[0][1], Xs[NN - 1][2] - Xs[0][2]};
    const double c_len = std::hypot(c[0], c[1], c[2]), tol = 1e-12 * f * size;
    std::array<double, 3> N{}, dN{};
    for (double xi : {-1.0, 0.0, 1.0}) {
      line_shape<NN>(xi, N, dN);
      Vec3 t{};
      for (int a = 0; a < NN; ++a)
        for (int i = 0; i < 3; ++i) t[i] += dN[a] * Xs[a][i];
      if (!(dot3(t, c) > tol * c_len && c_len > tol)) {
        *why = NN == 2 ? "the two nodes of this beam coincide, so it has no length; check the node "
                         "coordinates"
                       : "this beam has no length or folds back on itself (its middle node is not "
                         "between its end nodes); check the node coordinates and the node order "
                         "(end, middle, end)";
        return g;
      }
    }
  }
  for (int p = 0; p < g.n_points; ++p) {
    BeamPoint& bp = g.pts[p];
    std::array<double, 3> dNxi{};
    const Vec3 d = tangent(xis[p], bp.N, dNxi);
    const double J = std::hypot(d[0], d[1], d[2]);
    bp.weight = w * J;
    g.length += bp.weight;
    for (int a = 0; a < NN; ++a) bp.dN[a] = dNxi[a] / J;
    const Vec3 t{d[0] / J, d[1] / J, d[2] / J};
    bp.dX = t;
    const Vec3 c = cross3(t, n1a);
    const double cn = std::hypot(c[0], c[1], c[2]), n1n = std::hypot(n1a[0], n1a[1], n1a[2]);
    if (!(cn > 1e-6 * n1n)) {
      if (why != nullptr)
        *why = fmt::format("the approximate n1 direction ({}, {}, {}) of the beam section is "
                           "parallel to the beam axis, so the cross-section orientation is "
                           "undefined; give a different n1 direction on the second data line of "
                           "the beam section",
                           n1a[0], n1a[1], n1a[2]);
      return g;
    }
    const Vec3 n2{c[0] / cn, c[1] / cn, c[2] / cn};
    bp.L0 = {t, cross3(n2, t), n2};
  }
  return g;
}

/// Internal and external pressure on a pipe at one moment.
struct PipePressures {
  double inner = 0.0, outer = 0.0;
};

/// Lame's thick cylinder: sigma_r + sigma_theta = 2 (p_i a^2 - p_e b^2) / (b^2 - a^2), the same
/// at every radius (so the wall's Poisson response sigma_z = E eps_z + nu (sigma_r + sigma_theta)
/// is uniform), and sigma_theta, sigma_r at radius r.
double pipe_lame_sum(const BeamSectionProperties& s, const PipePressures& p);
double pipe_hoop_at(const BeamSectionProperties& s, const PipePressures& p, double r);
double pipe_radial_at(const BeamSectionProperties& s, const PipePressures& p, double r);

/// What the output of one element needs.
struct BeamOutput {
  const std::array<double, 36>& D;
  const std::array<double, 6>& initial;
  double E = 0.0, G = 0.0;
  const BeamSectionProperties& section;
  bool planar = false;
  bool pipe = false;
  double nu = 0.0;
  PipePressures pressure; ///< pipes: the PI, PE acting now
  /// The integrated section (BeamData::law): the section forces per integration point and the
  /// stresses and strains per integration and section point, which then replace D (e - e0) and
  /// the elastic section-point stresses (D, initial, E, G then serve the pipes' hoop strain only)
  std::span<const std::array<double, 6>> forces;
  std::span<const PointStress> points;
};

/// SF (per integration point) and S, E (per integration point and section point) from the strains
/// at the integration points.
void recover_beam_output(const BeamOutput& o, std::span<const Strains<double>> e,
                         ElementRecovery& out);

} // namespace gapfem::beam
