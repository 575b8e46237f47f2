#pragma once
// Helpers for the structural kernel tests: a small in-memory Model and its elements as kernel
// probes (unit/elements/kernel_harness.hpp evaluates and checks them).
#include "elements/element_kernel.hpp"
#include "model/model.hpp"
#include "unit/elements/kernel_harness.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <optional>
#include <vector>

namespace gapfem::structural_test {

using test::expect_fd_load_stiffness;
using test::expect_fd_tangent;
using test::expect_revert_is_exact;
using test::expect_rigid_body_invariance;
using test::FdOptions;
using test::KernelProbe;
using test::KernelResult;
using test::RigidBodyOptions;

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
  /// Element e alone on its own kernel (the model must outlive the probe).
  test::KernelProbe probe(ElemId e) const { return test::KernelProbe::of(model, e); }
  /// Element e evaluated by `k` (a kernel of its block that the caller keeps).
  test::KernelProbe probe(ElemId e, const ElementKernel& k) const {
    std::vector<Vec3> X;
    for (NodeId n : model.mesh.element_nodes(e)) X.push_back(model.mesh.coords[n]);
    test::KernelProbe p(k, std::move(X));
    p.ctx.space = model.space;
    p.ctx.model_size = model.model_size();
    return p;
  }
};

} // namespace gapfem::structural_test
