// Verification decks of the first-order reduced-integration elements (C3D8R, CPS4R, CAX4R) and
// of C3D8I (issue 13); the measured numbers are in docs/verification.md.
// - A cantilever (L = 20, 1 x 1 section, E = 1000, nu = 0.3, nx x 1 x nz elements through the
//   depth z) under a tip shear P (a uniform traction on the tip face: A_f P / 4 at the corners of
//   each face): Timoshenko's tip deflection P L^3 / (3 E I) + P L / (kappa G A), kappa = 5/6.
//   C3D8I and C3D8R (ENHANCED, the same element for linear elasticity) within 1.5% at 20 x 1 x 2;
//   C3D8R with nz = 16 within 1% and ALLAE / ALLIE < 1%: the hourglass energy is the energy of the
//   strain's variation within each element, 1 / nz^2 of the bending energy. HOURGLASS=STIFFNESS
//   (softer) is within 2% at nz = 16 with a smaller ALLAE, and hopeless at nz = 1 (tip deflection
//   several times the beam's: the total-stiffness approach needs several elements through the
//   depth). A linear model takes one Newton iteration.
// - NAFEMS LE1 (elliptic membrane, sigma_yy at D = 92.7 MPa) with CPS4R on the mapped mesh of
//   benchmarks_quadratic_test.cpp: the one-point stresses of the four elements nearest D
//   extrapolated bilinearly to D (centres at 1/2 and 3/2 element from it: weights 9/4, -3/4,
//   -3/4, 1/4), rising towards the target.
// - Cook's membrane with CPS4R converges from below to 25.1 (the CPS8/CPS8R/CPS6 limit of
//   benchmarks_quadratic_test.cpp).
// - NAFEMS LE10 (thick plate, sigma_yy at D = -5.38 MPa) with C3D8I, trilinear extrapolation
//   from the 2 x 2 x 2 points of the element at D.
// - Bad input: HOURGLASS=VISCOUS and an undefined CONTROLS= name exit 1 with file:line.
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <map>

using namespace gapfem;
using namespace gapfem::test;

namespace {
const double kPi = std::acos(-1.0);
constexpr double kE = 1000.0, kNu = 0.3;

/// A structured grid of first-order hexahedra: (nx + 1)(ny + 1)(nz + 1) nodes.
struct Hex8Grid {
  int nx, ny, nz;
  int label(int i, int j, int k) const { return 1 + i + (nx + 1) * (j + (ny + 1) * k); }
  int element(int i, int j, int k) const { return 1 + i + nx * (j + ny * k); }
  template <class Map>
  std::string nodes(Map map) const {
    std::string out = "*NODE\n";
    for (int k = 0; k <= nz; ++k)
      for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
          const auto p = map(double(i) / nx, double(j) / ny, double(k) / nz);
          out += fmt::format("{}, {:.17g}, {:.17g}, {:.17g}\n", label(i, j, k), p[0], p[1], p[2]);
        }
    return out;
  }
  std::string elements(const std::string& type) const {
    std::string out = fmt::format("*ELEMENT, TYPE={}, ELSET=ALL\n", type);
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
          out += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", element(i, j, k),
                             label(i, j, k), label(i + 1, j, k), label(i + 1, j + 1, k),
                             label(i, j + 1, k), label(i, j, k + 1), label(i + 1, j, k + 1),
                             label(i + 1, j + 1, k + 1), label(i, j + 1, k + 1));
    return out;
  }
  /// Nodes with index `axis` (0: i, 1: j, 2: k) equal to n.
  std::vector<int> plane(int axis, int n) const {
    std::vector<int> v;
    for (int k = 0; k <= nz; ++k)
      for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i)
          if ((axis == 0 ? i : axis == 1 ? j : k) == n) v.push_back(label(i, j, k));
    return v;
  }
};

std::string nset(const std::string& name, const std::vector<int>& labels) {
  std::string out = "*NSET, NSET=" + name + "\n";
  for (std::size_t i = 0; i < labels.size(); ++i)
    out += std::to_string(labels[i]) + (i % 8 == 7 || i + 1 == labels.size() ? "\n" : ", ");
  return out;
}

struct Cantilever {
  double tip = 0.0; ///< mean w over the tip face
  double allae = 0.0, allse = 0.0, allie = 0.0;
  int iterations = 0;
};

Cantilever cantilever(const std::string& type, int nx, int nz, const std::string& controls = "") {
  const double L = 20.0, P = 0.01;
  const Hex8Grid m{nx, 1, nz};
  std::string d = "*HEADING\ncantilever " + type + "\n";
  d += m.nodes([&](double s, double t, double w) { return std::array{L * s, t, w}; });
  d += m.elements(type) + fmt::format("*MATERIAL, NAME=M\n*ELASTIC\n{}, {}\n", kE, kNu);
  d += "*SOLID SECTION, ELSET=ALL, MATERIAL=M" +
       std::string(controls.empty() ? "" : ", CONTROLS=EC");
  d += "\n" + (controls.empty() ? "" : "*SECTION CONTROLS, NAME=EC, HOURGLASS=" + controls + "\n");
  d += nset("FIX", m.plane(0, 0)) + "*STEP\n*STATIC\n*BOUNDARY\nFIX, 1, 3\n*CLOAD\n";
  std::map<int, double> fz; // uniform shear traction on the tip face: A_f P / 4 per face corner
  const double Af = 1.0 / (m.ny * m.nz);
  for (int k = 0; k < m.nz; ++k)
    for (int dj : {0, 1})
      for (int dk : {0, 1}) fz[m.label(nx, dj, k + dk)] -= Af * P / 4.0;
  for (auto [lbl, v] : fz) d += fmt::format("{}, 3, {:.17g}\n", lbl, v);
  d += "*END STEP\n";
  const JobResult r = run_deck(d, false, fmt::format("cantilever_{}_{}_{}", type, nx, nz));
  EXPECT_EQ(r.exit_code, 0) << r.error;
  Cantilever c;
  if (r.exit_code != 0) return c;
  const auto tip = m.plane(0, nx);
  for (int lbl : tip) c.tip += U(r, last_frame(r), lbl)[2] / static_cast<double>(tip.size());
  c.allae = r.steps[0].checks.allae;
  c.allse = r.steps[0].checks.allse;
  c.allie = r.steps[0].checks.allie;
  // a linear elastic step: the work of the element forces is the strain plus hourglass energy
  if (r.steps[0].checks.hourglass) EXPECT_NEAR(c.allse + c.allae, c.allie, 1e-9 * c.allie);
  c.iterations = r.steps[0].iterations;
  EXPECT_EQ(r.steps[0].checks.hourglass, type.find('R') != std::string::npos) << type;
  return c;
}

double timoshenko() {
  const double L = 20.0, P = 0.01, I = 1.0 / 12.0, G = kE / (2 * (1 + kNu));
  return -(P * L * L * L / (3 * kE * I) + P * L / (5.0 / 6.0 * G * 1.0));
}

} // namespace

// measured (Timoshenko -0.32062): C3D8I = C3D8R 20 x 1 x 2 -0.31704 (ALLAE/ALLIE 0.253);
// C3D8R 40 x 1 x 12 -0.31864 (0.0097), 40 x 1 x 16 -0.31864 (0.0067; CalculiX -0.31897);
// STIFFNESS 40 x 1 x 12 -0.32115 (ALLAE/ALLIE 0.003), 20 x 1 x 1 -18.48 (58 times the beam)
TEST(ReducedElements, CantileverBendingAndHourglassEnergy) {
  const double ref = timoshenko();
  const Cantilever i8 = cantilever("C3D8I", 20, 2), r8 = cantilever("C3D8R", 20, 2);
  EXPECT_LT(std::abs(i8.tip / ref - 1.0), 1.5e-2) << i8.tip << " vs " << ref;
  EXPECT_NEAR(r8.tip, i8.tip, 1e-8 * std::abs(ref)); // ENHANCED: the incompatible-mode element
  EXPECT_EQ(r8.iterations, 1);
  // two elements through the depth: the within-element variation is 1/4 of the bending energy
  EXPECT_NEAR(r8.allae / (r8.allse + r8.allae), 0.25, 0.02);
  const Cantilever fine = cantilever("C3D8R", 40, 16);
  EXPECT_LT(std::abs(fine.tip / ref - 1.0), 1e-2) << fine.tip;
  EXPECT_LT(fine.allae, 1e-2 * (fine.allse + fine.allae));
  EXPECT_GT(fine.allae, 0.0);
  const Cantilever stiff = cantilever("C3D8R", 40, 16, "STIFFNESS");
  EXPECT_LT(std::abs(stiff.tip / ref - 1.0), 2e-2) << stiff.tip;
  EXPECT_LT(stiff.tip, fine.tip); // softer (more negative)
  EXPECT_LT(stiff.allae, fine.allae);
  const Cantilever coarse = cantilever("C3D8R", 20, 1, "STIFFNESS");
  EXPECT_GT(coarse.tip / ref, 3.0); // one element through the depth: hourglassing
}

namespace {

/// sigma_yy at D of NAFEMS LE1 with CPS4R on an nt x nr mapped mesh (s across, t along the angle).
double le1_cps4r(int nt, int nr) {
  auto map = [](double s, double t) {
    const double th = 0.5 * kPi * t;
    const double xi = 2.0 * std::cos(th), yi = std::sin(th);
    const double xo = 3.25 * std::cos(th), yo = 2.75 * std::sin(th);
    return std::array<double, 2>{xi + s * (xo - xi), yi + s * (yo - yi)};
  };
  auto label = [&](int i, int j) { return 1 + i + (nr + 1) * j; };
  auto element = [&](int i, int j) { return 1 + i + nr * j; };
  std::string d = "*HEADING\nNAFEMS LE1 CPS4R\n*NODE\n";
  for (int j = 0; j <= nt; ++j)
    for (int i = 0; i <= nr; ++i) {
      const auto p = map(double(i) / nr, double(j) / nt);
      d += fmt::format("{}, {:.17g}, {:.17g}\n", label(i, j), p[0], p[1]);
    }
  d += "*ELEMENT, TYPE=CPS4R, ELSET=ALL\n";
  for (int j = 0; j < nt; ++j)
    for (int i = 0; i < nr; ++i)
      d += fmt::format("{}, {}, {}, {}, {}\n", element(i, j), label(i, j), label(i + 1, j),
                       label(i + 1, j + 1), label(i, j + 1));
  d += "*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n*SOLID SECTION, ELSET=ALL, "
       "MATERIAL=STEEL\n0.1\n";
  std::vector<int> xsym, ysym;
  for (int i = 0; i <= nr; ++i) {
    ysym.push_back(label(i, 0));
    xsym.push_back(label(i, nt));
  }
  d += nset("YSYM", ysym) + nset("XSYM", xsym);
  d += "*STEP\n*STATIC\n*BOUNDARY\nYSYM, 2, 2\nXSYM, 1, 1\n*DLOAD\n";
  for (int j = 0; j < nt; ++j) d += fmt::format("{}, P2, -10.\n", element(nr - 1, j));
  d += "*EL PRINT, ELSET=ALL\nS\n*END STEP\n";
  const JobResult r = run_deck(d, false, fmt::format("le1_cps4r_{}", nt));
  EXPECT_EQ(r.exit_code, 0) << r.error;
  if (r.exit_code != 0) return 0.0;
  const Frame& f = last_frame(r);
  auto syy = [&](int i, int j) {
    const ElementResult* er = f.element(r.model->mesh.find_element(element(i, j)));
    const OutputBlock* b = er ? er->data.find(ElemVar::S) : nullptr;
    EXPECT_TRUE(b && b->n_points == 1);
    return b ? b->values[1] : 0.0;
  };
  return 2.25 * syy(0, 0) - 0.75 * syy(1, 0) - 0.75 * syy(0, 1) + 0.25 * syy(1, 1);
}

/// Tip deflection of Cook's membrane with an n x n CPS4R mesh.
double cook_cps4r(int n) {
  auto label = [&](int i, int j) { return 1 + i + (n + 1) * j; };
  std::string d = "*HEADING\nCook's membrane CPS4R\n*NODE\n";
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double s = double(i) / n, t = double(j) / n;
      const double y = s * (1 - t) * 44.0 + s * t * 60.0 + (1 - s) * t * 44.0;
      d += fmt::format("{}, {:.17g}, {:.17g}\n", label(i, j), 48.0 * s, y);
    }
  d += "*ELEMENT, TYPE=CPS4R, ELSET=ALL\n";
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      d += fmt::format("{}, {}, {}, {}, {}\n", 1 + i + n * j, label(i, j), label(i + 1, j),
                       label(i + 1, j + 1), label(i, j + 1));
  std::vector<int> clamp;
  for (int j = 0; j <= n; ++j) clamp.push_back(label(0, j));
  d += "*MATERIAL, NAME=M\n*ELASTIC\n1., 0.333333333333333333\n*SOLID SECTION, ELSET=ALL, "
       "MATERIAL=M\n1.\n" +
       nset("CLAMP", clamp) + "*STEP\n*STATIC\n*BOUNDARY\nCLAMP, 1, 2\n*CLOAD\n";
  std::map<int, double> f; // total shear 1 on the right edge: 1 / (2 n) per edge end
  for (int j = 0; j < n; ++j) {
    f[label(n, j)] += 0.5 / n;
    f[label(n, j + 1)] += 0.5 / n;
  }
  for (auto [lbl, v] : f) d += fmt::format("{}, 2, {:.17g}\n", lbl, v);
  d += "*END STEP\n";
  const JobResult r = run_deck(d, false, fmt::format("cook_cps4r_{}", n));
  EXPECT_EQ(r.exit_code, 0) << r.error;
  return r.exit_code == 0 ? U(r, last_frame(r), label(n, n))[1] : 0.0;
}

/// sigma_yy at D = (2, 0, 0.3) of NAFEMS LE10 with C3D8I on nr x nt x nz elements.
double le10_c3d8i(int nr, int nt, int nz) {
  const Hex8Grid m{nr, nt, nz};
  auto map = [](double s, double t, double w) {
    const double th = 0.5 * kPi * t;
    const double xi = 2.0 * std::cos(th), yi = std::sin(th);
    const double xo = 3.25 * std::cos(th), yo = 2.75 * std::sin(th);
    return std::array{xi + s * (xo - xi), yi + s * (yo - yi), -0.3 + 0.6 * w};
  };
  std::string d = "*HEADING\nNAFEMS LE10 C3D8I\n" + m.nodes(map) + m.elements("C3D8I");
  d += "*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n*SOLID SECTION, ELSET=ALL, "
       "MATERIAL=STEEL\n";
  std::vector<int> midline; // the outer face's mid-plane line (nz even)
  for (int j = 0; j <= nt; ++j) midline.push_back(m.label(nr, j, nz / 2));
  d += nset("YSYM", m.plane(1, 0)) + nset("XSYM", m.plane(1, nt)) + nset("OUTER", m.plane(0, nr)) +
       nset("MIDLINE", midline);
  d += "*STEP\n*STATIC\n*BOUNDARY\nYSYM, 2, 2\nXSYM, 1, 1\nOUTER, 1, 2\nMIDLINE, 3, 3\n*DLOAD\n";
  for (int j = 0; j < nt; ++j)
    for (int i = 0; i < nr; ++i) d += fmt::format("{}, P2, 1.\n", m.element(i, j, nz - 1));
  d += "*EL PRINT, ELSET=ALL\nS\n*END STEP\n";
  const JobResult r = run_deck(d, false, fmt::format("le10_c3d8i_{}", nt));
  EXPECT_EQ(r.exit_code, 0) << r.error;
  if (r.exit_code != 0) return 0.0;
  const ElementResult* er =
      last_frame(r).element(r.model->mesh.find_element(m.element(0, 0, nz - 1)));
  const OutputBlock* b = er ? er->data.find(ElemVar::S) : nullptr;
  if (!b || b->n_points != 8) return 0.0;
  // D is node 5 of the element: (xi, eta, zeta) = (-1, -1, +1)
  const double a = 0.5 * (1 + std::sqrt(3.0)), c = 0.5 * (1 - std::sqrt(3.0));
  double v = 0.0;
  for (int q = 0; q < 8; ++q) {
    const double wx = q % 2 ? c : a, wy = (q / 2) % 2 ? c : a, wz = q / 4 ? a : c;
    v += wx * wy * wz * b->values[q * b->names.size() + 1];
  }
  return v;
}

} // namespace

// measured sigma_yy(D): 75.26, 84.52, 89.47, 91.59 (12 x 4 ... 96 x 32): the one-point stresses
// sit half an element from D, in the steep gradient there, so the point value converges slowly
TEST(ReducedElements, NafemsLe1WithCps4r) {
  double previous = 0.0;
  for (int n : {12, 24, 48, 96}) {
    const double v = le1_cps4r(n, n / 3);
    EXPECT_GT(v, previous) << n;
    previous = v;
  }
  EXPECT_LT(std::abs(previous / 92.7 - 1.0), 1.5e-2) << previous;
}

// measured v(C): 23.60, 24.46, 24.84, 25.02 (n = 4, 8, 16, 32)
TEST(ReducedElements, CooksMembraneWithCps4r) {
  double previous = 0.0, v = 0.0;
  for (int n : {4, 8, 16, 32}) {
    v = cook_cps4r(n);
    EXPECT_GT(v, previous) << n;
    previous = v;
  }
  EXPECT_NEAR(v, 25.1, 0.25);
}

// measured sigma_yy(D): -5.455 (6 x 12 x 4), -5.494 (12 x 24 x 8)
TEST(ReducedElements, NafemsLe10WithC3d8i) {
  const double v = le10_c3d8i(6, 12, 4);
  EXPECT_LT(std::abs(v / -5.38 - 1.0), 5e-2) << v;
}

TEST(ReducedElements, BadSectionControls) {
  const std::string mesh = "*NODE\n1,0,0\n2,1,0\n3,1,1\n4,0,1\n*ELEMENT, TYPE=CPS4R, ELSET=A\n"
                           "1, 1, 2, 3, 4\n*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n";
  const std::string step = "*STEP\n*STATIC\n*BOUNDARY\n1, 1, 2\n4, 1, 1\n*CLOAD\n2, 1, 1.\n"
                           "*END STEP\n";
  JobResult r = run_deck(mesh +
                         "*SOLID SECTION, ELSET=A, MATERIAL=M, CONTROLS=EC\n"
                         "*SECTION CONTROLS, NAME=EC, HOURGLASS=VISCOUS\n" +
                         step);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.error.find("job.inp:12"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("Abaqus/Explicit"), std::string::npos) << r.error;
  EXPECT_EQ(r.error.find("not defined"), std::string::npos) << r.error; // no follow-on error
  r = run_deck(mesh + "*SOLID SECTION, ELSET=A, MATERIAL=M, CONTROLS=NOPE\n" + step);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.error.find("job.inp:11"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("NOPE"), std::string::npos) << r.error;
  r = run_deck(mesh +
               "*SOLID SECTION, ELSET=A, MATERIAL=M, CONTROLS=EC\n"
               "*SECTION CONTROLS, NAME=EC, HOURGLASS=STIFFNESS\n0.5, 1., 1.\n" +
               step);
  EXPECT_EQ(r.exit_code, 0) << r.error;
  EXPECT_TRUE(r.steps[0].checks.hourglass);
  EXPECT_GT(r.steps[0].checks.allae, 0.0);
}

// A CAX4R shrink fit: an inner ring a..b and an outer ring b..c (one element high, u_z = 0:
// plane strain) joined by GAPUNI elements at the two interface node pairs with the radial
// interference delta as negative clearance. Lame (same material): p = E delta (b^2 - a^2)
// (c^2 - b^2) / (2 b^3 (c^2 - a^2) (1 - nu^2)); the gap forces add up to p 2 pi b h. First-order
// elements, 12 + 16 across: within 1% (measured below 0.5%).
TEST(ReducedElements, Cax4rShrinkFitOnGaps) {
  const double a = 1.0, b = 1.5, c = 2.5, h = 0.1, delta = 2e-3;
  const int ni = 12, no = 16, off = 1000;
  std::string d = "*HEADING\nCAX4R shrink fit on GAPUNI\n*NODE, NSET=NALL\n";
  for (int j = 0; j <= 1; ++j) {
    for (int i = 0; i <= ni; ++i)
      d += fmt::format("{}, {:.17g}, {:.17g}\n", 1 + i + (ni + 1) * j, a + (b - a) * i / ni, h * j);
    for (int i = 0; i <= no; ++i)
      d += fmt::format("{}, {:.17g}, {:.17g}\n", off + 1 + i + (no + 1) * j, b + (c - b) * i / no,
                       h * j);
  }
  d += "*ELEMENT, TYPE=CAX4R, ELSET=ALL\n";
  for (int i = 0; i < ni; ++i)
    d += fmt::format("{}, {}, {}, {}, {}\n", 1 + i, 1 + i, 2 + i, 2 + i + (ni + 1),
                     1 + i + (ni + 1));
  for (int i = 0; i < no; ++i)
    d += fmt::format("{}, {}, {}, {}, {}\n", 100 + i, off + 1 + i, off + 2 + i,
                     off + 2 + i + (no + 1), off + 1 + i + (no + 1));
  d += fmt::format("*ELEMENT, TYPE=GAPUNI, ELSET=GAPS\n501, {}, {}\n502, {}, {}\n", 1 + ni, off + 1,
                   1 + ni + (ni + 1), off + 1 + (no + 1));
  d += fmt::format("*GAP, ELSET=GAPS\n{}, 1., 0., 0.\n", -delta);
  d += fmt::format("*MATERIAL, NAME=M\n*ELASTIC\n{}, {}\n*SOLID SECTION, ELSET=ALL, MATERIAL=M\n",
                   kE, kNu);
  d += "*STEP\n*STATIC\n*BOUNDARY\nNALL, 2, 2\n*END STEP\n";
  const JobResult r = run_deck(d);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Frame& f = last_frame(r);
  const double p = kE * delta * (b * b - a * a) * (c * c - b * b) /
                   (2 * b * b * b * (c * c - a * a) * (1 - kNu * kNu));
  double total = 0.0;
  for (Label g : {501, 502}) {
    EXPECT_EQ(gap(r, f, g).status, ContactStatus::Closed);
    total += gap(r, f, g).normal_force;
  }
  EXPECT_NEAR(total, p * 2 * kPi * b * h, 1e-2 * p * 2 * kPi * b * h);
  EXPECT_TRUE(r.steps[0].checks.hourglass);
  // radial strain varies little across an element: the hourglass energy is a small part
  EXPECT_LT(r.steps[0].checks.allae, 1e-2 * r.steps[0].checks.allse);
}
