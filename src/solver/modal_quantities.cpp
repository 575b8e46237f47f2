#include "solver/modal_quantities.hpp"

#include <algorithm>
#include <cmath>

namespace gapfem {
namespace {

/// T_i over the equations: the rigid-body motion of direction i (0-2 translations, 3-5 rotations
/// about the axes through the origin); `rotations` set when any equation is a rotation.
std::array<std::vector<double>, 6> rigid_body_vectors(const Mesh& mesh, const DofMap& dofs,
                                                      const EquationMap& eqm, bool& rotations) {
  const LocalIndex n = eqm.n_eq();
  std::array<std::vector<double>, 6> T;
  for (auto& t : T) t.assign(static_cast<std::size_t>(n), 0.0);
  rotations = false;
  for (LocalIndex eq = 0; eq < n; ++eq) {
    const LocalIndex s = eqm.eq_slot[eq];
    const int d = static_cast<int>(dofs.slot_dof(s));
    const Vec3& x = mesh.coords[dofs.slot_node(s)];
    if (d < 3) {
      T[d][eq] = 1.0;
      // rotation about axis j moves x by e_j x x: component d of it
      for (int j = 0; j < 3; ++j) {
        const Vec3 e{j == 0 ? 1.0 : 0.0, j == 1 ? 1.0 : 0.0, j == 2 ? 1.0 : 0.0};
        const Vec3 c{e[1] * x[2] - e[2] * x[1], e[2] * x[0] - e[0] * x[2],
                     e[0] * x[1] - e[1] * x[0]};
        T[3 + j][eq] = c[d];
      }
    } else if (d < 6) {
      T[d][eq] = 1.0;
      rotations = true;
    }
  }
  return T;
}

} // namespace

std::size_t largest_entry(std::span<const double> phi, const DofMap& dofs, const EquationMap& eqm) {
  std::size_t best = 0;
  double big = -1.0;
  for (std::size_t eq = 0; eq < phi.size(); ++eq) {
    if (static_cast<int>(dofs.slot_dof(eqm.eq_slot[eq])) >= 6) continue;
    if (std::abs(phi[eq]) > big * (1.0 + 1e-12)) {
      big = std::abs(phi[eq]);
      best = eq;
    }
  }
  return best;
}

EigenSummary modal_summary(const Mesh& mesh, const DofMap& dofs, const EquationMap& eqm,
                           const CsrMatrix& M, EigenPairs& pairs, bool mass_normalized) {
  EigenSummary out;
  out.mass_normalized = mass_normalized;
  out.shift = pairs.shift;
  const auto n = static_cast<std::size_t>(eqm.n_eq());
  const auto T = rigid_body_vectors(mesh, dofs, eqm, out.rotations);
  std::vector<double> MT(n), Mphi(n);
  std::array<std::vector<double>, 6> MTs;
  for (int i = 0; i < 6; ++i) {
    MTs[i].resize(n);
    M.multiply(T[i], MTs[i]);
    double m = 0.0;
    for (std::size_t k = 0; k < n; ++k) m += T[i][k] * MTs[i][k];
    out.model_mass[i] = m;
  }
  for (std::size_t k = 0; k < pairs.values.size(); ++k) {
    std::span<double> phi(pairs.vectors.data() + k * n, n);
    const std::size_t big = largest_entry(phi, dofs, eqm);
    // Spectra's vectors have unit generalized mass: scale to the largest entry +1, or flip only
    const double scale = mass_normalized ? (phi[big] < 0.0 ? -1.0 : 1.0) : 1.0 / phi[big];
    for (double& v : phi) v *= scale;
    M.multiply(phi, Mphi);
    ModeInfo mi;
    mi.mode = static_cast<int>(k) + 1;
    mi.eigenvalue = pairs.values[k];
    for (std::size_t j = 0; j < n; ++j) mi.generalized_mass += phi[j] * Mphi[j];
    for (int i = 0; i < 6; ++i) {
      double p = 0.0;
      for (std::size_t j = 0; j < n; ++j) p += phi[j] * MTs[i][j];
      mi.participation[i] = mi.generalized_mass > 0.0 ? p / mi.generalized_mass : 0.0;
      mi.effective_mass[i] = mi.participation[i] * mi.participation[i] * mi.generalized_mass;
      out.total_effective_mass[i] += mi.effective_mass[i];
    }
    if (std::abs(mi.eigenvalue) <= 1e-11 * pairs.scale) ++out.rigid_body_modes;
    out.modes.push_back(mi);
  }
  return out;
}

} // namespace gapfem
