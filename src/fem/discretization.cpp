#include "fem/discretization.hpp"

#include "common/log.hpp"
#include "fem/element_gather.hpp"
#include "model/model.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <map>
#include <tuple>

namespace gapfem {

Discretization::Discretization(const Model& model, const KernelOptions& options) : _model(model) {
  const Mesh& mesh = model.mesh;
  const ElemId ne = mesh.n_elements();
  // Group elements by (type, property), keeping deck order within a block.
  std::map<std::tuple<int, int, int, int>, int> block_of;
  _elem_block.assign(static_cast<std::size_t>(ne), -1);
  _elem_index.assign(static_cast<std::size_t>(ne), -1);
  for (ElemId e = 0; e < ne; ++e) {
    const PropertyRef prop =
        model.element_property.empty() ? PropertyRef{} : model.element_property[e];
    const auto key =
        std::make_tuple(static_cast<int>(mesh.elem_types[e]), static_cast<int>(mesh.variant(e)),
                        static_cast<int>(prop.kind), static_cast<int>(prop.index));
    auto [it, inserted] = block_of.try_emplace(key, static_cast<int>(_blocks.size()));
    if (inserted) {
      _blocks.emplace_back();
      _blocks.back().type = mesh.elem_types[e];
      _blocks.back().variant = mesh.variant(e);
      _blocks.back().property = prop;
    }
    auto& b = _blocks[it->second];
    _elem_block[e] = it->second;
    _elem_index[e] = static_cast<LocalIndex>(b.elements.size());
    b.elements.push_back(e);
  }
  // Kernels and DOF masks.
  std::vector<DofMask> masks(static_cast<std::size_t>(mesh.n_nodes()), 0);
  for (auto& b : _blocks) {
    b.kernel = make_element_kernel(
        KernelContext{model, b.type, b.property, b.elements, b.variant, options});
    const ElementKernel& k = *b.kernel;
    b.n_nodes = k.n_nodes();
    b.n_dofs = k.n_dofs();
    b.n_state = k.n_state();
    b.n_mult = k.n_multipliers();
    b.uses_temperature = k.uses_temperature_field();
    _uses_temperature_field |= b.uses_temperature;
    _has_gaps |= element_info(b.type).family == ElementFamily::Gap;
    for (ElemId e : b.elements) {
      const auto nodes = mesh.element_nodes(e);
      for (int a = 0; a < b.n_nodes; ++a)
        for (DofType d : k.node_dofs(a)) masks[nodes[a]] |= dof_bit(d);
    }
  }
  // Constraints bring their DOFs to nodes no element carries them at (reference nodes).
  for (const LinearConstraint& c : model.constraints)
    for (const ConstraintTerm& t : c.terms)
      if (t.activates) masks[t.node] |= dof_bit(t.dof);
  // so do the matrices of *MATRIX ASSEMBLE
  for (const MatrixTerm& t : model.matrix_terms) {
    DofType r{}, c{};
    if (dof_from_abaqus(t.row_dof, r)) masks[t.row_node] |= dof_bit(r);
    if (dof_from_abaqus(t.col_dof, c)) masks[t.col_node] |= dof_bit(c);
  }
  _dofs = DofMap(std::move(masks));
  _constraints = ConstraintSet(model, _dofs);
  _matrix_terms = MatrixTerms(model, _dofs);
  // Gather lists and storage.
  for (std::size_t bi = 0; bi < _blocks.size(); ++bi) {
    auto& b = _blocks[bi];
    b.slots.resize(b.size() * static_cast<std::size_t>(b.n_dofs));
    for (std::size_t i = 0; i < b.size(); ++i) {
      const auto nodes = mesh.element_nodes(b.elements[i]);
      std::size_t k = 0;
      for (int a = 0; a < b.n_nodes; ++a)
        for (DofType d : b.kernel->node_dofs(a))
          b.slots[i * b.n_dofs + k++] = _dofs.slot(nodes[a], d);
    }
    b.state_committed.assign(b.size() * static_cast<std::size_t>(b.n_state), 0.0);
    b.mult_committed.assign(b.size() * static_cast<std::size_t>(b.n_mult), 0.0);
    if (b.n_mult > 0) {
      b.mult_offset = _n_mult;
      _mult_blocks.emplace_back(static_cast<int>(bi), _n_mult);
      _n_mult += static_cast<std::int64_t>(b.size()) * b.n_mult;
    }
    if (element_info(b.type).family == ElementFamily::Gap) {
      b.interference.assign(b.size(), 0.0);
      b.stiffness_hint.assign(b.size(), 0.0);
    }
  }
  // Validate and initialise every element (reference configuration, zero displacement).
  std::vector<double> zero(static_cast<std::size_t>(_dofs.n_slots()), 0.0);
  std::vector<double> t0 = model.initial_temperature;
  t0.resize(static_cast<std::size_t>(mesh.n_nodes()), 0.0);
  FieldView fields{zero, zero, t0, t0, t0, {}, {}, {}, {}, {}, {}};
  StepContext ctx;
  ctx.space = model.space;
  ctx.model_size = model.model_size();
  ctx.constants = &model.constants;
  ElementGather gather;
  std::vector<std::string> problems;
  for (auto& b : _blocks) {
    b.state_trial = b.state_committed;
    b.mult_trial = b.mult_committed;
    for (std::size_t i = 0; i < b.size(); ++i) {
      ElementInput& in = gather.gather(*this, b, i, fields, &ctx);
      const std::string msg = b.kernel->validate(in);
      if (!msg.empty()) {
        std::string nodes;
        for (NodeId n : model.mesh.element_nodes(b.elements[i]))
          nodes += (nodes.empty() ? "" : ", ") + model.node_label(n).str();
        problems.push_back(InputError(model.element_location(b.elements[i]),
                                      fmt::format("element {} ({})", in.label,
                                                  model.element_type_name(b.elements[i])),
                                      fmt::format("{} (nodes {})", msg, nodes))
                               .what());
        if (problems.size() >= 50) break;
        continue;
      }
      b.kernel->initialize(in);
    }
    b.state_committed = b.state_trial;
  }
  if (!problems.empty()) {
    std::string all;
    for (const auto& p : problems) all += (all.empty() ? "" : "\n") + p;
    throw InputError({}, all);
  }
}

void Discretization::set_equations(const EquationMap& eqmap,
                                   std::span<const std::pair<NodeId, int>> local_bcs) {
  for (auto& b : _blocks) {
    b.eqs.resize(b.slots.size());
    for (std::size_t k = 0; k < b.slots.size(); ++k) b.eqs[k] = eqmap.slot_eq[b.slots[k]];
  }
  _constraints.set_equations(_model, eqmap, local_bcs);
  _matrix_terms.set_equations(eqmap);
}

void Discretization::reset_trial() {
  for (auto& b : _blocks) {
    std::copy(b.state_committed.begin(), b.state_committed.end(), b.state_trial.begin());
    std::copy(b.mult_committed.begin(), b.mult_committed.end(), b.mult_trial.begin());
  }
  _constraints.mult_trial = _constraints.mult_committed;
}

void Discretization::commit() {
  for (auto& b : _blocks) {
    std::copy(b.state_trial.begin(), b.state_trial.end(), b.state_committed.begin());
    std::copy(b.mult_trial.begin(), b.mult_trial.end(), b.mult_committed.begin());
  }
  _constraints.mult_committed = _constraints.mult_trial;
}

void Discretization::save_trial(std::vector<double>& out) const {
  out.clear();
  for (const auto& b : _blocks) {
    out.insert(out.end(), b.state_trial.begin(), b.state_trial.end());
    out.insert(out.end(), b.mult_trial.begin(), b.mult_trial.end());
  }
  out.insert(out.end(), _constraints.mult_trial.begin(), _constraints.mult_trial.end());
}

void Discretization::restore_trial(std::span<const double> saved) {
  auto it = saved.begin();
  auto take = [&](std::vector<double>& v) {
    FE_CHECK(saved.end() - it >= static_cast<std::ptrdiff_t>(v.size()),
             "saved trial state does not match the model");
    std::copy(it, it + static_cast<std::ptrdiff_t>(v.size()), v.begin());
    it += static_cast<std::ptrdiff_t>(v.size());
  };
  for (auto& b : _blocks) {
    take(b.state_trial);
    take(b.mult_trial);
  }
  take(_constraints.mult_trial);
  FE_CHECK(it == saved.end(), "saved trial state does not match the model");
}

double& Discretization::multiplier(std::int64_t index, bool trial) {
  if (index >= _n_mult) {
    FE_CHECK(index - _n_mult < _constraints.n_rows(), "multiplier index out of range");
    auto& m = trial ? _constraints.mult_trial : _constraints.mult_committed;
    return m[static_cast<std::size_t>(index - _n_mult)];
  }
  auto it = std::upper_bound(_mult_blocks.begin(), _mult_blocks.end(), index,
                             [](std::int64_t v, const auto& p) { return v < p.second; });
  FE_CHECK(it != _mult_blocks.begin(), "multiplier index out of range");
  --it;
  auto& b = _blocks[it->first];
  return (trial ? b.mult_trial : b.mult_committed)[static_cast<std::size_t>(index - it->second)];
}

bool Discretization::is_contact_normal(std::int64_t index) const {
  return index >= 0 && contact_normal_of(index) == index;
}

std::int64_t Discretization::contact_normal_of(std::int64_t index) const {
  if (index >= _n_mult) return -1;
  auto it = std::upper_bound(_mult_blocks.begin(), _mult_blocks.end(), index,
                             [](std::int64_t v, const auto& p) { return v < p.second; });
  if (it == _mult_blocks.begin()) return -1;
  --it;
  const ElementBlock& b = _blocks[it->first];
  // a gap's multipliers: the normal force first, then its friction rows (gap_assemble.cpp)
  if (element_info(b.type).family != ElementFamily::Gap || b.n_mult <= 0) return -1;
  return it->second + (index - it->second) / b.n_mult * b.n_mult;
}

double& Discretization::multiplier_trial(std::int64_t index) {
  return multiplier(index, true);
}

double& Discretization::multiplier_committed(std::int64_t index) {
  return multiplier(index, false);
}

} // namespace gapfem
