#pragma once
/// @file reduced_kernel.hpp
/// The first-order reduced-integration elements C3D8R, CPS4R, CPE4R and CAX4R (and the mechanics
/// of C3D8RT, CPS4RT, CPE4RT, CAX4RT): Abaqus's uniform strain formulation (one stress point, the
/// strain being the element mean; Flanagan and Belytschko) with hourglass control
/// (hourglass.hpp). Theory: docs/theory/continuum.md, "Reduced integration and hourglass control".
///
///   W(u) = V psi(E(Hbar, hbar)) + 1/2 u^T K_hg u
///   Hbar = sum_a u_a (x) b_a,   hbar (CAX hoop) = sum_a c_a u_ar
///   small strain E = sym Hbar; NLGEOM E = 1/2 (Fbar^T Fbar - I), Fbar = I + Hbar (total
///   Lagrangian); S = law(E) at the element's mean temperature (the material's solid law through
///   the shared point loop, solid_point.hpp; one point, one slot of history)
///   residual r = V Bbar^T S + K_hg u,  tangent V (Bbar^T D Bbar + geometric) + K_hg
/// The hourglass forces are linear in u on the reference configuration (with the law's elastic
/// moduli at the current mean temperature); they vanish for every rigid motion, large
/// rotations included, because K_hg is zero on every linear displacement field (3-D, plane).
/// recover() reports S and E at the single point and the element's artificial (hourglass) energy
/// 1/2 u^T K_hg u, summed into ALLAE.
#include "elements/element_kernel.hpp"
#include "elements/reference_scale.hpp"
#include "elements/solid/continuum_kernel.hpp"
#include "elements/solid/continuum_mass.hpp"
#include "elements/solid/hourglass.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <memory>
#include <vector>

namespace gapfem {

template <ElementType Type, Kinematics K>
class ReducedKernel final : public ElementKernel {
 public:
  using Geo = HourglassGeometry<K>;
  static constexpr Kinematics kKin = K;
  static constexpr Shape kShape = Geo::kShape;
  static constexpr int ND = Geo::ND, NN = Geo::NN, NS = Geo::NS, NNRM = Geo::NNRM;
  static constexpr int NDOF = Geo::NDOF;
  static constexpr bool kAxi = K == Kinematics::Axisymmetric;

  using VecS = Eigen::Matrix<double, NS, 1>;
  using MatB = Eigen::Matrix<double, NS, NDOF>;
  using VecD = Eigen::Matrix<double, NDOF, 1>;
  using MatK = Eigen::Matrix<double, NDOF, NDOF, Eigen::RowMajor>;
  using MatF = Eigen::Matrix<double, ND, ND>;

  explicit ReducedKernel(ContinuumSetup setup)
      : _setup(std::move(setup)), _law(_setup.material, K) {}

  ElementType type() const override { return Type; }
  std::span<const DofType> node_dofs(int) const override {
    if constexpr (ND == 3)
      return continuum_detail::kDofs3;
    else
      return continuum_detail::kDofs2;
  }
  bool uses_temperature_field() const override { return _setup.needs_temperature; }
  bool has_artificial_energy() const override { return true; }
  int n_state() const override { return _law.n_state(); }
  /// The consistent mass with the full 2x2(x2) rule (continuum_mass.hpp); zero without *DENSITY.
  bool has_mass() const override { return true; }
  bool has_damping() const override { return false; }
  void initialize(const ElementInput& in) const override { initialize_points(_law, 1, in.state); }
  const SolidLaw& law() const { return *_law; }

  std::string validate(const ElementInput& given) const override {
    std::array<Vec3, NN> xs{}; // the element at an extent near 1: no det J overflows or underflows
    ElementInput in = given;
    in.X = scaled_nodes(given.X, xs);
    Geo g;
    int bad = 0;
    if (!g.build(in.X, _setup.thickness, bad)) {
      if (kAxi && radius_at_fault(in, bad))
        return fmt::format("axisymmetric element has integration point {} at r <= 0; "
                           "axisymmetric models must lie in x >= 0",
                           bad);
      return fmt::format("element is inverted or degenerate (Jacobian <= 0 at integration point "
                         "{}); check the node order",
                         bad);
    }
    if (_setup.thickness <= 0.0) return "the *SOLID SECTION thickness must be positive";
    return {};
  }

  void evaluate(const ElementInput& in, ElementOutput& out) const override {
    if (out.want_mass && !out.mass.empty())
      add_continuum_mass<kShape, K>(in, _setup.material, _setup.thickness, out.mass);
    Work w;
    compute(in, w, in.state);
    Eigen::Map<VecD> r(out.residual.data());
    const bool want_K =
        out.want_tangent && out.tangent.size() == static_cast<std::size_t>(NDOF * NDOF);
    MatK Km;
    if (want_K) Km.setZero();
    add_point<NS>(w.law, w.B, w.S, w.g.V, r, want_K ? &Km : nullptr);
    r.noalias() += w.Khg * Eigen::Map<const VecD>(in.u.data());
    if (!want_K) return;
    Eigen::Map<MatK> Kout(out.tangent.data());
    Km += w.Khg;
    if (in.ctx && in.ctx->nlgeom) add_geometric(w, Km);
    Kout += Km;
  }

  /// Coupled twins: d r / d T_b (NDOF x NN, row-major, overwritten), through the mean temperature
  /// (thermal strain, temperature-dependent elasticity and hourglass stiffness).
  void temperature_tangent(const ElementInput& in, std::span<double> dr_dT) const {
    FE_CHECK(dr_dT.size() == static_cast<std::size_t>(NDOF * NN) &&
                 in.temperature.size() == static_cast<std::size_t>(NN),
             "temperature_tangent: sizes");
    Work w;
    compute(in, w, in.state, {.dstress_dT = true});
    VecD col = w.g.V * (w.B.transpose() * w.dS);
    IsotropicModuli dm;
    _law->elastic_moduli(w.T, &dm);
    if (dm.lambda != 0.0 || dm.mu != 0.0) {
      typename Geo::MatK Khg, dK;
      w.g.stiffness(_setup.hourglass, _setup.hourglass_scale, w.moduli.lambda, w.moduli.mu, Khg,
                    dm.lambda, dm.mu, &dK);
      col.noalias() += dK * Eigen::Map<const VecD>(in.u.data());
    }
    for (int i = 0; i < NDOF; ++i)
      for (int b = 0; b < NN; ++b) dr_dT[i * NN + b] = col(i) * w.g.nbar(b);
  }

  bool supports_load(DistLoadKind kind, int face) const override {
    if (kind == DistLoadKind::Pressure)
      return face >= 1 && face <= static_cast<int>(element_faces(kShape).size());
    return (kind == DistLoadKind::Gravity || kind == DistLoadKind::BodyForce ||
            kind == DistLoadKind::Centrifugal) &&
           face == 0;
  }
  void load(const ElementInput& in, const DistributedLoad& ld, double magnitude, double,
            std::span<double> f_ext, std::span<double> tangent) const override {
    LoadGeometry g{K, kShape, in.X, in.u, ND, _setup.thickness};
    continuum_distributed_load(g, in, ld, magnitude, _setup.material, f_ext, tangent);
  }

  bool supports_output(ElemVar var) const override {
    return continuum_detail::continuum_output(var);
  }
  void recover(const ElementInput& in, ElementRecovery& out) const override {
    Work w;
    std::vector<double> trial(static_cast<std::size_t>(n_state())); // history is not written here
    compute(in, w, trial, {.recovery = true});
    OutputBlock sb, eb;
    continuum_detail::stress_strain_blocks<K>(1, sb, eb);
    const VecS sig =
        in.ctx && in.ctx->nlgeom
            ? continuum_detail::cauchy_stress<K>(w.S, w.F, w.F33, w.law.thickness_strain)
            : w.S;
    for (int c = 0; c < NS; ++c) {
      sb.values[c] = sig(c);
      eb.values[c] = w.E(c);
    }
    out.blocks.push_back(std::move(sb));
    out.blocks.push_back(std::move(eb));
    // the single point at the cell's centre, where every node's weight is 1 / NN
    const bool nlgeom = in.ctx && in.ctx->nlgeom;
    continuum_detail::PointExtras extras(1, ND);
    extras.add(
        in, 0, w.law.energy,
        w.g.V * continuum_detail::volume_ratio<K>(w.F, w.F33, w.law.thickness_strain, nlgeom),
        [](int) { return 1.0 / NN; }, NN, nlgeom);
    extras.append_to(out);
    const Eigen::Map<const VecD> u(in.u.data());
    out.artificial_energy = 0.5 * u.dot(w.Khg * u);
    out.strain_energy = w.g.V * w.law.energy;
  }

 private:
  struct Work {
    Geo g;
    MatF F = MatF::Identity();
    double F33 = 1.0;
    VecS E, S;
    VecS dS; ///< dS/dT (temperature_tangent only)
    MatB B;
    PointLaw<NS> law;
    typename PointLaw<NS>::MatD D; ///< the law's tangent when not isotropic
    double T = 0.0;                ///< the element's mean temperature
    IsotropicModuli moduli;        ///< the law's elastic moduli at T (hourglass stiffness)
    typename Geo::MatK Khg;
  };

  bool radius_at_fault(const ElementInput& in, int point) const {
    const auto rule = full_integration_rule(kShape);
    double N[NN], dN[NN * ND];
    ShapeFunctions<kShape>::eval(rule[point - 1].xi.data(), N, dN);
    double R = 0.0;
    for (int a = 0; a < NN; ++a) R += N[a] * in.X[a][0];
    return !(R > 0.0);
  }

  /// The uniform strain, the law's stress at the mean temperature (trial history to `trial`) and
  /// the hourglass stiffness.
  void compute(const ElementInput& in, Work& w, std::span<double> trial,
               PointRequest request = {}) const {
    int bad = 0;
    if (!w.g.build(in.X, _setup.thickness, bad))
      throw ConvergenceFailure(fmt::format("element {}: degenerate geometry", in.label));
    const bool nlgeom = in.ctx && in.ctx->nlgeom;
    Eigen::Matrix<double, NN, ND> U;
    for (int a = 0; a < NN; ++a)
      for (int i = 0; i < ND; ++i) U(a, i) = in.u[a * ND + i];
    const MatF H = U.transpose() * w.g.b;
    double hoop = 0.0;
    if constexpr (kAxi) hoop = w.g.c.dot(U.col(0));
    w.F = MatF::Identity();
    w.F33 = 1.0;
    if (nlgeom) {
      w.F += H;
      if constexpr (kAxi) w.F33 = 1.0 + hoop;
      const double detF = w.F.determinant() * w.F33;
      if (!(detF > 0.0))
        throw ConvergenceFailure(fmt::format(
            "element {}: the deformation gradient has det F = {:.3g} <= 0 (element turned "
            "inside out); cutting back",
            in.label, detF));
    }
    constexpr auto C = continuum_detail::voigt_pairs<K>();
    for (int c = 0; c < NS; ++c) {
      const int I = C[c][0], J = C[c][1];
      w.B.row(c).setZero();
      if (I == J && I >= ND) { // out-of-plane normal: hoop (CAX) or zero (CPE)
        w.E(c) = 0.0;
        if constexpr (kAxi) {
          w.E(c) = nlgeom ? hoop + 0.5 * hoop * hoop : hoop;
          for (int a = 0; a < NN; ++a) w.B(c, a * ND) = w.F33 * w.g.c(a);
        }
        continue;
      }
      double e = I == J ? H(I, I) : H(I, J) + H(J, I);
      if (nlgeom)
        for (int k = 0; k < ND; ++k) e += (I == J ? 0.5 : 1.0) * H(k, I) * H(k, J);
      w.E(c) = e;
      for (int a = 0; a < NN; ++a)
        for (int i = 0; i < ND; ++i)
          w.B(c, a * ND + i) =
              I == J ? w.F(i, I) * w.g.b(a, I) : w.F(i, I) * w.g.b(a, J) + w.F(i, J) * w.g.b(a, I);
    }
    const PointTemperature t = point_temperature(in, w.g.nbar, NN, true);
    w.law.D = &w.D;
    update_point<NS>(_law, in, 0, trial, t, w.E, w.S, w.law, request, &w.dS);
    w.T = t.T;
    w.moduli = _law->elastic_moduli(t.T);
    w.g.stiffness(_setup.hourglass, _setup.hourglass_scale, w.moduli.lambda, w.moduli.mu, w.Khg);
  }

  /// V S : d2E/du2 of the uniform strain.
  void add_geometric(const Work& w, MatK& K_) const {
    constexpr auto C = continuum_detail::voigt_pairs<K>();
    MatF Sm = MatF::Zero();
    double S33 = 0.0;
    for (int c = 0; c < NS; ++c) {
      const int I = C[c][0], J = C[c][1];
      if (I == J && I >= ND) {
        S33 = w.S(c);
        continue;
      }
      Sm(I, J) = Sm(J, I) = w.S(c);
    }
    const Eigen::Matrix<double, NN, NN> G = w.g.V * (w.g.b * Sm * w.g.b.transpose());
    for (int a = 0; a < NN; ++a)
      for (int b = 0; b < NN; ++b) {
        for (int i = 0; i < ND; ++i) K_(a * ND + i, b * ND + i) += G(a, b);
        if constexpr (kAxi) K_(a * ND, b * ND) += w.g.V * S33 * w.g.c(a) * w.g.c(b);
      }
  }

  ContinuumSetup _setup;
  SolidLawHandle _law;
};

} // namespace gapfem
