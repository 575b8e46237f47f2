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
///   Lagrangian); S = C : (E - eps_th I) at the element's mean temperature
///   residual r = V Bbar^T S + K_hg u,  tangent V (Bbar^T D Bbar + geometric) + K_hg
/// The hourglass forces are linear in u on the reference configuration (with the elastic
/// constants at the current mean temperature); they vanish for every rigid motion, large
/// rotations included, because K_hg is zero on every linear displacement field (3-D, plane).
/// recover() reports S and E at the single point and the element's artificial (hourglass) energy
/// 1/2 u^T K_hg u, summed into ALLAE.
#include "elements/element_kernel.hpp"
#include "elements/reference_scale.hpp"
#include "elements/solid/continuum_kernel.hpp"
#include "elements/solid/hourglass.hpp"

#include <Eigen/Dense>
#include <cmath>

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

  explicit ReducedKernel(ContinuumSetup setup) : _setup(std::move(setup)) {}

  ElementType type() const override { return Type; }
  std::span<const DofType> node_dofs(int) const override {
    if constexpr (ND == 3)
      return continuum_detail::kDofs3;
    else
      return continuum_detail::kDofs2;
  }
  bool uses_temperature_field() const override { return _setup.needs_temperature; }
  bool has_artificial_energy() const override { return true; }

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
    Work w;
    compute(in, w);
    Eigen::Map<VecD> r(out.residual.data());
    r.noalias() += w.g.V * (w.B.transpose() * w.S);
    r.noalias() += w.Khg * Eigen::Map<const VecD>(in.u.data());
    if (!out.want_tangent || out.tangent.size() != static_cast<std::size_t>(NDOF * NDOF)) return;
    Eigen::Map<MatK> Kout(out.tangent.data());
    MatB DB;
    w.law.apply(NNRM, w.B, DB);
    MatK Km = w.g.V * w.B.transpose().lazyProduct(DB);
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
    compute(in, w);
    const double T =
        w.g.nbar.dot(Eigen::Map<const Eigen::Matrix<double, NN, 1>>(in.temperature.data()));
    const double deth = _setup.material.thermal_strain_derivative(T);
    double dlambda = 0.0, dmu = 0.0;
    if (!const_elastic())
      continuum_detail::elastic_derivatives(K, _setup.material, T, dlambda, dmu);
    const ElasticPoint& law = w.law;
    double tr = 0.0;
    for (int c = 0; c < NNRM; ++c) tr += w.E(c) - law.eps_th;
    VecS dS;
    for (int c = 0; c < NNRM; ++c)
      dS(c) = dlambda * tr + 2.0 * dmu * (w.E(c) - law.eps_th) -
              deth * (law.lambda * NNRM + 2.0 * law.mu);
    for (int c = NNRM; c < NS; ++c) dS(c) = dmu * w.E(c);
    VecD col = w.g.V * (w.B.transpose() * dS);
    if (dlambda != 0.0 || dmu != 0.0) {
      typename Geo::MatK Khg, dK;
      w.g.stiffness(_setup.hourglass, _setup.hourglass_scale, law.lambda, law.mu, Khg, dlambda, dmu,
                    &dK);
      col.noalias() += dK * Eigen::Map<const VecD>(in.u.data());
    }
    for (int i = 0; i < NDOF; ++i)
      for (int b = 0; b < NN; ++b) dr_dT[i * NN + b] = col(i) * w.g.nbar(b);
  }

  bool supports_load(DistLoadKind kind, int face) const override {
    if (kind == DistLoadKind::Pressure)
      return face >= 1 && face <= static_cast<int>(element_faces(kShape).size());
    return (kind == DistLoadKind::Gravity || kind == DistLoadKind::BodyForce) && face == 0;
  }
  void load(const ElementInput& in, const DistributedLoad& ld, double magnitude, double,
            std::span<double> f_ext, std::span<double> tangent) const override {
    LoadGeometry g{K, kShape, in.X, in.u, ND, _setup.thickness};
    continuum_distributed_load(g, in, ld, magnitude, _setup.material, f_ext, tangent);
  }

  bool supports_output(ElemVar var) const override {
    return var == ElemVar::S || var == ElemVar::E;
  }
  void recover(const ElementInput& in, ElementRecovery& out) const override {
    Work w;
    compute(in, w);
    OutputBlock sb, eb;
    continuum_detail::stress_strain_blocks<K>(1, sb, eb);
    const VecS sig = in.ctx && in.ctx->nlgeom
                         ? continuum_detail::cauchy_stress<K>(w.S, w.E, w.F, w.F33, w.law)
                         : w.S;
    for (int c = 0; c < NS; ++c) {
      sb.values[c] = sig(c);
      eb.values[c] = w.E(c);
    }
    out.blocks.push_back(std::move(sb));
    out.blocks.push_back(std::move(eb));
    const Eigen::Map<const VecD> u(in.u.data());
    out.artificial_energy = 0.5 * u.dot(w.Khg * u);
    out.strain_energy = w.g.V * continuum_detail::energy_density(NNRM, w.S, w.E, w.law.eps_th);
  }

 private:
  struct Work {
    Geo g;
    MatF F = MatF::Identity();
    double F33 = 1.0;
    VecS E, S;
    MatB B;
    ElasticPoint law;
    typename Geo::MatK Khg;
  };

  bool const_elastic() const {
    return _setup.material.elastic.n_rows() <= 1 || _setup.material.elastic.keys.size() <= 1;
  }

  bool radius_at_fault(const ElementInput& in, int point) const {
    const auto rule = full_integration_rule(kShape);
    double N[NN], dN[NN * ND];
    ShapeFunctions<kShape>::eval(rule[point - 1].xi.data(), N, dN);
    double R = 0.0;
    for (int a = 0; a < NN; ++a) R += N[a] * in.X[a][0];
    return !(R > 0.0);
  }

  /// The law at the element's mean temperature.
  ElasticPoint mean_law(const ElementInput& in, const Geo& g) const {
    const bool thermal = !in.temperature.empty();
    double T = 0.0, Ti = 0.0;
    for (int a = 0; a < NN; ++a) {
      if (thermal) T += g.nbar(a) * in.temperature[a];
      if (!in.initial_temperature.empty()) Ti += g.nbar(a) * in.initial_temperature[a];
    }
    if (!thermal) T = Ti;
    double E = 0.0, nu = 0.0;
    _setup.material.elastic_at(T, E, nu);
    return ElasticPoint::make(K, E, nu, thermal ? _setup.material.thermal_strain(T, Ti) : 0.0);
  }

  void compute(const ElementInput& in, Work& w) const {
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
    w.law = mean_law(in, w.g);
    w.law.stress(NNRM, w.E, w.S);
    w.g.stiffness(_setup.hourglass, _setup.hourglass_scale, w.law.lambda, w.law.mu, w.Khg);
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
};

} // namespace gapfem
