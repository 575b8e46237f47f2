// The heat-transfer shells DS3, DS4 and DS8: temperatures at the section points through the
// thickness (heat_shell.hpp; theory in docs/theory/thermal.md §7).
#include "elements/heat/heat_shell.hpp"

#include "elements/heat/face_exchange.hpp"
#include "elements/heat/heat_kernel.hpp"
#include "elements/structural/shell_geometry.hpp"
#include "elements/structural/shell_section.hpp"
#include "model/model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <vector>

namespace gapfem {

namespace {

constexpr int kMaxNodes = shell::kMaxNodes;
constexpr int kMaxPoints = kMaxTemperaturePoints;

constexpr std::array<DofType, kMaxPoints> kDofs = [] {
  std::array<DofType, kMaxPoints> d{};
  for (int k = 0; k < kMaxPoints; ++k) d[k] = temperature_dof(k);
  return d;
}();
constexpr std::array<std::string_view, 3> kHfl{"HFL1", "HFL2", "HFL3"};

/// d L_l / d s at the three points s = -1, 0, 1 of a layer (quadratic Lagrange, s in [-1, 1]).
constexpr double kDL[3][3] = {{-1.5, 2.0, -0.5}, {-0.5, 0.0, 0.5}, {0.5, -2.0, 1.5}};
/// Simpson's weights of a layer's three points, as fractions of the layer's thickness.
constexpr double kSimpson[3] = {1.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0};

/// Geometry of one point of the surface.
struct SurfacePoint {
  std::array<double, kMaxNodes> N{};
  std::array<Vec3, kMaxNodes> G{}; ///< surface gradients of N_a (tangent to the surface)
  double dA = 0.0;                 ///< area element times the rule's weight
  double t = 0.0;                  ///< thickness
  Vec3 n{}, e1{}, e2{};            ///< normal and local directions 1, 2
};

double dot3(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

bool surface_point(std::span<const Vec3> X, std::span<const double> thickness,
                   const std::array<double, 3>& rsw, SurfacePoint& p) {
  const int nn = static_cast<int>(X.size());
  const shell::Shape sh = shell::shape_at(nn, rsw[0], rsw[1]);
  Vec3 A1{}, A2{};
  p.t = 0.0;
  for (int a = 0; a < nn; ++a) {
    for (int i = 0; i < 3; ++i) {
      A1[i] += sh.dr[a] * X[a][i];
      A2[i] += sh.ds[a] * X[a][i];
    }
    p.N[a] = sh.N[a];
    p.t += sh.N[a] * thickness[a];
  }
  const Vec3 c{A1[1] * A2[2] - A1[2] * A2[1], A1[2] * A2[0] - A1[0] * A2[2],
               A1[0] * A2[1] - A1[1] * A2[0]};
  const double J = std::sqrt(dot3(c, c));
  if (!(J > 0.0) || !(p.t > 0.0)) return false;
  for (int i = 0; i < 3; ++i) p.n[i] = c[i] / J;
  p.dA = J * rsw[2];
  // contravariant basis A^1, A^2 from the inverse metric
  const double g11 = dot3(A1, A1), g12 = dot3(A1, A2), g22 = dot3(A2, A2);
  const double det = g11 * g22 - g12 * g12;
  Vec3 B1{}, B2{};
  for (int i = 0; i < 3; ++i) {
    B1[i] = (g22 * A1[i] - g12 * A2[i]) / det;
    B2[i] = (g11 * A2[i] - g12 * A1[i]) / det;
  }
  for (int a = 0; a < nn; ++a)
    for (int i = 0; i < 3; ++i) p.G[a][i] = sh.dr[a] * B1[i] + sh.ds[a] * B2[i];
  shell::local_directions(p.n, p.e1, p.e2);
  return true;
}

/// Conduction rule (DS3 1 point, DS4 2 x 2, DS8 3 x 3) and capacity/area rule (exact for N_a
/// times the area element: DS3 three edge midpoints, DS4 2 x 2, DS8 3 x 3, also exact for
/// N_a N_b of DS8).
shell::Rule conduction_rule(int nn) {
  return nn == 8 ? shell::gauss3x3_rule() : shell::full_rule(nn);
}
shell::Rule area_rule(int nn) {
  if (nn != 3) return conduction_rule(nn);
  shell::Rule q;
  q.n = 3;
  q.pts[0] = {0.5, 0.0, 1.0 / 6.0};
  q.pts[1] = {0.5, 0.5, 1.0 / 6.0};
  q.pts[2] = {0.0, 0.5, 1.0 / 6.0};
  return q;
}

class HeatShellKernel final : public ElementKernel {
 public:
  HeatShellKernel(ElementType type, HeatMaterial material, int n_points,
                  std::vector<double> thickness)
      : _type(type), _mat(std::move(material)), _P(n_points), _nn(element_info(type).n_nodes),
        _thickness(std::move(thickness)), _cond(conduction_rule(_nn)), _area(area_rule(_nn)) {
    // fraction of the thickness carried by each section point (Simpson's rule, composite)
    _frac.fill(0.0);
    if (_P == 1) {
      _frac[0] = 1.0;
    } else {
      const double h = 1.0 / layers();
      for (int j = 0; j < layers(); ++j)
        for (int i = 0; i < 3; ++i) _frac[2 * j + i] += h * kSimpson[i];
    }
  }

  ElementType type() const override { return _type; }
  std::span<const DofType> node_dofs(int) const override {
    return {kDofs.data(), static_cast<std::size_t>(_P)};
  }

  std::string validate(const ElementInput& in) const override {
    const auto t = thickness(in);
    for (int a = 0; a < _nn; ++a)
      if (!(t[a] > 0.0))
        return fmt::format("the shell thickness at its node {} is {}; give a positive thickness "
                           "(*SHELL SECTION or *NODAL THICKNESS)",
                           a + 1, t[a]);
    for (int q = 0; q < _cond.n; ++q) {
      SurfacePoint p;
      if (!surface_point(in.X, t, _cond.pts[q], p))
        return fmt::format("the element's surface is degenerate at integration point {} (zero "
                           "area); check the node coordinates and order",
                           q + 1);
    }
    return {};
  }

  void evaluate(const ElementInput& in, ElementOutput& out) const override {
    const int n = _nn * _P;
    const bool want_K = out.want_tangent && static_cast<int>(out.tangent.size()) == n * n;
    std::span<double> K = want_K ? out.tangent : std::span<double>{};
    const auto t = thickness(in);
    for (int q = 0; q < _cond.n; ++q) {
      SurfacePoint p;
      if (!surface_point(in.X, t, _cond.pts[q], p)) continue;
      add_surface_conduction(p, in.u, out.residual, K);
      if (_P > 1) add_thickness_conduction(p, in.u, out.residual, K);
    }
    const RateCoefficients rates = in.ctx ? rate_coefficients(*in.ctx) : RateCoefficients{};
    FE_CHECK(!rates.velocity_has_history(), "heat capacity: the integrator needs E's rate");
    if (rates.first_order) add_capacity(in, t, rates.v_du, out.residual, K);
    if (out.want_damping) add_capacity_block(in, t, out.damping);
    out.unsymmetric |= want_K && _mat.conductivity_varies();
  }

  /// No inertia; the heat capacity is the damping operator, integrated by the kernel itself.
  bool has_mass() const override { return false; }
  bool has_damping() const override { return _mat.has_capacity(); }
  bool damping_in_residual() const override { return true; }

  double stored_heat(const ElementInput& in) const override {
    double Q = 0.0;
    const auto t = thickness(in);
    for_capacity_points(in, t, [&](int, int, double w, double T, double T0, const SurfacePoint*) {
      Q += w * (_mat.energy(T) - _mat.energy(T0));
    });
    return Q;
  }

  bool supports_load(DistLoadKind kind, int face) const override {
    if (kind == DistLoadKind::BodyFlux) return face == 0;
    return (kind == DistLoadKind::SurfaceFlux || is_face_exchange(kind)) &&
           (face == 1 || face == 2);
  }

  void load(const ElementInput& in, const DistributedLoad& ld, double magnitude, double sink,
            std::span<double> f, std::span<double> K) const override {
    const int n = _nn * _P;
    if (static_cast<int>(K.size()) != n * n) K = {};
    const auto t = thickness(in);
    if (ld.kind == DistLoadKind::BodyFlux) {
      const auto V = nodal_volumes(in.X, t);
      for (int a = 0; a < _nn; ++a)
        for (int k = 0; k < _P; ++k) f[idx(a, k)] += magnitude * V[a] * _frac[k];
      return;
    }
    const int k = ld.face == 1 ? 0 : _P - 1; // SNEG: DOF 11, SPOS: the last point
    std::array<double, kMaxNodes> A{};
    std::array<std::array<double, kMaxNodes>, kMaxNodes> M{};
    for (int q = 0; q < _area.n; ++q) {
      SurfacePoint p;
      if (!surface_point(in.X, t, _area.pts[q], p)) continue;
      for (int a = 0; a < _nn; ++a) {
        A[a] += p.N[a] * p.dA;
        for (int b = 0; b < _nn; ++b) M[a][b] += p.N[a] * p.N[b] * p.dA;
      }
    }
    for (int a = 0; a < _nn; ++a) {
      if (ld.kind == DistLoadKind::SurfaceFlux) {
        f[idx(a, k)] += magnitude * A[a];
      } else if (lumped()) {
        const FaceExchange x = face_exchange(ld, magnitude, sink, in.u[idx(a, k)]);
        f[idx(a, k)] += A[a] * x.q;
        if (!K.empty()) K[idx(a, k) * n + idx(a, k)] -= A[a] * x.dq_dT;
      } else {
        for (int b = 0; b < _nn; ++b) {
          const FaceExchange x = face_exchange(ld, magnitude, sink, in.u[idx(b, k)]);
          f[idx(a, k)] += M[a][b] * x.q;
          if (!K.empty()) K[idx(a, k) * n + idx(b, k)] -= M[a][b] * x.dq_dT;
        }
      }
    }
  }

  bool supports_output(ElemVar var) const override { return var == ElemVar::HFL; }
  void recover(const ElementInput& in, ElementRecovery& out) const override {
    OutputBlock b;
    b.var = ElemVar::HFL;
    b.names = kHfl;
    b.n_points = _cond.n * _P;
    b.section_points = _P;
    b.values.assign(static_cast<std::size_t>(b.n_points * 3), 0.0);
    const auto t = thickness(in);
    for (int q = 0; q < _cond.n; ++q) {
      SurfacePoint p;
      if (!surface_point(in.X, t, _cond.pts[q], p)) continue;
      for (int k = 0; k < _P; ++k) {
        double T = 0.0;
        Vec3 gs{};
        point_values(p, in.u, k, T, gs);
        double kc = 0.0, dk = 0.0;
        _mat.conductivity(T, kc, dk);
        double* v = &b.values[static_cast<std::size_t>(3 * (q * _P + k))];
        // + 0.0: a zero flux prints as 0, not -0
        v[0] = -kc * dot3(gs, p.e1) + 0.0;
        v[1] = -kc * dot3(gs, p.e2) + 0.0;
        v[2] = -kc * thickness_gradient(p, in.u, k) + 0.0;
      }
    }
    out.blocks.push_back(std::move(b));
  }

 private:
  int layers() const { return (_P - 1) / 2; }
  bool lumped() const { return _nn != 8; }
  int idx(int a, int k) const { return a * _P + k; }
  std::span<const double> thickness(const ElementInput& in) const {
    return {_thickness.data() + static_cast<std::size_t>(in.block_index) * _nn,
            static_cast<std::size_t>(_nn)};
  }

  /// Temperature and its surface gradient at section point k.
  void point_values(const SurfacePoint& p, std::span<const double> u, int k, double& T,
                    Vec3& gs) const {
    T = 0.0;
    gs = Vec3{};
    for (int a = 0; a < _nn; ++a) {
      const double Ta = u[idx(a, k)];
      T += p.N[a] * Ta;
      for (int i = 0; i < 3; ++i) gs[i] += p.G[a][i] * Ta;
    }
  }

  /// dT/dz at section point k (the mean of the two layers' values at a point they share).
  double thickness_gradient(const SurfacePoint& p, std::span<const double> u, int k) const {
    if (_P == 1) return 0.0;
    const double h = p.t / layers();
    double sum = 0.0;
    int count = 0;
    for (int j = std::max(0, (k - 1) / 2); j <= std::min(layers() - 1, k / 2); ++j) {
      const int i = k - 2 * j;
      if (i < 0 || i > 2) continue;
      for (int a = 0; a < _nn; ++a)
        for (int l = 0; l < 3; ++l) sum += p.N[a] * (2.0 / h) * kDL[i][l] * u[idx(a, 2 * j + l)];
      ++count;
    }
    return count ? sum / count : 0.0;
  }

  /// Conduction along the surface at every section point (weights: Simpson's through the
  /// thickness).
  void add_surface_conduction(const SurfacePoint& p, std::span<const double> u, std::span<double> r,
                              std::span<double> K) const {
    const int n = _nn * _P;
    for (int k = 0; k < _P; ++k) {
      double T = 0.0;
      Vec3 gs{};
      point_values(p, u, k, T, gs);
      double kc = 0.0, dk = 0.0;
      _mat.conductivity(T, kc, dk);
      const double W = p.dA * p.t * _frac[k];
      std::array<double, kMaxNodes> Gg{};
      for (int a = 0; a < _nn; ++a) {
        Gg[a] = dot3(p.G[a], gs);
        r[idx(a, k)] += W * kc * Gg[a];
      }
      if (K.empty()) continue;
      for (int a = 0; a < _nn; ++a)
        for (int b = 0; b < _nn; ++b)
          K[idx(a, k) * n + idx(b, k)] += W * (kc * dot3(p.G[a], p.G[b]) + dk * p.N[b] * Gg[a]);
    }
  }

  /// Conduction through the thickness, layer by layer (Simpson's rule is exact for it).
  void add_thickness_conduction(const SurfacePoint& p, std::span<const double> u,
                                std::span<double> r, std::span<double> K) const {
    const int n = _nn * _P;
    const double h = p.t / layers();
    for (int j = 0; j < layers(); ++j) {
      const int k0 = 2 * j;
      for (int i = 0; i < 3; ++i) {
        const int k = k0 + i;
        double T = 0.0, gz = 0.0;
        for (int a = 0; a < _nn; ++a) {
          T += p.N[a] * u[idx(a, k)];
          for (int l = 0; l < 3; ++l) gz += p.N[a] * (2.0 / h) * kDL[i][l] * u[idx(a, k0 + l)];
        }
        double kc = 0.0, dk = 0.0;
        _mat.conductivity(T, kc, dk);
        const double W = p.dA * h * kSimpson[i];
        for (int a = 0; a < _nn; ++a)
          for (int l = 0; l < 3; ++l) {
            const double Bal = p.N[a] * (2.0 / h) * kDL[i][l];
            r[idx(a, k0 + l)] += W * kc * Bal * gz;
            if (K.empty()) continue;
            const int row = idx(a, k0 + l) * n;
            for (int b = 0; b < _nn; ++b) {
              for (int m = 0; m < 3; ++m)
                K[row + idx(b, k0 + m)] += W * kc * Bal * p.N[b] * (2.0 / h) * kDL[i][m];
              K[row + idx(b, k)] += W * dk * p.N[b] * Bal * gz;
            }
          }
      }
    }
  }

  /// V_a = integral of N_a t over the surface.
  std::array<double, kMaxNodes> nodal_volumes(std::span<const Vec3> X,
                                              std::span<const double> t) const {
    std::array<double, kMaxNodes> V{};
    for (int q = 0; q < _area.n; ++q) {
      SurfacePoint p;
      if (!surface_point(X, t, _area.pts[q], p)) continue;
      for (int a = 0; a < _nn; ++a) V[a] += p.N[a] * p.dA * p.t;
    }
    return V;
  }

  /// Calls f(a, k, weight, T, T0, point) for every capacity point: the nodes (lumped; point is
  /// null) or the surface rule's points (consistent, a = -1) at each section point.
  template <class F>
  void for_capacity_points(const ElementInput& in, std::span<const double> t, F&& f) const {
    auto start = [&](int i) { return in.u_start.empty() ? in.u[i] : in.u_start[i]; };
    if (lumped()) {
      const auto V = nodal_volumes(in.X, t);
      for (int a = 0; a < _nn; ++a)
        for (int k = 0; k < _P; ++k)
          f(a, k, V[a] * _frac[k], in.u[idx(a, k)], start(idx(a, k)), nullptr);
      return;
    }
    for (int q = 0; q < _area.n; ++q) {
      SurfacePoint p;
      if (!surface_point(in.X, t, _area.pts[q], p)) continue;
      for (int k = 0; k < _P; ++k) {
        double T = 0.0, T0 = 0.0;
        for (int a = 0; a < _nn; ++a) {
          T += p.N[a] * in.u[idx(a, k)];
          T0 += p.N[a] * start(idx(a, k));
        }
        f(-1, k, p.dA * p.t * _frac[k], T, T0, &p);
      }
    }
  }

  /// d(capacity flux) / d(temperature rate) into D (same points as the flux).
  void add_capacity_block(const ElementInput& in, std::span<const double> t,
                          std::span<double> D) const {
    const int n = _nn * _P;
    for_capacity_points(in, t,
                        [&](int a, int k, double w, double T, double, const SurfacePoint* p) {
                          const double c = w * _mat.capacity(T);
                          if (!p) {
                            D[idx(a, k) * n + idx(a, k)] += c;
                            return;
                          }
                          for (int b = 0; b < _nn; ++b)
                            for (int d = 0; d < _nn; ++d)
                              D[idx(b, k) * n + idx(d, k)] += c * p->N[b] * p->N[d];
                        });
  }

  /// The capacity flux with E's rate v_du (E(T) - E(T0)) and its tangent (v_du = 1/dt: backward
  /// Euler, the step's integrator; the kernel never sees dt).
  void add_capacity(const ElementInput& in, std::span<const double> t, double inv_dt,
                    std::span<double> r, std::span<double> K) const {
    const int n = _nn * _P;
    for_capacity_points(in, t,
                        [&](int a, int k, double w, double T, double T0, const SurfacePoint* p) {
                          const double e = w * (_mat.energy(T) - _mat.energy(T0)) * inv_dt;
                          const double c = w * _mat.capacity(T) * inv_dt;
                          if (!p) {
                            r[idx(a, k)] += e;
                            if (!K.empty()) K[idx(a, k) * n + idx(a, k)] += c;
                            return;
                          }
                          for (int b = 0; b < _nn; ++b) {
                            r[idx(b, k)] += p->N[b] * e;
                            if (K.empty()) continue;
                            for (int d = 0; d < _nn; ++d)
                              K[idx(b, k) * n + idx(d, k)] += c * p->N[b] * p->N[d];
                          }
                        });
  }

  ElementType _type;
  HeatMaterial _mat;
  int _P = 1;
  int _nn = 4;
  std::vector<double> _thickness; ///< per element of the block, per node
  shell::Rule _cond, _area;
  std::array<double, kMaxPoints> _frac{};
};

} // namespace

std::unique_ptr<ElementKernel> make_heat_shell_kernel(const KernelContext& ctx) {
  const Model& model = ctx.model;
  const ShellSection& sec = shell::shell_section_of(ctx);
  const std::string entity = fmt::format("ELSET={}", sec.elset);
  if (sec.material < 0 || sec.material >= static_cast<int>(model.materials.size()))
    throw InputError(sec.loc, entity, "the *SHELL SECTION has no valid MATERIAL");
  if (sec.n_points > kMaxTemperaturePoints)
    throw InputError(sec.loc, entity,
                     fmt::format("heat-transfer shells carry at most {} temperatures through the "
                                 "thickness (DOFs 11-{}); give at most {} section points",
                                 kMaxTemperaturePoints, kMaxAbaqusDof, kMaxTemperaturePoints));
  HeatMaterial m = heat_material_for(ctx, model.materials[sec.material]);
  std::vector<double> thickness = shell::block_thicknesses(ctx, sec);
  return std::make_unique<HeatShellKernel>(ctx.type, std::move(m), sec.n_points,
                                           std::move(thickness));
}

} // namespace gapfem
