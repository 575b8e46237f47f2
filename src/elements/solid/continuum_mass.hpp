#pragma once
/// @file continuum_mass.hpp
/// The consistent mass of every continuum element (ElementOutput::mass, on request):
///   M_(a i)(b j) = delta_ij integral rho N_a N_b dV
/// over the reference volume (times the thickness for plane elements, 2 pi R for axisymmetric
/// ones, as the kernels integrate), with rho from *DENSITY at the point's temperature, always with
/// the full rule of the shape (fe/quadrature.hpp): the reduced-integration elements too, as
/// Abaqus does. A material without *DENSITY gives a zero block (the element still has a mass
/// operator; a dynamic step asks for the density, not the kernel). Not on the static hot path: it
/// runs only when the assembler asks for the mass; allocation-free.
#include "elements/element_kernel.hpp"
#include "elements/solid/solid_point.hpp"
#include "fe/quadrature.hpp"
#include "fe/shape_functions.hpp"
#include "model/material.hpp"

#include <Eigen/Dense>
#include <numbers>
#include <span>

namespace gapfem {

/// Adds the consistent mass of an element of cell S and kinematics K to M (n x n row-major,
/// n = nodes x displacement components, node-major) from the reference coordinates in.X and the
/// temperatures of `in` (predefined field, or the NT DOFs of a coupled element as its kernel
/// hands them over). `thickness`: plane elements.
template <Shape S, Kinematics K>
void add_continuum_mass(const ElementInput& in, const Material& mat, double thickness,
                        std::span<double> M) {
  constexpr int NN = shape_n_nodes(S);
  constexpr int ND = K == Kinematics::ThreeD ? 3 : 2;
  constexpr int NDOF = NN * ND;
  FE_CHECK(M.size() == static_cast<std::size_t>(NDOF * NDOF), "continuum mass: block size");
  if (mat.density.empty()) return;
  const bool varying = mat.density.n_rows() > 1 && mat.density.keys.size() > 1;
  for (const QuadraturePoint& qp : full_integration_rule(S)) {
    double N[NN], dN[NN * ND];
    ShapeFunctions<S>::eval(qp.xi.data(), N, dN);
    Eigen::Matrix<double, ND, ND> J = Eigen::Matrix<double, ND, ND>::Zero();
    for (int a = 0; a < NN; ++a)
      for (int k = 0; k < ND; ++k)
        for (int l = 0; l < ND; ++l) J(k, l) += in.X[a][k] * dN[a * ND + l];
    double dV = qp.weight * J.determinant();
    if constexpr (K == Kinematics::Axisymmetric) {
      double R = 0.0;
      for (int a = 0; a < NN; ++a) R += N[a] * in.X[a][0];
      dV *= 2.0 * std::numbers::pi * R;
    } else if constexpr (ND == 2) {
      dV *= thickness;
    }
    const PointTemperature t = point_temperature(
        in, [&N](int a) { return N[a]; }, NN, varying);
    const double rho_dV = mat.density.value(t.T) * dV;
    for (int a = 0; a < NN; ++a)
      for (int b = 0; b < NN; ++b) {
        const double m = rho_dV * (N[a] * N[b]); // exactly symmetric
        for (int i = 0; i < ND; ++i) M[(a * ND + i) * NDOF + b * ND + i] += m;
      }
  }
}

} // namespace gapfem
