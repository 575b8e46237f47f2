// The material-point seam of the solids (elements/material/solid_law.hpp) proven by a toy law
// that lives in this file alone: "linear elastic with a state counter". It is registered here
// (one register_solid_law call, no other file touched) for materials named COUNTING, and then
// runs through every continuum kernel the registry has (full, B-bar, reduced with hourglass
// control, incompatible modes, quadratic, plane stress/strain, axisymmetric and the coupled
// temperature-displacement twins):
//   - residual, tangent (and the coupled kernels' d r / d T columns) equal the built-in elastic
//     law's, small strain and NLGEOM, although the toy law hands its tangent over as a full Voigt
//     matrix (the general D B path) where the built-in law takes the isotropic fast path;
//   - its history is points x 1 slot in the kernel's flat state; the counter equals the number of
//     commits; revert restores it; recover() never writes it;
//   - the tangent passes the harness's central differences, revert-then-evaluate is exact.
// A restart (solver/analysis_restart.cpp saves the flat committed arrays) carries the counter
// over: RestartCarriesTheLawHistory.
#include "elements/material/isotropic_elastic.hpp"
#include "elements/material/solid_law.hpp"
#include "test_util.hpp"
#include "unit/elements/solid/continuum_fixture.hpp"

#include <algorithm>
#include <atomic>
#include <fmt/format.h>

namespace gapfem::test {
namespace {

/// Largest committed counter any COUNTING point has been evaluated from (the restart test).
std::atomic<int> g_most_commits_seen{0};

/// Linear elasticity (the built-in law's stress) with one history slot per point counting the
/// increments the point has been committed in; its tangent is given as a full Voigt matrix.
class CountingElasticLaw final : public SolidLaw {
 public:
  CountingElasticLaw(const Material& m, Kinematics k) : _elastic(m, k), _kin(k) {}

  int n_state() const override { return 1; }
  void initialize(std::span<double> state) const override { state[0] = 0.0; }
  bool temperature_dependent() const override { return _elastic.temperature_dependent(); }

  void update(const MaterialPointInput& in, MaterialPointOutput& out) const override {
    MaterialPointOutput elastic = out;
    elastic.tangent = {};
    elastic.state = {};
    _elastic.update(in, elastic);
    out.energy = elastic.energy;
    out.thickness_strain = elastic.thickness_strain;
    out.isotropic = false;
    if (!out.tangent.empty()) { // D = lambda 1 1^T + 2 mu I on the normals, mu on the shears
      const int n = voigt_size(_kin), nn = voigt_normals(_kin);
      const IsotropicModuli& m = elastic.moduli;
      std::fill(out.tangent.begin(), out.tangent.end(), 0.0);
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
          out.tangent[i * n + j] =
              i < nn && j < nn ? m.lambda + (i == j ? 2.0 * m.mu : 0.0) : (i == j ? m.mu : 0.0);
    }
    const int commits = static_cast<int>(in.state_start[0]);
    int seen = g_most_commits_seen.load();
    while (commits > seen && !g_most_commits_seen.compare_exchange_weak(seen, commits)) {
    }
    out.state[0] = in.state_start[0] + 1.0;
  }
  IsotropicModuli elastic_moduli(double T, IsotropicModuli* dT) const override {
    return _elastic.elastic_moduli(T, dT);
  }

 private:
  IsotropicElasticLaw _elastic;
  Kinematics _kin;
};

// The one registration: materials named COUNTING get the toy law.
const bool kRegistered = register_solid_law(
    "counting elastic (test)", [](const Material& m) { return m.name == "COUNTING"; },
    [](const Material& m, Kinematics k) { return std::make_unique<CountingElasticLaw>(m, k); });

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
  EXPECT_TRUE(kRegistered);
  Material m;
  m.name = "COUNTING";
  m.elastic.n_values = 2;
  m.elastic.values = {1.0, 0.3};
  EXPECT_EQ(make_solid_law(m, Kinematics::ThreeD)->n_state(), 1);
  m.name = "STEEL";
  EXPECT_EQ(make_solid_law(m, Kinematics::ThreeD)->n_state(), 0);
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
