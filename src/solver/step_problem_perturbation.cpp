// The operators of a linear perturbation step about the committed state (*FREQUENCY, *BUCKLE, a
// static perturbation): what the elements' tangent and mass are there, with the constraint rows
// that hold the state; the perturbation's right sides; the differential stiffness of buckling.
#include "solver/step_problem.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace gapfem {

StepProblem::PerturbationOperators StepProblem::perturbation_operators(bool with_mass) {
  PerturbationOperators ops;
  const OperatorWeights keep = _weights;
  begin_increment(0.0, 0.0); // the committed state, the step's values at its start
  _weights = {1.0, 0.0, 0.0, 1.0};
  evaluate(true);
  ops.K = _K;
  ops.C = _C;
  if (with_mass) {
    _weights = {0.0, 0.0, 1.0, 1.0};
    evaluate(true);
    ops.M = _K;
  }
  _weights = keep;
  return ops;
}

namespace {

/// The rows' values of `now` in the order of `rows` (matched by multiplier; 0 where absent).
std::vector<double> row_values(const ConstraintBlock& rows, const ConstraintBlock& now) {
  std::unordered_map<std::int64_t, double> g;
  for (int r = 0; r < now.n_rows(); ++r) g[now.multiplier[r]] = now.g[r];
  std::vector<double> out(rows.g.size(), 0.0);
  for (int r = 0; r < rows.n_rows(); ++r)
    if (const auto it = g.find(rows.multiplier[r]); it != g.end()) out[r] = it->second;
  return out;
}

} // namespace

StepProblem::PerturbationLoad StepProblem::perturbation_load(const ConstraintBlock& C) {
  const OperatorWeights keep = _weights;
  _weights = {1.0, 0.0, 0.0, 1.0};
  PerturbationLoad p;
  // A: the committed state at the step's start; B: the same state under the step's end values
  begin_increment(0.0, 0.0);
  evaluate(false);
  const std::vector<double> rhs_a = _rhs, g_a = row_values(C, _C);
  begin_increment(0.0, _loads.period());
  const std::vector<double> u_end = _s.u; // the prescribed values at the step's end
  std::copy(_s.u_start.begin(), _s.u_start.end(), _s.u.begin());
  evaluate(false);
  p.b.resize(rhs_a.size());
  const std::vector<double> g_b = row_values(C, _C);
  for (std::size_t i = 0; i < p.b.size(); ++i) p.b[i] = _rhs[i] - rhs_a[i];
  p.g.resize(g_a.size());
  for (std::size_t r = 0; r < p.g.size(); ++r) p.g[r] = g_b[r] - g_a[r];
  p.prescribed.assign(_s.u.size(), 0.0);
  double big = 0.0;
  for (std::size_t k = 0; k < u_end.size(); ++k) {
    p.prescribed[k] = u_end[k] - _s.u_start[k];
    big = std::max(big, std::abs(p.prescribed[k]));
  }
  if (big > 0.0) { // C: B moved by eps of the prescribed perturbation, for its stiffness
    const double eps = 1e-6 * _ctx.model_size / big;
    const std::vector<double> rhs_b = _rhs;
    for (std::size_t k = 0; k < u_end.size(); ++k) _s.u[k] = _s.u_start[k] + eps * p.prescribed[k];
    evaluate(false);
    const std::vector<double> g_c = row_values(C, _C);
    for (std::size_t i = 0; i < p.b.size(); ++i) p.b[i] += (_rhs[i] - rhs_b[i]) / eps;
    for (std::size_t r = 0; r < p.g.size(); ++r) p.g[r] += (g_c[r] - g_b[r]) / eps;
  }
  const double scale = std::max(1.0, std::abs(_ctx.model_size));
  p.any = big > 0.0;
  for (double v : p.b) p.any |= std::abs(v) > 1e-300;
  for (double v : p.g) p.any |= std::abs(v) > 1e-14 * scale;
  begin_increment(0.0, 0.0);
  _weights = keep;
  return p;
}

CsrMatrix StepProblem::differential_stiffness(std::span<const double> du, bool load_stiffness) {
  const OperatorWeights keep = _weights;
  const bool nlgeom = _ctx.nlgeom;
  _weights = {1.0, 0.0, 0.0, 1.0};
  begin_increment(0.0, 0.0);
  _asm.stress_stiffness(fields(), _ctx, du, _Kin);
  CsrMatrix KD = _K;
  auto d = KD.values();
  if (load_stiffness) { // the follower loads' stiffness at the step's end less that at its start
    _ctx.nlgeom = true;
    const auto at = [&](double step_time) {
      begin_increment(0.0, step_time);
      std::copy(_s.u_start.begin(), _s.u_start.end(), _s.u.begin());
      evaluate(true);
      return _K;
    };
    const CsrMatrix end = at(_loads.period()), start = at(0.0);
    const auto e = end.values(), s0 = start.values();
    for (std::size_t k = 0; k < d.size(); ++k) d[k] += e[k] - s0[k];
    _ctx.nlgeom = nlgeom;
  }
  begin_increment(0.0, 0.0);
  _weights = keep;
  // symmetrised, as Abaqus does (a follower load's stiffness is not symmetric)
  const SparsityPattern& p = KD.pattern();
  for (LocalIndex i = 0; i < p.n; ++i)
    for (LocalIndex k = p.row_ptr[i]; k < p.row_ptr[i + 1]; ++k)
      if (const LocalIndex j = p.col[k]; j > i)
        if (const LocalIndex t = p.find(j, i); t >= 0) d[k] = d[t] = 0.5 * (d[k] + d[t]);
  return KD;
}

} // namespace gapfem
