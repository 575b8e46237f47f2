// gapfem against CalculiX on the same *BUCKLE deck. Runs only where ccx is installed; skipped with
// a visible message otherwise.
//
// The model: a column along z of 2 x 2 x 16 C3D20R elements (section 1 x 1.5, length 8,
// E = 210000, nu = 0.3), clamped at z = 0 (DOFs 1-3 of the base nodes), -1 along z on every node
// of the top face; one step `*BUCKLE` / `4`. Compared: the four buckling factors (ccx's .dat table
// "B U C K L I N G   F A C T O R   O U T P U T"), relative difference, criterion 2e-6 (measured
// 3e-7 at most, session 17: ccx prints 7 significant digits).
//
// Why the two agree: both codes' buckling operator is K0 + lambda K_sigma, K_sigma the initial
// stress matrix of the stresses of the linear static response to the load (gapfem's C3D20R
// provides it exactly: ElementKernel::stress_stiffness, docs/theory/buckling.md §2), both with
// the 8-point reduced rule of C3D20R.
#include "ccx_runner.hpp"
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <iostream>
#include <sstream>

using namespace gapfem;
using namespace gapfem::test;

namespace {

std::string column() {
  const Brick20Block block = brick20_block(2, 2, 16, 1.0, 1.5, 8.0, "C3D20R", "EALL");
  std::string d = "*HEADING\nC3D20R column, buckling, compared with CalculiX\n*NODE\n" +
                  block.nodes + block.elements;
  std::string base = "*NSET, NSET=BASE\n", top = "*NSET, NSET=TOP\n";
  for (const auto& [node, p] : block.used) {
    if (p[2] == 0) base += fmt::format("{}\n", node);
    if (p[2] == 32) top += fmt::format("{}\n", node);
  }
  return d + base + top +
         "*BOUNDARY\nBASE, 1, 3\n*MATERIAL, NAME=EL\n*ELASTIC\n210000., 0.3\n"
         "*SOLID SECTION, ELSET=EALL, MATERIAL=EL\n*STEP\n*BUCKLE\n4\n*CLOAD\nTOP, 3, -1.\n"
         "*END STEP\n";
}

/// The buckling factors of ccx's .dat file.
std::vector<double> ccx_factors(const std::filesystem::path& dat) {
  std::ifstream in(dat);
  std::string line;
  std::vector<double> out;
  bool reading = false;
  while (std::getline(in, line)) {
    if (line.find("B U C K L I N G   F A C T O R") != std::string::npos) {
      reading = true;
      continue;
    }
    if (!reading) continue;
    std::istringstream ls(line);
    int mode = 0;
    double f = 0.0;
    if (ls >> mode >> f) out.push_back(f);
  }
  return out;
}

TEST(CcxBuckleCompare, C3D20RColumnFactorsAgree) {
  if (find_ccx().empty()) {
    std::cout
        << "[  SKIPPED ] ccx (CalculiX) is not installed: the *BUCKLE comparison is skipped\n";
    GTEST_SKIP() << "ccx not installed";
  }
  const std::string deck = column();
  const auto dir = test::test_dir() / "ccx_buckle";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "col.inp") << deck;
  ASSERT_EQ(run_ccx(dir / "col.inp"), 0);
  const std::vector<double> ref = ccx_factors(dir / "col.dat");
  ASSERT_EQ(ref.size(), 4u);
  const JobResult r = test::run_deck(deck);
  ASSERT_EQ(r.exit_code, 0) << r.error;
  ASSERT_EQ(r.modes.size(), 1u);
  const EigenSummary& m = r.modes.front().second;
  ASSERT_EQ(m.modes.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    std::cout << fmt::format("  mode {}: gapfem {:.7e}, ccx {:.7e}, difference {:.2e}\n", k + 1,
                             m.modes[k].eigenvalue, ref[k], m.modes[k].eigenvalue / ref[k] - 1);
    EXPECT_NEAR(m.modes[k].eigenvalue, ref[k], 2e-6 * ref[k]) << "mode " << k + 1;
  }
}

} // namespace
