// *STEADY STATE DYNAMICS steps, mode-based (docs/theory/modal_dynamics.md): no increments; at each
// excitation frequency Omega the harmonic response of the modes of the last *FREQUENCY step,
//   q_k = sum_t F_tk a_t(Omega) / (omega_k^2 - Omega^2 + 2 i zeta_k omega_k Omega),
// a_t the term's amplitude at the frequency (times i for an imaginary part; for a base motion
// the base acceleration: the amplitude, i Omega times it for a velocity, -Omega^2 times it for a
// displacement), u = sum_k phi_k q_k relative to the base. A frame per frequency: U and UR the
// real part, Frame::harmonic the imaginary part.
#include "solver/analysis_impl.hpp"
#include "solver/modal_response.hpp"
#include "solver/procedures.hpp"

#include <cmath>
#include <complex>
#include <fmt/format.h>

namespace gapfem {
namespace {

using Complex = std::complex<double>;
constexpr double kTwoPi = 2.0 * 3.14159265358979323846;

class SteadyStateProcedure final : public StepProcedure {
 public:
  using StepProcedure::StepProcedure;
  bool incremental() const override { return false; }
  void check(const Step& step) const override;
  void run(StepRun& r) override;

 private:
  /// The modal coordinates at frequency f (cycles per time).
  std::vector<Complex> coordinates(double f) const;
  void write_frame(StepRun& r, int index, double f, const std::vector<Complex>& q, bool last);

  std::shared_ptr<const ModalBasis> _b;
  ModalSelection _sel;
  std::vector<ModalTerm> _terms;
};

std::vector<Complex> SteadyStateProcedure::coordinates(double f) const {
  const double W = kTwoPi * f;
  std::vector<Complex> q(_sel.modes.size(), 0.0);
  for (const ModalTerm& t : _terms) {
    Complex a = t.amplitude >= 0 ? _a.model.amplitudes[t.amplitude].at(f) : 1.0;
    if (t.base && t.type == BaseMotion::Type::Velocity) a *= Complex(0.0, W);
    if (t.base && t.type == BaseMotion::Type::Displacement) a *= -W * W;
    if (t.imaginary) a *= Complex(0.0, 1.0);
    for (std::size_t i = 0; i < q.size(); ++i) q[i] += t.force[i] * a;
  }
  for (std::size_t i = 0; i < q.size(); ++i) {
    const double w = _sel.omega[i];
    q[i] /= Complex(w * w - W * W, 2.0 * _sel.zeta[i] * w * W);
  }
  return q;
}

void SteadyStateProcedure::write_frame(StepRun& r, int index, double f,
                                       const std::vector<Complex>& q, bool last) {
  const Step& step = *r.step;
  std::vector<double> re(q.size()), im(q.size());
  for (std::size_t i = 0; i < q.size(); ++i) {
    re[i] = q[i].real();
    im[i] = q[i].imag();
  }
  bool field_elements = false;
  // every frequency is a frame (as every mode is one)
  std::optional<Frame> fr = _a.frame_due(step, *r.prob, index, true, 0.0, false, field_elements);
  fr->last_in_step = last;
  fr->step_time = f; // Abaqus: the step time of a steady-state frame is its frequency
  std::fill(fr->el_print_due.begin(), fr->el_print_due.end(), false);
  Frame imaginary = *fr;
  _a.perturbation_nodes(modal_superposition(*_b, _sel, im), imaginary);
  _a.perturbation_nodes(modal_superposition(*_b, _sel, re), *fr);
  fr->harmonic = Frame::Harmonic{f, std::move(imaginary.nodes.U), std::move(imaginary.nodes.UR)};
  ScopedTimer timer(&_a.stats, TimeCategory::Output);
  for (auto* w : _a.writers) w->frame(_a.model, r.index, *fr);
}

void SteadyStateProcedure::check(const Step& step) const {
  require_frequency_step(_a.model, step, step.steady_state.loc);
}

void SteadyStateProcedure::run(StepRun& r) {
  check(*r.step);
  const Step& step = *r.step;
  const SteadyStateSettings& ss = step.steady_state;
  ModalProblem mp =
      modal_problem(_a.model, _a.disc, _a.modal_basis, step, ss.loc, _a.solver_warnings);
  _b = std::move(mp.basis);
  _sel = std::move(mp.sel);
  _terms = std::move(mp.terms);
  if (_terms.empty())
    _a.solver_warnings.push_back(fmt::format(
        "step {} (*STEADY STATE DYNAMICS): no *CLOAD and no *BASE MOTION excite the modes: the "
        "response is zero",
        step.number));
  std::vector<double> fe;
  for (int k : _sel.modes) fe.push_back(_b->frequency(k));
  const std::vector<double> freqs = steady_state_frequencies(ss, fe);
  log::progress("  {} modes of step {}, {} frequencies from {:.6g} to {:.6g} cycles/time",
                _sel.modes.size(), _b->step_number, freqs.size(), freqs.front(), freqs.back());
  for (std::size_t j = 0; j < freqs.size(); ++j) {
    const double f = freqs[j];
    for (std::size_t i = 0; i < _sel.modes.size(); ++i)
      if (_sel.zeta[i] == 0.0 && std::abs(kTwoPi * f - _sel.omega[i]) <= 1e-12 * _sel.omega[i])
        throw InputError(ss.loc, fmt::format("step {}", step.number),
                         fmt::format("the excitation frequency {:.6g} is mode {}'s natural "
                                     "frequency and the mode has no damping: the response is "
                                     "unbounded; give *MODAL DAMPING",
                                     f, _sel.modes[i] + 1));
    write_frame(r, static_cast<int>(j) + 1, f, coordinates(f), j + 1 == freqs.size());
  }
  if (!step.el_prints.empty() ||
      std::any_of(step.field_outputs.begin(), step.field_outputs.end(),
                  [](const FieldOutputRequest& f) { return !f.elem_vars.empty(); }))
    _a.solver_warnings.push_back(
        fmt::format("step {} (*STEADY STATE DYNAMICS): element output (stresses, strains, section "
                    "forces) of the "
                    "mode-based response is not written by gapfem; the frames hold U and UR",
                    step.number));
  r.sum.increments = static_cast<int>(freqs.size());
}

} // namespace

std::unique_ptr<StepProcedure> make_steady_state_procedure(Analysis::Impl& a) {
  return std::make_unique<SteadyStateProcedure>(a);
}

} // namespace gapfem
