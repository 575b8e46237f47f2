#pragma once
// A small version of bench/gen_block.py's slab for the backend tests: a quarter plate of C3D8
// (side L, thickness h, nx x nx x nz elements, symmetry on x = 0 and y = 0) on one GAPUNI per
// bottom node to a fixed ground node, clearances graded with the squared distance from the centre
// in 4 classes, a uniform load on the top nodes, NLGEOM. Every equation is a translation, so the
// iterative backend aggregates nodes (block size 3) from 1,000 equations on.
#include <cmath>
#include <fmt/format.h>
#include <string>
#include <vector>

namespace gapfem::test {

inline std::string slab_on_gaps(int nx, int nz, double length = 10.0, double height = 0.4,
                                double load = -20.0, double dmax = 2e-4) {
  const int n1 = nx + 1, per_layer = n1 * n1, n_block = per_layer * (nz + 1);
  auto nid = [&](int i, int j, int k) { return 1 + i + n1 * j + per_layer * k; };
  std::string d = "*HEADING\nslab on GAPUNI\n*NODE\n";
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= nx; ++j)
      for (int i = 0; i <= nx; ++i)
        d += fmt::format("{}, {}, {}, {}\n", nid(i, j, k), length * i / nx, length * j / nx,
                         height * k / nz);
  d += "*NODE, NSET=GROUND\n";
  for (int j = 0; j <= nx; ++j)
    for (int i = 0; i <= nx; ++i)
      d += fmt::format("{}, {}, {}, -1.\n", n_block + nid(i, j, 0), length * i / nx,
                       length * j / nx);
  d += "*ELEMENT, TYPE=C3D8, ELSET=SLAB\n";
  int e = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < nx; ++j)
      for (int i = 0; i < nx; ++i)
        d += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", ++e, nid(i, j, k),
                         nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k), nid(i, j, k + 1),
                         nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1));
  std::vector<std::vector<int>> classes(4);
  for (int j = 0; j <= nx; ++j)
    for (int i = 0; i <= nx; ++i) {
      const double rr = (i * i + j * j) / (2.0 * nx * nx);
      classes[static_cast<int>(std::lround(3 * rr))].push_back(nid(i, j, 0));
    }
  for (int c = 0; c < 4; ++c) {
    if (classes[c].empty()) continue;
    d += fmt::format("*ELEMENT, TYPE=GAPUNI, ELSET=G{}\n", c);
    for (int n : classes[c]) d += fmt::format("{}, {}, {}\n", ++e, n, n_block + n);
    d += fmt::format("*GAP, ELSET=G{}\n{}, 0., 0., -1.\n", c, dmax * c / 3);
  }
  d += "*MATERIAL, NAME=STEEL\n*ELASTIC\n2e5, 0.3\n*SOLID SECTION, ELSET=SLAB, MATERIAL=STEEL\n";
  d += "*BOUNDARY\nGROUND, 1, 3\n";
  for (int k = 0; k <= nz; ++k)
    for (int t = 0; t <= nx; ++t)
      d += fmt::format("{}, 1, 1\n{}, 2, 2\n", nid(0, t, k), nid(t, 0, k));
  d += "*STEP, NLGEOM\n*STATIC\n0.5, 1.\n*CLOAD\n";
  const double h = length / nx;
  for (int j = 0; j <= nx; ++j)
    for (int i = 0; i <= nx; ++i) {
      const double w = (i == 0 || i == nx ? 0.5 : 1.0) * (j == 0 || j == nx ? 0.5 : 1.0);
      d += fmt::format("{}, 3, {}\n", nid(i, j, nz), load * h * h * w);
    }
  d += "*END STEP\n";
  return d;
}

} // namespace gapfem::test
