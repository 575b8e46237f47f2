// The kernel harness on every continuum element type (full, reduced, incompatible, quadratic;
// 3-D, plane, axisymmetric), small strain and NLGEOM, with and without thermal strain: the
// tangent and the follower pressure's load stiffness against central differences,
// revert-then-evaluate, and rigid motions.
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

class ContinuumTangent : public ::testing::TestWithParam<TangentCase> {
 protected:
  /// The element of the case at random displacements of 1 % (small strain) or 5 % (NLGEOM) of
  /// its size, heated from 20 to 150 in the thermal cases.
  static ElementHarness element(const TangentCase& c) {
    ElementHarness h(c.type, reference_nodes(c.type));
    h.ctx.nlgeom = c.nlgeom;
    if (c.thermal) h.set_temperature(150.0, 20.0);
    random_displacements(h.u, c.nlgeom ? 0.05 : 0.01, 1234u + static_cast<unsigned>(c.type));
    return h;
  }
};

// The tangent against central differences (the harness's tolerance: truncation by Richardson,
// rounding of the rows' forces). The residual is a polynomial of degree <= 3 in u (St.
// Venant-Kirchhoff; CAX's hoop term adds 1/R factors but stays polynomial in u), so the
// difference resolves every entry to ~1e-10 of its row; a wrong term shows at O(|u|) ~ 1e-2. The
// element energy is a function of u (B-bar included), so the kernel calls its tangent symmetric
// and the harness checks that it is.
TEST_P(ContinuumTangent, MatchesCentralDifferences) {
  ElementHarness h = element(GetParam());
  const FdReport fd = expect_fd_tangent(h);
  EXPECT_FALSE(h.evaluate().unsymmetric);
  EXPECT_GT(*std::max_element(fd.fd.begin(), fd.fd.end()), 0.0);
}

TEST_P(ContinuumTangent, RevertIsExact) {
  ElementHarness h = element(GetParam());
  expect_revert_is_exact(h);
}

// A translation (CAX: along the axis) and a rotation (small strain: infinitesimal, residual
// unchanged; NLGEOM: a finite rotation of the deformed state, residual and tangent turn with it;
// none for CAX) of the deformed, heated element. The first-order reduced elements' hourglass
// forces (ENHANCED, the default) turn with the body from the reference state only
// (hourglass_test.cpp).
TEST_P(ContinuumTangent, RigidBodyInvariance) {
  ElementHarness h = element(GetParam());
  expect_rigid_body_invariance(h, {.from_reference = h.kernel->has_artificial_energy()});
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
  const int n_faces = static_cast<int>(element_faces(shape_of(t)).size());
  for (int face = 1; face <= n_faces; ++face) {
    SCOPED_TRACE("face " + std::to_string(face));
    ASSERT_TRUE(h.kernel->supports_load(DistLoadKind::Pressure, face));
    DistributedLoad ld;
    ld.kind = DistLoadKind::Pressure;
    ld.face = face;
    const FdReport fd = expect_fd_load_stiffness(h, ld, 7.5);
    double fmax = 0.0;
    for (double v : fd.fd) fmax = std::max(fmax, std::abs(v));
    EXPECT_GT(fmax, 0.0);
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
