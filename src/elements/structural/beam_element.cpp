#include "elements/structural/beam_element.hpp"

#include "elements/rayleigh_damping.hpp"
#include "elements/structural/beam_loads.hpp"
#include "elements/structural/beam_mass.hpp"
#include "elements/structural/structural_common.hpp"
#include "elements/structural/structural_factory.hpp"
#include "model/model.hpp"

#include <fmt/format.h>
#include <numbers>

namespace gapfem::beam {

using namespace structural;

namespace {

bool is_pipe(ElementType t) {
  return t == ElementType::PIPE31 || t == ElementType::PIPE32;
}

/// The material of a *BEAM GENERAL SECTION: its E, G, alpha and DENSITY as constant tables.
Material general_material(const BeamSection& sec) {
  Material m;
  m.name = fmt::format("of *BEAM GENERAL SECTION, ELSET={}", sec.elset);
  m.loc = sec.loc;
  m.elastic.n_values = 2;
  m.elastic.values = {sec.E, sec.E / (2.0 * sec.G) - 1.0};
  if (sec.alpha != 0.0) {
    m.expansion.n_values = 1;
    m.expansion.values = {sec.alpha};
  }
  if (sec.density > 0.0) {
    m.density.n_values = 1;
    m.density.values = {sec.density};
  }
  return m;
}

void check_general_density(const KernelContext& ctx, const BeamSection& sec) {
  if (sec.density > 0.0) return;
  for (const Step& step : ctx.model.steps)
    for (const DistributedLoad& load : step.dloads)
      if (load.kind == DistLoadKind::Gravity && load.elem >= 0 &&
          ctx.model.element_property[load.elem].kind == ctx.property.kind &&
          ctx.model.element_property[load.elem].index == ctx.property.index)
        throw InputError(load.loc, fmt::format("element {}", ctx.model.element_label(load.elem)),
                         fmt::format("GRAV needs the mass density of the beam section; add "
                                     "DENSITY=<rho> to *BEAM GENERAL SECTION, ELSET={}",
                                     sec.elset));
}

/// *BEAM ADDED INERTIA of the section: its data lines summed (beam_mass.hpp), and their damping
/// sum alpha_k M_k. A material *DAMPING ALPHA (RayleighDampingKernel, around this kernel) damps
/// the element's whole mass block, the added inertia with it, whereas Abaqus damps the added
/// inertia with the ALPHA of its own keyword only: the kernel's damping block takes
/// alpha_R M_added back out (docs/theory/dynamics.md, "Added inertia").
void add_inertia(const KernelContext& ctx, const BeamSection& sec, bool planar, BeamData& d) {
  for (const BeamAddedInertia& a : sec.added_inertia) {
    if (planar && a.angle != 0.0)
      throw InputError(a.loc, fmt::format("ELSET={}", sec.elset),
                       fmt::format("{} is a planar beam: the orientation angle of the rotary "
                                   "inertia (field 4, {}) is for beams in space only; leave it "
                                   "blank",
                                   element_info(ctx.type).name, a.angle));
    const SectionInertia si = added_section_inertia(a);
    d.added += si;
    d.added_damping += si.scaled(a.alpha);
  }
  const Material* mat = property_material(ctx);
  if (!d.added.empty() && mat != nullptr && mat->damping && mat->damping->viscous() &&
      mat->damping->alpha != 0.0)
    d.added_damping += d.added.scaled(-mat->damping->alpha);
}

} // namespace

BeamData beam_data(const KernelContext& ctx) {
  const Model& model = ctx.model;
  const BeamSection& sec = beam_section_of(ctx);
  const std::string entity = fmt::format("ELSET={}", sec.elset);
  const std::string_view name = element_info(ctx.type).name;
  const bool planar = element_info(ctx.type).space == SpaceRequirement::Planar;
  BeamData d;
  d.type = ctx.type;
  d.pipe = is_pipe(ctx.type);
  d.section = beam_section_properties(sec, planar);
  d.slenderness = sec.slenderness;
  if (d.pipe && sec.shape != BeamSection::Shape::Pipe)
    throw InputError(sec.loc, entity,
                     fmt::format("{} elements are pipes and need SECTION=PIPE; use B31/B32 for "
                                 "other sections",
                                 name));
  if (planar) {
    const Vec3& n = sec.n1;
    if (sec.n1_given && !(n[0] == 0.0 && n[1] == 0.0 && n[2] < 0.0))
      throw InputError(sec.loc, entity,
                       fmt::format("{} is a planar beam, whose n1 direction is always (0, 0, -1); "
                                   "remove the second data line or give 0, 0, -1",
                                   name));
    d.n1a = {0.0, 0.0, -1.0};
  } else {
    d.n1a = sec.n1;
  }
  add_inertia(ctx, sec, planar, d);
  // GRAV acts on the added mass too: an added mass alone is enough for it
  const bool weighs = d.added.m > 0.0;
  if (sec.general) {
    d.material = general_material(sec);
    if (!weighs) check_general_density(ctx, sec);
  } else {
    d.material = section_material(model, sec.material, sec.loc, entity);
    if (!weighs) check_density_for_gravity(ctx, d.material);
  }
  // the path: the built-in elastic law and GENERAL (resultant) sections keep the pre-integrated
  // section; any other law is called at the section's fibres (beam_fibres.hpp)
  if (!sec.general && sec.shape != BeamSection::Shape::General) {
    auto law = make_solid_law(d.material, Kinematics::Beam);
    if (!law->linear_isotropic_elastic()) {
      d.fibres = beam_section_fibres(sec, d.section);
      d.law = std::move(law);
    }
  }
  return d;
}

bool beam_supports_load(DistLoadKind kind, int face, bool planar, bool pipe) {
  switch (kind) {
  case DistLoadKind::PipePressure:
    return pipe && (face == 1 || face == 2);
  case DistLoadKind::Gravity:
  case DistLoadKind::BodyForce:
    return face == 0;
  case DistLoadKind::LineLoad:
    return face == 0 || face == 2 || (face == 1 && !planar);
  default:
    return false;
  }
}

double pipe_lame_sum(const BeamSectionProperties& s, const PipePressures& p) {
  const double a2 = s.r_inner * s.r_inner, b2 = s.r_outer * s.r_outer;
  return 2.0 * (p.inner * a2 - p.outer * b2) / (b2 - a2);
}

double pipe_radial_at(const BeamSectionProperties& s, const PipePressures& p, double r) {
  const double a2 = s.r_inner * s.r_inner, b2 = s.r_outer * s.r_outer, d = b2 - a2;
  return (p.inner * a2 - p.outer * b2) / d - (p.inner - p.outer) * a2 * b2 / (d * r * r);
}

double pipe_hoop_at(const BeamSectionProperties& s, const PipePressures& p, double r) {
  // Lame: sigma_theta = (p_i a^2 - p_e b^2) / (b^2 - a^2) + (p_i - p_e) a^2 b^2 / ((b^2 - a^2) r^2)
  const double a2 = s.r_inner * s.r_inner, b2 = s.r_outer * s.r_outer, d = b2 - a2;
  return (p.inner * a2 - p.outer * b2) / d + (p.inner - p.outer) * a2 * b2 / (d * r * r);
}

double pipe_axial_force(const BeamSectionProperties& s, const DistributedLoad& load, double p,
                        double nu) {
  const bool inner = load.face == 1;
  const double D = load.diameter > 0.0 ? load.diameter : 2.0 * (inner ? s.r_inner : s.r_outer);
  const double cap = 0.25 * std::numbers::pi * D * D * (inner ? p : -p);
  const PipePressures pp{inner ? p : 0.0, inner ? 0.0 : p};
  return cap - nu * s.A * pipe_lame_sum(s, pp);
}

Vec3 dead_intensity(const BeamLoadInput& li, int p) {
  const DistributedLoad& load = li.load;
  if (load.kind == DistLoadKind::LineLoad) {
    // (face 0 is PX/PY/PZ: a global direction; a label without one is rejected by the reader)
    FE_CHECK(load.face != 0 || load.direction != Vec3{}, "a beam line load without a direction");
    if (load.face == 0) return scale(li.magnitude, load.direction);
    return scale(li.magnitude, li.g.pts[p].L0[load.face]);
  }
  // GRAV weighs the added mass (*BEAM ADDED INERTIA) too, on the beam's axis
  const bool added_weight = load.kind == DistLoadKind::Gravity && li.b.added.m > 0.0;
  double w = added_weight ? li.b.added.m * li.magnitude : 0.0;
  if (!added_weight || !li.b.material.density.empty())
    w += line_load_intensity(li.b.material, li.b.section.A, load, li.magnitude,
                             average(li.in.temperature), li.in.label);
  return scale(w, load.direction);
}

namespace {

/// Strains of the fibre at section point k: axial eps + kappa_1 x2 - kappa_2 x1 (total e11 and
/// initial e0; docs/theory/structural.md §3.5) and the engineering shear strain of the twist.
struct Fibre {
  double e11 = 0.0, e0 = 0.0, e12 = 0.0, r = 0.0;
};
Fibre fibre(const BeamOutput& o, const Strains<double>& e, int k) {
  const double x1 = o.section.points[k][0], x2 = o.section.points[k][1];
  return {e[0] + e[3] * x2 - e[4] * x1, o.initial[0] + o.initial[3] * x2 - o.initial[4] * x1,
          e[5] * o.section.torsion_radius[k], std::hypot(x1, x2)};
}

/// Pipes: S11 axial E eps + nu (sigma_r + sigma_theta), S22 hoop (Lame, at the section point's
/// radius), S12 torsional shear; E22 the hoop strain (S22 - nu (S11 + sigma_r)) / E + eps_th.
void recover_pipe_points(const BeamOutput& o, std::span<const Strains<double>> e,
                         ElementRecovery& out) {
  const BeamSectionProperties& sec = o.section;
  const int np = static_cast<int>(e.size());
  add_block(out, ElemVar::S, kPipeS, np * sec.n_points);
  add_block(out, ElemVar::E, kPipeE, np * sec.n_points);
  OutputBlock& S = out.blocks[out.blocks.size() - 2];
  OutputBlock& E = out.blocks.back();
  S.section_points = E.section_points = sec.n_points;
  for (int p = 0; p < np; ++p)
    for (int k = 0; k < sec.n_points; ++k) {
      const auto [e11, e0, e12, r] = fibre(o, e[p], k);
      const double hoop = pipe_hoop_at(sec, o.pressure, r);
      const PointStress* at = o.points.empty() ? nullptr : &o.points[p * sec.n_points + k];
      const double s11 = at ? at->s11 + o.nu * pipe_lame_sum(sec, o.pressure)
                            : o.E * (e11 - e0) + o.nu * pipe_lame_sum(sec, o.pressure);
      const int row = 3 * (p * sec.n_points + k);
      S.values[row] = s11;
      S.values[row + 1] = hoop;
      S.values[row + 2] = at ? at->s12 : o.G * e12;
      E.values[row] = e11;
      E.values[row + 1] =
          (hoop - o.nu * (s11 + pipe_radial_at(sec, o.pressure, r))) / o.E + o.initial[0];
      E.values[row + 2] = e12;
    }
}

} // namespace

void recover_beam_output(const BeamOutput& o, std::span<const Strains<double>> e,
                         ElementRecovery& out) {
  const int np = static_cast<int>(e.size());
  static constexpr int kPlanarSF[3] = {0, 1, 3};
  OutputBlock& sf = o.planar ? add_block(out, ElemVar::SF, kBeamSF2D, np)
                             : add_block(out, ElemVar::SF, kBeamSF, np);
  const int nsf = o.planar ? 3 : 6;
  for (int p = 0; p < np; ++p) {
    std::array<double, 6> s{};
    if (!o.forces.empty())
      s = o.forces[p];
    else
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) s[i] += o.D[6 * i + j] * (e[p][j] - o.initial[j]);
    for (int c = 0; c < nsf; ++c) sf.values[p * nsf + c] = s[o.planar ? kPlanarSF[c] : c];
  }
  const BeamSectionProperties& sec = o.section;
  if (o.pipe) // the wall's axial force includes its Poisson response to the hoop stress
    for (int p = 0; p < np; ++p)
      sf.values[p * nsf] += o.nu * sec.A * pipe_lame_sum(sec, o.pressure);
  if (sec.n_points == 0) return;
  if (o.pipe) return recover_pipe_points(o, e, out);
  // add both blocks before taking references: a second add_block may reallocate the first
  add_block(out, ElemVar::S, kBeamS, np * sec.n_points);
  add_block(out, ElemVar::E, kBeamE, np * sec.n_points);
  OutputBlock& S = out.blocks[out.blocks.size() - 2];
  OutputBlock& E = out.blocks.back();
  S.section_points = E.section_points = sec.n_points;
  for (int p = 0; p < np; ++p)
    for (int k = 0; k < sec.n_points; ++k) {
      const auto [e11, e0, e12, r] = fibre(o, e[p], k);
      const int row = p * sec.n_points + k;
      E.values[2 * row] = e11;
      E.values[2 * row + 1] = e12;
      if (!o.points.empty()) { // the integrated section: the law's stress there
        S.values[2 * row] = o.points[row].s11;
        S.values[2 * row + 1] = o.points[row].s12;
        continue;
      }
      S.values[2 * row] = o.E * (e11 - e0);
      S.values[2 * row + 1] = o.G * e12;
    }
}

} // namespace gapfem::beam
