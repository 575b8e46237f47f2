// The kernel harness on every heat-transfer and coupled element: the tangent against central
// differences (conduction with temperature-dependent conductivity, capacity with
// temperature-dependent density and specific heat, the thermal-strain coupling block of the
// coupled elements, films), revert-then-evaluate, and rigid motions.
#include "heat_fixture.hpp"

#include <cmath>
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

class HeatTangent : public ::testing::TestWithParam<Case> {
 protected:
  /// The element of the case at random temperatures in [40, 160] (start and end of the
  /// increment) and random displacements of 1 % of its size, between the table breakpoints (0 and
  /// 200) so that the residual is smooth.
  static Harness element(const Case& c) {
    Props p;
    p.varying = c.varying;
    p.alpha = 1.2e-5;
    Harness h(c.type, nodes_of(c.type), p, 0.8, 20.0);
    h.ctx.nlgeom = c.nlgeom;
    if (c.transient) h.set_transient(25.0);
    randomize(h, 40.0, 160.0, 0.01, 77u + static_cast<unsigned>(c.type));
    return h;
  }
};

// Every block (uu, uT, Tu, TT) against central differences: the harness's tolerance is relative to
// each row's own forces, so the thermal-strain block (~1e-6 of the mechanical stiffness) and the
// k'(T) grad T term (~10 % of the conduction block with these tables) are checked at their own
// scale. Then the structure of the differences: conduction and capacity do not depend on the
// displacements (reference geometry); thermal strain couples; only k(T) makes the conduction
// tangent unsymmetric.
TEST_P(HeatTangent, MatchesCentralDifferences) {
  const Case c = GetParam();
  Harness h = element(c);
  const FdReport fd = expect_fd_tangent(h);
  const bool unsym = h.evaluate().unsymmetric;
  double scale[2][2] = {{0, 0}, {0, 0}};
  for (int i = 0; i < h.n(); ++i)
    for (int j = 0; j < h.n(); ++j) {
      double& b = scale[h.is_nt(i)][h.is_nt(j)];
      b = std::max(b, std::abs(fd.fd_at(i, j)));
    }
  EXPECT_GT(scale[1][1], 0.0);
  EXPECT_EQ(scale[1][0], 0.0);
  if (element_info(c.type).displacement) {
    EXPECT_GT(scale[0][1], 0.0); // thermal strain couples
    EXPECT_TRUE(unsym);
  } else {
    EXPECT_EQ(unsym, c.varying); // only k(T) makes the conduction tangent unsymmetric
  }
}

TEST_P(HeatTangent, RevertIsExact) {
  Harness h = element(GetParam());
  expect_revert_is_exact(h);
}

// Heat transfer: the element moved and turned in space (its frame) conducts the same (DCAX: moved
// along the axis only). Coupled: a rigid motion of the body (as the mechanical twins, the
// first-order reduced ones turned from the reference state; temperatures unchanged).
TEST_P(HeatTangent, RigidBodyInvariance) {
  Harness h = element(GetParam());
  expect_rigid_body_invariance(h, {.frame = !element_info(GetParam().type).displacement,
                                   .from_reference = h.kernel->has_artificial_energy()});
}

INSTANTIATE_TEST_SUITE_P(Heat, HeatTangent, ::testing::ValuesIn(all_cases()), case_name);

class HeatFilmTangent : public ::testing::TestWithParam<ElementType> {};

// Film on face 1: f_ext,a depends linearly on the temperatures; the kernel returns -d f_ext / dT
// in the tangent. At the sink temperature the film carries no heat.
TEST_P(HeatFilmTangent, MatchesCentralDifferences) {
  const ElementType t = GetParam();
  Harness h(t, nodes_of(t), {}, 0.8);
  randomize(h, 40.0, 160.0, 0.0, 5u);
  const FdReport fd =
      expect_fd_load_stiffness(h, distributed_load(DistLoadKind::Film, 1, 12.5, 80.0), 12.5, 80.0);
  EXPECT_GT(*std::max_element(fd.fd.begin(), fd.fd.end()), 0.0);
  for (int a = 0; a < static_cast<int>(h.X.size()); ++a) h.u[h.nt(a)] = 80.0;
  std::vector<double> f0;
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

class HeatRadiationTangent : public ::testing::TestWithParam<ElementType> {};

// Radiation on face 1 (eps = 0.7, sigma = 5.67e-8, absolute zero -273.15): f_ext is quartic in
// the temperatures; the kernel returns -d f_ext / dT. At the sink temperature it carries no heat,
// and at a uniform T the face's total is eps sigma ((Ts - Z)^4 - (T - Z)^4) times its area, the
// film's total with h = 1 times that flux over (Ts - T).
TEST_P(HeatRadiationTangent, MatchesCentralDifferencesAndTheUniformFlux) {
  const ElementType t = GetParam();
  Harness h(t, nodes_of(t), {}, 0.8);
  randomize(h, 40.0, 160.0, 0.0, 7u);
  DistributedLoad ld = distributed_load(DistLoadKind::Radiation, 1, 0.7, 80.0);
  ld.stefan_boltzmann = 5.67e-8;
  ld.absolute_zero = -273.15;
  const FdReport fd = expect_fd_load_stiffness(h, ld, 0.7, 80.0);
  EXPECT_GT(*std::max_element(fd.fd.begin(), fd.fd.end()), 0.0);
  for (int a = 0; a < static_cast<int>(h.X.size()); ++a) h.u[h.nt(a)] = 80.0;
  for (double v : h.load(ld, 0.7, 80.0, nullptr)) EXPECT_NEAR(v, 0.0, 1e-12);
  const double T = 150.0, Ts = 80.0;
  for (int a = 0; a < static_cast<int>(h.X.size()); ++a) h.u[h.nt(a)] = T;
  double radiated = 0.0, film = 0.0;
  for (double v : h.load(ld, 0.7, Ts, nullptr)) radiated += v;
  std::vector<double> f;
  h.load(DistLoadKind::Film, 1, 1.0, Ts, f);
  for (double v : f) film += v; // = (Ts - T) x area
  const double q = 0.7 * 5.67e-8 * (std::pow(Ts + 273.15, 4) - std::pow(T + 273.15, 4));
  EXPECT_NEAR(radiated, film / (Ts - T) * q, 1e-12 * std::abs(film / (Ts - T) * q));
}

INSTANTIATE_TEST_SUITE_P(Heat, HeatRadiationTangent, ::testing::ValuesIn(film_types()),
                         [](const auto& info) {
                           return std::string(element_info(info.param).name);
                         });

} // namespace
} // namespace gapfem::test::heat
