#pragma once
/// @file shape_functions.hpp
/// Lagrange shape functions and their parametric derivatives for the reference cells used by the
/// continuum (C3D*, CPS*, CPE*, CAX*) and heat-transfer (DC*) elements, in Abaqus node order.
///
/// Reference cells:
///   Line2/Line3  xi in [-1, 1]; Line3 midside node is node 3
///   Tri3/Tri6    area coordinates (xi, eta), N1 = 1 - xi - eta; Tri6 midside 4: 1-2, 5: 2-3, 6:
///   3-1 Quad4        [-1, 1]^2, nodes counter-clockwise from (-1, -1) Tet4/Tet10   volume
///   coordinates (xi, eta, zeta), N1 = 1 - xi - eta - zeta; Tet10 midside
///                nodes 5..10 on edges 1-2, 2-3, 3-1, 1-4, 2-4, 3-4
///   Hex8         [-1, 1]^3, nodes 1-4 on zeta = -1 counter-clockwise from (-1, -1), 5-8 above
/// The compile-time ShapeFunctions<S> evaluates into fixed-size arrays (no allocation), for the
/// element kernels; shape_eval() is the run-time dispatch for everything else.
#include <array>
#include <cstdint>
#include <span>
#include <string_view>

namespace gapfem {

enum class Shape : std::uint8_t { Line2, Line3, Tri3, Tri6, Quad4, Tet4, Tet10, Hex8 };

/// Number of nodes of a shape.
constexpr int shape_n_nodes(Shape s) {
  switch (s) {
  case Shape::Line2:
    return 2;
  case Shape::Line3:
    return 3;
  case Shape::Tri3:
    return 3;
  case Shape::Tri6:
    return 6;
  case Shape::Quad4:
    return 4;
  case Shape::Tet4:
    return 4;
  case Shape::Tet10:
    return 10;
  case Shape::Hex8:
    return 8;
  }
  return 0;
}
/// Parametric dimension of a shape.
constexpr int shape_dim(Shape s) {
  switch (s) {
  case Shape::Line2:
  case Shape::Line3:
    return 1;
  case Shape::Tri3:
  case Shape::Tri6:
  case Shape::Quad4:
    return 2;
  default:
    return 3;
  }
}
std::string_view shape_name(Shape s);

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

/// Run-time dispatch: N (shape_n_nodes) and dN (n x shape_dim, row-major) at xi.
void shape_eval(Shape s, std::span<const double> xi, std::span<double> N, std::span<double> dN);

/// Parametric coordinates of the nodes of a shape (for tests and extrapolation).
std::span<const std::array<double, 3>> shape_node_coords(Shape s);

} // namespace gapfem
