#pragma once
/// @file beam_section.hpp
/// Geometric properties of the beam sections gapfem supports: the *BEAM SECTION library shapes
/// RECT, CIRC, PIPE (solid/annulus, exact), TRAPEZOID (solid polygon), BOX, I, HEX and L
/// (thin-walled, integrated along the wall mid-lines as Abaqus does), and SECTION=GENERAL of *BEAM
/// GENERAL SECTION; their shear correction factors, and the section points used for stress output.
/// All properties are about the section origin (the beam node), which need not be the centroid (the
/// I section's is not). Formulas and sources: docs/theory/structural.md §3.3.
#include "model/section.hpp"

#include <array>

namespace gapfem {

/// Cross-section properties in the local (1, 2) axes of the section, about its origin.
struct BeamSectionProperties {
  double A = 0.0;   ///< area
  double Q1 = 0.0;  ///< first moment: integral of x1 dA
  double Q2 = 0.0;  ///< first moment: integral of x2 dA
  double I11 = 0.0; ///< second moment about local axis 1: integral of x2^2 dA
  double I22 = 0.0; ///< second moment about local axis 2: integral of x1^2 dA
  double I12 = 0.0; ///< product moment: integral of x1 x2 dA
  double J = 0.0;   ///< St. Venant torsion constant
  double k = 0.0;   ///< transverse shear correction factor (Abaqus's table, Cowper 1966)
  /// *TRANSVERSE SHEAR STIFFNESS K23 (along local 2) and K13 (along local 1); 0: k G A
  double k23 = 0.0, k13 = 0.0;
  /// Section points (x1, x2) for S/E output (n_points of them; 0 for GENERAL sections): the four
  /// corners of RECT and BOX, 0/90/180/270 degrees on the outer radius of CIRC/PIPE, the flange
  /// tips of I.
  int n_points = 0;
  static constexpr int kMaxPoints = 20; ///< *SECTION POINTS may give up to this many
  std::array<std::array<double, 2>, kMaxPoints> points{};
  /// Shear stress per unit twist and shear modulus at each point, S12 = G * r * twist (CIRC/PIPE:
  /// the radius; RECT corners 0; thin walls: the wall thickness (open) or J / (2 A_m t) (closed)).
  std::array<double, kMaxPoints> torsion_radius{};

  /// PIPE: outer and inner radius (0 for other sections)
  double r_outer = 0.0, r_inner = 0.0;

  /// Centroidal second moments (for the shear-flexibility correction of two-node beams).
  double I11_centroid() const { return I11 - Q2 * Q2 / A; }
  double I22_centroid() const { return I22 - Q1 * Q1 / A; }
  double I12_centroid() const { return I12 - Q1 * Q2 / A; }
};

/// Properties of a section; throws InputError at the section's line for missing, non-positive or
/// inconsistent dimensions. Planar beams need only A and I11 of a GENERAL section.
BeamSectionProperties beam_section_properties(const BeamSection& section, bool planar = false);

/// Torsion constant of an a x b rectangle (exact St. Venant series, Timoshenko & Goodier §109).
double rectangle_torsion_constant(double a, double b);

/// Torsion constant of a symmetric trapezoid of bottom width a, height b and top width c (c = 0:
/// an isosceles triangle): Prandtl's stress function by finite elements, extrapolated (relative
/// error below 1e-5; tests/unit/elements/beam_section_test.cpp).
double trapezoid_torsion_constant(double a, double b, double c);

} // namespace gapfem
