#pragma once
// Helpers for the heat-transfer and coupled element unit tests: a one-element model with thermal
// (and elastic) material data, its element as a kernel probe built by the real factory
// (unit/elements/kernel_harness.hpp), and the position of the temperature DOFs.
#include "elements/element_kernel.hpp"
#include "fe/shape_functions.hpp"
#include "model/model.hpp"
#include "unit/elements/solid/continuum_fixture.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <random>
#include <vector>

namespace gapfem::test::heat {

/// Thermal and mechanical data of the tests (steel-like in m, s, K, N).
struct Props {
  double k = 45.0;      ///< conductivity
  double rho = 7800.0;  ///< density
  double c = 460.0;     ///< specific heat
  bool varying = false; ///< temperature tables for k, rho, c (and E, alpha when elastic)
  double E = 2.0e11;
  double nu = 0.3;
  double alpha = 1.2e-5; ///< 0: no *EXPANSION
  bool capacity = true;  ///< *DENSITY and *SPECIFIC HEAT given
};

inline Shape shape_of(ElementType t) {
  return element_info(t).cell.value_or(Shape::Line2);
}
/// Every heat-transfer (DC*) type and every coupled temperature-displacement type.
inline std::vector<ElementType> heat_types(bool coupled) {
  std::vector<ElementType> out;
  for (const ElementTypeInfo& info : all_element_types())
    if (info.temperature && info.family != ElementFamily::Gap &&
        info.family != ElementFamily::Shell && info.displacement == coupled) // shells: own tests
      out.push_back(info.type);
  return out;
}
inline std::vector<ElementType> all_heat_types() {
  auto v = heat_types(false);
  const auto c = heat_types(true);
  v.insert(v.end(), c.begin(), c.end());
  return v;
}
inline ModelSpace space_of(ElementType t) {
  switch (element_info(t).space) {
  case SpaceRequirement::Planar:
    return ModelSpace::Planar;
  case SpaceRequirement::Axisymmetric:
    return ModelSpace::Axisymmetric;
  default:
    return ModelSpace::ThreeD;
  }
}

/// A valid, mildly distorted element of edge length about 1 (2-D elements at x in [1, 2.2] so
/// that axisymmetric radii are positive; links along a skew axis).
inline std::vector<Vec3> nodes_of(ElementType t, bool distorted = true) {
  const Shape s = shape_of(t);
  if (s == Shape::Line2) {
    if (t == ElementType::T2D2T) return {{0.1, 0.2, 0.0}, {0.9, 0.7, 0.0}};
    return {{0.1, 0.2, 0.3}, {0.9, 0.7, -0.2}};
  }
  return gapfem::test::reference_nodes(t, distorted); // continuum_fixture.hpp
}

/// Single-valued table; with `varying` two rows at T = 0 and 200 (v and `factor` v).
inline PropertyTable table(double v, bool varying, double factor) {
  PropertyTable t;
  t.n_values = 1;
  if (!varying) {
    t.values = {v};
    return t;
  }
  t.values = {v, factor * v};
  t.keys = {0.0, 200.0};
  return t;
}

/// One-element model (nodes 1..n, element 1) with material "M" and a solid section.
inline std::shared_ptr<Model> model_of(ElementType t, const std::vector<Vec3>& X, const Props& p,
                                       double section = 1.0, double initial_temperature = 0.0) {
  auto model = std::make_shared<Model>();
  add_lone_element(*model, t, X);
  model->space = space_of(t);
  Material m;
  m.name = "M";
  m.conductivity = table(p.k, p.varying, 1.5);
  if (p.capacity) {
    m.density = table(p.rho, p.varying, 0.9);
    m.specific_heat = table(p.c, p.varying, 1.3);
  }
  if (element_info(t).displacement) {
    m.elastic.n_values = 2;
    if (p.varying) {
      m.elastic.values = {p.E, p.nu, 0.7 * p.E, 0.32};
      m.elastic.keys = {0.0, 200.0};
    } else {
      m.elastic.values = {p.E, p.nu};
    }
    if (p.alpha != 0.0) m.expansion = table(p.alpha, p.varying, 1.4);
  }
  model->materials.push_back(m);
  SolidSection sec;
  sec.elset = "ALL";
  sec.material = 0;
  sec.thickness = section;
  model->solid_sections.push_back(sec);
  model->element_property.push_back({PropertyRef::Kind::Solid, 0});
  model->initial_temperature.assign(X.size(), initial_temperature);
  return model;
}

/// A one-element model of type t as a kernel probe (unit/elements/kernel_harness.hpp); u holds
/// displacements and temperatures.
struct Harness : KernelProbe {
  Harness(ElementType t, std::vector<Vec3> coords, const Props& p = {}, double section = 1.0,
          double initial_temperature = 0.0)
      : KernelProbe(KernelProbe::of(
            std::shared_ptr<const Model>(model_of(t, coords, p, section, initial_temperature)))) {}
  int per_node() const { return n() / static_cast<int>(X.size()); }
  /// Local index of the temperature DOF of node a.
  int nt(int a) const { return a * per_node() + per_node() - 1; }
  bool is_nt(int i) const { return i % per_node() == per_node() - 1; }

  void set_transient(double dt) {
    ctx.procedure = Procedure::HeatTransfer;
    ctx.transient = true;
    ctx.dt = dt;
  }
  using KernelProbe::load;
  /// Equivalent nodal load of one distributed load and -d f/du.
  void load(DistLoadKind kind, int face, double magnitude, double sink, std::vector<double>& f,
            std::vector<double>* K = nullptr) {
    f = load(distributed_load(kind, face, magnitude, sink), magnitude, sink, K);
  }
  double stored_heat() { return kernel->stored_heat(input()); }
  /// Nodal temperatures T(X) = T_ref + g . X (u and u0 alike unless `now_only`).
  void set_linear_temperature(double T_ref, const Vec3& g, bool now_only = false) {
    for (std::size_t a = 0; a < X.size(); ++a) {
      const double v = T_ref + g[0] * X[a][0] + g[1] * X[a][1] + g[2] * X[a][2];
      u[nt(static_cast<int>(a))] = v;
      if (!now_only) u0[nt(static_cast<int>(a))] = v;
    }
  }
};

/// Seeded random temperatures in [lo, hi] at the NT DOFs and displacements of size `disp`.
inline void randomize(Harness& h, double lo, double hi, double disp, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> t(lo, hi), d(-disp, disp);
  for (int i = 0; i < h.n(); ++i) {
    h.u[i] = h.is_nt(i) ? t(gen) : d(gen);
    h.u0[i] = h.is_nt(i) ? t(gen) : d(gen);
  }
}

} // namespace gapfem::test::heat
