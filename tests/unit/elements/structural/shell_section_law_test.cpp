// Shell section points on the material-point seam (shell_section_points.hpp): a law other than
// the built-in isotropic elasticity is called at every section point of every integration point.
// The toy law of the seam tests (unit/elements/counting_law.hpp: the built-in elastic stress, a
// full-matrix tangent, one history slot counting commits) takes that path; the built-in law the
// closed-form section. For S3, S3R, S4, S4R, S8R and S8, small strain and NLGEOM, with an offset,
// a temperature, a through-thickness gradient and thermal expansion:
//   - residual and tangent of the two paths agree (Simpson's rule is exact for the linear
//     through-thickness strain, so they differ by rounding only);
//   - S, E and SF at the section points and the strain energy agree (S4R, S3, S3R report at the
//     centre the mean of their integration points: equal on a flat parallelogram in small strain,
//     where the fields are linear);
//   - the history is 4 quaternion slots per node + integration points x section points x 1; the
//     counter counts commits, revert restores it, recover() writes nothing; the tangent passes
//     central differences and revert-then-evaluate is exact.
#include "structural_test_support.hpp"
#include "unit/elements/counting_law.hpp"

#include <algorithm>
#include <random>

namespace gapfem::structural_test {
namespace {

constexpr double kE = 210e3, kNu = 0.3, kT = 0.05;
const ElementType kTypes[] = {ElementType::S3,  ElementType::S3R, ElementType::S4,
                              ElementType::S4R, ElementType::S8R, ElementType::S8};
/// Integration points of each type (shell.cpp's rule()).
int n_integration_points(ElementType t) {
  const int nn = element_info(t).n_nodes;
  return nn == 3 ? 3 : (t == ElementType::S8 ? 9 : 4);
}

/// Nodes of an element: curved and distorted, or a flat parallelogram.
std::vector<Vec3> element_nodes(int nn, bool flat) {
  std::vector<Vec3> X;
  if (nn == 3)
    return flat ? std::vector<Vec3>{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.3, 0.8, 0.0}}
                : std::vector<Vec3>{{0.0, 0.0, 0.0}, {1.1, 0.1, 0.05}, {0.2, 0.9, -0.04}};
  if (flat)
    X = {{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {1.3, 0.8, 0.0}, {0.3, 0.8, 0.0}};
  else
    X = {{0.0, 0.0, 0.0}, {1.0, 0.1, 0.05}, {1.2, 1.1, 0.1}, {-0.1, 0.9, 0.02}};
  if (nn == 8)
    for (int a = 0; a < 4; ++a) {
      const Vec3 &p = X[a], &q = X[(a + 1) % 4];
      const double bump = flat ? 0.0 : 0.02;
      X.push_back({0.5 * (p[0] + q[0]) + bump, 0.5 * (p[1] + q[1]) - 0.5 * bump,
                   0.5 * (p[2] + q[2]) + 1.5 * bump});
    }
  return X;
}

/// One shell of the built-in elastic law or the toy law, displaced at random, hot, with a
/// through-thickness gradient.
struct OneShell {
  TestModel tm;
  KernelProbe p;

  OneShell(ElementType type, bool counting, bool nlgeom, bool flat = false)
      : p(probe_of(tm, type, counting, flat)) {
    p.ctx.nlgeom = nlgeom;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> d(-1.0, 1.0);
    const double size = nlgeom ? 0.05 : 0.01;
    for (double& v : p.u) v = size * d(rng);
    const std::size_t nn = p.X.size();
    p.T.assign(nn, 150.0);
    p.T0 = p.T;
    p.Ti.assign(nn, 20.0);
    p.Tgrad.assign(2 * nn, 0.0);
    for (std::size_t a = 0; a < nn; ++a) p.Tgrad[2 * a] = 400.0 + 30.0 * a;
  }
  static KernelProbe probe_of(TestModel& tm, ElementType type, bool counting, bool flat) {
    std::vector<NodeId> ids;
    for (const Vec3& x : element_nodes(element_info(type).n_nodes, flat))
      ids.push_back(tm.add_node(x));
    const int m = tm.add_material(kE, kNu, 1.2e-5);
    if (counting) tm.model.materials[m].name = "COUNTING";
    return tm.probe(tm.add_element(type, ids, tm.add_shell_section(m, kT, flat ? 0.0 : 0.3)));
  }
};

/// |a - b| <= tol of the largest entry of b, entry by entry.
void expect_close(const std::vector<double>& a, const std::vector<double>& b,
                  const std::string& what, double tol = 1e-10) {
  ASSERT_EQ(a.size(), b.size()) << what;
  double scale = 0.0;
  for (double v : b) scale = std::max(scale, std::abs(v));
  int bad = 0;
  for (std::size_t i = 0; i < a.size(); ++i) bad += std::abs(a[i] - b[i]) > tol * scale;
  EXPECT_EQ(bad, 0) << what << ": " << bad << " of " << a.size() << " entries differ";
}

void expect_same_output(KernelProbe& ref, KernelProbe& toy) {
  const ElementRecovery ra = ref.recover(), rb = toy.recover();
  for (ElemVar v : {ElemVar::S, ElemVar::E, ElemVar::SF}) {
    const OutputBlock* a = ra.find(v);
    const OutputBlock* b = rb.find(v);
    ASSERT_TRUE(a && b);
    EXPECT_EQ(a->n_points, b->n_points);
    EXPECT_EQ(a->section_points, b->section_points);
    expect_close(b->values, a->values, "output");
  }
  EXPECT_NEAR(*rb.strain_energy, *ra.strain_energy, 1e-10 * std::abs(*ra.strain_energy));
}

TEST(ShellSectionLaw, ToyLawGivesTheClosedFormSectionResponse) {
  ASSERT_TRUE(test::counting_law_registered());
  for (ElementType t : kTypes)
    for (bool nl : {false, true}) {
      SCOPED_TRACE(std::string(element_info(t).name) + (nl ? " NLGEOM" : " small strain"));
      OneShell ref(t, false, nl), toy(t, true, nl);
      const KernelResult a = ref.p.evaluate(), b = toy.p.evaluate();
      expect_close(b.r, a.r, "residual");
      expect_close(b.K, a.K, "tangent");
      EXPECT_EQ(a.unsymmetric, b.unsymmetric);
      const bool same_points =
          t == ElementType::S4 || t == ElementType::S8R || t == ElementType::S8;
      if (same_points) expect_same_output(ref.p, toy.p);
      if (!nl) { // the centre's mean of the integration points on a flat parallelogram
        OneShell ref_flat(t, false, false, true), toy_flat(t, true, false, true);
        expect_same_output(ref_flat.p, toy_flat.p);
      }
      const int nn = element_info(t).n_nodes;
      EXPECT_EQ(ref.p.kernel->n_state(), 4 * nn);
      EXPECT_EQ(toy.p.kernel->n_state(), 4 * nn + n_integration_points(t) * 5);
    }
}

/// A coupled temperature-displacement shell (S3RT, S4T, S4RT) of the built-in law or the toy law,
/// 5 temperatures through the thickness at each node.
KernelProbe coupled_probe(Model& model, ElementType t, bool counting) {
  const std::vector<Vec3> X = element_nodes(element_info(t).n_nodes, false);
  test::add_lone_element(model, t, X);
  model.source_files.push_back("test.inp");
  Material m;
  m.name = counting ? "COUNTING" : "M";
  m.elastic.n_values = 2;
  m.elastic.values = {2.0e5, 0.3};
  m.expansion.n_values = 1;
  m.expansion.values = {1.2e-5};
  m.conductivity.n_values = 1;
  m.conductivity.values = {40.0};
  m.density.n_values = 1;
  m.density.values = {7.8e-3};
  m.specific_heat.n_values = 1;
  m.specific_heat.values = {460.0};
  model.materials.push_back(m);
  ShellSection sec;
  sec.elset = "SHELL";
  sec.material = 0;
  sec.thickness = 0.05;
  sec.n_points = 5;
  model.shell_sections.push_back(sec);
  model.element_property.push_back({PropertyRef::Kind::Shell, 0});
  model.initial_temperature.assign(X.size(), 20.0);
  KernelProbe p = KernelProbe::of(model);
  p.ctx.procedure = Procedure::CoupledTempDisp;
  p.ctx.model_size = 1.5;
  p.ctx.transient = true;
  p.ctx.dt = 0.5;
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> d(-1e-3, 1e-3), r(-0.05, 0.05), T(20.0, 180.0);
  for (int i = 0; i < p.n(); ++i) {
    const int c = i % 11;
    p.u[i] = c < 3 ? d(gen) : c < 6 ? r(gen) : T(gen);
    p.u0[i] = c < 6 ? 0.0 : T(gen);
  }
  return p;
}

// The coupled shells wrap the stress shell: on the section-point path their residual and tangent
// (K_uT by differences of the mechanical residual in the temperatures) are the closed form's.
TEST(ShellSectionLaw, CoupledShellsTakeTheSectionPointsToo) {
  for (ElementType t : {ElementType::S3RT, ElementType::S4T, ElementType::S4RT})
    for (bool nl : {false, true}) {
      SCOPED_TRACE(std::string(element_info(t).name) + (nl ? " NLGEOM" : " small strain"));
      Model ma, mb;
      KernelProbe ref = coupled_probe(ma, t, false), toy = coupled_probe(mb, t, true);
      ref.ctx.nlgeom = toy.ctx.nlgeom = nl;
      EXPECT_GT(toy.kernel->n_state(), ref.kernel->n_state());
      const KernelResult a = ref.evaluate(), b = toy.evaluate();
      expect_close(b.r, a.r, "residual");
      expect_close(b.K, a.K, "tangent", 1e-7); // K_uT: central differences of both
      expect_fd_tangent(toy);
    }
}

/// The law's slots of a shell's history (after the quaternions).
std::vector<double> law_slots(const std::vector<double>& state, int nn) {
  return {state.begin() + 4 * nn, state.end()};
}

TEST(ShellSectionLaw, HistoryFollowsCommitAndRevertAndTheTangentIsExact) {
  for (ElementType t : kTypes) {
    SCOPED_TRACE(std::string(element_info(t).name));
    OneShell s(t, true, true);
    KernelProbe& p = s.p;
    const int nn = element_info(t).n_nodes;
    auto all = [&](const std::vector<double>& st, double v) {
      const auto slots = law_slots(st, nn);
      return std::all_of(slots.begin(), slots.end(), [v](double x) { return x == v; });
    };
    EXPECT_TRUE(all(p.state0, 0.0)); // initialize()
    for (int k = 1; k <= 3; ++k) {
      p.evaluate();
      EXPECT_TRUE(all(p.state, k));
      p.evaluate(false); // a second evaluation in the same increment counts once
      p.commit();
    }
    EXPECT_TRUE(all(p.state0, 3.0));
    p.evaluate();
    p.revert();
    EXPECT_TRUE(all(p.state, 3.0));
    std::fill(p.state.begin() + 4 * nn, p.state.end(), -1.0);
    p.recover();
    EXPECT_TRUE(all(p.state, -1.0));
    p.revert();
    expect_fd_tangent(p);
    expect_revert_is_exact(p);
    OneShell lin(t, true, false);
    expect_fd_tangent(lin.p);
  }
}

} // namespace
} // namespace gapfem::structural_test
