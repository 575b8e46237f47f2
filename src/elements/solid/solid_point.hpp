#pragma once
/// @file solid_point.hpp
/// The point loop every continuum kernel shares (continuum_kernel.hpp, reduced_kernel.hpp,
/// incompatible_kernel.hpp and, through them, coupled_continuum.hpp): at each integration point
/// the kernel forms its kinematics (B and the strain E, modified for B-bar or enriched by
/// incompatible modes) and then, here,
///   1. the point's temperature            point_temperature()
///   2. the law's update                   update_point(): stress S, tangent, dS/dT, trial history
///   3. r += dV B^T S, K += dV B^T D B     add_point()
/// so a law (elements/material/solid_law.hpp) goes into every kernel at once. The point's history
/// is slice q of the element's: n_state() = points x the law's n_state.
///
/// Fast paths: a law whose tangent is isotropic elasticity says so (MaterialPointOutput::isotropic)
/// and D B is formed from lambda and mu row by row; any other tangent is a fixed-size Voigt matrix
/// and D B one Eigen product. The built-in elastic law's stress is called inline, not through the
/// virtual update() (SolidLawHandle), when only stress and tangent are asked. Nothing here
/// allocates.
#include "common/error.hpp"
#include "elements/element_kernel.hpp"
#include "elements/material/isotropic_elastic.hpp"
#include "elements/material/solid_law.hpp"

#include <Eigen/Dense>
#include <memory>
#include <span>

namespace gapfem {

/// A kernel's handle on its law, with what the point loop asks of it at every point cached.
class SolidLawHandle {
 public:
  /// The law of `material` for the kinematics (make_solid_law).
  SolidLawHandle(const Material& material, Kinematics kinematics)
      : _law(make_solid_law(material, kinematics)), _n_state(_law->n_state()),
        _temperature_dependent(_law->temperature_dependent()),
        _elastic(dynamic_cast<const IsotropicElasticLaw*>(_law.get())) {}

  const SolidLaw& operator*() const { return *_law; }
  const SolidLaw* operator->() const { return _law.get(); }
  int n_state() const { return _n_state; }
  bool temperature_dependent() const { return _temperature_dependent; }
  /// The built-in elastic law, or nullptr.
  const IsotropicElasticLaw* elastic() const { return _elastic; }

 private:
  std::shared_ptr<const SolidLaw> _law;
  int _n_state = 0;
  bool _temperature_dependent = false;
  const IsotropicElasticLaw* _elastic = nullptr;
};

/// The temperature at a point: now (the initial one without a temperature field) and initial.
struct PointTemperature {
  double T = 0.0;
  double Ti = 0.0;
  bool thermal = false; ///< a temperature field acts
};

/// The temperatures at a point from the nodal ones with weights w(a) (the shape functions, or the
/// element means of the reduced elements), a = 0 .. n - 1. Without a temperature field they are
/// interpolated only when the law needs them (`needed`).
template <class Weights>
PointTemperature point_temperature(const ElementInput& in, const Weights& w, int n, bool needed) {
  PointTemperature t;
  t.thermal = !in.temperature.empty();
  if (t.thermal || needed) {
    for (int a = 0; a < n; ++a) {
      if (t.thermal) t.T += w(a) * in.temperature[a];
      if (!in.initial_temperature.empty()) t.Ti += w(a) * in.initial_temperature[a];
    }
    if (!t.thermal) t.T = t.Ti;
  }
  return t;
}

/// The law's answer at one point as a kernel keeps it until it assembles.
template <int NS>
struct PointLaw {
  static constexpr int kNormals = NS == 3 ? 2 : 3; ///< plane stress has 3 components, 2 normal
  using MatD = Eigen::Matrix<double, NS, NS, Eigen::RowMajor>;
  bool isotropic = true;
  IsotropicModuli moduli; ///< the tangent when isotropic
  /// the tangent dS/dE otherwise, in storage the kernel keeps apart from its hot per-point data
  /// (an isotropic law never touches it)
  MatD* D = nullptr;
  double energy = 0.0;           ///< recovery: energy density
  double thickness_strain = 0.0; ///< recovery, plane stress: E33

  /// DB = D * B.
  template <class MatB, class MatDB>
  void apply(const MatB& B, MatDB& DB) const {
    if (isotropic)
      moduli.apply(kNormals, B, DB);
    else
      DB.noalias() = *D * B;
  }
};

/// What a kernel asks of the law besides stress and tangent.
struct PointRequest {
  bool recovery = false;   ///< energy density and thickness strain (recover())
  bool dstress_dT = false; ///< dS/dT (coupled elements' temperature tangent)
};

/// The law's update at point q of an element: strain E, temperature t, the committed history of
/// the point (slice q of in.state_start) and its trial history written into slice q of `trial`
/// (in.state in evaluate(); a scratch copy in recover(), which must not write history).
template <int NS>
void update_point(const SolidLawHandle& law, const ElementInput& in, int q, std::span<double> trial,
                  const PointTemperature& t, const Eigen::Matrix<double, NS, 1>& E,
                  Eigen::Matrix<double, NS, 1>& S, PointLaw<NS>& pl, PointRequest request = {},
                  Eigen::Matrix<double, NS, 1>* dS = nullptr) {
  if (law.elastic() && !request.recovery && !request.dstress_dT) {
    law.elastic()->stress<NS>(E.data(), t.T, t.Ti, t.thermal, S.data(), pl.moduli);
    pl.isotropic = true;
    return;
  }
  MaterialPointInput mi;
  mi.strain = {E.data(), static_cast<std::size_t>(NS)};
  mi.temperature = t.T;
  mi.initial_temperature = t.Ti;
  mi.thermal = t.thermal;
  mi.dt = in.ctx ? in.ctx->dt : 0.0;
  mi.nlgeom = in.ctx && in.ctx->nlgeom;
  mi.recovery = request.recovery;
  MaterialPointOutput mo;
  mo.stress = {S.data(), static_cast<std::size_t>(NS)};
  FE_CHECK(pl.D, "solid point: no storage for the law's tangent");
  mo.tangent = {pl.D->data(), static_cast<std::size_t>(NS * NS)};
  if (request.dstress_dT && dS) mo.dstress_dT = {dS->data(), static_cast<std::size_t>(NS)};
  if (const auto ns = static_cast<std::size_t>(law.n_state()); ns > 0) {
    const std::size_t at = static_cast<std::size_t>(q) * ns;
    FE_CHECK(in.state_start.size() >= at + ns && trial.size() >= at + ns,
             "solid law history: the element's state arrays are too short");
    mi.state_start = in.state_start.subspan(at, ns);
    mo.state = trial.subspan(at, ns);
  }
  law->update(mi, mo);
  pl.isotropic = mo.isotropic;
  pl.moduli = mo.moduli;
  pl.energy = mo.energy;
  pl.thickness_strain = mo.thickness_strain;
}

/// One point's share: r += dV B^T S and, with K, K += dV B^T D B.
template <int NS, class MatB, class VecS, class VecR, class MatK>
void add_point(const PointLaw<NS>& pl, const MatB& B, const VecS& S, double dV, VecR& r, MatK* K) {
  r.noalias() += dV * (B.transpose() * S);
  if (!K) return;
  typename MatB::PlainObject DB;
  pl.apply(B, DB);
  K->noalias() += dV * B.transpose().lazyProduct(DB);
}

/// The initial history of every point of an element (ElementKernel::initialize).
inline void initialize_points(const SolidLawHandle& law, int n_points, std::span<double> state) {
  const auto ns = static_cast<std::size_t>(law.n_state());
  if (ns == 0) return;
  for (int q = 0; q < n_points; ++q) law->initialize(state.subspan(q * ns, ns));
}

} // namespace gapfem
