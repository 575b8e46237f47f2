// Unit tests of the coupled temperature-displacement shells S3RT, S4T, S4RT and S8RT
// (elements/structural/coupled_shell.hpp): the whole tangent, K_uT included, against central
// differences of the residual (linear and NLGEOM, temperature-dependent elasticity and
// expansion), and the DOF layout.
#include "elements/element_kernel.hpp"
#include "model/model.hpp"
#include "unit/elements/kernel_harness.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace gapfem::test {
namespace {

std::vector<Vec3> nodes_of(ElementType t) {
  std::vector<Vec3> X;
  if (t == ElementType::S3RT) return {{0.0, 0.0, 0.0}, {1.1, 0.1, 0.05}, {0.2, 0.9, -0.03}};
  X = {{0.0, 0.0, 0.0}, {1.1, 0.1, 0.05}, {1.0, 0.9, -0.04}, {-0.1, 0.8, 0.02}};
  if (t == ElementType::S8RT)
    for (int a = 0; a < 4; ++a) {
      const Vec3& A = X[a];
      const Vec3& B = X[(a + 1) % 4];
      X.push_back({0.5 * (A[0] + B[0]) + 0.02, 0.5 * (A[1] + B[1]) - 0.01, 0.5 * (A[2] + B[2])});
    }
  return X;
}

/// One coupled shell of type t with `points` temperatures through the thickness, as a probe.
struct CoupledHarness {
  Model model;
  KernelProbe p;

  CoupledHarness(ElementType t, int points) : p(probe_of(model, t, points)) {
    p.ctx.procedure = Procedure::CoupledTempDisp;
    p.ctx.model_size = 1.5;
  }
  static KernelProbe probe_of(Model& model, ElementType t, int points) {
    const std::vector<Vec3> X = nodes_of(t);
    add_lone_element(model, t, X);
    model.source_files.push_back("test.inp");
    Material m;
    m.name = "M";
    m.elastic.n_values = 2;
    m.elastic.values = {2.0e5, 0.3, 1.4e5, 0.32}; // E(T), nu(T) between 0 and 200
    m.elastic.keys = {0.0, 200.0};
    m.expansion.n_values = 1;
    m.expansion.values = {1.2e-5, 1.6e-5};
    m.expansion.keys = {0.0, 200.0};
    m.conductivity.n_values = 1;
    m.conductivity.values = {40.0, 60.0};
    m.conductivity.keys = {0.0, 200.0};
    m.density.n_values = 1;
    m.density.values = {7.8e-3};
    m.specific_heat.n_values = 1;
    m.specific_heat.values = {460.0};
    model.materials.push_back(m);
    ShellSection sec;
    sec.elset = "SHELL";
    sec.material = 0;
    sec.thickness = 0.05;
    sec.n_points = points;
    model.shell_sections.push_back(sec);
    model.element_property.push_back({PropertyRef::Kind::Shell, 0});
    model.initial_temperature.assign(X.size(), 20.0);
    return KernelProbe::of(model);
  }
  int n() const { return p.n(); }
};

struct Case {
  ElementType type;
  int points;
  bool nlgeom;
};

class CoupledShell : public ::testing::TestWithParam<Case> {};

// Random rotations up to 0.05 rad, displacements 1e-3 and temperatures 20..180 (a gradient
// through the thickness at every node): every column of the tangent, K_uT included, against
// central differences of the residual; revert-then-evaluate.
TEST_P(CoupledShell, TangentMatchesCentralDifferences) {
  CoupledHarness h(GetParam().type, GetParam().points);
  h.p.ctx.nlgeom = GetParam().nlgeom;
  h.p.ctx.transient = true;
  h.p.ctx.dt = 0.5;
  const int per = 6 + GetParam().points;
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> d(-1e-3, 1e-3), r(-0.05, 0.05), T(20.0, 180.0);
  for (int i = 0; i < h.n(); ++i) {
    const int c = i % per;
    h.p.u[i] = c < 3 ? d(gen) : c < 6 ? r(gen) : T(gen);
    h.p.u0[i] = c < 6 ? 0.0 : T(gen);
  }
  expect_fd_tangent(h.p);
  expect_revert_is_exact(h.p);
}

// Rigid motions at a uniform temperature equal to the initial one (no thermal load): from the
// reference state a translation and a rotation of 1.2 rad (NLGEOM) store no energy; at a deformed
// state a translation and an infinitesimal rotation (small strain) change nothing.
TEST_P(CoupledShell, RigidMotionsStoreNoEnergy) {
  CoupledHarness h(GetParam().type, GetParam().points);
  h.p.ctx.nlgeom = GetParam().nlgeom;
  const int per = 6 + GetParam().points;
  for (int i = 0; i < h.n(); ++i)
    if (i % per >= 6) h.p.u[i] = h.p.u0[i] = 20.0;
  if (!GetParam().nlgeom)
    for (int i = 0; i < h.n(); ++i)
      if (i % per < 6) h.p.u[i] = 1e-3 * std::sin(1.0 + i);
  expect_rigid_body_invariance(h.p, {.angle = 1.2});
}

std::vector<Case> all_cases() {
  std::vector<Case> c;
  for (ElementType t : {ElementType::S3RT, ElementType::S4T, ElementType::S4RT, ElementType::S8RT})
    for (bool nl : {false, true}) c.push_back({t, 3, nl});
  c.push_back({ElementType::S4RT, 5, false});
  return c;
}
std::string case_name(const ::testing::TestParamInfo<Case>& i) {
  return std::string(element_info(i.param.type).name) + "_" + std::to_string(i.param.points) +
         (i.param.nlgeom ? "_nlgeom" : "");
}
INSTANTIATE_TEST_SUITE_P(Shell, CoupledShell, ::testing::ValuesIn(all_cases()), case_name);

TEST(CoupledShellDofs, RotationsThenOneTemperaturePerSectionPoint) {
  CoupledHarness h(ElementType::S4RT, 5);
  const auto d = h.p.kernel->node_dofs(1);
  ASSERT_EQ(d.size(), 11u);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(abaqus_number(d[i]), i + 1);
  for (int k = 0; k < 5; ++k) EXPECT_EQ(abaqus_number(d[6 + k]), 11 + k);
}

} // namespace
} // namespace gapfem::test
