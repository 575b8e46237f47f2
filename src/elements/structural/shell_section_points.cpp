// A shell section integrated at its section points by a solid law (shell_section_points.hpp).
#include "elements/structural/shell_section_points.hpp"

#include "elements/structural/structural_common.hpp"

#include <limits>
#include <vector>

namespace gapfem::shell {

using structural::average;

SectionTemperature section_temperature(const Material& material, const ElementInput& in) {
  SectionTemperature s;
  const auto T = average(in.temperature);
  s.T = T.value_or(-std::numeric_limits<double>::infinity()); // the table's first row
  s.Ti = in.initial_temperature.empty() ? s.T : *average(in.initial_temperature);
  s.thermal = T.has_value() && !material.expansion.empty();
  if (!s.thermal) s.Ti = s.T;
  if (s.thermal && !in.temperature_gradient.empty()) {
    const std::size_t nn = in.temperature_gradient.size() / 2;
    for (std::size_t a = 0; a < nn; ++a) s.gradient += in.temperature_gradient[2 * a] / nn;
  }
  return s;
}

ShellSectionPoints::ShellSectionPoints(std::shared_ptr<const SolidLaw> law, int n_points)
    : _law(std::move(law)), _n(n_points) {}

void ShellSectionPoints::initialize(std::span<double> state) const {
  const auto m = static_cast<std::size_t>(_law->n_state());
  if (m == 0) return;
  for (int k = 0; k < _n; ++k) _law->initialize(state.subspan(k * m, m));
}

/// One section point: its stress, and with D its tangent (3 x 3) and with `energy` its stored
/// energy per unit volume.
std::array<double, 3> ShellSectionPoints::point_update(const SectionTemperature& temp, double z,
                                                       const std::array<double, 3>& strain,
                                                       std::span<const double> start,
                                                       std::span<double> trial,
                                                       std::array<double, 9>* D,
                                                       double* energy) const {
  std::array<double, 3> sigma{};
  MaterialPointInput in;
  in.strain = strain;
  in.state_start = start;
  in.temperature = temp.thermal ? temp.T + z * temp.gradient : temp.T;
  in.initial_temperature = temp.Ti;
  in.thermal = temp.thermal;
  in.recovery = energy != nullptr;
  MaterialPointOutput out;
  out.stress = sigma;
  out.state = trial;
  if (D) out.tangent = *D;
  _law->update(in, out);
  if (D && out.isotropic) { // lambda* 1 1^T + 2 mu I on the normals, mu on the shear
    const IsotropicModuli& m = out.moduli;
    *D = {
        m.lambda + 2.0 * m.mu, m.lambda, 0.0, m.lambda, m.lambda + 2.0 * m.mu, 0.0, 0.0, 0.0, m.mu};
  }
  if (energy) *energy = out.energy;
  return sigma;
}

void ShellSectionPoints::respond(const SectionLaw& l, const SectionTemperature& temp, double t,
                                 const SectionStrains<double>& s,
                                 std::span<const double> state_start, std::span<double> state,
                                 bool want_tangent, SectionResponse& out,
                                 SectionPointsOutput* recovery) const {
  const auto m = static_cast<std::size_t>(_law->n_state());
  std::vector<double> scratch(state.empty() ? m : 0u);
  out.R = {};
  out.C = {};
  const double zm = -l.offset * t, h = t / (_n - 1);
  for (int k = 0; k < _n; ++k) {
    const double z = zm - 0.5 * t + h * k;
    const double w = h / 3.0 * (k == 0 || k == _n - 1 ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0));
    std::array<double, 3> strain;
    for (int i = 0; i < 3; ++i) strain[i] = s.eps[i] + z * s.kap[i];
    std::array<double, 9> D{};
    double energy = 0.0;
    const std::span<double> trial =
        state.empty() ? std::span<double>(scratch) : state.subspan(k * m, m);
    const auto sigma = point_update(temp, z, strain, state_start.subspan(k * m, m), trial,
                                    want_tangent ? &D : nullptr, recovery ? &energy : nullptr);
    for (int i = 0; i < 3; ++i) {
      out.R[i] += w * sigma[i];
      out.R[3 + i] += w * z * sigma[i];
    }
    if (want_tangent)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const double d = w * D[3 * i + j];
          out.C[8 * i + j] += d;
          out.C[8 * i + 3 + j] += z * d;
          out.C[8 * (3 + i) + j] += z * d;
          out.C[8 * (3 + i) + 3 + j] += z * z * d;
        }
    if (recovery) {
      recovery->energy += w * energy;
      for (int i = 0; i < 3; ++i) {
        if (!recovery->stress.empty()) recovery->stress[3 * k + i] = sigma[i];
        if (!recovery->strain.empty()) recovery->strain[3 * k + i] = strain[i];
      }
    }
  }
  const auto K = shear_stiffness(l, t);
  out.R[6] = K[0] * s.gam[0];
  out.R[7] = K[1] * s.gam[1];
  out.C[8 * 6 + 6] = K[0];
  out.C[8 * 7 + 7] = K[1];
  if (recovery) recovery->energy += 0.5 * (out.R[6] * s.gam[0] + out.R[7] * s.gam[1]);
}

double recover_section_points(const ShellSectionPoints& sp, const SectionLaw& l,
                              const SectionTemperature& temp,
                              std::span<const SectionStrains<double>> e, std::span<const double> t,
                              std::span<const double> dA, std::span<const double> state_start,
                              bool one_point, ElementRecovery& out) {
  const int nq = static_cast<int>(e.size()), ns = sp.n_points(), np = one_point ? 1 : nq;
  const ShellOutputBlocks b = add_shell_output_blocks(np, ns, out);
  const auto m = static_cast<std::size_t>(sp.n_state());
  const double share = one_point ? 1.0 / nq : 1.0; // the centre point: the points' mean
  std::vector<double> S(3 * static_cast<std::size_t>(ns)), E(S.size());
  double energy = 0.0;
  for (int q = 0; q < nq; ++q) {
    SectionPointsOutput r{S, E};
    SectionResponse resp;
    sp.respond(l, temp, t[q], e[q], state_start.subspan(q * m, m), {}, false, resp, &r);
    energy += dA[q] * r.energy;
    const int p = one_point ? 0 : q;
    for (int i = 0; i < 8; ++i) // SF1-3 = N, SF4-5 = Q, SM1-3 = M
      b.SF->values[8 * p + i] += share * resp.R[i < 3 ? i : (i < 5 ? i + 3 : i - 2)];
    for (std::size_t i = 0; i < S.size(); ++i) {
      b.S->values[3 * ns * p + i] += share * S[i];
      b.E->values[3 * ns * p + i] += share * E[i];
    }
  }
  return energy;
}

} // namespace gapfem::shell
