#pragma once
/// @file modal_combination.hpp
/// The summation rules of a response spectrum analysis (*RESPONSE SPECTRUM, SUM=): the peak of
/// one response quantity from its modal peaks, each of which reaches its own maximum at its own
/// time (Abaqus Theory Guide, "Response spectrum analysis"; docs/theory/frequency.md §6).
#include "model/step.hpp" // ModalSum

#include <span>

namespace gapfem {

struct ModalPeaks {
  std::span<const double> r;     ///< the quantity's peak in each mode, signed (phi_k Gamma_k S_d)
  std::span<const double> omega; ///< the modes' circular frequencies, ascending
  std::span<const double> zeta;  ///< the modes' damping fractions
  double duration = 0.0;         ///< DSC: the earthquake's duration (0: none)
};

/// The CQC correlation of modes i and j (Der Kiureghian): 1 for i = j.
double cqc_correlation(double wi, double wj, double zi, double zj);
/// The DSC (Rosenblueth) correlation of modes i and j for a motion of duration `duration`.
double dsc_correlation(double wi, double wj, double zi, double zj, double duration);
/// The combined peak (non-negative).
double combine_modes(ModalSum rule, const ModalPeaks& p);

} // namespace gapfem
