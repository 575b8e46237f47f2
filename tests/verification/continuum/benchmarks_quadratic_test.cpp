// Published benchmarks of the quadratic plane elements (issue 13); the measured numbers are in
// docs/verification.md.
// - Cook's membrane (Cook, Concepts and Applications of FEA): the tapered panel (0,0), (48,44),
//   (48,60), (0,44), plane stress, E = 1, nu = 1/3, thickness 1, clamped at x = 0, a total shear
//   force 1 along the right edge (uniform traction: consistent Line3 forces 1/6, 4/6, 1/6 per
//   edge). CPS8, CPS8R and CPS6 (each quadrilateral split in two) on n x n meshes converge from
//   below to the same tip deflection v(48, 60) = 25.1 (CalculiX on the same deck: 25.06).
// - NAFEMS LE10, thick elliptic plate, sigma_yy at D with C3D20R (within 5%).
// - NAFEMS LE1, elliptic membrane: quarter of the region between the ellipses (x/2)^2 + y^2 = 1 and
//   (x/3.25)^2 + (y/2.75)^2 = 1, plane stress, E = 210 GPa, nu = 0.3, thickness 0.1, normal outward
//   pressure 10 MPa on the outer edge, symmetry on x = 0 and y = 0. Target sigma_yy at D = (2, 0):
//   92.7 MPa. CPS8R and CPS8 on a mapped mesh (angle x radius), sigma_yy at D extrapolated from the
//   integration points of the element at D with the element's own rule (bilinear from 2 x 2 for
//   CPS8R, the 3 x 3 Lagrange interpolant for CPS8): CPS8 within 1% at 24 x 8 elements, CPS8R
//   rising to within 1.5% at 48 x 16; CPS4I (corner nodes of the same grid) within 1% at 48 x 16.
#include "quadratic_mesh.hpp"
#include "test_util.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <map>

using namespace gapfem;
using namespace gapfem::test;

namespace {

const double kPi = std::acos(-1.0);

/// CPS6: each Quad8 split along its (s, t) diagonal from corner 1 to 3 into two Tri6.
std::string split_tri6(const QuadMesh2D& m, const std::string& elset) {
  std::string out = "*ELEMENT, TYPE=CPS6, ELSET=" + elset + "\n";
  int e = 1;
  for (int j = 0; j < m.ny; ++j)
    for (int i = 0; i < m.nx; ++i) {
      const int I = 2 * i, J = 2 * j;
      // the diagonal's midpoint is the quadrilateral's centre node (not a Quad8 node)
      const int c = m.label(I + 1, J + 1);
      out += fmt::format("{}, {}, {}, {}, {}, {}, {}\n", e++, m.label(I, J), m.label(I + 2, J),
                         m.label(I + 2, J + 2), m.label(I + 1, J), m.label(I + 2, J + 1), c);
      out += fmt::format("{}, {}, {}, {}, {}, {}, {}\n", e++, m.label(I, J), m.label(I + 2, J + 2),
                         m.label(I, J + 2), c, m.label(I + 1, J + 2), m.label(I, J + 1));
    }
  return out;
}

/// Tip deflection of Cook's membrane with an n x n mesh of `type`.
double cook(const std::string& type, int n) {
  QuadMesh2D m{n, n};
  auto map = [](double s, double t) {
    // bilinear map of (0,0), (48,44), (48,60), (0,44)
    const double x = 48.0 * s;
    const double y =
        (1 - s) * (1 - t) * 0.0 + s * (1 - t) * 44.0 + s * t * 60.0 + (1 - s) * t * 44.0;
    return std::array<double, 2>{x, y};
  };
  std::string d = "*HEADING\nCook's membrane " + type + "\n";
  if (type == "CPS6") {
    // all grid points, the quadrilaterals' centres included
    d += "*NODE\n";
    for (int j = 0; j <= 2 * n; ++j)
      for (int i = 0; i <= 2 * n; ++i) {
        const auto p = map(i / (2.0 * n), j / (2.0 * n));
        d += fmt::format("{}, {:.17g}, {:.17g}\n", m.label(i, j), p[0], p[1]);
      }
    d += split_tri6(m, "ALL");
  } else {
    d += m.nodes(map) + m.elements(type, "ALL");
  }
  d += "*MATERIAL, NAME=M\n*ELASTIC\n1., 0.333333333333333333\n*SOLID SECTION, ELSET=ALL, "
       "MATERIAL=M\n1.\n" +
       nset("CLAMP", m.line_i(0)) + "*STEP\n*STATIC\n*BOUNDARY\nCLAMP, 1, 2\n*CLOAD\n";
  // right edge: n edges of force 1 / n each, 1/6, 4/6, 1/6 at their nodes
  std::map<int, double> f;
  for (int j = 0; j < n; ++j) {
    f[m.label(2 * n, 2 * j)] += 1.0 / (6.0 * n);
    f[m.label(2 * n, 2 * j + 1)] += 4.0 / (6.0 * n);
    f[m.label(2 * n, 2 * j + 2)] += 1.0 / (6.0 * n);
  }
  for (auto [lbl, v] : f) d += fmt::format("{}, 2, {:.17g}\n", lbl, v);
  d += "*END STEP\n";
  const JobResult r = run_deck(d, false, fmt::format("cook_{}_{}", type, n));
  EXPECT_EQ(r.exit_code, 0) << r.error;
  if (r.exit_code != 0) return 0.0;
  return U(r, last_frame(r), m.label(2 * n, 2 * n))[1];
}

} // namespace

TEST(QuadraticBenchmarks, CooksMembraneConverges) {
  // measured v(C): CPS8 23.35, 24.54, 24.91, 25.06; CPS8R 23.83, 24.85, 25.06, 25.13; CPS6 22.54,
  // 24.32, 24.81, 25.02 (n = 2, 4, 8, 16). CalculiX on the same 16 x 16 CPS8 deck: 25.058. The
  // often quoted 23.96 is not reached by any element on this deck (CPS4 at 64 x 64: 25.04, rising),
  // see docs/verification.md; the test checks convergence and agreement between the elements.
  std::vector<double> finest;
  for (const char* type : {"CPS8", "CPS8R", "CPS6"}) {
    double previous = 0.0, v = 0.0;
    for (int n : {2, 4, 8, 16}) {
      v = cook(type, n);
      EXPECT_GT(v, previous) << type << " n = " << n;
      previous = v;
    }
    finest.push_back(v);
  }
  for (double v : finest) EXPECT_NEAR(v, 25.1, 0.1);
}

namespace {

/// sigma_yy at D = (2, 0) of NAFEMS LE1 on an nt x nr mesh of `type` (t: angle, r: across).
double le1(const std::string& type, int nt, int nr) {
  // s runs outward across the membrane, t along the angle (counter-clockwise elements)
  const QuadMesh2D m{nr, nt};
  auto map = [](double s, double t) {
    const double th = 0.5 * kPi * t;
    const double xi = 2.0 * std::cos(th), yi = std::sin(th);
    const double xo = 3.25 * std::cos(th), yo = 2.75 * std::sin(th);
    return std::array<double, 2>{xi + s * (xo - xi), yi + s * (yo - yi)};
  };
  std::string d = "*HEADING\nNAFEMS LE1 " + type + "\n";
  const bool linear = type.find('4') != std::string::npos; // CPS4, CPS4I: corner nodes only
  if (linear) {
    d += "*NODE\n";
    for (int j = 0; j <= 2 * m.ny; j += 2)
      for (int i = 0; i <= 2 * m.nx; i += 2) {
        const auto p = map(i / (2.0 * m.nx), j / (2.0 * m.ny));
        d += fmt::format("{}, {:.17g}, {:.17g}\n", m.label(i, j), p[0], p[1]);
      }
    d += "*ELEMENT, TYPE=" + type + ", ELSET=ALL\n";
    for (int j = 0; j < m.ny; ++j)
      for (int i = 0; i < m.nx; ++i)
        d += fmt::format("{}, {}, {}, {}, {}\n", m.element(i, j), m.label(2 * i, 2 * j),
                         m.label(2 * i + 2, 2 * j), m.label(2 * i + 2, 2 * j + 2),
                         m.label(2 * i, 2 * j + 2));
  } else {
    d += m.nodes(map) + m.elements(type, "ALL");
  }
  d += "*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n*SOLID SECTION, ELSET=ALL, "
       "MATERIAL=STEEL\n0.1\n";
  std::vector<int> xsym, ysym;
  for (int i = 0; i <= 2 * m.nx; i += linear ? 2 : 1) {
    ysym.push_back(m.label(i, 0));        // on y = 0
    xsym.push_back(m.label(i, 2 * m.ny)); // on x = 0
  }
  d += nset("YSYM", ysym) + nset("XSYM", xsym);
  d += "*STEP\n*STATIC\n*BOUNDARY\nYSYM, 2, 2\nXSYM, 1, 1\n*DLOAD\n";
  // outer edge s = 1 is face S2 (nodes 2-3) of the elements i = nr - 1; outward pressure -10
  for (int j = 0; j < m.ny; ++j) d += fmt::format("{}, P2, -10.\n", m.element(m.nx - 1, j));
  d += "*EL PRINT, ELSET=ALL\nS\n*END STEP\n";
  const JobResult r = run_deck(d, false, fmt::format("le1_{}_{}", type, nt));
  EXPECT_EQ(r.exit_code, 0) << r.error;
  if (r.exit_code != 0) return 0.0;
  const Frame& f = last_frame(r);
  // D = (2, 0) is corner 1 of element (0, 0): (xi, eta) = (-1, -1)
  const ElementResult* er = f.element(r.model->mesh.find_element(m.element(0, 0)));
  const OutputBlock* b = er ? er->data.find(ElemVar::S) : nullptr;
  if (!b) return 0.0;
  const std::size_t nc = b->names.size(); // S11, S22, S12
  if (b->n_points == 4) {
    // bilinear through the 2 x 2 points at +-1/sqrt 3: at xi = -1 the point weights are
    // (1 + sqrt 3)/2 and (1 - sqrt 3)/2 per direction
    const double a = 0.5 * (1 + std::sqrt(3.0)), c = 0.5 * (1 - std::sqrt(3.0));
    const double w[4] = {a * a, c * a, a * c, c * c}; // points (-,-), (+,-), (-,+), (+,+)
    double v = 0.0;
    for (int q = 0; q < 4; ++q) v += w[q] * b->values[q * nc + 1];
    return v;
  }
  // 3 x 3 points at -g, 0, g (g = sqrt 0.6): quadratic Lagrange weights at -1
  const double g = std::sqrt(0.6);
  auto L = [&](int k, double x) {
    const double p[3] = {-g, 0.0, g};
    double l = 1.0;
    for (int m2 = 0; m2 < 3; ++m2)
      if (m2 != k) l *= (x - p[m2]) / (p[k] - p[m2]);
    return l;
  };
  double v = 0.0;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) v += L(i, -1.0) * L(j, -1.0) * b->values[(3 * j + i) * nc + 1];
  return v;
}

} // namespace

TEST(QuadraticBenchmarks, NafemsLe1EllipticMembrane) {
  // measured sigma_yy(D): CPS8 92.16 (12 x 4), 93.13 (24 x 8), 92.93 (48 x 16); CPS8R 85.03,
  // 89.53, 91.58 (the bilinear extrapolation from its 2 x 2 points converges more slowly)
  const double cps8 = le1("CPS8", 24, 8);
  EXPECT_LT(std::abs(cps8 / 92.7 - 1.0), 1e-2) << cps8;
  double previous = 0.0;
  for (int n : {12, 24, 48}) {
    const double v = le1("CPS8R", n, n / 3);
    EXPECT_GT(v, previous) << n; // rising towards the target
    previous = v;
  }
  EXPECT_LT(std::abs(previous / 92.7 - 1.0), 1.5e-2) << previous;
  // first-order, 48 x 16, bilinear extrapolation from the 2 x 2 points: CPS4I 92.91, CPS4 94.26
  const double i4 = le1("CPS4I", 48, 16);
  EXPECT_LT(std::abs(i4 / 92.7 - 1.0), 1e-2) << i4;
}

namespace {

/// sigma_yy at D = (2, 0, 0.3) of NAFEMS LE10 (thick elliptic plate under 1 MPa on its top face)
/// with C3D20R on nr x nt x nz elements (radius x angle x thickness), extrapolated trilinearly from
/// the 2 x 2 x 2 points of the element at D.
double le10(int nr, int nt, int nz) {
  const HexMesh20 m{nr, nt, nz};
  auto map = [](double s, double t, double w) {
    const double th = 0.5 * kPi * t;
    const double xi = 2.0 * std::cos(th), yi = std::sin(th);
    const double xo = 3.25 * std::cos(th), yo = 2.75 * std::sin(th);
    return Point3{xi + s * (xo - xi), yi + s * (yo - yi), -0.3 + 0.6 * w};
  };
  std::string d = "*HEADING\nNAFEMS LE10\n" + m.nodes(map) + m.elements("C3D20R", "ALL");
  d += "*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n*SOLID SECTION, ELSET=ALL, "
       "MATERIAL=STEEL\n\n";
  const std::vector<int> mid = m.plane(0, 2 * m.nx); // the outer curved face
  // the outer face's mid-plane line: i = 2 nx, k = nz
  std::vector<int> line;
  for (int j = 0; j <= 2 * m.ny; ++j)
    if (HexMesh20::present(2 * m.nx, j, m.nz)) line.push_back(m.label(2 * m.nx, j, m.nz));
  d += nset("YSYM", m.plane(1, 0)) + nset("XSYM", m.plane(1, 2 * m.ny)) + nset("OUTER", mid) +
       nset("MIDLINE", line);
  d += "*STEP\n*STATIC\n*BOUNDARY\nYSYM, 2, 2\nXSYM, 1, 1\nOUTER, 1, 2\nMIDLINE, 3, 3\n*DLOAD\n";
  for (int j = 0; j < m.ny; ++j)
    for (int i = 0; i < m.nx; ++i) d += fmt::format("{}, P2, 1.\n", m.element(i, j, m.nz - 1));
  d += "*EL PRINT, ELSET=ALL\nS\n*END STEP\n";
  const JobResult r = run_deck(d, false, fmt::format("le10_{}", nt));
  EXPECT_EQ(r.exit_code, 0) << r.error;
  if (r.exit_code != 0) return 0.0;
  const Frame& f = last_frame(r);
  // D is node 5 of element (0, 0, nz - 1): (xi, eta, zeta) = (-1, -1, +1)
  const ElementResult* er = f.element(r.model->mesh.find_element(m.element(0, 0, m.nz - 1)));
  const OutputBlock* b = er ? er->data.find(ElemVar::S) : nullptr;
  if (!b || b->n_points != 8) return 0.0;
  const double a = 0.5 * (1 + std::sqrt(3.0)), c = 0.5 * (1 - std::sqrt(3.0));
  double v = 0.0;
  for (int q = 0; q < 8; ++q) { // points: xi fastest, then eta, then zeta (- then +)
    const double wx = q % 2 ? c : a, wy = (q / 2) % 2 ? c : a, wz = q / 4 ? a : c;
    v += wx * wy * wz * b->values[q * b->names.size() + 1];
  }
  return v;
}

} // namespace

// NAFEMS LE10: target sigma_yy(D) = -5.38 MPa. Measured with C3D20R (radius x angle x thickness,
// trilinear extrapolation from the element at D): -5.346 (3 x 6 x 2), -5.284 (6 x 12 x 4), -5.443
// (12 x 24 x 4), -5.150 (6 x 12 x 8): within 5% but not monotone (the point value extrapolated
// from the reduced points of one element; see docs/verification.md).
TEST(QuadraticBenchmarks, NafemsLe10ThickPlate) {
  for (auto [nr, nt, nz] : {std::array{3, 6, 2}, std::array{6, 12, 4}}) {
    const double v = le10(nr, nt, nz);
    EXPECT_LT(std::abs(v / -5.38 - 1.0), 5e-2) << nr << " x " << nt << " x " << nz << ": " << v;
  }
}
