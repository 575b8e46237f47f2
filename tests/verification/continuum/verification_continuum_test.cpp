// Deck-level verification of the continuum elements through gapfem::run_job. The decks are
// generated here (structured meshes, optionally split into tetrahedra) and compared with
// closed-form answers whose derivations sit next to each check.
#include "app/job.hpp"
#include "model/model.hpp"
#include "test_util.hpp"

#include <array>
#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <map>
#include <numbers>
#include <string>
#include <vector>

namespace gapfem::test {
namespace {

constexpr double kE = 200000.0, kNu = 0.3, kAlpha = 1.2e-5;

/// A small deck writer: nodes, one element block, node sets by predicate.
struct DeckMesh {
  std::vector<std::array<double, 3>> nodes; // label = index + 1
  std::vector<std::vector<int>> elems;      // 1-based node labels
  std::string type;

  int add_node(double x, double y, double z) {
    nodes.push_back({x, y, z});
    return static_cast<int>(nodes.size());
  }
  template <class Pred>
  std::string nset(const std::string& name, Pred pred) const {
    std::string s = fmt::format("*NSET, NSET={}\n", name);
    int k = 0;
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (pred(nodes[i])) s += fmt::format("{},{}", i + 1, (++k % 12 == 0) ? "\n" : " ");
    return s + "\n";
  }
  std::string text() const {
    std::string s = "*NODE\n";
    for (std::size_t i = 0; i < nodes.size(); ++i)
      s += fmt::format("{}, {:.15g}, {:.15g}, {:.15g}\n", i + 1, nodes[i][0], nodes[i][1],
                       nodes[i][2]);
    s += fmt::format("*ELEMENT, TYPE={}, ELSET=EALL\n", type);
    for (std::size_t e = 0; e < elems.size(); ++e) {
      s += fmt::format("{}", e + 1);
      for (std::size_t k = 0; k < elems[e].size(); ++k)
        s += fmt::format(",{}{}", (k == 7 && elems[e].size() > 8) ? "\n" : " ", elems[e][k]);
      s += "\n";
    }
    return s;
  }
};

std::string material_block(const std::string& section_line) {
  return section_line +
         fmt::format("*MATERIAL, NAME=STEEL\n*ELASTIC\n{}, {}\n*EXPANSION\n{}\n", kE, kNu, kAlpha);
}

/// Structured block [0,L]x[0,W]x[0,H] with nx*ny*nz cells; interior nodes perturbed (the boundary
/// stays planar) so that a uniform stress state is not helped by a regular mesh.
std::vector<std::array<int, 8>> block_cells(DeckMesh& m, int nx, int ny, int nz, double L, double W,
                                            double H) {
  auto id = [&](int i, int j, int k) { return 1 + i + (nx + 1) * (j + (ny + 1) * k); };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        double x = L * i / nx, y = W * j / ny, z = H * k / nz;
        if (i > 0 && i < nx) x += 0.15 * L / nx * std::sin(1.0 + i + 2 * j + 3 * k);
        if (j > 0 && j < ny) y += 0.15 * W / ny * std::cos(2.0 + 3 * i + j + k);
        if (k > 0 && k < nz) z += 0.15 * H / nz * std::sin(3.0 + i + j + 5 * k);
        m.add_node(x, y, z);
      }
  std::vector<std::array<int, 8>> cells;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        cells.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                         id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
                         id(i, j + 1, k + 1)});
  return cells;
}

double signed_volume(const DeckMesh& m, const std::vector<int>& t) {
  const auto &a = m.nodes[t[0] - 1], &b = m.nodes[t[1] - 1], &c = m.nodes[t[2] - 1],
             &d = m.nodes[t[3] - 1];
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double w[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
         u[2] * (v[0] * w[1] - v[1] * w[0]);
}

/// Plate mesh of C3D8, C3D4 (Kuhn split of each cell into 6 conforming tetrahedra) or C3D10.
DeckMesh plate_mesh(const std::string& type, double L, double W, double H) {
  DeckMesh m;
  m.type = type;
  const auto cells = block_cells(m, 4, 2, 2, L, W, H);
  if (type == "C3D8") {
    for (const auto& c : cells) m.elems.push_back({c.begin(), c.end()});
    return m;
  }
  // Kuhn: the six monotone paths from corner 0 (0,0,0) to corner 6 (1,1,1).
  constexpr int kTets[6][4] = {{0, 1, 2, 6}, {0, 3, 2, 6}, {0, 3, 7, 6},
                               {0, 4, 7, 6}, {0, 4, 5, 6}, {0, 1, 5, 6}};
  std::map<std::pair<int, int>, int> mid;
  for (const auto& c : cells)
    for (const auto& t : kTets) {
      std::vector<int> e{c[t[0]], c[t[1]], c[t[2]], c[t[3]]};
      if (signed_volume(m, e) < 0) std::swap(e[1], e[2]);
      if (type == "C3D10") {
        constexpr int edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
        std::vector<int> mids;
        for (const auto& ed : edges) {
          const int a = e[ed[0]], b = e[ed[1]];
          const auto key = std::minmax(a, b);
          auto it = mid.find(key);
          if (it == mid.end()) {
            const auto &pa = m.nodes[a - 1], &pb = m.nodes[b - 1];
            it = mid.emplace(key, m.add_node(0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]),
                                             0.5 * (pa[2] + pb[2])))
                     .first;
          }
          mids.push_back(it->second);
        }
        e.insert(e.end(), mids.begin(), mids.end());
      }
      m.elems.push_back(e);
    }
  return m;
}

/// *DLOAD lines putting pressure p on every element face whose corner nodes satisfy `on`.
template <class Pred>
std::string face_loads(const DeckMesh& m, double p, Pred on) {
  // Abaqus face corner nodes (0-based), see src/fe/element_faces.hpp.
  static const std::vector<std::vector<int>> hex{{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1},
                                                 {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 4, 0}};
  static const std::vector<std::vector<int>> tet{{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
  const auto& faces = m.type == "C3D8" ? hex : tet;
  std::string s = "*DLOAD\n";
  for (std::size_t e = 0; e < m.elems.size(); ++e)
    for (std::size_t f = 0; f < faces.size(); ++f) {
      bool all = true;
      for (int a : faces[f]) all = all && on(m.nodes[m.elems[e][a] - 1]);
      if (all) s += fmt::format("{}, P{}, {}\n", e + 1, f + 1, p);
    }
  return s;
}

/// Value of component `comp` at point `q` of output `var` of element label `e`.
double element_value(const JobResult& r, const Frame& f, Label e, ElemVar var, int comp, int q) {
  const ElementResult* er = f.element(r.model->mesh.find_element(e));
  if (!er) return NAN;
  const OutputBlock* b = er->data.find(var);
  if (!b) return NAN;
  return b->values[static_cast<std::size_t>(q) * b->names.size() + comp];
}

class VerificationContinuumPlate : public ::testing::TestWithParam<std::string> {};

// Plate in tension: symmetry planes x = 0, y = 0, z = 0 and a tensile traction sigma on x = L
// (pressure -sigma). The exact solution is homogeneous: sigma11 = sigma, all other stresses 0,
// u1 = sigma x / E, u2 = -nu sigma y / E, u3 = -nu sigma z / E. A linear displacement field lies in
// the finite element space of every element (perturbed interior nodes included), so the FE solution
// is exact up to round-off: relative tolerance 1e-7 (conditioning ~1e4-1e5 of these small meshes).
TEST_P(VerificationContinuumPlate, UniformTensionIsExact) {
  const std::string type = GetParam();
  const double L = 10.0, W = 4.0, H = 2.0, sigma = 50.0;
  const DeckMesh m = plate_mesh(type, L, W, H);
  auto near = [](double a, double b) { return std::abs(a - b) < 1e-9; };
  std::string deck = "*HEADING\nplate in tension, " + type + "\n" + m.text();
  deck += m.nset("X0", [&](const auto& p) { return near(p[0], 0); });
  deck += m.nset("Y0", [&](const auto& p) { return near(p[1], 0); });
  deck += m.nset("Z0", [&](const auto& p) { return near(p[2], 0); });
  deck += material_block("*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n");
  deck += "*BOUNDARY\nX0, 1\nY0, 2\nZ0, 3\n*STEP\n*STATIC\n";
  deck += face_loads(m, -sigma, [&](const auto& p) { return near(p[0], L); });
  deck += "*EL PRINT\nS, E\n*NODE PRINT\nU, RF\n*END STEP\n";
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  const Frame& f = last_frame(r);
  const double tol = 1e-7 * sigma / kE * L;
  for (std::size_t n = 0; n < m.nodes.size(); ++n) {
    const Vec3& u = f.nodes.U[r.model->mesh.find_node(static_cast<Label>(n + 1))];
    EXPECT_NEAR(u[0], sigma / kE * m.nodes[n][0], tol) << "node " << n + 1;
    EXPECT_NEAR(u[1], -kNu * sigma / kE * m.nodes[n][1], tol) << "node " << n + 1;
    EXPECT_NEAR(u[2], -kNu * sigma / kE * m.nodes[n][2], tol) << "node " << n + 1;
  }
  const int n_points = type == "C3D8" ? 8 : (type == "C3D10" ? 4 : 1);
  for (std::size_t e = 0; e < m.elems.size(); ++e)
    for (int q = 0; q < n_points; ++q)
      for (int c = 0; c < 6; ++c)
        EXPECT_NEAR(element_value(r, f, static_cast<Label>(e + 1), ElemVar::S, c, q),
                    c == 0 ? sigma : 0.0, 1e-7 * sigma)
            << "element " << e + 1 << " point " << q + 1 << " component " << c;
}

INSTANTIATE_TEST_SUITE_P(VerificationContinuum, VerificationContinuumPlate,
                         ::testing::Values("C3D8", "C3D10", "C3D4"),
                         [](const auto& info) { return info.param; });

/// Lame thick cylinder under internal pressure p, plane strain (eps_z = 0):
///   sigma_r = A - B / r^2, sigma_t = A + B / r^2, A = p a^2 / (b^2 - a^2), B = p a^2 b^2 / (b^2 -
///   a^2) u_r = (1 + nu) / E * ((1 - 2 nu) A r + B / r)
struct Lame {
  double a, b, p;
  double A() const { return p * a * a / (b * b - a * a); }
  double B() const { return p * a * a * b * b / (b * b - a * a); }
  double u(double r) const { return (1 + kNu) / kE * ((1 - 2 * kNu) * A() * r + B() / r); }
  double hoop(double r) const { return A() + B() / (r * r); }
  double radial(double r) const { return A() - B() / (r * r); }
};

// Mesh-size tolerance: bilinear elements converge as O(h^2) in displacement and, at the Gauss
// points, in stress. With h = (b - a) / 20 = 0.5 and the solution's length scale a = 10 the
// expected relative error is of order (h / a)^2 = 2.5e-3; the polygonal boundary of the CPE4
// quarter ring (24 segments over 90 degrees) adds a chord error (dtheta)^2 / 8 = 5e-4. We allow 1 %
// for displacements and 2 % for Gauss-point hoop stresses (compared with the exact value at the
// point's own radius, so no extrapolation error enters).
constexpr double kDispTol = 0.01, kStressTol = 0.02;

TEST(VerificationContinuumLame, AxisymmetricCAX4) {
  const Lame lame{10.0, 20.0, 100.0};
  const int nr = 20;
  const double h = 1.0;
  DeckMesh m;
  m.type = "CAX4";
  for (int k = 0; k <= 1; ++k)
    for (int i = 0; i <= nr; ++i) m.add_node(lame.a + (lame.b - lame.a) * i / nr, h * k, 0.0);
  for (int i = 0; i < nr; ++i) m.elems.push_back({i + 1, i + 2, nr + 1 + i + 2, nr + 1 + i + 1});
  std::string deck = "*HEADING\nLame cylinder, CAX4\n" + m.text();
  deck += m.nset("ALLN", [](const auto&) { return true; });
  deck += material_block("*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n");
  // eps_z = 0 (plane strain cylinder): u_z = 0 on both end planes, i.e. at every node here.
  deck += "*BOUNDARY\nALLN, 2\n*STEP\n*STATIC\n*DLOAD\n1, P4, 100.\n";
  deck += "*EL PRINT\nS, E\n*NODE PRINT\nU, RF\n*END STEP\n";
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  const Frame& f = last_frame(r);
  const double u_in = f.nodes.U[r.model->mesh.find_node(1)][0];
  const double u_out = f.nodes.U[r.model->mesh.find_node(nr + 1)][0];
  EXPECT_NEAR(u_in, lame.u(lame.a), kDispTol * lame.u(lame.a));
  EXPECT_NEAR(u_out, lame.u(lame.b), kDispTol * lame.u(lame.b));
  // Element 1, points 1 (r = a + (1 - 1/sqrt 3) h_r / 2): hoop stress is component 3 (S33).
  const double hr = (lame.b - lame.a) / nr;
  const double r1 = lame.a + 0.5 * hr * (1 - 1 / std::sqrt(3.0));
  EXPECT_NEAR(element_value(r, f, 1, ElemVar::S, 2, 0), lame.hoop(r1), kStressTol * lame.hoop(r1));
}

TEST(VerificationContinuumLame, PlaneStrainCPE4QuarterRing) {
  const Lame lame{10.0, 20.0, 100.0};
  const int nr = 20, nt = 24;
  DeckMesh m;
  m.type = "CPE4";
  auto id = [&](int i, int j) { return 1 + i + (nr + 1) * j; };
  for (int j = 0; j <= nt; ++j)
    for (int i = 0; i <= nr; ++i) {
      const double rr = lame.a + (lame.b - lame.a) * i / nr;
      const double t = 0.5 * std::numbers::pi * j / nt;
      m.add_node(rr * std::cos(t), rr * std::sin(t), 0.0);
    }
  for (int j = 0; j < nt; ++j)
    for (int i = 0; i < nr; ++i)
      m.elems.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  std::string deck = "*HEADING\nLame cylinder, CPE4 quarter ring\n" + m.text();
  deck += m.nset("XSYM", [](const auto& p) { return std::abs(p[0]) < 1e-9; });
  deck += m.nset("YSYM", [](const auto& p) { return std::abs(p[1]) < 1e-9; });
  deck += material_block("*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n1.\n");
  deck += "*BOUNDARY\nXSYM, 1\nYSYM, 2\n*STEP\n*STATIC\n*DLOAD\n";
  for (int j = 0; j < nt; ++j) deck += fmt::format("{}, P4, 100.\n", 1 + j * nr);
  deck += "*EL PRINT\nS, E\n*NODE PRINT\nU, RF\n*END STEP\n";
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  const Frame& f = last_frame(r);
  for (int j : {0, nt / 2, nt}) {
    const Vec3& ui = f.nodes.U[r.model->mesh.find_node(id(0, j))];
    const Vec3& uo = f.nodes.U[r.model->mesh.find_node(id(nr, j))];
    EXPECT_NEAR(std::hypot(ui[0], ui[1]), lame.u(lame.a), kDispTol * lame.u(lame.a)) << j;
    EXPECT_NEAR(std::hypot(uo[0], uo[1]), lame.u(lame.b), kDispTol * lame.u(lame.b)) << j;
  }
  // Element on the x axis next to the bore: at its Gauss point 1 (near node 1, at the angle
  // theta_q ~ small) the hoop stress is sigma_t(r_q) rotated into x-y: S22 ~ sigma_t cos^2 + ...
  // Compare the invariant-free combination S11 + S22 = sigma_r + sigma_t at the point's radius.
  const double hr = (lame.b - lame.a) / nr;
  const double g = 0.5 * (1 - 1 / std::sqrt(3.0));
  const double rq = lame.a + g * hr; // approximately: the element is a thin trapezoid
  const double sum =
      element_value(r, f, 1, ElemVar::S, 0, 0) + element_value(r, f, 1, ElemVar::S, 1, 0);
  EXPECT_NEAR(sum, lame.hoop(rq) + lame.radial(rq), kStressTol * lame.hoop(lame.a));
  // Exact sigma_33 = nu (sigma_r + sigma_t) = 2 nu A, constant. B-bar makes the dilatation (and so
  // the pressure) element-constant while the deviatoric eps33 = (theta_bar - theta) / 3 varies, so
  // S33 carries the O(h) deviatoric error of the element next to the bore: judged against the peak
  // stress sigma_t(a) like the other stresses.
  EXPECT_NEAR(element_value(r, f, 1, ElemVar::S, 2, 0), 2 * kNu * lame.A(),
              kStressTol * lame.hoop(lame.a));
}

// Thermal strain with *TEMPERATURE: a C3D8 bar (6 x 2 x 2, perturbed interior nodes) heated from
// 20 to 120, held axially between x = 0 and x = L (U1 = 0 at both ends) and free laterally
// (symmetry planes y = 0, z = 0 only). Exact homogeneous state: eps11 = 0, sigma22 = sigma33 = 0,
// so sigma11 = -E alpha dT, and the lateral strains are (1 + nu) alpha dT: u2 = (1 + nu) alpha dT
// y, u3 = (1 + nu) alpha dT z. A homogeneous field is exact for any mesh: relative tolerance 1e-7.
TEST(VerificationContinuumThermal, HeatedBarHeldBetweenWalls) {
  const double dT = 100.0, eth = kAlpha * dT, L = 6.0;
  DeckMesh m;
  m.type = "C3D8";
  for (const auto& c : block_cells(m, 3, 2, 2, L, 2.0, 2.0))
    m.elems.push_back({c.begin(), c.end()});
  auto near = [](double v, double w) { return std::abs(v - w) < 1e-9; };
  std::string deck = "*HEADING\nheated bar between walls\n" + m.text();
  deck += m.nset("ALLN", [](const auto&) { return true; });
  deck += m.nset("XEND", [&](const auto& p) { return near(p[0], 0) || near(p[0], L); });
  deck += m.nset("Y0", [&](const auto& p) { return near(p[1], 0); });
  deck += m.nset("Z0", [&](const auto& p) { return near(p[2], 0); });
  deck += material_block("*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n");
  deck += "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nALLN, 20.\n";
  deck += "*BOUNDARY\nXEND, 1\nY0, 2\nZ0, 3\n";
  deck +=
      "*STEP\n*STATIC\n*TEMPERATURE\nALLN, 120.\n*EL PRINT\nS, E\n*NODE PRINT\nU, RF\n*END STEP\n";
  const JobResult r = run_deck(deck);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  const Frame& f = last_frame(r);
  for (std::size_t e = 0; e < m.elems.size(); ++e)
    for (int q = 0; q < 8; ++q)
      for (int c = 0; c < 6; ++c)
        EXPECT_NEAR(element_value(r, f, static_cast<Label>(e + 1), ElemVar::S, c, q),
                    c == 0 ? -kE * eth : 0.0, 1e-7 * kE * eth)
            << "element " << e + 1 << " point " << q + 1 << " component " << c;
  for (std::size_t n = 0; n < m.nodes.size(); ++n) {
    const Vec3& u = f.nodes.U[r.model->mesh.find_node(static_cast<Label>(n + 1))];
    EXPECT_NEAR(u[0], 0.0, 1e-7 * eth * L);
    EXPECT_NEAR(u[1], (1 + kNu) * eth * m.nodes[n][1], 1e-7 * eth * L);
    EXPECT_NEAR(u[2], (1 + kNu) * eth * m.nodes[n][2], 1e-7 * eth * L);
  }
}

} // namespace
} // namespace gapfem::test
