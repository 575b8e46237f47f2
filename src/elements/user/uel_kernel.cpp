#include "elements/user/uel_kernel.hpp"

#include "common/log.hpp"
#include "elements/user/user_code.hpp"
#include "model/model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>

namespace gapfem {
namespace {

/// What PNEWDT holds before a call (Abaqus: "a large value").
constexpr double kNoRequest = 1.0e36;

/// LFLAGS(1), the procedure type.
int procedure_code(const StepContext& ctx) {
  switch (ctx.procedure) {
  case Procedure::Static:
    return ctx.direct ? 2 : 1;
  case Procedure::HeatTransfer:
    return ctx.transient ? 32 : 31;
  case Procedure::CoupledTempDisp:
    return ctx.transient ? 72 : 71;
  case Procedure::SubstructureGenerate: // the stiffness of a linear step
    return 1;
  case Procedure::Dynamic: // implicit dynamics: automatic (11) or fixed (12) increments
    return ctx.direct ? 12 : 11;
  case Procedure::Frequency: // the mass call of an eigenfrequency extraction
    return 41;
  case Procedure::Buckle: // the stiffness about the base state and its change (static calls)
    return 1;
  case Procedure::ResponseSpectrum: // mode-based: combine modes, no element is called
  case Procedure::SteadyStateDynamics:
  case Procedure::ModalDynamic:
    return 1;
  }
  return 1;
}

/// The first entry of `v` that is not finite, or -1.
int first_non_finite(std::span<const double> v) {
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i])) return static_cast<int>(i);
  return -1;
}

/// The arrays one call of the user code reads and writes, in the layout both interfaces share.
struct UserCall {
  int ndofel, nnode, mcrd, nsvars;
  std::size_t n;  ///< ndofel
  double* svars;  ///< the trial SVARS (the element's trial state)
  double* energy; ///< the trial ENERGY, after SVARS
  std::vector<double> coords, du, rhs, amatrx, zeros;
  double pnewdt = kNoRequest;
  std::int64_t label;
};

UserCall prepare_call(const ElementInput& in, const NodeDofTable& dofs,
                      const UserElementType& type) {
  UserCall c;
  c.ndofel = dofs.n_dofs();
  c.nnode = dofs.n_nodes();
  c.mcrd = type.n_coords;
  c.nsvars = type.n_variables;
  c.n = static_cast<std::size_t>(c.ndofel);
  c.svars = in.state.data();
  c.energy = in.state.data() + c.nsvars;
  c.coords.assign(static_cast<std::size_t>(c.mcrd) * c.nnode, 0.0);
  c.du.assign(c.n, 0.0);
  c.rhs.assign(c.n, 0.0);
  c.amatrx.assign(c.n * c.n, 0.0);
  c.zeros.assign(c.n, 0.0);
  for (int a = 0; a < c.nnode; ++a)
    for (int i = 0; i < c.mcrd; ++i) c.coords[a * c.mcrd + i] = in.X[a][i];
  for (std::size_t i = 0; i < c.n; ++i) c.du[i] = in.u[i] - in.u_start[i];
  c.label = static_cast<std::int64_t>(in.label.local());
  return c;
}

/// A gapfem element plugin: its residual and (row-major) tangent go straight to the output.
void call_plugin(const UserCode& code, const UserElementType& type,
                 const std::vector<double>& props, const std::vector<int>& jprops,
                 const ElementInput& in, UserCall& uc, std::span<double> residual,
                 std::span<double> tangent) {
  const StepContext& ctx = *in.ctx;
  std::array<char, 512> message{};
  gapfem_element_call c{};
  c.abi_version = GAPFEM_PLUGIN_ABI_VERSION;
  c.type = type.number;
  c.element = uc.label;
  c.n_nodes = uc.nnode;
  c.n_coords = uc.mcrd;
  c.n_dofs = uc.ndofel;
  c.n_state = uc.nsvars;
  c.n_properties = type.n_properties;
  c.n_int_properties = type.n_int_properties;
  c.coords = uc.coords.data();
  c.u = in.u.data();
  c.du = uc.du.data();
  c.properties = props.data();
  c.int_properties = jprops.data();
  c.state_start = in.state_start.data();
  c.state = uc.svars;
  c.energy = uc.energy;
  c.step_time = ctx.step_time - ctx.dt;
  c.total_time = ctx.total_time - ctx.dt;
  c.dt = ctx.dt;
  c.period = ctx.step_period;
  c.step = ctx.step_number;
  c.increment = ctx.increment;
  c.procedure = procedure_code(ctx);
  c.nlgeom = ctx.nlgeom ? 1 : 0;
  c.residual = residual.data();
  c.tangent = uc.amatrx.data();
  c.pnewdt = &uc.pnewdt;
  c.message = message.data();
  c.message_size = static_cast<std::int32_t>(message.size());
  int status = 0;
  {
    const std::lock_guard lock(code.mutex());
    status = code.plugin()(&c);
  }
  if (status != 0) {
    message.back() = '\0';
    throw AnalysisError(fmt::format("element {} ({}): the element plugin ({}) failed: {}", in.label,
                                    type.name, code.source(),
                                    message[0] ? message.data() : "no message"));
  }
  // the plugin's tangent is row-major already
  if (!tangent.empty()) std::copy(uc.amatrx.begin(), uc.amatrx.end(), tangent.begin());
}

/// LFLAGS of a call: LFLAGS(3) = `what` (1 residual and Jacobian, 2 stiffness only, 3 damping
/// only, 4 mass only). In a dynamic step gapfem applies the inertia, the damping and the time
/// integrator itself (M and C from the LFLAGS(3) = 4 and 3 calls, which say LFLAGS(1) = 11 or 12):
/// the residual and stiffness calls are those of a static step, LFLAGS(1) = 1, so that a UEL
/// written for Abaqus/Standard, which adds its own inertia, damping and HHT operator when
/// LFLAGS(1) = 11 or 12 and LFLAGS(3) = 1, returns only its internal forces here
/// (docs/theory/dynamics.md, "Mass of each element type"). `operators`: the stiffness asked for
/// beside the damping (to compare them) is asked as the damping is, with LFLAGS(1) = 11 or 12.
std::array<int, 7> uel_flags(const StepContext& ctx, int what, bool operators = false) {
  int procedure = procedure_code(ctx);
  if (uses_mass(ctx.procedure) && what != 4 && what != 3 && !operators) procedure = 1;
  return {procedure, ctx.nlgeom ? 1 : 0, what, 0, 0, 0, 1};
}

/// An Abaqus UEL: RHS = external - internal (gapfem's residual is its negative), AMATRX
/// column-major (copied row-major to `tangent` when given).
void call_uel(const UserCode& code, const UserElementType& type, const std::vector<double>& props,
              const std::vector<int>& jprops, const ElementInput& in, UserCall& uc,
              std::array<int, 7> lflags, std::span<double> residual, std::span<double> tangent) {
  const StepContext& ctx = *in.ctx;
  int nrhs = 1, mlvarx = uc.ndofel, jtype = type.number, kstep = ctx.step_number,
      kinc = ctx.increment, jelem = static_cast<int>(uc.label), ndload = 0, mdload = 1, npredf = 1,
      nprops = type.n_properties, njprop = type.n_int_properties;
  std::array<int, 1> jdltyp{};
  std::array<double, 1> adlmag{}, ddlmag{};
  std::array<double, 3> params{};
  // TIME: step and total time at the start of the increment
  std::array<double, 2> time{ctx.step_time - ctx.dt, ctx.total_time - ctx.dt};
  double dtime = ctx.dt, period = ctx.step_period;
  // PREDEF(2, NPREDF, NNODE): the temperature at the end of the increment and its increment
  std::vector<double> predef(2 * static_cast<std::size_t>(uc.nnode), 0.0);
  if (!in.temperature.empty())
    for (int a = 0; a < uc.nnode; ++a) {
      predef[2 * a] = in.temperature[a];
      predef[2 * a + 1] =
          in.temperature[a] -
          (in.temperature_start.empty() ? in.temperature[a] : in.temperature_start[a]);
    }
  std::vector<double> u(in.u.begin(), in.u.end());
  // V and A: the trial rates in dynamic steps (where the assembler gathers them), zero otherwise
  const bool rates = ctx.procedure == Procedure::Dynamic;
  std::vector<double> v =
      in.v.empty() || !rates ? uc.zeros : std::vector<double>(in.v.begin(), in.v.end());
  std::vector<double> a =
      in.a.empty() || !rates ? uc.zeros : std::vector<double>(in.a.begin(), in.a.end());
  {
    const std::lock_guard lock(code.mutex());
    code.uel()(uc.rhs.data(), uc.amatrx.data(), uc.svars, uc.energy, &uc.ndofel, &nrhs, &uc.nsvars,
               const_cast<double*>(props.data()), &nprops, uc.coords.data(), &uc.mcrd, &uc.nnode,
               u.data(), uc.du.data(), v.data(), a.data(), &jtype, time.data(), &dtime, &kstep,
               &kinc, &jelem, params.data(), &ndload, jdltyp.data(), adlmag.data(), predef.data(),
               &npredf, lflags.data(), &mlvarx, ddlmag.data(), &mdload, &uc.pnewdt,
               const_cast<int*>(jprops.data()), &njprop, &period);
  }
  const std::size_t n = uc.n;
  for (std::size_t i = 0; i < n; ++i) residual[i] = -uc.rhs[i];
  if (!tangent.empty())
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) tangent[i * n + j] = uc.amatrx[i + j * n];
}

/// What the user code returned in `v` (named `what`) must be finite. A probe (a step-start
/// evaluation: a UEL may divide by DTIME) that fails contributes nothing: residual, tangent and
/// trial state are reset. In an increment it is an error.
void check_returned(const UserCode& code, const UserElementType& type, const ElementInput& in,
                    bool probe, const char* what, std::span<const double> v,
                    std::span<double> residual, std::span<double> tangent) {
  const int k = first_non_finite(v);
  if (k < 0) return;
  if (probe) {
    std::fill(residual.begin(), residual.end(), 0.0);
    std::fill(tangent.begin(), tangent.end(), 0.0);
    std::copy(in.state_start.begin(), in.state_start.end(), in.state.begin());
    return;
  }
  const StepContext& ctx = *in.ctx;
  throw AnalysisError(fmt::format(
      "element {} ({}): the user {} ({}) returned {}({}) = {} {}; a user element must return "
      "finite numbers: check it for an uninitialised variable or a division by zero",
      in.label, type.name, code.uel() ? "subroutine UEL" : "element plugin", code.source(), what,
      k + 1, v[static_cast<std::size_t>(k)],
      fmt::format("in step {}, increment {}", ctx.step_number, ctx.increment)));
}

} // namespace

UelKernel::UelKernel(const UserElementType& type, const UelProperty* properties,
                     std::shared_ptr<const UserCode> code, bool temperatures, bool dynamic)
    : _type(type), _dofs(type.node_dofs), _code(std::move(code)), _temperatures(temperatures),
      _mass(dynamic && _code && _code->uel() != nullptr) {
  if (properties) {
    _props = properties->properties;
    _jprops = properties->int_properties;
  }
  _props.resize(std::max<std::size_t>(_props.size(), 1), 0.0); // Fortran arrays of size >= 1
  _jprops.resize(std::max<std::size_t>(_jprops.size(), 1), 0);
}

double UelKernel::call(const ElementInput& in, std::span<double> residual,
                       std::span<double> tangent) const {
  const StepContext& ctx = *in.ctx;
  const bool probe = ctx.increment == 0; // a step-start evaluation, not an increment
  // every call of an attempt starts from the start of the increment
  std::copy(in.state_start.begin(), in.state_start.end(), in.state.begin());
  UserCall uc = prepare_call(in, _dofs, _type);
  const UserCode& code = *_code;
  if (code.plugin())
    call_plugin(code, _type, _props, _jprops, in, uc, residual, tangent);
  else // outside an increment (the step's stiffness probes, dt = 0) only the stiffness is asked for
    call_uel(code, _type, _props, _jprops, in, uc, uel_flags(ctx, probe ? 2 : 1), residual,
             tangent);
  check_returned(code, _type, in, probe, code.uel() ? "RHS" : "residual", residual, residual,
                 tangent);
  if (!tangent.empty())
    check_returned(code, _type, in, probe, code.uel() ? "AMATRX" : "tangent", tangent, residual,
                   tangent);
  check_returned(code, _type, in, probe, "SVARS",
                 std::span<const double>(uc.svars, static_cast<std::size_t>(uc.nsvars)), residual,
                 tangent);
  check_returned(code, _type, in, probe, "ENERGY", std::span<const double>(uc.energy, 8), residual,
                 tangent);
  if (probe) return kNoRequest;
  const double pnewdt = uc.pnewdt;
  if (std::isnan(pnewdt) || pnewdt <= 0.0)
    throw AnalysisError(fmt::format("element {} ({}): the user code ({}) set PNEWDT to {}; set it "
                                    "below 1 to ask for a smaller increment, above 1 for a larger "
                                    "one, or leave it",
                                    in.label, _type.name, code.source(), pnewdt));
  return pnewdt;
}

namespace {

/// Without UNSYMM Abaqus uses the symmetric part of AMATRX (n x n row-major).
void symmetrize(std::span<double> A, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const double m = 0.5 * (A[i * n + j] + A[j * n + i]);
      A[i * n + j] = A[j * n + i] = m;
    }
}

const char* operator_name(int what) {
  return what == 2 ? "stiffness" : what == 3 ? "damping" : "mass";
}

} // namespace

void UelKernel::operator_matrix(const ElementInput& in, int what, std::span<double> A) const {
  // a call of its own on copies of the trial SVARS and ENERGY: asking for an operator never
  // changes the element's history
  std::vector<double> state(in.state.begin(), in.state.end());
  ElementInput copy = in;
  copy.state = state;
  UserCall uc = prepare_call(copy, _dofs, _type);
  std::vector<double> rhs(uc.n, 0.0);
  call_uel(*_code, _type, _props, _jprops, copy, uc, uel_flags(*in.ctx, what, true), rhs, A);
  const int k = first_non_finite(A);
  if (k >= 0) {
    const int n = _dofs.n_dofs();
    throw AnalysisError(fmt::format(
        "element {} ({}): the user subroutine UEL ({}) returned AMATRX({},{}) = {} when asked "
        "for the {} matrix (LFLAGS(3) = {}) in step {}, increment {}; a user element must return "
        "finite numbers",
        in.label, _type.name, _code->source(), k / n + 1, k % n + 1, A[static_cast<std::size_t>(k)],
        operator_name(what), what, in.ctx->step_number, in.ctx->increment));
  }
}

double UelKernel::damping(const ElementInput& in, double known, std::span<double> C) const {
  const double step = in.ctx->step_number;
  if (known == step) return step; // found undamped at its first evaluation in this step
  operator_matrix(in, 3, C);
  const bool zero = std::all_of(C.begin(), C.end(), [](double c) { return c == 0.0; });
  if (zero) return step;
  if (known != -step) {
    // first look in this step: a UEL that does not read LFLAGS(3) = 3 returns what it returns for
    // the stiffness (bit for bit); it is undamped, not damped by C = K
    std::vector<double> K(C.size(), 0.0);
    operator_matrix(in, 2, K);
    if (std::equal(C.begin(), C.end(), K.begin())) {
      if (!_warned_stiffness_as_damping.exchange(true))
        log::warning("user element type {} (element {}): the UEL ({}) returns the same matrix for "
                     "LFLAGS(3) = 3 (the damping matrix) as for LFLAGS(3) = 2 (the stiffness): it "
                     "does not read LFLAGS(3) = 3, so gapfem takes its elements as undamped; give "
                     "it an LFLAGS(3) = 3 branch returning the damping matrix (zeros if none)",
                     _type.name, in.label, _code->source());
      std::fill(C.begin(), C.end(), 0.0);
      return step;
    }
  }
  if (!_type.unsymmetric) symmetrize(C, static_cast<std::size_t>(_dofs.n_dofs()));
  return -step;
}

void UelKernel::evaluate(const ElementInput& in, ElementOutput& out) const {
  // what is known of the damping in this step, kept across the evaluations of an attempt
  const std::size_t slot = damping_slot();
  const double known = in.state[slot];
  const double pnewdt =
      call(in, out.residual, out.want_tangent ? out.tangent : std::span<double>{});
  in.state[slot] = known;
  const auto n = static_cast<std::size_t>(_dofs.n_dofs());
  if (out.want_tangent && !_type.unsymmetric) symmetrize(out.tangent, n);
  if (out.want_mass) {
    operator_matrix(in, 4, out.mass);
    if (!_type.unsymmetric) symmetrize(out.mass, n);
  }
  if (out.want_damping && _mass && in.ctx->procedure == Procedure::Dynamic)
    in.state[slot] = damping(in, known, out.damping);
  out.unsymmetric = _type.unsymmetric;
  if (pnewdt < kNoRequest) out.dt_ratio = pnewdt;
  // the internal force, for output at the converged state (NFORC) without another call
  std::copy(out.residual.begin(), out.residual.end(),
            in.state.begin() + _type.n_variables + kEnergies);
}

void UelKernel::recover(const ElementInput& in, ElementRecovery& out) const {
  const auto f = in.state_start.subspan(static_cast<std::size_t>(_type.n_variables) + kEnergies,
                                        static_cast<std::size_t>(_dofs.n_dofs()));
  add_nodal_forces(_dofs, f, out);
  out.strain_energy = in.state_start[static_cast<std::size_t>(_type.n_variables) + 1];
}

std::unique_ptr<ElementKernel> make_uel_kernel(const Model& model, const UserElementType& type,
                                               const UelProperty* properties) {
  if (!model.user_code || (!model.user_code->uel() && !model.user_code->plugin()))
    throw InputError(type.loc, fmt::format("TYPE={}", type.name),
                     fmt::format("{} is a user element computed by a user subroutine (it is not "
                                 "LINEAR), but no user code was given; run gapfem --user uel.f "
                                 "deck.inp (a UEL in Fortran or C, a gapfem element plugin in "
                                 "C++, or a compiled .so)",
                                 type.name));
  bool temperatures = model.has_initial_temperature, dynamic = false;
  for (const Step& s : model.steps) {
    temperatures |= !s.temperatures.empty();
    dynamic |= uses_mass(s.procedure);
  }
  return std::make_unique<UelKernel>(type, properties, model.user_code, temperatures, dynamic);
}

} // namespace gapfem
