// Beam sections on the material-point seam (elements/structural/beam_fibres.hpp), proven by the
// toy law of the seam tests (counting_law.hpp: the built-in elastic stress handed over with a full
// tangent matrix and one history slot counting commits; it is not the built-in law, so the beams
// integrate it at their section fibres while the built-in law keeps the pre-integrated section):
//   - the fibres of every library shape reproduce the section's A, Q1, Q2, I11, I22, I12 and hold
//     the default output points (L's, on the outer faces, excepted);
//   - for every beam type and every library shape, small strain and NLGEOM, with a temperature
//     and a gradient over the section: residual, tangent, SF, S and E equal the pre-integrated
//     section's; the history is the kernel's slots plus points x fibres x 1;
//   - the counter counts commits, revert restores it, recover() writes nothing; the tangent passes
//     central differences and revert-then-evaluate is exact.
#include "elements/structural/beam_fibres.hpp"
#include "elements/structural/beam_section.hpp"
#include "structural_test_support.hpp"
#include "unit/elements/counting_law.hpp"
#include "unit/elements/kernel_probe.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace gapfem::structural_test {
namespace {

using Shape = BeamSection::Shape;
constexpr double kE = 210e3, kNu = 0.3, kAlpha = 1.2e-5;

struct ShapeCase {
  Shape shape;
  const char* name;
  std::vector<double> dims; ///< asymmetric where the shape allows
};

const std::vector<ShapeCase>& shapes() {
  static const std::vector<ShapeCase> all = {
      {Shape::Rect, "RECT", {0.3, 0.5}},
      {Shape::Circ, "CIRC", {0.2}},
      {Shape::Pipe, "PIPE", {0.25, 0.04}},
      {Shape::Trapezoid, "TRAPEZOID", {0.4, 0.3, 0.15, 0.1}},
      {Shape::Box, "BOX", {0.4, 0.3, 0.02, 0.03, 0.025, 0.035}},
      {Shape::I, "I", {0.12, 0.4, 0.2, 0.15, 0.03, 0.02, 0.015}},
      {Shape::Hex, "HEX", {0.2, 0.03}},
      {Shape::L, "L", {0.3, 0.2, 0.03, 0.02}},
  };
  return all;
}

const ElementType kBeams[] = {ElementType::B21,   ElementType::B22,  ElementType::B31,
                              ElementType::B32,   ElementType::B32R, ElementType::PIPE31,
                              ElementType::PIPE32};

bool planar(ElementType t) {
  return element_info(t).space == SpaceRequirement::Planar;
}
bool pipe(ElementType t) {
  return t == ElementType::PIPE31 || t == ElementType::PIPE32;
}

BeamSection section_of(const ShapeCase& c) {
  BeamSection s;
  s.shape = c.shape;
  s.dims = c.dims;
  return s;
}

TEST(BeamSectionLaw, FibresReproduceTheSectionPropertiesOfEveryShape) {
  for (const ShapeCase& c : shapes()) {
    SCOPED_TRACE(c.name);
    const BeamSection sec = section_of(c);
    const BeamSectionProperties p = beam_section_properties(sec);
    const beam::BeamFibres f = beam::beam_section_fibres(sec, p);
    double A = 0, Q1 = 0, Q2 = 0, I11 = 0, I22 = 0, I12 = 0, size = 0;
    for (const beam::BeamFibre& x : f.fibres) {
      A += x.w, Q1 += x.w * x.x1, Q2 += x.w * x.x2;
      I11 += x.w * x.x2 * x.x2, I22 += x.w * x.x1 * x.x1, I12 += x.w * x.x1 * x.x2;
      size = std::max(size, std::hypot(x.x1, x.x2));
    }
    const double tol = 1e-13;
    EXPECT_NEAR(A, p.A, tol * p.A);
    EXPECT_NEAR(Q1, p.Q1, tol * p.A * size);
    EXPECT_NEAR(Q2, p.Q2, tol * p.A * size);
    EXPECT_NEAR(I11, p.I11, tol * p.A * size * size);
    EXPECT_NEAR(I22, p.I22, tol * p.A * size * size);
    EXPECT_NEAR(I12, p.I12, tol * p.A * size * size);
    // the torsion scale: an elastic fibre section carries G J twist
    EXPECT_NEAR(f.torsion * f.torsion * (I11 + I22), p.J, 1e-12 * p.J);
    if (c.shape == Shape::L) continue; // its output points are on the outer faces
    for (int k = 0; k < p.n_points; ++k) {
      const auto [x1, x2] = p.points[k];
      const beam::BeamFibre& n = f.fibres[f.nearest(x1, x2)];
      EXPECT_LT(std::hypot(n.x1 - x1, n.x2 - x2), 1e-12 * size) << "output point " << k;
    }
  }
}

/// One element of type t and section c, of the built-in elastic material or the toy law, with a
/// temperature field and gradients, and trial displacements away from the reference state.
struct Beam {
  TestModel tm;
  KernelProbe p;

  Beam(ElementType t, const ShapeCase& c, bool counting, bool nlgeom)
      : p(make(tm, t, c, counting)) {
    p.ctx.nlgeom = nlgeom;
    const int nn = static_cast<int>(p.X.size()), dpn = p.n() / nn;
    for (int i = 0; i < p.n(); ++i) {
      const bool rot = i % dpn >= (dpn == 3 ? 2 : 3);
      p.u[i] = (rot ? (nlgeom ? 0.3 : 0.01) : (nlgeom ? 0.05 : 0.002)) * std::sin(1.3 + 2.1 * i);
    }
    for (int a = 0; a < nn; ++a) {
      p.T.push_back(150.0 + 10.0 * a);
      p.Ti.push_back(20.0);
      p.Tgrad.push_back(300.0 + 50.0 * a);  // dT/dx2
      p.Tgrad.push_back(-200.0 + 30.0 * a); // dT/dx1
    }
  }
  static KernelProbe make(TestModel& tm, ElementType t, const ShapeCase& c, bool counting) {
    std::vector<NodeId> ids;
    const Vec3 a{0.1, 0.2, 0.0}, b = planar(t) ? Vec3{1.6, 0.7, 0.0} : Vec3{1.5, 0.6, 0.4};
    ids.push_back(tm.add_node(a));
    if (element_info(t).n_nodes == 3) // slightly curved
      ids.push_back(tm.add_node(
          {0.5 * (a[0] + b[0]) + 0.05, 0.5 * (a[1] + b[1]) - 0.04, 0.5 * (a[2] + b[2])}));
    ids.push_back(tm.add_node(b));
    const int m = tm.add_material(kE, kNu, kAlpha);
    if (counting) tm.model.materials[m].name = "COUNTING";
    const std::optional<Vec3> n1 =
        planar(t) ? std::optional<Vec3>{} : std::optional<Vec3>{Vec3{0.3, 1.0, 0.2}};
    const ElemId e = tm.add_element(t, ids, tm.add_beam_section(m, c.shape, c.dims, n1));
    return tm.probe(e);
  }
};

/// |a - b| <= tol of the largest entry of b, entry by entry.
void expect_close(const std::vector<double>& a, const std::vector<double>& b,
                  const std::string& what, double tol = 1e-10) {
  ASSERT_EQ(a.size(), b.size()) << what;
  double scale = 0.0;
  for (double v : b) scale = std::max(scale, std::abs(v));
  int bad = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    bad += std::abs(a[i] - b[i]) > tol * scale;
    worst = std::max(worst, std::abs(a[i] - b[i]) / scale);
  }
  EXPECT_EQ(bad, 0) << what << ": " << bad << " entries differ, worst " << worst;
}

void expect_same_output(const ElementRecovery& a, const ElementRecovery& b) {
  for (ElemVar v : {ElemVar::SF, ElemVar::S, ElemVar::E}) {
    const OutputBlock* x = a.find(v);
    const OutputBlock* y = b.find(v);
    ASSERT_TRUE(x && y) << static_cast<int>(v);
    EXPECT_EQ(x->section_points, y->section_points);
    expect_close(y->values, x->values, "output " + std::to_string(static_cast<int>(v)));
  }
}

/// The element's fibre history (after the pre-integrated kernel's slots).
std::vector<double> fibres_of(const std::vector<double>& state, std::size_t base) {
  return {state.begin() + static_cast<std::ptrdiff_t>(base), state.end()};
}

template <class Fn>
void for_every_beam_and_shape(Fn&& fn) {
  EXPECT_TRUE(test::counting_law_registered());
  for (ElementType t : kBeams)
    for (const ShapeCase& c : shapes()) {
      if (pipe(t) && c.shape != Shape::Pipe) continue; // PIPE31/PIPE32 need SECTION=PIPE
      SCOPED_TRACE(std::string(element_info(t).name) + " " + c.name);
      fn(t, c);
    }
}

TEST(BeamSectionLaw, ToyLawAtTheFibresGivesThePreIntegratedResponse) {
  for_every_beam_and_shape([](ElementType t, const ShapeCase& c) {
    const BeamSection sec = section_of(c);
    const auto nf = static_cast<int>(
        beam::beam_section_fibres(sec, beam_section_properties(sec, planar(t))).fibres.size());
    const int along = element_info(t).n_nodes == 2 ? 1 : 2;
    for (bool nlgeom : {false, true}) {
      SCOPED_TRACE(nlgeom ? "NLGEOM" : "small strain");
      Beam ref(t, c, false, nlgeom), toy(t, c, true, nlgeom);
      EXPECT_EQ(ref.p.kernel->n_state(), 4 * element_info(t).n_nodes + 6);
      EXPECT_EQ(toy.p.kernel->n_state(), ref.p.kernel->n_state() + along * nf);
      const KernelResult a = ref.p.evaluate(), b = toy.p.evaluate();
      expect_close(b.r, a.r, "residual");
      expect_close(b.K, a.K, "tangent");
      EXPECT_FALSE(b.unsymmetric);
      expect_same_output(ref.p.recover(), toy.p.recover());
    }
  });
}

TEST(BeamSectionLaw, ToyLawHistoryFollowsCommitAndRevertAtTheFibres) {
  for_every_beam_and_shape([](ElementType t, const ShapeCase& c) {
    Beam toy(t, c, true, true);
    KernelProbe& p = toy.p;
    const auto base = static_cast<std::size_t>(4 * element_info(t).n_nodes + 6);
    ASSERT_GT(p.state.size(), base);
    auto all = [](std::vector<double> v, double x) {
      std::fill(v.begin(), v.end(), x);
      return v;
    };
    const std::vector<double> zero = all(fibres_of(p.state0, base), 0.0);
    EXPECT_EQ(fibres_of(p.state0, base), zero); // initialize()
    const auto u = p.u;
    for (int k = 1; k <= 3; ++k) {
      p.evaluate();
      EXPECT_EQ(fibres_of(p.state, base), all(zero, k));
      p.evaluate(false); // a second evaluation in the same increment counts once
      EXPECT_EQ(fibres_of(p.state, base), all(zero, k));
      p.commit();
    }
    EXPECT_EQ(fibres_of(p.state0, base), all(zero, 3.0));
    p.evaluate();
    p.revert();
    EXPECT_EQ(fibres_of(p.state, base), all(zero, 3.0));
    const auto before = p.state;
    std::fill(p.state.begin() + static_cast<std::ptrdiff_t>(base), p.state.end(), -1.0);
    const auto poisoned = p.state;
    p.recover();
    EXPECT_EQ(p.state, poisoned); // recover() writes no history
    p.state = before;
    p.revert();
    p.u = u;
    expect_fd_tangent(p);
    expect_revert_is_exact(p);
  });
}

} // namespace
} // namespace gapfem::structural_test
