#pragma once
/// @file continuum_kernel.hpp
/// The stress/displacement continuum element kernels (C3D8, C3D4, C3D10, CPS3, CPS4, CPE3, CPE4,
/// CAX3, CAX4) as one template over the element traits. Theory: docs/theory/continuum.md.
///
/// Formulation, per integration point q with reference volume weight dV_q (w det J, times the
/// thickness for plane elements or 2 pi R for axisymmetric ones):
///   small strain  eps = sym(H),                       sigma = law(eps)
///   NLGEOM        E = sym(H) + 1/2 H^T H (total Lagrangian), S = law(E) (second Piola-Kirchhoff)
///   residual      r = sum_q B^T s dV_q,   tangent K = sum_q (B^T D B + geometric) dV_q
/// The law is the material's solid law (elements/material/solid_law.hpp; isotropic elasticity
/// S = C : (E - eps_th I) today), called through the shared point loop (solid_point.hpp).
/// B-bar (C3D8, CPE4, CAX4; Abaqus's fully integrated first-order elements use selectively reduced
/// integration of the volumetric part, Abaqus Theory Guide, "Solid isoparametric quadrilaterals
/// and hexahedra", section "Fully integrated first-order isoparametric elements"): the volumetric
/// part of the strain (the trace over the three normal components, which includes the hoop strain
/// of CAX4) is replaced by its element mean, Ebar = E + (Theta_bar - tr E)/3 I. Under NLGEOM the
/// same substitution is applied to the Green-Lagrange strain; the element energy is a function of
/// Ebar(u), so the tangent is its Hessian and stays symmetric.
#include "elements/element_kernel.hpp"
#include "elements/reference_scale.hpp"
#include "elements/solid/continuum_loads.hpp"
#include "elements/solid/continuum_mass.hpp"
#include "elements/solid/solid_point.hpp"
#include "fe/element_faces.hpp"
#include "fe/quadrature.hpp"
#include "fe/shape_functions.hpp"
#include "model/material.hpp"
#include "model/section.hpp"

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <memory>
#include <numbers>
#include <string_view>
#include <vector>

namespace gapfem {

/// What a continuum kernel needs from the model.
struct ContinuumSetup {
  Material material;      ///< copy of the section's material
  double thickness = 1.0; ///< plane elements
  bool needs_temperature = false;
  /// first-order reduced-integration elements (reduced_kernel.hpp): *SECTION CONTROLS
  HourglassControl hourglass = HourglassControl::Enhanced;
  double hourglass_scale = 1.0;
};

/// Compile-time description of one continuum element type.
/// Reduced: the reduced rule of the R types (fe/quadrature.hpp; only for the quadratic shapes,
/// which need no hourglass control).
template <ElementType T, Shape S, Kinematics K, bool BBar, bool Reduced = false>
struct ContinuumTraits {
  static constexpr ElementType type = T;
  static constexpr Shape shape = S;
  static constexpr Kinematics kin = K;
  static constexpr bool bbar = BBar;
  static constexpr bool reduced = Reduced;
  static_assert(!Reduced || shape_quadratic(S), "reduced integration of a linear shape needs "
                                                "hourglass control");
};

namespace continuum_detail {
inline constexpr std::array<DofType, 3> kDofs3{DofType::U1, DofType::U2, DofType::U3};
inline constexpr std::array<DofType, 2> kDofs2{DofType::U1, DofType::U2};
inline constexpr std::array<std::string_view, 6> kS3{"S11", "S22", "S33", "S12", "S13", "S23"};
inline constexpr std::array<std::string_view, 6> kE3{"E11", "E22", "E33", "E12", "E13", "E23"};
inline constexpr std::array<std::string_view, 4> kS4{"S11", "S22", "S33", "S12"};
inline constexpr std::array<std::string_view, 4> kE4{"E11", "E22", "E33", "E12"};
inline constexpr std::array<std::string_view, 3> kSps{"S11", "S22", "S12"};
inline constexpr std::array<std::string_view, 3> kEps{"E11", "E22", "E12"};

constexpr int n_strain(Kinematics k) {
  return voigt_size(k);
}
constexpr int n_normal(Kinematics k) {
  return voigt_normals(k);
}
/// Points of the stiffness rule (full_integration_rule / reduced_integration_rule).
constexpr int n_points(Shape s, bool reduced) {
  switch (s) {
  case Shape::Hex8:
    return 8;
  case Shape::Hex20:
    return reduced ? 8 : 27;
  case Shape::Quad8:
    return reduced ? 4 : 9;
  case Shape::Wedge15:
    return 9;
  case Shape::Wedge6:
    return 2;
  case Shape::Tri6:
    return 3;
  case Shape::Tet10:
    return 4;
  case Shape::Quad4:
    return 4;
  default:
    return 1;
  }
}

/// Tensor index pairs (I, J) of the Voigt components in the output order of a kinematic class.
template <Kinematics K>
constexpr std::array<std::array<int, 2>, n_strain(K)> voigt_pairs() {
  if constexpr (K == Kinematics::ThreeD)
    return {{{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}}};
  else if constexpr (K == Kinematics::PlaneStress)
    return {{{0, 0}, {1, 1}, {0, 1}}};
  else
    return {{{0, 0}, {1, 1}, {2, 2}, {0, 1}}};
}

/// S and E output blocks with their component names, sized for n_points points.
template <Kinematics K>
void stress_strain_blocks(int n_points, OutputBlock& sb, OutputBlock& eb) {
  sb.var = ElemVar::S;
  eb.var = ElemVar::E;
  if constexpr (K == Kinematics::ThreeD) {
    sb.names = kS3;
    eb.names = kE3;
  } else if constexpr (K == Kinematics::PlaneStress) {
    sb.names = kSps;
    eb.names = kEps;
  } else {
    sb.names = kS4;
    eb.names = kE4;
  }
  sb.n_points = eb.n_points = n_points;
  sb.values.resize(static_cast<std::size_t>(n_points * n_strain(K)));
  eb.values.resize(static_cast<std::size_t>(n_points * n_strain(K)));
}

/// Cauchy stress F S F^T / det F in the output order, from the second Piola-Kirchhoff stress S,
/// the in-plane (or 3-D) F, F33 (CPE, CAX) and, plane stress, the law's thickness strain E33.
template <Kinematics K, class VecS, class MatF>
VecS cauchy_stress(const VecS& S, const MatF& Fin, double F33, double thickness_strain) {
  constexpr int ND = K == Kinematics::ThreeD ? 3 : 2;
  constexpr auto C = voigt_pairs<K>();
  Eigen::Matrix3d Sg = Eigen::Matrix3d::Zero(), F = Eigen::Matrix3d::Identity();
  for (int c = 0; c < n_strain(K); ++c) Sg(C[c][0], C[c][1]) = Sg(C[c][1], C[c][0]) = S(c);
  F.topLeftCorner<ND, ND>() = Fin;
  if constexpr (K == Kinematics::PlaneStress) {
    F(2, 2) = std::sqrt(std::max(1.0 + 2.0 * thickness_strain, 0.0));
  } else if constexpr (ND == 2) {
    F(2, 2) = F33;
  }
  const Eigen::Matrix3d sig = F * Sg * F.transpose() / F.determinant();
  VecS out;
  for (int c = 0; c < n_strain(K); ++c) out(c) = sig(C[c][0], C[c][1]);
  return out;
}

/// det F of a point (1 without NLGEOM): its current volume over its reference volume; plane
/// stress with the thickness stretch of the law's thickness strain E33, CPE/CAX with F33.
template <Kinematics K, class MatF>
double volume_ratio(const MatF& Fin, double F33, double thickness_strain, bool nlgeom) {
  if (!nlgeom) return 1.0;
  double j = Fin.determinant();
  if constexpr (K == Kinematics::PlaneStress)
    j *= std::sqrt(std::max(1.0 + 2.0 * thickness_strain, 0.0));
  else if constexpr (K != Kinematics::ThreeD)
    j *= F33;
  return j;
}

inline constexpr std::array<std::string_view, 1> kSener{"SENER"};
inline constexpr std::array<std::string_view, 1> kEvol{"EVOL"};
inline constexpr std::array<std::string_view, 3> kCoord{"COORD1", "COORD2", "COORD3"};

/// ENER (the strain energy density SENER), COORD and EVOL of a continuum element, gathered point
/// by point in recover().
class PointExtras {
 public:
  PointExtras(int n_points, int nd) : _nd(nd) {
    _sener.var = ElemVar::ENER;
    _sener.names = kSener;
    _sener.n_points = _coord.n_points = n_points;
    _sener.values.resize(static_cast<std::size_t>(n_points));
    _coord.var = ElemVar::COORD;
    _coord.names = std::span<const std::string_view>(kCoord.data(), static_cast<std::size_t>(nd));
    _coord.values.resize(static_cast<std::size_t>(n_points * nd));
  }
  /// Point q: its energy density, its volume (current under NLGEOM) and its coordinates, the
  /// interpolation sum_a N_a (X_a + u_a) (u only under NLGEOM).
  template <class Weights>
  void add(const ElementInput& in, int q, double sener, double volume, const Weights& N, int nn,
           bool nlgeom) {
    _sener.values[static_cast<std::size_t>(q)] = sener;
    _volume += volume;
    for (int i = 0; i < _nd; ++i) {
      double x = 0.0;
      for (int a = 0; a < nn; ++a)
        x += N(a) * (in.X[a][i] + (nlgeom ? in.u[static_cast<std::size_t>(a * _nd + i)] : 0.0));
      _coord.values[static_cast<std::size_t>(q * _nd + i)] = x;
    }
  }
  void append_to(ElementRecovery& out) {
    OutputBlock evol;
    evol.var = ElemVar::EVOL;
    evol.names = kEvol;
    evol.n_points = 1;
    evol.values = {_volume};
    out.blocks.push_back(std::move(_sener));
    out.blocks.push_back(std::move(_coord));
    out.blocks.push_back(std::move(evol));
  }

 private:
  int _nd;
  double _volume = 0.0;
  OutputBlock _sener, _coord;
};

/// The variables every continuum kernel reports (ELSE from the strain energy: fem/assembler).
constexpr bool continuum_output(ElemVar var) {
  return var == ElemVar::S || var == ElemVar::E || var == ElemVar::ENER || var == ElemVar::ELSE ||
         var == ElemVar::EVOL || var == ElemVar::COORD;
}

} // namespace continuum_detail

template <class Tr>
class ContinuumKernel final : public ElementKernel {
 public:
  static constexpr Kinematics kKin = Tr::kin;
  static constexpr Shape kShape = Tr::shape;
  static constexpr int NN = shape_n_nodes(Tr::shape);
  static constexpr int ND = kKin == Kinematics::ThreeD ? 3 : 2;
  static constexpr int NS = continuum_detail::n_strain(kKin);
  static constexpr int NNRM = continuum_detail::n_normal(kKin);
  static constexpr int NDOF = NN * ND;
  static constexpr int NIP = continuum_detail::n_points(Tr::shape, Tr::reduced);
  static constexpr bool kAxi = kKin == Kinematics::Axisymmetric;

  using VecS = Eigen::Matrix<double, NS, 1>;
  using MatB = Eigen::Matrix<double, NS, NDOF>;
  using VecD = Eigen::Matrix<double, NDOF, 1>;
  using MatK = Eigen::Matrix<double, NDOF, NDOF, Eigen::RowMajor>;
  using MatG = Eigen::Matrix<double, NN, ND>;
  using MatF = Eigen::Matrix<double, ND, ND>;

  explicit ContinuumKernel(ContinuumSetup setup)
      : _setup(std::move(setup)), _law(_setup.material, kKin) {
    const auto rule =
        Tr::reduced ? reduced_integration_rule(Tr::shape) : full_integration_rule(Tr::shape);
    FE_CHECK(static_cast<int>(rule.size()) == NIP, "continuum rule size mismatch");
    for (int q = 0; q < NIP; ++q) {
      _w[q] = rule[q].weight;
      double N[NN], dN[NN * ND];
      ShapeFunctions<Tr::shape>::eval(rule[q].xi.data(), N, dN);
      for (int a = 0; a < NN; ++a) {
        _N[q](a) = N[a];
        for (int k = 0; k < ND; ++k) _dN[q](a, k) = dN[a * ND + k];
      }
    }
  }

  ElementType type() const override { return Tr::type; }
  std::span<const DofType> node_dofs(int) const override {
    if constexpr (ND == 3)
      return continuum_detail::kDofs3;
    else
      return continuum_detail::kDofs2;
  }
  bool uses_temperature_field() const override { return _setup.needs_temperature; }
  int n_state() const override { return NIP * _law.n_state(); }
  /// The consistent mass, full rule (continuum_mass.hpp); zero without *DENSITY.
  bool has_mass() const override { return true; }
  bool has_damping() const override { return false; }
  void initialize(const ElementInput& in) const override { initialize_points(_law, NIP, in.state); }
  /// The material law at the points (for the coupled and the tests).
  const SolidLaw& law() const { return *_law; }

  std::string validate(const ElementInput& given) const override {
    std::array<Vec3, NN> xs{}; // the element at an extent near 1: no det J overflows or underflows
    ElementInput in = given;
    in.X = scaled_nodes(given.X, xs);
    for (int q = 0; q < NIP; ++q) {
      MatG g;
      double detJ = 0.0;
      reference_gradients(in, q, g, detJ);
      if (!(detJ > 0.0))
        return fmt::format("element is inverted or degenerate (Jacobian <= 0 at integration point "
                           "{}); check the node order",
                           q + 1);
      if constexpr (kAxi) {
        if (!(radius(in, q) > 0.0))
          return fmt::format("axisymmetric element has integration point {} at r <= 0; "
                             "axisymmetric models must lie in x >= 0",
                             q + 1);
      }
    }
    if (_setup.thickness <= 0.0) return "the *SOLID SECTION thickness must be positive";
    return {};
  }

  void evaluate(const ElementInput& in, ElementOutput& out) const override {
    if (out.want_mass && !out.mass.empty())
      add_continuum_mass<kShape, kKin>(in, _setup.material, _setup.thickness, out.mass);
    Work w;
    compute(in, w, in.state);
    Eigen::Map<VecD> r(out.residual.data());
    const bool want_K = out.want_tangent && out.tangent.size() == NDOF * NDOF;
    MatK K;
    if (want_K) K.setZero();
    const bool nlgeom = in.ctx && in.ctx->nlgeom;
    bool pairs = kNodePairs; // the isotropic fast path needs an isotropic tangent at every point
    for (int q = 0; q < NIP && pairs; ++q) pairs = w.ip[q].law.isotropic;
    for (int q = 0; q < NIP; ++q) {
      const Ip& p = w.ip[q];
      if (!want_K || pairs)
        add_point<NS>(p.law, p.B, p.S, p.dV, r, static_cast<MatK*>(nullptr));
      else
        add_point<NS>(p.law, p.B, p.S, p.dV, r, &K);
      if (!want_K) continue;
      if constexpr (kNodePairs)
        if (pairs) add_material_pairs(p, K);
      if (nlgeom) add_geometric(p, w, q, K);
    }
    if (want_K) {
      if constexpr (kNodePairs)
        if (pairs) // the upper triangle of node pairs was formed
          for (int a = 0; a < NN; ++a)
            for (int b = 0; b < a; ++b)
              K.template block<ND, ND>(a * ND, b * ND) =
                  K.template block<ND, ND>(b * ND, a * ND).transpose();
      Eigen::Map<MatK> Kout(out.tangent.data());
      Kout += K;
    }
  }

  /// The initial-stress matrix of the perturbation du: the geometric term at in.u (NLGEOM
  /// kinematics) with the stress change dS = (S(u + h du) - S(u - h du)) / (2 h) in place of the
  /// stress (exact for a law linear in the strain; B-bar's mean pressure alike).
  bool stress_stiffness(const ElementInput& in, std::span<const double> du,
                        std::span<double> Kout) const override {
    if (Kout.size() != static_cast<std::size_t>(NDOF * NDOF) || du.size() != in.u.size())
      return false;
    double big = 0.0;
    for (double v : du) big = std::max(big, std::abs(v));
    if (!(big > 0.0)) return true;
    StepContext nl = in.ctx ? *in.ctx : StepContext{};
    nl.nlgeom = true;
    ElementInput at = in;
    at.ctx = &nl;
    const double h = 1e-6 * std::max(nl.model_size, 1e-300) / big;
    std::array<double, NDOF> up{}, um{};
    for (int i = 0; i < NDOF; ++i) {
      up[i] = in.u[i] + h * du[i];
      um[i] = in.u[i] - h * du[i];
    }
    std::vector<double> trial(static_cast<std::size_t>(n_state()));
    auto w0 = std::make_unique<Work>(), wp = std::make_unique<Work>(),
         wm = std::make_unique<Work>();
    compute(at, *w0, trial);
    at.u = up;
    compute(at, *wp, trial);
    at.u = um;
    compute(at, *wm, trial);
    if constexpr (Tr::bbar) w0->p_bar = (wp->p_bar - wm->p_bar) / (2.0 * h);
    auto K = std::make_unique<MatK>(MatK::Zero());
    for (int q = 0; q < NIP; ++q) {
      Ip p = w0->ip[q];
      p.S = (wp->ip[q].S - wm->ip[q].S) / (2.0 * h);
      add_geometric(p, *w0, q, *K);
    }
    Eigen::Map<MatK> out(Kout.data());
    out += *K;
    return true;
  }

  /// Coupled temperature-displacement elements (coupled_continuum.hpp): the derivative of the
  /// residual with respect to the nodal temperatures in.temperature (thermal strain and
  /// temperature-dependent elasticity at each point), NDOF x NN row-major, overwritten. The strain
  /// (B-bar included) does not depend on temperature, so d r / d T_b = sum_q B^T dS/dT N_b dV.
  void temperature_tangent(const ElementInput& in, std::span<double> dr_dT) const {
    FE_CHECK(dr_dT.size() == static_cast<std::size_t>(NDOF * NN) &&
                 in.temperature.size() == static_cast<std::size_t>(NN),
             "temperature_tangent: sizes");
    std::fill(dr_dT.begin(), dr_dT.end(), 0.0);
    Work w;
    compute(in, w, in.state, {.dstress_dT = true});
    for (int q = 0; q < NIP; ++q) {
      const Ip& p = w.ip[q];
      const VecD col = p.dV * (p.B.transpose() * p.dS);
      for (int i = 0; i < NDOF; ++i)
        for (int b = 0; b < NN; ++b) dr_dT[i * NN + b] += col(i) * _N[q](b);
    }
  }

  bool supports_load(DistLoadKind kind, int face) const override {
    if (kind == DistLoadKind::Pressure)
      return face >= 1 && face <= static_cast<int>(element_faces(Tr::shape).size());
    return (kind == DistLoadKind::Gravity || kind == DistLoadKind::BodyForce ||
            kind == DistLoadKind::Centrifugal) &&
           face == 0;
  }

  void load(const ElementInput& in, const DistributedLoad& ld, double magnitude, double,
            std::span<double> f_ext, std::span<double> tangent) const override {
    LoadGeometry g{kKin, Tr::shape, in.X, in.u, ND, _setup.thickness};
    continuum_distributed_load(g, in, ld, magnitude, _setup.material, f_ext, tangent);
  }

  bool supports_output(ElemVar var) const override {
    return continuum_detail::continuum_output(var);
  }

  void recover(const ElementInput& in, ElementRecovery& out) const override {
    Work w;
    std::vector<double> trial(static_cast<std::size_t>(n_state())); // history is not written here
    compute(in, w, trial, {.recovery = true});
    const bool nlgeom = in.ctx && in.ctx->nlgeom;
    OutputBlock sb, eb;
    continuum_detail::stress_strain_blocks<kKin>(NIP, sb, eb);
    continuum_detail::PointExtras extras(NIP, ND);
    double energy = 0.0;
    for (int q = 0; q < NIP; ++q) {
      const Ip& p = w.ip[q];
      energy += p.dV * p.law.energy;
      extras.add(
          in, q, p.law.energy,
          p.dV * continuum_detail::volume_ratio<kKin>(p.F, p.F33, p.law.thickness_strain, nlgeom),
          [&](int a) { return _N[q](a); }, NN, nlgeom);
      VecS sig = p.S;
      if (nlgeom)
        sig = continuum_detail::cauchy_stress<kKin>(p.S, p.F, p.F33, p.law.thickness_strain);
      for (int c = 0; c < NS; ++c) {
        sb.values[q * NS + c] = sig(c);
        eb.values[q * NS + c] = p.E(c);
      }
    }
    out.blocks.push_back(std::move(sb));
    out.blocks.push_back(std::move(eb));
    extras.append_to(out);
    out.strain_energy = energy;
  }

 private:
  /// Per integration point state of one evaluation.
  struct Ip {
    MatG g; ///< dN/dX
    double dV = 0.0;
    double R = 1.0; ///< reference radius (axisymmetric)
    MatF F;         ///< in-plane deformation gradient (identity for small strain)
    double F33 = 1.0;
    VecS E;  ///< (modified) strain, engineering shears
    MatB B;  ///< d E / d u (modified for B-bar)
    VecS S;  ///< stress conjugate to E (second Piola-Kirchhoff under NLGEOM)
    VecS dS; ///< dS/dT (temperature_tangent only)
    PointLaw<NS> law;
  };
  struct Work {
    std::array<Ip, NIP> ip;
    std::array<typename PointLaw<NS>::MatD, NIP> D; ///< the laws' tangents when not isotropic
    double p_bar = 0.0; ///< element mean of the mean normal stress (B-bar)
  };

  static constexpr auto comps() { return continuum_detail::voigt_pairs<kKin>(); }

  /// 3-D elements without B-bar form the material stiffness node pair by node pair when the law's
  /// tangent is isotropic (elasticity): with f_a = F grad N_a and the isotropic C, the block of
  /// nodes a, b is
  ///   dV [lambda f_a f_b^T + mu f_b f_a^T + mu (grad N_a . grad N_b) F F^T],
  /// the same as B^T D B (F = I for small strain) in about a third of the operations; only the
  /// pairs b >= a are formed, the rest mirrored after the loop over the points.
  static constexpr bool kNodePairs = kKin == Kinematics::ThreeD && !Tr::bbar;

  void add_material_pairs(const Ip& p, MatK& K) const {
    const Eigen::Matrix<double, NN, ND> f = p.g * p.F.transpose();
    const Eigen::Matrix<double, NN, NN> gg = p.g * p.g.transpose();
    const MatF FFt = p.F * p.F.transpose();
    const double l = p.dV * p.law.moduli.lambda, m = p.dV * p.law.moduli.mu;
    for (int a = 0; a < NN; ++a) {
      const Eigen::Matrix<double, ND, 1> fa = f.row(a).transpose();
      for (int b = a; b < NN; ++b) {
        const Eigen::Matrix<double, ND, 1> fb = f.row(b).transpose();
        K.template block<ND, ND>(a * ND, b * ND) +=
            l * fa * fb.transpose() + m * fb * fa.transpose() + (m * gg(a, b)) * FFt;
      }
    }
  }

  void reference_gradients(const ElementInput& in, int q, MatG& g, double& detJ) const {
    MatF J = MatF::Zero();
    for (int a = 0; a < NN; ++a)
      for (int k = 0; k < ND; ++k)
        for (int l = 0; l < ND; ++l) J(k, l) += in.X[a][k] * _dN[q](a, l);
    detJ = J.determinant();
    g.noalias() = _dN[q] * J.inverse();
  }

  double radius(const ElementInput& in, int q) const {
    double R = 0.0;
    for (int a = 0; a < NN; ++a) R += _N[q](a) * in.X[a][0];
    return R;
  }

  /// Kinematics, (B-bar) strains and, through the law, stresses at all points; the trial
  /// history goes to `trial`.
  void compute(const ElementInput& in, Work& w, std::span<double> trial,
               PointRequest request = {}) const {
    const bool nlgeom = in.ctx && in.ctx->nlgeom;
    MatG U;
    for (int a = 0; a < NN; ++a)
      for (int i = 0; i < ND; ++i) U(a, i) = in.u[a * ND + i];
    constexpr auto C = comps();
    double V = 0.0, theta_bar = 0.0;
    VecD b_bar = VecD::Zero();
    for (int q = 0; q < NIP; ++q) {
      Ip& p = w.ip[q];
      double detJ = 0.0;
      reference_gradients(in, q, p.g, detJ);
      p.dV = _w[q] * detJ;
      double hoop = 0.0; // u_r / R
      if constexpr (kAxi) {
        p.R = radius(in, q);
        p.dV *= 2.0 * std::numbers::pi * p.R;
        double ur = 0.0;
        for (int a = 0; a < NN; ++a) ur += _N[q](a) * U(a, 0);
        hoop = ur / p.R;
      } else if constexpr (ND == 2) {
        p.dV *= _setup.thickness;
      }
      const MatF H = U.transpose() * p.g; // H_iJ = du_i/dX_J
      p.F = MatF::Identity();
      p.F33 = 1.0;
      if (nlgeom) {
        p.F += H;
        if constexpr (kAxi) p.F33 = 1.0 + hoop;
        const double detF = p.F.determinant() * p.F33;
        if (!(detF > 0.0))
          throw ConvergenceFailure(fmt::format(
              "element {}: the deformation gradient has det F = {:.3g} <= 0 at integration point "
              "{} (element turned inside out); cutting back",
              in.label, detF, q + 1));
      }
      for (int c = 0; c < NS; ++c) {
        const int I = C[c][0], J = C[c][1];
        if (I == J && I >= ND) { // out-of-plane normal: hoop (CAX) or zero (CPE)
          p.B.row(c).setZero();
          p.E(c) = 0.0;
          if constexpr (kAxi) {
            p.E(c) = nlgeom ? hoop + 0.5 * hoop * hoop : hoop;
            for (int a = 0; a < NN; ++a) p.B(c, a * ND) = p.F33 * _N[q](a) / p.R;
          }
          continue;
        }
        if (I == J) {
          double e = H(I, I);
          if (nlgeom)
            for (int k = 0; k < ND; ++k) e += 0.5 * H(k, I) * H(k, I);
          p.E(c) = e;
          for (int a = 0; a < NN; ++a)
            for (int i = 0; i < ND; ++i) p.B(c, a * ND + i) = p.F(i, I) * p.g(a, I);
        } else {
          double e = H(I, J) + H(J, I);
          if (nlgeom)
            for (int k = 0; k < ND; ++k) e += H(k, I) * H(k, J);
          p.E(c) = e;
          for (int a = 0; a < NN; ++a)
            for (int i = 0; i < ND; ++i)
              p.B(c, a * ND + i) = p.F(i, I) * p.g(a, J) + p.F(i, J) * p.g(a, I);
        }
      }
      if constexpr (Tr::bbar) {
        V += p.dV;
        theta_bar += p.dV * (p.E(0) + p.E(1) + p.E(2));
        b_bar.noalias() += p.dV * (p.B.row(0) + p.B.row(1) + p.B.row(2)).transpose();
      }
    }
    if constexpr (Tr::bbar) {
      theta_bar /= V;
      b_bar /= V;
      double p_sum = 0.0;
      for (int q = 0; q < NIP; ++q) {
        Ip& p = w.ip[q];
        const double dtheta = (theta_bar - (p.E(0) + p.E(1) + p.E(2))) / 3.0;
        const auto db = ((b_bar.transpose() - (p.B.row(0) + p.B.row(1) + p.B.row(2))) / 3.0).eval();
        for (int c = 0; c < 3; ++c) {
          p.E(c) += dtheta;
          p.B.row(c) += db;
        }
        update(in, q, trial, request, p, w.D[q]);
        p_sum += p.dV * (p.S(0) + p.S(1) + p.S(2)) / 3.0;
      }
      w.p_bar = p_sum / V;
    } else {
      for (int q = 0; q < NIP; ++q) update(in, q, trial, request, w.ip[q], w.D[q]);
    }
  }

  /// The law at point q (shared point loop, solid_point.hpp).
  void update(const ElementInput& in, int q, std::span<double> trial, PointRequest request, Ip& p,
              typename PointLaw<NS>::MatD& D) const {
    p.law.D = &D;
    const PointTemperature t = point_temperature(in, _N[q], NN, _law.temperature_dependent());
    update_point<NS>(_law, in, q, trial, t, p.E, p.S, p.law, request, &p.dS);
  }

  /// Geometric stiffness sum_q dV S* : d2E/du2 with S* = S (B-bar: S - p + p_bar on the normals).
  void add_geometric(const Ip& p, const Work& w, int q, MatK& K) const {
    constexpr auto C = comps();
    Eigen::Matrix<double, ND, ND> Sm = Eigen::Matrix<double, ND, ND>::Zero();
    double S33 = 0.0;
    double shift = 0.0;
    if constexpr (Tr::bbar) shift = w.p_bar - (p.S(0) + p.S(1) + p.S(2)) / 3.0;
    for (int c = 0; c < NS; ++c) {
      const int I = C[c][0], J = C[c][1];
      if (I == J && I >= ND) {
        S33 = p.S(c) + shift;
        continue;
      }
      const double v = p.S(c) + (I == J && c < 3 ? shift : 0.0);
      Sm(I, J) = v;
      Sm(J, I) = v;
    }
    const Eigen::Matrix<double, NN, NN> G = p.dV * (p.g * Sm * p.g.transpose());
    for (int a = 0; a < NN; ++a)
      for (int b = 0; b < NN; ++b) {
        for (int i = 0; i < ND; ++i) K(a * ND + i, b * ND + i) += G(a, b);
        if constexpr (kAxi) K(a * ND, b * ND) += p.dV * S33 * _N[q](a) * _N[q](b) / (p.R * p.R);
      }
  }

  ContinuumSetup _setup;
  SolidLawHandle _law;
  std::array<double, NIP> _w{};
  std::array<Eigen::Matrix<double, NN, 1>, NIP> _N{};
  std::array<MatG, NIP> _dN{};
};

} // namespace gapfem
