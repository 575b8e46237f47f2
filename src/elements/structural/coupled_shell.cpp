// The coupled temperature-displacement shells S3RT, S4T, S4RT and S8RT: the stress/displacement
// shell of the same shape (S3R, S4, S4R, S8R) with the heat-transfer shell (DS3, DS4, DS8) on the
// same nodes (coupled_shell.hpp).
#include "elements/structural/coupled_shell.hpp"

#include "elements/heat/heat_kernel.hpp"
#include "elements/heat/heat_shell.hpp"
#include "elements/structural/shell.hpp"
#include "elements/structural/shell_section.hpp"
#include "model/model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <vector>

namespace gapfem {

namespace {

constexpr int kMaxNodes = 8;
constexpr int kMaxPerNode = 6 + kMaxTemperaturePoints;

constexpr std::array<DofType, kMaxPerNode> kDofs = [] {
  std::array<DofType, kMaxPerNode> d{};
  for (int i = 0; i < 6; ++i) d[i] = static_cast<DofType>(i);
  for (int k = 0; k < kMaxTemperaturePoints; ++k) d[6 + k] = temperature_dof(k);
  return d;
}();

/// Scratch of one call (the kernels are shared between threads, so it lives on the stack).
struct Split {
  std::vector<double> um, um0, rm, Km, uh, uh0, rh, Kh, gradient;
  std::vector<double> op; ///< a part's mass or damping block (operators on request)
  std::array<double, kMaxNodes> T{}, T0{}, grad{}, Ti{};
};

class CoupledShellKernel final : public ElementKernel {
 public:
  CoupledShellKernel(ElementType type, std::unique_ptr<ElementKernel> mech,
                     std::unique_ptr<ElementKernel> heat, int n_points,
                     std::vector<double> thickness, std::vector<double> initial)
      : _type(type), _mech(std::move(mech)), _heat(std::move(heat)), _P(n_points),
        _nn(element_info(type).n_nodes), _thickness(std::move(thickness)),
        _initial(std::move(initial)) {
    _w.fill(0.0);
    _zeta.fill(0.0);
    if (_P == 1) {
      _w[0] = 1.0;
    } else {
      const int layers = (_P - 1) / 2;
      const double s[3] = {1.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0};
      for (int j = 0; j < layers; ++j)
        for (int i = 0; i < 3; ++i) _w[2 * j + i] += s[i] / layers;
      for (int k = 0; k < _P; ++k) _zeta[k] = -0.5 + static_cast<double>(k) / (_P - 1);
    }
  }

  ElementType type() const override { return _type; }
  std::span<const DofType> node_dofs(int) const override {
    return {kDofs.data(), static_cast<std::size_t>(6 + _P)};
  }
  int n_state() const override { return _mech->n_state(); }

  std::string validate(const ElementInput& in) const override {
    Split sp;
    ElementInput mi = mech_input(in, sp), hi = heat_input(in, sp);
    std::string msg = _mech->validate(mi);
    return msg.empty() ? _heat->validate(hi) : msg;
  }
  void initialize(const ElementInput& in) const override {
    Split sp;
    _mech->initialize(mech_input(in, sp));
  }

  void evaluate(const ElementInput& in, ElementOutput& out) const override {
    Split sp;
    const int nm = 6 * _nn, nh = _P * _nn, n = nm + nh;
    const bool want_K = out.want_tangent && static_cast<int>(out.tangent.size()) == n * n;
    ElementInput mi = mech_input(in, sp);
    mech_residual(mi, sp, want_K);
    for (int a = 0; a < _nn; ++a)
      for (int i = 0; i < 6; ++i) out.residual[mdof(a, i)] += sp.rm[6 * a + i];
    if (want_K) {
      for (int p = 0; p < nm; ++p)
        for (int q = 0; q < nm; ++q) out.tangent[mrow(p) * n + mrow(q)] += sp.Km[p * nm + q];
      add_coupling(in, mi, sp, out.tangent);
    }
    ElementInput hi = heat_input(in, sp);
    sp.rh.assign(static_cast<std::size_t>(nh), 0.0);
    sp.Kh.assign(want_K ? static_cast<std::size_t>(nh * nh) : 0u, 0.0);
    ElementOutput ho;
    ho.residual = sp.rh;
    ho.tangent = sp.Kh;
    ho.want_tangent = want_K;
    _heat->evaluate(hi, ho);
    for (int p = 0; p < nh; ++p) {
      out.residual[hrow(p)] += sp.rh[p];
      if (want_K)
        for (int q = 0; q < nh; ++q) out.tangent[hrow(p) * n + hrow(q)] += sp.Kh[p * nh + q];
    }
    out.unsymmetric = true; // d r_u / d T without d r_T / d u
    if (out.want_mass || out.want_damping) add_operators(in, sp, out);
  }

  /// The shell's mass on the displacements and rotations, the DS element's heat capacity (the
  /// damping operator, which it integrates itself) on the temperatures.
  bool has_mass() const override { return _mech->has_mass(); }
  bool has_damping() const override { return _heat->has_damping(); }
  bool damping_in_residual() const override { return true; }

  double stored_heat(const ElementInput& in) const override {
    Split sp;
    return _heat->stored_heat(heat_input(in, sp));
  }

  bool supports_load(DistLoadKind kind, int face) const override {
    return thermal(kind) ? _heat->supports_load(kind, face) : _mech->supports_load(kind, face);
  }
  void load(const ElementInput& in, const DistributedLoad& ld, double magnitude, double sink,
            std::span<double> f, std::span<double> K) const override {
    Split sp;
    const bool heat = thermal(ld.kind);
    const int n = (6 + _P) * _nn, nl = heat ? _P * _nn : 6 * _nn;
    const bool want_K = static_cast<int>(K.size()) == n * n;
    std::vector<double> fl(static_cast<std::size_t>(nl), 0.0),
        Kl(want_K ? static_cast<std::size_t>(nl * nl) : 0u, 0.0);
    if (heat)
      _heat->load(heat_input(in, sp), ld, magnitude, sink, fl, Kl);
    else
      _mech->load(mech_input(in, sp), ld, magnitude, sink, fl, Kl);
    auto row = [&](int p) { return heat ? hrow(p) : mrow(p); };
    for (int p = 0; p < nl; ++p) {
      f[row(p)] += fl[p];
      if (want_K)
        for (int q = 0; q < nl; ++q) K[row(p) * n + row(q)] += Kl[p * nl + q];
    }
  }

  bool supports_output(ElemVar var) const override {
    return _mech->supports_output(var) || _heat->supports_output(var);
  }
  void recover(const ElementInput& in, ElementRecovery& out) const override {
    Split sp;
    _mech->recover(mech_input(in, sp), out);
    _heat->recover(heat_input(in, sp), out);
  }

 private:
  static bool thermal(DistLoadKind k) {
    return k == DistLoadKind::BodyFlux || k == DistLoadKind::SurfaceFlux ||
           k == DistLoadKind::Film || k == DistLoadKind::Radiation;
  }
  int per() const { return 6 + _P; }
  int mdof(int a, int i) const { return a * per() + i; }
  int mrow(int p) const { return mdof(p / 6, p % 6); }            ///< mechanical local p
  int hrow(int p) const { return (p / _P) * per() + 6 + p % _P; } ///< heat local p
  std::span<const double> thickness(const ElementInput& in) const {
    return {_thickness.data() + static_cast<std::size_t>(in.block_index) * _nn,
            static_cast<std::size_t>(_nn)};
  }

  /// The mechanical shell's input: its DOFs, and the temperature field it reads (per node the
  /// mean through the thickness and the gradient dT/dn of the least-squares line through the
  /// section points, both with Simpson's weights, so that the membrane and bending thermal
  /// strains integrate the section points' temperatures as Simpson's rule does).
  ElementInput mech_input(const ElementInput& in, Split& sp) const {
    const auto t = thickness(in);
    sp.um.assign(static_cast<std::size_t>(6 * _nn), 0.0);
    sp.um0 = sp.um;
    for (int a = 0; a < _nn; ++a) {
      double T = 0.0, T0 = 0.0, g = 0.0;
      for (int k = 0; k < _P; ++k) {
        const double v = in.u[mdof(a, 6 + k)];
        const double v0 = in.u_start.empty() ? v : in.u_start[mdof(a, 6 + k)];
        T += _w[k] * v;
        T0 += _w[k] * v0;
        g += 12.0 * _w[k] * _zeta[k] * v / t[a];
      }
      sp.T[a] = T;
      sp.T0[a] = T0;
      sp.grad[a] = g;
      sp.Ti[a] =
          _initial.empty() ? 0.0 : _initial[static_cast<std::size_t>(in.block_index) * _nn + a];
      for (int i = 0; i < 6; ++i) {
        sp.um[6 * a + i] = in.u[mdof(a, i)];
        sp.um0[6 * a + i] = in.u_start.empty() ? in.u[mdof(a, i)] : in.u_start[mdof(a, i)];
      }
    }
    sp.gradient.assign(static_cast<std::size_t>(2 * _nn), 0.0);
    for (int a = 0; a < _nn; ++a) sp.gradient[2 * a] = sp.grad[a];
    ElementInput mi = in;
    mi.u = sp.um;
    mi.u_start = sp.um0;
    mi.temperature = std::span<const double>(sp.T.data(), _nn);
    mi.temperature_start = std::span<const double>(sp.T0.data(), _nn);
    mi.temperature_gradient = sp.gradient;
    mi.initial_temperature = std::span<const double>(sp.Ti.data(), _nn);
    mi.free = {};
    mi.v = mi.a = mi.v_start = mi.a_start = {}; // the element's rates, not the part's
    return mi;
  }

  ElementInput heat_input(const ElementInput& in, Split& sp) const {
    sp.uh.assign(static_cast<std::size_t>(_P * _nn), 0.0);
    sp.uh0 = sp.uh;
    for (int a = 0; a < _nn; ++a)
      for (int k = 0; k < _P; ++k) {
        sp.uh[a * _P + k] = in.u[mdof(a, 6 + k)];
        sp.uh0[a * _P + k] = in.u_start.empty() ? in.u[mdof(a, 6 + k)] : in.u_start[mdof(a, 6 + k)];
      }
    ElementInput hi = in;
    hi.u = sp.uh;
    hi.u_start = sp.uh0;
    hi.state = {};
    hi.state_start = {};
    hi.free = {};
    hi.v = hi.a = hi.v_start = hi.a_start = {}; // the element's rates, not the part's
    return hi;
  }

  /// The parts' operator blocks (each evaluated once more, asking only for its block).
  void add_operators(const ElementInput& in, Split& sp, ElementOutput& out) const {
    const int nm = 6 * _nn, nh = _P * _nn, n = nm + nh;
    std::vector<double> r;
    if (out.want_mass && _mech->has_mass()) {
      ElementInput mi = mech_input(in, sp);
      const std::vector<double> keep(mi.state.begin(), mi.state.end());
      r.assign(static_cast<std::size_t>(nm), 0.0);
      sp.op.assign(static_cast<std::size_t>(nm * nm), 0.0);
      ElementOutput mo;
      mo.residual = r;
      mo.want_tangent = false;
      mo.mass = sp.op;
      mo.want_mass = true;
      _mech->evaluate(mi, mo);
      std::copy(keep.begin(), keep.end(), mi.state.begin());
      for (int p = 0; p < nm; ++p)
        for (int q = 0; q < nm; ++q) out.mass[mrow(p) * n + mrow(q)] += sp.op[p * nm + q];
    }
    if (out.want_damping && _heat->has_damping()) {
      ElementInput hi = heat_input(in, sp);
      r.assign(static_cast<std::size_t>(nh), 0.0);
      sp.op.assign(static_cast<std::size_t>(nh * nh), 0.0);
      ElementOutput ho;
      ho.residual = r;
      ho.want_tangent = false;
      ho.damping = sp.op;
      ho.want_damping = true;
      _heat->evaluate(hi, ho);
      for (int p = 0; p < nh; ++p)
        for (int q = 0; q < nh; ++q) out.damping[hrow(p) * n + hrow(q)] += sp.op[p * nh + q];
    }
  }

  void mech_residual(const ElementInput& mi, Split& sp, bool want_K) const {
    const int nm = 6 * _nn;
    sp.rm.assign(static_cast<std::size_t>(nm), 0.0);
    sp.Km.assign(want_K ? static_cast<std::size_t>(nm * nm) : 0u, 0.0);
    ElementOutput mo;
    mo.residual = sp.rm;
    mo.tangent = sp.Km;
    mo.want_tangent = want_K;
    _mech->evaluate(mi, mo);
  }

  /// K_uT = d r_u / d T_bk. The shell section reads the element's mean temperature and mean
  /// gradient (shell_section.hpp, section_law), so r_u depends on the temperatures through these
  /// two numbers: their derivatives by central differences (r_u is linear in the gradient and
  /// smooth in the mean), times d mean / d T_bk = w_k / n and d gradient / d T_bk = 12 w_k zeta_k
  /// / (t_b n).
  void add_coupling(const ElementInput& in, const ElementInput& mi, Split& sp,
                    std::span<double> K) const {
    const int nm = 6 * _nn, n = (6 + _P) * _nn;
    double Tm = 0.0, gm = 0.0;
    for (int a = 0; a < _nn; ++a) {
      Tm += sp.T[a] / _nn;
      gm += sp.grad[a] / _nn;
    }
    const double hT = 1e-4 * (1.0 + std::abs(Tm)), hg = 1e-4 * (1.0 + std::abs(gm));
    std::vector<double> dT(static_cast<std::size_t>(nm)), dg(static_cast<std::size_t>(nm));
    const std::vector<double> keep_state(mi.state.begin(), mi.state.end());
    auto shifted = [&](double sT, double sg, std::vector<double>& r) {
      Split s2;
      ElementInput m2 = mech_input(in, s2);
      for (int a = 0; a < _nn; ++a) {
        s2.T[a] += sT;
        s2.gradient[2 * a] += sg;
      }
      mech_residual(m2, s2, false);
      r = s2.rm;
    };
    std::vector<double> rp, rm;
    shifted(hT, 0.0, rp);
    shifted(-hT, 0.0, rm);
    for (int p = 0; p < nm; ++p) dT[p] = (rp[p] - rm[p]) / (2.0 * hT);
    shifted(0.0, hg, rp);
    shifted(0.0, -hg, rm);
    for (int p = 0; p < nm; ++p) dg[p] = (rp[p] - rm[p]) / (2.0 * hg);
    // the shifted evaluations wrote the mechanical kernel's trial history: restore it
    std::copy(keep_state.begin(), keep_state.end(), mi.state.begin());
    const auto t = thickness(in);
    for (int p = 0; p < nm; ++p)
      for (int b = 0; b < _nn; ++b)
        for (int k = 0; k < _P; ++k)
          K[mrow(p) * n + mdof(b, 6 + k)] +=
              dT[p] * _w[k] / _nn + dg[p] * 12.0 * _w[k] * _zeta[k] / (t[b] * _nn);
  }

  ElementType _type;
  std::unique_ptr<ElementKernel> _mech, _heat;
  int _P = 3;
  int _nn = 4;
  std::vector<double> _thickness; ///< per element of the block, per node
  std::vector<double> _initial;   ///< initial temperatures, per element and node (empty: zero)
  std::array<double, kMaxTemperaturePoints> _w{}, _zeta{};
};

} // namespace

std::unique_ptr<ElementKernel> make_coupled_shell_kernel(const KernelContext& ctx) {
  using T = ElementType;
  T mech = T::S4R, heat = T::DS4;
  switch (ctx.type) {
  case T::S3RT:
    mech = T::S3R, heat = T::DS3;
    break;
  case T::S4T:
    mech = T::S4, heat = T::DS4;
    break;
  case T::S4RT:
    break;
  case T::S8RT:
    mech = T::S8R, heat = T::DS8;
    break;
  default:
    throw InternalError("make_coupled_shell_kernel: not a coupled shell type");
  }
  const Model& model = ctx.model;
  const ShellSection& sec = shell::shell_section_of(ctx);
  if (sec.material >= 0 && sec.material < static_cast<int>(model.materials.size()))
    heat_material_for(ctx, model.materials[sec.material]); // names the coupled type in errors
  auto m = make_shell_kernel(KernelContext{model, mech, ctx.property, ctx.elements});
  auto h = make_heat_shell_kernel(KernelContext{model, heat, ctx.property, ctx.elements});
  std::vector<double> thickness = shell::block_thicknesses(ctx, sec), initial;
  bool any_initial = false;
  for (ElemId e : ctx.elements)
    for (NodeId node : model.mesh.element_nodes(e)) {
      const double ti = node < static_cast<NodeId>(model.initial_temperature.size())
                            ? model.initial_temperature[node]
                            : 0.0;
      any_initial |= ti != 0.0;
      initial.push_back(ti);
    }
  if (!any_initial) initial.clear();
  return std::make_unique<CoupledShellKernel>(ctx.type, std::move(m), std::move(h), sec.n_points,
                                              std::move(thickness), std::move(initial));
}

} // namespace gapfem
