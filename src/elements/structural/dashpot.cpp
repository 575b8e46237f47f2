// Dashpots DASHPOT1, DASHPOT2, DASHPOTA (dashpot.hpp).
#include "elements/structural/dashpot.hpp"

#include "elements/reference_scale.hpp"
#include "elements/structural/structural_common.hpp"

namespace gapfem {

using namespace structural;

DashpotKernel::DashpotKernel(ElementType type, const SpringSection& section, ModelSpace space)
    : _type(type), _c(section.stiffness), _nonlinear(section.nonlinear) {
  if (_nonlinear) {
    _table.x = section.relative;
    _table.y = section.force;
    _table.extrapolation = Curve::Extrapolation::Constant;
  }
  switch (type) {
  case ElementType::DASHPOT1:
  case ElementType::DASHPOT2:
    _act = fixed_action(type, section, space);
    break;
  case ElementType::DASHPOTA:
    _ndim = space == ModelSpace::ThreeD ? 3 : 2;
    _act.n0 = _act.n1 = _ndim;
    for (int i = 0; i < _ndim; ++i) _act.dofs0[i] = _act.dofs1[i] = static_cast<DofType>(i);
    break;
  default:
    FE_CHECK(false, "DashpotKernel built for a non-dashpot element type");
  }
}

std::span<const DofType> DashpotKernel::node_dofs(int local_node) const {
  return local_node == 0 ? std::span<const DofType>(_act.dofs0.data(), _act.n0)
                         : std::span<const DofType>(_act.dofs1.data(), _act.n1);
}

std::string DashpotKernel::validate(const ElementInput& in) const {
  if (_type != ElementType::DASHPOTA) return {};
  Vec3 b = in.X[1];
  if (_ndim == 2) b[2] = in.X[0][2];
  if (!(point_distance(in.X[0], b) > 1e-12 * (in.ctx ? in.ctx->model_size : 1.0)))
    return "the two nodes of this DASHPOTA element coincide, so its line of action is undefined; "
           "move one node or use DASHPOT2 with explicit degrees of freedom";
  return {};
}

void DashpotKernel::force(const ElementInput& in, double w, double& F, double& dF) const {
  if (_nonlinear) {
    F = _table.value(w);
    dF = _table.slope(w);
    return;
  }
  dF = table_value(_c, average(in.temperature));
  F = dF * w;
}

bool DashpotKernel::nlgeom_line(const ElementInput& in) const {
  return _type == ElementType::DASHPOTA && in.ctx != nullptr && in.ctx->nlgeom;
}

DashpotKernel::Line DashpotKernel::line(const ElementInput& in) const {
  Line ln;
  switch (_type) {
  case ElementType::DASHPOT1:
  case ElementType::DASHPOT2:
    ln.nd = _act.n_dofs();
    ln.B = _act.B;
    return ln;
  default: {
    const AxialKinematics kin = axial_kinematics(_ndim, in.X, in.u, nlgeom_line(in));
    ln.nd = 2 * _ndim;
    ln.l = kin.l;
    for (int i = 0; i < _ndim; ++i) {
      ln.n[i] = kin.n[i];
      ln.B[i] = -kin.n[i];
      ln.B[_ndim + i] = kin.n[i];
    }
    return ln;
  }
  }
}

void DashpotKernel::add_turning(const Line& ln, std::span<const double> dv, double F, double dF,
                                ElementOutput& out) const {
  // r2 = F n = -r1, n = d / l: dn/du2 = P / l = -dn/du1 with P = I - n n^T, and at fixed nodal
  // velocities dw/du2 = (P dv)^T / l, dv = v(2) - v(1) (or the increment over dt). So
  // d r2 / d u2 = (dF n (P dv)^T + F P) / l, with the signs of an axial member for the others.
  if (!out.want_tangent || !(ln.l > 0.0)) return;
  const int nd = _ndim, n = 2 * nd;
  std::array<double, 3> Pdv{};
  const double ndv = ln.n[0] * dv[0] + ln.n[1] * dv[1] + (nd == 3 ? ln.n[2] * dv[2] : 0.0);
  for (int i = 0; i < nd; ++i) Pdv[i] = dv[i] - ln.n[i] * ndv;
  bool unsym = false;
  for (int i = 0; i < nd; ++i)
    for (int j = 0; j < nd; ++j) {
      const double P = (i == j ? 1.0 : 0.0) - ln.n[i] * ln.n[j];
      const double kij = (dF * ln.n[i] * Pdv[j] + F * P) / ln.l;
      unsym = unsym || dF * Pdv[j] * ln.n[i] != 0.0;
      out.tangent[i * n + j] += kij;
      out.tangent[i * n + nd + j] -= kij;
      out.tangent[(nd + i) * n + j] -= kij;
      out.tangent[(nd + i) * n + nd + j] += kij;
    }
  out.unsymmetric = out.unsymmetric || unsym;
}

void DashpotKernel::evaluate(const ElementInput& in, ElementOutput& out) const {
  const Line ln = line(in);
  const int n = ln.nd;
  const StepContext* ctx = in.ctx;
  // the nodal velocities: the integrator's (the assembler applies C v) or, in a static step,
  // the increment over the time increment
  const bool operator_path = !in.v.empty();
  const bool quasi_static = !operator_path && ctx != nullptr && !ctx->rates.defined() &&
                            ctx->procedure != Procedure::Dynamic && ctx->dt > 0.0;
  std::array<double, 6> v{};
  if (operator_path)
    for (int k = 0; k < n; ++k) v[k] = in.v[k];
  else if (quasi_static)
    for (int k = 0; k < n; ++k) v[k] = (in.u[k] - in.u_start[k]) / ctx->dt;
  double w = 0.0;
  for (int k = 0; k < n; ++k) w += ln.B[k] * v[k];
  double F = 0.0, dF = 0.0;
  force(in, w, F, dF);
  if (out.want_damping)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) out.damping[i * n + j] += dF * ln.B[i] * ln.B[j];
  if (!operator_path && !quasi_static) return; // no velocity: no force
  if (!in.state.empty()) in.state[0] = F;
  // the assembler adds C v = dF w B: the kernel adds the rest of F B (nothing when linear)
  const double own = operator_path ? F - dF * w : F;
  for (int i = 0; i < n; ++i) out.residual[i] += own * ln.B[i];
  if (!out.want_tangent) return;
  if (quasi_static)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) out.tangent[i * n + j] += dF / ctx->dt * ln.B[i] * ln.B[j];
  if (nlgeom_line(in)) {
    std::array<double, 3> dv{};
    for (int i = 0; i < _ndim; ++i) dv[i] = v[_ndim + i] - v[i];
    add_turning(ln, dv, F, dF, out);
  }
}

bool DashpotKernel::supports_output(ElemVar var) const {
  return var == ElemVar::S || var == ElemVar::E;
}

void DashpotKernel::recover(const ElementInput& in, ElementRecovery& out) const {
  double du = 0.0;
  if (_type == ElementType::DASHPOTA)
    du = axial_kinematics(_ndim, in.X, in.u, nlgeom_line(in)).delta;
  else
    for (int k = 0; k < _act.n_dofs(); ++k) du += _act.B[k] * in.u[k];
  const std::span<const double> s =
      in.state.empty() ? in.state_start : std::span<const double>(in.state);
  add_block(out, ElemVar::S, kS11, 1).values[0] = s.empty() ? 0.0 : s[0];
  add_block(out, ElemVar::E, kE11, 1).values[0] = du;
}

} // namespace gapfem
