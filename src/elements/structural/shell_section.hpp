#pragma once
/// @file shell_section.hpp
/// The homogeneous elastic shell section (*SHELL SECTION): resultant stiffnesses, the section
/// energy of one point, output at the section points, and the block data of the shell kernels
/// (nodal directors and thicknesses). docs/theory/structural.md §4.3.
///
/// With z measured from the reference surface (z in [zm - t/2, zm + t/2], zm = -offset t) and
/// Q the plane-stress stiffness, Simpson's rule through the thickness integrates the linear strain
/// eps + z kappa exactly:
///   N = t Q (eps - eps_th) + t zm Q kappa,  M = t zm Q (eps - eps_th) + (t^3/12 + t zm^2) Q kappa,
///   Q_s = K gamma with K = 5/6 G t (or K11, K22 of *TRANSVERSE SHEAR STIFFNESS).
#include "elements/element_kernel.hpp"
#include "elements/structural/shell_strains.hpp"
#include "model/material.hpp"

#include <span>
#include <vector>

namespace gapfem::shell {

/// What a shell block needs beyond the element's local data.
struct ShellData {
  ElementType type = ElementType::S4R;
  Material material;
  int n_points = 5;    ///< section points (Simpson)
  double offset = 0.0; ///< reference surface offset, fraction of the thickness
  double k11 = 0.0, k22 = 0.0;
  std::vector<Vec3> directors;   ///< per element of the block, per node: unit reference director
  std::vector<double> thickness; ///< per element of the block, per node
};

/// The block's data; InputError for wrong combinations (no *ELASTIC, missing nodal thickness).
ShellData shell_data(const KernelContext& ctx);
/// The *SHELL SECTION of a block of shells (stress, heat-transfer or coupled); InputError naming
/// the element type when the block has none.
const ShellSection& shell_section_of(const KernelContext& ctx);
/// Thickness per element of the block, per node: the section's, or with NODAL THICKNESS the
/// node's (InputError for a node without one).
std::vector<double> block_thicknesses(const KernelContext& ctx, const ShellSection& sec);

/// Elastic constants of an element at its temperature.
struct SectionLaw {
  double E = 0.0, nu = 0.0, G = 0.0;
  double eps_th = 0.0; ///< isotropic thermal strain of the membrane
  double kap_th =
      0.0; ///< thermal curvature alpha dT/dn (11 and 22) of a through-thickness gradient
  double offset = 0.0;
  double k11 = 0.0, k22 = 0.0; ///< given shear stiffnesses, 0 for 5/6 G t
  int n_points = 5;
};
SectionLaw section_law(const ShellData& d, const ElementInput& in);

/// q^T Q q / 2 for the plane-stress stiffness Q of (E, nu) and Voigt strains (11, 22, 12).
template <class T>
T plane_energy(const SectionLaw& l, const std::array<T, 3>& a, const std::array<T, 3>& b) {
  const double c = l.E / (1.0 - l.nu * l.nu);
  return c * (a[0] * b[0] + a[1] * b[1] + l.nu * (a[0] * b[1] + a[1] * b[0]) +
              0.5 * (1.0 - l.nu) * (a[2] * b[2]));
}

/// Energy per unit area of a section with thickness t at strains s.
template <class T>
T section_energy(const SectionLaw& l, double t, const SectionStrains<T>& s) {
  std::array<T, 3> e = s.eps;
  e[0] -= l.eps_th;
  e[1] -= l.eps_th;
  const double zm = -l.offset * t;
  const double A = t, B = t * zm, D = t * t * t / 12.0 + t * zm * zm;
  std::array<T, 3> k = s.kap;
  k[0] -= l.kap_th;
  k[1] -= l.kap_th;
  T W =
      0.5 * A * plane_energy(l, e, e) + B * plane_energy(l, e, k) + 0.5 * D * plane_energy(l, k, k);
  const double K1 = l.k11 > 0.0 ? l.k11 : 5.0 / 6.0 * l.G * t;
  const double K2 = l.k22 > 0.0 ? l.k22 : 5.0 / 6.0 * l.G * t;
  W += 0.5 * (K1 * (s.gam[0] * s.gam[0]) + K2 * (s.gam[1] * s.gam[1]));
  return W;
}

/// The 8 x 8 section stiffness of the strains (eps 11, 22, 12; kappa 11, 22, 12; gamma 13, 23) of
/// a section with thickness t, row-major: the Hessian of section_energy.
std::array<double, 64> section_matrix(const SectionLaw& l, double t);

/// The output blocks of np output points with ns section points each: SF (SF1-SF5, SM1-SM3 per
/// output point), S and E (3 per section point, rows point-major, SNEG to SPOS).
struct ShellOutputBlocks {
  OutputBlock* SF = nullptr;
  OutputBlock* S = nullptr;
  OutputBlock* E = nullptr;
};
ShellOutputBlocks add_shell_output_blocks(int np, int ns, ElementRecovery& out);

/// S and E at the section points (rows point-major: output point, then section point 1..n from
/// SNEG to SPOS) and SF1-SF5, SM1-SM3 per output point.
void recover_shell_output(const SectionLaw& l, std::span<const SectionStrains<double>> e,
                          std::span<const double> thickness, ElementRecovery& out);

} // namespace gapfem::shell
