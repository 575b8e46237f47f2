#include "solver/extrapolation.hpp"

#include "common/error.hpp"

namespace gapfem {

void IncrementPredictor::start_step() {
  _known = 0;
  _dt1 = _dt2 = 0.0;
}

void IncrementPredictor::record(std::span<const double> u, std::span<const double> u_start,
                                double dt) {
  if (!(dt > 0.0)) return; // a zero-length increment says nothing about the rate
  std::swap(_du1, _du2);
  _dt2 = _dt1;
  _du1.resize(u.size());
  for (std::size_t k = 0; k < u.size(); ++k) _du1[k] = u[k] - u_start[k];
  _dt1 = dt;
  _known = std::min(_known + 1, 2);
}

std::span<const double> IncrementPredictor::guess(Extrapolation how, double dt) {
  if (how == Extrapolation::None || _known == 0 || !(dt > 0.0)) return {};
  const std::size_t n = _du1.size();
  _guess.resize(n);
  const double r = dt / _dt1;
  if (how == Extrapolation::Linear || _known < 2 || _du2.size() != n) {
    for (std::size_t k = 0; k < n; ++k) _guess[k] = r * _du1[k];
    return _guess;
  }
  // The parabola p through u_{n-2}, u_{n-1}, u_n (at t_n - dt1 - dt2, t_n - dt1, t_n), in
  // Newton's form about t_n: p(t_n + h) - u_n = s1 h + s12 h (h + dt1), with the divided
  // differences s1 = du1 / dt1 and s12 = (du1 / dt1 - du2 / dt2) / (dt1 + dt2).
  const double a = dt / _dt1 + dt * (dt + _dt1) / (_dt1 * (_dt1 + _dt2));
  const double b = -dt * (dt + _dt1) / (_dt2 * (_dt1 + _dt2));
  for (std::size_t k = 0; k < n; ++k) _guess[k] = a * _du1[k] + b * _du2[k];
  return _guess;
}

void IncrementPredictor::save(ArchiveWriter& a) const {
  a.pod(_known);
  a.pod(_dt1);
  a.pod(_dt2);
  a.vec(_du1);
  a.vec(_du2);
}

void IncrementPredictor::restore(ArchiveReader& in, std::size_t slots) {
  in.pod(_known);
  in.pod(_dt1);
  in.pod(_dt2);
  in.vec(_du1);
  in.vec(_du2);
  if (_known < 0 || _known > 2 || (_known > 0 && (!(_dt1 > 0) || _du1.size() != slots)) ||
      (_known > 1 && (!(_dt2 > 0) || _du2.size() != slots)))
    throw RestartDataError("the restart record's extrapolation history is damaged");
}

} // namespace gapfem
