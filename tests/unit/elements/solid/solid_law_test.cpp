// The material-point seam of the solids (elements/material/solid_law.hpp) proven by a toy law
// that lives in the tests alone: "linear elastic with a state counter" (counting_law.hpp). It is
// registered there (one register_solid_law call, no file of src/ touched) for materials named
// COUNTING, and then runs through every continuum kernel the registry has (full, B-bar, reduced
// with hourglass control, incompatible modes, quadratic, plane stress/strain, axisymmetric and the
// coupled temperature-displacement twins):
//   - residual, tangent (and the coupled kernels' d r / d T columns) equal the built-in elastic
//     law's, small strain and NLGEOM, although the toy law hands its tangent over as a full Voigt
//     matrix (the general D B path) where the built-in law takes the isotropic fast path;
//   - its history is points x 1 slot in the kernel's flat state; the counter equals the number of
//     commits; revert restores it; recover() never writes it;
//   - the tangent passes the harness's central differences, revert-then-evaluate is exact.
// A restart (solver/analysis_restart.cpp saves the flat committed arrays) carries the counter
// over: RestartCarriesTheLawHistory.
#include "elements/material/solid_law.hpp"
#include "test_util.hpp"
#include "unit/elements/counting_law.hpp"
#include "unit/elements/solid/continuum_fixture.hpp"

#include <algorithm>
#include <atomic>
#include <fmt/format.h>

namespace gapfem::test {
namespace {

/// Every continuum type, stress/displacement and coupled.
std::vector<ElementType> every_continuum_type() {
  std::vector<ElementType> out;
  for (const ElementTypeInfo& info : all_element_types())
    if (info.family == ElementFamily::Continuum) out.push_back(info.type);
  return out;
}

/// A one-element model of type t whose material is the built-in elastic one or the toy law.
KernelProbe probe(ElementType t, bool counting, bool nlgeom) {
  auto model = one_element_model(t, reference_nodes(t));
  Material& mat = model->materials[0];
  if (element_info(t).temperature) {
    mat.conductivity.n_values = 1;
    mat.conductivity.values = {45.0};
    mat.specific_heat.n_values = 1;
    mat.specific_heat.values = {4.6e8};
  }
  if (counting) mat.name = "COUNTING";
  KernelProbe p = KernelProbe::of(std::shared_ptr<const Model>(std::move(model)));
  p.ctx.nlgeom = nlgeom;
  random_displacements(p.u, nlgeom ? 0.05 : 0.01, 77u + static_cast<unsigned>(t));
  const int per_node = p.n() / static_cast<int>(p.X.size());
  if (element_info(t).temperature) { // the NT DOFs: a temperature field around 100
    for (std::size_t a = 0; a < p.X.size(); ++a) {
      p.u[a * per_node + per_node - 1] = 100.0 + 10.0 * std::sin(1.0 + a);
      p.u0[a * per_node + per_node - 1] = 100.0;
    }
  } else {
    p.T.assign(p.X.size(), 150.0);
    p.Ti.assign(p.X.size(), 20.0);
  }
  return p;
}

/// |a - b| <= 1e-12 of the largest entry, entry by entry.
void expect_close(const std::vector<double>& a, const std::vector<double>& b,
                  const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  double scale = 0.0;
  for (double v : b) scale = std::max(scale, std::abs(v));
  int bad = 0;
  for (std::size_t i = 0; i < a.size(); ++i) bad += std::abs(a[i] - b[i]) > 1e-12 * scale;
  EXPECT_EQ(bad, 0) << what << ": " << bad << " entries differ";
}

std::vector<double> all_of(std::vector<double> v, double x) {
  std::fill(v.begin(), v.end(), x);
  return v;
}

TEST(SolidLaw, ToyLawIsRegisteredFromItsTestFile) {
  EXPECT_TRUE(counting_law_registered());
  Material m;
  m.name = "COUNTING";
  m.elastic.n_values = 2;
  m.elastic.values = {1.0, 0.3};
  EXPECT_EQ(make_solid_law(m, Kinematics::ThreeD)->n_state(), 1);
  m.name = "STEEL";
  EXPECT_EQ(make_solid_law(m, Kinematics::ThreeD)->n_state(), 0);
}

// A beam fibre (Kinematics::Beam: 11, 12, 13 with the lateral stresses zero): sigma11 = E (eps11 -
// eps_th), tau = G gamma, and lambda* + 2 mu = E in the fast path's moduli; dS/dT by differences.
TEST(SolidLaw, BuiltInElasticLawOnABeamFibre) {
  Material m;
  m.name = "STEEL";
  m.elastic.n_values = 2;
  m.elastic.keys = {0.0, 200.0};
  m.elastic.values = {200000.0, 0.3, 180000.0, 0.25};
  m.expansion.n_values = 1;
  m.expansion.values = {1.2e-5};
  const auto law = make_solid_law(m, Kinematics::Beam);
  EXPECT_TRUE(law->linear_isotropic_elastic());
  const double T = 100.0, Ti = 20.0, E = 190000.0, nu = 0.275, G = E / (2.0 * (1.0 + nu));
  const std::array<double, 3> e{1e-3, 2e-4, -3e-4};
  std::array<double, 3> s{}, ds{};
  auto update = [&](double temp, std::span<double> out_s, std::span<double> out_ds) {
    MaterialPointInput in;
    in.strain = e;
    in.temperature = temp;
    in.initial_temperature = Ti;
    in.thermal = true;
    MaterialPointOutput out;
    out.stress = out_s;
    out.dstress_dT = out_ds;
    law->update(in, out);
    return out.moduli;
  };
  const IsotropicModuli mod = update(T, s, ds);
  const double eth = m.thermal_strain(T, Ti);
  EXPECT_NEAR(s[0], E * (e[0] - eth), 1e-9 * E * 1e-3);
  EXPECT_NEAR(s[1], G * e[1], 1e-9 * E * 1e-3);
  EXPECT_NEAR(s[2], G * e[2], 1e-9 * E * 1e-3);
  EXPECT_NEAR(mod.lambda + 2.0 * mod.mu, E, 1e-9 * E);
  const double h = 1e-3;
  std::array<double, 3> sp{}, sm{};
  update(T + h, sp, {});
  update(T - h, sm, {});
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(ds[c], (sp[c] - sm[c]) / (2.0 * h), 1e-6 * std::abs(ds[c]) + 1e-9);
  m.name = "COUNTING";
  EXPECT_FALSE(make_solid_law(m, Kinematics::Beam)->linear_isotropic_elastic());
}

// The toy law against the built-in one in every kernel: same residual and tangent (small strain
// and NLGEOM), same output; its history is one slot per point.
TEST(SolidLaw, ToyLawGivesTheElasticResponseInEveryContinuumKernel) {
  const auto types = every_continuum_type();
  EXPECT_GE(types.size(), 40u);
  for (ElementType t : types) {
    SCOPED_TRACE(std::string(element_info(t).name));
    for (bool nlgeom : {false, true}) {
      KernelProbe ref = probe(t, false, nlgeom), toy = probe(t, true, nlgeom);
      EXPECT_EQ(ref.kernel->n_state(), 0);
      const KernelResult a = ref.evaluate(), b = toy.evaluate();
      expect_close(b.r, a.r, "residual");
      expect_close(b.K, a.K, "tangent");
      EXPECT_EQ(a.unsymmetric, b.unsymmetric);
      const ElementRecovery ra = ref.recover(), rb = toy.recover();
      const OutputBlock* sa = ra.find(ElemVar::S);
      const OutputBlock* sb = rb.find(ElemVar::S);
      ASSERT_TRUE(sa && sb);
      expect_close(sb->values, sa->values, "stress output");
      EXPECT_NEAR(*rb.strain_energy, *ra.strain_energy, 1e-12 * std::abs(*ra.strain_energy));
      EXPECT_EQ(toy.kernel->n_state(), sa->n_points); // points x the law's one slot
    }
  }
}

// The counter counts commits; revert gives the committed value back; recover() writes nothing;
// the tangent (the general D B path) passes central differences; revert-then-evaluate is exact.
TEST(SolidLaw, ToyLawHistoryFollowsCommitAndRevertInEveryContinuumKernel) {
  for (ElementType t : every_continuum_type()) {
    SCOPED_TRACE(std::string(element_info(t).name));
    KernelProbe p = probe(t, true, true);
    ASSERT_GT(p.kernel->n_state(), 0);
    EXPECT_EQ(p.state0, all_of(p.state0, 0.0)); // initialize()
    for (int k = 1; k <= 3; ++k) {
      p.evaluate();
      EXPECT_EQ(p.state, all_of(p.state, k));
      p.evaluate(false); // a second evaluation in the same increment counts once
      p.commit();
    }
    EXPECT_EQ(p.state0, all_of(p.state0, 3.0));
    p.evaluate();
    p.revert();
    EXPECT_EQ(p.state, all_of(p.state, 3.0));
    p.state = all_of(p.state, -1.0);
    p.recover();
    EXPECT_EQ(p.state, all_of(p.state, -1.0));
    p.revert();
    expect_fd_tangent(p);
    expect_revert_is_exact(p);
  }
}

/// Two C3D8 bricks of the toy material pulled in two steps of fixed increments; `restart` is
/// the restart request or the restart read of the model data.
std::string counting_deck(const std::string& restart, const std::string& steps) {
  return fmt::format(R"(*HEADING
counting law
*NODE
1, 0., 0., 0.
2, 1., 0., 0.
3, 2., 0., 0.
4, 0., 1., 0.
5, 1., 1., 0.
6, 2., 1., 0.
7, 0., 0., 1.
8, 1., 0., 1.
9, 2., 0., 1.
10, 0., 1., 1.
11, 1., 1., 1.
12, 2., 1., 1.
*NSET, NSET=LEFT
1, 4, 7, 10
*NSET, NSET=RIGHT
3, 6, 9, 12
*ELEMENT, TYPE=C3D8, ELSET=SOLID
1, 1, 2, 5, 4, 7, 8, 11, 10
2, 2, 3, 6, 5, 8, 9, 12, 11
*MATERIAL, NAME=COUNTING
*ELASTIC
210000., 0.3
*SOLID SECTION, ELSET=SOLID, MATERIAL=COUNTING
*BOUNDARY
LEFT, 1, 3
{}
{})",
                     restart, steps);
}

constexpr const char* kStep1 = R"(*STEP, NAME=ONE
*STATIC, DIRECT
0.25, 1.
*BOUNDARY
RIGHT, 1, 1, 0.001
*EL PRINT
S
*END STEP
)";
constexpr const char* kStep2 = R"(*STEP, NAME=TWO
*STATIC, DIRECT
0.5, 1.
*BOUNDARY
RIGHT, 1, 1, 0.002
*EL PRINT
S
*END STEP
)";

// Restart saves the flat committed history: a restart deck continuing after step 1 (4
// increments) evaluates from a counter of 4 and ends at 6, as the uninterrupted run does (from
// scratch it would end at 2).
TEST(SolidLaw, RestartCarriesTheLawHistory) {
  g_most_commits_seen = 0;
  const JobResult old = run_deck(
      counting_deck("*RESTART, WRITE, FREQUENCY=1", std::string(kStep1) + kStep2), true, "old");
  ASSERT_EQ(old.exit_code, 0) << old.error;
  EXPECT_EQ(g_most_commits_seen.load(), 6); // recover() after the last commit sees 6

  g_most_commits_seen = 0;
  JobOptions o;
  o.deck = write_deck(std::string("*HEADING\ncontinued\n*RESTART, READ, STEP=1\n") + kStep2, "new");
  o.oldjob = (o.deck.parent_path() / "old.res").string();
  o.write_files = true;
  o.quiet = true;
  const JobResult resumed = run_job(o);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.error;
  EXPECT_EQ(g_most_commits_seen.load(), 6);
}

} // namespace
} // namespace gapfem::test
