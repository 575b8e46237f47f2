#pragma once
/// @file modal_basis.hpp
/// The modes a *FREQUENCY step extracted, kept for the mode-based procedures that follow it
/// (*RESPONSE SPECTRUM, *STEADY STATE DYNAMICS, *MODAL DYNAMIC; docs/theory/frequency.md):
/// eigenvalues, mass-normalised shapes per DOF slot, participation factors of the unit-mass
/// shapes, and modal damping fractions once a step gives them.
#include "common/types.hpp"

#include <array>
#include <cmath>
#include <vector>

namespace gapfem {

struct ModalBasis {
  int step_number = 0;        ///< the *FREQUENCY step
  LocalIndex n_slots = 0;     ///< entries per shape
  std::vector<double> omega2; ///< eigenvalues omega^2, ascending
  std::vector<double> shapes; ///< n_slots per mode, phi^T M phi = 1 (0 at held DOFs)
  /// per mode: Gamma = phi^T M T for the unit-mass shape (X, Y, Z, rotations about X, Y, Z)
  std::vector<std::array<double, 6>> participation;

  int modes() const { return static_cast<int>(omega2.size()); }
  double omega(int k) const { return omega2[k] > 0.0 ? std::sqrt(omega2[k]) : 0.0; }
  double frequency(int k) const { return omega(k) / (2.0 * 3.14159265358979323846); }
  const double* shape(int k) const { return shapes.data() + static_cast<std::size_t>(k) * n_slots; }
};

} // namespace gapfem
