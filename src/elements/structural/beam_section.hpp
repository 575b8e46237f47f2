#pragma once
/// @file beam_section.hpp
/// Geometric properties of the *BEAM SECTION library shapes gapfem supports (RECT, CIRC, PIPE),
/// their shear correction factors and the section points used for stress output.
/// Formulas and sources: docs/theory/structural.md §3.
#include "model/section.hpp"

#include <array>

namespace gapfem {

/// Cross-section properties in the local (1, 2) axes of the section.
struct BeamSectionProperties {
  double A = 0.0;   ///< area
  double I11 = 0.0; ///< second moment about local axis 1: integral of x2^2 dA
  double I22 = 0.0; ///< second moment about local axis 2: integral of x1^2 dA
  double J = 0.0;   ///< St. Venant torsion constant
  double k = 0.0;   ///< transverse shear correction factor (Abaqus defaults, Cowper 1966)
  /// Section points (x1, x2) for S/E output: the four corners of RECT, or 0/90/180/270 degrees on
  /// the outer radius of CIRC/PIPE.
  std::array<std::array<double, 2>, 4> points{};
  /// Radius used for the torsional shear S12 = T r / J at each point (0 at RECT corners, where the
  /// St. Venant shear stress vanishes).
  std::array<double, 4> torsion_radius{};
};

/// Properties of a section; throws InputError at the *BEAM SECTION line for missing or
/// non-positive dimensions.
BeamSectionProperties beam_section_properties(const BeamSection& section);

/// Torsion constant of an a x b rectangle (exact St. Venant series, Timoshenko & Goodier §109).
double rectangle_torsion_constant(double a, double b);

} // namespace gapfem
