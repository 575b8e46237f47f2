// *RESPONSE SPECTRUM steps (docs/theory/frequency.md §6): no increments; the peak response of the
// modes of the last *FREQUENCY step to the spectra along their directions. Mode k's peak in
// direction d: q_kd = s_d S_d(f_k, zeta_k) sum_j c_dj Gamma_kj (unit-mass shapes), at a DOF
// phi_k q_kd; the modes combine by the SUM rule (modal_combination) and the directions by SRSS,
// or (COMP=ALGEBRAIC) the directions add up in each mode first.
#include "solver/analysis_impl.hpp"
#include "solver/modal_combination.hpp"
#include "solver/modal_response.hpp"
#include "solver/procedures.hpp"

#include <cmath>
#include <fmt/format.h>

namespace gapfem {
namespace {

class ResponseSpectrumProcedure final : public StepProcedure {
 public:
  using StepProcedure::StepProcedure;
  bool incremental() const override { return false; }
  void check(const Step& step) const override;
  void run(StepRun& r) override;

 private:
  /// The modes used (0-based), their circular frequencies and damping fractions.
  void modes(const Step& step, const ModalBasis& b);
  /// q[d][i]: mode i's peak generalized coordinate for direction d.
  std::vector<std::vector<double>> modal_peaks(const Step& step, const ModalBasis& b);
  std::vector<double> combine(const Step& step, const ModalBasis& b,
                              const std::vector<std::vector<double>>& q) const;

  std::vector<int> _modes;
  std::vector<double> _omega, _zeta;
};

void ResponseSpectrumProcedure::modes(const Step& step, const ModalBasis& b) {
  ModalSelection sel = select_modes(step, b, step.spectrum.loc);
  _modes = std::move(sel.modes);
  _omega = std::move(sel.omega);
  _zeta = std::move(sel.zeta);
}

std::vector<std::vector<double>> ResponseSpectrumProcedure::modal_peaks(const Step& step,
                                                                        const ModalBasis& b) {
  std::vector<std::vector<double>> q;
  std::vector<std::string> outside;
  int rigid = 0;
  for (const auto& d : step.spectrum.directions) {
    const Spectrum& sp = _a.model.spectra[d.spectrum];
    std::vector<double>& qd = q.emplace_back();
    for (std::size_t i = 0; i < _modes.size(); ++i) {
      const int k = _modes[i];
      double gamma = 0.0;
      for (int j = 0; j < 3; ++j) gamma += d.cosines[j] * b.participation[k][j];
      bool clamped = false;
      const double sd =
          b.omega(k) > 0.0 ? sp.displacement(b.frequency(k), _zeta[i], &clamped) : 0.0;
      rigid += b.omega(k) > 0.0 ? 0 : 1;
      if (clamped)
        outside.push_back(fmt::format("mode {} ({:.4g} cycles/time, damping {:.3g}) on {}", k + 1,
                                      b.frequency(k), _zeta[i], sp.name));
      qd.push_back(d.scale * sd * gamma);
    }
  }
  if (!outside.empty())
    _a.solver_warnings.push_back(fmt::format(
        "step {}: {} lie(s) outside the spectrum's table (frequency or damping): the table's end "
        "value is used there; e.g. {}",
        step.number, outside.size(), outside.front()));
  if (rigid > 0)
    _a.solver_warnings.push_back(fmt::format(
        "step {}: {} rigid-body mode(s) (frequency 0) have no spectral response and are left out",
        step.number, rigid));
  return q;
}

std::vector<double>
ResponseSpectrumProcedure::combine(const Step& step, const ModalBasis& b,
                                   const std::vector<std::vector<double>>& q) const {
  const ResponseSpectrumSettings& rs = step.spectrum;
  const std::size_t nm = _modes.size(), nd = q.size();
  std::vector<double> peak(static_cast<std::size_t>(b.n_slots), 0.0), r(nm);
  double duration = 0.0;
  for (const auto& d : rs.directions) duration = std::max(duration, d.duration);
  for (LocalIndex s = 0; s < b.n_slots; ++s) {
    const ModalPeaks p{r, _omega, _zeta, duration};
    if (rs.algebraic) {
      for (std::size_t i = 0; i < nm; ++i) {
        r[i] = 0.0;
        for (std::size_t d = 0; d < nd; ++d) r[i] += b.shape(_modes[i])[s] * q[d][i];
      }
      peak[s] = combine_modes(rs.sum, p);
      continue;
    }
    double sum = 0.0;
    for (std::size_t d = 0; d < nd; ++d) {
      for (std::size_t i = 0; i < nm; ++i) r[i] = b.shape(_modes[i])[s] * q[d][i];
      const double rd = combine_modes(rs.sum, p);
      sum += rd * rd;
    }
    peak[s] = std::sqrt(sum);
  }
  return peak;
}

void ResponseSpectrumProcedure::check(const Step& step) const {
  require_frequency_step(_a.model, step, step.spectrum.loc);
}

void ResponseSpectrumProcedure::run(StepRun& r) {
  check(*r.step);
  const Step& step = *r.step;
  const std::shared_ptr<const ModalBasis> b = _a.modal_basis;
  basis_of(b, step, step.spectrum.loc);
  modes(step, *b);
  const auto q = modal_peaks(step, *b);
  log::progress("  {} modes of step {}, {} direction(s)", _modes.size(), b->step_number, q.size());
  for (std::size_t i = 0; i < _modes.size(); ++i) {
    std::string row;
    for (const auto& qd : q) row += fmt::format(" {:12.4e}", qd[i]);
    log::progress("  mode {:4d}  {:11.4e} cycles/time  damping {:.4g}  peak q{}", _modes[i] + 1,
                  b->frequency(_modes[i]), _zeta[i], row);
  }
  const std::vector<double> peak = combine(step, *b, q);
  bool field_elements = false;
  std::optional<Frame> fr = _a.frame_due(step, *r.prob, 1, true, 0.0, false, field_elements);
  fr->step_time = 0.0;
  std::fill(fr->el_print_due.begin(), fr->el_print_due.end(), false);
  _a.perturbation_nodes(peak, *fr);
  ScopedTimer timer(&_a.stats, TimeCategory::Output);
  for (auto* w : _a.writers) w->frame(_a.model, r.index, *fr);
  if (field_elements || !step.el_prints.empty())
    _a.solver_warnings.push_back(fmt::format(
        "step {} (*RESPONSE SPECTRUM): element output of the peak response is not written by "
        "gapfem; the frame holds the peak U and UR",
        step.number));
  r.sum.increments = 1;
}

} // namespace

std::unique_ptr<StepProcedure> make_response_spectrum_procedure(Analysis::Impl& a) {
  return std::make_unique<ResponseSpectrumProcedure>(a);
}

} // namespace gapfem
