#include "fem/mortar.hpp"

#include "fe/quadrature.hpp"
#include "model/model.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace gapfem {

namespace {

using P2 = std::array<double, 2>;

Vec3 sub(const Vec3& a, const Vec3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 unit(const Vec3& v) {
  const double n = std::sqrt(dot(v, v));
  return n > 0 ? Vec3{v[0] / n, v[1] / n, v[2] / n} : v;
}
int corners(const SurfaceFacet& f) {
  switch (f.shape) {
  case Shape::Tri3:
  case Shape::Tri6:
    return 3;
  case Shape::Line2:
  case Shape::Line3:
    return 2;
  default:
    return 4;
  }
}
double signed_area(const std::vector<P2>& p) {
  double a = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const P2& u = p[i];
    const P2& v = p[(i + 1) % p.size()];
    a += u[0] * v[1] - v[0] * u[1];
  }
  return 0.5 * a;
}
/// Sutherland-Hodgman: `subject` clipped by the convex counter-clockwise polygon `clip`.
std::vector<P2> clip_polygon(std::vector<P2> subject, const std::vector<P2>& clip) {
  for (std::size_t e = 0; e < clip.size() && !subject.empty(); ++e) {
    const P2 a = clip[e], b = clip[(e + 1) % clip.size()];
    auto side = [&](const P2& p) {
      return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
    };
    std::vector<P2> out;
    for (std::size_t i = 0; i < subject.size(); ++i) {
      const P2 p = subject[i], q = subject[(i + 1) % subject.size()];
      const double sp = side(p), sq = side(q);
      if (sp >= 0) out.push_back(p);
      if ((sp >= 0) != (sq >= 0)) {
        const double t = sp / (sp - sq);
        out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
      }
    }
    subject = std::move(out);
  }
  return subject;
}

/// Accumulates N_s N_s' w and N_s N_m w at one point of the slave plane.
struct Accumulator {
  const Model& model;
  double gap;
  std::map<NodeId, std::map<NodeId, double>> M, D;
  void add(const SurfaceFacet& fs, const SurfaceFacet& fm, const Vec3& x, double w) {
    const FacetPoint ps = closest_point(model, fs, x);
    const FacetPoint pm = closest_point(model, fm, x);
    if (pm.distance > gap + 1e-9 * std::max(1.0, facet_size(model, fm))) return;
    for (int a = 0; a < fs.n_nodes; ++a) {
      if (ps.N[a] == 0.0) continue;
      auto& Ma = M[fs.nodes[a]];
      auto& Da = D[fs.nodes[a]];
      for (int b = 0; b < fs.n_nodes; ++b) Ma[fs.nodes[b]] += w * ps.N[a] * ps.N[b];
      for (int b = 0; b < fm.n_nodes; ++b) Da[fm.nodes[b]] += w * ps.N[a] * pm.N[b];
    }
  }
};

void integrate_3d(const Model& model, const SurfaceFacet& fs,
                  const std::vector<SurfaceFacet>& master, Accumulator& acc) {
  const int nc = corners(fs);
  std::array<Vec3, 4> X;
  Vec3 c{};
  for (int a = 0; a < nc; ++a) {
    X[a] = model.mesh.coords[fs.nodes[a]];
    for (int i = 0; i < 3; ++i) c[i] += X[a][i] / nc;
  }
  const Vec3 n = unit(nc == 4 ? cross(sub(X[2], X[0]), sub(X[3], X[1]))
                              : cross(sub(X[1], X[0]), sub(X[2], X[0])));
  const Vec3 t1 = unit(sub(X[1], X[0]));
  const Vec3 t2 = cross(n, t1);
  auto to_plane = [&](const Vec3& p) { return P2{dot(sub(p, c), t1), dot(sub(p, c), t2)}; };
  std::vector<P2> S;
  for (int a = 0; a < nc; ++a) S.push_back(to_plane(X[a]));
  if (signed_area(S) < 0) std::reverse(S.begin(), S.end());
  const double size = facet_size(model, fs);
  for (const SurfaceFacet& fm : master) {
    std::vector<P2> P;
    double dmax = 0.0;
    bool near = false;
    for (int a = 0; a < corners(fm); ++a) {
      const Vec3& Y = model.mesh.coords[fm.nodes[a]];
      P.push_back(to_plane(Y));
      dmax = std::max(dmax, std::abs(dot(sub(Y, c), n)));
      const P2 q = P.back();
      near |= std::abs(q[0]) < 2 * size && std::abs(q[1]) < 2 * size;
    }
    if (!near || dmax > acc.gap + size) continue;
    const double area = signed_area(P);
    if (std::abs(area) < 1e-14 * size * size) continue; // edge-on
    if (area < 0) std::reverse(P.begin(), P.end());
    const std::vector<P2> piece = clip_polygon(S, P);
    if (piece.size() < 3 || signed_area(piece) < 1e-12 * size * size) continue;
    for (std::size_t k = 1; k + 1 < piece.size(); ++k) {
      const P2 &v0 = piece[0], &v1 = piece[k], &v2 = piece[k + 1];
      const double tri =
          0.5 * std::abs((v1[0] - v0[0]) * (v2[1] - v0[1]) - (v2[0] - v0[0]) * (v1[1] - v0[1]));
      for (const QuadraturePoint& q : kTri6) {
        const double a = v0[0] + q.xi[0] * (v1[0] - v0[0]) + q.xi[1] * (v2[0] - v0[0]);
        const double b = v0[1] + q.xi[0] * (v1[1] - v0[1]) + q.xi[1] * (v2[1] - v0[1]);
        const Vec3 x{c[0] + a * t1[0] + b * t2[0], c[1] + a * t1[1] + b * t2[1],
                     c[2] + a * t1[2] + b * t2[2]};
        acc.add(fs, fm, x, 2.0 * tri * q.weight);
      }
    }
  }
}

void integrate_2d(const Model& model, const SurfaceFacet& fs,
                  const std::vector<SurfaceFacet>& master, bool axisymmetric, Accumulator& acc) {
  const Vec3 A = model.mesh.coords[fs.nodes[0]], B = model.mesh.coords[fs.nodes[1]];
  const Vec3 t = unit(sub(B, A));
  const double L = dot(sub(B, A), t);
  for (const SurfaceFacet& fm : master) {
    const Vec3& C = model.mesh.coords[fm.nodes[0]];
    const Vec3& E = model.mesh.coords[fm.nodes[1]];
    const double s0 = dot(sub(C, A), t), s1 = dot(sub(E, A), t);
    const double lo = std::max(0.0, std::min(s0, s1)), hi = std::min(L, std::max(s0, s1));
    if (hi - lo < 1e-12 * L) continue;
    for (const QuadraturePoint& q : kGaussLine3) {
      const double s = 0.5 * (lo + hi) + 0.5 * (hi - lo) * q.xi[0];
      const Vec3 x{A[0] + s * t[0], A[1] + s * t[1], 0.0};
      const double w = 0.5 * (hi - lo) * q.weight * (axisymmetric ? x[0] : 1.0);
      acc.add(fs, fm, x, w);
    }
  }
}

} // namespace

std::vector<MortarRow> mortar_rows(const Model& model, const std::vector<SurfaceFacet>& slave,
                                   const std::vector<SurfaceFacet>& master, double gap,
                                   bool space_2d) {
  Accumulator acc{model, gap, {}, {}};
  const bool axisymmetric = model.space == ModelSpace::Axisymmetric;
  for (const SurfaceFacet& fs : slave) {
    if (space_2d)
      integrate_2d(model, fs, master, axisymmetric, acc);
    else
      integrate_3d(model, fs, master, acc);
  }
  std::set<NodeId> master_nodes;
  for (const SurfaceFacet& f : master)
    for (int a = 0; a < f.n_nodes; ++a) master_nodes.insert(f.nodes[a]);
  std::vector<MortarRow> rows;
  for (const auto& [s, Ms] : acc.M) {
    if (master_nodes.count(s)) continue;
    const auto it = Ms.find(s);
    const double Mss = it == Ms.end() ? 0.0 : it->second;
    if (!(Mss > 0)) continue;
    MortarRow row;
    row.slave = s;
    row.slave_terms.emplace_back(s, 1.0);
    for (const auto& [s2, v] : Ms)
      if (s2 != s && std::abs(v) > 1e-14 * Mss) row.slave_terms.emplace_back(s2, v / Mss);
    for (const auto& [m, v] : acc.D[s])
      if (std::abs(v) > 1e-14 * Mss) row.master_terms.emplace_back(m, v / Mss);
    rows.push_back(std::move(row));
  }
  return rows;
}

} // namespace gapfem
