// job.frd (*NODE FILE / *EL FILE): read back by a fixed-column reader written from CalculiX's
// documented record layout and compared with closed-form states, then read by CalculiX's own
// viewer cgx in batch mode (skipped with a message where cgx is missing; CI installs
// calculix-cgx).
//
// Tension deck: two C3D8 bricks, 2 x 1 x 1, E = 1000, nu = 0.25, 100 pulled on the end face (25 at
// each corner node), symmetry supports only: the exact state is uniform, s11 = 100, e11 = 0.1,
// e22 = e33 = -nu e11 = -0.025, so u = (0.1 x, -0.025 y, -0.025 z) at every node.
// Shear deck: one C3D20 unit cube with u1 = g y prescribed at all 20 nodes (g = 0.01): e12 = g
// (engineering) so the .frd's tensor component EXY = g/2 = 0.005, s12 = G g = 400 x 0.01 = 4.
#include "test_util.hpp"

#include <array>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>
#include <map>
#include <sstream>

namespace gapfem {
namespace {

struct FrdDataset {
  std::string name;
  int step = 0, increment = 0;
  double time = 0.0;
  std::map<long long, std::vector<double>> values;
};

struct FrdFile {
  std::map<long long, std::array<double, 3>> nodes;
  std::map<long long, std::pair<int, std::vector<long long>>> elements;
  std::vector<FrdDataset> datasets;
  bool ended = false;
};

double num(const std::string& line, std::size_t from, std::size_t width) {
  return std::stod(line.substr(from, width));
}
long long integer(const std::string& line, std::size_t from, std::size_t width) {
  return std::stoll(line.substr(from, width));
}

/// The records of CalculiX's frd format, long form: 2C nodes, 3C elements, 1PSTEP/100CL datasets.
FrdFile read_frd(const std::filesystem::path& path) {
  std::ifstream in(path);
  FrdFile f;
  std::string line;
  enum { None, Nodes, Elements, Data } block = None;
  long long elem = 0, node = 0;
  while (std::getline(in, line)) {
    if (line.rfind("    2C", 0) == 0)
      block = Nodes;
    else if (line.rfind("    3C", 0) == 0)
      block = Elements;
    else if (line.rfind("    1PSTEP", 0) == 0) {
      f.datasets.push_back({});
      f.datasets.back().increment = static_cast<int>(integer(line, 36, 12));
      f.datasets.back().step = static_cast<int>(integer(line, 48, 12));
    } else if (line.rfind("  100CL", 0) == 0) {
      f.datasets.back().time = num(line, 12, 12);
      block = Data;
    } else if (line.rfind(" -4", 0) == 0) {
      std::istringstream s(line.substr(5, 8));
      s >> f.datasets.back().name;
    } else if (line.rfind(" -3", 0) == 0)
      block = None;
    else if (line.rfind(" 9999", 0) == 0)
      f.ended = true;
    else if (line.rfind(" -1", 0) == 0 && block == Nodes) {
      f.nodes[integer(line, 3, 10)] = {num(line, 13, 12), num(line, 25, 12), num(line, 37, 12)};
    } else if (line.rfind(" -1", 0) == 0 && block == Elements) {
      elem = integer(line, 3, 10);
      f.elements[elem].first = static_cast<int>(integer(line, 13, 5));
    } else if (line.rfind(" -2", 0) == 0 && block == Elements) {
      for (std::size_t c = 3; c + 10 <= line.size(); c += 10)
        f.elements[elem].second.push_back(integer(line, c, 10));
    } else if ((line.rfind(" -1", 0) == 0 || line.rfind(" -2", 0) == 0) && block == Data) {
      if (line[2] == '1') node = integer(line, 3, 10);
      auto& v = f.datasets.back().values[node];
      for (std::size_t c = 13; c + 12 <= line.size(); c += 12) v.push_back(num(line, c, 12));
    }
  }
  return f;
}

const char* const kTension =
    "*NODE\n"
    "1, 0, 0, 0\n2, 1, 0, 0\n3, 2, 0, 0\n4, 0, 1, 0\n5, 1, 1, 0\n6, 2, 1, 0\n"
    "7, 0, 0, 1\n8, 1, 0, 1\n9, 2, 0, 1\n10, 0, 1, 1\n11, 1, 1, 1\n12, 2, 1, 1\n"
    "*NSET, NSET=END\n3, 6, 9, 12\n"
    "*ELEMENT, TYPE=C3D8, ELSET=BAR\n1, 1, 2, 5, 4, 7, 8, 11, 10\n2, 2, 3, 6, 5, 8, 9, 12, 11\n"
    "*SOLID SECTION, ELSET=BAR, MATERIAL=M\n*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.25\n"
    "*BOUNDARY\n1, 1, 3\n4, 1, 1\n4, 3, 3\n7, 1, 2\n10, 1, 1\n";

std::string tension_deck(const std::string& step_data) {
  return std::string(kTension) + "*STEP\n*STATIC\n*CLOAD\nEND, 1, 25.\n" + step_data +
         "*END STEP\n";
}

TEST(FrdFile, UniformTensionAsTheClosedForm) {
  const JobResult r = test::run_deck(tension_deck("*NODE FILE\nU, RF\n*EL FILE\nS, E\n"), true);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  const FrdFile f = read_frd(test::test_dir() / "job.frd");
  EXPECT_TRUE(f.ended);
  ASSERT_EQ(f.nodes.size(), 12u);
  ASSERT_EQ(f.elements.size(), 2u);
  EXPECT_EQ(f.elements.at(2).first, 1); // he8
  EXPECT_EQ(f.elements.at(2).second, (std::vector<long long>{2, 3, 6, 5, 8, 9, 12, 11}));
  ASSERT_EQ(f.datasets.size(), 4u);
  const char* names[] = {"DISP", "FORC", "STRESS", "TOSTRAIN"};
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(f.datasets[k].name, names[k]);
    EXPECT_EQ(f.datasets[k].step, 1);
    EXPECT_DOUBLE_EQ(f.datasets[k].time, 1.0);
    EXPECT_EQ(f.datasets[k].values.size(), 12u) << names[k];
  }
  double reaction = 0.0;
  for (const auto& [n, x] : f.nodes) {
    const auto& u = f.datasets[0].values.at(n);
    ASSERT_EQ(u.size(), 3u);
    EXPECT_NEAR(u[0], 0.1 * x[0], 1e-6) << "node " << n; // 6 digits: the format's E12.5
    EXPECT_NEAR(u[1], -0.025 * x[1], 1e-7) << "node " << n;
    EXPECT_NEAR(u[2], -0.025 * x[2], 1e-7) << "node " << n;
    if (x[0] == 0.0) reaction += f.datasets[1].values.at(n)[0];
    const auto& s = f.datasets[2].values.at(n);
    const auto& e = f.datasets[3].values.at(n);
    ASSERT_EQ(s.size(), 6u);
    ASSERT_EQ(e.size(), 6u);
    const double s_ref[6] = {100, 0, 0, 0, 0, 0}, e_ref[6] = {0.1, -0.025, -0.025, 0, 0, 0};
    for (int c = 0; c < 6; ++c) {
      EXPECT_NEAR(s[c], s_ref[c], 1e-8 * 100) << "node " << n << " S component " << c;
      EXPECT_NEAR(e[c], e_ref[c], 1e-9) << "node " << n << " E component " << c;
    }
  }
  EXPECT_NEAR(reaction, -100.0, 1e-4);
}

/// The 20 nodes of the unit cube in Abaqus's C3D20 order.
const std::array<std::array<double, 3>, 20> kHex20{
    {{0, 0, 0},  {1, 0, 0},  {1, 1, 0},  {0, 1, 0},  {0, 0, 1},  {1, 0, 1},  {1, 1, 1},
     {0, 1, 1},  {.5, 0, 0}, {1, .5, 0}, {.5, 1, 0}, {0, .5, 0}, {.5, 0, 1}, {1, .5, 1},
     {.5, 1, 1}, {0, .5, 1}, {0, 0, .5}, {1, 0, .5}, {1, 1, .5}, {0, 1, .5}}};

TEST(FrdFile, SimpleShearOfAC3D20HasTensorStrainsAndCgxNodeOrder) {
  std::string deck = "*NODE\n";
  for (int n = 0; n < 20; ++n)
    deck += fmt::format("{}, {}, {}, {}\n", n + 1, kHex20[n][0], kHex20[n][1], kHex20[n][2]);
  deck +=
      "*ELEMENT, TYPE=C3D20, ELSET=CUBE\n1, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15,\n"
      "16, 17, 18, 19, 20\n*SOLID SECTION, ELSET=CUBE, MATERIAL=M\n*MATERIAL, NAME=M\n"
      "*ELASTIC\n1000., 0.25\n*STEP\n*STATIC\n*BOUNDARY\n";
  for (int n = 0; n < 20; ++n)
    deck += fmt::format("{0}, 1, 1, {1}\n{0}, 2, 3, 0.\n", n + 1, 0.01 * kHex20[n][1]);
  deck += "*EL FILE\nS, E\n*END STEP\n";
  const JobResult r = test::run_deck(deck, true);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  const FrdFile f = read_frd(test::test_dir() / "job.frd");
  ASSERT_EQ(f.elements.size(), 1u);
  EXPECT_EQ(f.elements.at(1).first, 4); // he20: the vertical edges' mid-nodes before the top's
  EXPECT_EQ(f.elements.at(1).second,
            (std::vector<long long>{1,  2,  3,  4,  5,  6,  7,  8,  9,  10,
                                    11, 12, 17, 18, 19, 20, 13, 14, 15, 16}));
  ASSERT_EQ(f.datasets.size(), 2u);
  for (long long n = 1; n <= 20; ++n) {
    const auto& s = f.datasets[0].values.at(n);
    const auto& e = f.datasets[1].values.at(n);
    for (int c = 0; c < 6; ++c) {
      EXPECT_NEAR(s[c], c == 3 ? 4.0 : 0.0, 1e-9) << "node " << n << " S component " << c;
      EXPECT_NEAR(e[c], c == 3 ? 0.005 : 0.0, 1e-12) << "node " << n << " E component " << c;
    }
  }
}

TEST(FrdFile, FrequencySetAndCarryOverToTheNextStep) {
  // four fixed increments per step; every second one written, on the end nodes only; the second
  // step gives no *NODE FILE and inherits the first step's
  const std::string deck = std::string(kTension) +
                           "*STEP\n*STATIC, DIRECT\n0.25, 1.\n*CLOAD\nEND, 1, 25.\n"
                           "*NODE FILE, FREQUENCY=2, NSET=END\nU\n*END STEP\n"
                           "*STEP\n*STATIC, DIRECT\n0.25, 1.\n*END STEP\n";
  const JobResult r = test::run_deck(deck, true);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  const FrdFile f = read_frd(test::test_dir() / "job.frd");
  ASSERT_EQ(f.datasets.size(), 4u);
  const double time[4] = {0.5, 1.0, 1.5, 2.0}, tip[4] = {0.1, 0.2, 0.2, 0.2};
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(f.datasets[k].step, k < 2 ? 1 : 2);
    EXPECT_EQ(f.datasets[k].increment, k % 2 == 0 ? 2 : 4);
    EXPECT_NEAR(f.datasets[k].time, time[k], 1e-12);
    ASSERT_EQ(f.datasets[k].values.size(), 4u);
    for (long long n : {3, 6, 9, 12}) EXPECT_NEAR(f.datasets[k].values.at(n)[0], tip[k], 1e-6);
  }
}

TEST(FrdFile, NotWrittenWithoutARequest) {
  const JobResult r = test::run_deck(tension_deck(""), true);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  EXPECT_FALSE(std::filesystem::exists(test::test_dir() / "job.frd"));
}

TEST(FrdFile, SectionForcesAreLeftOutWithAWarning) {
  // an output request never stops a run: SF is not a nodal value, so job.frd gets S alone
  const JobResult r = test::run_deck(tension_deck("*EL FILE\nS, SF\n"), true);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  int warned = 0;
  for (const std::string& w : r.run.warnings)
    warned += w.find("section forces (SF) are not written to job.frd") != std::string::npos;
  EXPECT_EQ(warned, 1);
  const std::string frd = test::slurp(test::test_dir() / "job.frd");
  EXPECT_NE(frd.find("STRESS"), std::string::npos);
}

TEST(ElPrintAveragedAtNodes, OneRowPerNodeWithTheExtrapolatedValues) {
  // the tension deck's uniform state at every node; the summary names nodes, not elements
  const JobResult r = test::run_deck(
      tension_deck("*EL PRINT, ELSET=BAR, POSITION=AVERAGED AT NODES\nS, E\n"), true);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  std::ifstream in(test::test_dir() / "job.dat");
  std::string line;
  int rows = 0, tables = 0;
  bool in_table = false;
  while (std::getline(in, line)) {
    if (line.find("PRINTED AVERAGED AT THE NODES FOR ELEMENT TYPE C3D8 AND ELEMENT SET BAR") !=
        std::string::npos) {
      ++tables;
      in_table = true;
      continue;
    }
    if (!in_table) continue;
    std::istringstream s(line);
    long long node = 0;
    double v[6];
    if (!(s >> node)) {
      if (line.find("MAXIMUM") != std::string::npos) in_table = false;
      continue;
    }
    for (double& x : v) s >> x;
    ASSERT_TRUE(static_cast<bool>(s)) << line;
    ++rows;
    const bool stress = tables == 1;
    const double ref[6] = {
        stress ? 100.0 : 0.1, stress ? 0.0 : -0.025, stress ? 0.0 : -0.025, 0, 0, 0};
    for (int c = 0; c < 6; ++c) EXPECT_NEAR(v[c], ref[c], 1e-6) << line;
  }
  EXPECT_EQ(tables, 2);
  EXPECT_EQ(rows, 24); // 12 nodes, S and E
}

/// A bar with a mass at its free end, pulled by 5 from t = 0 (*DYNAMIC, trapezoidal rule), or
/// statically when `procedure` says so; `output` goes into the step.
std::string dynamic_bar(const std::string& procedure, const std::string& output) {
  return "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=T3D2, ELSET=BAR\n1, 1, 2\n"
         "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.\n*DENSITY\n2.\n"
         "*SOLID SECTION, ELSET=BAR, MATERIAL=M\n0.5\n*BOUNDARY\n1, 1, 3\n2, 2, 3\n"
         "*AMPLITUDE, NAME=CONST\n0., 1., 10., 1.\n*STEP\n" +
         procedure + "\n0.01, 0.02\n*CLOAD, AMPLITUDE=CONST\n2, 1, 5.\n" + output + "*END STEP\n";
}

TEST(FrdFile, VelocityAndAccelerationOfADynamicStep) {
  // CalculiX's velocity block VELO (V1 V2 V3 ALL) and, of the same form, ACCE (A1 A2 A3 ALL)
  const JobResult r =
      test::run_deck(dynamic_bar("*DYNAMIC, DIRECT, ALPHA=0.", "*NODE FILE\nU, V, A\n"), true);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  const std::string text = test::slurp(test::test_dir() / "job.frd");
  EXPECT_NE(text.find(" -4  VELO        4    1\n -5  V1          1    2    1    0\n"),
            std::string::npos);
  EXPECT_NE(text.find(" -4  ACCE        4    1\n -5  A1          1    2    1    0\n"),
            std::string::npos);
  const FrdFile f = read_frd(test::test_dir() / "job.frd");
  ASSERT_EQ(f.datasets.size(), 6u); // two increments, three variables
  const Frame& end = test::last_frame(r);
  const NodeId tip = r.model->mesh.find_node(2);
  const char* names[] = {"DISP", "VELO", "ACCE"};
  const Vec3* expected[] = {&end.nodes.U[tip], &end.nodes.V[tip], &end.nodes.A[tip]};
  for (int k = 0; k < 3; ++k) {
    const FrdDataset& d = f.datasets[3 + k];
    EXPECT_EQ(d.name, names[k]);
    EXPECT_EQ(d.increment, 2);
    const auto& x = d.values.at(2);
    ASSERT_EQ(x.size(), 3u);
    const double value = (*expected[k])[0];
    EXPECT_NE(value, 0.0) << names[k];
    EXPECT_NEAR(x[0], value, 1e-5 * std::abs(value)) << names[k]; // the format's E12.5
  }
  if (std::system("command -v cgx > /dev/null 2>&1") != 0) return; // cgx: see below
  const auto dir = test::test_dir();
  std::ofstream(dir / "read.fbd") << "read job.frd\nprnt info\nquit\n";
  const std::string cmd = "cd '" + dir.string() + "' && timeout 60 cgx -bg read.fbd > cgx.log 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  EXPECT_NE(test::slurp(dir / "cgx.log").find("ds:6"), std::string::npos)
      << test::slurp(dir / "cgx.log");
}

TEST(FrdFile, NoVelocitiesInAStaticStep) {
  const JobResult r = test::run_deck(dynamic_bar("*STATIC, DIRECT", "*NODE FILE\nU, V, A\n"), true);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  const FrdFile f = read_frd(test::test_dir() / "job.frd");
  ASSERT_EQ(f.datasets.size(), 2u);
  for (const FrdDataset& d : f.datasets) EXPECT_EQ(d.name, "DISP");
}

TEST(FrdFile, CgxReadsItInBatchMode) {
  if (std::system("command -v cgx > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "cgx (Debian calculix-cgx) is not installed";
  const JobResult r = test::run_deck(tension_deck("*NODE FILE\nU, RF\n*EL FILE\nS, E\n"), true);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  const auto dir = test::test_dir();
  std::ofstream(dir / "read.fbd") << "read job.frd\nprnt info\nds 1 e 1\nds 3 e 1\nquit\n";
  const std::string cmd = "cd '" + dir.string() + "' && timeout 60 cgx -bg read.fbd > cgx.log 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::ifstream in(dir / "cgx.log");
  std::stringstream log;
  log << in.rdbuf();
  const std::string text = log.str();
  // cgx's summary line: 12 nodes, 2 elements, 4 datasets
  EXPECT_NE(text.find("n:12 e:2"), std::string::npos) << text;
  EXPECT_NE(text.find("ds:4"), std::string::npos) << text;
  // "ds 1 e 1" shows DISP D1 with its extremes: 0.2 at the loaded end, 0 at the supported one
  std::vector<double> maxima;
  for (std::size_t at = text.find(" max:"); at != std::string::npos;
       at = text.find(" max:", at + 5))
    maxima.push_back(std::stod(text.substr(at + 5, 16)));
  ASSERT_EQ(maxima.size(), 2u) << text;
  EXPECT_NEAR(maxima[0], 0.2, 1e-6);
  EXPECT_NEAR(maxima[1], 100.0, 1e-4); // STRESS SXX
}

} // namespace
} // namespace gapfem
