#include "solver/modal_response.hpp"

#include "fem/discretization.hpp"
#include "fem/dof_map.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>

namespace gapfem {

void require_frequency_step(const Model& model, const Step& step, const SourceLocation& loc) {
  for (const Step& s : model.steps) {
    if (s.number >= step.number) break;
    if (s.procedure == Procedure::Frequency) return;
  }
  throw InputError(loc, fmt::format("step {}", step.number),
                   fmt::format("a mode-based *{} step works on the modes of a *FREQUENCY step, "
                               "and no *FREQUENCY step comes before it; add one",
                               procedure_name(step.procedure)));
}

const ModalBasis& basis_of(const std::shared_ptr<const ModalBasis>& b, const Step& step,
                           const SourceLocation& loc) {
  if (!b)
    throw InputError(loc, fmt::format("step {}", step.number),
                     "the modes of the *FREQUENCY step before this one are not at hand; run the "
                     "analysis from that step on");
  return *b;
}

ModalSelection select_modes(const Step& step, const ModalBasis& b, const SourceLocation& loc) {
  ModalSelection sel;
  if (step.selected_modes.empty())
    for (int k = 0; k < b.modes(); ++k) sel.modes.push_back(k);
  for (int k : step.selected_modes) {
    if (k > b.modes())
      throw InputError(loc, fmt::format("step {}", step.number),
                       fmt::format("*SELECT EIGENMODES names mode {}, but the *FREQUENCY step {} "
                                   "extracted {} modes",
                                   k, b.step_number, b.modes()));
    sel.modes.push_back(k - 1);
  }
  for (int k : sel.modes) {
    sel.omega.push_back(b.omega(k));
    sel.zeta.push_back(step.modal_damping ? step.modal_damping->fraction(k + 1, b.omega(k)) : 0.0);
  }
  return sel;
}

namespace {

/// phi_k^T F over the selected modes for the load vector F (per slot).
std::vector<double> project(const ModalBasis& b, const ModalSelection& sel,
                            const std::map<LocalIndex, double>& F) {
  std::vector<double> out;
  for (int k : sel.modes) {
    double p = 0.0;
    for (const auto& [slot, f] : F) p += b.shape(k)[slot] * f;
    out.push_back(p);
  }
  return out;
}

/// Adds a concentrated load to F: global along DOF d, or along local axis d at a *TRANSFORM node.
void add_load(const Model& model, const DofMap& dofs, const NodalLoad& l,
              std::map<LocalIndex, double>& F) {
  const int d = abaqus_number(l.dof);
  const auto Q = d <= 6 ? model.node_axes(l.node) : std::nullopt;
  if (!Q) {
    const LocalIndex s = dofs.slot(l.node, l.dof);
    if (s < 0)
      throw InputError(
          l.loc, fmt::format("node {}", model.node_label(l.node)),
          fmt::format("no element at this node has DOF {}; the load cannot be applied", d));
    F[s] += l.value;
    return;
  }
  const int base = d <= 3 ? 0 : 3, i = d - 1 - base;
  for (int j = 0; j < 3; ++j) {
    const LocalIndex s = dofs.slot(l.node, static_cast<DofType>(base + j));
    if (s >= 0) F[s] += (*Q)[3 * i + j] * l.value;
  }
}

} // namespace

std::vector<ModalTerm> modal_excitation(const Model& model, const DofMap& dofs, const Step& step,
                                        const ModalBasis& b, const ModalSelection& sel) {
  std::vector<ModalTerm> terms;
  std::map<std::pair<int, bool>, std::map<LocalIndex, double>> groups;
  for (const NodalLoad& l : step.cloads)
    if (!l.propagated && !is_temperature(l.dof))
      add_load(model, dofs, l, groups[{l.amplitude, l.imaginary}]);
  for (const auto& [key, F] : groups) {
    ModalTerm t;
    t.amplitude = key.first;
    t.imaginary = key.second;
    t.force = project(b, sel, F);
    terms.push_back(std::move(t));
  }
  for (const BaseMotion& m : step.base_motions) {
    ModalTerm t;
    t.amplitude = m.amplitude;
    t.imaginary = m.imaginary;
    t.base = true;
    t.type = m.type;
    const int d = static_cast<int>(m.dof);
    for (int k : sel.modes) t.force.push_back(-m.scale * b.participation[k][d]);
    terms.push_back(std::move(t));
  }
  return terms;
}

namespace {

/// n points over [f1, f2] with bias p, ends included.
void interval_points(double f1, double f2, int n, double p, bool logarithmic, double scale,
                     std::vector<double>& out) {
  const bool log_scale = logarithmic && f1 > 0.0;
  const double a = log_scale ? std::log(f1) : f1, c = log_scale ? std::log(f2) : f2;
  for (int k = 0; k < n; ++k) {
    const double y = -1.0 + 2.0 * k / (n - 1);
    const double z = std::copysign(std::pow(std::abs(y), 1.0 / p), y);
    const double v = 0.5 * (a + c) + 0.5 * (c - a) * z;
    double f = log_scale ? std::exp(v) : v;
    if (k == 0) f = f1;
    if (k == n - 1) f = f2;
    out.push_back(k == 0 || k == n - 1 ? f : f * scale);
  }
}

} // namespace

std::vector<double> steady_state_frequencies(const SteadyStateSettings& ss,
                                             std::span<const double> eigenfrequencies) {
  std::vector<double> out;
  const bool by_modes = ss.interval == SteadyStateSettings::Interval::Eigenfrequency;
  for (const SteadyStateSettings::Range& g : ss.ranges) {
    if (g.upper == 0.0 || g.upper == g.lower) {
      out.push_back(g.lower);
      continue;
    }
    const double p = g.bias.value_or(by_modes ? 3.0 : 1.0);
    std::vector<double> ends{g.lower};
    if (by_modes)
      for (double f : eigenfrequencies)
        if (f > g.lower && f < g.upper) ends.push_back(f);
    ends.push_back(g.upper);
    std::sort(ends.begin(), ends.end());
    for (std::size_t i = 0; i + 1 < ends.size(); ++i)
      if (ends[i + 1] > ends[i])
        interval_points(ends[i], ends[i + 1], g.points, p, ss.logarithmic, g.scale, out);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end(),
                        [](double x, double y) { return std::abs(x - y) <= 1e-12 * std::abs(y); }),
            out.end());
  return out;
}

std::string element_damping_warning(const Discretization& disc, const Step& step) {
  for (const ElementBlock& b : disc.blocks())
    if (b.kernel->has_damping())
      return fmt::format("step {} (*{}): the damping of the elements (dashpots, ALPHA, material "
                         "damping) is not part of the mode-based response, which *MODAL DAMPING "
                         "alone damps",
                         step.number, procedure_name(step.procedure));
  return {};
}

ModalProblem modal_problem(const Model& model, const Discretization& disc,
                           std::shared_ptr<const ModalBasis> basis, const Step& step,
                           const SourceLocation& loc, std::vector<std::string>& warnings) {
  ModalProblem p;
  basis_of(basis, step, loc);
  p.basis = std::move(basis);
  p.sel = select_modes(step, *p.basis, loc);
  p.terms = modal_excitation(model, disc.dofs(), step, *p.basis, p.sel);
  if (std::string w = element_damping_warning(disc, step); !w.empty())
    warnings.push_back(std::move(w));
  return p;
}

std::vector<double> modal_superposition(const ModalBasis& b, const ModalSelection& sel,
                                        std::span<const double> q) {
  std::vector<double> u(static_cast<std::size_t>(b.n_slots), 0.0);
  for (std::size_t i = 0; i < sel.modes.size(); ++i) {
    const double* phi = b.shape(sel.modes[i]);
    for (LocalIndex s = 0; s < b.n_slots; ++s) u[s] += phi[s] * q[i];
  }
  return u;
}

} // namespace gapfem
