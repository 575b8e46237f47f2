#pragma once
/// @file coupled_continuum.hpp
/// The coupled temperature-displacement continuum elements CPS4T, CPE4T, CAX4T, C3D4T and C3D8T:
/// node DOFs U1, U2 (, U3), NT. The mechanics is the stress/displacement kernel of the same shape
/// (ContinuumKernel: B-bar, NLGEOM, loads, S and E output) with the thermal strain taken from the
/// NT DOFs; heat conduction, capacity and thermal loads are HeatCore's (heat_core.hpp).
///
/// Tangent blocks (local DOFs node-major):
///   K_uu  mechanical stiffness                    K_uT  d r_u / d T: thermal strain and
///                                                       temperature-dependent elasticity
///   K_Tu  0 (conduction on the reference geometry) K_TT  conduction + capacity
/// K_uT makes the tangent unsymmetric (ElementOutput::unsymmetric). The heat equation has no
/// mechanical source (no thermoelastic or plastic heating), as in Abaqus's elastic coupled
/// elements. Theory: docs/theory/thermal.md.
/// Operators: the mass is the mechanical kernel's consistent mass on the displacement DOFs (none
/// on NT); the damping operator is the heat capacity on NT, whose flux HeatCore integrates itself
/// (damping_in_residual), as in the heat kernels.
#include "elements/heat/heat_core.hpp"
#include "elements/solid/continuum_kernel.hpp"

#include <memory>
#include <vector>

namespace gapfem {

namespace coupled_detail {
inline constexpr std::array<DofType, 4> kDofs3T{DofType::U1, DofType::U2, DofType::U3, DofType::NT};
inline constexpr std::array<DofType, 3> kDofs2T{DofType::U1, DofType::U2, DofType::NT};
} // namespace coupled_detail

/// Per-element initial temperatures of a block (the thermal-strain reference), indexed by the
/// element's position in its block; empty when every initial temperature is zero.
struct InitialTemperatures {
  int n_nodes = 0;
  std::vector<double> values; ///< block size x n_nodes
  /// Nodal initial temperatures of element `i` of the block (zeros when none were given).
  std::span<const double> of(LocalIndex i, std::span<double> zeros) const {
    if (values.empty()) return zeros;
    return {values.data() + static_cast<std::size_t>(i) * n_nodes,
            static_cast<std::size_t>(n_nodes)};
  }
};

/// Mech: the stress/displacement kernel of the shape (ContinuumKernel, ReducedKernel), with
/// kShape, kKin, a constructor from ContinuumSetup and temperature_tangent().
template <class Mech, HeatGeometry G>
class CoupledContinuumKernel final : public ElementKernel {
 public:
  using Heat = HeatCore<Mech::kShape, G>;
  static constexpr int NN = Heat::NN;
  static constexpr int ND = Mech::kKin == Kinematics::ThreeD ? 3 : 2;
  static constexpr int NPN = ND + 1; ///< DOFs per node
  static constexpr int NDOF = NN * NPN;
  static constexpr int NDM = NN * ND; ///< mechanical DOFs

  CoupledContinuumKernel(ElementType type, ContinuumSetup setup, HeatMaterial heat,
                         double thickness, InitialTemperatures initial)
      : _type(type), _mech(std::move(setup)), _heat(std::move(heat), thickness),
        _initial(std::move(initial)) {}

  ElementType type() const override { return _type; }
  std::span<const DofType> node_dofs(int) const override {
    if constexpr (ND == 3)
      return coupled_detail::kDofs3T;
    else
      return coupled_detail::kDofs2T;
  }

  bool has_artificial_energy() const override { return _mech.has_artificial_energy(); }
  bool has_mass() const override { return _mech.has_mass(); }
  bool has_damping() const override { return _heat.material().has_capacity(); }
  bool damping_in_residual() const override { return true; }
  /// The history is the mechanical kernel's (its solid law's, point by point).
  int n_state() const override { return _mech.n_state(); }
  void initialize(const ElementInput& in) const override {
    Local l;
    split(in, l);
    _mech.initialize(l.in);
  }

  std::string validate(const ElementInput& in) const override {
    Local l;
    split(in, l);
    std::string msg = _mech.validate(l.in);
    return msg.empty() ? _heat.validate(in.X) : msg;
  }

  void evaluate(const ElementInput& in, ElementOutput& out) const override {
    Local l;
    split(in, l);
    const bool want_K = out.want_tangent && out.tangent.size() == NDOF * NDOF;
    std::array<double, NDM> rm{};
    std::array<double, NDM * NDM> Km{};
    ElementOutput mo;
    mo.residual = rm;
    mo.tangent = want_K ? std::span<double>(Km) : std::span<double>{};
    mo.want_tangent = want_K;
    const bool want_M = out.want_mass && out.mass.size() == NDOF * NDOF;
    std::array<double, NDM * NDM> Mm; // zeroed only when the mass is asked for
    if (want_M) {
      Mm.fill(0.0);
      mo.mass = Mm;
      mo.want_mass = true;
    }
    _mech.evaluate(l.in, mo);
    for (int i = 0; i < NDM; ++i) out.residual[slot(i)] += rm[i];
    if (want_M)
      for (int i = 0; i < NDM; ++i)
        for (int j = 0; j < NDM; ++j) out.mass[slot(i) * NDOF + slot(j)] += Mm[i * NDM + j];
    if (out.want_damping && out.damping.size() == NDOF * NDOF)
      _heat.add_capacity_block(in.X, l.T, layout(), out.damping);
    if (want_K) {
      for (int i = 0; i < NDM; ++i)
        for (int j = 0; j < NDM; ++j) out.tangent[slot(i) * NDOF + slot(j)] += Km[i * NDM + j];
      std::array<double, NDM * NN> dT{};
      _mech.temperature_tangent(l.in, dT);
      bool coupled = false;
      for (int i = 0; i < NDM; ++i)
        for (int b = 0; b < NN; ++b) {
          const double v = dT[i * NN + b];
          out.tangent[slot(i) * NDOF + b * NPN + ND] += v;
          coupled |= v != 0.0;
        }
      out.unsymmetric |= coupled || mo.unsymmetric;
    }
    out.unsymmetric |= _heat.add_internal(in.X, l.T, l.T0, in.ctx, layout(), out.residual,
                                          want_K ? out.tangent : std::span<double>{});
  }

  double stored_heat(const ElementInput& in) const override {
    Local l;
    split(in, l);
    return _heat.stored_heat(in.X, l.T, l.T0);
  }

  bool supports_load(DistLoadKind kind, int face) const override {
    return _heat.supports_load(kind, face) || _mech.supports_load(kind, face);
  }

  void load(const ElementInput& in, const DistributedLoad& ld, double magnitude, double sink,
            std::span<double> f_ext, std::span<double> tangent) const override {
    Local l;
    split(in, l);
    const bool with_K = tangent.size() == NDOF * NDOF;
    if (_heat.supports_load(ld.kind, ld.face)) {
      _heat.add_load(in.X, l.T, ld, magnitude, sink, layout(), f_ext,
                     with_K ? tangent : std::span<double>{});
      return;
    }
    std::array<double, NDM> fm{};
    std::array<double, NDM * NDM> Km{};
    _mech.load(l.in, ld, magnitude, sink, fm, with_K ? std::span<double>(Km) : std::span<double>{});
    for (int i = 0; i < NDM; ++i) f_ext[slot(i)] += fm[i];
    if (with_K)
      for (int i = 0; i < NDM; ++i)
        for (int j = 0; j < NDM; ++j) tangent[slot(i) * NDOF + slot(j)] += Km[i * NDM + j];
  }

  bool supports_output(ElemVar var) const override {
    return var == ElemVar::HFL || _mech.supports_output(var);
  }
  void recover(const ElementInput& in, ElementRecovery& out) const override {
    Local l;
    split(in, l);
    _mech.recover(l.in, out);
    OutputBlock b;
    b.var = ElemVar::HFL;
    b.names = Heat::flux_names();
    b.n_points = Heat::NQ;
    b.values.resize(static_cast<std::size_t>(Heat::NQ * Heat::D));
    _heat.heat_flux(in.X, l.T, b.values);
    out.blocks.push_back(std::move(b));
  }

 private:
  /// The mechanical view of the element's local data.
  struct Local {
    ElementInput in;
    std::array<double, NDM> u{}, u0{};
    typename Heat::Temps T{}, T0{};
    std::array<double, NN> zeros{};
  };
  /// Local position of mechanical DOF i (node-major, ND per node).
  static constexpr int slot(int i) { return (i / ND) * NPN + i % ND; }
  static HeatLayout layout() { return {NPN, ND, NDOF}; }

  void split(const ElementInput& in, Local& l) const {
    for (int a = 0; a < NN; ++a) {
      for (int i = 0; i < ND; ++i) {
        l.u[a * ND + i] = in.u[a * NPN + i];
        l.u0[a * ND + i] = in.u_start.empty() ? l.u[a * ND + i] : in.u_start[a * NPN + i];
      }
      l.T[a] = in.u[a * NPN + ND];
      l.T0[a] = in.u_start.empty() ? l.T[a] : in.u_start[a * NPN + ND];
    }
    l.in = in;
    l.in.u = l.u;
    l.in.u_start = l.u0;
    l.in.temperature = l.T;
    l.in.temperature_start = l.T0;
    l.in.initial_temperature = _initial.of(in.block_index, l.zeros);
  }

  ElementType _type;
  Mech _mech;
  Heat _heat;
  InitialTemperatures _initial;
};

struct KernelContext;

/// CPS4T, CPE4T, CAX4T, C3D4T, C3D8T kernels (coupled_continuum.cpp); `setup` as checked by
/// make_continuum_kernel.
std::unique_ptr<ElementKernel>
make_coupled_continuum_kernel(const KernelContext& ctx, ContinuumSetup setup, double thickness);
/// The initial temperatures of a block's elements (model/initial conditions).
InitialTemperatures block_initial_temperatures(const KernelContext& ctx);

} // namespace gapfem
