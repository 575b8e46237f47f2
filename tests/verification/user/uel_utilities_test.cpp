// The Abaqus utility routines a UEL may call (src/app/abaqus_utilities.cpp), from a Fortran UEL
// written for the tests (uel/uel_utilities.f): a linear spring (k = 100, node 2 pulled by
// P = 50, so u2 = P / k = 0.5) that asks for the job's name and folder, the process count and
// rank, the invariants, principal values and directions of a fixed tensor and its rotation, and
// that prints messages, stops with an error or calls XIT.
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

using namespace gapfem;
using namespace gapfem::test;

namespace {

namespace fs = std::filesystem;

const fs::path kUtilitiesUel =
    fs::path(GAPFEM_TEST_DIR) / "verification" / "user" / "uel" / "uel_utilities.f";

/// The spring with MODE and the limit of u2 (PROPS(2), PROPS(3)), loaded in two increments of 0.5.
std::string spring_deck(int mode, double limit = 1.0) {
  return fmt::format(R"(*HEADING
a linear UEL spring that calls the Abaqus utility routines
*NODE
1, 0., 0., 0.
2, 1., 0., 0.
*USER ELEMENT, TYPE=U1, NODES=2, PROPERTIES=3
1
*UEL PROPERTY, ELSET=S
100., {}, {}
*ELEMENT, TYPE=U1, ELSET=S
1, 1, 2
*BOUNDARY
1, 1, 3
2, 2, 3
*STEP
*STATIC, DIRECT
0.5, 1.
*CLOAD
2, 1, 50.
*END STEP
)",
                     mode, limit);
}

JobResult run_spring(int mode, const std::string& name, double limit = 1.0) {
  JobOptions o;
  o.deck = write_deck(spring_deck(mode, limit), name);
  o.write_files = true;
  o.write_vtu = false;
  o.quiet = true;
  o.user_code = kUtilitiesUel;
  return run_job(o);
}

std::vector<double> numbers(const std::string& line) {
  std::istringstream in(line);
  std::vector<double> v;
  for (double x = 0.0; in >> x;) v.push_back(x);
  return v;
}

void expect_values(const std::string& line, const std::vector<double>& expected, const char* what) {
  const std::vector<double> got = numbers(line);
  ASSERT_EQ(got.size(), expected.size()) << what << ": " << line;
  for (std::size_t i = 0; i < got.size(); ++i)
    EXPECT_NEAR(got[i], expected[i], 1e-12) << what << " component " << i + 1;
}

} // namespace

// GETJOBNAME / GETOUTDIR: the job's name and its absolute output folder; GETNUMCPUS 1 and GETRANK
// 0 on one process. S = (2, 2, 5, 1, 0, 0): the 2x2 block [2 1; 1 2] has eigenvalues 1 and 3 with
// directions (1, -1, 0) / sqrt 2 and (1, 1, 0) / sqrt 2, and 5 along z; SINV1 = trace / 3 = 3,
// SINV2 = sqrt(3/2 s:s) with s = (-1, -1, 2, 1, 0, 0): s:s = 1 + 1 + 4 + 2 = 8, sqrt 12. The
// strain (2, 2, 5, 2, 0, 0) has engineering shear 2, the same tensor. A rotation of 90 degrees
// about z maps S12 to -S12 and keeps the rest (R S R^T).
TEST(AbaqusUtilities, TheUelGetsTheJobTheInvariantsAndThePrincipalValues) {
  const JobResult r = run_spring(0, "utilities");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  EXPECT_NEAR(U(r, last_frame(r, 1), 2)[0], 0.5, 1e-12);
  const fs::path dir = fs::absolute(test_dir()).lexically_normal();
  std::ifstream in(dir / "utilities.utl");
  ASSERT_TRUE(in) << "the UEL wrote no " << (dir / "utilities.utl");
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 11u);
  EXPECT_EQ(lines[0], "utilities");
  std::string outdir = dir.string();
  while (outdir.size() > 1 && outdir.back() == '/') outdir.pop_back();
  EXPECT_EQ(lines[1], outdir);
  expect_values(lines[2], {9.0, static_cast<double>(outdir.size()), 1.0, 0.0}, "lengths, cpus");
  expect_values(lines[3], {3.0, std::sqrt(12.0)}, "SINV");
  for (int l : {4, 5, 6}) {
    std::vector<double> ps = numbers(lines[static_cast<std::size_t>(l)]);
    std::sort(ps.begin(), ps.end());
    ASSERT_EQ(ps.size(), 3u) << lines[static_cast<std::size_t>(l)];
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(ps[static_cast<std::size_t>(i)], 1.0 + 2 * i, 1e-12);
  }
  // SPRIND: row I of AN is the unit direction of PS(I): S n = PS(I) n
  const std::vector<double> ps = numbers(lines[6]), an = numbers(lines[7]);
  ASSERT_EQ(an.size(), 9u);
  const double S[3][3] = {{2, 1, 0}, {1, 2, 0}, {0, 0, 5}};
  for (int i = 0; i < 3; ++i) {
    const double* n = &an[static_cast<std::size_t>(3 * i)];
    EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0, 1e-12);
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(S[a][0] * n[0] + S[a][1] * n[1] + S[a][2] * n[2],
                  ps[static_cast<std::size_t>(i)] * n[a], 1e-12)
          << "direction " << i + 1;
  }
  expect_values(lines[8], {2, 2, 5, -1, 0, 0}, "ROTSIG stress");
  expect_values(lines[9], {2, 2, 5, -2, 0, 0}, "ROTSIG strain");
  expect_values(lines[10], {2, 2, 5, -1}, "ROTSIG NDI=3 NSHR=1");
}

// STDB_ABQERR: LOP = 1 information and -1 a warning on the terminal, with %S, %I and %R replaced
// by the values; -3 stops the analysis with the message (exit 2) after the increments that
// converged; XIT stops it too.
TEST(AbaqusUtilities, MessagesAndXitEndTheAnalysisCleanly) {
  const fs::path deck = write_deck(spring_deck(1), "warn");
  const std::string cmd =
      fmt::format("cd '{}' && '{}' --user '{}' warn.inp > warn.log 2>&1",
                  deck.parent_path().string(), GAPFEM_EXE, kUtilitiesUel.string());
  const int rc = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(rc));
  const std::string log = slurp(deck.parent_path() / "warn.log");
  EXPECT_EQ(WEXITSTATUS(rc), 0) << log;
  EXPECT_NE(log.find("user code: increment 2: spring checked"), std::string::npos) << log;

  JobResult r = run_spring(2, "stop", 0.3);
  EXPECT_EQ(r.exit_code, kExitNoConvergence);
  EXPECT_NE(r.error.find("element 1 stretched to 0.5 beyond 0.3"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("STDB_ABQERR with LOP=-3"), std::string::npos) << r.error;
  EXPECT_NEAR(U(r, last_frame(r, 1), 2)[0], 0.25, 1e-12); // the increment that converged

  r = run_spring(3, "xit", 0.3);
  EXPECT_EQ(r.exit_code, kExitNoConvergence);
  EXPECT_NE(r.error.find("called XIT"), std::string::npos) << r.error;
  EXPECT_NEAR(U(r, last_frame(r, 1), 2)[0], 0.25, 1e-12);
}
