#include "output/field_selection.hpp"

#include <limits>

namespace gapfem::output {

FieldSelection::FieldSelection(const Model& model, int step_index, const Frame& frame) {
  const auto nn = static_cast<std::size_t>(model.mesh.n_nodes());
  const auto ne = static_cast<std::size_t>(model.mesh.n_elements());
  const bool known_step = step_index >= 0 && step_index < static_cast<int>(model.steps.size());
  if (frame.field_output_due.empty() || !known_step) { // no *OUTPUT, FIELD: all but the loads
    for (NodeVar v : {NodeVar::U, NodeVar::UR, NodeVar::RF, NodeVar::RM, NodeVar::NT, NodeVar::RFL,
                      NodeVar::V, NodeVar::VR, NodeVar::A, NodeVar::AR})
      _node[static_cast<std::size_t>(v)].assign(nn, 1);
    for (auto& m : _elem) m.assign(ne, 1);
    return;
  }
  const Step& step = model.steps[static_cast<std::size_t>(step_index)];
  for (std::size_t r = 0; r < step.field_outputs.size() && r < frame.field_output_due.size(); ++r) {
    if (!frame.field_output_due[r]) continue;
    const FieldOutputRequest& req = step.field_outputs[r];
    for (NodeVar v : req.node_vars_everywhere) _node[static_cast<std::size_t>(v)].assign(nn, 1);
    for (ElemVar v : req.elem_vars_everywhere) _elem[static_cast<std::size_t>(v)].assign(ne, 1);
    for (const auto& [v, set] : req.node_sets) {
      auto& m = _node[static_cast<std::size_t>(v)];
      if (m.empty()) m.assign(nn, 0);
      for (NodeId n : set) m[static_cast<std::size_t>(n)] = 1;
    }
    for (const auto& [v, set] : req.elem_sets) {
      auto& m = _elem[static_cast<std::size_t>(v)];
      if (m.empty()) m.assign(ne, 0);
      for (ElemId e : set) m[static_cast<std::size_t>(e)] = 1;
    }
  }
}

std::vector<double> FieldSelection::masked(const std::vector<double>& values, std::size_t width,
                                           const std::vector<char>& mask) {
  std::vector<double> out = values;
  for (std::size_t i = 0; i < mask.size() && width * (i + 1) <= out.size(); ++i)
    if (!mask[i])
      std::fill_n(out.begin() + static_cast<std::ptrdiff_t>(width * i), width,
                  std::numeric_limits<double>::quiet_NaN());
  return out;
}

} // namespace gapfem::output
