#pragma once
/// @file shell_section_points.hpp
/// A shell section integrated through the thickness at its section points by a SolidLaw (plane
/// stress): the path of every law that is not the built-in isotropic elasticity, whose section
/// shell_section.hpp integrates in closed form (docs/theory/structural.md §4.3).
///
/// At a point of the reference surface with section strains s = (eps, kappa, gamma) the n section
/// points sit at z_k = zm - t/2 + k t / (n - 1) (k = 0 .. n - 1, SNEG to SPOS; zm = -offset t),
/// with Simpson's weights w_k. Each takes the strain eps + z_k kappa and the temperature
/// T + z_k dT/dn (the law computes the thermal strain) and its own history; then
///   N = sum w_k sigma_k,  M = sum w_k z_k sigma_k,
///   dN/deps = sum w_k D_k,  dN/dkappa = dM/deps = sum w_k z_k D_k,  dM/dkappa = sum w_k z_k^2 D_k,
/// and the transverse shear stays elastic, Q = K gamma (K = 5/6 G t or *TRANSVERSE SHEAR
/// STIFFNESS), as Abaqus keeps it. For an elastic law this is the closed form to rounding (Simpson
/// is exact for the linear strain).
#include "elements/material/solid_law.hpp"
#include "elements/structural/shell_section.hpp"

#include <array>
#include <memory>
#include <span>
#include <tuple>

namespace gapfem::shell {

/// The temperatures a section reads: at the reference surface (the element's mean) and the
/// gradient through the thickness.
struct SectionTemperature {
  double T = 0.0;        ///< now (the table's first row without a temperature field)
  double Ti = 0.0;       ///< the thermal-strain reference
  double gradient = 0.0; ///< dT/dn
  bool thermal = false;  ///< a temperature field acts on a material with expansion
};
SectionTemperature section_temperature(const Material& material, const ElementInput& in);

/// The section's answer at one surface point: resultants conjugate to (eps 11 22 12, kappa 11 22
/// 12, gamma 13 23) and, when asked, C = dR/ds (8 x 8, row-major).
struct SectionResponse {
  std::array<double, 8> R{};
  std::array<double, 64> C{};
};

/// What recovery wants at one surface point besides the resultants.
struct SectionPointsOutput {
  std::span<double> stress; ///< 3 per section point (11, 22, 12), may be empty
  std::span<double> strain; ///< 3 per section point, may be empty
  double energy = 0.0;      ///< stored energy per unit area (law energy + transverse shear)
};

class ShellSectionPoints {
 public:
  ShellSectionPoints(std::shared_ptr<const SolidLaw> law, int n_points);

  int n_points() const { return _n; }
  /// History doubles of one surface point (all its section points).
  int n_state() const { return _n * _law->n_state(); }
  void initialize(std::span<double> state) const;

  /// The response of a section of thickness t at strains s from the committed history
  /// `state_start` (n_state()); the trial history goes to `state` (not written when empty).
  void respond(const SectionLaw& l, const SectionTemperature& temp, double t,
               const SectionStrains<double>& s, std::span<const double> state_start,
               std::span<double> state, bool want_tangent, SectionResponse& out,
               SectionPointsOutput* recovery = nullptr) const;

 private:
  std::shared_ptr<const SolidLaw> _law;
  int _n;
  std::array<double, 3> point_update(const SectionTemperature& temp, double z,
                                     const std::array<double, 3>& strain,
                                     std::span<const double> start, std::span<double> trial,
                                     std::array<double, 9>* D, double* energy) const;
};

/// The values of strains carried by Jets or Duals.
template <class S>
SectionStrains<double> strain_values(const SectionStrains<S>& e) {
  SectionStrains<double> v;
  for (int i = 0; i < 3; ++i) {
    v.eps[i] = e.eps[i].v;
    v.kap[i] = e.kap[i].v;
  }
  v.gam = {e.gam[0].v, e.gam[1].v};
  return v;
}

/// Residual and tangent of one surface point of weight dA from its section response and its
/// strains s(u) (Duals: gradients; Jets: gradients and Hessians):
///   r += dA sum_c R_c grad s_c,   K += dA (sum_cd grad s_c C_cd grad s_d^T + sum_c R_c Hess s_c).
template <class S>
void add_section_terms(double dA, const SectionStrains<S>& e, const SectionResponse& resp,
                       bool want_tangent, std::span<double> residual, std::span<double> tangent) {
  constexpr int N = static_cast<int>(std::tuple_size_v<decltype(S::g)>);
  const std::array<const S*, 8> b{&e.eps[0], &e.eps[1], &e.eps[2], &e.kap[0],
                                  &e.kap[1], &e.kap[2], &e.gam[0], &e.gam[1]};
  for (int c = 0; c < 8; ++c)
    if (const double R = dA * resp.R[c]; R != 0.0)
      for (int a = 0; a < N; ++a) residual[a] += R * b[c]->g[a];
  if (!want_tangent) return;
  std::array<std::array<double, N>, 8> CB{}; // dA C grad s^T
  for (int c = 0; c < 8; ++c)
    for (int d = 0; d < 8; ++d)
      if (const double v = dA * resp.C[8 * c + d]; v != 0.0)
        for (int j = 0; j < N; ++j) CB[c][j] += v * b[d]->g[j];
  for (int c = 0; c < 8; ++c)
    for (int a = 0; a < N; ++a)
      if (const double g = b[c]->g[a]; g != 0.0)
        for (int j = 0; j < N; ++j) tangent[a * N + j] += g * CB[c][j];
  if constexpr (requires { b[0]->h; }) {
    for (int c = 0; c < 8; ++c) {
      const double R = dA * resp.R[c];
      if (R == 0.0) continue;
      int k = 0;
      for (int a = 0; a < N; ++a)
        for (int j = a; j < N; ++j, ++k) {
          const double h = R * b[c]->h[k];
          tangent[a * N + j] += h;
          if (j != a) tangent[j * N + a] += h;
        }
    }
  }
}

/// Output of the section-point path (S, E at the section points and SF of every output point, as
/// recover_shell_output lays them out) from the integration points q: strains e[q], thickness
/// t[q], surface weight dA[q] and committed history state_start.subspan(q * sp.n_state()). The
/// output points are the integration points, or with `one_point` (S4R, S3) the single centre
/// point, which reports the mean of the integration points (the history lives there). Returns
/// the stored energy sum_q dA[q] (law energy + transverse shear).
double recover_section_points(const ShellSectionPoints& sp, const SectionLaw& l,
                              const SectionTemperature& temp,
                              std::span<const SectionStrains<double>> e, std::span<const double> t,
                              std::span<const double> dA, std::span<const double> state_start,
                              bool one_point, ElementRecovery& out);

/// The elastic transverse shear stiffnesses (K13, K23) of a section of thickness t.
inline std::array<double, 2> shear_stiffness(const SectionLaw& l, double t) {
  return {l.k11 > 0.0 ? l.k11 : 5.0 / 6.0 * l.G * t, l.k22 > 0.0 ? l.k22 : 5.0 / 6.0 * l.G * t};
}

} // namespace gapfem::shell
