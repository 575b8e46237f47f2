#include "elements/solid/continuum_loads.hpp"

#include "common/error.hpp"
#include "fe/element_faces.hpp"
#include "fe/quadrature.hpp"

#include <array>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace gapfem {
namespace {

constexpr int kMaxNodes = 20;

int displacement_dofs(Kinematics k) {
  return k == Kinematics::ThreeD ? 3 : 2;
}

/// Current (or reference) coordinates of local node a.
std::array<double, 3> node_position(const LoadGeometry& g, int a, bool deformed) {
  std::array<double, 3> x = g.X[a];
  if (deformed && !g.u.empty()) {
    const int nd = displacement_dofs(g.kin);
    for (int i = 0; i < nd; ++i) x[i] += g.u[a * g.dofs_per_node + i];
  }
  return x;
}

/// Rule used for body loads: exact for the straight-sided cell with a linear radius weight.
std::span<const QuadraturePoint> body_rule(Shape cell) {
  switch (cell) {
  case Shape::Tri3:
    return kTri3;
  case Shape::Tet4:
    return kTet4;
  case Shape::Wedge6:
    return kWedge6;
  default:
    return full_integration_rule(cell);
  }
}

} // namespace

void continuum_face_pressure(const LoadGeometry& g, int face, double p, bool follower,
                             std::span<double> f, std::span<double> tangent) {
  const auto faces = element_faces(g.cell);
  FE_CHECK(face >= 1 && face <= static_cast<int>(faces.size()), "face number out of range");
  const FaceDef& fd = faces[face - 1];
  const int nf = fd.n_nodes;
  const int stride = g.dofs_per_node;
  const std::size_t n_dofs = f.size();
  const bool add_tangent = follower && tangent.size() == n_dofs * n_dofs;
  auto K = [&](int row, int col) -> double& { return tangent[row * n_dofs + col]; };

  std::array<std::array<double, 3>, kMaxNodes> x{};
  for (int j = 0; j < nf; ++j) x[j] = node_position(g, fd.nodes[j], follower);

  std::array<double, kMaxNodes> N{};
  std::array<double, 2 * kMaxNodes> dN{};
  const int fdim = shape_dim(fd.shape);

  for (const QuadraturePoint& q : face_load_rule(fd.shape)) {
    shape_eval(fd.shape, q.xi, N, dN);
    if (g.kin == Kinematics::ThreeD) {
      std::array<double, 3> t1{}, t2{};
      for (int j = 0; j < nf; ++j)
        for (int i = 0; i < 3; ++i) {
          t1[i] += x[j][i] * dN[fdim * j];
          t2[i] += x[j][i] * dN[fdim * j + 1];
        }
      // n = t1 x t2 points into the element for Abaqus face orderings (element_faces.hpp).
      const std::array<double, 3> n{t1[1] * t2[2] - t1[2] * t2[1], t1[2] * t2[0] - t1[0] * t2[2],
                                    t1[0] * t2[1] - t1[1] * t2[0]};
      for (int a = 0; a < nf; ++a)
        for (int i = 0; i < 3; ++i) f[fd.nodes[a] * stride + i] += p * q.weight * N[a] * n[i];
      if (!add_tangent) continue;
      // d n / d x_b = -dN_b,xi [t2]x + dN_b,eta [t1]x, with [v]x w = v x w.
      for (int b = 0; b < nf; ++b) {
        const double s = dN[fdim * b], r = dN[fdim * b + 1];
        double M[3][3];
        const std::array<double, 3> v{-s * t2[0] + r * t1[0], -s * t2[1] + r * t1[1],
                                      -s * t2[2] + r * t1[2]};
        M[0][0] = 0, M[0][1] = -v[2], M[0][2] = v[1];
        M[1][0] = v[2], M[1][1] = 0, M[1][2] = -v[0];
        M[2][0] = -v[1], M[2][1] = v[0], M[2][2] = 0;
        for (int a = 0; a < nf; ++a)
          for (int i = 0; i < 3; ++i)
            for (int k = 0; k < 3; ++k)
              K(fd.nodes[a] * stride + i, fd.nodes[b] * stride + k) -=
                  p * q.weight * N[a] * M[i][k];
      }
    } else {
      double xp = 0.0, yp = 0.0, r = 0.0;
      for (int j = 0; j < nf; ++j) {
        xp += x[j][0] * dN[j];
        yp += x[j][1] * dN[j];
        r += x[j][0] * N[j];
      }
      const double scale =
          g.kin == Kinematics::Axisymmetric ? 2.0 * std::numbers::pi * r : g.thickness;
      // Inward normal times edge length: the tangent rotated by +90 degrees.
      const double nx = -yp, ny = xp;
      for (int a = 0; a < nf; ++a) {
        f[fd.nodes[a] * stride + 0] += p * q.weight * N[a] * scale * nx;
        f[fd.nodes[a] * stride + 1] += p * q.weight * N[a] * scale * ny;
      }
      if (!add_tangent) continue;
      for (int a = 0; a < nf; ++a)
        for (int b = 0; b < nf; ++b) {
          const double c = p * q.weight * N[a];
          const int ra = fd.nodes[a] * stride, cb = fd.nodes[b] * stride;
          // d(scale * n)/dx_b: scale * dn/dx_b (+ n * dscale/dx_b for axisymmetric).
          K(ra + 0, cb + 1) -= c * scale * (-dN[b]);
          K(ra + 1, cb + 0) -= c * scale * dN[b];
          if (g.kin == Kinematics::Axisymmetric) {
            const double ds = 2.0 * std::numbers::pi * N[b];
            K(ra + 0, cb + 0) -= c * nx * ds;
            K(ra + 1, cb + 0) -= c * ny * ds;
          }
        }
    }
  }
}

namespace {

/// The reference volume per quadrature weight at a point of the element's body (shape values N,
/// derivatives dN): det J, times 2 pi r for axisymmetric elements and the thickness for plane ones.
double reference_volume_factor(const LoadGeometry& g, const double* N, const double* dN) {
  const int n = shape_n_nodes(g.cell);
  const int dim = shape_dim(g.cell);
  double J[3][3] = {};
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < dim; ++i)
      for (int k = 0; k < dim; ++k) J[i][k] += g.X[a][i] * dN[dim * a + k];
  if (dim == 3)
    return J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
           J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
           J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
  const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
  if (g.kin != Kinematics::Axisymmetric) return det * g.thickness;
  double r = 0.0; // (the reference radius: the ring's mass)
  for (int a = 0; a < n; ++a) r += N[a] * g.X[a][0];
  return det * 2.0 * std::numbers::pi * r;
}

} // namespace

void continuum_body_force(const LoadGeometry& g, const Vec3& b, std::span<double> f) {
  const int n = shape_n_nodes(g.cell);
  const int nd = displacement_dofs(g.kin);
  std::array<double, kMaxNodes> N{};
  std::array<double, 3 * kMaxNodes> dN{};
  for (const QuadraturePoint& q : body_rule(g.cell)) {
    shape_eval(g.cell, q.xi, N, dN);
    const double dV = q.weight * reference_volume_factor(g, N.data(), dN.data());
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < nd; ++i) f[a * g.dofs_per_node + i] += N[a] * b[i] * dV;
  }
}

namespace {

/// The axis a plane or axisymmetric element's CENTRIF can use (an InputError otherwise).
void check_centrifugal_axis(const LoadGeometry& g, const Vec3& point, const Vec3& axis,
                            const SourceLocation& loc, const std::string& label) {
  if (g.kin == Kinematics::ThreeD) return;
  const double tol = 1e-9;
  if (g.kin == Kinematics::Axisymmetric) {
    if (std::abs(std::abs(axis[1]) - 1.0) > tol || std::abs(point[0]) > tol)
      throw InputError(loc, label,
                       "CENTRIF on an axisymmetric element turns about the symmetry axis: give "
                       "the axis through (0, 0, 0) along (0, 1, 0)");
    return;
  }
  if (std::abs(std::abs(axis[2]) - 1.0) > tol)
    throw InputError(loc, label,
                     "CENTRIF on a plane element needs the rotation axis normal to the model's "
                     "plane, along (0, 0, 1)");
}

} // namespace

void continuum_centrifugal(const LoadGeometry& g, double rho_omega2, const Vec3& point,
                           const Vec3& axis, bool follower, std::span<double> f,
                           std::span<double> tangent, const SourceLocation& loc,
                           const std::string& label) {
  check_centrifugal_axis(g, point, axis, loc, label);
  const int n = shape_n_nodes(g.cell);
  const int dim = shape_dim(g.cell);
  const int nd = displacement_dofs(g.kin);
  const int stride = g.dofs_per_node, n_dofs = n * stride;
  std::array<double, kMaxNodes> N{};
  std::array<double, 3 * kMaxNodes> dN{};
  for (const QuadraturePoint& q : body_rule(g.cell)) {
    shape_eval(g.cell, q.xi, N, dN);
    Vec3 x{0.0, 0.0, 0.0};
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < dim; ++i)
        x[i] += N[a] * (g.X[a][i] + (follower ? g.u[a * stride + i] : 0.0));
    const double dV = q.weight * reference_volume_factor(g, N.data(), dN.data());
    // r = (x - p) - ((x - p) . a) a
    const Vec3 d{x[0] - point[0], x[1] - point[1], x[2] - point[2]};
    const double along = d[0] * axis[0] + d[1] * axis[1] + d[2] * axis[2];
    const Vec3 r{d[0] - along * axis[0], d[1] - along * axis[1], d[2] - along * axis[2]};
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < nd; ++i) f[a * stride + i] += N[a] * rho_omega2 * r[i] * dV;
    if (!follower || tangent.empty()) continue;
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b)
        for (int i = 0; i < nd; ++i)
          for (int j = 0; j < nd; ++j) {
            const double P = (i == j ? 1.0 : 0.0) - axis[i] * axis[j];
            tangent[static_cast<std::size_t>((a * stride + i) * n_dofs + b * stride + j)] -=
                N[a] * N[b] * rho_omega2 * P * dV;
          }
  }
}

double continuum_reference_volume(const LoadGeometry& g) {
  // The first component of the integral of N_a * (1, 1, 1) summed over nodes.
  const int n = shape_n_nodes(g.cell);
  std::array<double, 3 * kMaxNodes> f{};
  LoadGeometry g1 = g;
  g1.dofs_per_node = 3;
  continuum_body_force(g1, {1.0, 1.0, 1.0}, std::span<double>(f.data(), 3 * n));
  double v = 0.0;
  for (int a = 0; a < n; ++a) v += f[3 * a];
  return v;
}

namespace {

/// The density of the element's material at its mean temperature (GRAV and CENTRIF need one).
double load_density(const ElementInput& in, const DistributedLoad& ld, const Material& mat,
                    const char* label) {
  if (mat.density.empty())
    throw InputError(
        ld.loc, fmt::format("element {}", in.label),
        fmt::format("{} on element {} needs *DENSITY in material {}", label, in.label, mat.name));
  const auto& T = in.temperature.empty() ? in.initial_temperature : in.temperature;
  double mean = 0.0;
  for (double t : T) mean += t / static_cast<double>(T.size());
  return mat.density.value(mean);
}

} // namespace

void continuum_distributed_load(const LoadGeometry& g, const ElementInput& in,
                                const DistributedLoad& ld, double magnitude, const Material& mat,
                                std::span<double> f, std::span<double> tangent) {
  const bool nlgeom = in.ctx && in.ctx->nlgeom;
  switch (ld.kind) {
  case DistLoadKind::Pressure:
    continuum_face_pressure(g, ld.face, magnitude, nlgeom, f, tangent);
    return;
  case DistLoadKind::Gravity: {
    const double rho = load_density(in, ld, mat, "GRAV");
    continuum_body_force(g,
                         {rho * magnitude * ld.direction[0], rho * magnitude * ld.direction[1],
                          rho * magnitude * ld.direction[2]},
                         f);
    return;
  }
  case DistLoadKind::BodyForce:
    continuum_body_force(
        g, {magnitude * ld.direction[0], magnitude * ld.direction[1], magnitude * ld.direction[2]},
        f);
    return;
  case DistLoadKind::Centrifugal:
    continuum_centrifugal(g, load_density(in, ld, mat, "CENTRIF") * magnitude, ld.point,
                          ld.direction, nlgeom, f, tangent, ld.loc,
                          fmt::format("element {}", in.label));
    return;
  default:
    return;
  }
}

} // namespace gapfem
