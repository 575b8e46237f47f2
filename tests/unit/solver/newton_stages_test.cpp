// The stages of NewtonIteration, each on a one-unknown problem written against NonlinearProblem
// (no elements): Abaqus's criteria per field (check_field), a cubic spring converging in the
// iterations Newton's own recurrence takes, a linear problem in one iteration by the linear rule,
// a rising residual caught by the divergence check, severe discontinuity iterations and their
// limit, augmentation, the line-search hook, an element's cut-back request, a failed element, a
// non-finite residual, the equilibrium iteration limit and a problem with nothing to solve.
#include "common/error.hpp"
#include "linalg/kkt_solver.hpp"
#include "solver/newton.hpp"

#include <cmath>
#include <functional>
#include <gtest/gtest.h>

using namespace gapfem;

namespace {

/// One displacement unknown u (from 0) with residual r(u) and tangent dr(u); every evaluation
/// reports the same flux. Knobs make evaluations change contact status, ask for a cut-back,
/// throw, augment and limit the step.
class FunctionProblem final : public NonlinearProblem {
 public:
  FunctionProblem(std::function<double(double)> r, std::function<double(double)> dr, double flux)
      : _r(std::move(r)), _dr(std::move(dr)), _flux(flux) {
    std::vector<std::span<const LocalIndex>> el{std::span<const LocalIndex>(_eq)};
    _pattern = build_pattern(1, el);
    _K = CsrMatrix(_pattern);
    _rhs.assign(1, 0.0);
  }
  std::shared_ptr<const SparsityPattern> pattern() const { return _pattern; }

  Evaluation evaluate(bool tangent) override {
    ++evaluations;
    if (evaluations == throw_at) throw ConvergenceFailure("element 3 turned inside out");
    Evaluation ev;
    ev.tangent = tangent;
    const double r = _r(u);
    _rhs[0] = -r;
    if (tangent) assemble_tangent();
    ev.has_field[0] = true;
    ev.residual_max[0] = std::abs(r);
    ev.flux[0] = _flux;
    // evaluations 2 .. status_changes + 1 (those after the corrections) change a new element's
    // status each: severe iterations, never chattering
    if (evaluations >= 2 && evaluations <= status_changes + 1) {
      ev.status_changes = 1;
      ev.changed = {static_cast<ElemId>(evaluations)};
    }
    if (evaluations == 1) ev.dt_ratio = first_dt_ratio;
    return ev;
  }
  Evaluation assemble_tangent() override {
    _K.set_zero();
    _K.values()[0] = _dr(u);
    return {};
  }
  CsrMatrix& matrix() override { return _K; }
  std::span<const double> rhs() const override {
    return nothing_free ? std::span<const double>() : std::span<const double>(_rhs);
  }
  const ConstraintBlock& constraints() const override { return _C; }
  void apply(std::span<const double> du, std::span<const double>) override { u += du[0]; }
  Field equation_field(LocalIndex) const override { return Field::Displacement; }
  std::array<double, kNumFields> increment_max() const override { return {std::abs(u), 0, 0}; }
  double constraint_tolerance() const override { return 1e-10; }
  int augment() override { return augmentations_left > 0 ? (--augmentations_left, 1) : 0; }
  double step_limit(std::span<const double>, std::span<const double>) override {
    return step_fraction;
  }

  double u = 0.0;
  int evaluations = 0;
  int status_changes = 0;     ///< evaluations after a correction that change status
  int throw_at = -1;          ///< the evaluation that throws ConvergenceFailure
  int augmentations_left = 0; ///< augment() returns 1 this many times
  double step_fraction = 1.0;
  double first_dt_ratio = std::numeric_limits<double>::infinity();
  bool nothing_free = false; ///< every DOF prescribed: no equations

 private:
  std::function<double(double)> _r, _dr;
  double _flux;
  std::vector<LocalIndex> _eq{0};
  std::shared_ptr<SparsityPattern> _pattern;
  CsrMatrix _K;
  std::vector<double> _rhs;
  ConstraintBlock _C;
};

/// Full Newton: the stages' arithmetic, not the factor reuse, is under test.
NewtonControls full_newton() {
  NewtonControls c;
  c.factor_reuse = FactorReuse::Never;
  return c;
}

NewtonResult run(FunctionProblem& p, const NewtonControls& c = full_newton()) {
  KktSolver s;
  s.analyze(p.pattern());
  return NewtonIteration(p, s, c, FluxHistory{}, nullptr).run();
}

/// k u + c u^3 = f
FunctionProblem cubic_spring(double k, double c, double f) {
  return FunctionProblem([=](double u) { return k * u + c * u * u * u - f; },
                         [=](double u) { return k + 3 * c * u * u; }, f);
}

} // namespace

TEST(NewtonStages, FieldCriteria) {
  const NewtonControls::Field f; // R_n 0.005, C_n 0.01, epsilon_l 1e-8, q~_0 1e-2, epsilon 1e-5
  // residual and correction both within their ratios
  FieldCheck k = check_field(f, 100.0, 0.4, 0.009, 1.0);
  EXPECT_TRUE(k.counted);
  EXPECT_TRUE(k.converged);
  EXPECT_DOUBLE_EQ(k.ratio, 0.004);
  EXPECT_FALSE(k.within_stale) << "0.004 is above 1e-2 R_n";
  // the correction too large
  EXPECT_FALSE(check_field(f, 100.0, 0.4, 0.011, 1.0).converged);
  // the residual too large
  EXPECT_FALSE(check_field(f, 100.0, 0.6, 0.0, 1.0).converged);
  // linear rule: the correction is the whole increment, the residual 1e-8 of the flux
  k = check_field(f, 100.0, 1e-6, 1.0, 1.0);
  EXPECT_TRUE(k.converged);
  EXPECT_TRUE(k.within_stale);
  // zero flux: q~ below q~_0 and r below epsilon q~_0: left out
  k = check_field(f, 1e-3, 1e-8, 1.0, 1.0);
  EXPECT_FALSE(k.counted);
  // ... but a residual above epsilon q~_0 counts against the small flux
  k = check_field(f, 1e-3, 1e-6, 1.0, 1.0);
  EXPECT_TRUE(k.counted);
  EXPECT_FALSE(k.converged);
  // no flux scale yet (every evaluation changed status): never converged, no ratio
  k = check_field(f, 0.0, 1.0, 0.0, 1.0);
  EXPECT_FALSE(k.converged);
  EXPECT_EQ(k.ratio, 0.0);
  // a residual that is not finite has an infinite ratio
  k = check_field(f, 100.0, std::numeric_limits<double>::quiet_NaN(), 0.0, 1.0);
  EXPECT_FALSE(k.converged);
  EXPECT_TRUE(std::isinf(k.ratio));
  // the field's own R_n
  NewtonControls::Field loose;
  loose.residual_ratio = 0.05;
  EXPECT_TRUE(check_field(loose, 100.0, 4.0, 0.0, 1.0).converged);
}

// u + u^3 = 10 (u = 2): as many iterations as Newton's recurrence needs to meet R_n and C_n (or
// the linear rule), with the same iterate.
TEST(NewtonStages, CubicSpringConvergesInNewtonsIterations) {
  const double k = 1.0, c = 1.0, f = 10.0;
  FunctionProblem p = cubic_spring(k, c, f);
  const NewtonResult r = run(p);
  ASSERT_TRUE(r.converged) << r.reason;
  double u = 0.0;
  int expected = 0;
  for (;;) {
    const double du = -(k * u + c * u * u * u - f) / (k + 3 * c * u * u);
    u += du;
    ++expected;
    const double res = std::abs(k * u + c * u * u * u - f);
    if (res <= 1e-8 * f || (res <= 0.005 * f && std::abs(du) <= 0.01 * std::abs(u))) break;
  }
  EXPECT_GE(expected, 4);
  EXPECT_EQ(r.iterations, expected);
  EXPECT_NEAR(p.u, u, 1e-12);
  EXPECT_EQ(r.severe_iterations, 0);
  EXPECT_EQ(r.cause, FailureCause::None);
  EXPECT_EQ(r.residual_history.size(), static_cast<std::size_t>(expected));
  EXPECT_DOUBLE_EQ(r.flux[0], f);
}

// A linear problem, stage by stage: one solve lands on the answer and the linear rule accepts it
// although the correction is the whole increment.
TEST(NewtonStages, LinearProblemConvergesInOneIterationByTheLinearRule) {
  FunctionProblem p = cubic_spring(200.0, 0.0, 50.0);
  KktSolver s;
  s.analyze(p.pattern());
  NewtonIteration it(p, s, full_newton(), FluxHistory{}, nullptr);
  ASSERT_TRUE(it.start());
  ASSERT_TRUE(it.solve_system());
  it.limit_step();
  EXPECT_NEAR(it.correction()[0], 0.25, 1e-15);
  it.apply_correction();
  ASSERT_TRUE(it.evaluate_state());
  it.widen_flux_scale();
  ASSERT_TRUE(it.track_status_changes());
  EXPECT_TRUE(it.check_convergence());
  EXPECT_LE(it.residual_ratio(), 1e-8);
  EXPECT_FALSE(it.augment()) << "nothing to augment: the attempt is over";
  EXPECT_TRUE(it.result().converged);
  EXPECT_EQ(it.result().iterations, 1);
  EXPECT_EQ(p.evaluations, 2);
}

// r = cbrt(u - 1): Newton's step doubles the distance to the root and the residual grows by
// 2^(1/3) each iteration. The check waits for I_0 = 4 equilibrium iterations and two increases
// in a row.
TEST(NewtonStages, RisingResidualIsDiverging) {
  FunctionProblem p([](double u) { return std::cbrt(u - 1.0); },
                    [](double u) { return 1.0 / (3.0 * std::cbrt((u - 1.0) * (u - 1.0))); }, 1.0);
  const NewtonResult r = run(p);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.cause, FailureCause::Diverging);
  EXPECT_EQ(r.iterations, NewtonControls{}.divergence_check_after);
  ASSERT_EQ(r.residual_history.size(), 4u);
  for (std::size_t i = 1; i < 4; ++i) EXPECT_GT(r.residual_history[i], r.residual_history[i - 1]);
  // a later check (I_0 = 6) lets it rise two iterations more
  NewtonControls c = full_newton();
  c.divergence_check_after = 6;
  FunctionProblem q([](double u) { return std::cbrt(u - 1.0); },
                    [](double u) { return 1.0 / (3.0 * std::cbrt((u - 1.0) * (u - 1.0))); }, 1.0);
  EXPECT_EQ(run(q, c).iterations, 6);
}

// Evaluations that change contact status are severe discontinuity iterations: they do not count
// as equilibrium iterations and an iterate that changed status is not converged.
TEST(NewtonStages, StatusChangesAreSevereIterations) {
  FunctionProblem p = cubic_spring(200.0, 0.0, 50.0);
  p.status_changes = 2;
  NewtonResult r = run(p);
  ASSERT_TRUE(r.converged) << r.reason;
  EXPECT_EQ(r.severe_iterations, 2);
  EXPECT_EQ(r.iterations, 3);
  EXPECT_TRUE(r.chattering.empty());
  // status that never settles (a new element each time, so no chattering) ends the attempt once
  // the severe iterations exceed their limit
  FunctionProblem q = cubic_spring(200.0, 0.0, 50.0);
  q.status_changes = 1000;
  NewtonControls c = full_newton();
  c.max_severe_iterations = 5;
  r = run(q, c);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.cause, FailureCause::Status);
  EXPECT_EQ(r.severe_iterations, 6);
}

// At a converged state the problem may augment its multipliers: the attempt goes on until it
// augments nothing, or fails past max_augmentations.
TEST(NewtonStages, AugmentationContinuesUntilNothingChanges) {
  FunctionProblem p = cubic_spring(200.0, 0.0, 50.0);
  p.augmentations_left = 2;
  NewtonResult r = run(p);
  ASSERT_TRUE(r.converged) << r.reason;
  EXPECT_EQ(r.augmentations, 2);
  FunctionProblem q = cubic_spring(200.0, 0.0, 50.0);
  q.augmentations_left = 100;
  NewtonControls c = full_newton();
  c.max_augmentations = 3;
  r = run(q, c);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.cause, FailureCause::Augmentation);
  EXPECT_EQ(r.augmentations, 4);
}

// The line-search hook scales the correction before it is applied.
TEST(NewtonStages, StepLimitScalesTheCorrection) {
  FunctionProblem p = cubic_spring(200.0, 0.0, 50.0);
  p.step_fraction = 0.5;
  KktSolver s;
  s.analyze(p.pattern());
  NewtonIteration it(p, s, full_newton(), FluxHistory{}, nullptr);
  ASSERT_TRUE(it.start());
  ASSERT_TRUE(it.solve_system());
  it.limit_step();
  EXPECT_NEAR(it.correction()[0], 0.125, 1e-15);
  it.apply_correction();
  EXPECT_NEAR(p.u, 0.125, 1e-15);
  // run to the end: halving steps still converge, on R_n and C_n
  FunctionProblem q = cubic_spring(200.0, 0.0, 50.0);
  q.step_fraction = 0.5;
  const NewtonResult r = run(q);
  ASSERT_TRUE(r.converged) << r.reason;
  EXPECT_EQ(r.iterations, 8); // 2^-8 < R_n = 0.005 < 2^-7
}

TEST(NewtonStages, AnElementsCutBackRequestEndsTheAttempt) {
  FunctionProblem p = cubic_spring(200.0, 0.0, 50.0);
  p.first_dt_ratio = 0.25;
  const NewtonResult r = run(p);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.cause, FailureCause::Requested);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_EQ(r.dt_ratio, 0.25);
}

TEST(NewtonStages, AFailedElementEndsTheAttempt) {
  FunctionProblem p = cubic_spring(1.0, 1.0, 10.0);
  p.throw_at = 3; // after the second correction
  const NewtonResult r = run(p);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.cause, FailureCause::Element);
  EXPECT_EQ(r.iterations, 2);
  EXPECT_NE(r.reason.find("inside out"), std::string::npos);
}

TEST(NewtonStages, ANonFiniteResidualEndsTheAttempt) {
  FunctionProblem p([](double u) { return u == 0.0 ? -1.0 : std::nan(""); },
                    [](double) { return 1.0; }, 1.0);
  const NewtonResult r = run(p);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.cause, FailureCause::NonFinite);
  EXPECT_EQ(r.iterations, 1);
}

TEST(NewtonStages, EquilibriumIterationLimit) {
  FunctionProblem p = cubic_spring(1.0, 1.0, 10.0);
  NewtonControls c = full_newton();
  c.max_equilibrium_iterations = 2;
  const NewtonResult r = run(p, c);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.cause, FailureCause::Iterations);
  EXPECT_EQ(r.iterations, 2);
}

// Every DOF prescribed: the first evaluation gives the reactions, nothing is solved.
TEST(NewtonStages, NothingToSolveConvergesAtOnce) {
  FunctionProblem p = cubic_spring(200.0, 0.0, 50.0);
  p.nothing_free = true;
  const NewtonResult r = run(p);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_EQ(p.evaluations, 1);
  EXPECT_DOUBLE_EQ(r.flux[0], 50.0);
}
