// Eigenvalue buckling's initial-stress matrix of a perturbation (assembler.hpp,
// docs/theory/buckling.md): per element the kernel's own, or the central difference of its NLGEOM
// tangent along the perturbation.
#include "fem/assembler.hpp"

#include <algorithm>
#include <cmath>

namespace gapfem {

namespace {

/// (K(u + h du) - K(u - h du)) / (2 h) of one element into Ke (its NLGEOM tangent).
void tangent_difference(const ElementKernel& kernel, ElementGather& g, const ElementBlock& block,
                        ElementInput in, std::span<const double> du, double h,
                        std::vector<double>& Ke) {
  std::vector<double> u(in.u.begin(), in.u.end());
  const std::vector<double> u0 = u;
  for (const double sign : {1.0, -1.0}) {
    for (std::size_t k = 0; k < u.size(); ++k) u[k] = u0[k] + sign * h * du[k];
    in.u = u;
    ElementOutput& o = g.output(block, true);
    kernel.evaluate(in, o);
    for (std::size_t k = 0; k < Ke.size(); ++k) Ke[k] += sign * o.tangent[k] / (2.0 * h);
  }
}

} // namespace

void Assembler::stress_stiffness(const FieldView& fields, const StepContext& ctx,
                                 std::span<const double> du, MatrixInserter& K) {
  StepContext nl = ctx;
  nl.nlgeom = true; // the initial stress matrix is a term of the NLGEOM tangent
  K.set_zero();
  K.open(1);
  ElementGather& g = _scratch[0];
  std::vector<double> local, Ke;
  for (ElementBlock& b : _disc.blocks()) {
    for (std::size_t i = 0; i < b.size(); ++i) {
      const auto slots = b.element_slots(i);
      local.assign(slots.size(), 0.0);
      double big = 0.0;
      for (std::size_t k = 0; k < slots.size(); ++k) {
        local[k] = slots[k] >= 0 ? du[slots[k]] : 0.0;
        big = std::max(big, std::abs(local[k]));
      }
      if (!(big > 0.0)) continue;
      ElementInput& in = g.gather(_disc, b, i, fields, &nl);
      Ke.assign(slots.size() * slots.size(), 0.0);
      if (!b.kernel->stress_stiffness(in, local, Ke))
        tangent_difference(*b.kernel, g, b, in, local, 1e-6 * ctx.model_size / big, Ke);
      const auto eqs = b.element_eqs(i);
      K.add(0, eqs, eqs, Ke);
    }
  }
  K.close();
}

} // namespace gapfem
