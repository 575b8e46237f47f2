#pragma once
// Minimal in-memory models of one gap element, and the element as a kernel probe
// (unit/elements/kernel_harness.hpp evaluates and checks it).
#include "elements/element_kernel.hpp"
#include "elements/gap/mechanical_gap.hpp"
#include "model/model.hpp"
#include "unit/elements/kernel_harness.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <vector>

namespace gapfem::test {

/// A model with two nodes and one gap element of `type` using `section`.
inline Model two_node_gap_model(ElementType type, const Vec3& X1, const Vec3& X2,
                                GapSection section, ModelSpace space = ModelSpace::ThreeD) {
  Model m;
  m.space = space;
  m.source_files = {"unit.inp"};
  m.mesh.node_labels = {1, 2};
  m.mesh.coords = {X1, X2};
  m.mesh.node_index = {{1, 0}, {2, 1}};
  m.mesh.elem_labels = {10};
  m.mesh.elem_types = {type};
  m.mesh.conn = {0, 1};
  m.mesh.conn_offset = {0, 2};
  m.mesh.elem_src = {SourceRef{0, 5}};
  m.mesh.elem_index = {{10, 0}};
  section.elset = "G";
  m.gap_sections = {section};
  m.element_property = {PropertyRef{PropertyRef::Kind::Gap, 0}};
  m.initial_temperature = {0.0, 0.0};
  return m;
}

/// Element 0 of a gap model as a kernel probe (unit/elements/kernel_harness.hpp), with a time
/// increment of 1 (slip rates). The model must outlive the probe.
inline KernelProbe gap_probe(const Model& m, const KernelOptions& options = {}) {
  KernelProbe p = KernelProbe::of(m, 0, options);
  p.ctx.dt = 1.0;
  return p;
}

/// The gap's output record at the probe's trial state.
inline GapRecord gap_record(KernelProbe& p) {
  return p.recover().gap.value();
}

/// Commits a closed gap with status `st` (the trial history with it).
inline void commit_status(KernelProbe& p, ContactStatus st) {
  p.state[GapStateLayout::status] = static_cast<double>(st);
  p.state0[GapStateLayout::status] = static_cast<double>(st);
}

} // namespace gapfem::test
