#include "fem/element_gather.hpp"

#include "model/model.hpp"

#include <algorithm>

namespace gapfem {

void ElementGather::gather_rates(std::span<const LocalIndex> slots, const FieldView& f,
                                 const RateCoefficients& c) {
  const std::size_t n = slots.size();
  _v0.assign(n, 0.0);
  _a0.assign(n, 0.0);
  if (!f.v_start.empty())
    for (std::size_t k = 0; k < n; ++k) _v0[k] = f.v_start[slots[k]];
  if (!f.a_start.empty())
    for (std::size_t k = 0; k < n; ++k) _a0[k] = f.a_start[slots[k]];
  const auto given = [&](std::size_t k) {
    return !f.rate_given.empty() && f.rate_given[slots[k]] != 0;
  };
  _v.resize(n);
  for (std::size_t k = 0; k < n; ++k)
    _v[k] = given(k) ? f.v_given[slots[k]] : c.velocity(_u[k] - _u0[k], _v0[k], _a0[k]);
  _in.v = _v;
  _in.v_start = _v0;
  if (!c.second_order) return;
  _a.resize(n);
  for (std::size_t k = 0; k < n; ++k)
    _a[k] = given(k) ? f.a_given[slots[k]] : c.acceleration(_u[k] - _u0[k], _v0[k], _a0[k]);
  _in.a = _a;
  _in.a_start = _a0;
}

ElementInput& ElementGather::gather(const Discretization& disc, ElementBlock& block, std::size_t i,
                                    const FieldView& f, const StepContext* ctx, bool rates) {
  const Model& model = disc.model();
  const ElemId e = block.elements[i];
  const auto nodes = model.mesh.element_nodes(e);
  const auto nn = nodes.size();
  _X.resize(nn);
  for (std::size_t a = 0; a < nn; ++a) _X[a] = model.mesh.coords[nodes[a]];
  const auto slots = block.element_slots(i);
  _u.resize(slots.size());
  _u0.resize(slots.size());
  for (std::size_t k = 0; k < slots.size(); ++k) {
    _u[k] = f.u[slots[k]];
    _u0[k] = f.u_start.empty() ? _u[k] : f.u_start[slots[k]];
  }
  _in = ElementInput{};
  _in.elem = e;
  _in.label = model.element_label(e);
  _in.block_index = static_cast<LocalIndex>(i);
  _in.X = _X;
  _in.u = _u;
  _in.u_start = _u0;
  if (rates && ctx && ctx->rates.defined()) gather_rates(slots, f, ctx->rates);
  if (block.uses_temperature && !f.temperature.empty()) {
    _T.resize(nn);
    _T0.resize(nn);
    _Ti.resize(nn);
    for (std::size_t a = 0; a < nn; ++a) {
      _T[a] = f.temperature[nodes[a]];
      _T0[a] = f.temperature_start.empty() ? _T[a] : f.temperature_start[nodes[a]];
      _Ti[a] = f.initial_temperature.empty() ? 0.0 : f.initial_temperature[nodes[a]];
    }
    _in.temperature = _T;
    _in.temperature_start = _T0;
    _in.initial_temperature = _Ti;
    if (!f.temperature_gradient.empty()) {
      _G.resize(2 * nn);
      for (std::size_t a = 0; a < nn; ++a) {
        _G[2 * a] = f.temperature_gradient[2 * nodes[a]];
        _G[2 * a + 1] = f.temperature_gradient[2 * nodes[a] + 1];
      }
      _in.temperature_gradient = _G;
    }
  }
  if (block.n_state > 0) {
    _in.state_start = {block.state_committed.data() + i * block.n_state,
                       static_cast<std::size_t>(block.n_state)};
    _in.state = {block.state_trial.data() + i * block.n_state,
                 static_cast<std::size_t>(block.n_state)};
  }
  if (block.n_mult > 0)
    _in.multipliers = {block.mult_trial.data() + i * block.n_mult,
                       static_cast<std::size_t>(block.n_mult)};
  if (!block.eqs.empty()) {
    const auto eqs = block.element_eqs(i);
    _free.resize(eqs.size());
    for (std::size_t k = 0; k < eqs.size(); ++k) _free[k] = eqs[k] >= 0 ? 1 : 0;
    _in.free = _free;
  }
  if (!block.interference.empty()) _in.interference = block.interference[i];
  if (!block.stiffness_hint.empty()) _in.stiffness_hint = block.stiffness_hint[i];
  _in.ctx = ctx;
  return _in;
}

ElementOutput& ElementGather::output(const ElementBlock& block, bool want_tangent, bool want_mass,
                                     bool want_damping) {
  const auto n = static_cast<std::size_t>(block.n_dofs);
  _r.assign(n, 0.0);
  _K.assign(want_tangent ? n * n : 0, 0.0);
  const auto m = static_cast<std::size_t>(block.n_mult);
  _cslot.assign(m, 0);
  _cval.assign(m, 0.0);
  _ccomp.assign(m, 0.0);
  _ccoef.assign(m * n, 0.0);
  _ccol.assign(m * n, 0.0);
  _out = ElementOutput{};
  _out.residual = _r;
  _out.tangent = _K;
  _out.want_tangent = want_tangent;
  if (want_mass) {
    _M.assign(n * n, 0.0);
    _out.mass = _M;
    _out.want_mass = true;
  }
  if (want_damping) {
    _D.assign(n * n, 0.0);
    _out.damping = _D;
    _out.want_damping = true;
  }
  _out.constraint_slot = _cslot;
  _out.constraint_value = _cval;
  _out.constraint_compliance = _ccomp;
  _out.constraint_coeff = _ccoef;
  _out.constraint_column = _ccol;
  return _out;
}

} // namespace gapfem
