// *FREQUENCY steps (docs/theory/frequency.md): no increments; the natural frequencies and mode
// shapes of the model about its base state (the end of the last general step), found by
// shift-invert Lanczos over the run's solver (linalg/eigen_solver), with Abaqus's participation
// factors and effective masses (modal_quantities); the writers get the table and a frame per mode.
#include "solver/analysis_impl.hpp"
#include "solver/modal_quantities.hpp"
#include "solver/mode_frames.hpp"
#include "solver/procedures.hpp"

#include <cmath>
#include <fmt/format.h>

namespace gapfem {
namespace {

constexpr double kTwoPi = 2.0 * 3.14159265358979323846;

/// What the step asks for, in eigenvalues omega^2.
EigenRequest request(const FrequencySettings& f) {
  EigenRequest req;
  req.count = f.count;
  const auto sq = [](double cycles) { return (kTwoPi * cycles) * (kTwoPi * cycles); };
  if (f.min_frequency && *f.min_frequency > 0.0) req.lower = sq(*f.min_frequency);
  if (f.max_frequency) req.upper = sq(*f.max_frequency);
  if (f.shift) req.shift = sq(*f.shift);
  return req;
}

class FrequencyProcedure final : public StepProcedure {
 public:
  using StepProcedure::StepProcedure;
  bool incremental() const override { return false; }
  void check(const Step& step) const override;
  void run(StepRun& r) override;

 private:
  EigenPairs extract(StepRun& r, StepProblem::PerturbationOperators& ops);
  void report(const StepRun& r, const EigenSummary& sum) const;
  void keep_basis(const StepRun& r, const EigenPairs& pairs, const EigenSummary& sum);
};

EigenPairs FrequencyProcedure::extract(StepRun& r, StepProblem::PerturbationOperators& ops) {
  const FrequencySettings& f = r.step->frequency;
  const std::string what = fmt::format("step {}", r.step->number);
  try {
    return constrained_eigenpairs(*_a.solver, ops.K, ops.M, ops.C, request(f), &_a.stats);
  } catch (const EigenProblemError& e) {
    throw InputError(f.loc, what, e.what());
  } catch (const SingularSystem& e) {
    throw InputError(f.loc, what,
                     fmt::format("the stiffness about the base state cannot be factorised at any "
                                 "shift ({}); give a shift point in field 4 of the data line",
                                 e.what()));
  }
}

void FrequencyProcedure::check(const Step& step) const {
  for (const ElementBlock& b : _a.disc.blocks())
    if (b.kernel->has_mass()) return;
  throw InputError(step.frequency.loc, fmt::format("step {}", step.number),
                   "no element of the model has mass (no *DENSITY in the materials of its "
                   "elements, no MASS, ROTARY INERTIA or mass matrix): there are no natural "
                   "frequencies to extract; give the materials *DENSITY");
}

void FrequencyProcedure::run(StepRun& r) {
  check(*r.step);
  StepProblem::PerturbationOperators ops = r.prob->perturbation_operators();
  EigenPairs pairs = extract(r, ops);
  const EquationMap& eqm = r.prob->equations();
  EigenSummary sum = modal_summary(_a.model.mesh, _a.disc.dofs(), eqm, ops.M, pairs,
                                   r.step->frequency.mass_normalized);
  report(r, sum);
  log::progress("  eigensolver {}: {} factorisation(s), {} back-substitutions, {} restarts",
                pairs.method, pairs.factorizations, pairs.operations, pairs.restarts);
  write_mode_frames(_a, r, pairs, sum);
  keep_basis(r, pairs, sum);
  r.sum.increments = static_cast<int>(sum.modes.size());
}

void FrequencyProcedure::report(const StepRun& r, const EigenSummary& sum) const {
  log::progress("  {} eigenvalues (shift {:.6g}):", sum.modes.size(), sum.shift);
  for (const ModeInfo& m : sum.modes)
    log::progress("  mode {:4d}  eigenvalue {:13.6e}  frequency {:13.6e} cycles/time", m.mode,
                  m.eigenvalue, m.frequency());
  if (sum.rigid_body_modes > 0)
    log::progress("  {} of them rigid-body modes (eigenvalue near zero): the model is free to "
                  "move there",
                  sum.rigid_body_modes);
  const auto negative = std::count_if(sum.modes.begin(), sum.modes.end(), [&](const ModeInfo& m) {
    return m.eigenvalue < 0.0 && std::abs(m.eigenvalue) > 0.0;
  });
  if (negative > static_cast<long>(sum.rigid_body_modes))
    _a.solver_warnings.push_back(fmt::format(
        "step {}: negative eigenvalues: the base state is unstable there (its initial stresses "
        "make the stiffness indefinite), or the shift lies above some eigenvalues",
        r.step->number));
}

void FrequencyProcedure::keep_basis(const StepRun& r, const EigenPairs& pairs,
                                    const EigenSummary& sum) {
  auto b = std::make_shared<ModalBasis>();
  const EquationMap& eqm = r.prob->equations();
  const std::size_t n = static_cast<std::size_t>(eqm.n_eq());
  b->step_number = r.step->number;
  b->n_slots = _a.disc.dofs().n_slots();
  b->shapes.assign(sum.modes.size() * static_cast<std::size_t>(b->n_slots), 0.0);
  for (std::size_t k = 0; k < sum.modes.size(); ++k) {
    const ModeInfo& m = sum.modes[k];
    const double root = std::sqrt(m.generalized_mass); // to phi^T M phi = 1
    double* shape = b->shapes.data() + k * static_cast<std::size_t>(b->n_slots);
    for (std::size_t eq = 0; eq < n; ++eq)
      shape[eqm.eq_slot[eq]] = pairs.vectors[k * n + eq] / root;
    b->omega2.push_back(m.eigenvalue);
    std::array<double, 6> gamma{};
    for (int i = 0; i < 6; ++i) gamma[i] = m.participation[i] * root;
    b->participation.push_back(gamma);
  }
  _a.modal_basis = std::move(b);
}

} // namespace

std::unique_ptr<StepProcedure> make_frequency_procedure(Analysis::Impl& a) {
  return std::make_unique<FrequencyProcedure>(a);
}

} // namespace gapfem
