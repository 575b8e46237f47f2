// ENER (SENER), ELSE, EVOL and COORD of continuum elements (docs/results.md) under a homogeneous
// deformation prescribed at every node, u_i = a_i X_i, so that every point has the same strain:
//   small strain:  eps_i = a_i, SENER = lambda/2 (tr eps)^2 + mu eps:eps, EVOL = V0, COORD = X_q;
//   NLGEOM:        E_i = a_i + a_i^2 / 2 (Green-Lagrange), SENER = lambda/2 (tr E)^2 + mu E:E
//                  (St. Venant-Kirchhoff, per reference volume), EVOL = V0 prod(1 + a_i),
//                  COORD = (1 + a_i) X_q;
// ELSE = SENER V0 in both. Axisymmetric: u_r = a r, u_z = b z, the hoop strain is u_r / r = a;
// the volume of the ring r in [1, 3], z in [0, 2] is 2 pi r_mean A = 16 pi. Plane stress: the
// thickness strain makes S33 = 0: E33 = -lambda (E11 + E22) / (lambda + 2 mu), and the thickness
// stretches by sqrt(1 + 2 E33). E = 1000, nu = 0.25: lambda = mu = 400.
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <numbers>

using namespace gapfem;
using namespace gapfem::test;

namespace {

constexpr double kLambda = 400.0, kMu = 400.0;

struct Case {
  std::string type;
  int nd;           ///< 3 or 2
  bool axi = false; ///< CAX
  bool pstress = false;
};

/// Nodes of the element's box ([0,2]x[0,3]x[0,4] in 3-D, [0,2]x[0,3] in 2-D, [1,3]x[0,2] for CAX)
std::vector<std::array<double, 3>> box(const Case& c) {
  if (c.nd == 3)
    return {{0, 0, 0}, {2, 0, 0}, {2, 3, 0}, {0, 3, 0}, {0, 0, 4}, {2, 0, 4}, {2, 3, 4}, {0, 3, 4}};
  if (c.axi) return {{1, 0, 0}, {3, 0, 0}, {3, 2, 0}, {1, 2, 0}};
  return {{0, 0, 0}, {2, 0, 0}, {2, 3, 0}, {0, 3, 0}};
}

std::string deck(const Case& c, const std::array<double, 3>& a, bool nlgeom) {
  std::string d = "*HEADING\nhomogeneous deformation\n*NODE, NSET=ALLN\n";
  const auto X = box(c);
  for (std::size_t n = 0; n < X.size(); ++n)
    d += fmt::format("{}, {}, {}, {}\n", n + 1, X[n][0], X[n][1], X[n][2]);
  d += fmt::format("*ELEMENT, TYPE={}, ELSET=B\n1", c.type);
  for (std::size_t n = 0; n < X.size(); ++n) d += fmt::format(", {}", n + 1);
  d += fmt::format("\n*SOLID SECTION, ELSET=B, MATERIAL=M\n{}*MATERIAL, NAME=M\n*ELASTIC\n"
                   "1000., 0.25\n*STEP{}\n*STATIC\n1., 1.\n*BOUNDARY\n",
                   c.nd == 2 && !c.axi ? "1.\n" : "", nlgeom ? ", NLGEOM" : "");
  for (std::size_t n = 0; n < X.size(); ++n)
    for (int i = 0; i < c.nd; ++i)
      d += fmt::format("{}, {}, {}, {:.17g}\n", n + 1, i + 1, i + 1, a[i] * X[n][i]);
  return d + "*EL PRINT, ELSET=B\nENER, ELSE, EVOL, COORD\n*END STEP\n";
}

/// The strains (11, 22, 33) of the case and the reference volume.
std::array<double, 3> strains(const Case& c, const std::array<double, 3>& a, bool nlgeom) {
  auto gl = [&](double x) { return nlgeom ? x + 0.5 * x * x : x; };
  std::array<double, 3> e{gl(a[0]), gl(a[1]), c.nd == 3 ? gl(a[2]) : 0.0};
  if (c.axi) e[2] = gl(a[0]); // the hoop strain u_r / r = a
  if (c.pstress) e[2] = -kLambda * (e[0] + e[1]) / (kLambda + 2 * kMu);
  return e;
}

double reference_volume(const Case& c) {
  return c.nd == 3 ? 24.0 : c.axi ? 16.0 * std::numbers::pi : 6.0;
}

double current_volume(const Case& c, const std::array<double, 3>& a, bool nlgeom) {
  double v = reference_volume(c);
  if (!nlgeom) return v;
  v *= (1 + a[0]) * (1 + a[1]);
  if (c.nd == 3) v *= 1 + a[2];
  if (c.axi) v *= 1 + a[0];
  if (c.pstress) v *= std::sqrt(1 + 2 * strains(c, a, true)[2]);
  return v;
}

const OutputBlock& block(const JobResult& r, ElemVar v) {
  const ElementResult* e = last_frame(r).element(r.model->mesh.find_element(1));
  if (!e || !e->data.find(v)) throw std::runtime_error("no block");
  return *e->data.find(v);
}

void check(const Case& c, bool nlgeom) {
  SCOPED_TRACE(c.type + (nlgeom ? " NLGEOM" : ""));
  const std::array<double, 3> a =
      nlgeom ? std::array<double, 3>{0.1, -0.05, 0.2} : std::array<double, 3>{0.01, -0.002, 0.003};
  const JobResult r = run_deck(deck(c, a, nlgeom));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const auto e = strains(c, a, nlgeom);
  const double tr = e[0] + e[1] + e[2];
  const double W = 0.5 * kLambda * tr * tr + kMu * (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
  const OutputBlock& ener = block(r, ElemVar::ENER);
  ASSERT_GE(ener.n_points, 1);
  for (int p = 0; p < ener.n_points; ++p) EXPECT_NEAR(ener.values[p], W, 1e-10 * W) << p;
  EXPECT_NEAR(block(r, ElemVar::ELSE).values[0], W * reference_volume(c), 1e-10 * W);
  EXPECT_NEAR(block(r, ElemVar::EVOL).values[0], current_volume(c, a, nlgeom), 1e-11);
  // COORD: the points lie inside the box, at its Gauss coordinates, moved by (1 + a_i) under
  // NLGEOM; their mean is the box's centre (symmetric rules)
  const OutputBlock& x = block(r, ElemVar::COORD);
  ASSERT_EQ(static_cast<int>(x.names.size()), c.nd);
  const auto X = box(c);
  for (int i = 0; i < c.nd; ++i) {
    double lo = 1e30, hi = -1e30, mean = 0.0;
    for (const auto& n : X) {
      lo = std::min(lo, n[i]);
      hi = std::max(hi, n[i]);
    }
    const double stretch = nlgeom ? 1 + a[i] : 1.0;
    for (int p = 0; p < x.n_points; ++p) {
      const double v = x.values[p * c.nd + i] / stretch;
      mean += v / x.n_points;
      const double xi = (2 * v - lo - hi) / (hi - lo); // the point's parametric coordinate
      if (x.n_points == 1)
        EXPECT_NEAR(xi, 0.0, 1e-12);
      else
        EXPECT_NEAR(std::abs(xi), 1 / std::sqrt(3.0), 1e-12) << "point " << p + 1;
    }
    EXPECT_NEAR(mean, 0.5 * (lo + hi), 1e-12);
  }
}

} // namespace

TEST(EnergyVolumeOutput, ContinuumElementsGiveTheClosedForms) {
  for (const Case& c : {Case{"C3D8", 3}, Case{"C3D8R", 3}, Case{"C3D8I", 3}, Case{"CPE4", 2},
                        Case{"CPS4", 2, false, true}, Case{"CAX4", 2, true}, Case{"CPE4R", 2},
                        Case{"CAX4I", 2, true}})
    for (bool nlgeom : {false, true}) check(c, nlgeom);
}

// The .dat tables: ELSE and EVOL once per element ("FOR THE WHOLE ELEMENT", no point column),
// ENER per point; a variable an element type does not have (ENER of a truss) leaves that type out
// with a warning and prints the rest.
TEST(EnergyVolumeOutput, DatTablesAndUnavailableVariables) {
  const Case c{"C3D8", 3};
  std::string d = deck(c, {0.01, 0.0, 0.0}, false);
  d.replace(d.find("*SOLID SECTION"), 0,
            "*NODE\n20, 5., 0., 0.\n*ELEMENT, TYPE=T3D2, ELSET=T\n2, 2, 20\n*SOLID SECTION, "
            "ELSET=T, MATERIAL=M\n1.\n*ELSET, ELSET=EVERY\nB, T\n");
  d.replace(d.find("*EL PRINT, ELSET=B"), 18, "*EL PRINT, ELSET=EVERY");
  d.replace(d.find("*BOUNDARY\n") + 10, 0, "20, 1, 3\n");
  const JobResult r = run_deck(d, true, "tables");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const std::string dat = slurp(test_dir() / "tables.dat");
  EXPECT_NE(dat.find("PRINTED FOR THE WHOLE ELEMENT FOR ELEMENT TYPE C3D8"), std::string::npos)
      << dat;
  EXPECT_NE(dat.find("SENER"), std::string::npos);
  EXPECT_NE(dat.find("ELSE"), std::string::npos);
  EXPECT_NE(dat.find("EVOL"), std::string::npos);
  EXPECT_NE(dat.find("COORD1"), std::string::npos);
  EXPECT_EQ(dat.find("TYPE T3D2"), std::string::npos) << dat; // trusses have none of them
}
