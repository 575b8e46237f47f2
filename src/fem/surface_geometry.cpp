#include "fem/surface_geometry.hpp"

#include "fe/quadrature.hpp"
#include "model/model.hpp"

#include <algorithm>
#include <cmath>

namespace gapfem {

std::optional<Shape> cell_shape(ElementType type) {
  const auto cell = element_info(type).cell;
  if (!cell || shape_dim(*cell) < 2) return std::nullopt;
  return cell;
}

namespace {

/// The facet of a shell's SNEG (face 1) or SPOS (face 2) side: the whole reference surface, its
/// nodes ordered so that the facet normal points out of that side (SNEG reversed).
bool shell_facet(const Model& model, const Surface::Face& f, Shape cell, SurfaceFacet& sf) {
  if (f.face != 1 && f.face != 2) return false;
  const auto nodes = model.mesh.element_nodes(f.elem);
  static constexpr std::array<int, 8> tri3{0, 2, 1}, tri6{0, 2, 1, 5, 4, 3}, quad4{0, 3, 2, 1},
      quad8{0, 3, 2, 1, 7, 6, 5, 4};
  const std::array<int, 8>* reversed = nullptr;
  switch (cell) {
  case Shape::Tri3:
    reversed = &tri3;
    break;
  case Shape::Tri6:
    reversed = &tri6;
    break;
  case Shape::Quad4:
    reversed = &quad4;
    break;
  case Shape::Quad8:
    reversed = &quad8;
    break;
  default:
    return false;
  }
  sf.elem = f.elem;
  sf.face = f.face;
  sf.shape = cell;
  sf.n_nodes = static_cast<int>(nodes.size());
  for (int a = 0; a < sf.n_nodes; ++a) sf.nodes[a] = nodes[f.face == 1 ? (*reversed)[a] : a];
  return true;
}

} // namespace

std::vector<SurfaceFacet> surface_facets(const Model& model, const Surface& surface) {
  std::vector<SurfaceFacet> out;
  for (const Surface::Face& f : surface.faces) {
    const auto cell = cell_shape(model.mesh.elem_types[f.elem]);
    if (!cell) continue;
    if (element_info(model.mesh.elem_types[f.elem]).family == ElementFamily::Shell) {
      SurfaceFacet sf;
      if (shell_facet(model, f, *cell, sf)) out.push_back(sf);
      continue;
    }
    const auto faces = element_faces(*cell);
    if (f.face < 1 || f.face > static_cast<int>(faces.size())) continue;
    const FaceDef& fd = faces[f.face - 1];
    const auto nodes = model.mesh.element_nodes(f.elem);
    SurfaceFacet sf;
    sf.elem = f.elem;
    sf.face = f.face;
    sf.shape = fd.shape;
    sf.n_nodes = fd.n_nodes;
    for (int a = 0; a < fd.n_nodes; ++a) sf.nodes[a] = nodes[fd.nodes[a]];
    out.push_back(sf);
  }
  return out;
}

namespace {

/// x(xi) and the tangents dx/dxi_k of a facet.
void facet_map(const Model& model, const SurfaceFacet& f, const double* xi, Vec3& x,
               std::array<Vec3, 2>& t, std::array<double, 8>& N) {
  std::array<double, 16> dN{};
  shape_eval(f.shape, {xi, 2}, {N.data(), static_cast<std::size_t>(f.n_nodes)},
             {dN.data(), static_cast<std::size_t>(f.n_nodes * shape_dim(f.shape))});
  const int dim = shape_dim(f.shape);
  x = {};
  t = {};
  for (int a = 0; a < f.n_nodes; ++a) {
    const Vec3& X = model.mesh.coords[f.nodes[a]];
    for (int i = 0; i < 3; ++i) {
      x[i] += N[a] * X[i];
      for (int k = 0; k < dim; ++k) t[k][i] += dN[a * dim + k] * X[i];
    }
  }
}

double norm(const Vec3& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

bool triangle(Shape s) {
  return s == Shape::Tri3 || s == Shape::Tri6;
}

/// Projects facet coordinates onto the facet's parameter domain.
void clamp_domain(Shape s, std::array<double, 2>& xi) {
  if (shape_dim(s) == 1) {
    xi[0] = std::clamp(xi[0], -1.0, 1.0);
    xi[1] = 0.0;
  } else if (triangle(s)) {
    xi[0] = std::max(xi[0], 0.0);
    xi[1] = std::max(xi[1], 0.0);
    const double over = xi[0] + xi[1] - 1.0;
    if (over > 0) { // onto the hypotenuse, then back into the corners
      xi[0] -= 0.5 * over;
      xi[1] -= 0.5 * over;
      if (xi[0] < 0) xi = {0.0, 1.0};
      if (xi[1] < 0) xi = {1.0, 0.0};
    }
  } else {
    xi[0] = std::clamp(xi[0], -1.0, 1.0);
    xi[1] = std::clamp(xi[1], -1.0, 1.0);
  }
}

} // namespace

void add_tributary_areas(const Model& model, const SurfaceFacet& f,
                         std::map<NodeId, double>& area) {
  const int dim = shape_dim(f.shape);
  const bool quadratic = shape_quadratic(f.shape);
  std::array<double, 8> share{};
  double total = 0.0;
  for (const QuadraturePoint& q : face_load_rule(f.shape)) {
    Vec3 x;
    std::array<Vec3, 2> t;
    std::array<double, 8> N;
    facet_map(model, f, q.xi.data(), x, t, N);
    double J = norm(t[0]);
    if (dim == 2) {
      const Vec3 n{t[0][1] * t[1][2] - t[0][2] * t[1][1], t[0][2] * t[1][0] - t[0][0] * t[1][2],
                   t[0][0] * t[1][1] - t[0][1] * t[1][0]};
      J = norm(n);
    }
    total += q.weight * J;
    for (int a = 0; a < f.n_nodes; ++a) share[a] += q.weight * J * N[a];
  }
  for (int a = 0; a < f.n_nodes; ++a) area[f.nodes[a]] += quadratic ? total / f.n_nodes : share[a];
}

FacetPoint closest_point(const Model& model, const SurfaceFacet& f, const Vec3& p) {
  const int dim = shape_dim(f.shape);
  FacetPoint out;
  out.xi = triangle(f.shape) ? std::array<double, 2>{1.0 / 3.0, 1.0 / 3.0}
                             : std::array<double, 2>{0.0, 0.0};
  // Gauss-Newton on |x(xi) - p|^2 with the coordinates kept in the facet's domain
  for (int it = 0; it < 50; ++it) {
    Vec3 x;
    std::array<Vec3, 2> t;
    facet_map(model, f, out.xi.data(), x, t, out.N);
    const Vec3 r{x[0] - p[0], x[1] - p[1], x[2] - p[2]};
    double g[2] = {0, 0}, H[2][2] = {{0, 0}, {0, 0}};
    for (int k = 0; k < dim; ++k) {
      for (int i = 0; i < 3; ++i) g[k] += t[k][i] * r[i];
      for (int l = 0; l < dim; ++l)
        for (int i = 0; i < 3; ++i) H[k][l] += t[k][i] * t[l][i];
    }
    std::array<double, 2> step{};
    if (dim == 1) {
      step[0] = H[0][0] > 0 ? -g[0] / H[0][0] : 0.0;
    } else {
      const double det = H[0][0] * H[1][1] - H[0][1] * H[1][0];
      if (!(std::abs(det) > 0)) break;
      step[0] = -(H[1][1] * g[0] - H[0][1] * g[1]) / det;
      step[1] = -(-H[1][0] * g[0] + H[0][0] * g[1]) / det;
    }
    const std::array<double, 2> before = out.xi;
    out.xi[0] += step[0];
    out.xi[1] += step[1];
    clamp_domain(f.shape, out.xi);
    if (std::abs(out.xi[0] - before[0]) + std::abs(out.xi[1] - before[1]) < 1e-13) break;
  }
  std::array<Vec3, 2> t;
  facet_map(model, f, out.xi.data(), out.point, t, out.N);
  const Vec3 r{out.point[0] - p[0], out.point[1] - p[1], out.point[2] - p[2]};
  out.distance = norm(r);
  return out;
}

double facet_size(const Model& model, const SurfaceFacet& f) {
  const int corners = f.shape == Shape::Tri6    ? 3
                      : f.shape == Shape::Line3 ? 2
                      : f.shape == Shape::Quad8 ? 4
                                                : f.n_nodes;
  double size = 0.0;
  for (int a = 0; a < corners; ++a)
    for (int b = a + 1; b < corners; ++b) {
      const Vec3& A = model.mesh.coords[f.nodes[a]];
      const Vec3& B = model.mesh.coords[f.nodes[b]];
      size = std::max(size, norm({A[0] - B[0], A[1] - B[1], A[2] - B[2]}));
    }
  return size;
}

} // namespace gapfem
