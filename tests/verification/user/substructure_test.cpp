// Substructures (docs/substructures.md): a block of C3D8 reduced to its top nodes and used with
// frictional GAPUNI, GAPSPHER and GAPCYL gaps and a truss gives the full model's answers to 1e-10
// (displacements, gap forces, reactions) through gaps closing, sliding and opening; placed copies
// (translated, rotated, reflected) give the answers of the full model with the copies meshed;
// recovery gives the internal displacements and stresses of the full model; the reduced stiffness
// brought in as *MATRIX INPUT gives the same answers again; bad substructures are input errors.
#include "model/substructure_file.hpp"
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

using namespace gapfem;
using namespace gapfem::test;

namespace {

namespace fs = std::filesystem;

/// A block of nx x ny x nz C3D8 (10 x 10 x 12 cells of 1 x 1 x 1 ... scaled), fixed at its base.
struct Block {
  int nx = 3, ny = 2, nz = 4;
  double h = 10.0;
  int id(int x, int y, int z) const { return 1 + x + (nx + 1) * (y + (ny + 1) * z); }
  std::vector<int> top() const {
    std::vector<int> t;
    for (int y = 0; y <= ny; ++y)
      for (int x = 0; x <= nx; ++x) t.push_back(id(x, y, nz));
    return t;
  }
  Vec3 X(int n) const {
    const int k = n - 1, x = k % (nx + 1), y = (k / (nx + 1)) % (ny + 1),
              z = k / ((nx + 1) * (ny + 1));
    return {x * h, y * h * 0.8, z * h * 1.1};
  }
  /// The mesh with node and element numbers shifted by `offset`, coordinates placed by x' = R x +
  /// t.
  std::string mesh(int offset = 0, const std::array<double, 9>& R = {1, 0, 0, 0, 1, 0, 0, 0, 1},
                   const Vec3& t = {}) const {
    std::string d = "*NODE\n";
    for (int n = 1; n <= (nx + 1) * (ny + 1) * (nz + 1); ++n) {
      const Vec3 x = X(n);
      Vec3 y = t;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) y[i] += R[i * 3 + j] * x[j];
      d += fmt::format("{}, {:.17g}, {:.17g}, {:.17g}\n", n + offset, y[0], y[1], y[2]);
    }
    d += fmt::format("*ELEMENT, TYPE=C3D8, ELSET=SOLID{}\n", offset);
    // a reflected copy keeps its cells right-handed with the node order of each face reversed
    const double det = R[0] * (R[4] * R[8] - R[5] * R[7]) - R[1] * (R[3] * R[8] - R[5] * R[6]) +
                       R[2] * (R[3] * R[7] - R[4] * R[6]);
    int e = 1;
    for (int z = 0; z < nz; ++z)
      for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
          int c[8] = {
              id(x, y, z),     id(x + 1, y, z),     id(x + 1, y + 1, z),     id(x, y + 1, z),
              id(x, y, z + 1), id(x + 1, y, z + 1), id(x + 1, y + 1, z + 1), id(x, y + 1, z + 1)};
          if (det < 0) {
            std::swap(c[1], c[3]);
            std::swap(c[5], c[7]);
          }
          d += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", offset + e++, offset + c[0],
                           offset + c[1], offset + c[2], offset + c[3], offset + c[4],
                           offset + c[5], offset + c[6], offset + c[7]);
        }
    d += fmt::format("*SOLID SECTION, ELSET=SOLID{}, MATERIAL=STEEL\n", offset);
    d += fmt::format("*NSET, NSET=BASE{}, GENERATE\n{}, {}, 1\n", offset, offset + 1,
                     offset + (nx + 1) * (ny + 1));
    return d;
  }
  std::string generation(const std::string& type = "Z1") const {
    std::string d = "*HEADING\nblock reduced to its top\n" + mesh();
    d += "*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n*BOUNDARY\nBASE0, 1, 3\n";
    d += fmt::format("*STEP\n*SUBSTRUCTURE GENERATE, TYPE={}\n*RETAINED NODAL DOFS\n", type);
    for (int n : top()) d += fmt::format("{}, 1, 3\n", n);
    return d + "*END STEP\n";
  }
};

/// The top's surroundings: ground nodes, gaps of three types with friction, a truss across the
/// top, and two steps of loads (into the gaps and sideways, then mostly released).
std::string surroundings(const Block& b, int offset, const std::array<double, 9>& R, const Vec3& t,
                         const std::string& tag) {
  auto place = [&](const Vec3& x) {
    Vec3 y = t;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) y[i] += R[i * 3 + j] * x[j];
    return y;
  };
  auto dir = [&](const Vec3& x) {
    Vec3 y{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) y[i] += R[i * 3 + j] * x[j];
    return y;
  };
  const std::vector<int> top = b.top();
  std::string d = fmt::format("*NODE, NSET=GROUND{}\n", tag);
  for (std::size_t i = 0; i < top.size(); ++i) {
    const Vec3 g = place({b.X(top[i])[0], b.X(top[i])[1], b.X(top[i])[2] + 1.0});
    d += fmt::format("{}, {:.17g}, {:.17g}, {:.17g}\n", offset + 500 + i, g[0], g[1], g[2]);
  }
  const Vec3 up = dir({0, 0, 1}), axis = dir({1, 0, 0});
  d += fmt::format("*ELEMENT, TYPE=GAPUNI, ELSET=UNI{}\n", tag);
  for (std::size_t i = 0; i + 2 < top.size(); ++i)
    d += fmt::format("{}, {}, {}\n", offset + 600 + i, offset + top[i], offset + 500 + i);
  d += fmt::format("*ELEMENT, TYPE=GAPSPHER, ELSET=SPH{}\n{}, {}, {}\n", tag, offset + 700,
                   offset + top[top.size() - 2], offset + 500 + top.size() - 2);
  d += fmt::format("*ELEMENT, TYPE=GAPCYL, ELSET=CYL{}\n{}, {}, {}\n", tag, offset + 701,
                   offset + top.back(), offset + 500 + top.size() - 1);
  for (std::size_t i = 0; i + 2 < top.size(); ++i)
    d +=
        fmt::format("*ELSET, ELSET=G{}_{}\n{}\n*GAP, ELSET=G{}_{}\n{:.17g}, {:.17g}, {:.17g}, "
                    "{:.17g}, 4.\n*FRICTION, ELASTIC SLIP=0.0005\n0.25\n",
                    tag, i, offset + 600 + i, tag, i, 0.002 + 0.003 * (i % 4), up[0], up[1], up[2]);
  // the sphere and the cylinder keep the nodes at least 0.99 and 0.985 apart (1 at the start)
  d += fmt::format("*GAP, ELSET=SPH{}\n-0.99\n*GAP, ELSET=CYL{}\n-0.985, {:.17g}, {:.17g}, "
                   "{:.17g}\n",
                   tag, tag, axis[0], axis[1], axis[2]);
  d += fmt::format("*ELEMENT, TYPE=T3D2, ELSET=TIE{}\n{}, {}, {}\n*SOLID SECTION, ELSET=TIE{}, "
                   "MATERIAL=STEEL\n2.\n",
                   tag, offset + 800, offset + top.front(), offset + top.back(), tag);
  return d;
}

std::string steps(const Block& b,
                  const std::vector<std::pair<int, std::array<double, 9>>>& copies) {
  std::string d;
  for (const double f : {1.0, 0.15}) {
    // the same increments in both models (friction makes the answer depend on the path) and a
    // tight convergence (the two take different Newton paths through the contact changes, so
    // they agree to the convergence tolerance, here far below 1e-10)
    d += "*STEP, INC=200\n*STATIC, DIRECT\n0.1, 1.\n*CONTROLS, PARAMETERS=FIELD\n1e-10, 1e-8, , , "
         ", , "
         ", 1e-11\n*CLOAD\n";
    for (const auto& [offset, R] : copies) {
      const std::vector<int> top = b.top();
      for (std::size_t i = 0; i < top.size(); ++i) {
        const Vec3 l{f * 300.0 * std::sin(1.0 + i), f * 200.0 * std::cos(2.0 + i),
                     f * (6000.0 + 800.0 * i)};
        for (int c = 0; c < 3; ++c) {
          double v = 0.0;
          for (int j = 0; j < 3; ++j) v += R[c * 3 + j] * l[j];
          d += fmt::format("{}, {}, {:.17g}\n", offset + top[i], c + 1, v);
        }
      }
    }
    d += "*END STEP\n";
  }
  return d;
}

const std::array<double, 9> kI{1, 0, 0, 0, 1, 0, 0, 0, 1};

/// The usage of the library `gen` for a copy at (offset, R, t): the retained nodes placed, one Z1.
std::string usage_nodes(const Block& b, int offset, const std::array<double, 9>& R, const Vec3& t) {
  std::string d = "*NODE\n";
  for (int n : b.top()) {
    const Vec3 x = b.X(n);
    Vec3 y = t;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) y[i] += R[i * 3 + j] * x[j];
    d += fmt::format("{}, {:.17g}, {:.17g}, {:.17g}\n", offset + n, y[0], y[1], y[2]);
  }
  d += fmt::format("*ELEMENT, TYPE=Z1, ELSET=SUB{}, FILE=gen\n{}", offset, offset + 1000);
  int k = 0;
  for (int n : b.top()) d += fmt::format("{}{}", ++k % 12 == 0 ? ",\n" : ", ", offset + n);
  return d + "\n";
}

JobResult run_in(const fs::path& dir, const std::string& name, const std::string& deck) {
  std::ofstream(dir / (name + ".inp")) << deck;
  JobOptions o;
  o.deck = dir / (name + ".inp");
  o.quiet = true;
  o.write_vtu = false;
  o.factor_reuse = FactorReuse::Never;
  return run_job(o);
}

/// Largest difference of the field `get` over the frames, relative to its largest value.
template <typename Get>
double worst(const JobResult& a, const JobResult& b, const std::vector<Label>& nodes, Get get) {
  double d = 0.0, s = 0.0;
  for (std::size_t f = 0; f < a.frames.size(); ++f)
    for (Label n : nodes) {
      const Vec3 &x = get(a.frames[f].nodes)[a.model->mesh.find_node(n)],
                 &y = get(b.frames[f].nodes)[b.model->mesh.find_node(n)];
      for (int c = 0; c < 3; ++c) {
        d = std::max(d, std::abs(x[c] - y[c]));
        s = std::max(s, std::abs(x[c]));
      }
    }
  return s > 0 ? d / s : d;
}

void expect_same(const JobResult& full, const JobResult& used, const std::vector<Label>& nodes,
                 const std::vector<Label>& grounds, const std::vector<Label>& gaps) {
  ASSERT_EQ(full.exit_code, 0) << full.error;
  ASSERT_EQ(used.exit_code, 0) << used.error;
  ASSERT_EQ(full.frames.size(), used.frames.size());
  EXPECT_LE(worst(
                full, used, nodes, [](const NodeResults& r) -> auto& { return r.U; }),
            1e-10);
  EXPECT_LE(worst(
                full, used, grounds, [](const NodeResults& r) -> auto& { return r.RF; }),
            1e-10);
  int closed = 0, opened = 0, slipping = 0;
  double scale = 1.0; // the largest gap force
  for (Label g : gaps) scale = std::max(scale, gap(full, last_frame(full, 1), g).normal_force);
  for (Label g : gaps) {
    const GapRecord &a1 = gap(full, last_frame(full, 1), g),
                    &b1 = gap(used, last_frame(used, 1), g);
    const GapRecord &a2 = gap(full, last_frame(full, 2), g),
                    &b2 = gap(used, last_frame(used, 2), g);
    EXPECT_EQ(a1.status, b1.status) << "gap " << g;
    EXPECT_EQ(a2.status, b2.status) << "gap " << g;
    EXPECT_NEAR(a1.normal_force, b1.normal_force, 1e-10 * scale) << "gap " << g;
    EXPECT_NEAR(a2.normal_force, b2.normal_force, 1e-10 * scale) << "gap " << g;
    closed += a1.status != ContactStatus::Open;
    opened += a1.status != ContactStatus::Open && a2.status == ContactStatus::Open;
    slipping += a1.status == ContactStatus::Slip || a2.status == ContactStatus::Slip;
  }
  EXPECT_GE(closed, 3) << "too few gaps close: the test would not test contact";
  EXPECT_GE(opened, 1) << "no gap opens again";
}

std::vector<Label> offset_labels(const std::vector<int>& v, int offset, int add = 0) {
  std::vector<Label> out;
  for (std::size_t i = 0; i < v.size(); ++i)
    out.push_back(offset + add + (add ? static_cast<int>(i) : v[i]));
  return out;
}

} // namespace

TEST(Substructure, SplitModelGivesTheFullModelsAnswer) {
  const fs::path dir = test_dir();
  const Block b;
  const JobResult g = run_in(dir, "gen", b.generation());
  ASSERT_EQ(g.exit_code, 0) << g.error;
  ASSERT_TRUE(fs::exists(dir / "gen_Z1.sub"));
  const std::string material = "*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n";
  const std::string around = surroundings(b, 0, kI, {}, "");
  const std::string full = "*HEADING\nfull\n" + b.mesh() + material + around +
                           "*BOUNDARY\nBASE0, 1, 3\nGROUND, 1, 3\n" + steps(b, {{0, kI}});
  const std::string used = "*HEADING\nused\n" + usage_nodes(b, 0, kI, {}) +
                           "*SUBSTRUCTURE PROPERTY, ELSET=SUB0\n0., 0., 0.\n" + material + around +
                           "*BOUNDARY\nGROUND, 1, 3\n" + steps(b, {{0, kI}});
  const JobResult a = run_in(dir, "full", full);
  std::string used_recovered = used;
  used_recovered.replace(used_recovered.rfind("*END STEP"), 9,
                         "*SUBSTRUCTURE PATH\nSUB0\n*END STEP");
  const JobResult u = run_in(dir, "used", used_recovered);
  const std::vector<int> top = b.top();
  std::vector<Label> gaps;
  for (std::size_t i = 0; i + 2 < top.size(); ++i) gaps.push_back(600 + i);
  gaps.push_back(700);
  gaps.push_back(701);
  expect_same(a, u, offset_labels(top, 0), offset_labels(top, 0, 500), gaps);

  // recovery: the inside of the block at the end of step 2, against the full model
  const auto doc = nlohmann::json::parse(slurp(dir / "used_Z1_1000.results.json"));
  EXPECT_TRUE(doc.at("stresses").get<bool>()) << doc.at("note");
  const auto& fr = doc.at("frames").back();
  const Frame& last = last_frame(a, 2);
  double du = 0.0, su = 0.0, ds = 0.0, ss = 0.0;
  for (int n = 1; n <= (b.nx + 1) * (b.ny + 1) * (b.nz + 1); ++n) {
    const auto& x = fr.at("nodes").at(std::to_string(n)).at("U");
    const Vec3& y = U(a, last, n);
    for (int c = 0; c < 3; ++c) {
      du = std::max(du, std::abs(x[c].get<double>() - y[c]));
      su = std::max(su, std::abs(y[c]));
    }
  }
  for (int e = 1; e <= b.nx * b.ny * b.nz; ++e) {
    const auto& x = fr.at("elements").at(std::to_string(e)).at("S");
    const ElementResult* r = last.element(a.model->mesh.find_element(e));
    ASSERT_TRUE(r);
    std::vector<double> avg(6, 0.0);
    const OutputBlock* s = r->data.find(ElemVar::S);
    for (int p = 0; p < s->n_points; ++p)
      for (int c = 0; c < 6; ++c) avg[c] += s->values[p * 6 + c] / s->n_points;
    for (int c = 0; c < 6; ++c) {
      ds = std::max(ds, std::abs(x[c].get<double>() - avg[c]));
      ss = std::max(ss, std::abs(avg[c]));
    }
  }
  EXPECT_LE(du / su, 1e-10);
  EXPECT_LE(ds / ss, 1e-9);
  EXPECT_EQ(doc.at("frames").size(), 1u); // step 2 (the PATH is there) has no field output
                                          // requests: its end only
}

// One library, two placed copies: one translated, one rotated by 90 degrees about a vertical axis
// through a point and reflected; the full model meshes both copies where they are placed.
TEST(Substructure, PlacedCopiesGiveTheFullModelsAnswer) {
  const fs::path dir = test_dir();
  const Block b;
  ASSERT_EQ(run_in(dir, "gen", b.generation()).exit_code, 0);
  const std::string material = "*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n";
  // copy 2: x' = t + Rz(90 about (5, 5, 0)) M x, M the reflection in the plane y = 0
  const std::array<double, 9> M{1, 0, 0, 0, -1, 0, 0, 0, 1}, Rz{0, -1, 0, 1, 0, 0, 0, 0, 1};
  std::array<double, 9> R2{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) R2[i * 3 + j] += Rz[i * 3 + k] * M[k * 3 + j];
  const Vec3 t1{100.0, 0.0, 0.0};
  Vec3 t2{5.0 + 5.0, 5.0 - 5.0, 0.0}; // Rz about (5, 5, 0): x' = Rz (x - c) + c
  t2[0] += 200.0;
  const std::string full =
      "*HEADING\ncopies\n" + b.mesh(10000, kI, t1) + b.mesh(20000, R2, t2) + material +
      surroundings(b, 10000, kI, t1, "A") + surroundings(b, 20000, R2, t2, "B") +
      "*BOUNDARY\nBASE10000, 1, 3\nBASE20000, 1, 3\nGROUNDA, 1, 3\nGROUNDB, 1, 3\n" +
      steps(b, {{10000, kI}, {20000, R2}});
  const std::string used =
      "*HEADING\ncopies\n" + usage_nodes(b, 10000, kI, t1) + usage_nodes(b, 20000, R2, t2) +
      "*SUBSTRUCTURE PROPERTY, ELSET=SUB10000\n100., 0., 0.\n" +
      "*SUBSTRUCTURE PROPERTY, ELSET=SUB20000\n200., 0., 0.\n5., 5., 0., 5., 5., 1., 90.\n"
      "0., 0., 0., 1., 0., 0.\n0., 0., 1.\n" +
      material + surroundings(b, 10000, kI, t1, "A") + surroundings(b, 20000, R2, t2, "B") +
      "*BOUNDARY\nGROUNDA, 1, 3\nGROUNDB, 1, 3\n" + steps(b, {{10000, kI}, {20000, R2}});
  const JobResult a = run_in(dir, "full", full);
  const JobResult u = run_in(dir, "used", used);
  const std::vector<int> top = b.top();
  std::vector<Label> nodes = offset_labels(top, 10000), grounds = offset_labels(top, 10000, 500),
                     gaps;
  for (Label n : offset_labels(top, 20000)) nodes.push_back(n);
  for (Label n : offset_labels(top, 20000, 500)) grounds.push_back(n);
  for (int offset : {10000, 20000}) {
    for (std::size_t i = 0; i + 2 < top.size(); ++i) gaps.push_back(offset + 600 + i);
    gaps.push_back(offset + 700);
    gaps.push_back(offset + 701);
  }
  expect_same(a, u, nodes, grounds, gaps);
}

// The reduced stiffness written as Abaqus's matrix text (lower triangle, one term a line) and
// brought in with *MATRIX INPUT / *MATRIX ASSEMBLE: the same answers as the Z1 element.
TEST(Substructure, MatrixInputOfTheReducedStiffness) {
  const fs::path dir = test_dir();
  const Block b;
  ASSERT_EQ(run_in(dir, "gen", b.generation()).exit_code, 0);
  const SubstructureLibrary lib = read_substructure_file(dir / "gen_Z1.sub", false);
  const SubstructureType& t = lib.type;
  std::vector<std::pair<Label, int>> dofs;
  for (std::size_t a = 0; a < t.node_labels.size(); ++a)
    for (int d : t.node_dofs[a]) dofs.emplace_back(t.node_labels[a], d);
  std::string mtx;
  const std::size_t n = dofs.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j <= i; ++j)
      if (t.stiffness[i * n + j] != 0.0)
        mtx += fmt::format("{}, {}, {}, {}, {:.17g}\n", dofs[i].first, dofs[i].second,
                           dofs[j].first, dofs[j].second, t.stiffness[i * n + j]);
  std::ofstream(dir / "top.mtx") << mtx;
  const std::string material = "*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n";
  const std::string around = surroundings(b, 0, kI, {}, "");
  std::string nodes = usage_nodes(b, 0, kI, {});
  nodes = nodes.substr(0, nodes.find("*ELEMENT"));
  const std::string with_z = "*HEADING\nZ1\n" + usage_nodes(b, 0, kI, {}) +
                             "*SUBSTRUCTURE PROPERTY, ELSET=SUB0\n0., 0., 0.\n" + material +
                             around + "*BOUNDARY\nGROUND, 1, 3\n" + steps(b, {{0, kI}});
  const std::string with_matrix = "*HEADING\nmatrix\n" + nodes +
                                  "*MATRIX INPUT, NAME=TOP, INPUT=top.mtx\n*MATRIX ASSEMBLE, "
                                  "STIFFNESS=TOP\n" +
                                  material + around + "*BOUNDARY\nGROUND, 1, 3\n" +
                                  steps(b, {{0, kI}});
  const JobResult z = run_in(dir, "z", with_z), m = run_in(dir, "m", with_matrix);
  const std::vector<int> top = b.top();
  std::vector<Label> gaps;
  for (std::size_t i = 0; i + 2 < top.size(); ++i) gaps.push_back(600 + i);
  expect_same(z, m, offset_labels(top, 0), offset_labels(top, 0, 500), gaps);
  // The equilibrium self-check counts the force the condensed base supports take (through the Z1
  // element, or the *MATRIX ASSEMBLE terms) as a force to ground: no false alarm (it read 0.2-1
  // of the force scale before).
  for (const JobResult* r : {&z, &m}) {
    ASSERT_EQ(r->steps.size(), 2u);
    for (const StepSummary& s : r->steps) {
      EXPECT_GT(s.checks.force_scale, 0.0);
      EXPECT_LT(s.checks.relative_equilibrium, 1e-9) << "step " << s.step;
    }
  }
}

// What a user gets wrong: each an input error naming what to fix.
TEST(Substructure, BadSubstructuresAreInputErrors) {
  const fs::path dir = test_dir();
  const Block b;
  ASSERT_EQ(run_in(dir, "gen", b.generation()).exit_code, 0);
  // a library generated for another model: the usage nodes are not where its nodes go
  std::string used = "*HEADING\nmoved\n" + usage_nodes(b, 0, kI, {0.5, 0.0, 0.0}) +
                     "*SUBSTRUCTURE PROPERTY, ELSET=SUB0\n0., 0., 0.\n*STEP\n*STATIC\n*END STEP\n";
  JobResult r = run_in(dir, "moved", used);
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("lies 0.5 from where Z1 puts its retained node"), std::string::npos)
      << r.error;
  // no *SUBSTRUCTURE PROPERTY
  r = run_in(dir, "unplaced",
             "*HEADING\n" + usage_nodes(b, 0, kI, {}) + "*STEP\n*STATIC\n*END STEP\n");
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("*SUBSTRUCTURE PROPERTY"), std::string::npos) << r.error;
  // retained DOFs a solid's node does not carry, and a node that does not exist
  std::string gen = b.generation("Z2");
  gen.replace(gen.find("*END STEP"), 9, "1, 4, 6\n*END STEP");
  r = run_in(dir, "rot", gen);
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("node 1 has no DOF 4"), std::string::npos) << r.error;
  gen = b.generation("Z3");
  gen.replace(gen.find("*END STEP"), 9, "99999, 1, 3\n*END STEP");
  r = run_in(dir, "missing", gen);
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("99999"), std::string::npos) << r.error;
  // a retained DOF fixed by a boundary condition
  gen = b.generation("Z4");
  gen.replace(gen.find("*END STEP"), 9, "1, 1, 3\n*END STEP");
  r = run_in(dir, "fixed", gen);
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("fixed by a boundary condition"), std::string::npos) << r.error;
  // a file that is not a gapfem substructure, and one that is damaged
  std::ofstream(dir / "abaqus_Z1.sub") << "an Abaqus .sup library is something else\n";
  r = run_in(dir, "foreign",
             "*HEADING\n" + std::string("*NODE\n1, 0., 0., 0.\n*ELEMENT, TYPE=Z1, FILE=abaqus\n1, "
                                        "1\n*STEP\n*STATIC\n*END STEP\n"));
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("is not a gapfem substructure file"), std::string::npos) << r.error;
  {
    std::string bytes = slurp(dir / "gen_Z1.sub");
    bytes[bytes.size() / 2] ^= 0x5a;
    std::ofstream(dir / "broken_Z1.sub", std::ios::binary) << bytes;
  }
  used = "*HEADING\n" + usage_nodes(b, 0, kI, {});
  used.replace(used.find("FILE=gen"), 8, "FILE=broken");
  r = run_in(dir, "broken",
             used + "*SUBSTRUCTURE PROPERTY, ELSET=SUB0\n0., 0., 0.\n*STEP\n*STATIC\n*END STEP\n");
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("is damaged"), std::string::npos) << r.error;
  // gaps inside the generation model
  gen = b.generation("Z5");
  gen.replace(gen.find("*BOUNDARY"), 9,
              "*NODE\n9999, 0., 0., -1.\n*ELEMENT, TYPE=GAPUNI, ELSET=G\n9999, 1, 9999\n*GAP, "
              "ELSET=G\n0.1, 0., 0., -1.\n*BOUNDARY\n9999, 1, 3\n");
  r = run_in(dir, "gaps", gen);
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("gap elements respond nonlinearly"), std::string::npos) << r.error;
}

// CalculiX's layout: *SUBSTRUCTURE GENERATE without TYPE= (generated as Z1, a warning) and
// *SUBSTRUCTURE MATRIX OUTPUT (an output request: the matrices go to the library, a warning); the
// library is the one TYPE=Z1 writes (the same size: only the deck's name in its header differs).
TEST(Substructure, CalculixGenerationLayout) {
  const fs::path dir = test_dir();
  const Block b;
  std::string ccx = b.generation();
  ccx.replace(ccx.find(", TYPE=Z1"), 9, "");
  ccx.replace(ccx.find("*END STEP"), 0,
              "*SUBSTRUCTURE MATRIX OUTPUT, STIFFNESS=YES, OUTPUT FILE=USER DEFINED, FILE "
              "NAME=mine\n");
  const JobResult c = run_in(dir, "ccx", ccx);
  ASSERT_EQ(c.exit_code, 0) << c.error;
  int warned = 0;
  for (const std::string& w : c.model->warnings)
    warned += w.find("TYPE= is missing") != std::string::npos ||
              w.find("written to the substructure library") != std::string::npos;
  EXPECT_EQ(warned, 2);
  const JobResult g = run_in(dir, "abq", b.generation());
  ASSERT_EQ(g.exit_code, 0) << g.error;
  const std::string mine = slurp(dir / "ccx_Z1.sub"), theirs = slurp(dir / "abq_Z1.sub");
  ASSERT_FALSE(mine.empty());
  EXPECT_EQ(mine.size(), theirs.size());
}
