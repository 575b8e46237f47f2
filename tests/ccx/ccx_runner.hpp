#pragma once
// Running CalculiX (ccx) on a deck and reading its printed nodal tables, for comparison tests.
// Tests using it call GTEST_SKIP() with a visible message when ccx is not installed.
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
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

/// A block of nx x ny x nz 20-node bricks (Abaqus's node order) over [0, lx] x [0, ly] x [0, lz]:
/// its *NODE data lines, its *ELEMENT keyword and data lines, and the grid point (i, j, k) of each
/// node used, on the (2 nx + 1) x (2 ny + 1) x (2 nz + 1) grid whose label is
/// 1 + i + (2 nx + 1) (j + (2 ny + 1) k).
struct Brick20Block {
  std::string nodes, elements;
  std::map<int, std::array<int, 3>> used;
};
inline Brick20Block brick20_block(int nx, int ny, int nz, double lx, double ly, double lz,
                                  const std::string& type, const std::string& elset) {
  static constexpr int kCorner[20][3] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 2},
                                         {2, 0, 2}, {2, 2, 2}, {0, 2, 2}, {1, 0, 0}, {2, 1, 0},
                                         {1, 2, 0}, {0, 1, 0}, {1, 0, 2}, {2, 1, 2}, {1, 2, 2},
                                         {0, 1, 2}, {0, 0, 1}, {2, 0, 1}, {2, 2, 1}, {0, 2, 1}};
  Brick20Block out;
  out.elements = fmt::format("*ELEMENT, TYPE={}, ELSET={}\n", type, elset);
  int label = 0;
  for (int c = 0; c < nz; ++c)
    for (int b = 0; b < ny; ++b)
      for (int a = 0; a < nx; ++a) {
        out.elements += fmt::format("{}", ++label);
        for (int n = 0; n < 20; ++n) {
          const std::array<int, 3> p{2 * a + kCorner[n][0], 2 * b + kCorner[n][1],
                                     2 * c + kCorner[n][2]};
          const int node = 1 + p[0] + (2 * nx + 1) * (p[1] + (2 * ny + 1) * p[2]);
          out.used[node] = p;
          out.elements += fmt::format(",{}{}", n == 15 ? "\n" : " ", node);
        }
        out.elements += "\n";
      }
  for (const auto& [node, p] : out.used)
    out.nodes += fmt::format("{}, {:.15g}, {:.15g}, {:.15g}\n", node, lx * p[0] / (2 * nx),
                             ly * p[1] / (2 * ny), lz * p[2] / (2 * nz));
  return out;
}

} // namespace gapfem::test
