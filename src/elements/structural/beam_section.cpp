#include "elements/structural/beam_section.hpp"

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace gapfem {

namespace {

// Transverse shear correction factors k (K = k G A) of Abaqus's library sections ("Transverse
// shear stiffness in beams", Abaqus Analysis User's Guide; Cowper (1966), J. Appl. Mech. 33:335,
// at nu = 0.3: rectangle 10(1+nu)/(12+11nu) = 0.85, solid circle 6(1+nu)/(7+6nu) = 0.89,
// thin-walled tube 2(1+nu)/(4+3nu) = 0.53; box and I 0.44; general sections 1.0).
constexpr double kShearRect = 0.85;
constexpr double kShearCirc = 0.89;
constexpr double kShearPipe = 0.53;
constexpr double kShearThinWall = 0.44;
constexpr double kShearGeneral = 1.0;

const char* shape_name(BeamSection::Shape s) {
  switch (s) {
  case BeamSection::Shape::Rect:
    return "RECT";
  case BeamSection::Shape::Circ:
    return "CIRC";
  case BeamSection::Shape::Pipe:
    return "PIPE";
  case BeamSection::Shape::Box:
    return "BOX";
  case BeamSection::Shape::I:
    return "I";
  case BeamSection::Shape::General:
    return "GENERAL";
  case BeamSection::Shape::Hex:
    return "HEX";
  case BeamSection::Shape::L:
    return "L";
  case BeamSection::Shape::Trapezoid:
    return "TRAPEZOID";
  }
  return "?";
}

using P2 = std::array<double, 2>;

/// Adds a straight thin wall from a to b of thickness t, integrated along its mid-line (its own
/// bending about the mid-line, t^3/12 per length, is neglected: Abaqus's thin-walled rule).
void add_wall(BeamSectionProperties& p, P2 a, P2 b, double t) {
  const double d1 = b[0] - a[0], d2 = b[1] - a[1];
  const double m = t * std::hypot(d1, d2); // mass of the wall per unit of x
  p.A += m;
  p.Q1 += m * (a[0] + 0.5 * d1);
  p.Q2 += m * (a[1] + 0.5 * d2);
  p.I22 += m * (a[0] * a[0] + a[0] * d1 + d1 * d1 / 3.0);
  p.I11 += m * (a[1] * a[1] + a[1] * d2 + d2 * d2 / 3.0);
  p.I12 += m * (a[0] * a[1] + 0.5 * (a[0] * d2 + a[1] * d1) + d1 * d2 / 3.0);
}

class Checker {
 public:
  explicit Checker(const BeamSection& s) : _s(s), _entity(fmt::format("ELSET={}", s.elset)) {}
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(_s.loc, _entity, fmt::format("SECTION={}: {}", shape_name(_s.shape), what));
  }
  /// Needs n dimensions; the ones from `first_positive` on must be positive.
  void need(std::size_t n, const char* names, std::size_t first_positive = 0) const {
    bool ok = _s.dims.size() >= n;
    for (std::size_t i = 0; ok && i < n; ++i)
      ok = std::isfinite(_s.dims[i]) && (i < first_positive || _s.dims[i] > 0.0);
    if (!ok) fail(fmt::format("give {} on the first data line (all positive)", names));
  }

 private:
  const BeamSection& _s;
  std::string _entity;
};

void solid_rect(BeamSectionProperties& p, double a, double b) {
  p.A = a * b;
  p.I11 = a * b * b * b / 12.0; // bending about axis 1: x2 spans b
  p.I22 = b * a * a * a / 12.0;
  p.J = rectangle_torsion_constant(a, b);
  p.k = kShearRect;
  const double c1 = 0.5 * a, c2 = 0.5 * b;
  p.n_points = 4;
  p.points = {{{c1, c2}, {-c1, c2}, {-c1, -c2}, {c1, -c2}}};
  p.torsion_radius = {0.0, 0.0, 0.0, 0.0};
}

void round(BeamSectionProperties& p, double r, double ri, double k) {
  const double pi = std::numbers::pi;
  const double r4 = std::pow(r, 4) - std::pow(ri, 4);
  p.A = pi * (r * r - ri * ri);
  p.I11 = p.I22 = pi * r4 / 4.0;
  p.J = pi * r4 / 2.0; // exact for the disc and the annulus, thin or thick
  p.k = k;
  p.n_points = 4;
  p.points = {{{r, 0.0}, {0.0, r}, {-r, 0.0}, {0.0, -r}}};
  p.torsion_radius = {r, r, r, r};
}

/// BOX a, b (outer), t1..t4 the walls at +x1, +x2, -x1, -x2 (Abaqus's numbering: right, top,
/// left, bottom), single closed cell: Bredt's J = 4 A_m^2 / sum(L_i / t_i).
void box(BeamSectionProperties& p, const Checker& c, const std::vector<double>& d) {
  c.need(6, "a, b, t1, t2, t3, t4");
  const double a = d[0], b = d[1], t1 = d[2], t2 = d[3], t3 = d[4], t4 = d[5];
  if (!(t1 + t3 < a))
    c.fail(fmt::format("the walls at +x1 and -x1 are thicker than the box is wide: t1 + t3 = {} "
                       "must be below a = {}",
                       t1 + t3, a));
  if (!(t2 + t4 < b))
    c.fail(fmt::format("the walls at +x2 and -x2 are thicker than the box is high: t2 + t4 = {} "
                       "must be below b = {}",
                       t2 + t4, b));
  const double xr = 0.5 * a - 0.5 * t1, xl = -0.5 * a + 0.5 * t3;
  const double yt = 0.5 * b - 0.5 * t2, yb = -0.5 * b + 0.5 * t4;
  add_wall(p, {xr, yb}, {xr, yt}, t1);
  add_wall(p, {xr, yt}, {xl, yt}, t2);
  add_wall(p, {xl, yt}, {xl, yb}, t3);
  add_wall(p, {xl, yb}, {xr, yb}, t4);
  const double w = xr - xl, h = yt - yb, Am = w * h;
  p.J = 4.0 * Am * Am / (h / t1 + w / t2 + h / t3 + w / t4);
  p.k = kShearThinWall;
  p.n_points = 4;
  p.points = {{{xr, yt}, {xl, yt}, {xl, yb}, {xr, yb}}};
  // closed thin wall: tau = T / (2 A_m t) = G J twist / (2 A_m t), at the thinner wall of a corner
  const double tc[4] = {std::min(t1, t2), std::min(t2, t3), std::min(t3, t4), std::min(t4, t1)};
  for (int i = 0; i < 4; ++i) p.torsion_radius[i] = p.J / (2.0 * Am * tc[i]);
}

/// I: l (origin above the bottom flange's lower surface), h (overall height), b1, b2 (bottom and
/// top flange widths), t1, t2 (their thicknesses), t3 (web); open: J = sum(L t^3) / 3.
void i_section(BeamSectionProperties& p, const Checker& c, const std::vector<double>& d) {
  c.need(7, "l, h, b1, b2, t1, t2, t3", 1);
  const double l = d[0], h = d[1], b1 = d[2], b2 = d[3], t1 = d[4], t2 = d[5], t3 = d[6];
  if (!(t1 + t2 < h))
    c.fail(fmt::format("the flanges (t1 + t2 = {}) must be thinner than the height h = {}", t1 + t2,
                       h));
  if (!(t3 <= b1 && t3 <= b2))
    c.fail(fmt::format("the web thickness t3 = {} exceeds a flange width (b1 = {}, b2 = {})", t3,
                       b1, b2));
  const double yb = -l + 0.5 * t1, yt = h - l - 0.5 * t2;
  add_wall(p, {-0.5 * b1, yb}, {0.5 * b1, yb}, t1);
  add_wall(p, {-0.5 * b2, yt}, {0.5 * b2, yt}, t2);
  add_wall(p, {0.0, yb}, {0.0, yt}, t3);
  p.J = (b1 * t1 * t1 * t1 + b2 * t2 * t2 * t2 + (yt - yb) * t3 * t3 * t3) / 3.0;
  p.k = kShearThinWall;
  p.n_points = 4;
  p.points = {{{0.5 * b2, yt}, {-0.5 * b2, yt}, {-0.5 * b1, yb}, {0.5 * b1, yb}}};
  // open thin wall: tau = G t twist at the wall surface
  p.torsion_radius = {t2, t2, t1, t1};
}

/// HEX: a regular hexagonal tube, r the outer radius (centre to a corner), t the wall thickness
/// (across a flat, t < r sqrt(3) / 2). Thin-walled like BOX: six walls on the mid-line hexagon,
/// whose corners lie at r_m = r - t / sqrt(3), corners on the local 1-axis; single closed cell:
/// Bredt's J = 4 A_m^2 t / (6 r_m). A regular hexagon bends alike about every axis (I11 = I22,
/// I12 = 0), so the corners' orientation matters only for the output points: the corners on
/// the 1-axis and the middles of the flats on the 2-axis.
void hex(BeamSectionProperties& p, const Checker& c, const std::vector<double>& d) {
  c.need(2, "the outer radius r and the wall thickness t");
  const double r = d[0], t = d[1], s3 = std::sqrt(3.0);
  if (!(t < 0.5 * s3 * r))
    c.fail(fmt::format("the wall thickness t = {} must be smaller than r sqrt(3) / 2 = {} (the "
                       "distance from the centre to a flat)",
                       t, 0.5 * s3 * r));
  const double rm = r - t / s3, am = 0.5 * s3 * rm; // mid-line corner radius and apothem
  const double pi = std::numbers::pi;
  for (int i = 0; i < 6; ++i) {
    const double a0 = i * pi / 3.0, a1 = (i + 1) * pi / 3.0;
    add_wall(p, {rm * std::cos(a0), rm * std::sin(a0)}, {rm * std::cos(a1), rm * std::sin(a1)}, t);
  }
  const double Am = 1.5 * s3 * rm * rm;
  p.J = 4.0 * Am * Am * t / (6.0 * rm);
  p.k = kShearPipe; // a thin closed tube, as PIPE
  p.n_points = 4;
  p.points = {{{rm, 0.0}, {0.0, am}, {-rm, 0.0}, {0.0, -am}}};
  const double tr = p.J / (2.0 * Am * t); // closed thin wall: tau = T / (2 A_m t)
  p.torsion_radius = {tr, tr, tr, tr};
}

/// L: a (leg along axis 1, thickness t1 across it), b (leg along axis 2, thickness t2), the legs
/// meeting at the outer corner; the origin is the centroid (Abaqus gives no offset for L). Thin
/// walled like I: the two legs on their mid-lines, from the mid-line corner to the tips (the area
/// a t1 + b t2 - t1 t2 is exact); open: J = sum(L t^3) / 3.
void l_section(BeamSectionProperties& p, const Checker& c, const std::vector<double>& d) {
  c.need(4, "a, b, t1, t2");
  const double a = d[0], b = d[1], t1 = d[2], t2 = d[3];
  if (!(t1 < b))
    c.fail(fmt::format("the leg along axis 1 is too thick: its thickness t1 = {} must be below "
                       "b = {}, the length of the other leg",
                       t1, b));
  if (!(t2 < a))
    c.fail(fmt::format("the leg along axis 2 is too thick: its thickness t2 = {} must be below "
                       "a = {}, the length of the other leg",
                       t2, a));
  const double la = a - 0.5 * t2, lb = b - 0.5 * t1; // mid-line lengths of the legs
  const double area = t1 * la + t2 * lb;
  // centroid from the outer corner (the corner of the mid-lines is at (t2/2, t1/2))
  const double c1 = (t1 * la * (0.5 * t2 + 0.5 * la) + t2 * lb * 0.5 * t2) / area;
  const double c2 = (t1 * la * 0.5 * t1 + t2 * lb * (0.5 * t1 + 0.5 * lb)) / area;
  const P2 corner{0.5 * t2 - c1, 0.5 * t1 - c2};
  add_wall(p, corner, {a - c1, corner[1]}, t1);
  add_wall(p, corner, {corner[0], b - c2}, t2);
  p.J = (la * t1 * t1 * t1 + lb * t2 * t2 * t2) / 3.0;
  p.k = kShearThinWall;
  // the leg tips and the outer corner, on the outer faces
  p.n_points = 3;
  p.points = {{{a - c1, -c2}, {-c1, -c2}, {-c1, b - c2}}};
  p.torsion_radius = {t1, std::max(t1, t2), t2};
}

/// TRAPEZOID: a (bottom width), b (height), c (top width), d (the origin's height above the
/// bottom), symmetric about axis 2. A solid polygon: A, Q and I exact; J from Prandtl's stress
/// function (trapezoid_torsion_constant).
void trapezoid(BeamSectionProperties& p, const Checker& c, const std::vector<double>& d) {
  c.need(4, "a, b, c, d", 4);
  const double a = d[0], b = d[1], top = d[2], off = d[3];
  if (!(a > 0.0) || !(b > 0.0) || !(top >= 0.0))
    c.fail(fmt::format("the widths a and c and the height b must be positive (c may be 0 for a "
                       "triangle), not a = {}, b = {}, c = {}",
                       a, b, top));
  // corners counter-clockwise: bottom right, top right, top left, bottom left
  const P2 v[4] = {{0.5 * a, -off}, {0.5 * top, b - off}, {-0.5 * top, b - off}, {-0.5 * a, -off}};
  for (int i = 0; i < 4; ++i) { // polygon (Green's theorem) integrals
    const P2 &p0 = v[i], &p1 = v[(i + 1) % 4];
    const double x0 = p0[0], y0 = p0[1], x1 = p1[0], y1 = p1[1];
    const double cr = x0 * y1 - x1 * y0;
    p.A += 0.5 * cr;
    p.Q1 += cr * (x0 + x1) / 6.0;
    p.Q2 += cr * (y0 + y1) / 6.0;
    p.I11 += cr * (y0 * y0 + y0 * y1 + y1 * y1) / 12.0;
    p.I22 += cr * (x0 * x0 + x0 * x1 + x1 * x1) / 12.0;
    p.I12 += cr * (x0 * y1 + 2.0 * x0 * y0 + 2.0 * x1 * y1 + x1 * y0) / 24.0;
  }
  p.J = trapezoid_torsion_constant(a, b, top);
  p.k = kShearRect;
  p.n_points = 4; // the corners (no torsional shear at a convex corner)
  p.points = {{v[1], v[2], v[3], v[0]}};
  p.torsion_radius = {0.0, 0.0, 0.0, 0.0};
}

void general(BeamSectionProperties& p, const Checker& c, const std::vector<double>& d,
             bool planar) {
  c.need(2, "A, I11, I12, I22, J (A and I11 at least)");
  p.A = d[0];
  p.I11 = d[1];
  p.I12 = d.size() > 2 ? d[2] : 0.0;
  p.I22 = d.size() > 3 ? d[3] : 0.0;
  p.J = d.size() > 4 ? d[4] : 0.0;
  p.k = kShearGeneral;
  p.n_points = 0;
  if (planar) {
    if (!(p.A > 0.0) || !(p.I11 > 0.0)) c.fail("A and I11 must be positive");
    p.I12 = 0.0; // out-of-plane properties play no part in a planar beam
    return;
  }
  if (!(p.I22 > 0.0) || !(p.J > 0.0) || !std::isfinite(p.I12))
    c.fail(fmt::format("a beam in space needs I22 > 0 and J > 0 (fields 4 and 5), not I22 = {} "
                       "and J = {}",
                       p.I22, p.J));
  if (!(p.I11 * p.I22 - p.I12 * p.I12 > 0.0))
    c.fail(fmt::format("I11 I22 - I12^2 = {} must be positive (the bending stiffness would not be)",
                       p.I11 * p.I22 - p.I12 * p.I12));
}

} // namespace

double rectangle_torsion_constant(double a, double b) {
  // St. Venant torsion of a rectangle with long side a >= short side b:
  //   J = a b^3 / 3 * [1 - (192 / pi^5) (b / a) sum_{n odd} tanh(n pi a / (2 b)) / n^5].
  // The series converges like n^-5; 50 odd terms are far below double precision.
  if (a < b) std::swap(a, b);
  const double pi = std::numbers::pi;
  double sum = 0.0;
  for (int n = 1; n < 100; n += 2)
    sum += std::tanh(n * pi * a / (2.0 * b)) / std::pow(static_cast<double>(n), 5);
  return a * b * b * b / 3.0 * (1.0 - 192.0 / std::pow(pi, 5) * (b / a) * sum);
}

double trapezoid_torsion_constant(double a, double b, double c) {
  // Prandtl: laplace(phi) = -2 in the section, phi = 0 on its boundary, J = 2 * integral(phi).
  // Bilinear elements on the trapezoid mapped from the unit square (x2 = eta b, half width
  // w(eta) = (a + (c - a) eta) / 2); J from two meshes, Richardson-extrapolated (error O(h^4)).
  auto solve = [&](int n) {
    const int nn = n + 1;
    auto id = [&](int i, int j) { return j * nn + i; };
    auto at = [&](double xi, double eta) -> P2 {
      return {(2.0 * xi - 1.0) * 0.5 * (a + (c - a) * eta), eta * b};
    };
    std::vector<Eigen::Triplet<double>> trip;
    Eigen::VectorXd f = Eigen::VectorXd::Zero(nn * nn);
    const double g = 1.0 / std::sqrt(3.0);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int nodes[4] = {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)};
        P2 x[4];
        const double s[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (int k = 0; k < 4; ++k) x[k] = at((i + s[k][0]) / n, (j + s[k][1]) / n);
        double ke[4][4] = {}, fe[4] = {};
        for (double gr : {-g, g})
          for (double gs : {-g, g}) {
            const double r = gr, t = gs;
            const double N[4] = {0.25 * (1 - r) * (1 - t), 0.25 * (1 + r) * (1 - t),
                                 0.25 * (1 + r) * (1 + t), 0.25 * (1 - r) * (1 + t)};
            const double dr[4] = {-0.25 * (1 - t), 0.25 * (1 - t), 0.25 * (1 + t), -0.25 * (1 + t)};
            const double ds[4] = {-0.25 * (1 - r), -0.25 * (1 + r), 0.25 * (1 + r), 0.25 * (1 - r)};
            double J11 = 0, J12 = 0, J21 = 0, J22 = 0;
            for (int k = 0; k < 4; ++k) {
              J11 += dr[k] * x[k][0];
              J12 += dr[k] * x[k][1];
              J21 += ds[k] * x[k][0];
              J22 += ds[k] * x[k][1];
            }
            const double det = J11 * J22 - J12 * J21;
            if (!(det > 0.0)) continue; // the collapsed apex of a triangle
            double gx[4], gy[4];
            for (int k = 0; k < 4; ++k) {
              gx[k] = (J22 * dr[k] - J12 * ds[k]) / det;
              gy[k] = (-J21 * dr[k] + J11 * ds[k]) / det;
            }
            for (int k = 0; k < 4; ++k) {
              fe[k] += 2.0 * N[k] * det;
              for (int l = 0; l < 4; ++l) ke[k][l] += (gx[k] * gx[l] + gy[k] * gy[l]) * det;
            }
          }
        for (int k = 0; k < 4; ++k) {
          f[nodes[k]] += fe[k];
          for (int l = 0; l < 4; ++l) trip.emplace_back(nodes[k], nodes[l], ke[k][l]);
        }
      }
    // phi = 0 on the boundary: unit rows for the boundary nodes
    std::vector<char> boundary(static_cast<std::size_t>(nn * nn), 0);
    for (int k = 0; k < nn; ++k)
      boundary[id(k, 0)] = boundary[id(k, n)] = boundary[id(0, k)] = boundary[id(n, k)] = 1;
    std::vector<Eigen::Triplet<double>> kept;
    for (const auto& t : trip)
      if (!boundary[t.row()] && !boundary[t.col()]) kept.push_back(t);
    Eigen::VectorXd rhs = f;
    for (int k = 0; k < nn * nn; ++k)
      if (boundary[k]) {
        kept.emplace_back(k, k, 1.0);
        rhs[k] = 0.0;
      }
    Eigen::SparseMatrix<double> K(nn * nn, nn * nn);
    K.setFromTriplets(kept.begin(), kept.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(K);
    const Eigen::VectorXd phi = ldlt.solve(rhs);
    return f.dot(phi); // f = integral(2 N): f . phi = 2 integral(phi) = J
  };
  const double coarse = solve(40), fine = solve(80);
  return (4.0 * fine - coarse) / 3.0;
}

BeamSectionProperties beam_section_properties(const BeamSection& section, bool planar) {
  const Checker c(section);
  const auto& d = section.dims;
  BeamSectionProperties p;
  switch (section.shape) {
  case BeamSection::Shape::Rect:
    c.need(2, "the width a (local 1-direction) and the height b (local 2-direction)");
    solid_rect(p, d[0], d[1]);
    break;
  case BeamSection::Shape::Circ:
    c.need(1, "the radius r");
    round(p, d[0], 0.0, kShearCirc);
    break;
  case BeamSection::Shape::Pipe:
    c.need(2, "the outer radius r and the wall thickness t");
    if (!(d[1] < d[0]))
      c.fail(fmt::format("the wall thickness t = {} must be smaller than the outer radius r = {} "
                         "(use SECTION=CIRC for a solid circle)",
                         d[1], d[0]));
    round(p, d[0], d[0] - d[1], kShearPipe);
    p.r_outer = d[0];
    p.r_inner = d[0] - d[1];
    break;
  case BeamSection::Shape::Box:
    box(p, c, d);
    break;
  case BeamSection::Shape::I:
    i_section(p, c, d);
    break;
  case BeamSection::Shape::General:
    general(p, c, d, planar);
    break;
  case BeamSection::Shape::Hex:
    hex(p, c, d);
    break;
  case BeamSection::Shape::L:
    l_section(p, c, d);
    break;
  case BeamSection::Shape::Trapezoid:
    trapezoid(p, c, d);
    break;
  }
  if (!section.output_points.empty()) {
    // *SECTION POINTS: the axial stress and strain there; the torsional shear at an arbitrary
    // point of a general section is not known, so S12 is not reported (0)
    if (section.output_points.size() > static_cast<std::size_t>(BeamSectionProperties::kMaxPoints))
      c.fail(fmt::format("*SECTION POINTS gives {} points; gapfem reports at most {}",
                         section.output_points.size(), BeamSectionProperties::kMaxPoints));
    p.n_points = static_cast<int>(section.output_points.size());
    p.points = {};
    p.torsion_radius = {};
    for (int k = 0; k < p.n_points; ++k) p.points[k] = section.output_points[k];
  }
  p.k23 = section.k23;
  p.k13 = section.k13;
  return p;
}

} // namespace gapfem
