// Finite-difference checks of the continuum element tangents (internal forces and follower
// pressure) for every element type, small strain and NLGEOM, with and without thermal strain.
#include "continuum_fixture.hpp"
#include "fe/element_faces.hpp"

#include <fmt/format.h>

namespace gapfem::test {
namespace {

struct TangentCase {
  ElementType type;
  bool nlgeom;
  bool thermal;
};

std::string case_name(const ::testing::TestParamInfo<TangentCase>& info) {
  return fmt::format("{}_{}_{}", element_info(info.param.type).name,
                     info.param.nlgeom ? "nlgeom" : "small",
                     info.param.thermal ? "thermal" : "iso");
}

std::vector<TangentCase> all_cases() {
  std::vector<TangentCase> c;
  for (ElementType t : continuum_types())
    for (bool nl : {false, true})
      for (bool th : {false, true}) c.push_back({t, nl, th});
  return c;
}

class ContinuumTangent : public ::testing::TestWithParam<TangentCase> {};

// Tolerance: the residual is a polynomial of degree <= 3 in u (St. Venant-Kirchhoff; for CAX the
// hoop term adds 1/R factors but stays polynomial in u). The central-difference truncation error is
// h^2/6 |r'''| ~ 1e-11 |K| for h = cbrt(eps) ~ 6e-6 and O(1) third derivatives relative to |K|,
// and the round-off error eps |r| / h ~ 1e-11 |K| for |u| ~ 0.05. A tolerance of 1e-7 |K| is four
// orders above both, while a wrong term in the tangent shows up at O(|u|) ~ 1e-2 |K| or larger.
constexpr double kRelTol = 1e-7;

TEST_P(ContinuumTangent, MatchesCentralDifferences) {
  const TangentCase c = GetParam();
  ElementHarness h(c.type, reference_nodes(c.type));
  h.ctx.nlgeom = c.nlgeom;
  if (c.thermal) h.set_temperature(150.0, 20.0);
  random_displacements(h.u, c.nlgeom ? 0.05 : 0.01, 1234u + static_cast<unsigned>(c.type));
  std::vector<double> r0, K;
  h.evaluate(r0, &K);
  const int n = h.n();
  const double step = fd_step();
  std::vector<double> Kfd(n * n), rp, rm;
  for (int j = 0; j < n; ++j) {
    const double keep = h.u[j];
    h.u[j] = keep + step;
    h.evaluate(rp);
    h.u[j] = keep - step;
    h.evaluate(rm);
    h.u[j] = keep;
    for (int i = 0; i < n; ++i) Kfd[i * n + j] = (rp[i] - rm[i]) / (2.0 * step);
  }
  const auto [diff, kmax] = max_diff(K, Kfd);
  EXPECT_GT(kmax, 0.0);
  EXPECT_LE(diff, kRelTol * kmax) << "max |K - K_fd| = " << diff << " with max |K| = " << kmax;
  // The element energy is a function of u (B-bar included), so the tangent is symmetric.
  double asym = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) asym = std::max(asym, std::abs(K[i * n + j] - K[j * n + i]));
  EXPECT_LE(asym, 1e-12 * kmax);
}

INSTANTIATE_TEST_SUITE_P(Continuum, ContinuumTangent, ::testing::ValuesIn(all_cases()), case_name);

class ContinuumPressureTangent : public ::testing::TestWithParam<ElementType> {};

// Follower pressure: f_ext(u) on the current face; the kernel adds -df/du. The load is a polynomial
// of degree <= 2 in u (3-D faces, axisymmetric edges), so the same tolerance argument applies.
TEST_P(ContinuumPressureTangent, FollowerLoadStiffnessMatchesCentralDifferences) {
  const ElementType t = GetParam();
  ElementHarness h(t, reference_nodes(t));
  h.ctx.nlgeom = true;
  random_displacements(h.u, 0.05, 99u);
  const int n = h.n();
  const int n_faces = static_cast<int>(element_faces(shape_of(t)).size());
  const double p = 7.5;
  for (int face = 1; face <= n_faces; ++face) {
    ASSERT_TRUE(h.kernel->supports_load(DistLoadKind::Pressure, face));
    DistributedLoad ld;
    ld.kind = DistLoadKind::Pressure;
    ld.face = face;
    auto eval = [&](std::vector<double>& f, std::vector<double>* K) {
      f.assign(n, 0.0);
      std::vector<double> Kdummy(n * n, 0.0);
      if (K) K->assign(n * n, 0.0);
      ElementInput in = h.input();
      h.kernel->load(in, ld, p, 0.0, f, K ? std::span<double>(*K) : std::span<double>(Kdummy));
    };
    std::vector<double> f0, K, fp, fm;
    eval(f0, &K);
    std::vector<double> Kfd(n * n);
    const double step = fd_step();
    for (int j = 0; j < n; ++j) {
      const double keep = h.u[j];
      h.u[j] = keep + step;
      eval(fp, nullptr);
      h.u[j] = keep - step;
      eval(fm, nullptr);
      h.u[j] = keep;
      for (int i = 0; i < n; ++i) Kfd[i * n + j] = -(fp[i] - fm[i]) / (2.0 * step);
    }
    const auto [diff, kmax] = max_diff(K, Kfd);
    EXPECT_GT(kmax, 0.0) << "face " << face;
    EXPECT_LE(diff, kRelTol * kmax) << "face " << face;
  }
  EXPECT_FALSE(h.kernel->supports_load(DistLoadKind::Pressure, n_faces + 1));
  EXPECT_FALSE(h.kernel->supports_load(DistLoadKind::Pressure, 0));
}

INSTANTIATE_TEST_SUITE_P(Continuum, ContinuumPressureTangent,
                         ::testing::ValuesIn(continuum_types()), [](const auto& info) {
                           return std::string(element_info(info.param).name);
                         });

} // namespace
} // namespace gapfem::test
