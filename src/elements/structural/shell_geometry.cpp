#include "elements/structural/shell_geometry.hpp"

#include "common/error.hpp"
#include "elements/reference_scale.hpp"
#include "elements/structural/structural_common.hpp"

#include <cmath>
#include <fmt/format.h>

namespace gapfem::shell {

using structural::cross;
using structural::dot;
using structural::norm;
using structural::scale;

namespace {
constexpr std::array<std::array<double, 2>, 8> kQuadNodes{
    {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1}, {1, 0}, {0, 1}, {-1, 0}}};
constexpr std::array<std::array<double, 2>, 3> kTriNodes{{{0, 0}, {1, 0}, {0, 1}}};

Vec3 unit(const Vec3& a) {
  const double l = norm(a);
  return l > 0.0 ? scale(1.0 / l, a) : Vec3{0.0, 0.0, 0.0};
}
} // namespace

Shape shape_at(int n_nodes, double r, double s) {
  Shape sh;
  if (n_nodes == 3) {
    sh.N = {1.0 - r - s, r, s};
    sh.dr = {-1.0, 1.0, 0.0};
    sh.ds = {-1.0, 0.0, 1.0};
    return sh;
  }
  for (int a = 0; a < 4; ++a) {
    const double ra = kQuadNodes[a][0], sa = kQuadNodes[a][1];
    const double fr = 1.0 + r * ra, fs = 1.0 + s * sa;
    if (n_nodes == 4) {
      sh.N[a] = 0.25 * fr * fs;
      sh.dr[a] = 0.25 * ra * fs;
      sh.ds[a] = 0.25 * fr * sa;
    } else {
      const double g = r * ra + s * sa - 1.0;
      sh.N[a] = 0.25 * fr * fs * g;
      sh.dr[a] = 0.25 * ra * fs * (g + fr);
      sh.ds[a] = 0.25 * fr * sa * (g + fs);
    }
  }
  if (n_nodes == 8)
    for (int a = 4; a < 8; ++a) {
      const double ra = kQuadNodes[a][0], sa = kQuadNodes[a][1];
      if (ra == 0.0) {
        sh.N[a] = 0.5 * (1.0 - r * r) * (1.0 + s * sa);
        sh.dr[a] = -r * (1.0 + s * sa);
        sh.ds[a] = 0.5 * (1.0 - r * r) * sa;
      } else {
        sh.N[a] = 0.5 * (1.0 + r * ra) * (1.0 - s * s);
        sh.dr[a] = 0.5 * ra * (1.0 - s * s);
        sh.ds[a] = -s * (1.0 + r * ra);
      }
    }
  return sh;
}

std::array<double, 2> node_coordinates(int n_nodes, int a) {
  return n_nodes == 3 ? kTriNodes[a] : kQuadNodes[a];
}

void local_directions(const Vec3& n, Vec3& e1, Vec3& e2) {
  const double c = std::cos(0.1 * M_PI / 180.0);
  const Vec3 axis = std::abs(n[0]) > c ? Vec3{0.0, 0.0, 1.0} : Vec3{1.0, 0.0, 0.0};
  e1 = unit(structural::sub(axis, scale(dot(axis, n), n)));
  e2 = cross(n, e1);
}

bool surface_point(std::span<const Vec3> X, std::span<const Vec3> directors,
                   std::span<const double> thickness, double r, double s, double w,
                   SurfacePoint& p) {
  const int nn = static_cast<int>(X.size());
  p.sh = shape_at(nn, r, s);
  p.r = r;
  p.s = s;
  p.A1 = p.A2 = p.D = p.Dr = p.Ds = Vec3{0.0, 0.0, 0.0};
  p.thickness = 0.0;
  for (int a = 0; a < nn; ++a)
    for (int i = 0; i < 3; ++i) {
      p.A1[i] += p.sh.dr[a] * X[a][i];
      p.A2[i] += p.sh.ds[a] * X[a][i];
      p.D[i] += p.sh.N[a] * directors[a][i];
      p.Dr[i] += p.sh.dr[a] * directors[a][i];
      p.Ds[i] += p.sh.ds[a] * directors[a][i];
    }
  for (int a = 0; a < nn; ++a) p.thickness += p.sh.N[a] * thickness[a];
  const Vec3 c = cross(p.A1, p.A2);
  const double j = norm(c);
  if (!(j > 0.0)) return false;
  p.n = scale(1.0 / j, c);
  p.dA = j * w;
  local_directions(p.n, p.e1, p.e2);
  // contravariant tangents A^alpha = a^{alpha beta} A_beta
  const double a11 = dot(p.A1, p.A1), a12 = dot(p.A1, p.A2), a22 = dot(p.A2, p.A2);
  const double det = a11 * a22 - a12 * a12;
  Vec3 C1, C2;
  for (int i = 0; i < 3; ++i) {
    C1[i] = (a22 * p.A1[i] - a12 * p.A2[i]) / det;
    C2[i] = (-a12 * p.A1[i] + a11 * p.A2[i]) / det;
  }
  p.T = {{{dot(C1, p.e1), dot(C1, p.e2)}, {dot(C2, p.e1), dot(C2, p.e2)}}};
  return true;
}

Vec3 element_normal_at_node(std::span<const Vec3> X, int a) {
  const int nn = static_cast<int>(X.size());
  const auto rs = node_coordinates(nn, a);
  const Shape sh = shape_at(nn, rs[0], rs[1]);
  Vec3 A1{}, A2{};
  for (int b = 0; b < nn; ++b)
    for (int i = 0; i < 3; ++i) {
      A1[i] += sh.dr[b] * X[b][i];
      A2[i] += sh.ds[b] * X[b][i];
    }
  return unit(cross(A1, A2));
}

Rule full_rule(int n_nodes) {
  Rule q;
  if (n_nodes == 3) {
    q.n = 1;
    q.pts[0] = {1.0 / 3.0, 1.0 / 3.0, 0.5};
    return q;
  }
  const double g = 1.0 / std::sqrt(3.0);
  q.n = 4;
  // Abaqus's order of the 2x2 points: (-,-), (+,-), (-,+), (+,+)
  q.pts[0] = {-g, -g, 1.0};
  q.pts[1] = {g, -g, 1.0};
  q.pts[2] = {-g, g, 1.0};
  q.pts[3] = {g, g, 1.0};
  return q;
}

Rule gauss3x3_rule() {
  Rule q;
  const double g = std::sqrt(0.6), x[3] = {-g, 0.0, g}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  q.n = 9;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) q.pts[3 * j + i] = {x[i], x[j], w[i] * w[j]};
  return q;
}

std::array<double, 3> centre_point(int n_nodes) {
  if (n_nodes == 3) return {1.0 / 3.0, 1.0 / 3.0, 0.5};
  return {0.0, 0.0, 4.0};
}

std::string check_geometry(std::span<const Vec3> X_given, std::span<const Vec3> directors,
                           std::span<const double> thickness_given, double model_size_given) {
  // the check sees the shell scaled by a power of two to an extent near 1 (reference_scale.hpp),
  // lengths and thicknesses alike: areas and normals of coordinates near 1e200 do not overflow
  const int nn = static_cast<int>(X_given.size());
  FE_CHECK(nn <= 9, "check_geometry: a shell element has at most 9 nodes");
  const double f = unit_scale(X_given);
  std::array<Vec3, 9> Xs{};
  std::array<double, 9> ts{};
  for (int a = 0; a < nn; ++a) {
    for (int i = 0; i < 3; ++i) Xs[a][i] = f * X_given[a][i];
    ts[a] = f * thickness_given[a];
  }
  const std::span<const Vec3> X(Xs.data(), static_cast<std::size_t>(nn));
  const std::span<const double> thickness(ts.data(), static_cast<std::size_t>(nn));
  const double model_size = f * model_size_given;
  for (int a = 0; a < nn; ++a)
    if (!(thickness_given[a] > 0.0))
      return fmt::format("the shell thickness at its node {} is {}; give a positive thickness "
                         "(*SHELL SECTION or *NODAL THICKNESS)",
                         a + 1, thickness_given[a]);
  for (int a = 0; a < nn; ++a)
    for (int b = a + 1; b < nn; ++b)
      if (point_distance(X[a], X[b]) <= 1e-12 * model_size)
        return fmt::format("its nodes {} and {} coincide; a shell needs distinct nodes", a + 1,
                           b + 1);
  // the area element must keep its sign over the element (no folded or inverted corners)
  const Rule q = full_rule(nn);
  SurfacePoint ref, p;
  const auto c = centre_point(nn);
  if (!surface_point(X, directors, thickness, c[0], c[1], 1.0, ref))
    return "its surface has zero area; check the node coordinates";
  for (int k = 0; k < nn; ++k) {
    const auto rs = node_coordinates(nn, k);
    if (!surface_point(X, directors, thickness, rs[0], rs[1], 1.0, p) || dot(p.n, ref.n) <= 0.1)
      return fmt::format("its surface folds over at its node {} (the corner angle is 180 degrees "
                         "or more, or the nodes are not numbered around the element); renumber "
                         "the nodes or remesh",
                         k + 1);
  }
  for (int k = 0; k < q.n; ++k)
    if (!surface_point(X, directors, thickness, q.pts[k][0], q.pts[k][1], 1.0, p) ||
        dot(p.n, ref.n) <= 0.1)
      return "its surface folds over inside the element; check the node numbering";
  return {};
}

} // namespace gapfem::shell
