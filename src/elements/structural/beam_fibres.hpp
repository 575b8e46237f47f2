#pragma once
/// @file beam_fibres.hpp
/// Beam sections integrated through the material-point seam (elements/material/solid_law.hpp):
/// the section integration points ("fibres") of every library shape, and one integration point's
/// section response from the law's update at its fibres (docs/theory/structural.md §3.5).
///
/// A fibre at (x1, x2) with weight w (an area) has the strains (Kinematics::Beam)
///   eps11   = eps + kappa1 x2 - kappa2 x1          (beam_kinematics.hpp: strains 0, 3, 4)
///   gamma12 = -c x2 phi',  gamma13 = c x1 phi'     (phi' the twist, strain 5)
/// with c = sqrt(J / Ip), Ip = I11 + I22 about the section origin: the torsional shear of a fibre
/// is the circular shaft's, scaled so that an elastic law gives back exactly G J phi'^2 (the
/// warping-based shear distribution of Abaqus's sections is not modelled). The fibres reproduce
/// beam_section_properties()'s A, Q1, Q2, I11, I22 and I12 to rounding; the transverse shear stays
/// an elastic resultant in the kernel (as Abaqus treats it).
#include "elements/element_kernel.hpp"
#include "elements/material/solid_law.hpp"
#include "elements/structural/beam_kinematics.hpp"
#include "elements/structural/beam_section.hpp"

#include <array>
#include <span>
#include <vector>

namespace gapfem::beam {

/// One section integration point: its position in the local (1, 2) axes and its area weight.
struct BeamFibre {
  double x1 = 0.0, x2 = 0.0, w = 0.0;
};

/// The integration points of a section and its torsion scale c = sqrt(J / (I11 + I22)).
struct BeamFibres {
  std::vector<BeamFibre> fibres;
  double torsion = 0.0;

  int size() const { return static_cast<int>(fibres.size()); }
  /// The fibre nearest to (x1, x2) (the first of coincident ones).
  int nearest(double x1, double x2) const;
};

/// The fibres of a library section (not GENERAL): RECT Simpson 5 x 5 (with the corners); CIRC
/// Gauss-Lobatto in the radius (the centre's ring has no weight and is left out) x 16 equal
/// angles from 0; PIPE Gauss-Lobatto 3 through the wall (inner, middle, outer radius) x 16 angles;
/// TRAPEZOID Simpson 5 x 5 on the trapezoid mapped from a square (its corners included); BOX, I,
/// HEX, L Simpson 5 along every wall mid-line of beam_section.cpp with weight t ds (a corner
/// shared by two walls has a fibre from each).
BeamFibres beam_section_fibres(const BeamSection& section, const BeamSectionProperties& props);

/// The temperature field over a section: T + x2 g2 + x1 g1 (the element's averages of the nodal
/// values and of *TEMPERATURE's gradients), the initial temperature Ti; without a temperature
/// field (thermal false) the law sees the initial temperature and no thermal strain.
struct SectionTemperature {
  double T = 0.0, Ti = 0.0, g2 = 0.0, g1 = 0.0;
  bool thermal = false;

  static SectionTemperature of(const ElementInput& in);
  double at(double x1, double x2) const { return thermal ? T + x2 * g2 + x1 * g1 : T; }
};

/// What the fibres of one integration point give: the resultants R = sum w B^T sigma of the axial
/// force, moments and torque (entries 0, 3, 4, 5; the transverse shears 1, 2 are the kernel's)
/// and the section tangent C = sum w B^T D B (6 x 6 row-major).
struct SectionResponse {
  std::array<double, 6> R{};
  std::array<double, 36> C{};
  bool symmetric = true; ///< C is symmetric (every fibre's tangent was)
};

/// The law and the fibres of a section with what an update needs from the element.
struct FibreSection {
  const SolidLaw& law;
  const BeamFibres& fibres;
  SectionTemperature temperature;
  double dt = 0.0;
  bool nlgeom = false;
};

/// The law's update at every fibre of one integration point at the section strains e. `start`
/// and `trial` are that point's committed and trial history (fibres x the law's n_state).
void integrate_fibres(const FibreSection& s, const Strains<double>& e,
                      std::span<const double> start, std::span<double> trial, bool tangent,
                      SectionResponse& out);

/// The stress S11, S12 and strain E11, E12 reported at an output section point (x1, x2) with
/// torsion radius rt (beam_section.hpp): the law evaluated at the point's strain and temperature
/// from the committed history `start` of the nearest fibre (the fibre itself when the point is
/// one). E12 = rt phi' as the pre-integrated path reports; S12 the law's shear along the fibre's
/// circle scaled by rt / (c r), so an elastic law reports G rt phi' too.
struct PointStress {
  double s11 = 0.0, s12 = 0.0, e11 = 0.0, e12 = 0.0;
};
PointStress fibre_point_stress(const FibreSection& s, const Strains<double>& e, double x1,
                               double x2, double rt, std::span<const double> start);

} // namespace gapfem::beam
