#pragma once
// Minimal in-memory models and a single-element driver for gap kernel unit tests.
#include "elements/element_kernel.hpp"
#include "model/model.hpp"

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

/// Evaluates one kernel on local data it owns.
struct SingleElement {
  std::unique_ptr<ElementKernel> kernel;
  std::vector<Vec3> X;
  std::vector<double> u, u0, state, state0, mult;
  StepContext ctx;
  double stiffness_hint = 0.0;
  std::vector<double> r, K, cval, ccomp, ccoef, ccol;
  bool has_columns = false;
  bool unsymmetric = false;
  std::vector<int> cslot;
  int n_constraints = 0;
  int status_changes = 0;
  int branch_changes = 0;
  double interference = 0.0;

  static inline const std::vector<ElemId> kFirst{0};
  explicit SingleElement(const Model& m, const KernelOptions& options = {})
      : SingleElement(
            m, make_element_kernel(KernelContext{m, m.mesh.elem_types[0], m.element_property[0],
                                                 kFirst, -1, options})) {}
  SingleElement(const Model& m, std::unique_ptr<ElementKernel> k) : kernel(std::move(k)) {
    X = m.mesh.coords;
    const int nd = kernel->n_dofs();
    u.assign(nd, 0.0);
    u0 = u;
    state.assign(kernel->n_state(), 0.0);
    mult.assign(kernel->n_multipliers(), 0.0);
    ctx.space = m.space;
    ctx.model_size = m.model_size();
    ctx.dt = 1.0;
    auto in = input();
    kernel->initialize(in);
    state0 = state;
  }
  ElementInput input() {
    ElementInput in;
    in.X = X;
    in.u = u;
    in.u_start = u0;
    in.state_start = state0;
    in.state = state;
    in.multipliers = mult;
    in.interference = interference;
    in.stiffness_hint = stiffness_hint;
    in.ctx = &ctx;
    return in;
  }
  void evaluate() {
    const auto nd = static_cast<std::size_t>(kernel->n_dofs());
    const auto m = static_cast<std::size_t>(kernel->n_multipliers());
    r.assign(nd, 0.0);
    K.assign(nd * nd, 0.0);
    cslot.assign(m, 0);
    cval.assign(m, 0.0);
    ccomp.assign(m, 0.0);
    ccoef.assign(m * nd, 0.0);
    ccol.assign(m * nd, 0.0);
    ElementOutput out;
    out.residual = r;
    out.tangent = K;
    out.constraint_slot = cslot;
    out.constraint_value = cval;
    out.constraint_compliance = ccomp;
    out.constraint_coeff = ccoef;
    out.constraint_column = ccol;
    auto in = input();
    kernel->evaluate(in, out);
    n_constraints = out.n_constraints;
    status_changes = out.status_changes;
    branch_changes = out.branch_changes;
    has_columns = out.has_columns;
    unsymmetric = out.unsymmetric;
  }
  GapRecord record() {
    ElementRecovery rec;
    auto in = input();
    kernel->recover(in, rec);
    return *rec.gap;
  }
};

inline /// Central differences of the residual against the tangent (multipliers fixed; the trial
       /// state is
    /// restored before every evaluation so the status does not change), and of the residual against
    /// the normal multiplier against the constraint column.
    void
    check_element_tangent(SingleElement& el, double h_scale, double tol = 1e-6) {
  const auto state = el.state;
  const auto mult = el.mult;
  el.evaluate();
  auto K = el.K;
  const auto col = el.ccol;
  const bool has_columns = el.has_columns;
  const int n_rows = el.n_constraints;
  const auto cslot = std::vector<int>(el.cslot.begin(), el.cslot.end());
  const auto ccomp = el.ccomp;
  const auto nd = el.u.size();
  // a tangent the kernel calls symmetric must be: the solver then factorises one triangle of it
  if (!el.unsymmetric) {
    double scale = 1e-300;
    for (double v : K) scale = std::max(scale, std::abs(v));
    for (std::size_t i = 0; i < nd; ++i)
      for (std::size_t j = 0; j < i; ++j)
        EXPECT_NEAR(K[i * nd + j], K[j * nd + i], 1e-12 * scale)
            << "tangent called symmetric, entries (" << i << "," << j << ")";
  }
  // A compliant row (a force law's stiffness as a row of compliance E, its multiplier the force
  // itself) stands for the tangent term D c^T / E: condensed into K, it is what the residual's
  // differences see. Its value is 0 and its multiplier is recomputed at every evaluation.
  for (int row = 0; row < n_rows; ++row)
    if (ccomp[row] > 0)
      for (std::size_t i = 0; i < nd; ++i)
        for (std::size_t j = 0; j < nd; ++j)
          K[i * nd + j] += (has_columns ? col[row * nd + i] : el.ccoef[row * nd + i]) *
                           el.ccoef[row * nd + j] / ccomp[row];
  const double h = std::cbrt(2.2e-16) * h_scale;
  double kmax = 1.0;
  for (double v : K) kmax = std::max(kmax, std::abs(v));
  // residual and constraint values at u_j +- h, from the same trial state
  struct Probe {
    std::vector<double> r, g;
    int rows = 0;
  };
  auto probe = [&](std::size_t dof, double offset) {
    const double keep = el.u[dof];
    el.u[dof] = keep + offset;
    el.state = state;
    el.mult = mult;
    el.evaluate();
    el.u[dof] = keep;
    return Probe{el.r, el.cval, el.n_constraints};
  };
  const auto ccoef0 = el.ccoef;
  for (std::size_t j = 0; j < nd; ++j) {
    const Probe p = probe(j, h), m = probe(j, -h);
    for (std::size_t i = 0; i < nd; ++i)
      EXPECT_NEAR((p.r[i] - m.r[i]) / (2 * h), K[i * nd + j], tol * kmax)
          << "K(" << i << "," << j << ")";
    // the constraint rows: d g_i / d u against the row coefficients (unless the row set changed)
    if (p.rows != n_rows || m.rows != n_rows) continue;
    for (int row = 0; row < n_rows; ++row)
      if (ccomp[row] == 0.0)
        EXPECT_NEAR((p.g[row] - m.g[row]) / (2 * h), ccoef0[row * nd + j], 1e-6)
            << "constraint row " << row << " dof " << j;
  }
  // d r / d lambda for each active row
  for (int row = 0; row < n_rows; ++row) {
    if (ccomp[row] > 0) continue;
    const int slot = cslot[row];
    const double dl = 1e-6 * (1.0 + std::abs(mult[slot]));
    el.state = state;
    el.mult = mult;
    el.mult[slot] += dl;
    el.evaluate();
    const auto rp = el.r;
    el.state = state;
    el.mult = mult;
    el.mult[slot] -= dl;
    el.evaluate();
    const auto rm = el.r;
    for (std::size_t i = 0; i < nd; ++i) {
      const double expected = has_columns ? col[row * nd + i] : el.ccoef[row * nd + i];
      EXPECT_NEAR((rp[i] - rm[i]) / (2 * dl), expected, 1e-6) << "row " << row << " dof " << i;
    }
  }
  el.state = state;
  el.mult = mult;
  el.evaluate();
}

} // namespace gapfem::test
