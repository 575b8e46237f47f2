// The user elements of uel_elements.f written as a gapfem element plugin
// (include/gapfem/plugin.hpp): U1 a nonlinear spring, U2 an elastic-plastic truss with state
// variables and PNEWDT. The tests compare both with each other and with closed forms.
#include <cmath>
#include <gapfem/plugin.hpp>

extern "C" int gapfem_plugin_abi_version() {
  return GAPFEM_PLUGIN_ABI_VERSION;
}

namespace {

int spring(gapfem::plugin::Element e) {
  const auto p = e.properties();
  const double d = e.u()[1] - e.u()[0];
  const double f = p[0] * d + p[1] * d * d * d, k = p[0] + 3.0 * p[1] * d * d;
  // gapfem's residual is the internal force: -f at node 1, +f at node 2
  e.residual()[0] = -f;
  e.residual()[1] = f;
  e.tangent(0, 0) = e.tangent(1, 1) = k;
  e.tangent(0, 1) = e.tangent(1, 0) = -k;
  e.state()[0] = f;
  return 0;
}

int truss(gapfem::plugin::Element e) {
  const auto X = e.coords();
  const auto u = e.u();
  const auto p = e.properties();
  double dx[3], L = 0.0;
  for (int i = 0; i < 3; ++i) {
    dx[i] = X[3 + i] - X[i];
    L += dx[i] * dx[i];
  }
  L = std::sqrt(L);
  double eps = 0.0;
  for (int i = 0; i < 3; ++i) {
    dx[i] /= L;
    eps += dx[i] * (u[3 + i] - u[i]);
  }
  eps /= L;
  const double A = p[0], E = p[1], sigy = p[2], H = p[3];
  const auto s0 = e.state_start();
  const auto s = e.state();
  double sig = E * (eps - s0[0]), Et = E;
  const double fy = std::abs(sig) - (sigy + H * s0[1]);
  if (fy > 0.0) {
    const double dgam = fy / (E + H), sign = sig > 0 ? 1.0 : -1.0;
    sig -= E * dgam * sign;
    s[0] = s0[0] + dgam * sign;
    s[1] = s0[1] + dgam;
    Et = E * H / (E + H);
    if (dgam > p[4]) *e.call.pnewdt = 0.5;
  }
  s[2] = sig;
  const double f = sig * A;
  for (int i = 0; i < 3; ++i) {
    e.residual()[i] = -f * dx[i];
    e.residual()[3 + i] = f * dx[i];
    for (int j = 0; j < 3; ++j) {
      const double t = Et * A / L * dx[i] * dx[j];
      e.tangent(i, j) = e.tangent(3 + i, 3 + j) = t;
      e.tangent(i, 3 + j) = e.tangent(3 + i, j) = -t;
    }
  }
  e.energy()[1] = 0.5 * sig * sig / E * A * L;
  return 0;
}

} // namespace

extern "C" int gapfem_element(gapfem_element_call* call) {
  gapfem::plugin::Element e{*call};
  switch (call->type) {
  case 1:
    return spring(e);
  case 2:
    return truss(e);
  default:
    return e.fail("no user element U%d in this plugin", call->type);
  }
}
