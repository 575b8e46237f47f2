#pragma once
/// @file incompatible_kernel.hpp
/// The incompatible-mode elements C3D8I, CPS4I, CPE4I and CAX4I: first-order bricks and
/// quadrilaterals whose displacement gradient is enriched with the internal modes
/// M_k = 1 - xi_k^2 (one per parametric direction, each with ND components: 9 in 3-D, 4 in 2-D),
/// so that a regular mesh bends exactly (Abaqus Theory Guide, "Incompatible mode elements";
/// Wilson, Taylor; Simo and Rifai). Theory: docs/theory/continuum.md.
///
///   H = sum_a u_a (x) grad N_a + sum_k alpha_k (x) grad~M_k,
///   grad~M_k = (j0 / j) J0^-T dM_k/dxi      (J0, j0 at the centroid: the patch test passes;
///                                          CAX4I also scales by R0 / R, the radius ratio)
///
/// The modes are treated as extra "nodes" with gradients grad~M_k and no shape function (the hoop
/// strain of CAX4I comes from the nodes only). Small strain eps = sym H, NLGEOM
/// E = sym H + 1/2 H^T H with F = I + H, S = law(E) (the material's solid law through the shared
/// point loop, solid_point.hpp), 2 x 2 (x 2) Gauss points, no B-bar. The modes are condensed
/// inside the element: for the given nodal displacements the kernel solves r_alpha(u, alpha) = 0
/// by Newton from alpha = 0 (one step for small strain, a few under NLGEOM), so the modes need no
/// history (the law's history is the only one), and returns r_u at that alpha with the condensed
/// tangent K_uu - K_ua K_aa^-1 K_au, the exact derivative of r_u(u, alpha(u)).
#include "elements/element_kernel.hpp"
#include "elements/reference_scale.hpp"
#include "elements/solid/continuum_kernel.hpp"
#include "elements/solid/continuum_mass.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <memory>
#include <vector>

namespace gapfem {

template <ElementType Type, Shape Cell, Kinematics K>
class IncompatibleKernel final : public ElementKernel {
 public:
  static constexpr int NN = shape_n_nodes(Cell);
  static constexpr int ND = K == Kinematics::ThreeD ? 3 : 2;
  static constexpr int NM = ND;      ///< modes
  static constexpr int NT = NN + NM; ///< nodes and modes
  static constexpr int NS = continuum_detail::n_strain(K);
  static constexpr int NNRM = continuum_detail::n_normal(K);
  static constexpr int NIP = continuum_detail::n_points(Cell, false);
  static constexpr int NU = NN * ND, NA = NM * ND, NX = NT * ND;
  static constexpr bool kAxi = K == Kinematics::Axisymmetric;
  static_assert(Cell == Shape::Hex8 || Cell == Shape::Quad4, "incompatible modes: Hex8 and Quad4");

  using MatG = Eigen::Matrix<double, NT, ND>;
  using MatF = Eigen::Matrix<double, ND, ND>;
  using VecS = Eigen::Matrix<double, NS, 1>;
  using MatB = Eigen::Matrix<double, NS, NX>;
  using VecX = Eigen::Matrix<double, NX, 1>;
  using MatX = Eigen::Matrix<double, NX, NX>;

  explicit IncompatibleKernel(ContinuumSetup setup)
      : _setup(std::move(setup)), _law(_setup.material, K) {
    const auto rule = full_integration_rule(Cell);
    for (int q = 0; q < NIP; ++q) {
      _w[q] = rule[q].weight;
      double N[NN], dN[NN * ND];
      ShapeFunctions<Cell>::eval(rule[q].xi.data(), N, dN);
      for (int a = 0; a < NN; ++a) {
        _N[q](a) = N[a];
        for (int k = 0; k < ND; ++k) _dN[q](a, k) = dN[a * ND + k];
      }
      _dM[q].setZero();
      for (int k = 0; k < NM; ++k) _dM[q](k, k) = -2.0 * rule[q].xi[k]; // d(1 - xi_k^2)/dxi_k
    }
    double N0[NN], dN0[NN * ND];
    const double centre[3] = {0.0, 0.0, 0.0};
    ShapeFunctions<Cell>::eval(centre, N0, dN0);
    for (int a = 0; a < NN; ++a)
      for (int k = 0; k < ND; ++k) _dN0(a, k) = dN0[a * ND + k];
  }

  ElementType type() const override { return Type; }
  std::span<const DofType> node_dofs(int) const override {
    if constexpr (ND == 3)
      return continuum_detail::kDofs3;
    else
      return continuum_detail::kDofs2;
  }
  bool uses_temperature_field() const override { return _setup.needs_temperature; }
  int n_state() const override { return NIP * _law.n_state(); }
  /// The consistent mass of the nodes (the modes carry none; continuum_mass.hpp); zero without
  /// *DENSITY.
  bool has_mass() const override { return true; }
  bool has_damping() const override { return false; }
  void initialize(const ElementInput& in) const override { initialize_points(_law, NIP, in.state); }
  const SolidLaw& law() const { return *_law; }

  std::string validate(const ElementInput& given) const override {
    std::array<Vec3, NN> xs{}; // the element at an extent near 1: no det J overflows or underflows
    ElementInput in = given;
    in.X = scaled_nodes(given.X, xs);
    Geometry g;
    for (int q = 0; q < NIP; ++q)
      if (!geometry(in, q, g))
        return fmt::format("element is inverted or degenerate (Jacobian <= 0 at integration point "
                           "{}); check the node order",
                           q + 1);
      else if (kAxi && !(g.R > 0.0))
        return fmt::format("axisymmetric element has integration point {} at r <= 0; "
                           "axisymmetric models must lie in x >= 0",
                           q + 1);
    if (_setup.thickness <= 0.0) return "the *SOLID SECTION thickness must be positive";
    return {};
  }

  void evaluate(const ElementInput& in, ElementOutput& out) const override {
    if (out.want_mass && !out.mass.empty())
      add_continuum_mass<Cell, K>(in, _setup.material, _setup.thickness, out.mass);
    const bool nlgeom = in.ctx && in.ctx->nlgeom;
    VecX x, r;
    MatX Kx;
    condense(in, nlgeom, in.state, x, r, Kx);
    for (int i = 0; i < NU; ++i) out.residual[i] += r(i);
    if (!out.want_tangent || out.tangent.size() != static_cast<std::size_t>(NU * NU)) return;
    const Eigen::Matrix<double, NU, NU> Kc =
        Kx.template topLeftCorner<NU, NU>() -
        Kx.template topRightCorner<NU, NA>() * Kx.template bottomRightCorner<NA, NA>().ldlt().solve(
                                                   Kx.template bottomLeftCorner<NA, NU>());
    for (int i = 0; i < NU; ++i)
      for (int j = 0; j < NU; ++j) out.tangent[i * NU + j] += Kc(i, j);
  }

  bool supports_load(DistLoadKind kind, int face) const override {
    if (kind == DistLoadKind::Pressure)
      return face >= 1 && face <= static_cast<int>(element_faces(Cell).size());
    return (kind == DistLoadKind::Gravity || kind == DistLoadKind::BodyForce ||
            kind == DistLoadKind::Centrifugal) &&
           face == 0;
  }
  void load(const ElementInput& in, const DistributedLoad& ld, double magnitude, double,
            std::span<double> f_ext, std::span<double> tangent) const override {
    LoadGeometry g{K, Cell, in.X, in.u, ND, _setup.thickness};
    continuum_distributed_load(g, in, ld, magnitude, _setup.material, f_ext, tangent);
  }

  bool supports_output(ElemVar var) const override {
    return continuum_detail::continuum_output(var);
  }
  void recover(const ElementInput& in, ElementRecovery& out) const override {
    const bool nlgeom = in.ctx && in.ctx->nlgeom;
    VecX x, r;
    MatX Kx;
    std::vector<double> trial(static_cast<std::size_t>(n_state())); // history is not written here
    condense(in, nlgeom, trial, x, r, Kx);
    OutputBlock sb, eb;
    continuum_detail::stress_strain_blocks<K>(NIP, sb, eb);
    continuum_detail::PointExtras extras(NIP, ND);
    double energy = 0.0;
    for (int q = 0; q < NIP; ++q) {
      Point p;
      point(in, q, nlgeom, x, trial, p, {.recovery = true});
      energy += p.g.dV * p.law.energy;
      extras.add(
          in, q, p.law.energy,
          p.g.dV * continuum_detail::volume_ratio<K>(p.F, p.F33, p.law.thickness_strain, nlgeom),
          [&](int a) { return _N[q](a); }, NN, nlgeom);
      const VecS sig =
          nlgeom ? continuum_detail::cauchy_stress<K>(p.S, p.F, p.F33, p.law.thickness_strain)
                 : p.S;
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
  struct Geometry {
    MatG G;          ///< gradients of the nodes (rows 0..NN-1) and of the modes
    double dV = 0.0; ///< volume weight (thickness, 2 pi R included)
    double R = 1.0;
  };
  struct Point {
    Geometry g;
    MatF F = MatF::Identity();
    double F33 = 1.0;
    VecS E, S;
    MatB B;
    PointLaw<NS> law;
    typename PointLaw<NS>::MatD D; ///< the law's tangent when not isotropic
  };

  static constexpr auto comps() { return continuum_detail::voigt_pairs<K>(); }

  /// Gradients of nodes and modes at point q; false for a non-positive Jacobian.
  bool geometry(const ElementInput& in, int q, Geometry& g) const {
    MatF J = MatF::Zero(), J0 = MatF::Zero();
    for (int a = 0; a < NN; ++a)
      for (int k = 0; k < ND; ++k)
        for (int l = 0; l < ND; ++l) {
          J(k, l) += in.X[a][k] * _dN[q](a, l);
          J0(k, l) += in.X[a][k] * _dN0(a, l);
        }
    const double j = J.determinant(), j0 = J0.determinant();
    if (!(j > 0.0) || !(j0 > 0.0)) return false;
    g.G.template topRows<NN>() = _dN[q] * J.inverse();
    double scale = j0 / j;
    g.dV = _w[q] * j;
    if constexpr (kAxi) {
      g.R = 0.0;
      double R0 = 0.0;
      for (int a = 0; a < NN; ++a) {
        g.R += _N[q](a) * in.X[a][0];
        R0 += in.X[a][0] / NN;
      }
      g.dV *= 2.0 * std::numbers::pi * g.R;
      scale *= R0 / g.R; // the volume weight includes r: keep integral grad~M dV = 0
    }
    g.G.template bottomRows<NM>() = scale * (_dM[q] * J0.inverse());
    if constexpr (!kAxi && ND == 2) {
      g.dV *= _setup.thickness;
    }
    return true;
  }

  /// Strain, its derivative with respect to x = (u, alpha) and the stress at point q (the trial
  /// history to `trial`).
  void point(const ElementInput& in, int q, bool nlgeom, const VecX& x, std::span<double> trial,
             Point& p, PointRequest request = {}) const {
    if (!geometry(in, q, p.g))
      throw ConvergenceFailure(fmt::format("element {}: degenerate geometry", in.label));
    Eigen::Matrix<double, NT, ND> U;
    for (int a = 0; a < NT; ++a)
      for (int i = 0; i < ND; ++i) U(a, i) = x(a * ND + i);
    const MatF H = U.transpose() * p.g.G;
    double hoop = 0.0;
    if constexpr (kAxi) {
      for (int a = 0; a < NN; ++a) hoop += _N[q](a) * U(a, 0);
      hoop /= p.g.R;
    }
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
    constexpr auto C = comps();
    for (int c = 0; c < NS; ++c) {
      const int I = C[c][0], J = C[c][1];
      p.B.row(c).setZero();
      if (I == J && I >= ND) { // out-of-plane normal: hoop (CAX) or zero (CPE)
        p.E(c) = 0.0;
        if constexpr (kAxi) {
          p.E(c) = nlgeom ? hoop + 0.5 * hoop * hoop : hoop;
          for (int a = 0; a < NN; ++a) p.B(c, a * ND) = p.F33 * _N[q](a) / p.g.R;
        }
        continue;
      }
      double e = I == J ? H(I, I) : H(I, J) + H(J, I);
      if (nlgeom)
        for (int k = 0; k < ND; ++k) e += (I == J ? 0.5 : 1.0) * H(k, I) * H(k, J);
      p.E(c) = e;
      for (int a = 0; a < NT; ++a)
        for (int i = 0; i < ND; ++i)
          p.B(c, a * ND + i) =
              I == J ? p.F(i, I) * p.g.G(a, I) : p.F(i, I) * p.g.G(a, J) + p.F(i, J) * p.g.G(a, I);
    }
    const PointTemperature t = point_temperature(in, _N[q], NN, _law.temperature_dependent());
    p.law.D = &p.D;
    update_point<NS>(_law, in, q, trial, t, p.E, p.S, p.law, request);
  }

  /// Residual and tangent in x = (u, alpha).
  void assemble(const ElementInput& in, bool nlgeom, std::span<double> trial, const VecX& x,
                VecX& r, MatX& Kx) const {
    r.setZero();
    Kx.setZero();
    constexpr auto C = comps();
    for (int q = 0; q < NIP; ++q) {
      Point p;
      point(in, q, nlgeom, x, trial, p);
      add_point<NS>(p.law, p.B, p.S, p.g.dV, r, &Kx);
      if (!nlgeom) continue;
      MatF Sm = MatF::Zero();
      double S33 = 0.0;
      for (int c = 0; c < NS; ++c) {
        const int I = C[c][0], J = C[c][1];
        if (I == J && I >= ND) {
          S33 = p.S(c);
          continue;
        }
        Sm(I, J) = Sm(J, I) = p.S(c);
      }
      const Eigen::Matrix<double, NT, NT> Gm = p.g.dV * (p.g.G * Sm * p.g.G.transpose());
      for (int a = 0; a < NT; ++a)
        for (int b = 0; b < NT; ++b) {
          for (int i = 0; i < ND; ++i) Kx(a * ND + i, b * ND + i) += Gm(a, b);
          if constexpr (kAxi)
            if (a < NN && b < NN)
              Kx(a * ND, b * ND) += p.g.dV * S33 * _N[q](a) * _N[q](b) / (p.g.R * p.g.R);
        }
    }
  }

  /// x = (u, alpha) with alpha solving r_alpha = 0 at the element's nodal displacements u, and
  /// the residual and tangent there.
  void condense(const ElementInput& in, bool nlgeom, std::span<double> trial, VecX& x, VecX& r,
                MatX& Kx) const {
    x.setZero();
    for (int i = 0; i < NU; ++i) x(i) = in.u[i];
    double size = 0.0;
    for (int a = 1; a < NN; ++a)
      for (int i = 0; i < 3; ++i) size = std::max(size, std::abs(in.X[a][i] - in.X[0][i]));
    double r0 = -1.0;
    for (int it = 0; it < 30; ++it) {
      assemble(in, nlgeom, trial, x, r, Kx);
      const double ra = r.template tail<NA>().template lpNorm<Eigen::Infinity>();
      const double ru = r.template head<NU>().template lpNorm<Eigen::Infinity>();
      if (r0 < 0.0) r0 = ra;
      if (ra <= 1e-12 * std::max(ru, r0) || ra == 0.0) return;
      const Eigen::Matrix<double, NA, 1> da =
          -Kx.template bottomRightCorner<NA, NA>().ldlt().solve(r.template tail<NA>());
      x.template tail<NA>() += da;
      if (!nlgeom) { // linear in alpha: one step is exact
        assemble(in, nlgeom, trial, x, r, Kx);
        return;
      }
      if (da.template lpNorm<Eigen::Infinity>() <= 1e-14 * size) {
        assemble(in, nlgeom, trial, x, r, Kx);
        return;
      }
    }
    throw ConvergenceFailure(fmt::format(
        "element {}: the incompatible modes do not converge (local Newton); cutting back",
        in.label));
  }

  ContinuumSetup _setup;
  SolidLawHandle _law;
  std::array<double, NIP> _w{};
  std::array<Eigen::Matrix<double, NN, 1>, NIP> _N{};
  std::array<Eigen::Matrix<double, NN, ND>, NIP> _dN{};
  std::array<Eigen::Matrix<double, NM, ND>, NIP> _dM{};
  Eigen::Matrix<double, NN, ND> _dN0;
};

} // namespace gapfem
