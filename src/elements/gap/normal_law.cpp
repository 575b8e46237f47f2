#include "elements/gap/normal_law.hpp"

#include "model/section.hpp"

#include <cmath>

namespace gapfem {

void CcxPenaltyLaw::force(double g, double& F, double& dF_dg) const {
  constexpr double kPi = 3.141592653589793;
  const double x = g / _eps;
  const double f = 0.5 + std::atan(x) / kPi;
  F = _k * g * f;
  dF_dg = _k * f + _k * x / (kPi * (1.0 + x * x));
}

std::unique_ptr<NormalForceLaw> make_normal_law(const GapSection& s) {
  if (s.ccx_penalty) return std::make_unique<CcxPenaltyLaw>(s.ccx_stiffness, s.ccx_tension);
  return nullptr;
}

} // namespace gapfem
