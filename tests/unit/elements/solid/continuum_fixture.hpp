#pragma once
// Helpers for the continuum element unit tests: a one-element model and its element as a kernel
// probe built by the real factory (unit/elements/kernel_harness.hpp evaluates and checks it).
#include "elements/element_kernel.hpp"
#include "fe/shape_functions.hpp"
#include "model/model.hpp"
#include "unit/elements/kernel_harness.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace gapfem::test {

/// Material data of the tests (steel-like, in N, mm).
struct TestMaterial {
  double E = 200000.0;
  double nu = 0.3;
  double alpha = 1.2e-5;    ///< 0: no *EXPANSION
  double density = 7.85e-9; ///< 0: no *DENSITY
};

inline Shape shape_of(ElementType t) {
  return element_info(t).cell.value_or(Shape::Quad4);
}
/// Every stress/displacement continuum type (the coupled ones have their own tests).
inline std::vector<ElementType> continuum_types() {
  std::vector<ElementType> out;
  for (const ElementTypeInfo& info : all_element_types())
    if (info.family == ElementFamily::Continuum && !info.temperature) out.push_back(info.type);
  return out;
}
inline bool is_3d(ElementType t) {
  return shape_dim(shape_of(t)) == 3;
}
inline int dofs_per_node(ElementType t) {
  return is_3d(t) ? 3 : 2;
}

/// A valid, mildly distorted element of each type with edge lengths about 1 (2-D elements sit at
/// x in [1, 2.2] so that axisymmetric radii are positive). Midside nodes sit at the middle of the
/// (distorted) corners; those of Quad8, Wedge15 and Hex20 are moved off the straight edge as well
/// (curved edges), those of Tri6 and Tet10 are not.
inline std::vector<Vec3> reference_nodes(ElementType t, bool distorted = true) {
  const Shape s = shape_of(t);
  std::vector<Vec3> X;
  const auto xi = shape_node_coords(s);
  const double d = distorted ? 1.0 : 0.0;
  const bool box = s == Shape::Hex8 || s == Shape::Quad4 || s == Shape::Hex20 || s == Shape::Quad8;
  for (std::size_t a = 0; a < xi.size(); ++a) {
    Vec3 p{};
    if (box) {
      for (int i = 0; i < 3; ++i) p[i] = 0.5 * xi[a][i];
    } else {
      p = xi[a];
    }
    // Deterministic distortion, small enough to keep the Jacobian positive.
    p[0] += d * 0.07 * std::sin(1.0 + 3.0 * a);
    p[1] += d * 0.05 * std::cos(2.0 + 5.0 * a);
    if (shape_dim(s) == 3)
      p[2] += d * 0.06 * std::sin(3.0 + 7.0 * a);
    else
      p[2] = 0.0;
    if (shape_dim(s) == 2) p[0] += 1.5;
    X.push_back(p);
  }
  if (shape_quadratic(s)) {
    const int corners = s == Shape::Tri6 ? 3 : s == Shape::Wedge15 ? 6 : s == Shape::Hex20 ? 8 : 4;
    const bool curve = s == Shape::Quad8 || s == Shape::Wedge15 || s == Shape::Hex20;
    for (std::size_t a = static_cast<std::size_t>(corners); a < xi.size(); ++a)
      for (int i = 0; i < corners; ++i)
        for (int j = i + 1; j < corners; ++j) {
          bool mid = true;
          for (int k = 0; k < 3; ++k) mid &= 0.5 * (xi[i][k] + xi[j][k]) == xi[a][k];
          if (!mid) continue;
          for (int k = 0; k < 3; ++k) X[a][k] = 0.5 * (X[i][k] + X[j][k]);
          if (curve && distorted) {
            X[a][0] += 0.03 * std::sin(4.0 + 2.0 * a);
            X[a][1] += 0.03 * std::cos(1.0 + 3.0 * a);
            if (shape_dim(s) == 3) X[a][2] += 0.03 * std::sin(2.0 + 5.0 * a);
          }
        }
  }
  return X;
}

/// One-element model: nodes 1..n, element 1 of type t, one material and solid section.
inline std::shared_ptr<Model> one_element_model(ElementType t, const std::vector<Vec3>& X,
                                                const TestMaterial& m = {},
                                                double thickness = 1.0) {
  auto model = std::make_shared<Model>();
  add_lone_element(*model, t, X);
  model->space = is_3d(t)
                     ? ModelSpace::ThreeD
                     : (element_info(t).plane == PlaneKind::Axisymmetric ? ModelSpace::Axisymmetric
                                                                         : ModelSpace::Planar);
  Material mat;
  mat.name = "STEEL";
  mat.elastic.n_values = 2;
  mat.elastic.values = {m.E, m.nu};
  if (m.alpha != 0.0) {
    mat.expansion.n_values = 1;
    mat.expansion.values = {m.alpha};
  }
  if (m.density != 0.0) {
    mat.density.n_values = 1;
    mat.density.values = {m.density};
  }
  model->materials.push_back(mat);
  SolidSection sec;
  sec.elset = "ALL";
  sec.material = 0;
  sec.thickness = thickness;
  model->solid_sections.push_back(sec);
  model->element_property.push_back({PropertyRef::Kind::Solid, 0});
  model->initial_temperature.assign(X.size(), 0.0);
  return model;
}

/// A one-element model of type t as a kernel probe (unit/elements/kernel_harness.hpp), with the
/// fields the continuum tests set.
struct ElementHarness : KernelProbe {
  ElementHarness(ElementType t, std::vector<Vec3> coords, const TestMaterial& m = {},
                 double thickness = 1.0)
      : KernelProbe(KernelProbe::of(
            std::shared_ptr<const Model>(one_element_model(t, coords, m, thickness)))) {}

  /// Displacement field u(X) = A X + c at the nodes (2-D: upper-left 2x2 of A).
  void set_linear_field(const double A[3][3], const Vec3& c = {0, 0, 0}) {
    const int nd = dofs_per_node(kernel->type());
    for (std::size_t a = 0; a < X.size(); ++a)
      for (int i = 0; i < nd; ++i) {
        double v = c[i];
        for (int j = 0; j < nd; ++j) v += A[i][j] * X[a][j];
        u[a * nd + i] = v;
      }
  }
  void set_temperature(double T_now, double T_init) {
    T.assign(X.size(), T_now);
    Ti.assign(X.size(), T_init);
  }
};

/// Seeded random displacements of size `scale` (relative to the element size ~1).
inline void random_displacements(std::vector<double>& u, double scale, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> dist(-1.0, 1.0);
  for (double& v : u) v = scale * dist(gen);
}

} // namespace gapfem::test
