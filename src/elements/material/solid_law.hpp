#pragma once
/// @file solid_law.hpp
/// The material-point seam of the solids: one integration point's constitutive update, called by
/// the continuum kernels (solid/solid_point.hpp) and nowhere else. A law sees only the point: the
/// strain, its committed history, the temperatures and the time increment; it returns the stress,
/// the consistent tangent, dS/dT and its trial history. It never sees nodes, shapes or B matrices.
///
/// Strain and stress are Voigt vectors with engineering shears (gamma = 2 E_ij) in the output
/// order of the kinematic class:
///   ThreeD        11 22 33 12 13 23   (3 normal components)
///   PlaneStrain   11 22 33 12         (eps33 = 0 kinematically; sigma33 from the law)
///   Axisymmetric  11 22 33 12         (r, z, hoop, rz)
///   PlaneStress   11 22 12            (sigma33 = 0: the law condenses the thickness direction)
///   Beam          11 12 13            (a fibre of a beam section: sigma22 = sigma33 = sigma23 = 0,
///                                      the law condenses the lateral directions)
/// Small strain: the strain is sym(grad u) and the stress Cauchy's. NLGEOM (total Lagrangian): the
/// strain is Green-Lagrange's and the stress the second Piola-Kirchhoff stress, so an elastic law
/// is St. Venant-Kirchhoff.
///
/// History: a law has n_state() doubles per point; the element keeps n_points x n_state in the
/// model's flat committed/trial arrays (ElementInput::state_start / state), which commit, revert
/// and restart handle. update() always starts from the committed history and the whole strain, so
/// it may be called any number of times in one increment.
///
/// A law is chosen from the material by make_solid_law() (solid_law.cpp): the registrations are
/// asked newest first and the first that accepts the material makes the law. The built-in list is
/// in solid_law.cpp; a test or a plugin registers its own with register_solid_law().
#include "model/material.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>

namespace gapfem {

/// Kinematic class of a material point: a continuum element's, a shell's section point (plane
/// stress) or a beam section's fibre.
enum class Kinematics : std::uint8_t { ThreeD, PlaneStress, PlaneStrain, Axisymmetric, Beam };

/// Voigt components of a kinematic class (3, 4 or 6).
constexpr int voigt_size(Kinematics k) {
  return k == Kinematics::ThreeD ? 6
                                 : (k == Kinematics::PlaneStress || k == Kinematics::Beam ? 3 : 4);
}
/// Normal components among them (1 for a beam fibre, 2 for plane stress, else 3).
constexpr int voigt_normals(Kinematics k) {
  return k == Kinematics::Beam ? 1 : (k == Kinematics::PlaneStress ? 2 : 3);
}

/// Isotropic elastic constants in the form the kernels use: `lambda` is the effective constant of
/// the kinematics (lambda* = 2 lambda mu / (lambda + 2 mu) for plane stress, 2 mu nu for a beam
/// fibre, so that lambda + 2 mu = E), `lambda3` the 3-D value, `mu` the shear modulus.
struct IsotropicModuli {
  double lambda = 0.0;
  double lambda3 = 0.0;
  double mu = 0.0;

  /// D * B for a strain-displacement matrix B (rows = Voigt components, `n_normal` normals first).
  template <class MatB, class MatDB>
  void apply(int n_normal, const MatB& B, MatDB& DB) const {
    auto tr = B.row(0).eval();
    for (int c = 1; c < n_normal; ++c) tr += B.row(c);
    for (int c = 0; c < n_normal; ++c) DB.row(c) = 2.0 * mu * B.row(c) + lambda * tr;
    for (int c = n_normal; c < B.rows(); ++c) DB.row(c) = mu * B.row(c);
  }
};

/// What a law is given at one point.
struct MaterialPointInput {
  std::span<const double> strain;      ///< n Voigt components (small strain or Green-Lagrange)
  std::span<const double> state_start; ///< committed history (n_state)
  double temperature = 0.0;            ///< at the point now (the initial one when !thermal)
  double initial_temperature = 0.0;    ///< the thermal-strain reference
  bool thermal = false;                ///< a temperature field acts: thermal strain
  double dt = 0.0;                     ///< time increment
  bool nlgeom = false;
  bool recovery = false; ///< fill MaterialPointOutput's energy and thickness strain too
};

/// What a law returns at one point. The caller sizes the spans; empty ones are not wanted.
struct MaterialPointOutput {
  std::span<double> stress; ///< n components, always written
  std::span<double> state;  ///< trial history (n_state), always written
  /// consistent tangent dS/dE, n x n row-major; written when non-empty and `isotropic` is false
  std::span<double> tangent;
  std::span<double> dstress_dT; ///< dS/dT at fixed strain (n); written when non-empty
  /// the tangent is isotropic elasticity with `moduli` (the kernels' fast path); the law then
  /// leaves `tangent` unwritten
  bool isotropic = false;
  IsotropicModuli moduli;
  double energy = 0.0;           ///< recovery: stored (elastic) energy per unit volume
  double thickness_strain = 0.0; ///< recovery, plane stress: E33 (for the Cauchy stress)
};

/// One material point of a solid. Immutable after construction; called concurrently.
class SolidLaw {
 public:
  virtual ~SolidLaw() = default;
  /// History doubles per point.
  virtual int n_state() const { return 0; }
  /// The history of a virgin point (written once before the first step).
  virtual void initialize(std::span<double> state) const {}
  /// Does the response depend on temperature without a temperature field (temperature-dependent
  /// constants read at the initial temperature)? The kernels then interpolate it at every point.
  virtual bool temperature_dependent() const { return false; }
  /// Is the law isotropic linear (thermo-)elasticity without history, its stress C(E(T), nu(T))
  /// (strain - thermal strain)? Shell and beam sections then integrate it in closed form through
  /// the thickness or over the section (today's pre-integrated sections) instead of calling it at
  /// their section points. Only the built-in elastic law says yes.
  virtual bool linear_isotropic_elastic() const { return false; }
  /// Stress, tangent, dS/dT and trial history from the strain and the committed history.
  virtual void update(const MaterialPointInput& in, MaterialPointOutput& out) const = 0;
  /// The elastic (initial) moduli at temperature T and, with `dT`, their derivatives: what
  /// hourglass control and other penalty-like terms scale with.
  virtual IsotropicModuli elastic_moduli(double T, IsotropicModuli* dT = nullptr) const = 0;
};

/// Makes a law for a material and a kinematic class (InputError when the material lacks data).
using SolidLawFactory =
    std::function<std::unique_ptr<SolidLaw>(const Material& material, Kinematics kinematics)>;
/// Does a law apply to this material?
using SolidLawPredicate = std::function<bool(const Material& material)>;

/// Add a law to the registry: it is chosen for every material `applies` accepts, before the laws
/// registered earlier. Returns true (for `static const bool registered = register_solid_law(...)`).
bool register_solid_law(std::string name, SolidLawPredicate applies, SolidLawFactory make);

/// The law of a material for a kinematic class: the newest registration that applies.
std::shared_ptr<const SolidLaw> make_solid_law(const Material& material, Kinematics kinematics);

} // namespace gapfem
