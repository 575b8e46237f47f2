#include "elements/structural/beam.hpp"

#include "common/jet.hpp"
#include "elements/structural/beam_fibres.hpp"
#include "elements/structural/beam_kinematics.hpp"
#include "elements/structural/beam_loads.hpp"
#include "elements/structural/beam_mass.hpp"
#include "elements/structural/structural_common.hpp"
#include "elements/structural/structural_factory.hpp"
#include "model/model.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace gapfem {

using namespace structural;

namespace beam {

namespace {

constexpr std::array<DofType, 6> kSpaceDofs{DofType::U1,  DofType::U2,  DofType::U3,
                                            DofType::UR1, DofType::UR2, DofType::UR3};
constexpr std::array<DofType, 3> kPlaneDofs{DofType::U1, DofType::U2, DofType::UR3};

/// Section stiffness (6 x 6, strain order of beam_kinematics.hpp) and initial (thermal) strains
/// of an element at its temperature.
struct SectionLaw {
  std::array<double, 36> D{};
  std::array<double, 6> initial{};
  double E = 0.0, G = 0.0, nu = 0.0;
};

/// The transverse shear block (strains 1, 2) of the section stiffness Dm: k G A (or *TRANSVERSE
/// SHEAR STIFFNESS) with the slenderness compensation of two-node elements (beam.hpp). Both
/// paths use it: the fibres of an integrated section carry no transverse shear (Abaqus treats it
/// as elastic), which then takes E and G from the law's elastic moduli.
void transverse_shear(const BeamData& b, double E, double G, double L, int n_nodes,
                      std::array<double, 36>& Dm) {
  const BeamSectionProperties& p = b.section;
  auto D = [&](int i, int j, double v) { Dm[6 * i + j] = Dm[6 * j + i] = v; };
  const double K2 = p.k23 > 0.0 ? p.k23 : p.k * G * p.A;
  const double K1 = p.k13 > 0.0 ? p.k13 : p.k * G * p.A;
  if (b.slenderness >= 0.0 || n_nodes != 2) {
    // Abaqus's f_p = 1 / (1 + xi SCF L^2 A / (12 I)), xi = 1 (two nodes) or 1e-4 (three); a
    // planar beam has no out-of-plane bending (I22 = 0): K1 is then unused
    auto fp = [&](double K, double I) {
      if (b.slenderness < 0.0 || !(I > 0.0)) return K;
      const double xi = n_nodes == 2 ? 1.0 : 1e-4;
      return K / (1.0 + xi * b.slenderness * L * L * p.A / (12.0 * I));
    };
    D(1, 1, fp(K2, p.I11_centroid()));
    D(2, 2, fp(K1, p.I22_centroid()));
  } else {
    // exact prismatic two-node element: shear compliance plus the residual bending compliance
    // L^2/12 of the centroidal bending compliance, coupled through I12 (docs/theory §3.2):
    // F = diag(1/K2, 1/K1) + L^2 / (12 E det) [[I22, -I12], [-I12, I11]]
    const double I11 = p.I11_centroid(), I22 = p.I22_centroid(), I12 = p.I12_centroid();
    const double det = I11 * I22 - I12 * I12;
    double F22 = 1.0 / K2, F11 = 1.0 / K1, F21 = 0.0;
    if (I22 > 0.0 && det > 0.0) {
      const double c = L * L / (12.0 * E * det);
      F22 += c * I22, F11 += c * I11, F21 = -c * I12;
    } else if (I11 > 0.0) { // planar: bending about n1 only
      F22 += L * L / (12.0 * E * I11);
    }
    const double dF = F22 * F11 - F21 * F21;
    D(1, 1, F11 / dF);
    D(2, 2, F22 / dF);
    D(1, 2, -F21 / dF);
  }
}

SectionLaw section_law(const BeamData& b, const ElementInput& in, double L, int n_nodes) {
  SectionLaw s;
  double nu = 0.0;
  elastic_at(b.material, average(in.temperature), s.E, nu);
  s.G = s.E / (2.0 * (1.0 + nu));
  s.nu = nu;
  const BeamSectionProperties& p = b.section;
  const double E = s.E, G = s.G;
  auto D = [&](int i, int j, double v) { s.D[6 * i + j] = s.D[6 * j + i] = v; };
  // axial and bending about the section origin: fibre strain eps + kappa1 x2 - kappa2 x1
  D(0, 0, E * p.A);
  D(0, 3, E * p.Q2);
  D(0, 4, -E * p.Q1);
  D(3, 3, E * p.I11);
  D(3, 4, -E * p.I12);
  D(4, 4, E * p.I22);
  D(5, 5, G * p.J);
  // transverse shear, with the slenderness compensation of two-node elements (beam.hpp)
  transverse_shear(b, E, G, L, n_nodes, s.D);
  s.initial[0] = element_thermal_strain(b.material, in);
  if (!in.temperature_gradient.empty() && !b.material.expansion.empty()) {
    // T(x1, x2) = T + x2 dT/dx2 + x1 dT/dx1 over the section (values 2, 3 of *TEMPERATURE): the
    // fibre strain eps + kappa1 x2 - kappa2 x1 takes the thermal curvatures alpha dT/dx2 and
    // -alpha dT/dx1 (alpha the thermal strain's slope at the element's temperature)
    double g2 = 0.0, g1 = 0.0;
    const std::size_t nn = in.temperature_gradient.size() / 2;
    for (std::size_t a = 0; a < nn; ++a) {
      g2 += in.temperature_gradient[2 * a] / nn;
      g1 += in.temperature_gradient[2 * a + 1] / nn;
    }
    const double alpha = b.material.thermal_strain_derivative(*average(in.temperature));
    s.initial[3] = alpha * g2;
    s.initial[4] = -alpha * g1;
  }
  return s;
}

template <class T>
T unknown(double v, int i) {
  if constexpr (std::is_same_v<T, double>)
    return v;
  else
    return T::variable(v, i);
}

/// Energy density 1/2 (e - e0)^T D (e - e0) of one point.
template <class T>
T point_energy(Strains<T> e, const SectionLaw& s) {
  for (int i = 0; i < 6; ++i) e[i] -= s.initial[i];
  T w(0.0);
  for (int i = 0; i < 6; ++i) {
    T si(0.0);
    bool any = false;
    for (int j = 0; j < 6; ++j)
      if (const double d = s.D[6 * i + j]; d != 0.0) {
        si += d * e[j];
        any = true;
      }
    if (any) w += e[i] * si;
  }
  return 0.5 * w;
}

/// What an integrated section (BeamData::law) evaluates with at one element: the fibres' law
/// and temperatures, and the elastic transverse shear block (with E, G, nu at the element's
/// temperature from the law's elastic moduli).
struct FibreLaw {
  FibreSection section;
  std::array<double, 36> shear{};
  double E = 0.0, G = 0.0, nu = 0.0;
};

/// Adds the elastic transverse shear (strains 1, 2; no initial strain) to a point's response.
void add_shear(const std::array<double, 36>& K, const Strains<double>& e, SectionResponse& s) {
  for (int i = 1; i < 3; ++i)
    for (int j = 1; j < 3; ++j) {
      s.R[i] += K[6 * i + j] * e[j];
      s.C[6 * i + j] += K[6 * i + j];
    }
}

/// B21/B22/B31/B32/PIPE31/PIPE32 with NN nodes, planar (DOFs 1, 2, 6) or in space (1-6).
/// The section is pre-integrated (elastic: one energy, section_law) or integrated at its fibres
/// through the material's solid law (BeamData::law; history after the kState slots, per
/// integration point along the beam, per fibre, the law's n_state).
template <int NN, bool Planar>
class BeamKernel final : public ElementKernel {
  static constexpr int kDpn = Planar ? 3 : 6;
  static constexpr int kN = NN * kDpn;
  static constexpr int kPressureSlot = 4 * NN, kState = 4 * NN + 6;
  static constexpr int kAlong = NN == 2 ? 1 : 2; ///< integration points along the beam
  using J = Jet<kN>;

 public:
  explicit BeamKernel(BeamData data)
      : _b(std::move(data)), _n_fibre_state(_b.law ? _b.fibres.size() * _b.law->n_state() : 0) {}

  ElementType type() const override { return _b.type; }
  std::span<const DofType> node_dofs(int) const override {
    if constexpr (Planar)
      return kPlaneDofs;
    else
      return kSpaceDofs;
  }
  /// per node a unit quaternion; then the pipe pressures PI, PE with the step and time they were
  /// applied at (load() records them for the output); then an integrated section's fibre history
  int n_state() const override { return kState + kAlong * _n_fibre_state; }
  bool uses_temperature_field() const override {
    return material_uses_temperature(_b.material) || (_b.law && _b.law->temperature_dependent());
  }

  std::string validate(const ElementInput& in) const override {
    std::string why;
    beam_geometry<NN>(in.X, _b.n1a, in.ctx ? in.ctx->model_size : 1.0, &why);
    return why;
  }

  void initialize(const ElementInput& in) const override {
    for (int a = 0; a < NN; ++a) {
      in.state[4 * a] = 1.0;
      for (int i = 1; i < 4; ++i) in.state[4 * a + i] = 0.0;
    }
    for (int k = 0; k < 2; ++k) {
      in.state[kPressureSlot + 3 * k] = 0.0;
      in.state[kPressureSlot + 3 * k + 1] = 0.0;
      in.state[kPressureSlot + 3 * k + 2] = -1.0; // never applied
    }
    if (!_b.law) return;
    const auto ns = static_cast<std::size_t>(_b.law->n_state());
    for (int p = 0; p < kAlong; ++p)
      for (int f = 0; f < _b.fibres.size(); ++f)
        _b.law->initialize(history(in.state, p).subspan(f * ns, ns));
  }

  void evaluate(const ElementInput& in, ElementOutput& out) const override {
    const bool nl = in.ctx != nullptr && in.ctx->nlgeom;
    const BeamGeometry g = beam_geometry<NN>(in.X, _b.n1a, 1.0, nullptr);
    if (_b.law) {
      evaluate_fibres(in, out, g, nl);
    } else {
      const SectionLaw law = section_law(_b, in, g.length, NN);
      const auto nv = gather<J>(in, nl);
      const J W = energy(g, law, in.X, nv, nl);
      for (int i = 0; i < kN; ++i) out.residual[i] += W.g[i];
      if (out.want_tangent)
        for (int i = 0; i < kN; ++i)
          for (int j = 0; j < kN; ++j) out.tangent[i * kN + j] += W.hess(i, j);
    }
    write_rotations(in, nl);
    if (out.want_mass) add_mass(in, out.mass);
    if (out.want_damping && has_damping())
      add_beam_mass<NN, Planar>(in.X, _b.n1a, _b.added_damping, out.damping);
  }

  /// The initial-stress matrix of the perturbation du (elastic sections): the Hessian at in.u of
  /// sum_p w_p dR_p . e_p(v), e_p the geometrically exact strains and dR_p = D de_p the change of
  /// the section forces along du (central difference of the strains). Integrated (fibre)
  /// sections: not provided.
  bool stress_stiffness(const ElementInput& in, std::span<const double> du,
                        std::span<double> K) const override {
    if (_b.law || K.size() != static_cast<std::size_t>(kN * kN)) return false;
    double big = 0.0;
    for (double v : du) big = std::max(big, std::abs(v));
    if (!(big > 0.0)) return true;
    const BeamGeometry g = beam_geometry<NN>(in.X, _b.n1a, 1.0, nullptr);
    const SectionLaw law = section_law(_b, in, g.length, NN);
    const double h = 1e-6 * (in.ctx ? in.ctx->model_size : 1.0) / big;
    std::array<double, kN> up{}, um{};
    for (int i = 0; i < kN; ++i) {
      up[i] = in.u[i] + h * du[i];
      um[i] = in.u[i] - h * du[i];
    }
    ElementInput moved = in;
    moved.u = up;
    const auto ep = point_strains(g, in.X, gather<double>(moved, true), true);
    moved.u = um;
    const auto em = point_strains(g, in.X, gather<double>(moved, true), true);
    const auto e = point_strains(g, in.X, gather<J>(in, true), true);
    J W(0.0);
    for (int p = 0; p < g.n_points; ++p)
      for (int i = 0; i < 6; ++i) {
        double dR = 0.0;
        for (int j = 0; j < 6; ++j) dR += law.D[6 * i + j] * (ep[p][j] - em[p][j]) / (2.0 * h);
        W += g.pts[p].weight * dR * e[p][i];
      }
    for (int i = 0; i < kN; ++i)
      for (int j = 0; j < kN; ++j) K[i * kN + j] += W.hess(i, j);
    return true;
  }

  /// With *DENSITY: the section's mass and exact rotary inertia about the node, lumped at the
  /// nodes of two-node elements, consistent for three (beam_mass.hpp); a pipe's is its wall's.
  /// *BEAM ADDED INERTIA adds its own (contents, insulation, equipment), and with ALPHA the
  /// damping C = alpha M of that added inertia.
  bool has_mass() const override { return !_b.material.density.empty() || !_b.added.empty(); }
  bool has_damping() const override { return !_b.added_damping.empty(); }

  bool supports_load(DistLoadKind kind, int face) const override {
    return beam_supports_load(kind, face, Planar, _b.pipe);
  }
  void load(const ElementInput& in, const DistributedLoad& load, double magnitude, double,
            std::span<double> f_ext, std::span<double> tangent) const override {
    const bool nl = in.ctx != nullptr && in.ctx->nlgeom;
    if (load.kind == DistLoadKind::PipePressure)
      return pipe_pressure(in, load, magnitude, f_ext, tangent, nl);
    const BeamGeometry g = beam_geometry<NN>(in.X, _b.n1a, 1.0, nullptr);
    BeamLoadInput li{_b, g, load, magnitude, in, nl, Planar};
    if (nl && load.kind == DistLoadKind::LineLoad && load.face > 0) {
      // a follower load: its direction turns with the section
      const auto nv = gather<J>(in, true);
      const auto lr = local_rotations(nv);
      std::array<V3<J>, 2> dirs;
      for (int p = 0; p < g.n_points; ++p) {
        V3<J> phi{};
        for (int a = 0; a < NN; ++a)
          for (int i = 0; i < 3; ++i) phi[i] += g.pts[p].N[a] * lr.phi[a][i];
        const auto q = rotation::quat_mul(lr.r, rotation::quat_exp(phi));
        dirs[p] = rotation::rotate(q, g.pts[p].L0[load.face]);
      }
      follower_line_load<NN, kDpn>(li, dirs, f_ext, tangent);
      return;
    }
    dead_line_load<NN, kDpn>(li, f_ext);
  }

  bool supports_output(ElemVar var) const override {
    if (var == ElemVar::SF) return true;
    return (var == ElemVar::S || var == ElemVar::E) && _b.section.n_points > 0;
  }

  void recover(const ElementInput& in, ElementRecovery& out) const override {
    const bool nl = in.ctx != nullptr && in.ctx->nlgeom;
    const BeamGeometry g = beam_geometry<NN>(in.X, _b.n1a, 1.0, nullptr);
    if (_b.law) return recover_fibres(in, out, g, nl);
    const SectionLaw law = section_law(_b, in, g.length, NN);
    const auto nv = gather<double>(in, nl);
    std::array<Strains<double>, 2> e{};
    for (int p = 0; p < g.n_points; ++p) e[p] = strains(g.pts[p], in.X, nv, nl);
    BeamOutput o{law.D,   law.initial, law.E,
                 law.G,   _b.section,  Planar,
                 _b.pipe, law.nu,      _b.pipe ? pressures(in) : PipePressures{},
                 {},      {}};
    recover_beam_output(o, std::span(e.data(), static_cast<std::size_t>(g.n_points)), out);
  }

 private:
  /// Integration point p's slice of an integrated section's history (empty when `state` is too
  /// short to hold it, as for a kernel asked without history).
  template <class T>
  std::span<T> history(std::span<T> state, int p) const {
    const auto at = static_cast<std::size_t>(kState + p * _n_fibre_state);
    const auto n = static_cast<std::size_t>(_n_fibre_state);
    return state.size() >= at + n ? state.subspan(at, n) : std::span<T>{};
  }

  /// The fibres' law, temperatures and the elastic transverse shear of an element of length L.
  FibreLaw fibre_law(const ElementInput& in, double L, bool nl) const {
    const SectionTemperature t = SectionTemperature::of(in);
    const IsotropicModuli m = _b.law->elastic_moduli(t.T);
    FibreLaw f{FibreSection{*_b.law, _b.fibres, t, in.ctx ? in.ctx->dt : 0.0, nl},
               {},
               m.lambda + 2.0 * m.mu,
               m.mu,
               m.lambda / (2.0 * m.mu)};
    transverse_shear(_b, f.E, f.G, L, NN, f.shear);
    return f;
  }

  /// The strains of every integration point.
  template <class T>
  static std::array<Strains<T>, 2> point_strains(const BeamGeometry& g, std::span<const Vec3> X,
                                                 const BeamNodal<T, NN>& nv, bool nl) {
    std::array<Strains<T>, 2> e{};
    if (!nl) {
      for (int p = 0; p < g.n_points; ++p) e[p] = linear_strains(g.pts[p], nv);
      return e;
    }
    const auto lr = local_rotations(nv);
    for (int p = 0; p < g.n_points; ++p) e[p] = nonlinear_strains(g.pts[p], X, nv, lr);
    return e;
  }

  /// The integrated section: at each point the fibres' resultants R and tangent C (plus the
  /// elastic transverse shear) at the strains' values; residual sum w R . grad e, tangent
  /// sum w (grad e^T C grad e + R_c Hess e_c) from the strains' jets. The fibres' trial history
  /// goes to in.state, always from in.state_start.
  void evaluate_fibres(const ElementInput& in, ElementOutput& out, const BeamGeometry& g,
                       bool nl) const {
    const FibreLaw fl = fibre_law(in, g.length, nl);
    const auto e = point_strains(g, in.X, gather<J>(in, nl), nl);
    for (int p = 0; p < g.n_points; ++p) {
      Strains<double> ev{};
      for (int c = 0; c < 6; ++c) ev[c] = e[p][c].v;
      SectionResponse s;
      integrate_fibres(fl.section, ev, history(in.state_start, p), history(in.state, p),
                       out.want_tangent, s);
      add_shear(fl.shear, ev, s);
      if (!s.symmetric) out.unsymmetric = true;
      add_point(g.pts[p].weight, e[p], s, out);
    }
  }

  /// One point's share of the residual and tangent (w: its weight along the beam).
  static void add_point(double w, const Strains<J>& e, const SectionResponse& s,
                        ElementOutput& out) {
    for (int i = 0; i < kN; ++i) {
      double r = 0.0;
      for (int c = 0; c < 6; ++c) r += s.R[c] * e[c].g[i];
      out.residual[i] += w * r;
    }
    if (!out.want_tangent) return;
    std::array<std::array<double, kN>, 6> Cg{}; // C grad e
    for (int c = 0; c < 6; ++c)
      for (int d = 0; d < 6; ++d)
        if (const double C = s.C[6 * c + d]; C != 0.0)
          for (int j = 0; j < kN; ++j) Cg[c][j] += C * e[d].g[j];
    for (int i = 0; i < kN; ++i)
      for (int j = 0; j < kN; ++j) {
        double k = 0.0;
        for (int c = 0; c < 6; ++c) k += e[c].g[i] * Cg[c][j] + s.R[c] * e[c].hess(i, j);
        out.tangent[i * kN + j] += w * k;
      }
  }

  /// Output of an integrated section: section forces from the fibres' resultants and the elastic
  /// transverse shear; S at each section point from the law there (fibre_point_stress: the
  /// committed history of the nearest fibre, which is the point itself for every default output
  /// point but L's, on the outer faces while the thin-walled fibres lie on the mid-lines). The
  /// history is never written: the fibres update into a scratch copy.
  void recover_fibres(const ElementInput& in, ElementRecovery& out, const BeamGeometry& g,
                      bool nl) const {
    const FibreLaw fl = fibre_law(in, g.length, nl);
    const auto e = point_strains(g, in.X, gather<double>(in, nl), nl);
    const BeamSectionProperties& sec = _b.section;
    const auto ns = static_cast<std::size_t>(_b.law->n_state());
    std::vector<double> scratch(static_cast<std::size_t>(_n_fibre_state));
    std::array<std::array<double, 6>, 2> forces{};
    std::array<PointStress, 2 * BeamSectionProperties::kMaxPoints> points{};
    for (int p = 0; p < g.n_points; ++p) {
      const auto start = history(in.state_start, p);
      SectionResponse s;
      integrate_fibres(fl.section, e[p], start, scratch, false, s);
      add_shear(fl.shear, e[p], s);
      forces[p] = s.R;
      for (int k = 0; k < sec.n_points; ++k) {
        const auto [x1, x2] = sec.points[k];
        const auto f = static_cast<std::size_t>(_b.fibres.nearest(x1, x2));
        points[p * sec.n_points + k] =
            fibre_point_stress(fl.section, e[p], x1, x2, sec.torsion_radius[k],
                               start.empty() ? start : start.subspan(f * ns, ns));
      }
    }
    std::array<double, 6> initial{element_thermal_strain(_b.material, in)};
    const auto np = static_cast<std::size_t>(g.n_points);
    const BeamOutput o{fl.shear,
                       initial,
                       fl.E,
                       fl.G,
                       sec,
                       Planar,
                       _b.pipe,
                       fl.nu,
                       _b.pipe ? pressures(in) : PipePressures{},
                       std::span(forces.data(), np),
                       std::span(points.data(), np * static_cast<std::size_t>(sec.n_points))};
    recover_beam_output(o, std::span(e.data(), np), out);
  }

  void add_mass(const ElementInput& in, std::span<double> M) const {
    SectionInertia si = _b.added;
    if (!_b.material.density.empty())
      si += section_inertia(_b.section, table_value(_b.material.density, average(in.temperature)));
    add_beam_mass<NN, Planar>(in.X, _b.n1a, si, M);
  }

  /// PI/PE, closed-end condition: the axial force F of pipe_axial_force acting through the
  /// element's axis length l(x), f_ext = F dl/dx (the pressure's work F dl at constant area), with
  /// the load stiffness -F d2l/dx2 under NLGEOM (symmetric: the load is conservative).
  /// HPI/HPE: the pressure at the height of the element's midpoint in the reference
  /// configuration, p = magnitude (z0 - z) / (z0 - z1), zero beyond z0, constant along the
  /// element, plus the fluid's own weight (HPI, the contents) or its buoyancy (HPE) per unit
  /// length, A grad p with A the cap area: the pressure on a closed pipe sums to Archimedes'
  /// force, which the end-cap forces of a straight run alone (equal and opposite at each shared
  /// node) would miss.
  void pipe_pressure(const ElementInput& in, const DistributedLoad& load, double p,
                     std::span<double> f, std::span<double> tangent, bool nl) const {
    if (load.hydrostatic) {
      const int up = Planar ? 1 : 2;
      double z = 0.0;
      for (int a = 0; a < NN; ++a) z += in.X[a][up] / NN;
      const double factor = (load.z0 - z) / (load.z0 - load.z1);
      if (factor > 0.0) fluid_weight(in, load, p / (load.z0 - load.z1), up, f);
      p *= std::max(0.0, factor);
    }
    double E = 0.0, nu = 0.0;
    elastic_at(_b.material, average(in.temperature), E, nu);
    const double F = pipe_axial_force(_b.section, load, p, nu);
    const J l = axis_length(in, nl);
    for (int i = 0; i < kN; ++i) f[i] += F * l.g[i];
    if (nl && !tangent.empty())
      for (int i = 0; i < kN; ++i)
        for (int j = 0; j < kN; ++j) tangent[i * kN + j] -= F * l.hess(i, j);
    const int slot = kPressureSlot + 3 * (load.face - 1);
    if (in.state.size() >= static_cast<std::size_t>(kState) && in.ctx != nullptr) {
      in.state[slot] = p;
      in.state[slot + 1] = in.ctx->total_time;
      in.state[slot + 2] = in.ctx->step_index;
    }
  }

  /// HPI (contents' weight) or HPE (buoyancy): A grad p per unit reference length, grad p =
  /// -gradient e_up, A = pi D^2 / 4 with the load's effective or the section's diameter.
  void fluid_weight(const ElementInput& in, const DistributedLoad& load, double gradient, int up,
                    std::span<double> f) const {
    const bool inner = load.face == 1;
    const double D = load.diameter > 0.0 ? load.diameter
                                         : 2.0 * (inner ? _b.section.r_inner : _b.section.r_outer);
    const double q = 0.25 * std::numbers::pi * D * D * gradient * (inner ? -1.0 : 1.0);
    DistributedLoad line;
    line.kind = DistLoadKind::LineLoad;
    line.face = 0;
    line.direction[up] = 1.0;
    const BeamGeometry g = beam_geometry<NN>(in.X, _b.n1a, 1.0, nullptr);
    dead_line_load<NN, kDpn>(BeamLoadInput{_b, g, line, q, in, false, Planar}, f);
  }

  /// The PI and PE that load() recorded at the current time (0 when none acts now).
  PipePressures pressures(const ElementInput& in) const {
    PipePressures pp;
    if (in.state.size() < static_cast<std::size_t>(kState) || in.ctx == nullptr) return pp;
    auto now = [&](int k) {
      const double* s = in.state.data() + kPressureSlot + 3 * k;
      return s[2] == in.ctx->step_index && s[1] == in.ctx->total_time ? s[0] : 0.0;
    };
    pp.inner = now(0);
    pp.outer = now(1);
    return pp;
  }

  /// Length of the element's axis, as a jet of the DOFs: at the reference position without
  /// NLGEOM (its gradient is the reference direction), at the current one with it.
  J axis_length(const ElementInput& in, bool current) const {
    const int ndir = Planar ? 2 : 3;
    std::array<V3<J>, NN> x;
    for (int a = 0; a < NN; ++a)
      for (int i = 0; i < 3; ++i)
        x[a][i] = i < ndir
                      ? J::variable(in.X[a][i] + (current ? in.u[a * kDpn + i] : 0.0), a * kDpn + i)
                      : J(in.X[a][i]);
    using std::sqrt;
    if constexpr (NN == 2) {
      V3<J> d;
      for (int i = 0; i < 3; ++i) d[i] = x[1][i] - x[0][i];
      return sqrt(rotation::dot3(d, d));
    } else {
      // three-point Gauss rule of |dx/dxi| (exact for straight elements, 1e-6 for 90-degree arcs)
      const double g = std::sqrt(0.6), xi[3] = {-g, 0.0, g}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
      J l(0.0);
      for (int q = 0; q < 3; ++q) {
        std::array<double, 3> N{}, dN{};
        line_shape<NN>(xi[q], N, dN);
        V3<J> d{};
        for (int a = 0; a < NN; ++a)
          for (int i = 0; i < 3; ++i) d[i] += dN[a] * x[a][i];
        l += w[q] * sqrt(rotation::dot3(d, d));
      }
      return l;
    }
  }

  template <class T>
  BeamNodal<T, NN> gather(const ElementInput& in, bool nl) const {
    BeamNodal<T, NN> nv;
    for (int a = 0; a < NN; ++a) {
      const int b = a * kDpn;
      if constexpr (Planar) {
        nv.u[a] = {unknown<T>(in.u[b], b), unknown<T>(in.u[b + 1], b + 1), T(0.0)};
        nv.psi[a] = {T(0.0), T(0.0), unknown<T>(in.u[b + 2], b + 2)};
      } else {
        for (int i = 0; i < 3; ++i) {
          nv.u[a][i] = unknown<T>(in.u[b + i], b + i);
          nv.psi[a][i] = unknown<T>(in.u[b + 3 + i], b + 3 + i);
        }
      }
      if (!nl) continue;
      V3<T> inc = nv.psi[a];
      const int r0 = b + (Planar ? 2 : 3);
      if (!in.u_start.empty()) {
        if constexpr (Planar)
          inc[2] -= in.u_start[r0];
        else
          for (int i = 0; i < 3; ++i) inc[i] -= in.u_start[r0 + i];
      }
      nv.q[a] = rotation::quat_mul(rotation::quat_exp(inc), committed(in, a));
    }
    return nv;
  }

  static Quat<double> committed(const ElementInput& in, int a) {
    if (in.state_start.size() < static_cast<std::size_t>(4 * NN)) return {};
    const double* s = in.state_start.data() + 4 * a;
    return {s[0], s[1], s[2], s[3]};
  }

  template <class T>
  static Strains<T> strains(const BeamPoint& p, std::span<const Vec3> X, const BeamNodal<T, NN>& nv,
                            bool nl) {
    if (!nl) return linear_strains(p, nv);
    return nonlinear_strains(p, X, nv, local_rotations(nv));
  }

  template <class T>
  static T energy(const BeamGeometry& g, const SectionLaw& law, std::span<const Vec3> X,
                  const BeamNodal<T, NN>& nv, bool nl) {
    T W(0.0);
    if (!nl) {
      for (int p = 0; p < g.n_points; ++p)
        W += g.pts[p].weight * point_energy(linear_strains(g.pts[p], nv), law);
      return W;
    }
    const auto lr = local_rotations(nv);
    for (int p = 0; p < g.n_points; ++p)
      W += g.pts[p].weight * point_energy(nonlinear_strains(g.pts[p], X, nv, lr), law);
    return W;
  }

  /// Trial nodal rotations: exp(psi - psi_start) R_start under NLGEOM, exp(psi) otherwise (so an
  /// NLGEOM step after a linear one starts from the rotations reached).
  void write_rotations(const ElementInput& in, bool nl) const {
    if (in.state.size() < static_cast<std::size_t>(4 * NN)) return;
    const auto nv = gather<double>(in, nl);
    for (int a = 0; a < NN; ++a) {
      rotation::store_unit(nl ? nv.q[a] : rotation::quat_exp(nv.psi[a]), in.state.data() + 4 * a);
    }
  }

  BeamData _b;
  int _n_fibre_state = 0; ///< history per integration point: fibres x the law's n_state
};

} // namespace

} // namespace beam

std::unique_ptr<ElementKernel> make_beam_kernel(const KernelContext& ctx) {
  beam::BeamData data = beam::beam_data(ctx);
  switch (ctx.type) {
  case ElementType::B31:
  case ElementType::PIPE31:
    return std::make_unique<beam::BeamKernel<2, false>>(std::move(data));
  case ElementType::B32:
  case ElementType::B32R:
  case ElementType::PIPE32:
    return std::make_unique<beam::BeamKernel<3, false>>(std::move(data));
  case ElementType::B21:
    return std::make_unique<beam::BeamKernel<2, true>>(std::move(data));
  case ElementType::B22:
    return std::make_unique<beam::BeamKernel<3, true>>(std::move(data));
  default:
    break;
  }
  throw InternalError("make_beam_kernel: not a beam type");
}

} // namespace gapfem
