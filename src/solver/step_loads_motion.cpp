// Prescribed velocities and accelerations (*BOUNDARY, TYPE=VELOCITY|ACCELERATION): the motion
// q(t) of each driven DOF and its exact integrals over an increment. Theory and the Abaqus rules
// followed (default variation, propagation, static steps): docs/theory/dynamics.md, "Base motion".
#include "fem/constraint_set.hpp"
#include "model/model.hpp"
#include "solver/step_loads.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace gapfem {

namespace {

/// Steps in which Abaqus applies a prescribed velocity without an amplitude at once (a STEP
/// variation) whatever the step's default: static and quasi-static dynamic steps.
bool velocity_steps_at_once(const Step& st) {
  return st.procedure == Procedure::Static ||
         (st.procedure == Procedure::Dynamic &&
          st.dynamic.application == DynamicSettings::Application::QuasiStatic);
}

} // namespace

StepLoads::Motion StepLoads::make_motion(int k, const BoundaryEntry& bc, double start) const {
  const Step& st = _model.steps[k];
  Motion mo;
  mo.acceleration = bc.type == BoundaryType::Acceleration;
  if (bc.amplitude >= 0) {
    const Amplitude& a = _model.amplitudes[bc.amplitude];
    mo.m = a.absolute ? 1.0 : bc.value;
    // carried over unchanged: a step-time amplitude holds its end value, a total-time one goes on
    if (!bc.propagated || a.time == Amplitude::TimeBase::Total) {
      mo.amplitude = bc.amplitude;
      mo.x0 = a.time == Amplitude::TimeBase::Step ? 0.0 : start;
    } else {
      mo.p = end_rate(k - 1, bc);
    }
    return mo;
  }
  if (bc.propagated) {
    mo.p = end_rate(k - 1, bc);
  } else if (!st.ramp_default || (!mo.acceleration && velocity_steps_at_once(st))) {
    mo.p = bc.value;
  } else { // RAMP from the rate prescribed at the end of the previous step
    mo.p = end_rate(k - 1, bc);
    mo.s = st.inc.period > 0 ? (bc.value - mo.p) / st.inc.period : 0.0;
  }
  return mo;
}

double StepLoads::end_rate(int k, const BoundaryEntry& bc) const {
  if (k < 0) return 0.0;
  double start = 0.0; // total time at the start of step k
  for (int j = 0; j < k; ++j) start += _model.steps[j].inc.period;
  for (const BoundaryEntry& b : _model.steps[k].boundary)
    if (b.node == bc.node && b.dof == bc.dof) {
      if (b.type != bc.type) return 0.0;
      const double T = _model.steps[k].inc.period;
      return motion(make_motion(k, b, start), T, T, 0);
    }
  return 0.0;
}

void StepLoads::add_motion(const BoundaryEntry& bc, LocalIndex s) {
  check_motion(bc);
  std::erase_if(_bc, [&](const auto& e) { return e.first == s; });
  std::erase_if(_motion, [&](const Motion& m) { return m.slot == s; });
  Motion mo = make_motion(_step_index, bc, _step_start);
  mo.slot = s;
  _motion.push_back(mo);
  _prescribed[s] = 1;
}

bool StepLoads::add_local_motion(const BoundaryEntry& bc, int d,
                                 const std::array<LocalIndex, 3>& slots,
                                 const std::array<double, 3>& axis, const ConstraintSet& rows) {
  check_motion(bc);
  const int row = rows.bc_row(bc.node, d);
  if (row < 0) return false;
  std::erase_if(_local, [&](const LocalBc& l) { return l.row == row; });
  LocalBc l;
  l.node = bc.node;
  l.dof = d;
  l.row = row;
  l.moving = true;
  l.motion = make_motion(_step_index, bc, _step_start);
  l.slots = slots;
  l.axis = axis;
  _local.push_back(l);
  if (std::find(_local_keys.begin(), _local_keys.end(), std::make_pair(bc.node, d)) ==
      _local_keys.end())
    _local_keys.emplace_back(bc.node, d);
  return true;
}

void StepLoads::check_motion(const BoundaryEntry& bc) const {
  if (bc.type == BoundaryType::Acceleration && _step.procedure != Procedure::Dynamic)
    throw InputError(
        bc.loc, fmt::format("node {}", _model.node_label(bc.node)),
        fmt::format("a prescribed acceleration (*BOUNDARY, TYPE=ACCELERATION{}) needs a *DYNAMIC "
                    "step; step {} is *{}. Prescribe a displacement or velocity there, or remove "
                    "the condition with OP=NEW",
                    bc.propagated ? ", carried over from an earlier step" : "", _step.number,
                    procedure_name(_step.procedure)));
}

double StepLoads::motion(const Motion& mo, double t0, double t1, int which) const {
  if (mo.amplitude >= 0) {
    const Amplitude& a = _model.amplitudes[mo.amplitude];
    const double x0 = mo.x0 + t0, x1 = mo.x0 + t1;
    switch (which) {
    case 0:
      return mo.m * a.at(x1);
    case 1:
      return mo.m * a.slope(x1);
    case 2:
      return mo.m * a.integral(x0, x1);
    default:
      return mo.m * a.integral2(x0, x1);
    }
  }
  const double dt = t1 - t0;
  switch (which) {
  case 0:
    return mo.p + mo.s * t1;
  case 1:
    return mo.s;
  case 2:
    return mo.p * dt + 0.5 * mo.s * (t1 * t1 - t0 * t0);
  default:
    return (mo.p + mo.s * t0) * 0.5 * dt * dt + mo.s * dt * dt * dt / 6.0;
  }
}

void StepLoads::apply_prescribed_motion(double t0, double t1, std::span<const double> u0,
                                        std::span<const double> v0, std::span<double> u) const {
  for (const Motion& mo : _motion) {
    const LocalIndex s = mo.slot;
    if (mo.acceleration)
      u[s] = u0[s] + (v0.empty() ? 0.0 : v0[s]) * (t1 - t0) + motion(mo, t0, t1, 3);
    else
      u[s] = u0[s] + motion(mo, t0, t1, 2);
  }
}

void StepLoads::mark_motion(std::span<std::uint8_t> mask) const {
  for (const Motion& mo : _motion) mask[static_cast<std::size_t>(mo.slot)] = 1;
}

void StepLoads::prescribed_rates(double t0, double t1, std::span<const double> v0,
                                 std::span<double> v, std::span<double> a) const {
  if (v.empty() || a.empty()) return;
  for (const Motion& mo : _motion) {
    const LocalIndex s = mo.slot;
    if (mo.acceleration) {
      v[s] = (v0.empty() ? 0.0 : v0[s]) + motion(mo, t0, t1, 2);
      a[s] = motion(mo, t0, t1, 0);
    } else {
      v[s] = motion(mo, t0, t1, 0);
      a[s] = motion(mo, t0, t1, 1);
    }
  }
}

void StepLoads::prescribed_local_rates(double t0, double t1, std::span<const double> v0,
                                       std::span<double> v, std::span<double> a) const {
  if (v.empty() || a.empty()) return;
  for (const LocalBc& l : _local) {
    if (!l.moving) continue;
    const auto along = [&](std::span<const double> x) {
      double c = 0.0;
      for (int j = 0; j < 3; ++j)
        if (l.slots[j] >= 0) c += l.axis[j] * x[l.slots[j]];
      return c;
    };
    const Motion& mo = l.motion;
    const double vq = mo.acceleration ? (v0.empty() ? 0.0 : along(v0)) + motion(mo, t0, t1, 2)
                                      : motion(mo, t0, t1, 0);
    const double aq = motion(mo, t0, t1, mo.acceleration ? 0 : 1);
    const double dv = vq - along(v), da = aq - along(a);
    for (int j = 0; j < 3; ++j)
      if (l.slots[j] >= 0) {
        v[l.slots[j]] += l.axis[j] * dv;
        a[l.slots[j]] += l.axis[j] * da;
      }
  }
}

} // namespace gapfem
