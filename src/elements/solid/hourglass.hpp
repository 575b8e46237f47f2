#pragma once
/// @file hourglass.hpp
/// The reference geometry of the first-order reduced-integration elements (reduced_kernel.hpp):
/// the element means of the shape-function gradients (uniform strain) and the hourglass
/// stiffness K_hg. Theory: docs/theory/continuum.md, "Reduced integration and hourglass control".
///
///   b_a    = (1/V) int grad N_a dV             (2x2(x2) Gauss: exact for the multilinear map)
///   c_a    = (1/V) int N_a / R dV              (CAX4R: the mean hoop strain is sum_a c_a u_ar)
///   nbar_a = (1/V) int N_a dV                  (the element's mean temperature)
///
/// K_hg, symmetric, positive semi-definite and zero on every field of constant strain (so the
/// patch test and rigid motions are untouched):
///   ENHANCED  K_I - K_1: the small-strain stiffness of the incompatible-mode element of the same
///             shape (incompatible_kernel.hpp: modes 1 - xi_k^2, gradients scaled by j0/j and,
///             CAX, R0/R; condensed, K_uu - K_um K_mm^-1 K_mu) less that of the uniform strain,
///             V Bbar^T D Bbar. Because the modes have zero mean, the element's strain energy
///             splits into the energy of the mean strain and that of the strain's variation over
///             the element; K_hg is the second, which one point cannot see. For linear
///             elasticity and small strain the element is therefore the incompatible-mode
///             element, on any mesh.
///   STIFFNESS r_F G V (b:b) P^T P with r_F = 0.005: P u is what is left of the nodal
///             displacements after removing their constant-strain part (per component, the
///             coordinates in the basis {constant-strain fields, hourglass fields}: 1, x_j and
///             the hourglass vectors h_alpha = xi eta, eta zeta, zeta xi, xi eta zeta (2-D: xi
///             eta); CAX4R: u_r = r is the only constant-strain field of u_r, and u_r = 1, z, h
///             are penalised).
/// Both are multiplied by the *SECTION CONTROLS displacement hourglass scaling factor and use the
/// elastic moduli of the element's solid law at its mean temperature (SolidLaw::elastic_moduli).
#include "elements/solid/continuum_kernel.hpp"

#include <Eigen/Dense>
#include <array>
#include <numbers>

namespace gapfem {

template <Kinematics K>
struct HourglassGeometry {
  static constexpr int ND = K == Kinematics::ThreeD ? 3 : 2;
  static constexpr Shape kShape = ND == 3 ? Shape::Hex8 : Shape::Quad4;
  static constexpr int NN = shape_n_nodes(kShape);
  static constexpr int NQ = ND == 3 ? 8 : 4; ///< Gauss points of the full rule
  static constexpr int NMA = ND * ND;        ///< incompatible-mode unknowns (ND modes x ND)
  static constexpr int NS = continuum_detail::n_strain(K);
  static constexpr int NNRM = continuum_detail::n_normal(K);
  static constexpr int NDOF = NN * ND;
  static constexpr bool kAxi = K == Kinematics::Axisymmetric;
  static constexpr double kStiffnessFactor = 0.005; ///< r_F of HOURGLASS=STIFFNESS
  /// penalised (non-constant-strain) fields: 4 per component in 3-D, 1 plane; CAX u_r 3, u_z 1
  static constexpr int NSF = kAxi ? 4 : ND * (NN - ND - 1);

  using MatG = Eigen::Matrix<double, NN, ND>;
  using VecN = Eigen::Matrix<double, NN, 1>;
  using MatK = Eigen::Matrix<double, NDOF, NDOF>;
  using MatB = Eigen::Matrix<double, NS, NDOF>;
  using MatSF = Eigen::Matrix<double, NSF, NSF>;
  using MatS = Eigen::Matrix<double, NDOF, NSF>;
  using MatGam = Eigen::Matrix<double, NSF, NDOF>;

  /// Parametric node coordinates of the cell (Abaqus order).
  static constexpr double node_xi(int a, int k) {
    constexpr double hex[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                  {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    constexpr double quad[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    if constexpr (ND == 3)
      return hex[a][k];
    else
      return quad[a][k];
  }
  /// Hourglass base vector alpha at node a.
  static constexpr double h(int alpha, int a) {
    if constexpr (ND == 2) {
      return node_xi(a, 0) * node_xi(a, 1);
    } else {
      const double x = node_xi(a, 0), y = node_xi(a, 1), z = node_xi(a, 2);
      return alpha == 0 ? x * y : alpha == 1 ? y * z : alpha == 2 ? z * x : x * y * z;
    }
  }

  double V = 0.0;
  MatG b;       ///< mean gradients
  VecN c, nbar; ///< mean N/R (CAX), mean N
  double bb = 0.0;

  /// From the reference coordinates; false (with the failing point in `bad_point`) for a
  /// non-positive Jacobian or, axisymmetric, a point at r <= 0.
  bool build(std::span<const Vec3> X, double thickness, int& bad_point) {
    _X = X;
    _thickness = thickness;
    const auto rule = full_integration_rule(kShape);
    V = 0.0;
    b.setZero();
    c.setZero();
    nbar.setZero();
    for (int q = 0; q < NQ; ++q) {
      Point p;
      if (!point(q, rule[q].xi.data(), p)) {
        bad_point = q + 1;
        return false;
      }
      V += p.dV;
      b += p.dV * p.g;
      nbar += p.dV * p.N;
      if constexpr (kAxi) c += p.dV * p.N / p.R;
    }
    b /= V;
    c /= V;
    nbar /= V;
    bb = b.squaredNorm();
    return true;
  }

  /// Small-strain strain-displacement matrix of the mean strain.
  MatB mean_B() const {
    MatB B;
    for (int a = 0; a < NN; ++a)
      for (int i = 0; i < ND; ++i) {
        Eigen::Matrix<double, ND, 1> grad = b.row(a).transpose();
        B.col(a * ND + i) = field_strain(i, grad, c(a));
      }
    return B;
  }

  /// K_hg for the elastic constants (lambda the effective one of the kinematics, mu) and, when
  /// dK is given, its derivative for (dlambda, dmu). After build(). K_hg is zero on the
  /// constant-strain fields, so it is formed on the penalised fields S and mapped back with their
  /// dual coordinates Gam (u = constant-strain part + S Gam u): K_hg = Gam^T (S^T K_hg S) Gam.
  void stiffness(HourglassControl mode, double scale, double lambda, double mu, MatK& Khg,
                 double dlambda = 0.0, double dmu = 0.0, MatK* dK = nullptr) const {
    MatS S;
    MatGam Gam;
    basis(S, Gam);
    MatSF Kh, dKh;
    if (mode == HourglassControl::Stiffness) {
      const MatSF StS = S.transpose() * S;
      const double k = scale * kStiffnessFactor * V * bb;
      Kh = k * mu * StS;
      dKh = k * dmu * StS;
    } else {
      enhanced(S, lambda, mu, dlambda, dmu, dK != nullptr, Kh, dKh);
      Kh *= scale;
      dKh *= scale;
    }
    Khg.noalias() = Gam.transpose() * Kh * Gam;
    if (dK) dK->noalias() = Gam.transpose() * dKh * Gam;
  }

 private:
  struct Point {
    MatG g;
    VecN N;
    double dV = 0.0, R = 1.0, mode_scale = 1.0;
    Eigen::Matrix<double, ND, ND> J0inv;
  };

  std::span<const Vec3> _X;
  double _thickness = 1.0;

  static IsotropicModuli elastic(double lambda, double mu) {
    IsotropicModuli e;
    e.lambda = lambda;
    e.mu = mu;
    return e;
  }

  bool point(int q, const double* xi, Point& p) const {
    using MatF = Eigen::Matrix<double, ND, ND>;
    const auto rule = full_integration_rule(kShape);
    MatF J = MatF::Zero(), J0 = MatF::Zero();
    double N[NN], dN[NN * ND], N0[NN], dN0[NN * ND];
    const double centre[3] = {0.0, 0.0, 0.0};
    ShapeFunctions<kShape>::eval(xi, N, dN);
    ShapeFunctions<kShape>::eval(centre, N0, dN0);
    Eigen::Matrix<double, NN, ND> dNm;
    double R = 0.0, R0 = 0.0;
    for (int a = 0; a < NN; ++a) {
      p.N(a) = N[a];
      R += N[a] * _X[a][0];
      R0 += _X[a][0] / NN;
      for (int k = 0; k < ND; ++k) {
        dNm(a, k) = dN[a * ND + k];
        for (int l = 0; l < ND; ++l) {
          J(k, l) += _X[a][k] * dN[a * ND + l];
          J0(k, l) += _X[a][k] * dN0[a * ND + l];
        }
      }
    }
    const double j = J.determinant(), j0 = J0.determinant();
    if (!(j > 0.0) || !(j0 > 0.0) || (kAxi && !(R > 0.0))) return false;
    p.g = dNm * J.inverse();
    p.dV = rule[q].weight * j;
    p.R = R;
    p.mode_scale = j0 / j;
    if constexpr (kAxi) {
      p.dV *= 2.0 * std::numbers::pi * R;
      p.mode_scale *= R0 / R;
    } else if constexpr (ND == 2) {
      p.dV *= _thickness;
    }
    p.J0inv = J0.inverse();
    return true;
  }

  /// Small strain of the displacement field "component i = f" with gradient grad and, for the
  /// hoop strain, f / R (hoop).
  template <class VecGrad>
  static Eigen::Matrix<double, NS, 1> field_strain(int i, const VecGrad& grad, double hoop) {
    constexpr auto C = continuum_detail::voigt_pairs<K>();
    Eigen::Matrix<double, NS, 1> e = Eigen::Matrix<double, NS, 1>::Zero();
    for (int cc = 0; cc < NS; ++cc) {
      const int I = C[cc][0], J = C[cc][1];
      if (I == J && I >= ND) {
        if (kAxi && i == 0) e(cc) = hoop;
      } else if (I == J) {
        e(cc) = i == I ? grad(I) : 0.0;
      } else {
        e(cc) = (i == I ? grad(J) : 0.0) + (i == J ? grad(I) : 0.0);
      }
    }
    return e;
  }

  /// The nodal and mode strain-displacement matrices of the incompatible-mode element.
  void strains(const double* xi, const Point& p, MatB& Bu,
               Eigen::Matrix<double, NS, NMA>& Bm) const {
    for (int a = 0; a < NN; ++a)
      for (int i = 0; i < ND; ++i) {
        const Eigen::Matrix<double, ND, 1> grad = p.g.row(a).transpose();
        Bu.col(a * ND + i) = field_strain(i, grad, p.N(a) / p.R);
      }
    for (int k = 0; k < ND; ++k) {
      Eigen::Matrix<double, 1, ND> dM = Eigen::Matrix<double, 1, ND>::Zero();
      dM(k) = -2.0 * xi[k];
      const Eigen::Matrix<double, ND, 1> grad = p.mode_scale * (dM * p.J0inv).transpose();
      for (int i = 0; i < ND; ++i) Bm.col(k * ND + i) = field_strain(i, grad, 0.0);
    }
  }

  template <class MatBs, class MatKss, class MatKsm>
  static void add_blocks(const IsotropicModuli& law, double dV, const MatBs& Bs,
                         const Eigen::Matrix<double, NS, NMA>& Bm, MatKss& Kss, MatKsm& Ksm,
                         Eigen::Matrix<double, NMA, NMA>& Kmm) {
    MatBs DBs;
    Eigen::Matrix<double, NS, NMA> DBm;
    law.apply(NNRM, Bs, DBs);
    law.apply(NNRM, Bm, DBm);
    Kss.noalias() += dV * (Bs.transpose() * DBs);
    Ksm.noalias() += dV * (Bs.transpose() * DBm);
    Kmm.noalias() += dV * (Bm.transpose() * DBm);
  }

  /// S^T (K_I - K_1) S and, with `d`, its derivative for (dlambda, dmu): the incompatible-mode
  /// element's blocks on the fields S, condensed over the modes, less the uniform strain's part.
  void enhanced(const MatS& S, double lambda, double mu, double dlambda, double dmu, bool d,
                MatSF& Kh, MatSF& dKh) const {
    MatSF Kss = MatSF::Zero(), dKss = MatSF::Zero();
    Eigen::Matrix<double, NSF, NMA> Ksm = Eigen::Matrix<double, NSF, NMA>::Zero(), dKsm = Ksm;
    Eigen::Matrix<double, NMA, NMA> Kmm = Eigen::Matrix<double, NMA, NMA>::Zero(), dKmm = Kmm;
    const auto rule = full_integration_rule(kShape);
    const IsotropicModuli law = elastic(lambda, mu), dlaw = elastic(dlambda, dmu);
    for (int q = 0; q < NQ; ++q) {
      Point p;
      point(q, rule[q].xi.data(), p);
      MatB Bu;
      Eigen::Matrix<double, NS, NMA> Bm;
      strains(rule[q].xi.data(), p, Bu, Bm);
      const Eigen::Matrix<double, NS, NSF> Bs = Bu * S;
      add_blocks(law, p.dV, Bs, Bm, Kss, Ksm, Kmm);
      if (d) add_blocks(dlaw, p.dV, Bs, Bm, dKss, dKsm, dKmm);
    }
    const Eigen::Matrix<double, NS, NSF> B1 = mean_B() * S;
    const Eigen::Matrix<double, NMA, NSF> Xm = Kmm.ldlt().solve(Ksm.transpose());
    Eigen::Matrix<double, NS, NSF> DB;
    law.apply(NNRM, B1, DB);
    Kh = Kss - Ksm * Xm - V * (B1.transpose() * DB);
    Kh = 0.5 * (Kh + Kh.transpose()).eval();
    if (!d) return;
    dlaw.apply(NNRM, B1, DB);
    const MatSF cross = dKsm * Xm;
    dKh = dKss - cross - cross.transpose() + Xm.transpose() * dKmm * Xm - V * (B1.transpose() * DB);
  }

  /// The penalised fields S (columns: nodal values in one component) and their dual coordinates
  /// Gam, component by component from the basis {constant-strain fields, penalised fields}:
  /// 1, x_j then the hourglass vectors; CAX4R's u_r: r then 1, z and the hourglass vector.
  void basis(MatS& S, MatGam& Gam) const {
    S.setZero();
    Gam.setZero();
    int first = 0; // first column of the component's fields in S
    for (int i = 0; i < ND; ++i) {
      Eigen::Matrix<double, NN, NN> M;
      int col = 0, n_exact = 0;
      auto add = [&](auto f) {
        for (int a = 0; a < NN; ++a) M(a, col) = f(a);
        ++col;
      };
      const auto x = [this](int jx) { return [this, jx](int a) { return _X[a][jx]; }; };
      const auto one = [](int) { return 1.0; };
      if (kAxi && i == 0) {
        add(x(0)); // u_r = r
        n_exact = 1;
        add(one);
        add(x(1));
      } else {
        add(one);
        for (int jx = 0; jx < ND; ++jx) add(x(jx));
        n_exact = col;
      }
      for (int alpha = 0; alpha < (ND == 3 ? 4 : 1); ++alpha)
        add([alpha](int a) { return h(alpha, a); });
      const Eigen::Matrix<double, NN, NN> Minv = M.inverse();
      const int n = NN - n_exact;
      for (int k = 0; k < n; ++k)
        for (int a = 0; a < NN; ++a) {
          S(a * ND + i, first + k) = M(a, n_exact + k);
          Gam(first + k, a * ND + i) = Minv(n_exact + k, a);
        }
      first += n;
    }
  }
};

} // namespace gapfem
