// *MODAL DYNAMIC steps (docs/theory/modal_dynamics.md): the transient response of the modes of the
// last *FREQUENCY step, from rest, in fixed increments. Each mode's equation
//   q'' + 2 zeta omega q' + omega^2 q = f(t),  f linear over each increment,
// is integrated exactly (Abaqus: "exact whenever the forcing varies piecewise linearly"): the
// state (q, q', f, f') advances by the exponential of its constant 4 x 4 system matrix. The
// forcing sums the terms' generalized forces times their amplitudes at the step time (a base
// motion's acceleration: the amplitude, its slope for a velocity, its second difference for a
// displacement); the frames hold u = sum phi_k q_k (relative to the base) as U and UR, and the
// elements' values of that response (the change of each element's values along u about the base
// state: stresses, strains, section forces of the linear response).
#include "solver/analysis_impl.hpp"
#include "solver/modal_response.hpp"
#include "solver/procedures.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <fmt/format.h>
#include <unsupported/Eigen/MatrixFunctions>

namespace gapfem {
namespace {

using Mat4 = Eigen::Matrix4d;

/// exp(A h) of mode (omega, zeta) for an increment h.
Mat4 transition(double omega, double zeta, double h) {
  Mat4 A = Mat4::Zero();
  A(0, 1) = 1.0;
  A(1, 0) = -omega * omega;
  A(1, 1) = -2.0 * zeta * omega;
  A(1, 2) = 1.0;
  A(2, 3) = 1.0;
  return (A * h).exp();
}

class ModalDynamicProcedure final : public StepProcedure {
 public:
  using StepProcedure::StepProcedure;
  bool incremental() const override { return false; }
  void check(const Step& step) const override;
  void run(StepRun& r) override;

 private:
  /// The generalized forces at step time t.
  std::vector<double> forcing(double t) const;
  double amplitude(int index, double t) const;
  void write_frame(StepRun& r, int increment, double t, double dt, bool last);

  std::shared_ptr<const ModalBasis> _b;
  ModalSelection _sel;
  std::vector<ModalTerm> _terms;
  std::vector<double> _q, _qdot;
  double _dt = 0.0, _start = 0.0;
};

double ModalDynamicProcedure::amplitude(int index, double t) const {
  return index >= 0 ? _a.model.amplitudes[index].value(t, _start) : 1.0;
}

std::vector<double> ModalDynamicProcedure::forcing(double t) const {
  std::vector<double> f(_sel.modes.size(), 0.0);
  for (const ModalTerm& term : _terms) {
    double a = amplitude(term.amplitude, t);
    if (term.base && term.type == BaseMotion::Type::Velocity)
      a = term.amplitude >= 0 ? _a.model.amplitudes[term.amplitude].slope(
                                    _a.model.amplitudes[term.amplitude].time_of(t, _start))
                              : 0.0;
    if (term.base && term.type == BaseMotion::Type::Displacement)
      a = (amplitude(term.amplitude, t + _dt) - 2.0 * a + amplitude(term.amplitude, t - _dt)) /
          (_dt * _dt);
    for (std::size_t i = 0; i < f.size(); ++i) f[i] += term.force[i] * a;
  }
  return f;
}

void ModalDynamicProcedure::write_frame(StepRun& r, int increment, double t, double dt, bool last) {
  const Step& step = *r.step;
  bool field_elements = false;
  std::optional<Frame> fr = _a.frame_due(step, *r.prob, increment, last, dt, false, field_elements);
  if (!fr) return;
  fr->step_time = t;
  fr->total_time = _start + t;
  const std::vector<double> u = modal_superposition(*_b, _sel, _q);
  _a.perturbation_nodes(u, *fr);
  _a.perturbation_elements(step, *r.prob, u, field_elements, *fr);
  ScopedTimer timer(&_a.stats, TimeCategory::Output);
  for (auto* w : _a.writers) w->frame(_a.model, r.index, *fr);
}

void ModalDynamicProcedure::check(const Step& step) const {
  require_frequency_step(_a.model, step, step.modal_dynamic.loc);
}

void ModalDynamicProcedure::run(StepRun& r) {
  check(*r.step);
  const Step& step = *r.step;
  const ModalDynamicSettings& md = step.modal_dynamic;
  ModalProblem mp =
      modal_problem(_a.model, _a.disc, _a.modal_basis, step, md.loc, _a.solver_warnings);
  _b = std::move(mp.basis);
  _sel = std::move(mp.sel);
  _terms = std::move(mp.terms);
  _dt = md.dt;
  _start = r.prob->context().total_time - r.prob->context().step_time;
  const auto n = static_cast<int>(std::ceil(md.period / md.dt * (1.0 - 1e-12)));
  const std::size_t nm = _sel.modes.size();
  _q.assign(nm, 0.0);
  _qdot.assign(nm, 0.0);
  std::vector<Mat4> full(nm);
  for (std::size_t i = 0; i < nm; ++i) full[i] = transition(_sel.omega[i], _sel.zeta[i], md.dt);
  log::progress("  {} modes of step {}, {} increments of {:.6g}", nm, _b->step_number, n, md.dt);
  double t = 0.0;
  std::vector<double> f0 = forcing(0.0);
  for (int inc = 1; inc <= n; ++inc) {
    const double h = inc == n ? md.period - t : md.dt;
    const std::vector<double> f1 = forcing(t + h);
    for (std::size_t i = 0; i < nm; ++i) {
      const Mat4 T = h == md.dt ? full[i] : transition(_sel.omega[i], _sel.zeta[i], h);
      const Eigen::Vector4d s(_q[i], _qdot[i], f0[i], (f1[i] - f0[i]) / h);
      const Eigen::Vector4d e = T * s;
      _q[i] = e(0);
      _qdot[i] = e(1);
    }
    t += h;
    f0 = f1;
    write_frame(r, inc, t, h, inc == n);
  }
  r.sum.increments = n;
}

} // namespace

std::unique_ptr<StepProcedure> make_modal_dynamic_procedure(Analysis::Impl& a) {
  return std::make_unique<ModalDynamicProcedure>(a);
}

} // namespace gapfem
