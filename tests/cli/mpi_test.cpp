// `mpirun -np 2 gapfem` (issue 17): the same answer as one process to 1e-8, rank 0 alone writes
// the files and the terminal, the serial-only CHOLMOD backend is refused, and a rank that fails
// alone (bad input read on one rank) brings the whole job down with its message and exit status
// instead of leaving the other rank waiting. Skipped with a message where MPI or PETSc is absent.
#include "parallel/parallel.hpp"
#include "test_util.hpp"
#include "verification/parallel/slab_deck.hpp"

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>

using namespace gapfem;
using namespace gapfem::test;
namespace fs = std::filesystem;

namespace {

bool have_mpirun() {
  return std::system("command -v mpirun > /dev/null 2>&1") == 0;
}

#define REQUIRE_MPI()                                                                              \
  if (!parallel::available() || !have_mpirun())                                                    \
  GTEST_SKIP() << "no PETSc build or no mpirun here (Debian's petsc-dev and openmpi-bin): the "    \
                  "mpirun tests are not run"

/// Run a shell command line (mpirun as root needs Open MPI's consent); returns the exit status
/// and leaves stdout+stderr in `log`. In the sanitized build the ranks do not count leaks: Open MPI
/// keeps a few bytes of its connections in components it unloads, which LeakSanitizer cannot name
/// to suppress; gapfem's own code on these paths is leak-checked by SolverBackends.* in-process.
int shell(const std::string& cmd, const fs::path& log) {
  std::string asan = "detect_leaks=0";
  if (const char* env = std::getenv("ASAN_OPTIONS")) asan = std::string(env) + ":detect_leaks=0";
  const std::string line = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
                           "OMPI_MCA_rmaps_base_oversubscribe=1 ASAN_OPTIONS='" +
                           asan + "' " + cmd + " > '" + log.string() + "' 2>&1";
  const int rc = std::system(line.c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

/// gapfem on `deck` into `dir` with `args`, on `ranks` processes (0: without mpirun).
int run(const fs::path& deck, const fs::path& dir, const std::string& args, int ranks,
        std::string* output = nullptr) {
  fs::create_directories(dir);
  const std::string launcher = ranks > 0 ? fmt::format("mpirun -np {} ", ranks) : "";
  const fs::path log = dir / "terminal.log";
  const int rc = shell(fmt::format("{}'{}' {} -o '{}' '{}'", launcher, GAPFEM_EXE, args,
                                   dir.string(), deck.string()),
                       log);
  if (output) *output = slurp(log);
  return rc;
}

/// Every nodal value and gap force of the last frame of every step, by field name ("U", "RF",
/// "normal_force", …), and the gaps' statuses under "status" (1 closed or sticking, 0 open).
/// Element stresses are left out: where they vanish their round-off has no scale to compare to.
void collect(const nlohmann::json& j, const std::string& field,
             std::map<std::string, std::vector<double>>& out) {
  if (j.is_number()) {
    out[field].push_back(j.get<double>());
  } else if (j.is_array()) {
    for (const auto& e : j) collect(e, field, out);
  } else if (j.is_object()) {
    for (const auto& [k, v] : j.items())
      collect(v, std::isdigit(static_cast<unsigned char>(k[0])) ? field : k, out);
  }
}
std::map<std::string, std::vector<double>> last_frames(const fs::path& json_file) {
  const nlohmann::json j = nlohmann::json::parse(slurp(json_file));
  std::map<std::string, std::vector<double>> out;
  for (const auto& step : j.at("steps")) {
    const auto& frame = step.at("frames").back();
    collect(frame.at("nodes"), "nodes", out);
    for (const auto& [label, e] : frame.at("elements").items()) {
      if (!e.contains("gap")) continue;
      const auto& g = e.at("gap");
      collect(g.at("normal_force"), "normal_force", out);
      collect(g.at("friction_force"), "friction_force", out);
      out["status"].push_back(g.at("status").get<std::string>() == "open" ? 0.0 : 1.0);
    }
  }
  return out;
}
/// Each field of b within tol of a's largest value of that field.
void expect_same_results(const fs::path& a, const fs::path& b, double tol,
                         const std::string& what) {
  SCOPED_TRACE(what);
  const auto fa = last_frames(a), fb = last_frames(b);
  ASSERT_EQ(fa.size(), fb.size());
  for (const auto& [field, va] : fa) {
    const auto& vb = fb.at(field);
    ASSERT_EQ(va.size(), vb.size()) << field;
    double scale = 0.0, diff = 0.0;
    for (std::size_t i = 0; i < va.size(); ++i) {
      scale = std::max(scale, std::abs(va[i]));
      diff = std::max(diff, std::abs(va[i] - vb[i]));
    }
    EXPECT_LE(diff, tol * scale + 1e-300) << field;
  }
}

} // namespace

TEST(Mpi, TwoRanksGiveTheSerialAnswer) {
  REQUIRE_MPI();
  const fs::path src = GAPFEM_SOURCE_DIR, dir = test_dir();
  // gap verification decks of the examples (GAPUNI on a pipe with friction, an axisymmetric
  // shrink fit, a fuel pin with thermal GAPUNIT/DGAP gaps, a pipe elbow on GAPCYL guides), NLGEOM
  // trusses and shells, and a slab on gaps whose nodal blocks (iterative: block size 3) are split
  // between the ranks
  const fs::path slab = dir / "slab_on_gaps.inp";
  std::ofstream(slab) << slab_on_gaps(12, 2);
  const std::vector<std::pair<std::string, std::string>> decks = {
      {"pipe", "examples/01_pipe_on_supports/pipe_on_supports.inp"},
      {"shrink", "examples/02_shrink_fit/shrink_fit.inp"},
      {"fuel", "examples/03_fuel_pin/fuel_pin.inp"},
      {"elbow", "examples/04_pipe_elbow/pipe_elbow.inp"},
      {"truss", "tests/verification/structural/truss_nlgeom.inp"},
      {"thermal", "tests/verification/structural/thermal_gradient.inp"},
      {"slab", slab.string()}};
  for (const auto& [name, deck] : decks)
    for (const char* solver : {"mumps", "iterative"}) {
      // GMRES to 1e-13 (a PETSc option, passed through): the partitioned AMG cycle differs from
      // the serial one, so the iterates agree only to the Krylov tolerance, and the stick/slip
      // path of the friction supports would amplify 1e-10 to 1e-7
      const std::string args =
          fmt::format("--solver {} --no-vtu -q{}", solver,
                      std::string_view(solver) == "iterative" ? " -ksp_rtol 1e-13" : "");
      const fs::path one = dir / name / solver / "1", two = dir / name / solver / "2";
      ASSERT_EQ(run(src / deck, one, args, 0), 0) << deck;
      std::string out;
      ASSERT_EQ(run(src / deck, two, args, 2, &out), 0) << deck << "\n" << out;
      const std::string stem = fs::path(deck).stem().string();
      // ... and where friction decides the path (the pipe on its supports) the Newton tolerance
      // still leaves the two iterative runs 3e-8 apart
      const double tol = name == "pipe" && std::string_view(solver) == "iterative" ? 1e-7 : 1e-8;
      expect_same_results(one / (stem + ".results.json"), two / (stem + ".results.json"), tol,
                          deck + " with " + solver);
    }
}

TEST(Mpi, AGraphPartitionerChoosesTheRanksRows) {
  REQUIRE_MPI();
  // a slab of 14,640 equations (from 10,000 on, PT-Scotch chooses each rank's nodes): the serial
  // answer to 1e-8, and fewer couplings between the ranks than contiguous blocks of the node
  // numbering (which runs layer by layer, so that those blocks meet across a whole layer)
  const fs::path dir = test_dir() / "partition", slab = dir / "slab.inp";
  fs::create_directories(dir);
  std::ofstream(slab) << slab_on_gaps(40, 2);
  const std::string args = "--solver iterative --no-vtu -v -ksp_rtol 1e-13";
  ASSERT_EQ(run(slab, dir / "1", args, 0), 0);
  std::string out;
  ASSERT_EQ(run(slab, dir / "2", args, 2, &out), 0) << out;
  const std::regex line(R"(partition \((\w+)\): (\d+) blocks of 3 over 2 ranks, (\d+) to (\d+) a )"
                        R"(rank; (\d+) couplings between ranks \(contiguous blocks: (\d+)\))");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(out, m, line)) << out;
  const long blocks = std::stol(m[2]), fewest = std::stol(m[3]), most = std::stol(m[4]);
  const long cut = std::stol(m[5]), contiguous = std::stol(m[6]);
  EXPECT_EQ(fewest + most, blocks);
  EXPECT_LE(most - fewest, blocks / 20) << "the ranks' shares are balanced";
  EXPECT_LT(3 * cut, contiguous) << m[0];
  expect_same_results(dir / "1" / "slab.results.json", dir / "2" / "slab.results.json", 1e-8,
                      "partitioned slab");
}

TEST(Mpi, RankZeroAloneWritesTheFilesAndTheTerminal) {
  REQUIRE_MPI();
  const fs::path src = GAPFEM_SOURCE_DIR, dir = test_dir() / "out";
  fs::remove_all(dir);
  std::string out;
  ASSERT_EQ(run(src / "examples/02_shrink_fit/shrink_fit.inp", dir, "--no-vtu", 2, &out), 0) << out;
  // one progress report, one set of files
  std::size_t count = 0;
  for (std::size_t p = out.find("Step 1 completed"); p != std::string::npos;
       p = out.find("Step 1 completed", p + 1))
    ++count;
  EXPECT_EQ(count, 1u) << out;
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(dir)) files.push_back(e.path().filename().string());
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<std::string>{"shrink_fit.dat", "shrink_fit.msg",
                                             "shrink_fit.report.html", "shrink_fit.results.json",
                                             "shrink_fit.sta", "terminal.log"}));
}

TEST(Mpi, TheSerialCholmodBackendIsRefused) {
  REQUIRE_MPI();
  const fs::path src = GAPFEM_SOURCE_DIR;
  std::string out;
  EXPECT_EQ(
      run(src / "examples/02_shrink_fit/shrink_fit.inp", test_dir(), "--solver cholmod", 2, &out),
      1);
  EXPECT_NE(out.find("--solver cholmod solves on one process"), std::string::npos) << out;
}

TEST(Mpi, ARankThatFailsAloneStopsTheJob) {
  REQUIRE_MPI();
  // rank 0 reads a good deck, rank 1 a deck with an input error (mpirun's MPMD form): rank 1
  // must not leave rank 0 waiting in its first collective call, nor rank 0 hang
  const fs::path src = GAPFEM_SOURCE_DIR, dir = test_dir();
  const fs::path good = src / "examples/02_shrink_fit/shrink_fit.inp";
  const fs::path bad =
      write_deck("*NODE\n1, 0., 0.\n*STEP\n*STATIC\n*CLOAD\n99, 1, 1.\n*END STEP\n", "bad");
  const auto start = std::chrono::steady_clock::now();
  const std::string cmd =
      fmt::format("timeout 120 mpirun -np 1 '{0}' -o '{1}' '{2}' : -np 1 '{0}' -o '{1}' '{3}'",
                  GAPFEM_EXE, (dir / "run").string(), good.string(), bad.string());
  const int rc = shell(cmd, dir / "terminal.log");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string out = slurp(dir / "terminal.log");
  EXPECT_NE(rc, 0) << out;
  EXPECT_NE(rc, 124) << "the job hung until timeout killed it\n" << out;
  EXPECT_LT(seconds, 100.0);
  EXPECT_NE(out.find("gapfem (rank 1)"), std::string::npos) << out;
  EXPECT_NE(out.find("99"), std::string::npos) << out; // rank 1's own message names the node
  EXPECT_NE(out.find("stopping the whole job"), std::string::npos) << out;
}

TEST(Mpi, ARankShortOfMemoryStopsTheJobWithItsSentence) {
  REQUIRE_MPI();
  // the beam rolled into a circle defeats the AMG-preconditioned Krylov method, and its fallback,
  // a MUMPS factor, is checked against the memory left on every rank; rank 1 alone is short of
  // memory (GAPFEM_MEMORY_LIMIT, mpirun's MPMD form with -x for that rank only): every rank must
  // stop with the sentence that says so, exit status 2, no rank left waiting
  const fs::path src = GAPFEM_SOURCE_DIR, dir = test_dir();
  const fs::path deck = src / "tests/verification/structural/beam_rollup_2d.inp";
  const auto start = std::chrono::steady_clock::now();
  const std::string cmd =
      fmt::format("timeout 120 mpirun -np 1 '{0}' --solver iterative -o '{1}' '{2}' : -np 1 -x "
                  "GAPFEM_MEMORY_LIMIT=1 '{0}' --solver iterative -o '{1}' '{2}'",
                  GAPFEM_EXE, (dir / "run").string(), deck.string());
  const int rc = shell(cmd, dir / "terminal.log");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string out = slurp(dir / "terminal.log");
  EXPECT_EQ(rc, 2) << out;
  EXPECT_LT(seconds, 100.0);
  EXPECT_NE(out.find("would need about"), std::string::npos) << out;
  // ... naming the memory of the rank that is short, not rank 0's
  EXPECT_NE(out.find("more than is available (0.0 KiB on the rank with the least)"),
            std::string::npos)
      << out;
  // rank 0 kept what converged before: the results file of the increments before the failure
  EXPECT_TRUE(fs::exists(dir / "run" / "beam_rollup_2d.results.json")) << out;
}

namespace {

/// A C3D8 cantilever (consistent mass, Rayleigh damping) swinging down onto a GAPUNI stop under a
/// tip load, in two *DYNAMIC steps (HHT, then the trapezoidal rule after the load is removed),
/// with its tip's U and V and the gap's S11 as history output every increment.
std::string dynamic_cantilever() {
  std::string d = "*HEADING\ndynamic cantilever on a stop\n*NODE\n";
  const int nx = 8;
  auto id = [&](int i, int j, int k) { return 1 + i + (nx + 1) * (j + 2 * k); };
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i <= nx; ++i)
        d += fmt::format("{}, {}, {}, {}\n", id(i, j, k), 1.0 * i, 1.0 * j, 1.0 * k);
  d += "*ELEMENT, TYPE=C3D8, ELSET=BEAM\n";
  for (int i = 0; i < nx; ++i)
    d += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", i + 1, id(i, 0, 0), id(i + 1, 0, 0),
                     id(i + 1, 1, 0), id(i, 1, 0), id(i, 0, 1), id(i + 1, 0, 1), id(i + 1, 1, 1),
                     id(i, 1, 1));
  d += fmt::format("*NODE\n1000, {}, 0., -0.5\n*ELEMENT, TYPE=GAPUNI, ELSET=STOP\n100, {}, 1000\n",
                   1.0 * nx, id(nx, 0, 0));
  d += "*GAP, ELSET=STOP\n0.02, 0., 0., -1.\n";
  d += fmt::format("*NSET, NSET=FIX\n{}, {}, {}, {}, 1000\n*NSET, NSET=TIP\n{}\n", id(0, 0, 0),
                   id(0, 1, 0), id(0, 0, 1), id(0, 1, 1), id(nx, 1, 1));
  d += "*MATERIAL, NAME=S\n*ELASTIC\n2000., 0.3\n*DENSITY\n1.\n*DAMPING, ALPHA=0.1, BETA=0.001\n"
       "*SOLID SECTION, ELSET=BEAM, MATERIAL=S\n*BOUNDARY\nFIX, 1, 3\n";
  const std::string output = "*OUTPUT, HISTORY, VARIABLE=PRESELECT\n*NODE OUTPUT, NSET=TIP\nU, V\n"
                             "*ELEMENT OUTPUT, ELSET=STOP\nS\n";
  d += "*STEP, INC=1000\n*DYNAMIC, DIRECT\n0.05, 2.\n*CLOAD\nTIP, 3, -1.\n" + output +
       "*END STEP\n*STEP, INC=1000\n*DYNAMIC, DIRECT, ALPHA=0.\n0.05, 1.\n*CLOAD, OP=NEW\n" +
       output + "*END STEP\n";
  return d;
}

/// Every step's history rows (values and energies) of a results file, flattened per column.
std::map<std::string, std::vector<double>> histories(const fs::path& json_file) {
  const nlohmann::json j = nlohmann::json::parse(slurp(json_file));
  std::map<std::string, std::vector<double>> out;
  for (const auto& step : j.at("steps"))
    for (const char* table : {"values", "energies"}) {
      const auto& t = step.at("history").at(table);
      for (const auto& row : t.at("rows"))
        for (std::size_t c = 3; c < row.size(); ++c)
          out[t.at("columns").at(c).get<std::string>()].push_back(row.at(c).get<double>());
    }
  return out;
}

} // namespace

TEST(Mpi, DynamicHistoriesAreTheSameOnEveryBackend) {
  // issue 46: CHOLMOD, MUMPS and the iterative method, on one process and on two, give the same
  // histories (tip U and V, the stop's contact stress, the energies) to 1e-8 of each column's
  // largest value, through an impact on the stop and across two dynamic steps
  REQUIRE_MPI();
  const fs::path dir = test_dir(), deck = dir / "cantilever.inp";
  std::ofstream(deck) << dynamic_cantilever();
  const fs::path ref = dir / "cholmod";
  ASSERT_EQ(run(deck, ref, "--no-vtu -q", 0), 0);
  const auto a = histories(ref / "cantilever.results.json");
  ASSERT_GT(a.at("U3 at node 36").size(), 50u);
  double s11 = 0.0; // the tip reaches the stop
  for (double v : a.at("S11 at element 100")) s11 = std::max(s11, std::abs(v));
  EXPECT_GT(s11, 0.0);
  for (const char* solver : {"mumps", "iterative"})
    for (int ranks : {0, 2}) {
      const std::string what = fmt::format("{} on {} process(es)", solver, ranks ? ranks : 1);
      SCOPED_TRACE(what);
      const std::string args =
          fmt::format("--solver {} --no-vtu -q{}", solver,
                      std::string_view(solver) == "iterative" ? " -ksp_rtol 1e-13" : "");
      const fs::path out = dir / solver / std::to_string(ranks);
      std::string log;
      ASSERT_EQ(run(deck, out, args, ranks, &log), 0) << log;
      const auto b = histories(out / "cantilever.results.json");
      ASSERT_EQ(a.size(), b.size());
      for (const auto& [column, va] : a) {
        const auto& vb = b.at(column);
        ASSERT_EQ(va.size(), vb.size()) << column;
        double scale = 0.0, diff = 0.0;
        for (std::size_t i = 0; i < va.size(); ++i) {
          scale = std::max(scale, std::abs(va[i]));
          diff = std::max(diff, std::abs(va[i] - vb[i]));
        }
        EXPECT_LE(diff, 1e-8 * scale + 1e-300) << column;
      }
    }
}

namespace {

/// A C3D8 cantilever (24 x 2 x 3 elements, an unequal section so that no two modes share an
/// eigenvalue) on three GAPUNI props (two closed by the first step's load, one open) with an
/// *EQUATION at the tip, then *FREQUENCY, *BUCKLE (an axial tip load) and a mode-based *STEADY
/// STATE DYNAMICS: 864 equations, past the eigen solvers' dense route, so that the Krylov methods
/// run.
std::string cantilever_on_props() {
  const int nx = 24, ny = 2, nz = 3;
  auto id = [&](int i, int j, int k) { return 1 + k + (nz + 1) * (j + (ny + 1) * i); };
  std::string d = "*HEADING\ncantilever on props\n*NODE\n";
  for (int i = 0; i <= nx; ++i)
    for (int j = 0; j <= ny; ++j)
      for (int k = 0; k <= nz; ++k)
        d += fmt::format("{}, {}, {}, {}\n", id(i, j, k), 10.0 * i / nx, 0.3 * j, k / 3.0);
  const int ground = id(nx, ny, nz) + 1;
  const int stations[3] = {24, 18, 12};
  const double clearance[3] = {0.0, 0.0, 1.0};
  d += "*NODE, NSET=GROUND\n";
  for (int q = 0; q < 3; ++q)
    d += fmt::format("{}, {}, 0.3, -0.2\n", ground + q, stations[q] / 2.4);
  d += "*ELEMENT, TYPE=C3D8, ELSET=BEAM\n";
  int e = 0;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k)
        d += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", ++e, id(i, j, k), id(i + 1, j, k),
                         id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1), id(i + 1, j, k + 1),
                         id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1));
  for (int q = 0; q < 3; ++q)
    d += fmt::format("*ELEMENT, TYPE=GAPUNI, ELSET=G{0}\n{1}, {2}, {3}\n*GAP, ELSET=G{0}\n{4}, 0., "
                     "0., -1.\n",
                     q, ++e, id(stations[q], 1, 0), ground + q, clearance[q]);
  d += "*NSET, NSET=FIX\n";
  for (int j = 0; j <= ny; ++j)
    for (int k = 0; k <= nz; ++k) d += fmt::format("{}\n", id(0, j, k));
  d += "*NSET, NSET=TIP\n";
  for (int j = 0; j <= ny; ++j)
    for (int k = 0; k <= nz; ++k) d += fmt::format("{}\n", id(nx, j, k));
  d += "*MATERIAL, NAME=STEEL\n*ELASTIC\n2e5, 0.3\n*DENSITY\n7.8e-9\n"
       "*SOLID SECTION, ELSET=BEAM, MATERIAL=STEEL\n";
  d += fmt::format("*EQUATION\n2\n{}, 2, 1., {}, 2, -1.\n", id(nx, 0, nz), id(nx, ny, nz));
  d += "*BOUNDARY\nFIX, 1, 3\nGROUND, 1, 3\n*STEP\n*STATIC\n*CLOAD\nTIP, 3, -0.5\n*END STEP\n"
       "*STEP\n*FREQUENCY\n10\n*END STEP\n*STEP\n*BUCKLE\n4\n*CLOAD\nTIP, 1, -1.\n*END STEP\n";
  d += fmt::format("*STEP\n*STEADY STATE DYNAMICS\n100., 20000., 20\n*MODAL DAMPING\n1, 10, "
                   "0.02\n*CLOAD\n{}, 2, 1.\n*END STEP\n",
                   id(nx, 0, nz));
  return d;
}

/// The largest difference between two runs' frames of every step (U and the imaginary part of a
/// steady state, each frame with the sign that matches: a mode's sign is arbitrary), relative to
/// the frame's largest value, and between their eigenvalues, relative to each.
void expect_same_modes(const fs::path& a_file, const fs::path& b_file, double tol,
                       const std::string& what) {
  const nlohmann::json a = nlohmann::json::parse(slurp(a_file));
  const nlohmann::json b = nlohmann::json::parse(slurp(b_file));
  ASSERT_EQ(a.at("steps").size(), b.at("steps").size()) << what;
  for (std::size_t s = 0; s < a.at("steps").size(); ++s) {
    const auto &sa = a.at("steps")[s], &sb = b.at("steps")[s];
    const std::string step = fmt::format("{}, step {}", what, s + 1);
    if (sa.contains("modes"))
      for (std::size_t k = 0; k < sa.at("modes").size(); ++k) {
        const double la = sa.at("modes")[k].at("eigenvalue"),
                     lb = sb.at("modes")[k].at("eigenvalue");
        EXPECT_LE(std::abs(la - lb), tol * std::abs(la)) << step << ", mode " << k + 1;
      }
    ASSERT_EQ(sa.at("frames").size(), sb.at("frames").size()) << step;
    for (std::size_t f = 0; f < sa.at("frames").size(); ++f)
      for (const char* field : {"U", "U_imaginary"}) {
        std::vector<double> va, vb;
        for (const auto& [node, values] : sa.at("frames")[f].at("nodes").items())
          if (values.contains(field))
            for (std::size_t c = 0; c < 3; ++c) {
              va.push_back(values.at(field)[c]);
              vb.push_back(sb.at("frames")[f].at("nodes").at(node).at(field)[c]);
            }
        double dot = 0.0, scale = 0.0;
        for (std::size_t i = 0; i < va.size(); ++i) {
          dot += va[i] * vb[i];
          scale = std::max(scale, std::abs(va[i]));
        }
        const double sign = dot < 0.0 ? -1.0 : 1.0;
        double diff = 0.0;
        for (std::size_t i = 0; i < va.size(); ++i)
          diff = std::max(diff, std::abs(va[i] - sign * vb[i]));
        EXPECT_LE(diff, tol * scale + 1e-300) << step << ", frame " << f + 1 << ", " << field;
      }
  }
}

} // namespace

TEST(Mpi, EigenModesOnSeveralRanksAreTheSerialOnes) {
  // issue 47: SLEPc's Krylov-Schur over the PETSc backend (one process and two) finds the
  // frequencies, buckling loads and mode shapes that Spectra's Lanczos finds over CHOLMOD, to
  // 1e-8, about a base state with closed gaps and an *EQUATION; the steady state on those modes
  // agrees alike
  REQUIRE_MPI();
  const fs::path dir = test_dir(), deck = dir / "props.inp";
  std::ofstream(deck) << cantilever_on_props();
  const fs::path ref = dir / "cholmod";
  std::string log;
  ASSERT_EQ(run(deck, ref, "--no-vtu", 0, &log), 0) << log;
  EXPECT_NE(log.find("eigensolver Spectra"), std::string::npos) << log;
  EXPECT_NE(log.find("1 open, 2 closed"), std::string::npos) << log;
  for (int ranks : {0, 2}) {
    const fs::path out = dir / "mumps" / std::to_string(ranks);
    ASSERT_EQ(run(deck, out, "--solver mumps --no-vtu", ranks, &log), 0) << log;
    if (log.find("eigensolver SLEPc") == std::string::npos)
      GTEST_SKIP() << "this build has PETSc without SLEPc (slepc-dev)";
    expect_same_modes(ref / "props.results.json", out / "props.results.json", 1e-8,
                      fmt::format("SLEPc on {} process(es)", ranks ? ranks : 1));
  }
}
