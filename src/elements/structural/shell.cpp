#include "elements/structural/shell.hpp"

#include "common/jet.hpp"
#include "elements/structural/shell_section.hpp"
#include "elements/structural/shell_section_points.hpp"
#include "elements/structural/shell_strains.hpp"
#include "elements/structural/structural_common.hpp"

#include <cmath>
#include <optional>

namespace gapfem {

using namespace structural;

namespace shell {

namespace {

constexpr std::array<DofType, 6> kDofs{DofType::U1,  DofType::U2,  DofType::U3,
                                       DofType::UR1, DofType::UR2, DofType::UR3};
constexpr double kDrillFactor = 1e-3; ///< drilling penalty per area, times G t

template <class T>
T unknown(double v, int i) {
  if constexpr (std::is_same_v<T, double>)
    return v;
  else
    return T::variable(v, i);
}

/// Three-point rule of the triangle (interior points), weights summing to 1/2.
constexpr std::array<std::array<double, 3>, 3> kTri3{
    {{1.0 / 6, 1.0 / 6, 1.0 / 6}, {2.0 / 3, 1.0 / 6, 1.0 / 6}, {1.0 / 6, 2.0 / 3, 1.0 / 6}}};

template <int NN>
class ShellKernel final : public ElementKernel {
  static constexpr int kN = 6 * NN;
  using J = Jet<kN>;

 public:
  /// A law other than the built-in isotropic elasticity is integrated at the section points
  /// (shell_section_points.hpp); the built-in one through the closed-form section.
  ShellKernel(ShellData data, std::shared_ptr<const SolidLaw> law) : _d(std::move(data)) {
    if (!law->linear_isotropic_elastic()) _points.emplace(std::move(law), _d.n_points);
  }

  ElementType type() const override { return _d.type; }
  std::span<const DofType> node_dofs(int) const override { return kDofs; }
  /// A unit quaternion per node, then the law's history at each integration point's section
  /// points (section-point path only).
  int n_state() const override { return kRotState + rule().n * points_state(); }
  bool uses_temperature_field() const override { return material_uses_temperature(_d.material); }

  std::string validate(const ElementInput& in) const override {
    return check_geometry(in.X, directors(in), thickness(in), in.ctx ? in.ctx->model_size : 1.0);
  }

  void initialize(const ElementInput& in) const override {
    for (int a = 0; a < NN; ++a) {
      in.state[4 * a] = 1.0;
      for (int i = 1; i < 4; ++i) in.state[4 * a + i] = 0.0;
    }
    if (_points)
      for (int q = 0; q < rule().n; ++q) _points->initialize(point_state(in.state, q));
  }

  void evaluate(const ElementInput& in, ElementOutput& out) const override {
    const bool nl = in.ctx != nullptr && in.ctx->nlgeom;
    const SectionLaw law = section_law(_d, in);
    if (out.want_mass) add_mass(in, out.mass);
    if (!nl) {
      linear_evaluate(in, law, out);
      write_rotations(in, false);
      return;
    }
    if (_points) {
      integrated_evaluate(in, law, out);
      write_rotations(in, nl);
      return;
    }
    const auto nv = gather<J>(in, nl);
    const J W = energy(in, law, nv, nl);
    for (int i = 0; i < kN; ++i) out.residual[i] += W.g[i];
    if (out.want_tangent)
      for (int i = 0; i < kN; ++i)
        for (int j = 0; j < kN; ++j) out.tangent[i * kN + j] += W.hess(i, j);
    write_rotations(in, nl);
  }

  /// The initial-stress matrix of the perturbation du (homogeneous elastic sections): the
  /// Hessian at in.u of sum_q dA dR_q . s_q(v), s_q the section strains (membrane, bending,
  /// transverse shear; NLGEOM) and dR_q their section stiffness times the change of the strains
  /// along du (central difference); the drilling penalty's share is left out. Sections integrated
  /// at their points: not provided.
  bool stress_stiffness(const ElementInput& in, std::span<const double> du,
                        std::span<double> K) const override {
    if (_points || K.size() != static_cast<std::size_t>(kN * kN)) return false;
    double big = 0.0;
    for (double v : du) big = std::max(big, std::abs(v));
    if (!(big > 0.0)) return true;
    const SectionLaw law = section_law(_d, in);
    const double h = 1e-6 * (in.ctx ? in.ctx->model_size : 1.0) / big;
    std::array<double, kN> up{}, um{};
    for (int i = 0; i < kN; ++i) {
      up[i] = in.u[i] + h * du[i];
      um[i] = in.u[i] - h * du[i];
    }
    ElementInput plus = in, minus = in;
    plus.u = up;
    minus.u = um;
    const auto np = gather<double>(plus, true), nm = gather<double>(minus, true);
    const auto nv = gather<J>(in, true);
    const Tying<double> tp = tying(plus, np, true), tm = tying(minus, nm, true);
    const Tying<J> ty = tying(in, nv, true);
    const auto D = directors(in);
    const auto t = thickness(in);
    J W(0.0);
    const Rule q = rule();
    for (int k = 0; k < q.n; ++k) {
      SurfacePoint p;
      if (!surface_point(in.X, D, t, q.pts[k][0], q.pts[k][1], q.pts[k][2], p)) continue;
      const auto sp = flat(strains_at(p, np, true, tp)), sm = flat(strains_at(p, nm, true, tm));
      const auto sv = flat(strains_at(p, nv, true, ty));
      const std::array<double, 64> C = section_matrix(law, p.thickness);
      for (int i = 0; i < 8; ++i) {
        double dR = 0.0;
        for (int j = 0; j < 8; ++j) dR += C[8 * i + j] * (sp[j] - sm[j]) / (2.0 * h);
        W += p.dA * dR * sv[i];
      }
    }
    for (int i = 0; i < kN; ++i)
      for (int j = 0; j < kN; ++j) K[i * kN + j] += W.hess(i, j);
    return true;
  }

  /// The eight section strains in section_matrix's order (eps, kappa, gamma).
  template <class T>
  static std::array<T, 8> flat(const SectionStrains<T>& s) {
    return {s.eps[0], s.eps[1], s.eps[2], s.kap[0], s.kap[1], s.kap[2], s.gam[0], s.gam[1]};
  }

  /// With *DENSITY, as Abaqus/Standard (Theory Guide, "Rotary inertia for five degree of freedom
  /// shell elements"; docs/theory/dynamics.md §8): the translational mass integral rho t N_a N_b dA
  /// and the rotary inertia integral rho t^3/12 N_a N_b dA on each of the three global rotations,
  /// over the reference surface (the body-load rule); lumped (row sums) for the first-order S3,
  /// S3R, S4, S4R, consistent for S8R (whose row sums would make its corners negative).
  bool has_mass() const override { return !_d.material.density.empty(); }
  bool has_damping() const override { return false; }

  bool supports_load(DistLoadKind kind, int face) const override {
    if (kind == DistLoadKind::Pressure) return face >= 0 && face <= 2; // P, SNEG, SPOS
    return face == 0 && (kind == DistLoadKind::Gravity || kind == DistLoadKind::BodyForce);
  }

  void load(const ElementInput& in, const DistributedLoad& load, double magnitude, double,
            std::span<double> f_ext, std::span<double> tangent) const override {
    const bool nl = in.ctx != nullptr && in.ctx->nlgeom;
    if (load.kind == DistLoadKind::Pressure) {
      // a surface pressure pushes against the face's outward normal: SPOS (face 2) along -n
      const double sign = load.face == 2 ? -1.0 : 1.0;
      return pressure(in, sign * magnitude, nl, f_ext, tangent);
    }
    // body loads per unit reference area: rho g t or b t
    const auto D = directors(in);
    const auto t = thickness(in);
    const auto T = average(in.temperature);
    for (const auto& q : load_rule()) {
      SurfacePoint p;
      if (!surface_point(in.X, D, t, q[0], q[1], q[2], p)) continue;
      const double w = line_load_intensity(_d.material, p.thickness, load, magnitude, T, in.label);
      for (int a = 0; a < NN; ++a)
        for (int i = 0; i < 3; ++i) f_ext[6 * a + i] += p.dA * w * p.sh.N[a] * load.direction[i];
    }
  }

  bool supports_output(ElemVar var) const override {
    return var == ElemVar::S || var == ElemVar::E || var == ElemVar::SF;
  }

  void recover(const ElementInput& in, ElementRecovery& out) const override {
    const bool nl = in.ctx != nullptr && in.ctx->nlgeom;
    const SectionLaw law = section_law(_d, in);
    const auto nv = gather<double>(in, nl);
    if (_points) return integrated_recover(in, law, nv, nl, out);
    const auto D = directors(in);
    const auto t = thickness(in);
    std::array<SectionStrains<double>, 9> e{};
    std::array<double, 9> thick{};
    const Rule q = output_rule();
    const auto ty = tying(in, nv, nl);
    for (int k = 0; k < q.n; ++k) {
      SurfacePoint p;
      surface_point(in.X, D, t, q.pts[k][0], q.pts[k][1], q.pts[k][2], p);
      e[k] = strains_at(p, nv, nl, ty);
      thick[k] = p.thickness;
    }
    recover_shell_output(law, std::span(e.data(), q.n), std::span(thick.data(), q.n), out);
    out.strain_energy = energy(in, law, nv, nl);
  }

 private:
  void add_mass(const ElementInput& in, std::span<double> M) const {
    const auto D = directors(in);
    const auto t = thickness(in);
    const double rho = table_value(_d.material.density, average(in.temperature));
    for (const auto& q : load_rule()) {
      SurfacePoint p;
      if (!surface_point(in.X, D, t, q[0], q[1], q[2], p)) continue;
      const double w = p.dA * rho * p.thickness;
      double eta = w * p.thickness * p.thickness / 12.0; // rho t^3 / 12 dA
      // OFFSET: the mid-surface (the centre of mass) at zm = -offset t along the director from
      // the reference surface: rho t zm^2 more rotary inertia about it, and the first moment
      // rho t zm couples the translations and rotations (docs/theory/dynamics.md §8)
      const double zm = -_d.offset * p.thickness;
      const Vec3 n = unit_or(p.D, p.n);
      const double S = w * zm;
      if (zm != 0.0) eta += w * zm * zm;
      for (int a = 0; a < NN; ++a)
        for (int b = a; b < NN; ++b) { // symmetric to the last bit
          const double Nab = p.sh.N[a] * p.sh.N[b];
          if (!kLumped) {
            add_node_block(M, a, b, w * Nab, eta * Nab, b != a);
            if (zm != 0.0) add_coupling(M, a, b, S * Nab, n, b != a);
            continue;
          }
          // first order: lumped, each node's row sum on its diagonal
          add_node_block(M, a, a, w * Nab, eta * Nab, false);
          if (b != a) add_node_block(M, b, b, w * Nab, eta * Nab, false);
          if (zm == 0.0) continue;
          add_coupling(M, a, a, S * Nab, n, false);
          if (b != a) add_coupling(M, b, b, S * Nab, n, false);
        }
    }
  }

  static Vec3 unit_or(const Vec3& d, const Vec3& fallback) {
    const double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    return l > 0.0 ? Vec3{d[0] / l, d[1] / l, d[2] / l} : fallback;
  }
  /// The translation-rotation coupling of a first moment s along the unit director n between
  /// nodes a and b: the kinetic energy s u'.(w x n) = w^T [n]x u' s, so M(rot a, u b) += s [n]x
  /// and M(u b, rot a) += s [n]x^T (and the (b, a) pair when `mirror`).
  static void add_coupling(std::span<double> M, int a, int b, double s, const Vec3& n,
                           bool mirror) {
    const double N[3][3] = {{0.0, -n[2], n[1]}, {n[2], 0.0, -n[0]}, {-n[1], n[0], 0.0}};
    auto put = [&](int p, int q) { // rotations of p against translations of q
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          M[(6 * p + 3 + i) * kN + 6 * q + j] += s * N[i][j];
          M[(6 * q + j) * kN + 6 * p + 3 + i] += s * N[i][j];
        }
    };
    put(a, b);
    if (mirror) put(b, a);
  }

  static constexpr bool kLumped = NN < 8; ///< S3, S3R, S4, S4R: lumped; S8R: consistent
  /// Adds m on the translations and eta on the rotations of the (a, b) node block (and of the
  /// (b, a) block when `mirror`).
  static void add_node_block(std::span<double> M, int a, int b, double m, double eta, bool mirror) {
    for (int i = 0; i < 6; ++i) {
      const double v = i < 3 ? m : eta;
      M[(6 * a + i) * kN + 6 * b + i] += v;
      if (mirror) M[(6 * b + i) * kN + 6 * a + i] += v;
    }
  }

  static constexpr int kRotState = 4 * NN;
  int points_state() const { return _points ? _points->n_state() : 0; }
  /// The section-point history of integration point q in a state array.
  template <class Span>
  Span point_state(Span state, int q) const {
    const auto m = static_cast<std::size_t>(points_state());
    return state.subspan(kRotState + q * m, m);
  }

  /// The section-point path under NLGEOM: the strains as Jets, the section's response at their
  /// values, r and K by the chain rule (add_section_terms), the drilling penalty as an energy.
  void integrated_evaluate(const ElementInput& in, const SectionLaw& law,
                           ElementOutput& out) const {
    const auto nv = gather<J>(in, true);
    const Tying<J> ty = tying(in, nv, true);
    const SectionTemperature temp = section_temperature(_d.material, in);
    const auto D = directors(in);
    const auto t = thickness(in);
    double area = 0.0;
    const Rule q = rule();
    for (int k = 0; k < q.n; ++k) {
      SurfacePoint p;
      if (!surface_point(in.X, D, t, q.pts[k][0], q.pts[k][1], q.pts[k][2], p)) continue;
      area += p.dA;
      const SectionStrains<J> e = strains_at(p, nv, true, ty);
      SectionResponse resp;
      _points->respond(law, temp, p.thickness, strain_values(e), point_state(in.state_start, k),
                       point_state(in.state, k), out.want_tangent, resp);
      add_section_terms(p.dA, e, resp, out.want_tangent, out.residual, out.tangent);
    }
    const J W = drilling(in, law, nv, true, area);
    for (int i = 0; i < kN; ++i) out.residual[i] += W.g[i];
    if (out.want_tangent)
      for (int i = 0; i < kN; ++i)
        for (int j = 0; j < kN; ++j) out.tangent[i * kN + j] += W.hess(i, j);
  }

  /// Output of the section-point path: the law at the integration points' section points
  /// (recover_section_points), the drilling energy on top.
  void integrated_recover(const ElementInput& in, const SectionLaw& law,
                          const ShellNodal<double, NN>& nv, bool nl, ElementRecovery& out) const {
    const auto D = directors(in);
    const auto t = thickness(in);
    const Rule q = rule();
    const auto ty = tying(in, nv, nl);
    std::array<SectionStrains<double>, 9> e{};
    std::array<double, 9> thick{}, dA{};
    double area = 0.0;
    for (int k = 0; k < q.n; ++k) {
      SurfacePoint p;
      if (!surface_point(in.X, D, t, q.pts[k][0], q.pts[k][1], q.pts[k][2], p)) continue;
      e[k] = strains_at(p, nv, nl, ty);
      thick[k] = p.thickness;
      dA[k] = p.dA;
      area += p.dA;
    }
    const auto n = static_cast<std::size_t>(q.n);
    const double W = recover_section_points(
        *_points, law, section_temperature(_d.material, in), std::span(e.data(), n),
        std::span(thick.data(), n), std::span(dA.data(), n), in.state_start.subspan(kRotState),
        output_rule().n != q.n, out);
    out.strain_energy = W + drilling(in, law, nv, nl, area);
  }

  std::span<const Vec3> directors(const ElementInput& in) const {
    return std::span(_d.directors).subspan(static_cast<std::size_t>(in.block_index) * NN, NN);
  }
  std::span<const double> thickness(const ElementInput& in) const {
    return std::span(_d.thickness).subspan(static_cast<std::size_t>(in.block_index) * NN, NN);
  }

  /// Output points: Abaqus's integration points (S4R and S3/S3R one, S4 and S8R four).
  Rule output_rule() const {
    if (NN == 3 || _d.type == ElementType::S4R) {
      Rule r;
      r.n = 1;
      r.pts[0] = centre_point(NN);
      return r;
    }
    return rule();
  }

  /// Integration points: 3 on triangles, 2x2 on S4/S4R/S8R, 3x3 on S8.
  Rule rule() const {
    if (_d.type == ElementType::S8) return gauss3x3_rule();
    if constexpr (NN == 3) {
      Rule r;
      r.n = 3;
      for (int k = 0; k < 3; ++k) r.pts[k] = kTri3[k];
      return r;
    }
    return full_rule(NN);
  }

  /// Points for distributed loads: 3 on triangles, 2x2 on S4, 3x3 on S8R.
  std::vector<std::array<double, 3>> load_rule() const {
    std::vector<std::array<double, 3>> r;
    if (NN == 3) {
      for (const auto& p : kTri3) r.push_back(p);
    } else if (NN == 4) {
      for (int k = 0; k < 4; ++k) r.push_back(full_rule(4).pts[k]);
    } else {
      const double g = std::sqrt(0.6), x[3] = {-g, 0.0, g}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r.push_back({x[i], x[j], w[i] * w[j]});
    }
    return r;
  }

  /// Pressure on the reference surface: the force points along the positive (SPOS) normal, as in
  /// Abaqus ("Distributed loads": for conventional shells the force vector points along the SPOS
  /// normal) and CalculiX; a follower load under NLGEOM (its load stiffness added to the tangent).
  /// A surface-based pressure (*DSLOAD) acts against the surface normal: on an SNEG face (face 1)
  /// along +n like P, on an SPOS face (face 2) along -n; load() passes the signed magnitude.
  void pressure(const ElementInput& in, double pr, bool nl, std::span<double> f,
                std::span<double> tangent) const {
    for (const auto& q : load_rule()) {
      const Shape sh = shape_at(NN, q[0], q[1]);
      Vec3 xr{}, xs{};
      for (int a = 0; a < NN; ++a)
        for (int i = 0; i < 3; ++i) {
          const double x = in.X[a][i] + (nl ? in.u[6 * a + i] : 0.0);
          xr[i] += sh.dr[a] * x;
          xs[i] += sh.ds[a] * x;
        }
      const Vec3 n = cross(xr, xs);
      for (int a = 0; a < NN; ++a)
        for (int i = 0; i < 3; ++i) f[6 * a + i] += pr * q[2] * sh.N[a] * n[i];
      if (!nl || tangent.empty()) continue;
      // d(xr x xs)/du_bk = dr_b (e_k x xs) + ds_b (xr x e_k); tangent -= d f / du
      for (int b = 0; b < NN; ++b)
        for (int k = 0; k < 3; ++k) {
          Vec3 ek{};
          ek[k] = 1.0;
          const Vec3 c1 = cross(ek, xs), c2 = cross(xr, ek);
          for (int a = 0; a < NN; ++a)
            for (int i = 0; i < 3; ++i)
              tangent[(6 * a + i) * kN + 6 * b + k] -=
                  pr * q[2] * sh.N[a] * (sh.dr[b] * c1[i] + sh.ds[b] * c2[i]);
        }
    }
  }

  template <class T>
  ShellNodal<T, NN> gather(const ElementInput& in, bool nl) const {
    ShellNodal<T, NN> nv;
    const auto D = directors(in);
    for (int a = 0; a < NN; ++a) {
      const int b = 6 * a;
      V3<T> th;
      for (int i = 0; i < 3; ++i) {
        nv.u[a][i] = unknown<T>(in.u[b + i], b + i);
        th[i] = unknown<T>(in.u[b + 3 + i], b + 3 + i);
      }
      const V3<double> Da{D[a][0], D[a][1], D[a][2]};
      if (!nl) {
        nv.dd[a] = rotation::cross3(th, Da);
        continue;
      }
      const V3<T> d = rotation::rotate(rotation_of(in, th, a), Da);
      for (int i = 0; i < 3; ++i) nv.dd[a][i] = d[i] - Da[i];
    }
    return nv;
  }

  /// R_a = exp(theta - theta_start) R_start.
  template <class T>
  rotation::Quat<T> rotation_of(const ElementInput& in, V3<T> th, int a) const {
    if (!in.u_start.empty())
      for (int i = 0; i < 3; ++i) th[i] -= in.u_start[6 * a + 3 + i];
    rotation::Quat<double> q0{};
    if (in.state_start.size() >= static_cast<std::size_t>(4 * NN)) {
      const double* s = in.state_start.data() + 4 * a;
      q0 = {s[0], s[1], s[2], s[3]};
    }
    return rotation::quat_mul(rotation::quat_exp(th), q0);
  }

  /// What the assumed strains take from points other than the integration point: the covariant
  /// transverse shear at the MITC tying points and, for the quadrilaterals, the in-plane shear
  /// strains at the centre (selective integration). Computed once per evaluation.
  template <class T>
  struct Tying {
    std::array<T, 4> g{}; ///< S4: g_r at (0,-1), (0,1), g_s at (-1,0), (1,0); S3: MITC3 values
    T eps12{}, kap12{};   ///< S4: centre values in the centre's local directions
  };

  template <class T>
  Tying<T> tying(const ElementInput& in, const ShellNodal<T, NN>& nv, bool nl) const {
    Tying<T> ty;
    if constexpr (NN == 8) return ty;
    const auto D = directors(in);
    const auto t = thickness(in);
    auto shear = [&](double r, double s) {
      SurfacePoint q;
      surface_point(in.X, D, t, r, s, 1.0, q);
      return covariant_shear(q, nv, nl);
    };
    if constexpr (NN == 4) {
      ty.g = {shear(0.0, -1.0)[0], shear(0.0, 1.0)[0], shear(-1.0, 0.0)[1], shear(1.0, 0.0)[1]};
      SurfacePoint m;
      surface_point(in.X, D, t, 0.0, 0.0, 1.0, m);
      const Covariant<T> cm = covariant(m, nv, nl);
      ty.eps12 = to_local(m, cm.m)[2];
      ty.kap12 = to_local(m, cm.k)[2];
    } else {
      // MITC3: g_r at (1/2, 0), g_s at (0, 1/2), and c from the hypotenuse's midpoint
      const auto p1 = shear(0.5, 0.0), p2 = shear(0.0, 0.5), p3 = shear(0.5, 0.5);
      ty.g = {p1[0], p2[1], (p2[1] - p1[0]) - (p3[1] - p3[0]), T(0.0)};
    }
    return ty;
  }

  /// Local section strains at a point, with the assumed transverse shear of MITC3/MITC4 and, for
  /// the quadrilaterals, the in-plane shear strains replaced by their centre values.
  template <class T>
  SectionStrains<T> strains_at(const SurfacePoint& p, const ShellNodal<T, NN>& nv, bool nl,
                               const Tying<T>& ty) const {
    const Covariant<T> c = covariant(p, nv, nl);
    SectionStrains<T> s;
    s.eps = to_local(p, c.m);
    s.kap = to_local(p, c.k);
    T gr = c.g[0], gs = c.g[1];
    if constexpr (NN == 4) {
      gr = 0.5 * (1.0 - p.s) * ty.g[0] + 0.5 * (1.0 + p.s) * ty.g[1];
      gs = 0.5 * (1.0 - p.r) * ty.g[2] + 0.5 * (1.0 + p.r) * ty.g[3];
      s.eps[2] = ty.eps12;
      s.kap[2] = ty.kap12;
    } else if constexpr (NN == 3) {
      gr = ty.g[0] + ty.g[2] * p.s;
      gs = ty.g[1] - ty.g[2] * p.r;
    }
    s.gam = shear_to_local(p, gr, gs);
    return s;
  }

  template <class T>
  T energy(const ElementInput& in, const SectionLaw& law, const ShellNodal<T, NN>& nv,
           bool nl) const {
    const auto D = directors(in);
    const auto t = thickness(in);
    T W(0.0);
    double area = 0.0;
    const Tying<T> ty = tying(in, nv, nl);
    auto add = [&](double r, double s, double w) {
      SurfacePoint p;
      if (!surface_point(in.X, D, t, r, s, w, p)) return;
      W += p.dA * section_energy(law, p.thickness, strains_at(p, nv, nl, ty));
      area += p.dA;
    };
    const Rule q = rule();
    for (int k = 0; k < q.n; ++k) add(q.pts[k][0], q.pts[k][1], q.pts[k][2]);
    W += drilling(in, law, nv, nl, area);
    return W;
  }

  /// Small displacements: the strains are linear in the DOFs, so first-order duals give their
  /// matrix B at each point, K = sum w B^T C B and r = sum w B^T C (e - e_th) (the gradient and
  /// Hessian of the same energy as the NLGEOM path, at a fraction of the cost).
  void linear_evaluate(const ElementInput& in, const SectionLaw& law, ElementOutput& out) const {
    using Du = Dual<kN>;
    const auto nv = gather<Du>(in, false);
    const Tying<Du> ty = tying(in, nv, false);
    const auto D = directors(in);
    const auto t = thickness(in);
    double area = 0.0;
    const SectionTemperature temp =
        _points ? section_temperature(_d.material, in) : SectionTemperature{};
    auto add = [&](int qk, double r, double s, double w) {
      SurfacePoint p;
      if (!surface_point(in.X, D, t, r, s, w, p)) return;
      area += p.dA;
      const SectionStrains<Du> e = strains_at(p, nv, false, ty);
      if (_points) {
        SectionResponse resp;
        _points->respond(law, temp, p.thickness, strain_values(e), point_state(in.state_start, qk),
                         point_state(in.state, qk), out.want_tangent, resp);
        return add_section_terms(p.dA, e, resp, out.want_tangent, out.residual, out.tangent);
      }
      const std::array<const Du*, 8> b{&e.eps[0], &e.eps[1], &e.eps[2], &e.kap[0],
                                       &e.kap[1], &e.kap[2], &e.gam[0], &e.gam[1]};
      const auto C = section_matrix(law, p.thickness);
      std::array<double, 8> mech;
      for (int i = 0; i < 8; ++i)
        mech[i] = b[i]->v - (i < 2 ? law.eps_th : (i == 3 || i == 4) ? law.kap_th : 0.0);
      // CB (8 x N) and the stress resultants
      std::array<std::array<double, kN>, 8> CB{};
      std::array<double, 8> sig{};
      for (int i = 0; i < 8; ++i)
        for (int k = 0; k < 8; ++k)
          if (const double c = C[8 * i + k]; c != 0.0) {
            sig[i] += c * mech[k];
            for (int j = 0; j < kN; ++j) CB[i][j] += c * b[k]->g[j];
          }
      for (int i = 0; i < 8; ++i)
        for (int a = 0; a < kN; ++a) out.residual[a] += p.dA * b[i]->g[a] * sig[i];
      if (!out.want_tangent) return;
      for (int i = 0; i < 8; ++i)
        for (int a = 0; a < kN; ++a)
          if (const double ba = p.dA * b[i]->g[a]; ba != 0.0)
            for (int j = 0; j < kN; ++j) out.tangent[a * kN + j] += ba * CB[i][j];
    };
    const Rule q = rule();
    for (int k = 0; k < q.n; ++k) add(k, q.pts[k][0], q.pts[k][1], q.pts[k][2]);
    for (int a = 0; a < NN; ++a) {
      const Du d = drill_at(in, nv, false, a);
      const double k = kDrillFactor * law.G * t[a] * area / NN;
      for (int i = 0; i < kN; ++i) out.residual[i] += k * d.v * d.g[i];
      if (out.want_tangent)
        for (int i = 0; i < kN; ++i)
          for (int j = 0; j < kN; ++j) out.tangent[i * kN + j] += k * d.g[i] * d.g[j];
    }
  }

  /// 1/2 k A/NN sum_a (theta_n - omega)_a^2: the rotation about the normal at each node against the
  /// in-plane rotation of the surface there, objective under NLGEOM:
  ///   drill = 1/2 [(R e1) . g2 - (R e2) . g1],  g_i = F e_i (the deformed local directions).
  template <class T>
  T drilling(const ElementInput& in, const SectionLaw& law, const ShellNodal<T, NN>& nv, bool nl,
             double area) const {
    const auto t = thickness(in);
    T W(0.0);
    for (int a = 0; a < NN; ++a) {
      const T drill = drill_at(in, nv, nl, a);
      const double k = kDrillFactor * law.G * t[a] * area / NN;
      W += 0.5 * k * (drill * drill);
    }
    return W;
  }

  template <class T>
  T drill_at(const ElementInput& in, const ShellNodal<T, NN>& nv, bool nl, int a) const {
    const auto D = directors(in);
    const auto t = thickness(in);
    const auto rs = node_coordinates(NN, a);
    SurfacePoint p;
    if (!surface_point(in.X, D, t, rs[0], rs[1], 1.0, p)) return T(0.0);
    V3<T> ur, us;
    surface_derivatives(p, nv, ur, us);
    V3<T> dg1, dg2, de1, de2;
    for (int i = 0; i < 3; ++i) {
      dg1[i] = ur[i] * p.T[0][0] + us[i] * p.T[1][0];
      dg2[i] = ur[i] * p.T[0][1] + us[i] * p.T[1][1];
    }
    const V3<double> e1{p.e1[0], p.e1[1], p.e1[2]}, e2{p.e2[0], p.e2[1], p.e2[2]};
    V3<T> th;
    for (int i = 0; i < 3; ++i) th[i] = unknown<T>(in.u[6 * a + 3 + i], 6 * a + 3 + i);
    if (nl) {
      const auto q = rotation_of(in, th, a);
      const V3<T> r1 = rotation::rotate(q, e1), r2 = rotation::rotate(q, e2);
      for (int i = 0; i < 3; ++i) {
        de1[i] = r1[i] - e1[i];
        de2[i] = r2[i] - e2[i];
      }
    } else {
      de1 = rotation::cross3(th, e1);
      de2 = rotation::cross3(th, e2);
    }
    return 0.5 * (change(p.e1, de1, p.e2, dg2, nl) - change(p.e2, de2, p.e1, dg1, nl));
  }

  /// Trial nodal rotations: exp(theta - theta_start) R_start under NLGEOM, exp(theta) otherwise.
  void write_rotations(const ElementInput& in, bool nl) const {
    if (in.state.size() < static_cast<std::size_t>(4 * NN)) return;
    for (int a = 0; a < NN; ++a) {
      V3<double> th{in.u[6 * a + 3], in.u[6 * a + 4], in.u[6 * a + 5]};
      const auto q = nl ? rotation_of(in, th, a) : rotation::quat_exp(th);
      rotation::store_unit(q, in.state.data() + 4 * a);
    }
  }

  ShellData _d;
  std::optional<ShellSectionPoints> _points; ///< the section-point path, or closed form
};

} // namespace

} // namespace shell

std::unique_ptr<ElementKernel> make_shell_kernel(const KernelContext& ctx) {
  shell::ShellData data = shell::shell_data(ctx);
  auto law = make_solid_law(data.material, Kinematics::PlaneStress);
  switch (element_info(ctx.type).n_nodes) {
  case 3:
    return std::make_unique<shell::ShellKernel<3>>(std::move(data), std::move(law));
  case 4:
    return std::make_unique<shell::ShellKernel<4>>(std::move(data), std::move(law));
  case 8:
    return std::make_unique<shell::ShellKernel<8>>(std::move(data), std::move(law));
  default:
    break;
  }
  throw InternalError("make_shell_kernel: not a shell type");
}

} // namespace gapfem
