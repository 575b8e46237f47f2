#pragma once
/// @file beam.hpp
/// B31: two-node shear-flexible (Timoshenko) beam in space, 6 DOFs per node, small displacements
/// and rotations (Abaqus Analysis User's Manual,
/// "Beam element library" and "Choosing a beam element").
///
/// Formulation (docs/theory/structural.md §3): linear interpolation of displacements and rotations
/// with one integration point at mid-length, as Abaqus's B31, and a transverse shear stiffness
/// K_s = kGA / (1 + kGA L^2 / (12 E I)) per bending plane. This is Abaqus's "slenderness
/// compensation" with its factor set to the value kG/E that makes the element stiffness equal the
/// exact stiffness of a prismatic Timoshenko beam (MacNeal's residual bending flexibility), so
/// end-loaded beams are exact for any number of elements: a cantilever tip deflects
/// P L^3/(3EI) + P L/(kGA). (Abaqus's default factor 0.25 instead of kG/E makes its coarse meshes
/// slightly different.)
///
/// Local axes (Abaqus "Beam element cross-section orientation"): t = (X2 - X1)/L, n2 = t x n1a /
/// |.| with n1a the approximate n1 of *BEAM SECTION (default (0,0,-1)), n1 = n2 x t. Output at the
/// integration point: SF1 axial force, SF2/SF3 shear forces along n2/n1, SM1/SM2 bending moments
/// about n1/n2, SM3 twisting moment; S11/S12 and E11/E12 at four section points.
#include "elements/element_kernel.hpp"
#include "elements/structural/beam_section.hpp"
#include "model/material.hpp"

#include <array>

namespace gapfem {

/// B31 kernel. Immutable; thread-safe; no heap use in evaluate().
class BeamKernel final : public ElementKernel {
 public:
  BeamKernel(Material material, BeamSectionProperties section, Vec3 n1_approx);

  ElementType type() const override { return ElementType::B31; }
  std::span<const DofType> node_dofs(int local_node) const override;
  bool uses_temperature_field() const override;
  std::string validate(const ElementInput& in) const override;
  void evaluate(const ElementInput& in, ElementOutput& out) const override;
  bool supports_load(DistLoadKind kind, int face) const override;
  void load(const ElementInput& in, const DistributedLoad& load, double magnitude,
            double sink_temperature, std::span<double> f_ext,
            std::span<double> tangent) const override;
  bool supports_output(ElemVar var) const override;
  void recover(const ElementInput& in, ElementRecovery& out) const override;

  /// Local frame: rows t, n1, n2 (global components).
  using Frame = std::array<Vec3, 3>;
  /// Local frame of an element with reference coordinates X (undefined if validate() failed).
  Frame frame(std::span<const Vec3> X) const;

  /// Generalised strains and section forces at the integration point, in the order of the SF
  /// output: (axial strain, shear strain along n2, shear strain along n1, curvature about n1,
  /// curvature about n2, twist) and (SF1, SF2, SF3, SM1, SM2, SM3).
  struct SectionState {
    std::array<double, 6> strain{};
    std::array<double, 6> force{};
    double thermal_strain = 0.0;
    double E = 0.0, G = 0.0;
  };
  SectionState section_state(const ElementInput& in) const;

  const BeamSectionProperties& section() const { return _section; }

 private:
  Material _material;
  BeamSectionProperties _section;
  Vec3 _n1a;
};

/// Factory for B31 blocks: section and material checks, and the NLGEOM restriction.
std::unique_ptr<ElementKernel> make_beam_kernel(const KernelContext& ctx);

} // namespace gapfem
