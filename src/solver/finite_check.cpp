#include "solver/finite_check.hpp"

#include "fem/discretization.hpp"
#include "model/model.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace gapfem {
namespace {

std::string value_text(double v) {
  return std::isnan(v) ? "NaN" : (v > 0 ? "+inf" : "-inf");
}

/// "element 12 (C3D8)"
std::string element_text(const Model& model, ElemId e) {
  return fmt::format("element {} ({})", model.element_label(e), model.element_type_name(e));
}

/// The first non-finite entry of `values` (elements.size() x n per element), or "".
std::string first_in_history(const Model& model, const ElementBlock& b,
                             const std::vector<double>& values, int n, const char* what) {
  if (n <= 0) return {};
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (std::isfinite(values[k])) continue;
    const ElemId e = b.elements[k / static_cast<std::size_t>(n)];
    return fmt::format("{} {} of {}", value_text(values[k]), what, element_text(model, e));
  }
  return {};
}

} // namespace

std::string first_non_finite_state(const Model& model, const Discretization& disc,
                                   std::span<const double> u, std::span<const double> reactions) {
  const DofMap& dofs = disc.dofs();
  auto slot_text = [&](LocalIndex s, double v, const char* what) {
    return fmt::format("{} {} at node {} DOF {}", value_text(v), what,
                       model.node_label(dofs.slot_node(s)), abaqus_number(dofs.slot_dof(s)));
  };
  for (LocalIndex s = 0; s < dofs.n_slots() && static_cast<std::size_t>(s) < u.size(); ++s)
    if (!std::isfinite(u[s])) return slot_text(s, u[s], "in the solution (U, UR or NT)");
  for (LocalIndex s = 0; s < dofs.n_slots() && static_cast<std::size_t>(s) < reactions.size(); ++s)
    if (!std::isfinite(reactions[s]))
      return slot_text(s, reactions[s], "in the reaction (RF, RM or RFL)");
  for (const ElementBlock& b : disc.blocks()) {
    const bool gap = element_info(b.type).family == ElementFamily::Gap;
    std::string found = first_in_history(model, b, b.mult_trial, b.n_mult,
                                         gap ? "in the contact force" : "in a constraint force");
    if (found.empty())
      found = first_in_history(model, b, b.state_trial, b.n_state, "in the state (history)");
    if (!found.empty()) return found;
  }
  return {};
}

std::string first_non_finite_output(const Model& model, const Frame& frame) {
  for (const ElementResult& r : frame.elements) {
    for (const OutputBlock& block : r.data.blocks) {
      const std::size_t nc = block.names.size();
      for (std::size_t k = 0; k < block.values.size(); ++k) {
        if (std::isfinite(block.values[k])) continue;
        const std::string_view name = nc > 0 ? block.names[k % nc] : std::string_view("?");
        const std::size_t point = nc > 0 ? k / nc : 0;
        const auto sp = static_cast<std::size_t>(std::max(block.section_points, 1));
        const std::string at = sp > 1 ? fmt::format("integration point {}, section point {}",
                                                    point / sp + 1, point % sp + 1)
                                      : fmt::format("integration point {}", point + 1);
        return fmt::format("{} in the output {} ({}) of {}", value_text(block.values[k]), name, at,
                           element_text(model, r.elem));
      }
    }
    if (r.data.gap &&
        (!std::isfinite(r.data.gap->normal_force) || !std::isfinite(r.data.gap->clearance)))
      return fmt::format("a non-finite contact force or clearance of {}",
                         element_text(model, r.elem));
  }
  return {};
}

std::string non_finite_message(int increment, const std::string& where) {
  const std::string when = increment > 0 ? fmt::format("increment {}", increment)
                                         : std::string("at the start of the step");
  return fmt::format(
      "{}: the results hold a number that is not finite: {}; numbers beyond "
      "double precision (about 1.8E308) overflowed, so the loads, prescribed values or material "
      "constants are far too large for the model's units: check their magnitudes and units "
      "(the results of the increments before are written)",
      when, where);
}

} // namespace gapfem
