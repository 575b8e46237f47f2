// Parts, assembly and instances (issue 12): a deck in Abaqus/CAE's layout — one part instanced
// three times (as is, translated, translated and rotated), gap elements between instances and to
// an assembly-level reference point, assembly sets with INSTANCE=, history data naming instance
// nodes and sets — against the equivalent flat deck written out by the test (the same nodes with
// their placed coordinates, numbered 1.., 101.., 201..): the same answer to 1e-10.
#include "test_util.hpp"

#include <array>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

using namespace gapfem;
using namespace gapfem::test;

namespace {

// The part: two C3D8 along x, 2 x 1 x 1. Node n = 1 + ix + 3 iy + 6 iz.
Vec3 part_node(int n) {
  const int k = n - 1;
  return {double(k % 3), double((k / 3) % 2), double(k / 6)};
}
std::array<int, 8> part_element(int e) { // e = 1, 2
  const int o = e - 1;
  return {1 + o, 2 + o, 5 + o, 4 + o, 7 + o, 8 + o, 11 + o, 10 + o};
}

// Instance placements: A as is, B translated (0, 0, 1.5), C translated (2, 0, 0) and then
// rotated by 90 degrees about the z axis through the origin: (x, y, z) -> (-y, x, z).
Vec3 place(char inst, const Vec3& X) {
  if (inst == 'A') return X;
  if (inst == 'B') return {X[0], X[1], X[2] + 1.5};
  const Vec3 t{X[0] + 2.0, X[1], X[2]};
  return {-t[1], t[0], t[2]};
}
int flat_offset(char inst) {
  return inst == 'A' ? 0 : inst == 'B' ? 100 : 200;
}

const char* kMaterial = "*MATERIAL, NAME=STEEL\n*ELASTIC\n1000., 0.3\n";

// Gaps: A's top corners to B's bottom (d = 0.1, direction from the coordinates: +z), and C's
// tip to the reference point (given direction -x, d = 0.05).
const int kGapPairs[4][2] = {{7, 1}, {8, 2}, {9, 3}, {12, 6}};

std::string steps(const std::string& b_top, const std::string& a_bot, const std::string& c_bot,
                  const std::string& c_tip, const std::string& rp) {
  return fmt::format(R"(*BOUNDARY
{0}, 1, 3
{1}, 1, 3
{3}, 1, 3
*STEP, NLGEOM
*STATIC
0.25, 1.
*BOUNDARY
{2}, 1, 2
{2}, 3, 3, -0.3
*CLOAD
{4}, 1, -5.
*NODE PRINT
U
*EL PRINT, ELSET=GAPS
S, E
*END STEP
)",
                     a_bot, c_bot, b_top, rp, c_tip);
}

std::string assembly_deck() {
  std::string d =
      "*HEADING\nthree instances of one part, gaps between them\n*PART, NAME=BAR\n*NODE\n";
  for (int n = 1; n <= 12; ++n) {
    const Vec3 x = part_node(n);
    d += fmt::format("{}, {}, {}, {}\n", n, x[0], x[1], x[2]);
  }
  d += "*ELEMENT, TYPE=C3D8, ELSET=ALL\n";
  for (int e = 1; e <= 2; ++e) {
    const auto c = part_element(e);
    d += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", e, c[0], c[1], c[2], c[3], c[4], c[5],
                     c[6], c[7]);
  }
  d += "*NSET, NSET=BOT, GENERATE\n1, 6, 1\n*NSET, NSET=TOP, GENERATE\n7, 12, 1\n"
       "*NSET, NSET=TIP\n3, 6, 9, 12\n** Section: one per part\n"
       "*SOLID SECTION, ELSET=ALL, MATERIAL=STEEL\n,\n*END PART\n"
       "*ASSEMBLY, NAME=ASSEMBLY\n*INSTANCE, NAME=A, PART=BAR\n*END INSTANCE\n"
       "*INSTANCE, NAME=B, PART=BAR\n0., 0., 1.5\n*END INSTANCE\n"
       "*INSTANCE, NAME=C, PART=BAR\n2., 0., 0.\n0., 0., 0., 0., 0., 1., 90.\n*END INSTANCE\n"
       "*NODE\n1, -1.5, 2.5, 0.5\n*NSET, NSET=RP\n1\n";
  d += "*ELEMENT, TYPE=GAPUNI, ELSET=GAP-AB\n";
  for (int g = 0; g < 4; ++g)
    d += fmt::format("{}, A.{}, B.{}\n", 1001 + g, kGapPairs[g][0], kGapPairs[g][1]);
  d += "*ELEMENT, TYPE=GAPUNI, ELSET=GAP-C\n2001, C.12, 1\n"
       "*ELSET, ELSET=GAPS\nGAP-AB, GAP-C\n"
       "*NSET, NSET=B-TOP, INSTANCE=B\nTOP\n"
       "*NSET, NSET=C-BASE, INSTANCE=C\n1, 4, 7, 10\n"
       "*END ASSEMBLY\n";
  d += kMaterial;
  d += "*GAP, ELSET=GAP-AB\n0.1, , , , 1.\n*GAP, ELSET=GAP-C\n0.05, -1., 0., 0., 1.\n";
  return d + steps("B-TOP", "A.BOT", "C-BASE", "C.9", "RP");
}

std::string flat_deck() {
  std::string d = "*HEADING\nthe same model, flat\n*NODE\n";
  for (char inst : {'A', 'B', 'C'})
    for (int n = 1; n <= 12; ++n) {
      const Vec3 x = place(inst, part_node(n));
      d += fmt::format("{}, {:.17g}, {:.17g}, {:.17g}\n", flat_offset(inst) + n, x[0], x[1], x[2]);
    }
  d += "1000, -1.5, 2.5, 0.5\n*ELEMENT, TYPE=C3D8, ELSET=ALL\n";
  for (char inst : {'A', 'B', 'C'})
    for (int e = 1; e <= 2; ++e) {
      const auto c = part_element(e);
      const int o = flat_offset(inst);
      d += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", o + e, o + c[0], o + c[1], o + c[2],
                       o + c[3], o + c[4], o + c[5], o + c[6], o + c[7]);
    }
  d += "*SOLID SECTION, ELSET=ALL, MATERIAL=STEEL\n";
  d += kMaterial;
  d += "*ELEMENT, TYPE=GAPUNI, ELSET=GAP-AB\n";
  for (int g = 0; g < 4; ++g)
    d += fmt::format("{}, {}, {}\n", 1001 + g, kGapPairs[g][0], 100 + kGapPairs[g][1]);
  d += "*ELEMENT, TYPE=GAPUNI, ELSET=GAP-C\n2001, 212, 1000\n*ELSET, ELSET=GAPS\nGAP-AB, GAP-C\n"
       "*GAP, ELSET=GAP-AB\n0.1, , , , 1.\n*GAP, ELSET=GAP-C\n0.05, -1., 0., 0., 1.\n"
       "*NSET, NSET=B-TOP, GENERATE\n107, 112, 1\n*NSET, NSET=A-BOT, GENERATE\n1, 6, 1\n"
       "*NSET, NSET=C-BASE\n201, 204, 207, 210\n";
  return d + steps("B-TOP", "A-BOT", "C-BASE", "209", "1000");
}

} // namespace

TEST(Assembly, InstancedPartsGiveTheFlatDecksAnswer) {
  const JobResult a = run_deck_exact(assembly_deck(), "assembly", true);
  const JobResult f = run_deck_exact(flat_deck(), "flat");
  ASSERT_EQ(a.exit_code, 0) << a.error;
  ASSERT_EQ(f.exit_code, 0) << f.error;
  const Model& ma = *a.model;
  ASSERT_EQ(ma.instances, (std::vector<std::string>{"A", "B", "C"}));
  ASSERT_EQ(ma.mesh.n_nodes(), f.model->mesh.n_nodes());
  const Frame& fa = last_frame(a);
  const Frame& ff = last_frame(f);
  double scale = 0.0;
  for (const Vec3& u : ff.nodes.U)
    scale = std::max({scale, std::abs(u[0]), std::abs(u[1]), std::abs(u[2])});
  int inst = 0;
  for (char name : {'A', 'B', 'C'}) {
    ++inst;
    for (int n = 1; n <= 12; ++n) {
      const NodeId na = ma.mesh.find_node(make_key(inst, n));
      const NodeId nf = f.model->mesh.find_node(flat_offset(name) + n);
      ASSERT_GE(na, 0);
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(ma.mesh.coords[na][k], f.model->mesh.coords[nf][k], 1e-14) << name << n;
        EXPECT_NEAR(fa.nodes.U[na][k], ff.nodes.U[nf][k], 1e-10 * scale) << name << "." << n;
      }
    }
  }
  for (Label g : {1001, 1002, 1003, 1004, 2001}) {
    const GapRecord& ga = gap(a, fa, g);
    const GapRecord& gf = gap(f, ff, g);
    EXPECT_EQ(ga.status, gf.status) << g;
    EXPECT_NEAR(ga.normal_force, gf.normal_force, 1e-10 * (1 + std::abs(gf.normal_force))) << g;
  }
  // the gaps between A and B are closed (B pressed down by 0.3 against a clearance of 0.1)
  EXPECT_NE(gap(a, fa, 1001).status, ContactStatus::Open);
  // output names instance nodes and elements as Abaqus does
  std::ifstream dat(test_dir() / "assembly.dat");
  std::stringstream text;
  text << dat.rdbuf();
  EXPECT_NE(text.str().find("C.12"), std::string::npos) << "instance node names in job.dat";
  std::ifstream json(test_dir() / "assembly.results.json");
  std::stringstream jtext;
  jtext << json.rdbuf();
  EXPECT_NE(jtext.str().find("\"B.7\":"), std::string::npos) << "instance node keys in the JSON";
}

TEST(Assembly, BadInstancesAndQualifiedReferencesAreInputErrors) {
  const std::string part =
      "*PART, NAME=P\n*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=T3D2, ELSET=E\n1, 1, 2\n"
      "*SOLID SECTION, ELSET=E, MATERIAL=M\n1.\n*END PART\n";
  const std::string tail = "*MATERIAL, NAME=M\n*ELASTIC\n1., 0.3\n*STEP\n*STATIC\n*END STEP\n";
  auto error_of = [&](const std::string& assembly) {
    const JobResult r =
        run_deck(part + "*ASSEMBLY, NAME=ASM\n" + assembly + "*END ASSEMBLY\n" + tail);
    EXPECT_EQ(r.exit_code, kExitInputError) << assembly;
    return r.error;
  };
  EXPECT_NE(error_of("*INSTANCE, NAME=I, PART=Q\n*END INSTANCE\n").find("part Q is not defined"),
            std::string::npos);
  EXPECT_NE(error_of("*INSTANCE, NAME=I, PART=P\n*END INSTANCE\n*INSTANCE, NAME=I, PART=P\n"
                     "*END INSTANCE\n")
                .find("instance I is defined twice"),
            std::string::npos);
  EXPECT_NE(error_of("*INSTANCE, NAME=I, PART=P\n*END INSTANCE\n*NSET, NSET=S\nJ.1\n")
                .find("instance J is not defined"),
            std::string::npos);
  EXPECT_NE(error_of("*INSTANCE, NAME=I, PART=P\n*END INSTANCE\n*NSET, NSET=S\nI.7\n")
                .find("node I.7: instance I (part P) has no node 7; check the number"),
            std::string::npos);
  const std::string rot = error_of("*INSTANCE, NAME=I, PART=P\n0., 0., 0.\n1., 1., 1., 1., 1., 1., "
                                   "30.\n*END INSTANCE\n");
  EXPECT_NE(rot.find("the two points of the rotation axis coincide"), std::string::npos) << rot;
  EXPECT_NE(rot.find(":"), std::string::npos); // file:line
  // a keyword that cannot be inside a part
  const JobResult r = run_deck("*PART, NAME=P\n*MATERIAL, NAME=M\n*END PART\n*ASSEMBLY, NAME=A\n"
                               "*INSTANCE, NAME=I, PART=P\n*END INSTANCE\n*END ASSEMBLY\n" +
                               tail);
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("*MATERIAL cannot appear inside *PART"), std::string::npos) << r.error;
}

TEST(Assembly, DeckInTheAbaqusCaeLayoutRuns) {
  // tests/verification/assembly/cae_layout.inp: two placed instances of a block on eight GAPUNI
  // supports at assembly level, a surface of internal instance sets, *Restart, write,
  // frequency=0 and PRESELECT output requests as Abaqus/CAE writes them
  JobOptions o;
  o.deck = std::filesystem::path(GAPFEM_TEST_DIR) / "verification/assembly/cae_layout.inp";
  o.write_files = false;
  o.quiet = true;
  const JobResult r = run_job(o);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Model& m = *r.model;
  // Block-2.1: (0,0,0) + (3,0,0), turned by 90 degrees about the vertical through (3.5, 0.5)
  const Vec3& x = m.mesh.coords[m.mesh.find_node(make_key(2, 1))];
  EXPECT_NEAR(x[0], 4.0, 1e-12);
  EXPECT_NEAR(x[1], 0.0, 1e-12);
  EXPECT_NEAR(x[2], 0.0, 1e-12);
  // pressure 10 on each 1 x 1 top: every support carries a quarter
  const Frame& f = last_frame(r);
  for (Label g : {101, 102, 103, 104, 201, 202, 203, 204})
    EXPECT_NEAR(gap(r, f, g).normal_force, 2.5, 1e-9) << g;
  EXPECT_EQ(m.warnings.size(), 1u) << "the *Preprint note (*OUTPUT, HISTORY is read)";
}

TEST(Assembly, CaeLayoutTieAndCouplingAtAssemblyLevel) {
  // tests/verification/assembly/cae_constraints.inp: a cap tied (surface to surface, non-matching
  // meshes) on a base block, the cap's top kinematically coupled in DOF 3 to a reference point
  // pushed down by 20; surfaces of internal instance element sets, as Abaqus/CAE writes them.
  // Closed form: uniaxial stress -20 over the unit section, E = 1000, nu = 0.3:
  // u3 = -0.02 z, u1 = 0.006 x, u2 = 0.006 y everywhere (exact for C3D8 and the mortar tie).
  JobOptions o;
  o.deck = std::filesystem::path(GAPFEM_TEST_DIR) / "verification/assembly/cae_constraints.inp";
  o.write_files = false;
  o.quiet = true;
  const JobResult r = run_job(o);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const Model& m = *r.model;
  const Frame& f = last_frame(r);
  ASSERT_EQ(m.mesh.n_nodes(), 27 + 32 + 1);
  for (NodeId n = 0; n < m.mesh.n_nodes(); ++n) {
    const Vec3& X = m.mesh.coords[n];
    const Vec3& u = f.nodes.U[n];
    const std::string name = m.node_label(n).str();
    if (name == "1") { // the reference point follows the cap's top (z = 1.5)
      EXPECT_NEAR(u[2], -0.03, 1e-12);
      continue;
    }
    EXPECT_NEAR(u[0], 0.006 * X[0], 1e-12) << name;
    EXPECT_NEAR(u[1], 0.006 * X[1], 1e-12) << name;
    EXPECT_NEAR(u[2], -0.02 * X[2], 1e-12) << name;
  }
}
