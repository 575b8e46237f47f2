#pragma once
/// @file kernel_probe.hpp
/// One element's local data and the kernel that evaluates it, as the unit tests of every element
/// kernel hold them (kernel_harness.hpp checks kernels on it): what the assembler would gather
/// (X, u, u_start, temperatures, committed and trial history and multipliers, the StepContext)
/// lent to the kernel exactly as the assembler lends its buffers, and what the kernel returns
/// copied out.
#include "elements/element_kernel.hpp"
#include "model/model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace gapfem::test {

/// What one evaluation returned, copied out of the buffers the probe lent the kernel.
struct KernelResult {
  std::size_t n = 0;     ///< local DOFs
  std::vector<double> r; ///< residual
  std::vector<double> K; ///< tangent, n x n row-major (empty when not asked for)
  int n_constraints = 0;
  std::vector<int> slot;          ///< per row: its multiplier (capacity n_multipliers)
  std::vector<double> g;          ///< per row: the constraint value
  std::vector<double> compliance; ///< per row: 0 exact, 1/k compliant
  std::vector<double> coeff;      ///< n_multipliers x n: d g / d u
  std::vector<double> column;     ///< n_multipliers x n: d r / d lambda when has_columns
  bool has_columns = false;
  bool unsymmetric = false;
  bool stiffness_changed = false;
  bool friction = false;
  int status_changes = 0;
  int branch_changes = 0;
  double dt_ratio = std::numeric_limits<double>::infinity();

  double k(std::size_t i, std::size_t j) const { return K[i * n + j]; }
  /// d g_row / d u_j
  double c(int row, std::size_t j) const { return coeff[row * n + j]; }
  /// d r_i / d lambda of the row: its own column when the kernel gives one, else d g / d u
  double dr_dlambda(int row, std::size_t i) const {
    return has_columns ? column[row * n + i] : coeff[row * n + i];
  }
};

/// The local data of one element and the kernel that evaluates it. The members are the element's
/// whole world: tests set them directly (u, the committed history, the context) and call
/// evaluate(); input() lends them to the kernel exactly as the assembler lends its buffers.
struct KernelProbe {
  std::shared_ptr<const ElementKernel> kernel;
  /// keeps the model alive when the probe made the kernel (gap kernels refer to their section)
  std::shared_ptr<const Model> model;
  std::vector<Vec3> X;             ///< reference coordinates
  std::vector<double> u, u0;       ///< trial values and values at the start of the increment
  std::vector<double> T, T0, Ti;   ///< predefined temperatures now, at the start, initial (or none)
  std::vector<double> Tgrad;       ///< predefined through-section gradients (or none)
  std::vector<double> state;       ///< trial history (written by evaluate)
  std::vector<double> state0;      ///< committed history
  std::vector<double> mult, mult0; ///< trial and committed multipliers
  std::vector<std::uint8_t> free;  ///< per DOF: 1 unknown, 0 prescribed (empty: all free)
  double interference = 0.0;
  double stiffness_hint = 0.0;
  StepContext ctx;
  EntityLabel label{1};

  /// A probe of `k` on an element with nodes at `coords`: u = u0 = 0, the history as the kernel
  /// initializes it, committed.
  KernelProbe(std::shared_ptr<const ElementKernel> k, std::vector<Vec3> coords,
              const StepContext& context = {})
      : kernel(std::move(k)), X(std::move(coords)), ctx(context) {
    u.assign(static_cast<std::size_t>(kernel->n_dofs()), 0.0);
    u0 = u;
    state.assign(static_cast<std::size_t>(kernel->n_state()), 0.0);
    mult.assign(static_cast<std::size_t>(kernel->n_multipliers()), 0.0);
    initialize();
  }
  /// A probe of a kernel the caller keeps alive.
  KernelProbe(const ElementKernel& k, std::vector<Vec3> coords, const StepContext& context = {})
      : KernelProbe(
            std::shared_ptr<const ElementKernel>(std::shared_ptr<const ElementKernel>{}, &k),
            std::move(coords), context) {}

  /// The kernel the factory makes for element `e` of `m` alone, on that element's nodes; the
  /// context takes the model's space and size. The model must outlive the probe.
  static KernelProbe of(const Model& m, ElemId e = 0, const KernelOptions& options = {}) {
    const ElemId elems[1] = {e};
    const std::int32_t variant = m.mesh.elem_variant.empty() ? -1 : m.mesh.variant(e);
    std::shared_ptr<const ElementKernel> k = make_element_kernel(KernelContext{
        m, m.mesh.elem_types[e], m.element_property[e], {elems, 1}, variant, options});
    std::vector<Vec3> coords;
    for (NodeId a : m.mesh.element_nodes(e)) coords.push_back(m.mesh.coords[a]);
    StepContext context;
    context.space = m.space;
    context.model_size = m.model_size();
    return KernelProbe(std::move(k), std::move(coords), context);
  }
  /// The same, keeping the model alive.
  static KernelProbe of(std::shared_ptr<const Model> m, ElemId e = 0,
                        const KernelOptions& options = {}) {
    KernelProbe p = of(*m, e, options);
    p.model = std::move(m);
    return p;
  }

  int n() const { return kernel->n_dofs(); }
  /// The element's size: its largest distance between two nodes (1 for a single node).
  double size() const {
    double d = 0.0;
    for (const Vec3& a : X)
      for (const Vec3& b : X) d = std::max(d, std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
    return d > 0.0 ? d : 1.0;
  }

  ElementInput input() {
    ElementInput in;
    in.elem = 0;
    in.label = label;
    in.X = X;
    in.u = u;
    in.u_start = u0;
    in.temperature = T;
    in.temperature_start = T0.empty() ? std::span<const double>(T) : std::span<const double>(T0);
    in.temperature_gradient = Tgrad;
    in.initial_temperature = Ti;
    in.state_start = state0;
    in.state = state;
    in.multipliers = mult;
    in.free = free;
    in.interference = interference;
    in.stiffness_hint = stiffness_hint;
    in.ctx = &ctx;
    return in;
  }

  /// One evaluation at the trial data; writes the trial history and multipliers. Without the
  /// tangent the kernel gets an empty tangent span, as in the solver's residual-only passes.
  KernelResult evaluate(bool want_tangent = true) {
    const auto nd = static_cast<std::size_t>(n());
    const auto m = static_cast<std::size_t>(kernel->n_multipliers());
    KernelResult res;
    res.n = nd;
    res.r.assign(nd, 0.0);
    res.K.assign(want_tangent ? nd * nd : 0, 0.0);
    res.slot.assign(m, 0);
    res.g.assign(m, 0.0);
    res.compliance.assign(m, 0.0);
    res.coeff.assign(m * nd, 0.0);
    res.column.assign(m * nd, 0.0);
    ElementOutput out;
    out.residual = res.r;
    out.tangent = res.K;
    out.want_tangent = want_tangent;
    out.constraint_slot = res.slot;
    out.constraint_value = res.g;
    out.constraint_compliance = res.compliance;
    out.constraint_coeff = res.coeff;
    out.constraint_column = res.column;
    const ElementInput in = input();
    kernel->evaluate(in, out);
    res.n_constraints = out.n_constraints;
    res.has_columns = out.has_columns;
    res.unsymmetric = out.unsymmetric;
    res.stiffness_changed = out.stiffness_changed;
    res.friction = out.friction;
    res.status_changes = out.status_changes;
    res.branch_changes = out.branch_changes;
    res.dt_ratio = out.dt_ratio;
    return res;
  }
  /// The equivalent nodal load of `load` (f_ext) and, in `tangent`, -d f_ext / du.
  std::vector<double> load(const DistributedLoad& load, double magnitude, double sink,
                           std::vector<double>* tangent = nullptr) {
    const auto nd = static_cast<std::size_t>(n());
    std::vector<double> f(nd, 0.0), k(nd * nd, 0.0);
    kernel->load(input(), load, magnitude, sink, f, k);
    if (tangent) *tangent = std::move(k);
    return f;
  }
  ElementRecovery recover() {
    ElementRecovery rec;
    kernel->recover(input(), rec);
    return rec;
  }
  /// The kernel writes the initial history into the trial arrays; the result is committed.
  void initialize() {
    kernel->initialize(input());
    state0 = state;
    mult0 = mult;
  }
  /// An accepted increment: committed = trial, and the next increment starts from u.
  void commit() {
    u0 = u;
    state0 = state;
    mult0 = mult;
  }
  /// A new attempt: trial history and multipliers = committed (u is left as it is).
  void revert() {
    state = state0;
    mult = mult0;
  }
};

/// Puts element 1 of type t on nodes 1..n at X (one element alone: the probes' models).
inline void add_lone_element(Model& model, ElementType t, const std::vector<Vec3>& X) {
  Mesh& mesh = model.mesh;
  for (std::size_t a = 0; a < X.size(); ++a) {
    mesh.node_labels.push_back(static_cast<Label>(a + 1));
    mesh.coords.push_back(X[a]);
    mesh.node_index[static_cast<Label>(a + 1)] = static_cast<NodeId>(a);
    mesh.conn.push_back(static_cast<NodeId>(a));
  }
  mesh.elem_labels.push_back(1);
  mesh.elem_types.push_back(t);
  mesh.conn_offset.push_back(static_cast<std::int64_t>(X.size()));
  mesh.elem_src.push_back({});
  mesh.elem_index[1] = 0;
}

/// A distributed load of `kind` on `face` (0: the body) of element 0.
inline DistributedLoad distributed_load(DistLoadKind kind, int face, double magnitude = 0.0,
                                        double sink = 0.0) {
  DistributedLoad ld;
  ld.elem = 0;
  ld.kind = kind;
  ld.face = face;
  ld.magnitude = magnitude;
  ld.sink_temperature = sink;
  return ld;
}

} // namespace gapfem::test
