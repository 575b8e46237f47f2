#include "elements/structural/beam.hpp"

#include "elements/structural/structural_common.hpp"
#include "elements/structural/structural_factory.hpp"
#include "model/model.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <fmt/format.h>

namespace gapfem {

using namespace structural;

namespace {

constexpr std::array<DofType, 6> kBeamDofs{DofType::U1,  DofType::U2,  DofType::U3,
                                           DofType::UR1, DofType::UR2, DofType::UR3};

/// The message the B31 + NLGEOM restriction must carry (issue requirement).
constexpr const char* kNlgeomMessage =
    "B31 with NLGEOM is not available yet; run the step without NLGEOM";

using Mat6x12 = Eigen::Matrix<double, 6, 12>;
using Mat12 = Eigen::Matrix<double, 12, 12>;
using Vec12 = Eigen::Matrix<double, 12, 1>;
using Vec6 = Eigen::Matrix<double, 6, 1>;

/// Everything the integration point needs, in local coordinates.
struct Local {
  double L = 0.0;
  BeamKernel::Frame R{};
  Mat6x12 B = Mat6x12::Zero(); ///< generalised strains = B * local DOFs
  Vec6 D = Vec6::Zero();       ///< diagonal section stiffness
  double E = 0.0, G = 0.0, thermal_strain = 0.0;
};

/// Local DOF values (t, n1, n2 components of displacement and rotation) of the global ones.
Vec12 to_local(const BeamKernel::Frame& R, std::span<const double> u) {
  Vec12 ul;
  for (int blk = 0; blk < 4; ++blk)
    for (int i = 0; i < 3; ++i)
      ul(3 * blk + i) = R[i][0] * u[3 * blk] + R[i][1] * u[3 * blk + 1] + R[i][2] * u[3 * blk + 2];
  return ul;
}

/// Global components of a local 12-vector.
void add_global(const BeamKernel::Frame& R, const Vec12& fl, std::span<double> f) {
  for (int blk = 0; blk < 4; ++blk)
    for (int j = 0; j < 3; ++j)
      f[3 * blk + j] +=
          R[0][j] * fl(3 * blk) + R[1][j] * fl(3 * blk + 1) + R[2][j] * fl(3 * blk + 2);
}

} // namespace

BeamKernel::BeamKernel(Material material, BeamSectionProperties section, Vec3 n1_approx)
    : _material(std::move(material)), _section(section), _n1a(n1_approx) {}

std::span<const DofType> BeamKernel::node_dofs(int) const {
  return kBeamDofs;
}

bool BeamKernel::uses_temperature_field() const {
  return material_uses_temperature(_material);
}

BeamKernel::Frame BeamKernel::frame(std::span<const Vec3> X) const {
  const Vec3 d = sub(X[1], X[0]);
  const Vec3 t = scale(1.0 / norm(d), d);
  const Vec3 c = cross(t, _n1a);
  const Vec3 n2 = scale(1.0 / norm(c), c);
  return {t, cross(n2, t), n2};
}

std::string BeamKernel::validate(const ElementInput& in) const {
  const Vec3 d = sub(in.X[1], in.X[0]);
  const double L = norm(d);
  if (!(L > 1e-12 * (in.ctx ? in.ctx->model_size : 1.0)))
    return "the two nodes of this beam coincide, so it has no length; check the node coordinates";
  const double n1_len = norm(_n1a);
  // sin(angle between axis and n1) below 1e-6: n2 = t x n1 is undefined.
  if (!(norm(cross(d, _n1a)) > 1e-6 * L * n1_len))
    return fmt::format("the approximate n1 direction ({}, {}, {}) of the *BEAM SECTION is parallel "
                       "to the beam axis, so the cross-section orientation is undefined; give a "
                       "different n1 direction on the second data line of *BEAM SECTION",
                       _n1a[0], _n1a[1], _n1a[2]);
  return {};
}

namespace {

Local make_local(const BeamKernel& k, const Material& material, const BeamSectionProperties& s,
                 const ElementInput& in) {
  Local loc;
  loc.L = norm(sub(in.X[1], in.X[0]));
  loc.R = k.frame(in.X);
  double nu = 0.0;
  elastic_at(material, average(in.temperature), loc.E, nu);
  loc.G = loc.E / (2.0 * (1.0 + nu));
  loc.thermal_strain = element_thermal_strain(material, in);
  const double L = loc.L, E = loc.E, G = loc.G;
  // Shear stiffness with the residual-bending-flexibility correction (see beam.hpp):
  // 1/K_s = 1/(kGA) + L^2/(12 E I), I the moment of the bending plane the shear acts in.
  const double kGA = s.k * G * s.A;
  const double Ks2 =
      kGA / (1.0 + kGA * L * L / (12.0 * E * s.I11)); // shear along n2: bends about n1
  const double Ks1 =
      kGA / (1.0 + kGA * L * L / (12.0 * E * s.I22)); // shear along n1: bends about n2
  loc.D << E * s.A, Ks2, Ks1, E * s.I11, E * s.I22, G * s.J;
  // Local DOFs per node: 0 u_t, 1 v1, 2 v2, 3 theta_t, 4 theta_1, 5 theta_2 (node B: +6).
  // A rigid rotation theta_1 about n1 moves the axis by v2' = -theta_1, one about n2 by
  // v1' = +theta_2 (n1 x t = -n2, n2 x t = n1); the shear strains vanish for both.
  auto& B = loc.B;
  const double il = 1.0 / L;
  B(0, 0) = -il, B(0, 6) = il;                                  // eps   = u_t'
  B(1, 2) = -il, B(1, 8) = il, B(1, 4) = 0.5, B(1, 10) = 0.5;   // gam2  = v2' + theta_1
  B(2, 1) = -il, B(2, 7) = il, B(2, 5) = -0.5, B(2, 11) = -0.5; // gam1  = v1' - theta_2
  B(3, 4) = -il, B(3, 10) = il;                                 // kap1  = theta_1'
  B(4, 5) = -il, B(4, 11) = il;                                 // kap2  = theta_2'
  B(5, 3) = -il, B(5, 9) = il;                                  // twist = theta_t'
  return loc;
}

} // namespace

BeamKernel::SectionState BeamKernel::section_state(const ElementInput& in) const {
  const Local loc = make_local(*this, _material, _section, in);
  const Vec6 e = loc.B * to_local(loc.R, in.u);
  SectionState st;
  st.thermal_strain = loc.thermal_strain;
  st.E = loc.E;
  st.G = loc.G;
  for (int i = 0; i < 6; ++i) {
    st.strain[i] = e(i);
    st.force[i] = loc.D(i) * (e(i) - (i == 0 ? loc.thermal_strain : 0.0));
  }
  return st;
}

void BeamKernel::evaluate(const ElementInput& in, ElementOutput& out) const {
  if (in.ctx != nullptr && in.ctx->nlgeom)
    throw InputError({}, fmt::format("element {} (B31)", in.label), kNlgeomMessage);
  const Local loc = make_local(*this, _material, _section, in);
  const Vec12 ul = to_local(loc.R, in.u);
  Vec6 s = loc.B * ul;
  s(0) -= loc.thermal_strain;
  s = loc.D.cwiseProduct(s);
  // One-point rule over the length: f_loc = L B^T s, K_loc = L B^T D B.
  const Vec12 fl = loc.L * (loc.B.transpose() * s);
  add_global(loc.R, fl, out.residual);
  if (!out.want_tangent) return;
  const Mat12 Kl = loc.L * (loc.B.transpose() * loc.D.asDiagonal() * loc.B);
  // K = T^T Kl T with T = blockdiag(R, R, R, R), R rows = (t, n1, n2).
  Mat12 T = Mat12::Zero();
  for (int blk = 0; blk < 4; ++blk)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) T(3 * blk + i, 3 * blk + j) = loc.R[i][j];
  const Mat12 K = T.transpose() * Kl * T;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) out.tangent[i * 12 + j] += K(i, j);
}

bool BeamKernel::supports_load(DistLoadKind kind, int face) const {
  return face == 0 && (kind == DistLoadKind::Gravity || kind == DistLoadKind::BodyForce);
}

void BeamKernel::load(const ElementInput& in, const DistributedLoad& load, double magnitude, double,
                      std::span<double> f_ext, std::span<double>) const {
  // Uniform line load q (force per length, global) on a straight member: the consistent nodal
  // loads of the exact prismatic element are the fixed-end forces q L/2 and moments of magnitude
  // q_perp L^2/12 (independent of the shear flexibility).
  const double L = norm(sub(in.X[1], in.X[0]));
  const Frame R = frame(in.X);
  const double w = line_load_intensity(_material, _section.A, load, magnitude,
                                       average(in.temperature), in.label);
  const Vec3 q = scale(w, load.direction);
  const double q1 = dot(q, R[1]), q2 = dot(q, R[2]);
  // Node A: m1 = -q2 L^2/12, m2 = +q1 L^2/12; node B the opposite (see make_local for the signs).
  const double c = L * L / 12.0;
  const double m1 = -q2 * c, m2 = q1 * c;
  for (int j = 0; j < 3; ++j) {
    f_ext[j] += 0.5 * L * q[j];
    f_ext[6 + j] += 0.5 * L * q[j];
    const double mj = m1 * R[1][j] + m2 * R[2][j];
    f_ext[3 + j] += mj;
    f_ext[9 + j] -= mj;
  }
}

bool BeamKernel::supports_output(ElemVar var) const {
  return var == ElemVar::S || var == ElemVar::E || var == ElemVar::SF;
}

void BeamKernel::recover(const ElementInput& in, ElementRecovery& out) const {
  const SectionState st = section_state(in);
  OutputBlock& sf = add_block(out, ElemVar::SF, kBeamSF, 1);
  for (int i = 0; i < 6; ++i) sf.values[i] = st.force[i];
  // add both blocks before taking references: a second add_block may reallocate the first
  add_block(out, ElemVar::S, kBeamS, 4);
  add_block(out, ElemVar::E, kBeamE, 4);
  OutputBlock& s = out.blocks[out.blocks.size() - 2];
  OutputBlock& e = out.blocks.back();
  for (int p = 0; p < 4; ++p) {
    const double x1 = _section.points[p][0], x2 = _section.points[p][1];
    // Axial strain of a fibre: eps + kappa_1 x2 - kappa_2 x1 (docs/theory/structural.md §3.4).
    const double e11 = st.strain[0] + st.strain[3] * x2 - st.strain[4] * x1;
    const double e12 = st.strain[5] * _section.torsion_radius[p]; // engineering shear strain
    e.values[2 * p] = e11;
    e.values[2 * p + 1] = e12;
    s.values[2 * p] = st.E * (e11 - st.thermal_strain);
    s.values[2 * p + 1] = st.G * e12;
  }
}

std::unique_ptr<ElementKernel> make_beam_kernel(const KernelContext& ctx) {
  const Model& model = ctx.model;
  for (const Step& step : model.steps)
    if (step.nlgeom)
      throw InputError(step.loc,
                       ctx.elements.empty()
                           ? std::string("B31")
                           : fmt::format("element {} (B31)", model.element_label(ctx.elements[0])),
                       kNlgeomMessage);
  const BeamSection& sec = beam_section_of(ctx);
  const BeamSectionProperties props = beam_section_properties(sec);
  const Material& mat = section_material(model, sec.material, sec.loc,
                                         fmt::format("*BEAM SECTION, ELSET={}", sec.elset));
  check_density_for_gravity(ctx, mat);
  return std::make_unique<BeamKernel>(mat, props, sec.n1);
}

} // namespace gapfem
