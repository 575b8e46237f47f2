#pragma once
// Running CalculiX (ccx) on a deck and reading its printed nodal tables, for comparison tests.
// Tests using it call GTEST_SKIP() with a visible message when ccx is not installed.
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace gapfem::test {

inline std::string find_ccx() {
  const char* path = std::getenv("PATH");
  std::stringstream ss(path ? path : "");
  std::string dir;
  while (std::getline(ss, dir, ':')) {
    const auto p = std::filesystem::path(dir) / "ccx";
    if (std::filesystem::exists(p)) return p.string();
  }
  return {};
}

/// Runs `ccx -i <stem>` in the deck's directory; returns the exit status.
inline int run_ccx(const std::filesystem::path& deck) {
  const std::string cmd = "cd '" + deck.parent_path().string() + "' && OMP_NUM_THREADS=1 '" +
                          find_ccx() + "' -i '" + deck.stem().string() + "' > ccx.log 2>&1";
  return std::system(cmd.c_str());
}

/// The last "forces (fx,fy,fz) for set SET" table of a ccx .dat file: node → (fx, fy, fz).
inline std::map<long, std::array<double, 3>> ccx_last_forces(const std::filesystem::path& dat,
                                                             const std::string& set) {
  std::ifstream in(dat);
  std::string line;
  std::map<long, std::array<double, 3>> table;
  bool reading = false;
  while (std::getline(in, line)) {
    if (line.find("forces (fx,fy,fz) for set " + set) != std::string::npos &&
        line.find("total") == std::string::npos) {
      table.clear();
      reading = true;
      continue;
    }
    if (!reading) continue;
    std::istringstream ls(line);
    long node;
    std::array<double, 3> f;
    if (ls >> node >> f[0] >> f[1] >> f[2])
      table[node] = f;
    else if (!table.empty())
      reading = false;
  }
  return table;
}

} // namespace gapfem::test
