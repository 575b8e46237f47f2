// Newton and the increment controller on small problems written directly against the
// NonlinearProblem interface (no elements): a linear problem converges in one iteration, a
// nonlinear scalar problem converges quadratically, an element whose status flips every evaluation
// is reported as chattering, and the automatic incrementation follows Abaqus's rules.
#include "linalg/kkt_solver.hpp"
#include "solver/increment_control.hpp"
#include "solver/newton.hpp"

#include <cmath>
#include <gtest/gtest.h>

using namespace gapfem;

namespace {

/// r(u) = k u + c u^3 - f for one displacement unknown; optionally a fake contact status that flips
/// at every evaluation.
class ScalarProblem final : public NonlinearProblem {
 public:
  ScalarProblem(double k, double c, double f, bool chatter = false)
      : _k(k), _c(c), _f(f), _chatter(chatter) {
    std::vector<std::span<const LocalIndex>> el{std::span<const LocalIndex>(_eq)};
    _pattern = build_pattern(1, el);
    _K = CsrMatrix(_pattern);
    _rhs.assign(1, 0.0);
  }
  std::shared_ptr<const SparsityPattern> pattern() const { return _pattern; }
  Evaluation evaluate(bool tangent) override {
    ++evaluations;
    Evaluation ev;
    ev.tangent = tangent;
    const double r = _k * u + _c * u * u * u - _f;
    _rhs[0] = -r;
    if (tangent) {
      ++tangents;
      _K.set_zero();
      _K.values()[0] = _k + 3 * _c * u * u;
    }
    ev.has_field[0] = true;
    ev.residual_max[0] = std::abs(r);
    ev.flux[0] = std::abs(_f);
    if (_chatter) {
      ev.status_changes = 1;
      ev.changed = {7};
    }
    return ev;
  }
  Evaluation assemble_tangent() override {
    ++tangents;
    _K.set_zero();
    _K.values()[0] = _k + 3 * _c * u * u;
    return {};
  }
  CsrMatrix& matrix() override { return _K; }
  std::span<const double> rhs() const override { return _rhs; }
  const ConstraintBlock& constraints() const override { return _C; }
  void apply(std::span<const double> du, std::span<const double>) override {
    u += du[0];
    _last = du[0];
  }
  Field equation_field(LocalIndex) const override { return Field::Displacement; }
  std::array<double, kNumFields> increment_max() const override { return {std::abs(u), 0, 0}; }
  double constraint_tolerance() const override { return 1e-10; }

  double u = 0.0;
  int evaluations = 0, tangents = 0;

 private:
  double _k, _c, _f;
  bool _chatter;
  std::vector<LocalIndex> _eq{0};
  std::shared_ptr<SparsityPattern> _pattern;
  CsrMatrix _K;
  std::vector<double> _rhs;
  ConstraintBlock _C;
  double _last = 0.0;
};

} // namespace

TEST(Newton, LinearProblemConvergesInOneIteration) {
  ScalarProblem p(200.0, 0.0, 50.0);
  KktSolver s;
  s.analyze(p.pattern());
  const NewtonResult r = solve_increment(p, s, NewtonControls{}, FluxHistory{}, nullptr);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.iterations, 1);
  EXPECT_NEAR(p.u, 0.25, 1e-15);
}

TEST(Newton, NonlinearProblemConvergesQuadratically) {
  ScalarProblem p(1.0, 1.0, 10.0); // u + u^3 = 10, u = 2
  KktSolver s;
  s.analyze(p.pattern());
  const NewtonResult r = solve_increment(p, s, NewtonControls{}, FluxHistory{}, nullptr);
  ASSERT_TRUE(r.converged);
  EXPECT_NEAR(p.u, 2.0, 1e-6);
  // the last ratios fall quadratically: r_{k+1} <= C r_k^2 with C ~ |f''/(2 f')| / flux scale
  const auto& h = r.residual_history;
  ASSERT_GE(h.size(), 3u);
  for (std::size_t k = h.size() - 2; k + 1 < h.size(); ++k)
    EXPECT_LE(h[k + 1], 10.0 * h[k] * h[k]) << k;
}

TEST(Newton, ChatteringStatusIsDetected) {
  ScalarProblem p(200.0, 0.0, 50.0, /*chatter=*/true);
  KktSolver s;
  s.analyze(p.pattern());
  const NewtonResult r = solve_increment(p, s, NewtonControls{}, FluxHistory{}, nullptr);
  EXPECT_FALSE(r.converged);
  ASSERT_EQ(r.chattering.size(), 1u);
  EXPECT_EQ(r.chattering[0], 7);
  EXPECT_EQ(r.severe_iterations, NewtonControls{}.chatter_flips);
}

namespace {
/// Modified Newton on one unknown: keeps the first matrix it is given and tells Newton that it can
/// do without the matrix; with `refuse_once`, its first solve without the matrix asks for it.
class KeptFactorSolver final : public ConstrainedSolver {
 public:
  explicit KeptFactorSolver(bool refuse_once, bool report_stale = false)
      : _refuse(refuse_once), _report_stale(report_stale) {}
  std::string_view name() const override { return "kept factor"; }
  void analyze(std::shared_ptr<const SparsityPattern>) override {}
  void forget_factor() override { _k = 0.0; }
  bool matrix_optional() const override { return _k != 0.0; }
  /// One unknown without rows: x = b / K.
  struct OneFactor final : ConstrainedFactor {
    double k = 1.0;
    void solve(std::span<const double> b, std::span<const double>, std::span<double> x,
               std::span<double>, int n) override {
      for (int j = 0; j < n; ++j) x[j] = b[j] / k;
    }
  };
  std::unique_ptr<ConstrainedFactor> factorize(const CsrMatrix& K, const ConstraintBlock&, bool,
                                               RunStatistics*) override {
    auto f = std::make_unique<OneFactor>();
    f->k = K.values()[0];
    return f;
  }
  KktStatistics solve(CsrMatrix& K, std::span<const double> b, const ConstraintBlock&,
                      std::span<double> du, std::span<double>, bool, const KktOptions& opt,
                      RunStatistics*) override {
    KktStatistics st;
    fresh_requests += opt.force_fresh;
    st.stale_factor = _report_stale && _k != 0.0;
    if (!opt.matrix_current) {
      ++without_matrix;
      if (_refuse) {
        _refuse = false;
        st.needs_matrix = true;
        return st;
      }
    } else if (_k == 0.0) {
      _k = K.values()[0];
    }
    du[0] = b[0] / _k;
    return st;
  }
  int without_matrix = 0, fresh_requests = 0;

 private:
  bool _refuse, _report_stale;
  double _k = 0.0;
};
} // namespace

// While the solver keeps a factor it can reuse, Newton evaluates the residual alone: the tangent
// is assembled once (the first evaluation), and modified Newton still reaches the answer.
TEST(Newton, ResidualAloneWhileTheSolverKeepsItsFactor) {
  ScalarProblem p(1.0, 0.01, 2.0); // u + 0.01 u^3 = 2
  KeptFactorSolver s(false);
  const NewtonResult r = solve_increment(p, s, NewtonControls{}, FluxHistory{}, nullptr);
  ASSERT_TRUE(r.converged) << r.reason;
  EXPECT_NEAR(p.u + 0.01 * p.u * p.u * p.u, 2.0, 0.005 * 2.0);
  EXPECT_GT(r.iterations, 2);
  EXPECT_EQ(p.tangents, 1);
  EXPECT_EQ(s.without_matrix, r.iterations - 1);
  // switched off, every evaluation assembles it
  ScalarProblem q(1.0, 0.01, 2.0);
  KeptFactorSolver t(false);
  NewtonControls c;
  c.residual_only = false;
  const NewtonResult rq = solve_increment(q, t, c, FluxHistory{}, nullptr);
  ASSERT_TRUE(rq.converged);
  EXPECT_EQ(q.tangents, q.evaluations);
  EXPECT_EQ(t.without_matrix, 0);
}

// A solver that cannot do without the matrix after all gets it at the same state, and the step
// is solved again.
TEST(Newton, TheTangentIsAssembledWhenTheSolverAsksForIt) {
  ScalarProblem p(1.0, 0.01, 2.0);
  KeptFactorSolver s(true);
  const NewtonResult r = solve_increment(p, s, NewtonControls{}, FluxHistory{}, nullptr);
  ASSERT_TRUE(r.converged) << r.reason;
  EXPECT_EQ(p.tangents, 2);                      // the first evaluation, and the one asked for
  EXPECT_EQ(s.without_matrix, r.iterations - 1); // the refused call, then iterations 3, 4, ...
}

// A stale factor that contracts the residual slowly is replaced, unless full Newton itself was
// seen contracting as slowly in the step's earlier increments (NewtonControls::fresh_contraction).
TEST(Newton, AStaleFactorIsNotBlamedForTheStepsOwnSlowContraction) {
  for (const double hint : {0.0, 0.9}) {
    ScalarProblem p(1.0, 0.05, 2.0); // modified Newton from k = 1 contracts by about 0.45
    KeptFactorSolver s(false, /*report_stale=*/true);
    NewtonControls c;
    c.fresh_contraction = hint;
    const NewtonResult r = solve_increment(p, s, c, FluxHistory{}, nullptr);
    ASSERT_TRUE(r.converged) << r.reason;
    if (hint == 0.0)
      EXPECT_GT(s.fresh_requests, 0);
    else
      EXPECT_EQ(s.fresh_requests, 0);
  }
}

TEST(IncrementControl, CutbackGrowthAndMinimum) {
  Incrementation inc;
  inc.initial = 0.1;
  inc.period = 1.0;
  inc.minimum = 0.01;
  IncrementController c(inc, 100);
  EXPECT_DOUBLE_EQ(c.next(), 0.1);
  c.accept(3); // easy
  EXPECT_DOUBLE_EQ(c.next(), 0.1);
  c.accept(3); // second easy increment: grow by 1.5
  EXPECT_DOUBLE_EQ(c.next(), 0.15);
  EXPECT_TRUE(c.reject()); // cut back by 0.25
  EXPECT_DOUBLE_EQ(c.next(), 0.0375);
  EXPECT_FALSE(c.reject()); // 0.009375 < minimum 0.01
  EXPECT_NE(c.failure().find("less than the minimum"), std::string::npos);
}

TEST(IncrementControl, LastIncrementEndsExactlyAtThePeriod) {
  Incrementation inc;
  inc.initial = 0.3;
  IncrementController c(inc, 100);
  double t = 0;
  int n = 0;
  while (!c.finished()) {
    t += c.next();
    c.accept(12); // hard increments: no growth (shrink by 0.75)
    ++n;
  }
  EXPECT_DOUBLE_EQ(c.step_time(), 1.0);
  EXPECT_NEAR(t, 1.0, 1e-15);
  EXPECT_GE(n, 4);
}

// A dynamic step without HAFTOL (docs/theory/dynamics.md §4): the increments never exceed the
// initial size, but grow back to it after a cut-back by the static rules.
TEST(IncrementControl, CeilingLetsACutBackGrowBackToTheInitialSizeOnly) {
  Incrementation inc;
  inc.initial = 0.01;
  inc.period = 1.0;
  IncrementRules rules;
  rules.ceiling = 0.01;
  IncrementController c(inc, 1000, rules);
  c.accept(2);
  c.accept(2);
  EXPECT_DOUBLE_EQ(c.next(), 0.01) << "never above the initial size";
  EXPECT_TRUE(c.reject());
  EXPECT_DOUBLE_EQ(c.next(), 0.0025);
  c.accept(2);
  c.accept(2); // two easy increments: 1.5 x
  EXPECT_DOUBLE_EQ(c.next(), 0.00375);
  for (int k = 0; k < 6; ++k) c.accept(2);
  EXPECT_DOUBLE_EQ(c.next(), 0.01) << "back at the initial size, not beyond";
}

TEST(IncrementControl, DirectAllowsNoCutback) {
  Incrementation inc;
  inc.initial = 0.25;
  inc.direct = true;
  IncrementController c(inc, 100);
  c.accept(3);
  c.accept(3);
  EXPECT_DOUBLE_EQ(c.next(), 0.25) << "DIRECT never grows";
  EXPECT_FALSE(c.reject());
}
