#pragma once
/// @file shape_functions.hpp
/// Lagrange shape functions and their parametric derivatives for the reference cells used by the
/// continuum (C3D*, CPS*, CPE*, CAX*) and heat-transfer (DC*) elements, in Abaqus node order.
///
/// The reference cells and node orders are listed in model/cell_shape.hpp. Quad8 and Hex20 are the
/// serendipity elements, Wedge15 the serendipity wedge (quadratic triangle x quadratic line without
/// the face and centre nodes). The compile-time ShapeFunctions<S> evaluates into fixed-size arrays
/// (no allocation), for the element kernels; shape_eval() is the run-time dispatch for everything
/// else.
#include "model/cell_shape.hpp"

#include <array>
#include <span>

namespace gapfem {

/// Shape functions N (n) and parametric derivatives dN (n x dim, row-major: dN[a*dim + k] =
/// dN_a/dxi_k) of shape S at xi.
template <Shape S>
struct ShapeFunctions {
  static constexpr int n = shape_n_nodes(S);
  static constexpr int dim = shape_dim(S);
  static void eval(const double* xi, double* N, double* dN);
};

template <>
inline void ShapeFunctions<Shape::Line2>::eval(const double* xi, double* N, double* dN) {
  N[0] = 0.5 * (1.0 - xi[0]);
  N[1] = 0.5 * (1.0 + xi[0]);
  dN[0] = -0.5;
  dN[1] = 0.5;
}

template <>
inline void ShapeFunctions<Shape::Line3>::eval(const double* xi, double* N, double* dN) {
  const double x = xi[0];
  N[0] = 0.5 * x * (x - 1.0);
  N[1] = 0.5 * x * (x + 1.0);
  N[2] = 1.0 - x * x;
  dN[0] = x - 0.5;
  dN[1] = x + 0.5;
  dN[2] = -2.0 * x;
}

template <>
inline void ShapeFunctions<Shape::Tri3>::eval(const double* xi, double* N, double* dN) {
  N[0] = 1.0 - xi[0] - xi[1];
  N[1] = xi[0];
  N[2] = xi[1];
  dN[0] = -1.0, dN[1] = -1.0;
  dN[2] = 1.0, dN[3] = 0.0;
  dN[4] = 0.0, dN[5] = 1.0;
}

template <>
inline void ShapeFunctions<Shape::Tri6>::eval(const double* xi, double* N, double* dN) {
  const double L1 = 1.0 - xi[0] - xi[1], L2 = xi[0], L3 = xi[1];
  N[0] = L1 * (2.0 * L1 - 1.0);
  N[1] = L2 * (2.0 * L2 - 1.0);
  N[2] = L3 * (2.0 * L3 - 1.0);
  N[3] = 4.0 * L1 * L2;
  N[4] = 4.0 * L2 * L3;
  N[5] = 4.0 * L3 * L1;
  // dL1 = (-1, -1), dL2 = (1, 0), dL3 = (0, 1)
  dN[0] = -(4.0 * L1 - 1.0), dN[1] = -(4.0 * L1 - 1.0);
  dN[2] = 4.0 * L2 - 1.0, dN[3] = 0.0;
  dN[4] = 0.0, dN[5] = 4.0 * L3 - 1.0;
  dN[6] = 4.0 * (L1 - L2), dN[7] = -4.0 * L2;
  dN[8] = 4.0 * L3, dN[9] = 4.0 * L2;
  dN[10] = -4.0 * L3, dN[11] = 4.0 * (L1 - L3);
}

template <>
inline void ShapeFunctions<Shape::Quad4>::eval(const double* xi, double* N, double* dN) {
  constexpr double s[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int a = 0; a < 4; ++a) {
    const double p = 1.0 + s[a][0] * xi[0], q = 1.0 + s[a][1] * xi[1];
    N[a] = 0.25 * p * q;
    dN[2 * a] = 0.25 * s[a][0] * q;
    dN[2 * a + 1] = 0.25 * s[a][1] * p;
  }
}

template <>
inline void ShapeFunctions<Shape::Tet4>::eval(const double* xi, double* N, double* dN) {
  N[0] = 1.0 - xi[0] - xi[1] - xi[2];
  N[1] = xi[0];
  N[2] = xi[1];
  N[3] = xi[2];
  constexpr double d[12] = {-1, -1, -1, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  for (int k = 0; k < 12; ++k) dN[k] = d[k];
}

template <>
inline void ShapeFunctions<Shape::Tet10>::eval(const double* xi, double* N, double* dN) {
  const double L[4] = {1.0 - xi[0] - xi[1] - xi[2], xi[0], xi[1], xi[2]};
  // dL_i/dxi_k
  constexpr double dL[4][3] = {{-1, -1, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  constexpr int edge[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  for (int a = 0; a < 4; ++a) {
    N[a] = L[a] * (2.0 * L[a] - 1.0);
    for (int k = 0; k < 3; ++k) dN[3 * a + k] = (4.0 * L[a] - 1.0) * dL[a][k];
  }
  for (int e = 0; e < 6; ++e) {
    const int i = edge[e][0], j = edge[e][1];
    N[4 + e] = 4.0 * L[i] * L[j];
    for (int k = 0; k < 3; ++k) dN[3 * (4 + e) + k] = 4.0 * (dL[i][k] * L[j] + L[i] * dL[j][k]);
  }
}

template <>
inline void ShapeFunctions<Shape::Hex8>::eval(const double* xi, double* N, double* dN) {
  constexpr double s[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                              {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  for (int a = 0; a < 8; ++a) {
    const double p = 1.0 + s[a][0] * xi[0], q = 1.0 + s[a][1] * xi[1], r = 1.0 + s[a][2] * xi[2];
    N[a] = 0.125 * p * q * r;
    dN[3 * a] = 0.125 * s[a][0] * q * r;
    dN[3 * a + 1] = 0.125 * s[a][1] * p * r;
    dN[3 * a + 2] = 0.125 * s[a][2] * p * q;
  }
}

template <>
inline void ShapeFunctions<Shape::Quad8>::eval(const double* xi, double* N, double* dN) {
  constexpr double s[8][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1}, {1, 0}, {0, 1}, {-1, 0}};
  const double x = xi[0], y = xi[1];
  for (int a = 0; a < 8; ++a) {
    const double sa = s[a][0], ta = s[a][1];
    if (a < 4) { // corner: 1/4 (1 + x sa)(1 + y ta)(x sa + y ta - 1)
      const double p = 1.0 + sa * x, q = 1.0 + ta * y, r = sa * x + ta * y - 1.0;
      N[a] = 0.25 * p * q * r;
      dN[2 * a] = 0.25 * sa * q * (r + p);
      dN[2 * a + 1] = 0.25 * ta * p * (r + q);
    } else if (sa == 0.0) { // midside on y = ta: 1/2 (1 - x^2)(1 + y ta)
      N[a] = 0.5 * (1.0 - x * x) * (1.0 + ta * y);
      dN[2 * a] = -x * (1.0 + ta * y);
      dN[2 * a + 1] = 0.5 * ta * (1.0 - x * x);
    } else { // midside on x = sa: 1/2 (1 + x sa)(1 - y^2)
      N[a] = 0.5 * (1.0 + sa * x) * (1.0 - y * y);
      dN[2 * a] = 0.5 * sa * (1.0 - y * y);
      dN[2 * a + 1] = -y * (1.0 + sa * x);
    }
  }
}

template <>
inline void ShapeFunctions<Shape::Wedge6>::eval(const double* xi, double* N, double* dN) {
  const double L[3] = {1.0 - xi[0] - xi[1], xi[0], xi[1]};
  constexpr double dL[3][2] = {{-1, -1}, {1, 0}, {0, 1}};
  for (int h = 0; h < 2; ++h) {
    const double sz = h == 0 ? -1.0 : 1.0, f = 0.5 * (1.0 + sz * xi[2]);
    for (int i = 0; i < 3; ++i) {
      const int a = 3 * h + i;
      N[a] = L[i] * f;
      dN[3 * a] = dL[i][0] * f;
      dN[3 * a + 1] = dL[i][1] * f;
      dN[3 * a + 2] = 0.5 * sz * L[i];
    }
  }
}

template <>
inline void ShapeFunctions<Shape::Wedge15>::eval(const double* xi, double* N, double* dN) {
  const double L[3] = {1.0 - xi[0] - xi[1], xi[0], xi[1]}, z = xi[2];
  constexpr double dL[3][2] = {{-1, -1}, {1, 0}, {0, 1}};
  constexpr int edge[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  const double b = 1.0 - z * z; // vertical bubble
  for (int h = 0; h < 2; ++h) {
    const double sz = h == 0 ? -1.0 : 1.0, f = 1.0 + sz * z; // (1 -+ z)
    for (int i = 0; i < 3; ++i) {
      // corner: 1/2 L (2L - 1)(1 + sz z) - 1/2 L (1 - z^2)
      const int a = 3 * h + i;
      const double g = 0.5 * (2.0 * L[i] - 1.0) * f - 0.5 * b; // N = L g
      const double dg_dL = f;
      N[a] = L[i] * g;
      const double dN_dL = g + L[i] * dg_dL;
      dN[3 * a] = dN_dL * dL[i][0];
      dN[3 * a + 1] = dN_dL * dL[i][1];
      dN[3 * a + 2] = L[i] * (0.5 * (2.0 * L[i] - 1.0) * sz + z);
      // triangle-edge midside: 2 Li Lj (1 + sz z)
      const int m = 6 + 3 * h + i, p = edge[i][0], q = edge[i][1];
      N[m] = 2.0 * L[p] * L[q] * f;
      for (int k = 0; k < 2; ++k) dN[3 * m + k] = 2.0 * (dL[p][k] * L[q] + L[p] * dL[q][k]) * f;
      dN[3 * m + 2] = 2.0 * L[p] * L[q] * sz;
    }
  }
  for (int i = 0; i < 3; ++i) { // vertical-edge midside: L (1 - z^2)
    const int m = 12 + i;
    N[m] = L[i] * b;
    dN[3 * m] = dL[i][0] * b;
    dN[3 * m + 1] = dL[i][1] * b;
    dN[3 * m + 2] = -2.0 * z * L[i];
  }
}

template <>
inline void ShapeFunctions<Shape::Hex20>::eval(const double* xi, double* N, double* dN) {
  constexpr double s[20][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1},
                               {1, -1, 1},   {1, 1, 1},   {-1, 1, 1}, {0, -1, -1}, {1, 0, -1},
                               {0, 1, -1},   {-1, 0, -1}, {0, -1, 1}, {1, 0, 1},   {0, 1, 1},
                               {-1, 0, 1},   {-1, -1, 0}, {1, -1, 0}, {1, 1, 0},   {-1, 1, 0}};
  for (int a = 0; a < 20; ++a) {
    double p[3], dp[3]; // the factors (1 + s_k x_k) or, along the midside's own axis, (1 - x_k^2)
    int along = -1;
    for (int k = 0; k < 3; ++k) {
      if (s[a][k] == 0.0) {
        along = k;
        p[k] = 1.0 - xi[k] * xi[k];
        dp[k] = -2.0 * xi[k];
      } else {
        p[k] = 1.0 + s[a][k] * xi[k];
        dp[k] = s[a][k];
      }
    }
    if (along < 0) { // corner: 1/8 p0 p1 p2 (s.x - 2)
      const double r = s[a][0] * xi[0] + s[a][1] * xi[1] + s[a][2] * xi[2] - 2.0;
      N[a] = 0.125 * p[0] * p[1] * p[2] * r;
      dN[3 * a] = 0.125 * p[1] * p[2] * (dp[0] * r + p[0] * s[a][0]);
      dN[3 * a + 1] = 0.125 * p[0] * p[2] * (dp[1] * r + p[1] * s[a][1]);
      dN[3 * a + 2] = 0.125 * p[0] * p[1] * (dp[2] * r + p[2] * s[a][2]);
    } else { // midside: 1/4 p0 p1 p2
      N[a] = 0.25 * p[0] * p[1] * p[2];
      dN[3 * a] = 0.25 * dp[0] * p[1] * p[2];
      dN[3 * a + 1] = 0.25 * p[0] * dp[1] * p[2];
      dN[3 * a + 2] = 0.25 * p[0] * p[1] * dp[2];
    }
  }
}

/// Run-time dispatch: N (shape_n_nodes) and dN (n x shape_dim, row-major) at xi.
void shape_eval(Shape s, std::span<const double> xi, std::span<double> N, std::span<double> dN);

/// Parametric coordinates of the nodes of a shape (for tests and extrapolation).
std::span<const std::array<double, 3>> shape_node_coords(Shape s);

} // namespace gapfem
