#pragma once
// Structured meshes of quadratic elements written as Abaqus deck text, for the verification decks
// of the quadratic continuum elements (issue 13). A mesh is a grid of (2 n + 1) points per
// direction in parameter space (s, t[, w]) in [0, 1]; a map places each point, so curved
// boundaries (arcs) get their midside nodes on the curve. Serendipity elements use the grid points
// with at most one odd index; node labels are 1 + i + (2 nx + 1) (j + (2 ny + 1) k).
#include <array>
#include <fmt/format.h>
#include <functional>
#include <string>
#include <vector>

namespace gapfem::test {

using Point3 = std::array<double, 3>;

struct QuadMesh2D {
  int nx = 1, ny = 1;
  int label(int i, int j) const { return 1 + i + (2 * nx + 1) * j; }
  /// *NODE lines (z = 0) for the map (s, t) -> (x, y).
  std::string nodes(const std::function<std::array<double, 2>(double, double)>& map) const {
    std::string out = "*NODE\n";
    for (int j = 0; j <= 2 * ny; ++j)
      for (int i = 0; i <= 2 * nx; ++i) {
        if (i % 2 && j % 2) continue;
        const auto p = map(i / (2.0 * nx), j / (2.0 * ny));
        out += fmt::format("{}, {:.17g}, {:.17g}\n", label(i, j), p[0], p[1]);
      }
    return out;
  }
  /// *ELEMENT block of Quad8 elements (labels 1.., s fastest), counter-clockwise in (s, t).
  std::string elements(const std::string& type, const std::string& elset) const {
    std::string out = fmt::format("*ELEMENT, TYPE={}, ELSET={}\n", type, elset);
    int e = 1;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int I = 2 * i, J = 2 * j;
        out += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", e++, label(I, J),
                           label(I + 2, J), label(I + 2, J + 2), label(I, J + 2), label(I + 1, J),
                           label(I + 2, J + 1), label(I + 1, J + 2), label(I, J + 1));
      }
    return out;
  }
  int element(int i, int j) const { return 1 + i + nx * j; }
  /// Labels of the grid line i = const (all its nodes).
  std::vector<int> line_i(int i) const {
    std::vector<int> v;
    for (int j = 0; j <= 2 * ny; ++j)
      if (!(i % 2 && j % 2)) v.push_back(label(i, j));
    return v;
  }
  std::vector<int> all() const {
    std::vector<int> v;
    for (int j = 0; j <= 2 * ny; ++j)
      for (int i = 0; i <= 2 * nx; ++i)
        if (!(i % 2 && j % 2)) v.push_back(label(i, j));
    return v;
  }
};

struct HexMesh20 {
  int nx = 1, ny = 1, nz = 1;
  int label(int i, int j, int k) const { return 1 + i + (2 * nx + 1) * (j + (2 * ny + 1) * k); }
  static bool present(int i, int j, int k) { return (i % 2) + (j % 2) + (k % 2) < 2; }
  std::string nodes(const std::function<Point3(double, double, double)>& map) const {
    std::string out = "*NODE\n";
    for (int k = 0; k <= 2 * nz; ++k)
      for (int j = 0; j <= 2 * ny; ++j)
        for (int i = 0; i <= 2 * nx; ++i) {
          if (!present(i, j, k)) continue;
          const Point3 p = map(i / (2.0 * nx), j / (2.0 * ny), k / (2.0 * nz));
          out += fmt::format("{}, {:.17g}, {:.17g}, {:.17g}\n", label(i, j, k), p[0], p[1], p[2]);
        }
    return out;
  }
  /// Node labels of element (i, j, k) in the Abaqus C3D20 order.
  std::vector<int> connectivity(int i, int j, int k) const {
    static constexpr int c[20][3] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 2},
                                     {2, 0, 2}, {2, 2, 2}, {0, 2, 2}, {1, 0, 0}, {2, 1, 0},
                                     {1, 2, 0}, {0, 1, 0}, {1, 0, 2}, {2, 1, 2}, {1, 2, 2},
                                     {0, 1, 2}, {0, 0, 1}, {2, 0, 1}, {2, 2, 1}, {0, 2, 1}};
    std::vector<int> v;
    for (const auto& o : c) v.push_back(label(2 * i + o[0], 2 * j + o[1], 2 * k + o[2]));
    return v;
  }
  /// One element line (continued after the 15th node).
  static std::string element_line(int label, const std::vector<int>& nodes) {
    std::string out = fmt::format("{}", label);
    for (std::size_t a = 0; a < nodes.size(); ++a)
      out += fmt::format(", {}{}", nodes[a], a == 14 ? ",\n" : "");
    return out + "\n";
  }
  std::string elements(const std::string& type, const std::string& elset) const {
    std::string out = fmt::format("*ELEMENT, TYPE={}, ELSET={}\n", type, elset);
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) out += element_line(element(i, j, k), connectivity(i, j, k));
    return out;
  }
  int element(int i, int j, int k) const { return 1 + i + nx * (j + ny * k); }
  /// Nodes on a grid plane: axis 0 (i = idx), 1 (j = idx) or 2 (k = idx).
  std::vector<int> plane(int axis, int idx) const {
    std::vector<int> v;
    for (int k = 0; k <= 2 * nz; ++k)
      for (int j = 0; j <= 2 * ny; ++j)
        for (int i = 0; i <= 2 * nx; ++i) {
          const int g[3] = {i, j, k};
          if (g[axis] == idx && present(i, j, k)) v.push_back(label(i, j, k));
        }
    return v;
  }
  std::vector<int> all() const {
    std::vector<int> v;
    for (int k = 0; k <= 2 * nz; ++k)
      for (int j = 0; j <= 2 * ny; ++j)
        for (int i = 0; i <= 2 * nx; ++i)
          if (present(i, j, k)) v.push_back(label(i, j, k));
    return v;
  }
};

/// "*NSET, NSET=name" with the labels, 16 per line.
inline std::string nset(const std::string& name, const std::vector<int>& labels) {
  std::string out = fmt::format("*NSET, NSET={}\n", name);
  for (std::size_t i = 0; i < labels.size(); ++i)
    out +=
        fmt::format("{}{}", labels[i], (i + 1) % 16 == 0 || i + 1 == labels.size() ? "\n" : ", ");
  return out;
}

} // namespace gapfem::test
