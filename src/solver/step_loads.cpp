#include "solver/step_loads.hpp"

#include "common/log.hpp"
#include "fem/constraint_set.hpp"
#include "fem/discretization.hpp"
#include "model/model.hpp"

#include <fmt/format.h>
#include <set>

namespace gapfem {

namespace {
/// The value of u along local DOF d (1-6) of a transformed node with axes Q.
double local_value(const DofMap& dofs, std::span<const double> u, NodeId n, int d,
                   const std::array<double, 9>& Q) {
  const int base = d <= 3 ? 0 : 3, i = d - 1 - base;
  double v = 0.0;
  for (int j = 0; j < 3; ++j) {
    const LocalIndex s = dofs.slot(n, static_cast<DofType>(base + j));
    if (s >= 0) v += Q[3 * i + j] * u[s];
  }
  return v;
}

/// Boundary conditions on DOFs no element at the node has: how many, and the first.
struct IgnoredBcs {
  int count = 0;
  std::string example;
  void note(const Model& model, const BoundaryEntry& bc) {
    if (count++ == 0)
      example = fmt::format("node {} DOF {} ({})", model.node_label(bc.node), abaqus_number(bc.dof),
                            bc.loc.str());
  }
};
} // namespace

StepLoads::StepLoads(const Model& model, const Discretization& disc, int step_index,
                     const LoadHistory& history, std::span<const double> u_now,
                     double step_start_total_time)
    : _model(model), _step(model.steps[step_index]), _period(_step.inc.period),
      _step_start(step_start_total_time), _step_index(step_index) {
  // the step before: the last general step (a perturbation step's loads do not carry on)
  const Step* prev = nullptr;
  for (int k = step_index - 1; k >= 0 && !prev; --k)
    if (!model.steps[k].perturbation) prev = &model.steps[k];
  set_boundary_conditions(disc, u_now);
  _eqmap = EquationMap::build(_prescribed);
  set_concentrated_loads(disc.dofs(), history);
  set_released_reactions(disc.dofs(), history);
  set_distributed_loads(history, prev);
  set_temperatures(disc, history, prev);
  set_interference();
}

void StepLoads::set_boundary_conditions(const Discretization& disc, std::span<const double> u_now) {
  const DofMap& dofs = disc.dofs();
  _prescribed.assign(static_cast<std::size_t>(dofs.n_slots()), 0);
  IgnoredBcs ignored;
  for (const BoundaryEntry& bc : _step.boundary) {
    const int d = abaqus_number(bc.dof);
    if (d <= 6)
      if (const auto Q = _model.node_axes(bc.node)) {
        const int base = d <= 3 ? 0 : 3, i = d - 1 - base;
        std::array<LocalIndex, 3> slots{};
        std::array<double, 3> axis{};
        for (int j = 0; j < 3; ++j) {
          slots[j] = dofs.slot(bc.node, static_cast<DofType>(base + j));
          axis[j] = (*Q)[3 * i + j];
        }
        const bool added =
            bc.type == BoundaryType::Displacement
                ? add_local_bc(bc, d, local_value(dofs, u_now, bc.node, d, *Q), disc.constraints())
                : add_local_motion(bc, d, slots, axis, disc.constraints());
        for (LocalBc& l : _local)
          if (l.node == bc.node && l.dof == d) {
            l.slots = slots;
            l.axis = axis;
          }
        if (!added) ignored.note(_model, bc);
        continue;
      }
    const LocalIndex s = dofs.slot(bc.node, bc.dof);
    if (s < 0) {
      ignored.note(_model, bc);
      continue;
    }
    if (bc.type != BoundaryType::Displacement) {
      add_motion(bc, s);
      continue;
    }
    std::erase_if(_motion, [&](const Motion& m) { return m.slot == s; });
    Scalar sc;
    sc.start = u_now[s];
    sc.end = bc.fixed ? sc.start : bc.value;
    sc.amplitude = bc.fixed ? -1 : bc.amplitude;
    sc.constant = bc.fixed || bc.propagated;
    if (bc.propagated) sc.start = u_now[s];
    if (_prescribed[s]) {
      for (auto& [slot, existing] : _bc)
        if (slot == s) existing = sc;
    } else {
      _bc.emplace_back(s, sc);
    }
    _prescribed[s] = 1;
  }
  if (ignored.count == 0) return;
  // a temperature on a node of stress/displacement elements only: CalculiX gives every element
  // temperatures in thermal steps, Abaqus only the heat-transfer and coupled types
  const bool thermal =
      is_thermal(_step.procedure) && ignored.example.find(" DOF 11 ") != std::string::npos;
  _warnings.push_back(fmt::format(
      "step {}: {} boundary condition(s) refer to DOFs that no element at the node has, e.g. {}; "
      "they have no effect{}",
      _step.number, ignored.count, ignored.example,
      thermal ? " (stress/displacement elements such as C3D20R carry no temperature DOF: use the "
                "coupled types, e.g. C3D20RT, for heat conduction in the body, as in Abaqus)"
              : ""));
}

bool StepLoads::add_local_bc(const BoundaryEntry& bc, int d, double now,
                             const ConstraintSet& rows) {
  const int row = rows.bc_row(bc.node, d);
  if (row < 0) return false;
  std::erase_if(_local, [&](const LocalBc& l) { return l.row == row && l.moving; });
  Scalar sc;
  sc.start = now;
  sc.end = bc.fixed ? sc.start : bc.value;
  sc.amplitude = bc.fixed ? -1 : bc.amplitude;
  sc.constant = bc.fixed || bc.propagated;
  bool replaced = false;
  for (LocalBc& l : _local)
    if (l.row == row) {
      l.value = sc;
      replaced = true;
    }
  if (!replaced) {
    LocalBc l;
    l.node = bc.node;
    l.dof = d;
    l.row = row;
    l.value = sc;
    _local.push_back(l);
    if (std::find(_local_keys.begin(), _local_keys.end(), std::make_pair(bc.node, d)) ==
        _local_keys.end())
      _local_keys.emplace_back(bc.node, d);
  }
  return true;
}

// A load on DOF d of a node: on its slot, or along the local axis of a transformed node.
void StepLoads::add_nodal(const DofMap& dofs, NodeId n, int d,
                          const std::optional<std::array<double, 9>>& Q, const Scalar& sc) {
  if (!Q) {
    DofType t{};
    dof_from_abaqus(d, t);
    _nodal.push_back({dofs.slot(n, t), sc, 1.0});
    return;
  }
  const int base = d <= 3 ? 0 : 3, i = d - 1 - base;
  for (int j = 0; j < 3; ++j) {
    const LocalIndex s = dofs.slot(n, static_cast<DofType>(base + j));
    if (s >= 0 && (*Q)[3 * i + j] != 0.0) _nodal.push_back({s, sc, (*Q)[3 * i + j]});
  }
}

// Concentrated loads (CLOAD, CFLUX), including removed ones (to zero).
void StepLoads::set_concentrated_loads(const DofMap& dofs, const LoadHistory& history) {
  std::set<std::pair<NodeId, int>> seen;
  for (const NodalLoad& l : _step.cloads) {
    const LocalIndex s = dofs.slot(l.node, l.dof);
    const int d = abaqus_number(l.dof);
    const auto Q = d <= 6 ? _model.node_axes(l.node) : std::nullopt;
    if (s < 0)
      throw InputError(l.loc, fmt::format("node {}", _model.node_label(l.node)),
                       fmt::format("no element at this node has DOF {}; the load cannot be applied",
                                   abaqus_number(l.dof)));
    const auto key = std::make_pair(l.node, static_cast<int>(l.dof));
    Scalar sc;
    auto it = history.nodal.find(key);
    sc.start = it == history.nodal.end() ? 0.0 : it->second;
    sc.end = l.value;
    sc.amplitude = l.amplitude;
    sc.constant = l.propagated;
    add_nodal(dofs, l.node, d, Q, sc);
    _nodal_keys.emplace_back(key, sc);
    seen.insert(key);
  }
  for (const auto& [key, v] : history.nodal)
    if (!seen.count(key) && v != 0.0) {
      const int d = abaqus_number(static_cast<DofType>(key.second));
      Scalar sc{v, 0.0, -1, false};
      add_nodal(dofs, key.first, d, d <= 6 ? _model.node_axes(key.first) : std::nullopt, sc);
      _nodal_keys.emplace_back(key, sc);
    }
}

// Released boundary conditions: their reaction goes to zero like a removed load.
void StepLoads::set_released_reactions(const DofMap& dofs, const LoadHistory& history) {
  if (!history.prescribed.empty())
    for (LocalIndex s = 0; s < dofs.n_slots(); ++s)
      if (history.prescribed[s] && !_prescribed[s] && history.reaction[s] != 0.0)
        _nodal.push_back({s, Scalar{history.reaction[s], 0.0, -1, false}, 1.0});
  for (const auto& [key, r] : history.local_reaction) {
    bool held = false;
    for (const auto& k : _local_keys) held |= k == key;
    if (!held && r != 0.0)
      add_nodal(dofs, key.first, key.second, _model.node_axes(key.first),
                Scalar{r, 0.0, -1, false});
  }
}

namespace {
/// A film's coefficient follows FILM AMPLITUDE=, an emissivity none (AMPLITUDE= of both is the
/// sink temperature's), every other load its AMPLITUDE=.
int magnitude_amplitude(const DistributedLoad& l) {
  return l.kind == DistLoadKind::Film        ? l.film_amplitude
         : l.kind == DistLoadKind::Radiation ? -1
                                             : l.amplitude;
}
bool is_face_exchange(DistLoadKind k) {
  return k == DistLoadKind::Film || k == DistLoadKind::Radiation;
}
} // namespace

// Distributed loads, including those of the previous step this one removes (to zero).
void StepLoads::set_distributed_loads(const LoadHistory& history, const Step* prev) {
  std::set<std::tuple<ElemId, int, int>> dseen;
  for (const DistributedLoad& l : _step.dloads) {
    const auto key = std::make_tuple(l.elem, static_cast<int>(l.kind), l.face);
    auto it = history.distributed.find(key);
    Dist d{&l, {}, {}, {}};
    d.magnitude = Scalar{it == history.distributed.end() ? 0.0 : it->second.first, l.magnitude,
                         magnitude_amplitude(l), l.propagated};
    d.sink = Scalar{it == history.distributed.end() ? l.sink_temperature : it->second.second,
                    l.sink_temperature, is_face_exchange(l.kind) ? l.amplitude : -1, l.propagated};
    _dist.push_back(d);
    dseen.insert(key);
  }
  if (prev)
    for (const DistributedLoad& l : prev->dloads) {
      const auto key = std::make_tuple(l.elem, static_cast<int>(l.kind), l.face);
      if (dseen.count(key)) continue;
      auto it = history.distributed.find(key);
      if (it == history.distributed.end() || it->second.first == 0.0) continue;
      Dist d{nullptr, l, {}, {}};
      d.magnitude = Scalar{it->second.first, 0.0, -1, false};
      d.sink = Scalar{it->second.second, it->second.second, -1, true};
      _dist.push_back(d);
    }
  for (auto& d : _dist)
    if (!d.load) d.load = &d.removed;
}

// Predefined temperatures (and their through-section gradients); those of the previous step
// this one does not give return to the initial condition.
void StepLoads::set_temperatures(const Discretization& disc, const LoadHistory& history,
                                 const Step* prev) {
  const Model& model = _model;
  _has_temperature = disc.has_temperature_field();
  _temp_base = history.temperature;
  if (_temp_base.empty()) _temp_base = model.initial_temperature;
  _temp_base.resize(static_cast<std::size_t>(model.mesh.n_nodes()), 0.0);
  _has_gradient = _has_temperature && model.has_temperature_gradients;
  _grad_base = history.temperature_gradient;
  _grad_base.resize(2 * static_cast<std::size_t>(model.mesh.n_nodes()), 0.0);
  auto gradient_entry = [&](NodeId n, std::array<double, 2> to, int amplitude, bool propagated) {
    if (!_has_gradient) return;
    _grad.emplace_back(
        n, std::array<Scalar, 2>{Scalar{_grad_base[2 * n], to[0], amplitude, propagated},
                                 Scalar{_grad_base[2 * n + 1], to[1], amplitude, propagated}});
  };
  std::set<NodeId> tseen;
  for (const NodalTemperature& t : _step.temperatures) {
    _temp.emplace_back(t.node, Scalar{_temp_base[t.node], t.value, t.amplitude, t.propagated});
    gradient_entry(t.node, t.gradient, t.amplitude, t.propagated);
    tseen.insert(t.node);
  }
  if (prev)
    for (const NodalTemperature& t : prev->temperatures)
      if (!tseen.count(t.node)) {
        const double init = t.node < static_cast<NodeId>(model.initial_temperature.size())
                                ? model.initial_temperature[t.node]
                                : 0.0;
        _temp.emplace_back(t.node, Scalar{_temp_base[t.node], init, -1, false});
        gradient_entry(t.node, {0.0, 0.0}, -1, false);
      }
}

// Interference fits (SHRINK allowances are set later, from the clearance at the step start).
void StepLoads::set_interference() {
  for (const InterferenceEntry& e : _step.interference) {
    _interf.push_back({e.elem, e.allowance, e.shrink ? -1 : e.amplitude});
    if (e.shrink) _shrink_elems.push_back(e.elem);
  }
}

double StepLoads::value(const Scalar& s, double step_time) const {
  if (s.amplitude >= 0) {
    const Amplitude& a = _model.amplitudes[s.amplitude];
    if (s.constant && a.time == Amplitude::TimeBase::Step) return s.start;
    const double v = a.value(step_time, _step_start);
    return a.absolute ? v : s.end * v;
  }
  if (s.constant) return s.start;
  if (!_step.ramp_default) return s.end;
  const double f = _period > 0 ? std::clamp(step_time / _period, 0.0, 1.0) : 1.0;
  return s.start + (s.end - s.start) * f;
}

void StepLoads::apply_prescribed(double step_time, std::span<double> u) const {
  for (const auto& [s, sc] : _bc) u[s] = value(sc, step_time);
}

void StepLoads::add_nodal_loads(double step_time, std::span<double> f_ext) const {
  for (const NodalEntry& e : _nodal) f_ext[e.slot] += e.factor * value(e.value, step_time);
}

void StepLoads::apply_local_bcs(double t0, double t1, std::span<const double> u0,
                                std::span<const double> v0, std::span<const double> a0,
                                ConstraintSet& rows) const {
  rows.clear_rates();
  for (const LocalBc& l : _local) {
    // the committed displacement, velocity and acceleration along the local axis
    const auto along = [&](std::span<const double> x) {
      double c = 0.0;
      if (!x.empty())
        for (int j = 0; j < 3; ++j)
          if (l.slots[j] >= 0) c += l.axis[j] * x[l.slots[j]];
      return c;
    };
    if (!l.moving) { // a displacement: its row moves as the node did (the integrator's rates)
      rows.set_value(l.row, value(l.value, t1));
      if (!v0.empty()) rows.set_rates(l.row, along(v0), along(a0));
      continue;
    }
    // from the committed state, as apply_prescribed_motion
    const Motion& mo = l.motion;
    const double un = along(u0), vn = along(v0);
    if (mo.acceleration) {
      rows.set_value(l.row, un + vn * (t1 - t0) + motion(mo, t0, t1, 3));
      rows.set_rates(l.row, vn + motion(mo, t0, t1, 2), motion(mo, t0, t1, 0));
    } else {
      rows.set_value(l.row, un + motion(mo, t0, t1, 2));
      rows.set_rates(l.row, motion(mo, t0, t1, 0), motion(mo, t0, t1, 1));
    }
  }
}

bool StepLoads::has_local_motion() const {
  return std::any_of(_local.begin(), _local.end(), [](const LocalBc& l) { return l.moving; });
}

void StepLoads::distributed_loads(double step_time, std::vector<ActiveLoad>& out) const {
  out.clear();
  for (const Dist& d : _dist) {
    const double m = value(d.magnitude, step_time);
    if (m == 0.0) continue;
    out.push_back({d.load, m, value(d.sink, step_time)});
  }
}

void StepLoads::temperatures(double step_time, std::span<double> T) const {
  std::copy(_temp_base.begin(), _temp_base.end(), T.begin());
  for (const auto& [n, sc] : _temp) T[n] = value(sc, step_time);
}

void StepLoads::temperature_gradients(double step_time, std::span<double> G) const {
  std::copy(_grad_base.begin(), _grad_base.end(), G.begin());
  for (const auto& [n, sc] : _grad) {
    G[2 * n] = value(sc[0], step_time);
    G[2 * n + 1] = value(sc[1], step_time);
  }
}

void StepLoads::interference(double step_time, Discretization& disc) const {
  for (auto& b : disc.blocks()) std::fill(b.interference.begin(), b.interference.end(), 0.0);
  for (const Interf& i : _interf) {
    double factor;
    if (i.amplitude >= 0) {
      factor = _model.amplitudes[i.amplitude].value(step_time, _step_start);
    } else {
      factor = _period > 0 ? 1.0 - std::clamp(step_time / _period, 0.0, 1.0) : 0.0;
    }
    const auto [bi, idx] = disc.locate(i.elem);
    auto& b = disc.blocks()[bi];
    if (!b.interference.empty()) b.interference[idx] = i.allowance * factor;
  }
}

void StepLoads::set_shrink_allowance(ElemId e, double v) {
  for (Interf& i : _interf)
    if (i.elem == e) i.allowance = v;
}

double StepLoads::shrink_allowance(ElemId e) const {
  for (const Interf& i : _interf)
    if (i.elem == e) return i.allowance;
  return 0.0;
}

void StepLoads::finish(double t_end, std::span<const double> reaction, const ConstraintSet& rows,
                       LoadHistory& h) const {
  h.local_reaction.clear();
  for (const LocalBc& l : _local) h.local_reaction[{l.node, l.dof}] = -rows.mult_committed[l.row];
  h.nodal.clear();
  for (const auto& [key, sc] : _nodal_keys) {
    const double v = value(sc, t_end);
    if (v != 0.0) h.nodal[key] = v;
  }
  h.distributed.clear();
  for (const Dist& d : _dist) {
    if (d.load == &d.removed) continue;
    h.distributed[std::make_tuple(d.load->elem, static_cast<int>(d.load->kind), d.load->face)] = {
        value(d.magnitude, t_end), value(d.sink, t_end)};
  }
  h.temperature = _temp_base;
  for (const auto& [n, sc] : _temp) h.temperature[n] = value(sc, t_end);
  if (_has_gradient) {
    h.temperature_gradient.assign(_grad_base.size(), 0.0);
    temperature_gradients(t_end, h.temperature_gradient);
  }
  h.prescribed = _prescribed;
  h.reaction.assign(reaction.begin(), reaction.end());
}

} // namespace gapfem
