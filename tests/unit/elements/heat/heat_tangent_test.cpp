// Finite-difference checks of the tangents of every heat-transfer and coupled element: conduction
// (with temperature-dependent conductivity), capacity (with temperature-dependent density and
// specific heat), the thermal-strain coupling block of the coupled elements, and films.
#include "heat_fixture.hpp"

#include <fmt/format.h>

namespace gapfem::test::heat {
namespace {

const std::vector<ElementType> kHeatTypes = heat_types(false);
const std::vector<ElementType> kCoupledTypes = heat_types(true);

struct Case {
  ElementType type;
  bool varying;   ///< temperature-dependent properties
  bool transient; ///< capacity term active
  bool nlgeom;
};

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  return fmt::format(
      "{}_{}_{}{}", element_info(info.param.type).name, info.param.varying ? "tdep" : "const",
      info.param.transient ? "transient" : "steady", info.param.nlgeom ? "_nlgeom" : "");
}

std::vector<Case> all_cases() {
  std::vector<Case> c;
  for (ElementType t : kHeatTypes)
    for (bool v : {false, true})
      for (bool tr : {false, true}) c.push_back({t, v, tr, false});
  for (ElementType t : kCoupledTypes)
    for (bool v : {false, true})
      for (bool tr : {false, true})
        for (bool nl : {false, true}) c.push_back({t, v, tr, nl});
  return c;
}

/// Largest |A - B| and |B| over the entries (i, j) of one block (rows/cols selected by predicates).
struct BlockDiff {
  double diff = 0.0, scale = 0.0;
};

class HeatTangent : public ::testing::TestWithParam<Case> {};

// The residual is smooth in u and T away from the table breakpoints (0 and 200; the random
// temperatures lie in [40, 160]). Steps: cbrt(eps) * 100 for temperatures of O(100) and
// cbrt(eps) * 0.1 for displacements of O(0.01) (relative steps ~ 6e-6), balancing the O(h^2)
// truncation error against the O(eps/h) round-off, both ~ 1e-10 relative. Each block (uu, uT, Tu,
// TT) is compared against its own largest entry, since the thermal-strain block is ~1e-6 of the
// mechanical stiffness: a tolerance of 1e-6 per block is four orders above the FD error and far
// below the size of any missing term (e.g. the k'(T) grad T term is ~ 10% of the conduction
// block with these tables).
TEST_P(HeatTangent, MatchesCentralDifferences) {
  const Case c = GetParam();
  Props p;
  p.varying = c.varying;
  p.alpha = 1.2e-5;
  Harness h(c.type, nodes_of(c.type), p, 0.8, 20.0);
  h.ctx.nlgeom = c.nlgeom;
  if (c.transient) h.set_transient(25.0);
  randomize(h, 40.0, 160.0, 0.01, 77u + static_cast<unsigned>(c.type));
  std::vector<double> r0, K, rp, rm;
  bool unsym = false;
  h.evaluate(r0, &K, &unsym);
  const int n = h.n();
  const double eps3 = std::cbrt(std::numeric_limits<double>::epsilon());
  std::vector<double> Kfd(n * n);
  for (int j = 0; j < n; ++j) {
    const double step = eps3 * (h.is_nt(j) ? 100.0 : 0.1);
    const double keep = h.u[j];
    h.u[j] = keep + step;
    h.evaluate(rp);
    h.u[j] = keep - step;
    h.evaluate(rm);
    h.u[j] = keep;
    for (int i = 0; i < n; ++i) Kfd[i * n + j] = (rp[i] - rm[i]) / (2.0 * step);
  }
  BlockDiff blocks[2][2];
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      BlockDiff& b = blocks[h.is_nt(i)][h.is_nt(j)];
      b.diff = std::max(b.diff, std::abs(K[i * n + j] - Kfd[i * n + j]));
      b.scale = std::max(b.scale, std::abs(Kfd[i * n + j]));
    }
  const char* names[2][2] = {{"uu", "uT"}, {"Tu", "TT"}};
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      EXPECT_LE(blocks[a][b].diff, 1e-6 * blocks[a][b].scale)
          << names[a][b] << ": max |K - K_fd| = " << blocks[a][b].diff
          << ", max |K_fd| = " << blocks[a][b].scale;
  EXPECT_GT(blocks[1][1].scale, 0.0);
  // Conduction and capacity do not depend on the displacements (reference geometry).
  EXPECT_EQ(blocks[1][0].scale, 0.0);
  if (element_info(c.type).displacement) {
    EXPECT_GT(blocks[0][1].scale, 0.0); // thermal strain couples
    EXPECT_TRUE(unsym);
  } else {
    EXPECT_EQ(unsym, c.varying); // only k(T) makes the conduction tangent unsymmetric
  }
}

INSTANTIATE_TEST_SUITE_P(Heat, HeatTangent, ::testing::ValuesIn(all_cases()), case_name);

class HeatFilmTangent : public ::testing::TestWithParam<ElementType> {};

// Film on face 1: f_ext,a depends linearly on the temperatures, so central differences are exact
// up to round-off; the kernel returns -d f_ext / dT in the tangent.
TEST_P(HeatFilmTangent, MatchesCentralDifferences) {
  const ElementType t = GetParam();
  Harness h(t, nodes_of(t), {}, 0.8);
  randomize(h, 40.0, 160.0, 0.0, 5u);
  std::vector<double> f0, K, fp, fm;
  h.load(DistLoadKind::Film, 1, 12.5, 80.0, f0, &K);
  const int n = h.n();
  double diff = 0.0, scale = 0.0;
  for (int j = 0; j < n; ++j) {
    const double keep = h.u[j];
    h.u[j] = keep + 0.5;
    h.load(DistLoadKind::Film, 1, 12.5, 80.0, fp);
    h.u[j] = keep - 0.5;
    h.load(DistLoadKind::Film, 1, 12.5, 80.0, fm);
    h.u[j] = keep;
    for (int i = 0; i < n; ++i) {
      const double fd = -(fp[i] - fm[i]) / 1.0;
      diff = std::max(diff, std::abs(K[i * n + j] - fd));
      scale = std::max(scale, std::abs(fd));
    }
  }
  EXPECT_GT(scale, 0.0);
  EXPECT_LE(diff, 1e-12 * scale * n);
  // At the sink temperature the film carries no heat.
  for (int a = 0; a < static_cast<int>(h.X.size()); ++a) h.u[h.nt(a)] = 80.0;
  h.load(DistLoadKind::Film, 1, 12.5, 80.0, f0);
  for (double v : f0) EXPECT_NEAR(v, 0.0, 1e-12);
}

std::vector<ElementType> film_types() {
  std::vector<ElementType> v(std::begin(kHeatTypes), std::end(kHeatTypes));
  v.insert(v.end(), std::begin(kCoupledTypes), std::end(kCoupledTypes));
  return v;
}

INSTANTIATE_TEST_SUITE_P(Heat, HeatFilmTangent, ::testing::ValuesIn(film_types()),
                         [](const auto& info) {
                           return std::string(element_info(info.param).name);
                         });

} // namespace
} // namespace gapfem::test::heat
