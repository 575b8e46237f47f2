// Section integration points of the beams and their update through the solid law
// (beam_fibres.hpp).
#include "elements/structural/beam_fibres.hpp"

#include "elements/structural/structural_common.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace gapfem::beam {

namespace {

using P2 = std::array<double, 2>;

/// Composite Simpson on [0, 1] with four panels: exact for cubics, and for |x| kinked at a point.
constexpr std::array<double, 5> kSimpsonAt{0.0, 0.25, 0.5, 0.75, 1.0};
constexpr std::array<double, 5> kSimpsonW{1.0 / 12, 4.0 / 12, 2.0 / 12, 4.0 / 12, 1.0 / 12};
constexpr int kAngles = 16; ///< CIRC and PIPE: equally spaced angles from 0 (0/90/180/270 among)

/// A straight thin wall from a to b of thickness t: Simpson along its mid-line with weight t ds
/// (beam_section.cpp's add_wall integrates the same quadratics exactly).
void wall(std::vector<BeamFibre>& f, P2 a, P2 b, double t) {
  const double d1 = b[0] - a[0], d2 = b[1] - a[1], m = t * std::hypot(d1, d2);
  for (int k = 0; k < 5; ++k)
    f.push_back({a[0] + kSimpsonAt[k] * d1, a[1] + kSimpsonAt[k] * d2, m * kSimpsonW[k]});
}

void rect(std::vector<BeamFibre>& f, double a, double b) {
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 5; ++i)
      f.push_back({a * (kSimpsonAt[i] - 0.5), b * (kSimpsonAt[j] - 0.5),
                   a * b * kSimpsonW[i] * kSimpsonW[j]});
}

/// Rings at the radii of Gauss-Lobatto 3 on [ri, r] (ri, the middle, r; weights 1/6, 4/6, 1/6 of
/// the width): exact for the r and r^3 of A and I; x kAngles angles (exact for cos^2, sin cos).
/// A ring at radius 0 has no weight and is left out.
void circle(std::vector<BeamFibre>& f, double r, double ri) {
  const double h = r - ri, radii[3] = {ri, 0.5 * (ri + r), r};
  const double wr[3] = {h / 6.0, 4.0 * h / 6.0, h / 6.0};
  const double dtheta = 2.0 * std::numbers::pi / kAngles;
  for (int k = 0; k < 3; ++k) {
    if (!(radii[k] > 0.0)) continue;
    for (int j = 0; j < kAngles; ++j) {
      // the quarter angles exactly: cos(pi/2) would leave 6e-17 where the output point has 0
      const int q = j % (kAngles / 4);
      const double c =
          q == 0 ? std::array{1.0, 0.0, -1.0, 0.0}[j / (kAngles / 4)] : std::cos(j * dtheta);
      const double s =
          q == 0 ? std::array{0.0, 1.0, 0.0, -1.0}[j / (kAngles / 4)] : std::sin(j * dtheta);
      f.push_back({radii[k] * c, radii[k] * s, wr[k] * radii[k] * dtheta});
    }
  }
}

/// TRAPEZOID a (bottom), b (height), c (top), d (origin above the bottom): the square
/// [-1, 1] x [0, 1] mapped by x2 = eta b - d, x1 = xi h(eta), h the half width (linear in eta);
/// Simpson 5 x 5 there. The weight h b dxi deta makes I22's integrand xi^2 h^3 cubic in eta.
void trapezoid(std::vector<BeamFibre>& f, double a, double b, double c, double d) {
  for (int j = 0; j < 5; ++j) {
    const double eta = kSimpsonAt[j], h = 0.5 * (a + (c - a) * eta);
    for (int i = 0; i < 5; ++i) {
      const double xi = 2.0 * kSimpsonAt[i] - 1.0;
      f.push_back({xi * h, eta * b - d, 2.0 * kSimpsonW[i] * kSimpsonW[j] * h * b});
    }
  }
}

// The thin-walled shapes: the mid-lines of beam_section.cpp's box(), i_section(), hex() and
// l_section(), in the same order (the reproduction test keeps the two files together).

void box(std::vector<BeamFibre>& f, const std::vector<double>& d) {
  const double a = d[0], b = d[1], t1 = d[2], t2 = d[3], t3 = d[4], t4 = d[5];
  const double xr = 0.5 * a - 0.5 * t1, xl = -0.5 * a + 0.5 * t3;
  const double yt = 0.5 * b - 0.5 * t2, yb = -0.5 * b + 0.5 * t4;
  wall(f, {xr, yb}, {xr, yt}, t1);
  wall(f, {xr, yt}, {xl, yt}, t2);
  wall(f, {xl, yt}, {xl, yb}, t3);
  wall(f, {xl, yb}, {xr, yb}, t4);
}

void i_section(std::vector<BeamFibre>& f, const std::vector<double>& d) {
  const double l = d[0], h = d[1], b1 = d[2], b2 = d[3], t1 = d[4], t2 = d[5], t3 = d[6];
  const double yb = -l + 0.5 * t1, yt = h - l - 0.5 * t2;
  wall(f, {-0.5 * b1, yb}, {0.5 * b1, yb}, t1);
  wall(f, {-0.5 * b2, yt}, {0.5 * b2, yt}, t2);
  wall(f, {0.0, yb}, {0.0, yt}, t3);
}

void hex(std::vector<BeamFibre>& f, const std::vector<double>& d) {
  const double r = d[0], t = d[1], rm = r - t / std::sqrt(3.0), pi = std::numbers::pi;
  for (int i = 0; i < 6; ++i) {
    const double a0 = i * pi / 3.0, a1 = (i + 1) * pi / 3.0;
    wall(f, {rm * std::cos(a0), rm * std::sin(a0)}, {rm * std::cos(a1), rm * std::sin(a1)}, t);
  }
}

void l_section(std::vector<BeamFibre>& f, const std::vector<double>& d) {
  const double a = d[0], b = d[1], t1 = d[2], t2 = d[3];
  const double la = a - 0.5 * t2, lb = b - 0.5 * t1;
  const double area = t1 * la + t2 * lb;
  const double c1 = (t1 * la * (0.5 * t2 + 0.5 * la) + t2 * lb * 0.5 * t2) / area;
  const double c2 = (t1 * la * 0.5 * t1 + t2 * lb * (0.5 * t1 + 0.5 * lb)) / area;
  const P2 corner{0.5 * t2 - c1, 0.5 * t1 - c2};
  wall(f, corner, {a - c1, corner[1]}, t1);
  wall(f, corner, {corner[0], b - c2}, t2);
}

} // namespace

int BeamFibres::nearest(double x1, double x2) const {
  int best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (int k = 0; k < size(); ++k) {
    const double d = std::hypot(fibres[k].x1 - x1, fibres[k].x2 - x2);
    if (d < best_d) best = k, best_d = d;
  }
  return best;
}

BeamFibres beam_section_fibres(const BeamSection& section, const BeamSectionProperties& props) {
  BeamFibres out;
  auto& f = out.fibres;
  const auto& d = section.dims;
  switch (section.shape) {
  case BeamSection::Shape::Rect:
    rect(f, d[0], d[1]);
    break;
  case BeamSection::Shape::Circ:
    circle(f, d[0], 0.0);
    break;
  case BeamSection::Shape::Pipe:
    circle(f, d[0], d[0] - d[1]);
    break;
  case BeamSection::Shape::Trapezoid:
    trapezoid(f, d[0], d[1], d[2], d[3]);
    break;
  case BeamSection::Shape::Box:
    box(f, d);
    break;
  case BeamSection::Shape::I:
    i_section(f, d);
    break;
  case BeamSection::Shape::Hex:
    hex(f, d);
    break;
  case BeamSection::Shape::L:
    l_section(f, d);
    break;
  case BeamSection::Shape::General:
    throw InternalError("beam_section_fibres: a GENERAL section is pre-integrated");
  }
  const double Ip = props.I11 + props.I22;
  out.torsion = Ip > 0.0 ? std::sqrt(props.J / Ip) : 0.0;
  return out;
}

SectionTemperature SectionTemperature::of(const ElementInput& in) {
  SectionTemperature t;
  t.thermal = !in.temperature.empty();
  const double Ti =
      in.initial_temperature.empty() ? 0.0 : *structural::average(in.initial_temperature);
  if (!t.thermal) {
    t.T = t.Ti = Ti;
    return t;
  }
  t.T = *structural::average(in.temperature);
  t.Ti = in.initial_temperature.empty() ? t.T : Ti; // as element_thermal_strain()
  const std::size_t nn = in.temperature_gradient.size() / 2;
  for (std::size_t a = 0; a < nn; ++a) { // values 2, 3 of *TEMPERATURE: dT/dx2, dT/dx1
    t.g2 += in.temperature_gradient[2 * a] / static_cast<double>(nn);
    t.g1 += in.temperature_gradient[2 * a + 1] / static_cast<double>(nn);
  }
  return t;
}

namespace {

/// The fibre's strain-displacement rows B (3 x 6) in the section strains: eps11 = e0 + x2 e3 -
/// x1 e4, gamma12 = -c x2 e5, gamma13 = c x1 e5.
std::array<std::array<double, 6>, 3> fibre_b(const BeamFibre& f, double c) {
  return {{{1.0, 0.0, 0.0, f.x2, -f.x1, 0.0},
           {0.0, 0.0, 0.0, 0.0, 0.0, -c * f.x2},
           {0.0, 0.0, 0.0, 0.0, 0.0, c * f.x1}}};
}

/// One law update at (x1, x2) for the section strains e; D the 3 x 3 tangent when wanted.
void update_at(const FibreSection& s, const Strains<double>& e, double x1, double x2,
               std::span<const double> start, std::span<double> trial, std::array<double, 3>& sig,
               std::array<double, 9>* D, bool recovery = false) {
  const double c = s.fibres.torsion;
  const std::array<double, 3> eps{e[0] + e[3] * x2 - e[4] * x1, -c * x2 * e[5], c * x1 * e[5]};
  MaterialPointInput mi;
  mi.strain = eps;
  mi.state_start = start;
  mi.temperature = s.temperature.at(x1, x2);
  mi.initial_temperature = s.temperature.Ti;
  mi.thermal = s.temperature.thermal;
  mi.dt = s.dt;
  mi.nlgeom = s.nlgeom;
  mi.recovery = recovery;
  MaterialPointOutput mo;
  mo.stress = sig;
  mo.state = trial;
  if (D) mo.tangent = *D;
  s.law.update(mi, mo);
  if (D && mo.isotropic) // lambda + 2 mu on the normal (= E for a fibre), mu on the shears
    *D = {mo.moduli.lambda + 2.0 * mo.moduli.mu,
          0.0,
          0.0,
          0.0,
          mo.moduli.mu,
          0.0,
          0.0,
          0.0,
          mo.moduli.mu};
}

} // namespace

void integrate_fibres(const FibreSection& s, const Strains<double>& e,
                      std::span<const double> start, std::span<double> trial, bool tangent,
                      SectionResponse& out) {
  out = {};
  const auto ns = static_cast<std::size_t>(s.law.n_state());
  FE_CHECK(start.size() >= ns * s.fibres.fibres.size() &&
               trial.size() >= ns * s.fibres.fibres.size(),
           "beam fibres: the element's history arrays are too short");
  for (std::size_t k = 0; k < s.fibres.fibres.size(); ++k) {
    const BeamFibre& f = s.fibres.fibres[k];
    std::array<double, 3> sig{};
    std::array<double, 9> D{};
    update_at(s, e, f.x1, f.x2, start.subspan(k * ns, ns), trial.subspan(k * ns, ns), sig,
              tangent ? &D : nullptr);
    const auto B = fibre_b(f, s.fibres.torsion);
    for (int i = 0; i < 6; ++i)
      for (int a = 0; a < 3; ++a) out.R[i] += f.w * B[a][i] * sig[a];
    if (!tangent) continue;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < a; ++b) out.symmetric = out.symmetric && D[3 * a + b] == D[3 * b + a];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        if (D[3 * a + b] == 0.0) continue;
        const double wd = f.w * D[3 * a + b];
        for (int i = 0; i < 6; ++i)
          for (int j = 0; j < 6; ++j) out.C[6 * i + j] += wd * B[a][i] * B[b][j];
      }
  }
}

PointStress fibre_point_stress(const FibreSection& s, const Strains<double>& e, double x1,
                               double x2, double rt, std::span<const double> start) {
  std::vector<double> scratch(static_cast<std::size_t>(s.law.n_state())); // never the history
  std::array<double, 3> sig{};
  update_at(s, e, x1, x2, start, scratch, sig, nullptr, true);
  PointStress p;
  p.e11 = e[0] + e[3] * x2 - e[4] * x1;
  p.e12 = rt * e[5];
  p.s11 = sig[0];
  // the shear along the fibre's circle, tau_t = (-x2 s12 + x1 s13) / r, scaled to rt / (c r)
  const double cr2 = s.fibres.torsion * (x1 * x1 + x2 * x2);
  p.s12 = cr2 > 0.0 ? (-x2 * sig[1] + x1 * sig[2]) * rt / cr2 : 0.0;
  return p;
}

} // namespace gapfem::beam
