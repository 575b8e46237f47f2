#include "elements/structural/beam_section.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

namespace gapfem {

namespace {

// Transverse shear correction factors k (K = k G A) that Abaqus uses for its library sections
// ("Beam section behavior: transverse shear stiffness", Abaqus Analysis User's Guide; Abaqus adopts
// Cowper (1966), J. Appl. Mech. 33:335, evaluated at nu = 0.3: rectangle 10(1+nu)/(12+11nu) = 0.85,
// solid circle 6(1+nu)/(7+6nu) = 0.89, thin-walled tube 2(1+nu)/(4+3nu) = 0.53). Values as listed
// for RECT/CIRC/PIPE in the Abaqus documentation and in public Abaqus-preprocessing code tables.
constexpr double kShearRect = 0.85;
constexpr double kShearCirc = 0.89;
constexpr double kShearPipe = 0.53;

const char* shape_name(BeamSection::Shape s) {
  switch (s) {
  case BeamSection::Shape::Rect:
    return "RECT";
  case BeamSection::Shape::Circ:
    return "CIRC";
  case BeamSection::Shape::Pipe:
    return "PIPE";
  }
  return "?";
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

BeamSectionProperties beam_section_properties(const BeamSection& section) {
  const std::string entity = fmt::format("*BEAM SECTION, ELSET={}", section.elset);
  const char* shape = shape_name(section.shape);
  const auto& d = section.dims;
  auto need = [&](std::size_t n, const char* what) {
    bool ok = d.size() >= n;
    for (std::size_t i = 0; ok && i < n; ++i) ok = d[i] > 0.0 && std::isfinite(d[i]);
    if (!ok)
      throw InputError(
          section.loc, entity,
          fmt::format("SECTION={} needs {} (all positive) on the first data line", shape, what));
  };
  const double pi = std::numbers::pi;
  BeamSectionProperties p;
  switch (section.shape) {
  case BeamSection::Shape::Rect: {
    need(2, "the width a (local 1-direction) and the height b (local 2-direction)");
    const double a = d[0], b = d[1];
    p.A = a * b;
    p.I11 = a * b * b * b / 12.0; // bending about axis 1: x2 spans b
    p.I22 = b * a * a * a / 12.0;
    p.J = rectangle_torsion_constant(a, b);
    p.k = kShearRect;
    const double c1 = 0.5 * a, c2 = 0.5 * b;
    p.points = {{{c1, c2}, {-c1, c2}, {-c1, -c2}, {c1, -c2}}};
    p.torsion_radius = {0.0, 0.0, 0.0, 0.0};
    break;
  }
  case BeamSection::Shape::Circ: {
    need(1, "the radius r");
    const double r = d[0];
    p.A = pi * r * r;
    p.I11 = p.I22 = pi * std::pow(r, 4) / 4.0;
    p.J = pi * std::pow(r, 4) / 2.0;
    p.k = kShearCirc;
    p.points = {{{r, 0.0}, {0.0, r}, {-r, 0.0}, {0.0, -r}}};
    p.torsion_radius = {r, r, r, r};
    break;
  }
  case BeamSection::Shape::Pipe: {
    need(2, "the outer radius r and the wall thickness t");
    const double r = d[0], t = d[1];
    if (t > r)
      throw InputError(section.loc, entity,
                       fmt::format("the PIPE wall thickness {} exceeds the outer radius {}; give "
                                   "t <= r",
                                   t, r));
    const double ri = r - t;
    const double r4 = std::pow(r, 4) - std::pow(ri, 4);
    p.A = pi * (r * r - ri * ri);
    p.I11 = p.I22 = pi * r4 / 4.0;
    p.J = pi * r4 / 2.0; // exact for the annulus, thin or thick
    p.k = kShearPipe;
    p.points = {{{r, 0.0}, {0.0, r}, {-r, 0.0}, {0.0, -r}}};
    p.torsion_radius = {r, r, r, r};
    break;
  }
  }
  return p;
}

} // namespace gapfem
