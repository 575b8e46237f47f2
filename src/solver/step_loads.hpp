#pragma once
/// @file step_loads.hpp
/// Values of boundary conditions, loads, predefined temperatures and interference allowances at a
/// step time, following Abaqus: without an amplitude a new or changed value is ramped from the
/// value at the end of the previous step (RAMP, the default in static steps) or applied at once
/// (STEP); with an amplitude the magnitude is scaled by a(t) (VALUE=ABSOLUTE: a(t) itself);
/// unchanged (propagated) values stay constant; removed values go to zero (temperatures to the
/// initial condition) with the step's default variation; the reaction of a released boundary
/// condition is applied as a load that follows the same variation down to zero.
#include "fem/assembler.hpp"
#include "fem/dof_map.hpp"

#include <array>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace gapfem {

struct Model;
struct Step;
struct BoundaryEntry;
class Discretization;
class ConstraintSet;

/// What a step leaves behind for the next one.
struct LoadHistory {
  std::map<std::pair<NodeId, int>, double> nodal; ///< CLOAD/CFLUX values at step end
  std::map<std::tuple<ElemId, int, int>, std::pair<double, double>>
      distributed;                          ///< magnitude, sink
  std::vector<double> temperature;          ///< predefined field per node
  std::vector<double> temperature_gradient; ///< its gradients, 2 per node (empty: none)
  std::vector<std::uint8_t> prescribed;     ///< per slot, in the last step
  std::vector<double> reaction;             ///< per slot, at the end of the last step
  /// Boundary conditions in local systems (*TRANSFORM): (node, DOF) -> reaction at step end.
  std::map<std::pair<NodeId, int>, double> local_reaction;
};

class StepLoads {
 public:
  /// u_now: solution per slot at the start of the step.
  StepLoads(const Model& model, const Discretization& disc, int step_index,
            const LoadHistory& history, std::span<const double> u_now,
            double step_start_total_time);

  const EquationMap& equations() const { return _eqmap; }
  /// Warnings found while resolving the step's loads (reported with the run's warnings).
  const std::vector<std::string>& warnings() const { return _warnings; }
  std::span<const std::uint8_t> prescribed() const { return _prescribed; }
  double period() const { return _period; }

  /// Write the prescribed values at `step_time` into u (prescribed slots only).
  void apply_prescribed(double step_time, std::span<double> u) const;
  /// Prescribed velocities and accelerations (*BOUNDARY, TYPE=VELOCITY|ACCELERATION; docs/theory/
  /// dynamics.md, "Base motion"): the displacement at step time t1 from the committed state at
  /// t0 (u0, v0 per slot; v0 empty in steps without rates), the prescribed rate integrated
  /// exactly over [t0, t1]: u0 + int v, or u0 + v0 (t1 - t0) + the double integral of a.
  void apply_prescribed_motion(double t0, double t1, std::span<const double> u0,
                               std::span<const double> v0, std::span<double> u) const;
  /// Their velocities and accelerations at t1 into v and a (per slot): the prescribed ones, a
  /// prescribed acceleration's velocity integrated from v0 at t0 (v0 may alias v).
  void prescribed_rates(double t0, double t1, std::span<const double> v0, std::span<double> v,
                        std::span<double> a) const;
  /// The same for the conditions in local systems (*TRANSFORM nodes): the component along each
  /// one's local axis of v and a at its node's slots becomes the prescribed one (a committed state
  /// follows the prescribed motion exactly, as at a global DOF).
  void prescribed_local_rates(double t0, double t1, std::span<const double> v0, std::span<double> v,
                              std::span<double> a) const;
  /// 1 at the slots of those conditions in `mask` (per slot).
  void mark_motion(std::span<std::uint8_t> mask) const;
  bool has_motion() const { return !_motion.empty(); }
  /// Boundary conditions of this step in local systems (*TRANSFORM nodes): (node, DOF 1-6).
  std::span<const std::pair<NodeId, int>> local_bcs() const { return _local_keys; }
  /// Their values at step time t1 as the right-hand sides of their constraint rows; a velocity or
  /// acceleration integrated exactly over [t0, t1] from the committed state (u0, v0, a0 per slot,
  /// v0 and a0 empty without rates) as apply_prescribed_motion does. In dynamic steps also the
  /// rates of the right-hand sides: the prescribed ones, or a displacement's the node's committed
  /// velocity and acceleration along the axis (an impact leaves them as they are).
  void apply_local_bcs(double t0, double t1, std::span<const double> u0, std::span<const double> v0,
                       std::span<const double> a0, ConstraintSet& rows) const;
  /// Whether a velocity or acceleration is prescribed in a local system (its row's right-hand
  /// side moves with its own rates: the step's start makes the velocities compatible with it).
  bool has_local_motion() const;
  /// Add the concentrated loads (and released-reaction loads) at `step_time` to f_ext (per slot).
  void add_nodal_loads(double step_time, std::span<double> f_ext) const;
  /// The distributed loads active at `step_time`.
  void distributed_loads(double step_time, std::vector<ActiveLoad>& out) const;
  /// Predefined temperature per node at `step_time` (empty span: none in this model).
  void temperatures(double step_time, std::span<double> T) const;
  bool has_temperature_field() const { return _has_temperature; }
  /// Through-section gradients at `step_time`, 2 per node (only when has_temperature_gradients()).
  void temperature_gradients(double step_time, std::span<double> G) const;
  bool has_temperature_gradients() const { return _has_gradient; }
  /// Interference allowance of each gap element at `step_time` (0 where none).
  void interference(double step_time, Discretization& disc) const;
  /// SHRINK allowances need the clearance at the step start: set v for element e.
  void set_shrink_allowance(ElemId e, double v);
  /// The allowance set for element e (0 when none).
  double shrink_allowance(ElemId e) const;
  const std::vector<ElemId>& shrink_elements() const { return _shrink_elems; }

  /// Record the end-of-step values (call after the last increment); `rows` holds the
  /// multipliers (reactions) of the boundary conditions in local systems.
  void finish(double step_period_time, std::span<const double> reaction, const ConstraintSet& rows,
              LoadHistory& history) const;

 private:
  struct Scalar {
    double start = 0.0, end = 0.0;
    int amplitude = -1;
    bool constant = false;
  };
  double value(const Scalar& s, double step_time) const;

  /// A prescribed velocity or acceleration q(t) of one slot: m a(x0 + t) with an amplitude,
  /// p + s t without (STEP, RAMP, or held at the previous step's end value).
  struct Motion {
    LocalIndex slot = -1;
    bool acceleration = false;
    int amplitude = -1;
    double m = 0.0, x0 = 0.0; ///< magnitude; amplitude time at step time 0
    double p = 0.0, s = 0.0;
  };
  /// q at t1 (which 0), its slope (1), its integral over [t0, t1] (2), its double integral
  /// from t0 to t1 (3).
  double motion(const Motion& mo, double t0, double t1, int which) const;
  /// The motion of condition `bc` in step `k` (its step time starting at total time `start`).
  Motion make_motion(int k, const BoundaryEntry& bc, double start) const;
  /// The rate that the condition on bc's DOF of bc's type prescribed at the end of step k (0
  /// when it prescribed none there).
  double end_rate(int k, const BoundaryEntry& bc) const;
  /// _motion: a TYPE=VELOCITY or ACCELERATION condition (checked against the procedure).
  void add_motion(const BoundaryEntry& bc, LocalIndex s);

  // The constructor's stages, in this order (each appends to the members it names).
  /// _bc, _local, _prescribed; a warning for conditions on DOFs no element has.
  void set_boundary_conditions(const Discretization& disc, std::span<const double> u_now);
  /// A condition on local DOF d (1-6) of a transformed node, whose value is `now` at the step
  /// start; false when the node's constraint rows lack it (no element has the DOF).
  bool add_local_bc(const BoundaryEntry& bc, int d, double now, const ConstraintSet& rows);
  /// A velocity or acceleration on local DOF d of a transformed node (its global slots and the
  /// local axis' components); false as add_local_bc.
  bool add_local_motion(const BoundaryEntry& bc, int d, const std::array<LocalIndex, 3>& slots,
                        const std::array<double, 3>& axis, const ConstraintSet& rows);
  /// A TYPE=ACCELERATION condition outside a *DYNAMIC step: the error.
  void check_motion(const BoundaryEntry& bc) const;
  /// _nodal, _nodal_keys: this step's CLOAD/CFLUX and the previous step's removed ones.
  void set_concentrated_loads(const DofMap& dofs, const LoadHistory& history);
  /// _nodal: reactions of released boundary conditions, ramped to zero.
  void set_released_reactions(const DofMap& dofs, const LoadHistory& history);
  void add_nodal(const DofMap& dofs, NodeId n, int d, const std::optional<std::array<double, 9>>& Q,
                 const Scalar& sc);
  /// _dist: this step's loads and the previous step's removed ones.
  void set_distributed_loads(const LoadHistory& history, const Step* prev);
  /// _temp, _temp_base, _grad, _grad_base.
  void set_temperatures(const Discretization& disc, const LoadHistory& history, const Step* prev);
  /// _interf, _shrink_elems.
  void set_interference();

  const Model& _model;
  const Step& _step;
  double _period = 1.0;
  double _step_start = 0.0;
  EquationMap _eqmap;
  std::vector<std::uint8_t> _prescribed;
  std::vector<std::string> _warnings;
  std::vector<std::pair<LocalIndex, Scalar>> _bc;
  std::vector<Motion> _motion;
  int _step_index = 0;
  struct NodalEntry {
    LocalIndex slot;
    Scalar value;
    double factor = 1.0; ///< component of a load given in a local system
  };
  std::vector<NodalEntry> _nodal;
  struct LocalBc {
    NodeId node{};
    int dof = 0;  ///< 1-6
    int row = -1; ///< its ConstraintSet row
    Scalar value;
    bool moving = false; ///< a velocity or acceleration: `motion`
    Motion motion{};
    std::array<LocalIndex, 3> slots{-1, -1, -1}; ///< the node's global slots of the DOF's kind
    std::array<double, 3> axis{};                ///< the local axis in them
  };
  std::vector<LocalBc> _local;
  std::vector<std::pair<NodeId, int>> _local_keys;
  std::vector<std::pair<std::pair<NodeId, int>, Scalar>> _nodal_keys;
  struct Dist {
    const DistributedLoad* load;
    DistributedLoad removed; ///< storage for removed loads (load points here)
    Scalar magnitude, sink;
  };
  std::vector<Dist> _dist;
  std::vector<std::pair<NodeId, Scalar>> _temp;
  std::vector<double> _temp_base;
  bool _has_temperature = false;
  std::vector<std::pair<NodeId, std::array<Scalar, 2>>> _grad;
  std::vector<double> _grad_base; ///< 2 per node
  bool _has_gradient = false;
  struct Interf {
    ElemId elem;
    double allowance;
    int amplitude;
  };
  std::vector<Interf> _interf;
  std::vector<ElemId> _shrink_elems;
};

} // namespace gapfem
