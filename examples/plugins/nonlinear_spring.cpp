// A gapfem element plugin (include/gapfem/plugin.hpp): an elastic-plastic support spring with
// kinematic hardening, of the kind used for snubbers and friction dampers in piping.
//
// User element U1 (*USER ELEMENT, TYPE=U1, NODES=2, PROPERTIES=3, VARIABLES=2, with the DOF line
// "1"): a spring between DOF 1 of its two nodes. Properties (*UEL PROPERTY): k, the elastic
// stiffness; Fy, the force at first yield; h, the hardening stiffness after yield. State: (1) the
// plastic displacement dp, (2) the back force b. The force is F = k (d - dp), d = u2 - u1, inside
// the yield surface |F - b| <= Fy; plastic flow moves the surface with it, b = h dp (linear
// kinematic hardening: the tangent after yield is k h / (k + h)).
//
// Build it with the project (target example_plugin) or let gapfem compile it:
//   gapfem --user examples/plugins/nonlinear_spring.cpp examples/plugins/snubber.inp
#include <cmath>
#include <gapfem/plugin.hpp>

extern "C" int gapfem_plugin_abi_version() {
  return GAPFEM_PLUGIN_ABI_VERSION;
}

extern "C" int gapfem_element(gapfem_element_call* call) {
  gapfem::plugin::Element e{*call};
  if (call->type != 1) return e.fail("this plugin defines U1 only, not U%d", call->type);
  if (call->n_dofs != 2 || call->n_properties != 3 || call->n_state != 2)
    return e.fail("U1 needs NODES=2 with DOF 1, PROPERTIES=3 and VARIABLES=2");
  const double k = e.properties()[0], fy = e.properties()[1], h = e.properties()[2];
  if (!(k > 0) || !(fy > 0) || !(h >= 0)) return e.fail("U1 needs k > 0, Fy > 0, h >= 0");
  const auto start = e.state_start();
  const auto state = e.state();
  const double d = e.u()[1] - e.u()[0];
  // elastic predictor from the start of the increment, then the return map (linear kinematic
  // hardening: the yield surface |F - b| = Fy moves with the back force b = h dp)
  double dp = start[0], b = start[1];
  double f = k * (d - dp), kt = k;
  const double excess = std::abs(f - b) - fy;
  if (excess > 0) {
    const double sign = f - b > 0 ? 1.0 : -1.0, dgam = excess / (k + h);
    dp += dgam * sign;
    b += h * dgam * sign;
    f = k * (d - dp);
    kt = k * h / (k + h);
  }
  state[0] = dp;
  state[1] = b;
  // the internal force: -F on node 1, +F on node 2 (F > 0 in tension)
  e.residual()[0] = -f;
  e.residual()[1] = f;
  e.tangent(0, 0) = e.tangent(1, 1) = kt;
  e.tangent(0, 1) = e.tangent(1, 0) = -kt;
  e.energy()[1] = 0.5 * f * f / k; // the elastic energy (ALLSE)
  return 0;
}
