#pragma once
// Helpers for the structural kernel tests: a small in-memory Model, kernels from the real factory,
// one-element evaluation with caller-owned buffers, and a central-difference tangent check.
#include "elements/element_kernel.hpp"
#include "model/model.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <optional>
#include <vector>

namespace gapfem::structural_test {

/// A Model built by hand, one element at a time.
struct TestModel {
  Model model;

  NodeId add_node(const Vec3& x) {
    const auto id = model.mesh.n_nodes();
    model.mesh.node_labels.push_back(id + 1);
    model.mesh.coords.push_back(x);
    model.mesh.node_index[id + 1] = id;
    return id;
  }
  ElemId add_element(ElementType type, std::vector<NodeId> nodes, PropertyRef prop) {
    const auto id = model.mesh.n_elements();
    model.mesh.elem_labels.push_back(id + 1);
    model.mesh.elem_types.push_back(type);
    for (NodeId n : nodes) model.mesh.conn.push_back(n);
    model.mesh.conn_offset.push_back(static_cast<std::int64_t>(model.mesh.conn.size()));
    model.mesh.elem_src.push_back(SourceRef{0, 10 + id});
    model.mesh.elem_index[id + 1] = id;
    model.element_property.push_back(prop);
    if (model.source_files.empty()) model.source_files.push_back("test.inp");
    return id;
  }
  /// Isotropic elastic material; optional expansion coefficient and density.
  int add_material(double E, double nu, double alpha = 0.0, std::optional<double> rho = {}) {
    Material m;
    m.name = "MAT" + std::to_string(model.materials.size() + 1);
    m.loc = {"test.inp", 3, "*MATERIAL"};
    m.elastic.n_values = 2;
    m.elastic.values = {E, nu};
    if (alpha != 0.0) {
      m.expansion.n_values = 1;
      m.expansion.values = {alpha};
    }
    if (rho) {
      m.density.n_values = 1;
      m.density.values = {*rho};
    }
    model.materials.push_back(m);
    return static_cast<int>(model.materials.size()) - 1;
  }
  PropertyRef add_solid_section(int material, double area) {
    SolidSection s;
    s.elset = "TRUSS";
    s.material = material;
    s.thickness = area;
    s.thickness_given = true;
    s.loc = {"test.inp", 5, "*SOLID SECTION"};
    model.solid_sections.push_back(s);
    return {PropertyRef::Kind::Solid, static_cast<std::int32_t>(model.solid_sections.size() - 1)};
  }
  PropertyRef add_beam_section(int material, BeamSection::Shape shape, std::vector<double> dims,
                               std::optional<Vec3> n1 = {}) {
    BeamSection s;
    s.elset = "BEAM";
    s.material = material;
    s.shape = shape;
    s.dims = std::move(dims);
    if (n1) {
      s.n1 = *n1;
      s.n1_given = true;
    }
    s.loc = {"test.inp", 6, "*BEAM SECTION"};
    model.beam_sections.push_back(s);
    return {PropertyRef::Kind::Beam, static_cast<std::int32_t>(model.beam_sections.size() - 1)};
  }
  PropertyRef add_shell_section(int material, double thickness, double offset = 0.0) {
    ShellSection s;
    s.elset = "SHELL";
    s.material = material;
    s.thickness = thickness;
    s.offset = offset;
    s.loc = {"test.inp", 8, "*SHELL SECTION"};
    model.shell_sections.push_back(s);
    return {PropertyRef::Kind::Shell, static_cast<std::int32_t>(model.shell_sections.size() - 1)};
  }
  /// Linear spring; `k_rows` = (k, temperature) pairs (one pair: constant).
  PropertyRef add_spring(int dof1, int dof2, std::vector<std::pair<double, double>> k_rows) {
    SpringSection s;
    s.elset = "SPRINGS";
    s.dof1 = dof1;
    s.dof2 = dof2;
    s.stiffness.n_values = 1;
    for (auto [k, T] : k_rows) {
      s.stiffness.values.push_back(k);
      if (k_rows.size() > 1) s.stiffness.keys.push_back(T);
    }
    s.loc = {"test.inp", 7, "*SPRING"};
    model.spring_sections.push_back(s);
    return {PropertyRef::Kind::Spring, static_cast<std::int32_t>(model.spring_sections.size() - 1)};
  }

  /// Kernel for the block made of element e alone (through the real factory).
  std::unique_ptr<ElementKernel> kernel(ElemId e) const {
    const ElemId elems[1] = {e};
    return make_element_kernel(
        KernelContext{model, model.mesh.elem_types[e], model.element_property[e], {elems, 1}});
  }
};

/// Local data of one element with owned buffers; input() points into them.
struct LocalElement {
  std::vector<Vec3> X;
  std::vector<double> u, T, Ti;
  StepContext ctx;

  LocalElement(const TestModel& tm, ElemId e, int n_dofs) {
    for (NodeId n : tm.model.mesh.element_nodes(e)) X.push_back(tm.model.mesh.coords[n]);
    u.assign(static_cast<std::size_t>(n_dofs), 0.0);
    ctx.space = tm.model.space;
    ctx.model_size = tm.model.model_size();
  }
  ElementInput input() const {
    ElementInput in;
    in.label = EntityLabel{1};
    in.X = X;
    in.u = u;
    in.u_start = u;
    in.temperature = T;
    in.temperature_start = T;
    in.initial_temperature = Ti;
    in.ctx = &ctx;
    return in;
  }
};

/// Residual and row-major tangent of one evaluation.
struct Evaluation {
  std::size_t n = 0;
  std::vector<double> r, K;
  double k(std::size_t i, std::size_t j) const { return K[i * n + j]; }
};

inline Evaluation evaluate(const ElementKernel& kernel, const ElementInput& in) {
  const auto n = static_cast<std::size_t>(kernel.n_dofs());
  Evaluation ev;
  ev.n = n;
  ev.r.assign(n, 0.0);
  ev.K.assign(n * n, 0.0);
  ElementOutput out;
  out.residual = ev.r;
  out.tangent = ev.K;
  kernel.evaluate(in, out);
  return ev;
}

/// Central-difference check of the tangent at the state of `el`. Perturbation h (relative to
/// `length`) = cbrt(eps) * length gives a truncation error O(h^2) and a round-off error
/// O(eps/h) of the residual scale; the tolerance below is well above both for these smooth
/// elements and far below any sign or factor error.
inline void expect_tangent_matches_fd(const ElementKernel& kernel, LocalElement el, double length,
                                      double rel_tol = 1e-6) {
  const Evaluation ev = evaluate(kernel, el.input());
  const auto n = ev.r.size();
  const double h = 6e-6 * length; // ~ cbrt(2.2e-16) * length
  double kmax = 0.0;
  for (double v : ev.K) kmax = std::max(kmax, std::abs(v));
  ASSERT_GT(kmax, 0.0);
  for (std::size_t j = 0; j < n; ++j) {
    LocalElement plus = el, minus = el;
    plus.u[j] += h;
    minus.u[j] -= h;
    const Evaluation rp = evaluate(kernel, plus.input());
    const Evaluation rm = evaluate(kernel, minus.input());
    for (std::size_t i = 0; i < n; ++i) {
      const double fd = (rp.r[i] - rm.r[i]) / (2.0 * h);
      EXPECT_NEAR(ev.K[i * n + j], fd, rel_tol * kmax) << "K(" << i << "," << j << ")";
    }
  }
}

} // namespace gapfem::structural_test
