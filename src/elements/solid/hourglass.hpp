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
/// elastic constants at the element's mean temperature.
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

  using MatG = Eigen::Matrix<double, NN, ND>;
  using VecN = Eigen::Matrix<double, NN, 1>;
  using MatK = Eigen::Matrix<double, NDOF, NDOF>;
  using MatB = Eigen::Matrix<double, NS, NDOF>;

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
  /// dK is given, its derivative for (dlambda, dmu). After build().
  void stiffness(HourglassControl mode, double scale, double lambda, double mu, MatK& Khg,
                 double dlambda = 0.0, double dmu = 0.0, MatK* dK = nullptr) const {
    if (mode == HourglassControl::Stiffness) {
      const MatK PtP = projector_gram();
      const double k = scale * kStiffnessFactor * V * bb;
      Khg = k * mu * PtP;
      if (dK) *dK = k * dmu * PtP;
      return;
    }
    // the incompatible-mode element's blocks for (lambda, mu) and for (dlambda, dmu)
    const bool d = dK != nullptr;
    MatK Kuu = MatK::Zero(), dKuu = MatK::Zero();
    Eigen::Matrix<double, NDOF, NMA> Kum = Eigen::Matrix<double, NDOF, NMA>::Zero(), dKum = Kum;
    Eigen::Matrix<double, NMA, NMA> Kmm = Eigen::Matrix<double, NMA, NMA>::Zero(), dKmm = Kmm;
    const auto rule = full_integration_rule(kShape);
    const ElasticPoint law = elastic(lambda, mu), dlaw = elastic(dlambda, dmu);
    for (int q = 0; q < NQ; ++q) {
      Point p;
      point(q, rule[q].xi.data(), p);
      MatB Bu;
      Eigen::Matrix<double, NS, NMA> Bm;
      strains(rule[q].xi.data(), p, Bu, Bm);
      add_blocks(law, p.dV, Bu, Bm, Kuu, Kum, Kmm);
      if (d) add_blocks(dlaw, p.dV, Bu, Bm, dKuu, dKum, dKmm);
    }
    const MatB B1 = mean_B();
    const Eigen::Matrix<double, NMA, NDOF> Xm = Kmm.ldlt().solve(Kum.transpose());
    MatB DB;
    law.apply(NNRM, B1, DB);
    Khg = scale * (Kuu - Kum * Xm - V * (B1.transpose() * DB));
    Khg = 0.5 * (Khg + Khg.transpose()).eval();
    if (!d) return;
    dlaw.apply(NNRM, B1, DB);
    const MatK cross = dKum * Xm;
    *dK = scale * (dKuu - cross - cross.transpose() + Xm.transpose() * dKmm * Xm -
                   V * (B1.transpose() * DB));
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

  static ElasticPoint elastic(double lambda, double mu) {
    ElasticPoint e;
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

  static void add_blocks(const ElasticPoint& law, double dV, const MatB& Bu,
                         const Eigen::Matrix<double, NS, NMA>& Bm, MatK& Kuu,
                         Eigen::Matrix<double, NDOF, NMA>& Kum,
                         Eigen::Matrix<double, NMA, NMA>& Kmm) {
    MatB DBu;
    Eigen::Matrix<double, NS, NMA> DBm;
    law.apply(NNRM, Bu, DBu);
    law.apply(NNRM, Bm, DBm);
    Kuu.noalias() += dV * (Bu.transpose() * DBu);
    Kum.noalias() += dV * (Bu.transpose() * DBm);
    Kmm.noalias() += dV * (Bm.transpose() * DBm);
  }

  /// P^T P of HOURGLASS=STIFFNESS, P the oblique projector onto the penalised fields along the
  /// constant-strain ones, component by component.
  MatK projector_gram() const {
    MatK G = MatK::Zero();
    for (int i = 0; i < ND; ++i) {
      // basis columns: constant-strain fields first, then the penalised ones
      Eigen::Matrix<double, NN, NN> M;
      int col = 0, n_exact = 0;
      auto add = [&](auto f) {
        for (int a = 0; a < NN; ++a) M(a, col) = f(a);
        ++col;
      };
      const auto x = [&](int jx) { return [this, jx](int a) { return _X[a][jx]; }; };
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
      const Eigen::Matrix<double, NN, NN> P =
          M.rightCols(NN - n_exact) * Minv.bottomRows(NN - n_exact);
      const Eigen::Matrix<double, NN, NN> PtP = P.transpose() * P;
      for (int a = 0; a < NN; ++a)
        for (int bn = 0; bn < NN; ++bn) G(a * ND + i, bn * ND + i) = PtP(a, bn);
    }
    return G;
  }
};

} // namespace gapfem
