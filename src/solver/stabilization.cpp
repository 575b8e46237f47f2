#include "solver/stabilization.hpp"

#include "model/model.hpp"

#include <algorithm>
#include <cmath>

namespace gapfem {

std::vector<double> unit_density_mass(Discretization& disc, Assembler& assembler,
                                      const FieldView& fields, const StepContext& ctx) {
  const DofMap& dofs = disc.dofs();
  const int ndir = ctx.space == ModelSpace::ThreeD ? 3 : 2;
  std::vector<DistributedLoad> loads;
  for (const ElementBlock& b : disc.blocks()) {
    if (!b.kernel->supports_load(DistLoadKind::BodyForce, 0)) continue;
    for (ElemId e : b.elements)
      for (int d = 0; d < ndir; ++d) {
        DistributedLoad l;
        l.elem = e;
        l.kind = DistLoadKind::BodyForce;
        l.magnitude = 1.0;
        l.direction[d] = 1.0;
        loads.push_back(l);
      }
  }
  std::vector<ActiveLoad> active;
  active.reserve(loads.size());
  for (const DistributedLoad& l : loads) active.push_back({&l, 1.0, 0.0});
  std::vector<double> f(static_cast<std::size_t>(dofs.n_slots()), 0.0);
  assembler.assemble_loads(active, fields, ctx, f, nullptr);
  // a unit body force in x loads only the x slots: f is the lumped mass there
  for (LocalIndex s = 0; s < dofs.n_slots(); ++s)
    if (dofs.slot_field(s) != Field::Displacement || !(f[s] > 0.0)) f[s] = 0.0;
  return f;
}

double initial_stabilization_factor(const Stabilization& spec, double dt0,
                                    const std::vector<double>& mass,
                                    const std::vector<double>& stiffness_diagonal) {
  if (spec.factor) return *spec.factor;
  double k = 0.0, m = 0.0;
  for (std::size_t s = 0; s < mass.size(); ++s)
    if (mass[s] > 0.0) {
      m += mass[s];
      k += std::abs(stiffness_diagonal[s]);
    }
  if (!(m > 0.0) || !(k > 0.0) || !(dt0 > 0.0)) return 0.0;
  return spec.fraction * dt0 * k / (2.0 * m);
}

double adapted_stabilization_factor(const Stabilization& spec, double c, double allsd,
                                    double allie) {
  if (spec.allsdtol <= 0.0 || !(allie > 0.0)) return c;
  const double ratio = allsd / allie;
  if (ratio <= spec.allsdtol) return c;
  return c * std::max(0.25, spec.allsdtol / ratio);
}

} // namespace gapfem
