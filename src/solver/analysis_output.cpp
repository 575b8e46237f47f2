#include "solver/analysis_impl.hpp"
#include "solver/finite_check.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace gapfem {

void Analysis::Impl::to_local_systems(NodeResults& nr) const {
  if (model.transforms.empty()) return;
  const ConstraintSet& rows = disc.constraints();
  auto rotate = [](const std::array<double, 9>& Q, Vec3& v) {
    const Vec3 g = v;
    for (int i = 0; i < 3; ++i) v[i] = Q[3 * i] * g[0] + Q[3 * i + 1] * g[1] + Q[3 * i + 2] * g[2];
  };
  for (NodeId n = 0; n < static_cast<NodeId>(model.node_transform.size()); ++n) {
    const auto Q = model.node_axes(n);
    if (!Q) continue;
    nr.local_axes[n] = *Q;
    for (auto* v : {&nr.U, &nr.UR, &nr.CF, &nr.CM, &nr.V, &nr.VR, &nr.A, &nr.AR})
      if (!v->empty()) rotate(*Q, (*v)[n]);
    for (int d = 1; d <= 6; ++d) {
      const int r = rows.bc_row(n, d);
      const double reaction = r >= 0 && rows.active(r) ? -rows.mult_committed[r] : 0.0;
      (d <= 3 ? nr.RF[n][d - 1] : nr.RM[n][d - 4]) = reaction;
    }
  }
}

std::optional<double> Analysis::Impl::monitor_value(const Step& step, int increment,
                                                    bool last) const {
  if (!step.monitor) return std::nullopt;
  const DofMonitor& m = *step.monitor;
  if (!last && (m.frequency <= 0 || increment % m.frequency != 0)) return std::nullopt;
  DofType d{};
  if (!dof_from_abaqus(m.dof, d)) return std::nullopt;
  const LocalIndex s = disc.dofs().slot(m.node, d);
  if (s < 0) return std::nullopt; // the node does not carry the DOF: a blank column
  return st.u_start[static_cast<std::size_t>(s)];
}

/// A frame of the committed state with what is due at it, or nothing when nothing is due;
/// `field_elements` tells whether due field output asks for element variables. `repeat`: the
/// increment's regular output is already written (a step ended by *RESTART, READ, END STEP);
/// only what is due because it is now the last one follows.
std::optional<Frame> Analysis::Impl::frame_due(const Step& step, const StepProblem& prob,
                                               int increment, bool last, double dt, bool repeat,
                                               bool& field_elements) const {
  bool any = last;
  auto due = [&](int freq) {
    const bool d = freq > 0 && (repeat ? increment % freq != 0 : increment % freq == 0 || last);
    any |= d;
    return d;
  };
  Frame fr;
  fr.step = step.number;
  fr.increment = increment;
  fr.step_time = prob.context().step_time;
  fr.total_time = prob.context().total_time;
  fr.dt = dt;
  fr.last_in_step = last;
  for (const auto& r : step.node_prints) fr.node_print_due.push_back(due(r.frequency));
  for (const auto& r : step.el_prints) fr.el_print_due.push_back(due(r.frequency));
  field_elements = false;
  fr.field_due = step.field_outputs.empty() && last;
  for (const auto& r : step.field_outputs) {
    fr.field_output_due.push_back(due(r.frequency));
    if (!fr.field_output_due.back()) continue;
    fr.field_due = true;
    field_elements |= !r.elem_vars.empty();
  }
  for (const auto& r : step.file_outputs) fr.file_output_due.push_back(due(r.frequency));
  if (!any) return std::nullopt;
  return fr;
}

namespace {

/// Every nodal vector of a frame sized for the model and zero (temperatures through shells too).
void zero_node_results(const DofMap& dofs, NodeId nn, NodeResults& nr) {
  nr.U.assign(nn, Vec3{});
  nr.UR = nr.RF = nr.RM = nr.CF = nr.CM = nr.U;
  nr.NT.assign(nn, 0.0);
  nr.RFL = nr.CFL = nr.NT;
  nr.temperature_points = std::max(1, dofs.max_temperature_points());
  nr.NT_more.assign(static_cast<std::size_t>(nr.temperature_points - 1) * nn, 0.0);
  nr.RFL_more = nr.CFL_more = nr.NT_more;
}

} // namespace

/// The frame's nodal results: solution, reactions and loads per node (local systems at
/// *TRANSFORM nodes), and the predefined temperature field of a stress analysis.
void Analysis::Impl::frame_nodes(StepProblem& prob, Frame& fr) {
  const DofMap& dofs = disc.dofs();
  const NodeId nn = model.mesh.n_nodes();
  NodeResults& nr = fr.nodes;
  zero_node_results(dofs, nn, nr);
  const std::size_t more = static_cast<std::size_t>(nr.temperature_points - 1);
  nr.dof_mask.resize(nn);
  // velocities and accelerations: the committed ones of a dynamic step, the increment's end values
  // (empty in other steps, which have none)
  const bool rates = !st.v_start.empty() && st.v_start.size() == st.u_start.size() &&
                     st.a_start.size() == st.u_start.size();
  nr.V.clear();
  nr.VR.clear();
  nr.A.clear();
  nr.AR.clear();
  if (rates) nr.V = nr.VR = nr.A = nr.AR = nr.U;
  const std::vector<double> reaction = prob.reactions();
  const std::vector<double> cload = prob.concentrated_loads();
  for (LocalIndex s = 0; s < dofs.n_slots(); ++s) {
    const NodeId n = dofs.slot_node(s);
    const int d = static_cast<int>(dofs.slot_dof(s));
    const double u = st.u_start[s];
    if (d < 3) {
      nr.U[n][d] = u;
      nr.RF[n][d] = reaction[s];
      nr.CF[n][d] = cload[s];
      if (rates) {
        nr.V[n][d] = st.v_start[s];
        nr.A[n][d] = st.a_start[s];
      }
      nr.any_displacement = true;
    } else if (d < 6) {
      nr.UR[n][d - 3] = u;
      nr.RM[n][d - 3] = reaction[s];
      nr.CM[n][d - 3] = cload[s];
      if (rates) {
        nr.VR[n][d - 3] = st.v_start[s];
        nr.AR[n][d - 3] = st.a_start[s];
      }
      nr.any_rotation = true;
    } else if (d == static_cast<int>(DofType::NT)) {
      nr.NT[n] = u;
      nr.RFL[n] = reaction[s];
      nr.CFL[n] = cload[s];
      nr.any_temperature = true;
    } else { // DOF 12 … through a heat-transfer shell's thickness
      const std::size_t k = more * static_cast<std::size_t>(n) +
                            static_cast<std::size_t>(temperature_index(dofs.slot_dof(s)) - 1);
      nr.NT_more[k] = u;
      nr.RFL_more[k] = reaction[s];
      nr.CFL_more[k] = cload[s];
    }
  }
  for (NodeId n = 0; n < nn; ++n) nr.dof_mask[n] = dofs.mask(n);
  to_local_systems(nr);
  // Stress analyses report the predefined temperature field as NT.
  if (!nr.any_temperature && disc.has_temperature_field()) {
    nr.NT = st.T_start;
    nr.any_temperature = true;
    nr.nt_field.assign(static_cast<std::size_t>(nn), 0);
    for (const auto& b : disc.blocks())
      if (b.uses_temperature)
        for (ElemId e : b.elements)
          for (NodeId n : model.mesh.element_nodes(e)) nr.nt_field[n] = 1;
  }
}

/// The element results the frame's requests need (every element at the last frame).
std::vector<char> Analysis::Impl::elements_needed(const Step& step, bool field_elements,
                                                  const Frame& fr) const {
  const ElemId ne = model.mesh.n_elements();
  std::vector<char> need(static_cast<std::size_t>(ne), fr.last_in_step || field_elements ? 1 : 0);
  for (std::size_t k = 0; k < step.el_prints.size(); ++k) {
    if (!fr.el_print_due[k]) continue;
    const auto& r = step.el_prints[k];
    if (r.elset.empty())
      std::fill(need.begin(), need.end(), 1);
    else
      for (ElemId e : r.elements) need[e] = 1;
  }
  for (std::size_t k = 0; k < step.file_outputs.size(); ++k) {
    const auto& r = step.file_outputs[k];
    if (!fr.file_output_due[k] || !r.element) continue;
    if (r.set.empty())
      std::fill(need.begin(), need.end(), 1);
    else
      for (ElemId e : r.members) need[e] = 1;
  }
  return need;
}

namespace {
/// Energies, volumes and coordinates describe a state (a perturbation has no change of them);
/// kernels report them always, frames keep them where the step asks for them.
bool is_state_var(ElemVar v) {
  return v == ElemVar::ENER || v == ElemVar::ELSE || v == ElemVar::EVOL || v == ElemVar::COORD;
}

/// The element variables some output request of the step names.
std::array<bool, kNumElemVars> requested_elem_vars(const Step& step) {
  std::array<bool, kNumElemVars> want{};
  auto add = [&](ElemVar v) { want[static_cast<std::size_t>(v)] = true; };
  for (const ElPrintRequest& r : step.el_prints)
    for (ElemVar v : r.vars) add(v);
  for (const FieldOutputRequest& r : step.field_outputs)
    for (ElemVar v : r.elem_vars) add(v);
  for (const HistoryOutputRequest& r : step.history_outputs)
    for (const auto& [v, set] : r.elem_vars) add(v);
  for (const FileOutputRequest& r : step.file_outputs)
    for (ElemVar v : r.elem_vars) add(v);
  return want;
}
} // namespace

void Analysis::Impl::frame_elements(const Step& step, StepProblem& prob, bool field_elements,
                                    Frame& fr) {
  const std::vector<char> need = elements_needed(step, field_elements, fr);
  const std::array<bool, kNumElemVars> want = requested_elem_vars(step);
  const ElemId ne = model.mesh.n_elements();
  fr.element_slot.assign(static_cast<std::size_t>(ne), -1);
  const FieldView fields = prob.fields();
  for (ElemId e = 0; e < ne; ++e) {
    if (!need[e]) continue;
    fr.element_slot[e] = static_cast<std::int32_t>(fr.elements.size());
    fr.elements.push_back({e, {}});
    assembler.recover(e, fields, prob.context(), fr.elements.back().data);
    std::erase_if(fr.elements.back().data.blocks, [&](const OutputBlock& b) {
      return is_state_var(b.var) && !want[static_cast<std::size_t>(b.var)];
    });
  }
}

void Analysis::Impl::perturbation_elements(const Step& step, StepProblem& prob,
                                           std::span<const double> du, bool field_elements,
                                           Frame& fr) {
  const std::vector<char> need = elements_needed(step, field_elements, fr);
  const ElemId ne = model.mesh.n_elements();
  fr.element_slot.assign(static_cast<std::size_t>(ne), -1);
  FieldView base = prob.fields();
  std::vector<double> moved(base.u_start.begin(), base.u_start.end());
  double big = 0.0;
  for (double v : du) big = std::max(big, std::abs(v));
  const double eps = big > 0.0 ? 1e-6 * model.model_size() / big : 0.0;
  for (std::size_t k = 0; k < moved.size(); ++k) moved[k] += eps * du[k];
  base.u = base.u_start;
  FieldView shifted = base;
  shifted.u = moved;
  ElementRecovery r0;
  for (ElemId e = 0; e < ne; ++e) {
    if (!need[e]) continue;
    fr.element_slot[e] = static_cast<std::int32_t>(fr.elements.size());
    fr.elements.push_back({e, {}});
    ElementRecovery& r1 = fr.elements.back().data;
    r0.clear();
    assembler.recover(e, base, prob.context(), r0);
    assembler.recover(e, shifted, prob.context(), r1);
    // the perturbation's own values (a gap's record and the energies describe a state, not a
    // change: left out)
    r1.gap.reset();
    r1.strain_energy.reset();
    r1.artificial_energy.reset();
    for (std::size_t b = 0; b < r1.blocks.size() && b < r0.blocks.size(); ++b)
      for (std::size_t k = 0; k < r1.blocks[b].values.size(); ++k)
        r1.blocks[b].values[k] =
            eps > 0.0 ? (r1.blocks[b].values[k] - r0.blocks[b].values[k]) / eps : 0.0;
    std::erase_if(r1.blocks, [](const OutputBlock& b) { return is_state_var(b.var); });
  }
}

void Analysis::Impl::perturbation_nodes(std::span<const double> slots, Frame& fr) const {
  const DofMap& dofs = disc.dofs();
  const NodeId nn = model.mesh.n_nodes();
  NodeResults& nr = fr.nodes;
  zero_node_results(dofs, nn, nr);
  nr.dof_mask.resize(nn);
  for (NodeId n = 0; n < nn; ++n) nr.dof_mask[n] = dofs.mask(n);
  for (LocalIndex s = 0; s < dofs.n_slots(); ++s) {
    const int d = static_cast<int>(dofs.slot_dof(s));
    const NodeId n = dofs.slot_node(s);
    if (d < 3) {
      nr.U[n][d] = slots[s];
      nr.any_displacement = true;
    } else if (d < 6) {
      nr.UR[n][d - 3] = slots[s];
      nr.any_rotation = true;
    } else {
      nr.any_temperature = true;
    }
  }
  to_local_systems(nr);
}

void Analysis::Impl::write_frame(int index, StepProblem& prob, int increment, bool last, double dt,
                                 bool repeat) {
  const Step& step = model.steps[index];
  bool field_elements = false;
  std::optional<Frame> due = frame_due(step, prob, increment, last, dt, repeat, field_elements);
  if (!due) return;
  Frame& fr = *due;
  ScopedTimer timer(&stats, TimeCategory::Output);
  if (prob.integrator() && prob.integrator()->second_order()) fr.energies = st.energies();
  frame_nodes(prob, fr);
  frame_elements(step, prob, field_elements, fr);
  if (const std::string bad = first_non_finite_output(model, fr); !bad.empty())
    throw AnalysisError(non_finite_message(increment, bad));
  if (recoverer && (fr.field_due || last)) fr.substructures = recoverer->recover(model, index, fr);
  for (auto* w : writers) w->frame(model, index, fr);
}

double Analysis::Impl::damping_peak(StepProblem& prob) {
  bool any = false;
  for (const GapSection& g : model.gap_sections) any |= g.damping.given;
  if (!any) return 0.0;
  double peak = 0.0;
  ElementRecovery rec;
  const FieldView fields = prob.fields();
  for (auto& b : disc.blocks()) {
    if (element_info(b.type).family != ElementFamily::Gap) continue;
    for (std::size_t i = 0; i < b.size(); ++i) {
      assembler.recover(b.elements[i], fields, prob.context(), rec);
      if (rec.gap) peak = std::max(peak, std::abs(rec.gap->damping_force));
    }
  }
  return peak;
}

void Analysis::Impl::gap_samples(StepProblem& prob, IncrementInfo& info) {
  ScopedTimer timer(&stats, TimeCategory::Output);
  ElementRecovery rec;
  const FieldView fields = prob.fields();
  int closed = 0;
  for (auto& b : disc.blocks()) {
    if (element_info(b.type).family != ElementFamily::Gap) continue;
    for (std::size_t i = 0; i < b.size(); ++i) {
      assembler.recover(b.elements[i], fields, prob.context(), rec);
      if (!rec.gap) continue;
      info.gaps.push_back({b.elements[i], static_cast<float>(rec.gap->normal_force),
                           static_cast<float>(rec.gap->clearance), rec.gap->status});
      closed += rec.gap->status != ContactStatus::Open;
    }
  }
  info.gaps_closed = closed;
}

namespace {

/// The sums of the equilibrium self-check, in extended precision (loads near 1e308 do not
/// overflow them).
struct ForceBalance {
  std::array<long double, 3> reaction{}, applied{}, ground{};
  long double scale = 0.0;
  /// A force to ground (a spring to ground, a grounded element's net force, stabilization).
  void to_ground(int d, long double f) {
    ground[d] += f;
    scale += std::fabs(f);
  }
  void finish(StepChecks& c) const {
    long double err2 = 0.0;
    for (int d = 0; d < 3; ++d) {
      const long double e = reaction[d] + applied[d] - ground[d];
      err2 += e * e;
      c.reaction_sum[d] = static_cast<double>(reaction[d]);
      c.applied_sum[d] = static_cast<double>(applied[d]);
    }
    const long double err = std::sqrt(err2);
    c.equilibrium_error = static_cast<double>(err);
    c.force_scale = static_cast<double>(scale);
    c.relative_equilibrium = scale > 0 ? static_cast<double>(err / scale) : 0.0;
  }
};

/// Counts a gap's status and its penetration, tension and damping into the checks.
void count_gap(StepChecks& c, const GapRecord& g, double allowance, Label label) {
  ++c.n_gaps;
  switch (g.status) {
  case ContactStatus::Open:
    ++c.n_open;
    break;
  case ContactStatus::Closed:
    ++c.n_closed;
    break;
  case ContactStatus::Stick:
    ++c.n_stick;
    break;
  case ContactStatus::Slip:
    ++c.n_slip;
    break;
  }
  const double pen = -(g.clearance + allowance);
  if (g.status != ContactStatus::Open && pen > c.max_penetration) {
    c.max_penetration = pen;
    c.max_penetration_elem = label;
  }
  if (g.status != ContactStatus::Open && -g.normal_force > c.max_tensile_force) {
    c.max_tensile_force = -g.normal_force;
    c.max_tensile_elem = label;
  }
  c.max_damping_force = std::max(c.max_damping_force, std::abs(g.damping_force));
}

/// Elements that may hold the model to ground themselves: springs to ground, substructures
/// (their internal supports are condensed away), the deck's own elements. Their net force is a
/// force to ground; a free element's is zero and adds nothing.
bool may_be_grounded(ElementType t) {
  return t == ElementType::SPRING1 || t == ElementType::SUBSTRUCTURE || t == ElementType::USER;
}

} // namespace

void Analysis::Impl::hourglass_checks(StepProblem& prob, StepChecks& c) {
  for (auto& b : disc.blocks()) c.hourglass |= b.kernel->has_artificial_energy();
  if (!c.hourglass) return;
  // ALLAE and, to judge it, ALLSE of every continuum element
  const FieldView fields = prob.fields();
  ElementRecovery rec;
  for (auto& b : disc.blocks()) {
    const ElementTypeInfo& info = element_info(b.type);
    if (info.family != ElementFamily::Continuum || !info.displacement) continue;
    for (std::size_t i = 0; i < b.size(); ++i) {
      assembler.recover(b.elements[i], fields, prob.context(), rec);
      c.allae += rec.artificial_energy.value_or(0.0);
      c.allse += rec.strain_energy.value_or(0.0);
    }
  }
}

void Analysis::Impl::gap_checks(StepProblem& prob, StepChecks& c) {
  const FieldView fields = prob.fields();
  ElementRecovery rec;
  for (auto& b : disc.blocks()) {
    if (element_info(b.type).family != ElementFamily::Gap || !element_info(b.type).displacement)
      continue;
    for (std::size_t i = 0; i < b.size(); ++i) {
      assembler.recover(b.elements[i], fields, prob.context(), rec);
      if (rec.gap)
        count_gap(c, *rec.gap, b.interference.empty() ? 0.0 : b.interference[i],
                  model.element_label(b.elements[i]).key);
    }
  }
}

void Analysis::Impl::equilibrium_checks(StepProblem& prob, StepChecks& c) {
  const DofMap& dofs = disc.dofs();
  ForceBalance fb;
  const std::vector<double> reaction = prob.reactions();
  for (LocalIndex s = 0; s < dofs.n_slots(); ++s) {
    const int d = static_cast<int>(dofs.slot_dof(s));
    if (d >= 3) continue;
    fb.reaction[d] += reaction[s];
    fb.applied[d] += st.f_ext[s];
    fb.scale += std::fabs(static_cast<long double>(reaction[s])) + std::fabs(st.f_ext[s]);
  }
  // reactions of boundary conditions in local systems: -lambda along each held local axis
  const ConstraintSet& rows = disc.constraints();
  for (NodeId n = 0; n < static_cast<NodeId>(model.node_transform.size()); ++n) {
    const auto Q = model.node_axes(n);
    if (!Q) continue;
    for (int d = 0; d < 3; ++d) {
      const int row = rows.bc_row(n, d + 1);
      if (row < 0 || !rows.active(row)) continue;
      const double R = -rows.mult_trial[row];
      for (int j = 0; j < 3; ++j) fb.reaction[j] += static_cast<long double>(R) * (*Q)[3 * d + j];
      fb.scale += std::abs(R);
    }
  }
  // the stabilization's viscous forces hold the model like springs to ground
  const auto fstab = prob.stabilization_forces();
  for (std::size_t k = 0; k < fstab.size(); ++k) {
    const int d = static_cast<int>(dofs.slot_dof(static_cast<LocalIndex>(k)));
    if (d < 3 && fstab[k] != 0.0) fb.to_ground(d, fstab[k]);
  }
  // dynamic steps: the inertia forces (and HHT's history term) balance the rest; at prescribed
  // slots the reactions are the physical forces (StepProblem::reactions), so M a alone there
  const auto fdyn = prob.inertial_forces();
  const auto inertia = prob.inertia_forces();
  const auto presc = prob.prescribed();
  for (std::size_t k = 0; k < fdyn.size(); ++k) {
    const int d = static_cast<int>(dofs.slot_dof(static_cast<LocalIndex>(k)));
    const bool fixed = k < presc.size() && presc[k] && inertia.size() == fdyn.size();
    const double f = fixed ? inertia[k] : fdyn[k];
    if (d < 3 && f != 0.0) fb.to_ground(d, f);
  }
  grounded_forces(prob, fb.ground, fb.scale);
  fb.finish(c);
}

void Analysis::Impl::grounded_forces(StepProblem& prob, std::array<long double, 3>& ground,
                                     long double& scale) {
  const DofMap& dofs = disc.dofs();
  auto add_net = [&](const std::array<long double, 3>& net) {
    for (int d = 0; d < 3; ++d) {
      ground[d] += net[d];
      scale += std::fabs(net[d]);
    }
  };
  const FieldView fields = prob.fields();
  std::vector<double> r;
  std::vector<LocalIndex> slots;
  for (auto& b : disc.blocks()) {
    if (!may_be_grounded(b.type)) continue;
    for (std::size_t i = 0; i < b.size(); ++i) {
      assembler.element_residual(b.elements[i], fields, prob.context(), r, slots);
      std::array<long double, 3> net{};
      for (std::size_t k = 0; k < r.size(); ++k)
        if (const int d = static_cast<int>(dofs.slot_dof(slots[k])); d < 3) net[d] += r[k];
      add_net(net);
    }
  }
  if (disc.matrix_terms().empty()) return; // *MATRIX ASSEMBLE terms may be grounded too
  std::vector<double> f(static_cast<std::size_t>(dofs.n_slots()), 0.0);
  std::array<double, kNumFields> flux{};
  std::array<long, kNumFields> count{};
  disc.matrix_terms().assemble(st.u_start, f, nullptr, dofs, flux, count);
  std::array<long double, 3> net{};
  for (LocalIndex s = 0; s < dofs.n_slots(); ++s)
    if (const int d = static_cast<int>(dofs.slot_dof(s)); d < 3)
      net[d] += f[static_cast<std::size_t>(s)];
  add_net(net);
}

StepChecks Analysis::Impl::checks(StepProblem& prob) {
  StepChecks c;
  hourglass_checks(prob, c);
  gap_checks(prob, c);
  equilibrium_checks(prob, c);
  return c;
}

} // namespace gapfem
