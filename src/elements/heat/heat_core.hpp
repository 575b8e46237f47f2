#pragma once
/// @file heat_core.hpp
/// Heat conduction, heat capacity and thermal loads of one element, shared by the heat-transfer
/// kernels (DC1D2 … DC3D10, heat_kernel.hpp) and the coupled temperature-displacement kernels
/// (CPS4T … C3D8T, T2D2T/T3D2T), which place the temperature DOF at a different position of their
/// local vectors (HeatLayout). Theory and conventions: docs/theory/thermal.md.
///
/// With the nodal temperatures T_a (trial) and T0_a (start of the increment), f_a the element's
/// internal "flux" vector (residual r = f_int - f_ext, as for forces):
///   conduction  f_a = sum_q dV_q grad N_a . k(T_q) grad T_q,   T_q = sum_b N_b(q) T_b
///               tangent k grad N_a . grad N_b + k'(T_q) N_b grad N_a . grad T_q (unsymmetric
///               when k depends on T)
///   capacity    (transient steps) f_a = integral N_a dE/dt dV, E the internal energy per volume
///               (heat_material.hpp), its rate as the step's integrator says (StepContext::rates,
///               elements/rate_coefficients.hpp): backward Euler (E(T) - E(T0)) v_du, v_du = 1/dt,
///               tangent C(T) N_a N_b v_du. The kernel never sees dt. The damping operator (on
///               request, ElementOutput::damping) is d f / d(T rate) = integral C(T) N_a N_b dV.
///               First-order elements integrate it at the nodes (lumped: V_a (E(T_a) - E(T0_a))
///               v_du with V_a = integral N_a dV), as Abaqus does ("Integration in diffusive heat
///               transfer elements": the internal energy term of first-order elements is integrated
///               at the nodes); the quadratic shapes integrate it consistently with a rule exact
///               for N_a N_b.
///   loads       body flux BF: f_ext,a = r V_a; surface flux Sn: f_ext,a = q A_a; film Fn:
///               f_ext,a = h A_a (T_sink - T_a), tangent h A_a (nodal integration for first-order
///               elements, as Abaqus integrates distributed fluxes of first-order elements at the
///               nodes); quadratic faces integrate consistently (h integral N_a N_b dA).
/// dV carries the cross-section area (DC1D2, trusses), the thickness (planar) or 2 pi r
/// (axisymmetric). Everything is allocation-free; the object is immutable and thread-safe.
#include "elements/element_kernel.hpp"
#include "elements/heat/face_exchange.hpp"
#include "elements/heat/heat_material.hpp"
#include "elements/reference_scale.hpp"
#include "fe/element_faces.hpp"
#include "fe/quadrature.hpp"
#include "fe/shape_functions.hpp"

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <span>
#include <string>
#include <string_view>

namespace gapfem {

/// How the element's reference geometry carries a volume.
enum class HeatGeometry : std::uint8_t {
  Line,         ///< two-node link: length x cross-section area
  Planar,       ///< area x thickness
  Axisymmetric, ///< area x 2 pi r (totals around the circumference)
  Solid,        ///< volume
};

/// Position of the temperature DOF of node a in an element's local vectors.
struct HeatLayout {
  int stride = 1; ///< DOFs per node
  int offset = 0; ///< position of NT among them
  int n_dofs = 0; ///< total local DOFs (row length of the tangent)
  int index(int a) const { return a * stride + offset; }
};

namespace heat_detail {

/// 36-point collapsed Gauss rule on the unit tetrahedron (3 x 3 x 4 Gauss points in u, v, w with
/// xi = u (1-v)(1-w), eta = v (1-w), zeta = w and the weight factor (1-v)(1-w)^2): exact for
/// polynomials of degree 4, i.e. for N_a N_b of the straight-sided quadratic tetrahedron.
inline constexpr std::array<QuadraturePoint, 36> kTetCapacity = [] {
  constexpr double g3[3] = {0.5 - 0.5 * 0.77459666924148337704, 0.5,
                            0.5 + 0.5 * 0.77459666924148337704};
  constexpr double w3[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
  constexpr double a = 0.33998104358485626480, b = 0.86113631159405257522;
  constexpr double wa = 0.65214515486254614263, wb = 0.34785484513745385737;
  constexpr double g4[4] = {0.5 - 0.5 * b, 0.5 - 0.5 * a, 0.5 + 0.5 * a, 0.5 + 0.5 * b};
  constexpr double w4[4] = {0.5 * wb, 0.5 * wa, 0.5 * wa, 0.5 * wb};
  std::array<QuadraturePoint, 36> q{};
  int n = 0;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        const double u = g3[i], v = g3[j], w = g4[k];
        q[n].xi = {u * (1.0 - v) * (1.0 - w), v * (1.0 - w), w};
        q[n].weight = w3[i] * w3[j] * w4[k] * (1.0 - v) * (1.0 - w) * (1.0 - w);
        ++n;
      }
  return q;
}();

/// 16-point collapsed Gauss rule on the unit triangle (4 x 4 Gauss points in u, v with
/// xi = u (1 - v), eta = v and the weight factor (1 - v)): exact for polynomials of degree 6, i.e.
/// for N_a N_b of the quadratic triangle times the radius of axisymmetric elements.
inline constexpr std::array<QuadraturePoint, 16> kTriCapacity = [] {
  constexpr double a = 0.33998104358485626480, b = 0.86113631159405257522;
  constexpr double wa = 0.65214515486254614263, wb = 0.34785484513745385737;
  constexpr double g4[4] = {0.5 - 0.5 * b, 0.5 - 0.5 * a, 0.5 + 0.5 * a, 0.5 + 0.5 * b};
  constexpr double w4[4] = {0.5 * wb, 0.5 * wa, 0.5 * wa, 0.5 * wb};
  std::array<QuadraturePoint, 16> q{};
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const double u = g4[i], v = g4[j];
      q[4 * j + i].xi = {u * (1.0 - v), v, 0.0};
      q[4 * j + i].weight = w4[i] * w4[j] * (1.0 - v);
    }
  return q;
}();

/// 18-point wedge rule (6-point degree-4 triangle rule x 3 Gauss points): exact for N_a N_b of
/// the straight-sided quadratic wedge.
inline constexpr std::array<QuadraturePoint, 18> kWedgeCapacity = [] {
  constexpr double z[3] = {-0.77459666924148337704, 0.0, 0.77459666924148337704};
  constexpr double w[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  std::array<QuadraturePoint, 18> q{};
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 6; ++i)
      q[6 * k + i] = {{kTri6[i].xi[0], kTri6[i].xi[1], z[k]}, kTri6[i].weight * w[k]};
  return q;
}();

/// Rule for the capacity and the nodal volumes: exact for N_a times the volume weight (first-order
/// shapes, including the 2 pi r of axisymmetric ones) and for N_a N_b (quadratic shapes, which
/// integrate the capacity consistently).
constexpr std::span<const QuadraturePoint> capacity_rule(Shape s) {
  switch (s) {
  case Shape::Line2:
    return kGaussLine2;
  case Shape::Tri3:
    return kTri3;
  case Shape::Quad4:
    return kGaussQuad4;
  case Shape::Tet4:
    return kTet4;
  case Shape::Hex8:
    return kGaussHex8;
  case Shape::Wedge6:
    return kWedge6;
  case Shape::Tet10:
    return kTetCapacity;
  case Shape::Tri6:
    return kTriCapacity;
  case Shape::Quad8:
    return kGaussQuad9;
  case Shape::Wedge15:
    return kWedgeCapacity;
  case Shape::Hex20:
    return kGaussHex27;
  default:
    return {};
  }
}
constexpr int capacity_points(Shape s) {
  return static_cast<int>(capacity_rule(s).size());
}
/// Points of the conduction (full) rule (fe/quadrature.hpp, full_integration_rule).
constexpr int conduction_points(Shape s) {
  switch (s) {
  case Shape::Line2:
    return 2;
  case Shape::Tri3:
  case Shape::Tet4:
    return 1;
  case Shape::Wedge6:
    return 2;
  case Shape::Tri6:
    return 3;
  case Shape::Hex8:
    return 8;
  case Shape::Quad8:
  case Shape::Wedge15:
    return 9;
  case Shape::Hex20:
    return 27;
  default:
    return 4; // Quad4, Tet10
  }
}

inline constexpr std::array<std::string_view, 3> kHflNames{"HFL1", "HFL2", "HFL3"};

} // namespace heat_detail

template <Shape S, HeatGeometry G>
class HeatCore {
 public:
  static constexpr int NN = shape_n_nodes(S);
  static constexpr int D = shape_dim(S); ///< heat-flux components
  static constexpr int NQ = heat_detail::conduction_points(S);
  static constexpr int NC = heat_detail::capacity_points(S);
  /// First-order elements integrate capacity, fluxes and films at the nodes.
  static constexpr bool kLumped = !shape_quadratic(S);
  static constexpr int kMaxFaceNodes = 8;
  using Temps = std::array<double, NN>;
  using MatG = Eigen::Matrix<double, NN, D>;

  /// `section`: cross-section area (Line) or thickness (Planar); ignored otherwise.
  HeatCore(HeatMaterial material, double section) : _mat(std::move(material)), _section(section) {
    const auto rule = full_integration_rule(S);
    FE_CHECK(static_cast<int>(rule.size()) == NQ, "heat conduction rule size mismatch");
    for (int q = 0; q < NQ; ++q) tabulate(rule[q], _cond[q]);
    const auto crule = heat_detail::capacity_rule(S);
    FE_CHECK(static_cast<int>(crule.size()) == NC, "heat capacity rule size mismatch");
    for (int q = 0; q < NC; ++q) tabulate(crule[q], _cap[q]);
  }

  const HeatMaterial& material() const { return _mat; }
  double section() const { return _section; }

  /// An empty string, or a sentence about the geometry (caller adds element and deck location).
  std::string validate(std::span<const Vec3> given) const {
    std::array<Vec3, NN> xs{}; // the element at an extent near 1: no det J overflows or underflows
    const std::span<const Vec3> X = scaled_nodes(given, xs);
    if ((G == HeatGeometry::Line || G == HeatGeometry::Planar) && !(_section > 0.0))
      return G == HeatGeometry::Line ? "the cross-section area on *SOLID SECTION must be positive"
                                     : "the *SOLID SECTION thickness must be positive";
    for (int q = 0; q < NQ; ++q) {
      Point p;
      if (!geometry(X, _cond[q], p))
        return G == HeatGeometry::Line
                   ? std::string("the two nodes of the element coincide; check the coordinates")
                   : fmt::format("element is inverted or degenerate (Jacobian <= 0 at integration "
                                 "point {}); check the node order",
                                 q + 1);
      if (G == HeatGeometry::Axisymmetric && !(p.r > 0.0))
        return fmt::format("axisymmetric element has integration point {} at r <= 0; "
                           "axisymmetric models must lie in x >= 0",
                           q + 1);
    }
    return {};
  }

  /// Adds conduction (and, in steps whose integrator defines rates, capacity) to the residual
  /// and, when `K` is not empty, the tangent. Returns true when the added tangent is unsymmetric.
  bool add_internal(std::span<const Vec3> X, const Temps& T, const Temps& T0,
                    const StepContext* ctx, const HeatLayout& L, std::span<double> r,
                    std::span<double> K) const {
    const bool want_K = !K.empty();
    auto Kat = [&](int a, int b) -> double& { return K[L.index(a) * L.n_dofs + L.index(b)]; };
    for (int q = 0; q < NQ; ++q) {
      Point p;
      geometry(X, _cond[q], p);
      double Tq = 0.0;
      for (int a = 0; a < NN; ++a) Tq += _cond[q].N[a] * T[a];
      Eigen::Matrix<double, D, 1> grad = Eigen::Matrix<double, D, 1>::Zero();
      for (int a = 0; a < NN; ++a) grad += T[a] * p.g.row(a).transpose();
      double k = 0.0, dk = 0.0;
      _mat.conductivity(Tq, k, dk);
      const Eigen::Matrix<double, NN, 1> gq = p.g * grad; // grad N_a . grad T
      for (int a = 0; a < NN; ++a) r[L.index(a)] += p.dV * k * gq(a);
      if (!want_K) continue;
      const Eigen::Matrix<double, NN, NN> GG = p.g * p.g.transpose();
      for (int a = 0; a < NN; ++a)
        for (int b = 0; b < NN; ++b)
          Kat(a, b) += p.dV * (k * GG(a, b) + dk * _cond[q].N[b] * gq(a));
    }
    const RateCoefficients rates = ctx ? rate_coefficients(*ctx) : RateCoefficients{};
    if (rates.first_order) {
      // E's rate is v_du (E(T) - E(T0)): an integrator whose rates carry history (v_v, v_a) needs
      // the committed rate of E in the element's history (not there yet)
      FE_CHECK(!rates.velocity_has_history(), "heat capacity: the integrator needs E's rate");
      const double inv_dt = rates.v_du;
      if constexpr (kLumped) {
        const Temps V = nodal_volumes(X);
        for (int a = 0; a < NN; ++a) {
          r[L.index(a)] += V[a] * (_mat.energy(T[a]) - _mat.energy(T0[a])) * inv_dt;
          if (want_K) Kat(a, a) += V[a] * _mat.capacity(T[a]) * inv_dt;
        }
      } else {
        for (int q = 0; q < NC; ++q) {
          Point p;
          geometry(X, _cap[q], p);
          double Tq = 0.0, T0q = 0.0;
          for (int a = 0; a < NN; ++a) {
            Tq += _cap[q].N[a] * T[a];
            T0q += _cap[q].N[a] * T0[a];
          }
          const double e = p.dV * (_mat.energy(Tq) - _mat.energy(T0q)) * inv_dt;
          const double c = p.dV * _mat.capacity(Tq) * inv_dt;
          for (int a = 0; a < NN; ++a) {
            r[L.index(a)] += _cap[q].N[a] * e;
            if (want_K)
              for (int b = 0; b < NN; ++b) Kat(a, b) += c * _cap[q].N[a] * _cap[q].N[b];
          }
        }
      }
    }
    return want_K && _mat.conductivity_varies();
  }

  /// The damping operator of the capacity, d(capacity flux) / d(temperature rate) = integral
  /// C(T) N_a N_b dV (lumped at the nodes for first-order elements, like the flux), added to
  /// `damping`.
  void add_capacity_block(std::span<const Vec3> X, const Temps& T, const HeatLayout& L,
                          std::span<double> damping) const {
    auto Dat = [&](int a, int b) -> double& { return damping[L.index(a) * L.n_dofs + L.index(b)]; };
    if constexpr (kLumped) {
      const Temps V = nodal_volumes(X);
      for (int a = 0; a < NN; ++a) Dat(a, a) += V[a] * _mat.capacity(T[a]);
    } else {
      for (int q = 0; q < NC; ++q) {
        Point p;
        geometry(X, _cap[q], p);
        double Tq = 0.0;
        for (int a = 0; a < NN; ++a) Tq += _cap[q].N[a] * T[a];
        const double c = p.dV * _mat.capacity(Tq);
        for (int a = 0; a < NN; ++a)
          for (int b = 0; b < NN; ++b) Dat(a, b) += c * _cap[q].N[a] * _cap[q].N[b];
      }
    }
  }

  /// Heat stored between T0 and T: integral of E(T) - E(T0) (the same quadrature as the capacity,
  /// so that it equals dt times the sum of the capacity terms of the residual).
  double stored_heat(std::span<const Vec3> X, const Temps& T, const Temps& T0) const {
    double Q = 0.0;
    if constexpr (kLumped) {
      const Temps V = nodal_volumes(X);
      for (int a = 0; a < NN; ++a) Q += V[a] * (_mat.energy(T[a]) - _mat.energy(T0[a]));
    } else {
      for (int q = 0; q < NC; ++q) {
        Point p;
        geometry(X, _cap[q], p);
        double Tq = 0.0, T0q = 0.0;
        for (int a = 0; a < NN; ++a) {
          Tq += _cap[q].N[a] * T[a];
          T0q += _cap[q].N[a] * T0[a];
        }
        Q += p.dV * (_mat.energy(Tq) - _mat.energy(T0q));
      }
    }
    return Q;
  }

  /// Number of faces for Sn / Fn (the two ends of a link).
  static int n_faces() {
    if constexpr (S == Shape::Line2)
      return 2;
    else
      return static_cast<int>(element_faces(S).size());
  }

  bool supports_load(DistLoadKind kind, int face) const {
    if (kind == DistLoadKind::BodyFlux) return face == 0;
    if (kind == DistLoadKind::SurfaceFlux || is_face_exchange(kind))
      return face >= 1 && face <= n_faces();
    return false;
  }

  /// Thermal loads: adds f_ext (and for films and radiation -d f_ext / dT to K when not empty).
  void add_load(std::span<const Vec3> X, const Temps& T, const DistributedLoad& ld,
                double magnitude, double sink, const HeatLayout& L, std::span<double> f,
                std::span<double> K) const {
    auto Kat = [&](int a, int b) -> double& { return K[L.index(a) * L.n_dofs + L.index(b)]; };
    if (ld.kind == DistLoadKind::BodyFlux) {
      const Temps V = nodal_volumes(X);
      for (int a = 0; a < NN; ++a) f[L.index(a)] += magnitude * V[a];
      return;
    }
    if (ld.kind != DistLoadKind::SurfaceFlux && !is_face_exchange(ld.kind)) return;
    FE_CHECK(ld.face >= 1 && ld.face <= n_faces(), "heat load: face out of range");
    Face fc;
    face_matrix(X, ld.face, fc);
    for (int i = 0; i < fc.n; ++i) {
      const int a = fc.node[i];
      if (ld.kind == DistLoadKind::SurfaceFlux) {
        f[L.index(a)] += magnitude * fc.area[i];
        continue;
      }
      if constexpr (kLumped) {
        const FaceExchange x = face_exchange(ld, magnitude, sink, T[a]);
        f[L.index(a)] += fc.area[i] * x.q;
        if (!K.empty()) Kat(a, a) -= fc.area[i] * x.dq_dT;
      } else {
        for (int j = 0; j < fc.n; ++j) {
          const int b = fc.node[j];
          const FaceExchange x = face_exchange(ld, magnitude, sink, T[b]);
          f[L.index(a)] += fc.M[i][j] * x.q;
          if (!K.empty()) Kat(a, b) -= fc.M[i][j] * x.dq_dT;
        }
      }
    }
  }

  /// Heat flux q = -k grad T at the conduction points: NQ rows of D components into `values`.
  void heat_flux(std::span<const Vec3> X, const Temps& T, std::span<double> values) const {
    for (int q = 0; q < NQ; ++q) {
      Point p;
      geometry(X, _cond[q], p);
      double Tq = 0.0;
      Eigen::Matrix<double, D, 1> grad = Eigen::Matrix<double, D, 1>::Zero();
      for (int a = 0; a < NN; ++a) {
        Tq += _cond[q].N[a] * T[a];
        grad += T[a] * p.g.row(a).transpose();
      }
      double k = 0.0, dk = 0.0;
      _mat.conductivity(Tq, k, dk);
      for (int i = 0; i < D; ++i) values[q * D + i] = -k * grad(i);
    }
  }
  static std::span<const std::string_view> flux_names() {
    return {heat_detail::kHflNames.data(), static_cast<std::size_t>(D)};
  }

  /// V_a = integral of N_a over the element (with area, thickness or 2 pi r).
  Temps nodal_volumes(std::span<const Vec3> X) const {
    Temps V{};
    for (int q = 0; q < NC; ++q) {
      Point p;
      geometry(X, _cap[q], p);
      for (int a = 0; a < NN; ++a) V[a] += _cap[q].N[a] * p.dV;
    }
    return V;
  }

 private:
  struct Tab {
    double w = 0.0;
    std::array<double, NN> N{};
    Eigen::Matrix<double, NN, D> dN; ///< parametric derivatives
  };
  struct Point {
    MatG g = MatG::Zero(); ///< d N_a / d x
    double dV = 0.0;
    double r = 0.0; ///< radius (axisymmetric)
  };
  struct Face {
    int n = 0;
    std::array<int, kMaxFaceNodes> node{};
    std::array<double, kMaxFaceNodes> area{};                         ///< A_a
    std::array<std::array<double, kMaxFaceNodes>, kMaxFaceNodes> M{}; ///< integral N_a N_b dA
  };

  static void tabulate(const QuadraturePoint& qp, Tab& t) {
    double dN[NN * D];
    ShapeFunctions<S>::eval(qp.xi.data(), t.N.data(), dN);
    t.w = qp.weight;
    for (int a = 0; a < NN; ++a)
      for (int k = 0; k < D; ++k) t.dN(a, k) = dN[a * D + k];
  }

  /// Physical gradients and volume weight at a tabulated point; false if degenerate.
  bool geometry(std::span<const Vec3> X, const Tab& t, Point& p) const {
    if constexpr (G == HeatGeometry::Line) {
      Vec3 d{};
      for (int a = 0; a < NN; ++a)
        for (int i = 0; i < 3; ++i) d[i] += X[a][i] * t.dN(a, 0);
      const double J = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      if (!(J > 0.0)) return false;
      p.g = t.dN / J;
      p.dV = t.w * J * _section;
      return true;
    } else {
      Eigen::Matrix<double, D, D> J = Eigen::Matrix<double, D, D>::Zero();
      for (int a = 0; a < NN; ++a)
        for (int i = 0; i < D; ++i)
          for (int k = 0; k < D; ++k) J(i, k) += X[a][i] * t.dN(a, k);
      const double det = J.determinant();
      if (!(det > 0.0)) return false;
      p.g.noalias() = t.dN * J.inverse();
      p.dV = t.w * det;
      if constexpr (G == HeatGeometry::Planar) p.dV *= _section;
      if constexpr (G == HeatGeometry::Axisymmetric) {
        p.r = 0.0;
        for (int a = 0; a < NN; ++a) p.r += t.N[a] * X[a][0];
        p.dV *= 2.0 * std::numbers::pi * p.r;
      }
      return true;
    }
  }

  /// Nodal areas and the face mass matrix of face `face` (1-based) in the reference configuration.
  void face_matrix(std::span<const Vec3> X, int face, Face& fc) const {
    if constexpr (S == Shape::Line2) {
      fc.n = 1;
      fc.node[0] = face - 1;
      fc.area[0] = _section;
      fc.M[0][0] = _section;
      return;
    } else {
      const FaceDef& fd = element_faces(S)[face - 1];
      fc.n = fd.n_nodes;
      for (int i = 0; i < fc.n; ++i) fc.node[i] = fd.nodes[i];
      const int fdim = shape_dim(fd.shape);
      std::array<double, kMaxFaceNodes> N{};
      std::array<double, 2 * kMaxFaceNodes> dN{};
      for (const QuadraturePoint& q : face_load_rule(fd.shape)) {
        shape_eval(fd.shape, q.xi, N, dN);
        double dA = 0.0;
        if constexpr (D == 3) {
          Vec3 t1{}, t2{};
          for (int j = 0; j < fc.n; ++j)
            for (int i = 0; i < 3; ++i) {
              t1[i] += X[fc.node[j]][i] * dN[fdim * j];
              t2[i] += X[fc.node[j]][i] * dN[fdim * j + 1];
            }
          const double n0 = t1[1] * t2[2] - t1[2] * t2[1], n1 = t1[2] * t2[0] - t1[0] * t2[2],
                       n2 = t1[0] * t2[1] - t1[1] * t2[0];
          dA = q.weight * std::sqrt(n0 * n0 + n1 * n1 + n2 * n2);
        } else {
          double xp = 0.0, yp = 0.0, r = 0.0;
          for (int j = 0; j < fc.n; ++j) {
            xp += X[fc.node[j]][0] * dN[j];
            yp += X[fc.node[j]][1] * dN[j];
            r += X[fc.node[j]][0] * N[j];
          }
          dA = q.weight * std::sqrt(xp * xp + yp * yp) *
               (G == HeatGeometry::Axisymmetric ? 2.0 * std::numbers::pi * r : _section);
        }
        for (int i = 0; i < fc.n; ++i) {
          fc.area[i] += N[i] * dA;
          for (int j = 0; j < fc.n; ++j) fc.M[i][j] += N[i] * N[j] * dA;
        }
      }
    }
  }

  HeatMaterial _mat;
  double _section = 1.0;
  std::array<Tab, NQ> _cond;
  std::array<Tab, NC> _cap;
};

} // namespace gapfem
