#pragma once
// A small hand-built model and synthetic frames for the result-writer tests.
//
// Model: a unit cube C3D8 (element label 7) with corner nodes labelled 10, 20,
// ..., 80, and a GAPUNI (element label 3) from the cube's node 50 to an extra
// node labelled 5 (defined last, so label order differs from definition order).
// Sets: NSET TOP = nodes 50 60 70 80, ELSET ALL, ELSET GAPS. One static step
// (period 1) with
//   *NODE PRINT, NSET=TOP, TOTALS=YES : U, RF      (request 0)
//   *NODE PRINT (all nodes)           : U          (request 1)
//   *EL PRINT, ELSET=ALL              : S, E       (request 0, integration
//   points) *EL PRINT, ELSET=GAPS, POSITION=CENTROIDAL : S (request 1)
// Frame 1 (increment 1, step time 0.5): node request 0 and element request 1
// due; only the gap's element output is present. Frame 2 (increment 2, step
// time 1.0): last in step, everything due.
#include "model/model.hpp"
#include "results/results.hpp"

#include <array>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace gapfem::testing_output {

inline constexpr std::array<std::string_view, 6> kSNames = {"S11", "S22", "S33",
                                                            "S12", "S13", "S23"};
inline constexpr std::array<std::string_view, 6> kENames = {"E11", "E22", "E33",
                                                            "E12", "E13", "E23"};
inline constexpr std::array<std::string_view, 3> kGapSNames = {"S11", "S12", "S13"};
inline constexpr std::array<std::string_view, 3> kGapENames = {"E11", "E12", "E13"};

inline constexpr std::uint8_t kAllU =
    dof_bit(DofType::U1) | dof_bit(DofType::U2) | dof_bit(DofType::U3);

/// Node labels by NodeId.
inline const std::vector<Label> kNodeLabels = {10, 20, 30, 40, 50, 60, 70, 80, 5};

inline Model make_model() {
  Model m;
  m.heading = "Writer test: cube with a gap";
  m.job_name = "wt";
  m.source_files = {"wt.inp"};
  m.space = ModelSpace::ThreeD;
  const std::vector<Vec3> x = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},  {0, 0, 1},
                               {1, 0, 1}, {1, 1, 1}, {0, 1, 1}, {0, 0, 1.1}};
  for (std::size_t i = 0; i < x.size(); ++i) {
    m.mesh.node_labels.push_back(kNodeLabels[i]);
    m.mesh.coords.push_back(x[i]);
    m.mesh.node_index[kNodeLabels[i]] = static_cast<NodeId>(i);
  }
  auto add = [&](Label label, ElementType type, std::vector<NodeId> nodes) {
    m.mesh.elem_index[label] = m.mesh.n_elements();
    m.mesh.elem_labels.push_back(label);
    m.mesh.elem_types.push_back(type);
    m.mesh.conn.insert(m.mesh.conn.end(), nodes.begin(), nodes.end());
    m.mesh.conn_offset.push_back(static_cast<std::int64_t>(m.mesh.conn.size()));
    m.mesh.elem_src.push_back({0, 10 + m.mesh.n_elements()});
  };
  add(7, ElementType::C3D8, {0, 1, 2, 3, 4, 5, 6, 7});
  add(3, ElementType::GAPUNI, {4, 8});
  m.nsets["TOP"] = {4, 5, 6, 7};
  m.elsets["ALL"] = {0, 1};
  m.elsets["GAPS"] = {1};

  Step s;
  s.number = 1;
  s.name = "Load";
  s.procedure = Procedure::Static;
  s.inc.period = 1.0;
  s.inc.initial = 0.5;
  NodePrintRequest np0;
  np0.nset = "TOP";
  np0.nodes = m.nsets["TOP"];
  np0.vars = {NodeVar::U, NodeVar::RF};
  np0.totals = true;
  NodePrintRequest np1;
  np1.vars = {NodeVar::U};
  np1.frequency = 0;
  s.node_prints = {np0, np1};
  ElPrintRequest ep0;
  ep0.elset = "ALL";
  ep0.elements = m.elsets["ALL"];
  ep0.vars = {ElemVar::S, ElemVar::E};
  ElPrintRequest ep1;
  ep1.elset = "GAPS";
  ep1.elements = m.elsets["GAPS"];
  ep1.vars = {ElemVar::S};
  ep1.position = ElPosition::Centroidal;
  s.el_prints = {ep0, ep1};
  m.steps.push_back(s);
  return m;
}

/// Displacement of node `label` at load fraction `f` (distinct per node and
/// component).
inline Vec3 disp(Label label, double f) {
  return {1e-3 * label * f, -2e-3 * label * f, 5e-4 * label * f};
}

/// C3D8 stress at point p (0-based), component c: 10*(p+1) + c.
inline double c3d8_stress(int p, int c) {
  return 10.0 * (p + 1) + c;
}

inline ElementResult c3d8_result(double f) {
  ElementResult r;
  r.elem = 0;
  OutputBlock s{ElemVar::S, kSNames, 8, {}};
  OutputBlock e{ElemVar::E, kENames, 8, {}};
  for (int p = 0; p < 8; ++p)
    for (int c = 0; c < 6; ++c) {
      s.values.push_back(f * c3d8_stress(p, c));
      e.values.push_back(f * 1e-4 * (p + 1) * (c + 1));
    }
  r.data.blocks = {s, e};
  return r;
}

inline ElementResult gap_result(bool thermal = false) {
  ElementResult r;
  r.elem = 1;
  r.data.blocks.push_back(OutputBlock{ElemVar::S, kGapSNames, 1, {50.0, 2.0, 0.0}});
  r.data.blocks.push_back(OutputBlock{ElemVar::E, kGapENames, 1, {0.0, 1e-3, 0.0}});
  GapRecord g;
  g.status = ContactStatus::Stick;
  g.clearance = 0.0;
  g.normal_force = 50.0;
  g.pressure = 50.0;
  g.direction = {0, 0, -1};
  g.t1 = {1, 0, 0};
  g.t2 = {0, 1, 0};
  g.slip = {1e-3, 0.0};
  g.shear = {2.0, 0.0};
  g.friction_force = {2.0, 0.0};
  g.thermal = thermal;
  g.heat_flux = 12.5;
  g.heat_flow = 12.5;
  g.conductance = 4.0;
  r.data.gap = g;
  return r;
}

inline Frame make_frame(const Model& m, int increment, double step_time, bool last) {
  Frame fr;
  fr.step = 1;
  fr.increment = increment;
  fr.step_time = step_time;
  fr.total_time = step_time;
  fr.dt = 0.5;
  fr.last_in_step = last;
  const auto n = static_cast<std::size_t>(m.mesh.n_nodes());
  auto& r = fr.nodes;
  r.U.resize(n);
  r.UR.resize(n);
  r.RF.resize(n);
  r.RM.resize(n);
  r.CF.resize(n);
  r.CM.resize(n);
  r.NT.resize(n);
  r.RFL.resize(n);
  r.CFL.resize(n);
  r.dof_mask.assign(n, kAllU);
  r.any_displacement = true;
  for (std::size_t i = 0; i < n; ++i) r.U[i] = disp(m.mesh.node_labels[i], step_time);
  // Reactions at the four bottom nodes (10..40) balance a load of -100 * f in
  // direction 3.
  for (std::size_t i = 0; i < 4; ++i) r.RF[i] = {0.0, 0.0, 25.0 * step_time};
  r.CF[6] = {0.0, 0.0, -100.0 * step_time};
  fr.element_slot.assign(m.mesh.n_elements(), -1);
  if (last) fr.elements.push_back(c3d8_result(step_time));
  fr.elements.push_back(gap_result());
  for (std::size_t k = 0; k < fr.elements.size(); ++k)
    fr.element_slot[fr.elements[k].elem] = static_cast<std::int32_t>(k);
  fr.node_print_due = {true, last};
  fr.el_print_due = {last, true};
  fr.field_due = true;
  return fr;
}

inline StepSummary make_summary() {
  StepSummary s;
  s.step = 1;
  s.name = "Load";
  s.procedure = "STATIC";
  s.increments = 2;
  s.attempts = 3;
  s.iterations = 7;
  auto& c = s.checks;
  c.n_gaps = 1;
  c.n_stick = 1;
  c.max_penetration = 2.5e-7;
  c.max_penetration_elem = 3;
  c.reaction_sum = {0.0, 0.0, 100.0};
  c.applied_sum = {0.0, 0.0, -100.0};
  c.equilibrium_error = 1e-9;
  c.force_scale = 100.0;
  c.relative_equilibrium = 1e-11; // equilibrium_error / force_scale
  return s;
}

inline RunSummary make_run() {
  RunSummary r;
  r.wall_seconds = 1.25;
  r.stats.increments = 2;
  r.stats.attempts = 3;
  r.stats.iterations = 7;
  r.stats.factorizations = 7;
  r.warnings = {"*GAP: area not given; S11 is a force"};
  return r;
}

inline IncrementInfo inc_info(int increment, int attempt, bool converged, double step_time) {
  IncrementInfo i;
  i.step = 1;
  i.increment = increment;
  i.attempts = attempt;
  i.iterations = converged ? 3 : 8;
  i.severe_discontinuities = 1;
  i.step_time = step_time;
  i.total_time = step_time;
  i.dt = 0.5;
  i.converged = converged;
  return i;
}

/// A planar model: one CPS4 (label 1) on nodes 1-4 and a T2D2-like extra node 9 carrying a
/// rotation (to test UR in 2-D); one static step printing U and UR for all nodes.
inline Model make_planar_model() {
  Model m;
  m.space = ModelSpace::Planar;
  m.job_name = "p";
  const std::vector<Label> labels = {1, 2, 3, 4, 9};
  for (std::size_t i = 0; i < labels.size(); ++i) {
    m.mesh.node_labels.push_back(labels[i]);
    m.mesh.coords.push_back({double(i % 2), double(i / 2), 0.0});
    m.mesh.node_index[labels[i]] = static_cast<NodeId>(i);
  }
  m.mesh.elem_labels = {1};
  m.mesh.elem_types = {ElementType::CPS4};
  m.mesh.conn = {0, 1, 3, 2};
  m.mesh.conn_offset = {0, 4};
  m.mesh.elem_src = {{0, 1}};
  m.mesh.elem_index[1] = 0;
  Step s;
  s.number = 1;
  NodePrintRequest np;
  np.vars = {NodeVar::U, NodeVar::UR};
  s.node_prints = {np};
  m.steps.push_back(s);
  return m;
}

/// The last frame of the planar model: U = (label, 2*label), node 9 also has UR3 = 0.01.
inline Frame make_planar_frame(const Model& m) {
  Frame fr;
  fr.step = 1;
  fr.increment = 1;
  fr.step_time = fr.total_time = 1.0;
  fr.last_in_step = true;
  const auto n = static_cast<std::size_t>(m.mesh.n_nodes());
  fr.nodes.U.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double l = static_cast<double>(m.mesh.node_labels[i]);
    fr.nodes.U[i] = {l, 2.0 * l, 0.0};
  }
  fr.nodes.RF.assign(n, Vec3{});
  fr.nodes.UR.assign(n, Vec3{});
  fr.nodes.RM.assign(n, Vec3{});
  fr.nodes.UR[4] = {0.0, 0.0, 0.01};
  fr.nodes.dof_mask.assign(n, dof_bit(DofType::U1) | dof_bit(DofType::U2));
  fr.nodes.dof_mask[4] |= dof_bit(DofType::UR3);
  fr.nodes.any_displacement = true;
  fr.nodes.any_rotation = true;
  fr.element_slot = {-1};
  fr.node_print_due = {true};
  return fr;
}

/// A fresh, empty directory under the test temp dir, named after the running
/// test.
inline std::filesystem::path fresh_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  auto dir = std::filesystem::path(::testing::TempDir()) / "gapfem_output" /
             (std::string(info->test_suite_name()) + "_" + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline std::vector<std::string> read_lines(const std::filesystem::path& p) {
  std::vector<std::string> lines;
  std::ifstream in(p);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// Drive one writer through the standard two-frame run.
inline void run_standard(ResultWriter& w, const Model& m) {
  w.begin(m);
  w.begin_step(m, 0);
  w.increment(inc_info(1, 1, false, 0.5));
  w.increment(inc_info(1, 2, true, 0.5));
  w.frame(m, 0, make_frame(m, 1, 0.5, false));
  w.increment(inc_info(2, 1, true, 1.0));
  w.frame(m, 0, make_frame(m, 2, 1.0, true));
  w.end_step(m, 0, make_summary());
  w.end(m, make_run());
}

} // namespace gapfem::testing_output
