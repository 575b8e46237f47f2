// Unit tests of the gap interaction models (issue 4): each normal law against its formula, the
// friction law's return mapping, and the kernel harness's central differences of the complete
// element tangent — stick, slip, every normal law, damping — including the column d r / d lambda_N
// of the exact normal constraint when friction depends on the normal multiplier.
#include "elements/gap/friction.hpp"
#include "elements/gap/mechanical_gap.hpp"
#include "elements/gap/normal_law.hpp"
#include "gap_test_util.hpp"

#include <cmath>
#include <gtest/gtest.h>

using namespace gapfem;
using namespace gapfem::test;

namespace {

GapSection gapuni(double d = 0.0) {
  GapSection s;
  s.d = d;
  s.direction = {0, -1, 0};
  s.direction_given = true;
  return s;
}

FrictionSpec coulomb(double mu, double elastic_slip = 1e-3) {
  FrictionSpec f;
  f.given = true;
  f.rows = {{mu, 0, 0, 0}};
  f.elastic_slip = elastic_slip;
  return f;
}

} // namespace

TEST(GapLaws, LinearExponentialTabularFormulas) {
  double F, dF;
  LinearLaw lin(1e4, 2.0); // F = A k g
  lin.force(1e-3, 0, F, dF);
  EXPECT_DOUBLE_EQ(F, 2.0 * 1e4 * 1e-3);
  lin.force(-1e-3, 0, F, dF);
  EXPECT_EQ(F, 0.0);
  // exponential: p(0) = p0, p(-c0) = 0, p(g) = p0/(e-1) x (e^x - 1), x = g/c0 + 1
  ExponentialLaw ex(0.01, 50.0, 0.0, 1.0);
  ex.force(0.0, 0, F, dF);
  EXPECT_NEAR(F, 50.0, 1e-12);
  ex.force(-0.01, 0, F, dF);
  EXPECT_NEAR(F, 0.0, 1e-12);
  for (double g : {-0.007, -0.002, 0.004}) {
    const double x = g / 0.01 + 1.0;
    ex.force(g, 0, F, dF);
    EXPECT_NEAR(F, 50.0 / (std::exp(1.0) - 1.0) * x * (std::exp(x) - 1.0), 1e-10) << g;
    double Fp, Fm, d;
    ex.force(g + 1e-7, 0, Fp, d);
    ex.force(g - 1e-7, 0, Fm, d);
    EXPECT_NEAR((Fp - Fm) / 2e-7, dF, 1e-5 * dF);
  }
  // with K_max the slope never exceeds K_max and the curve is continuous
  ExponentialLaw capped(0.01, 50.0, 3e4, 1.0);
  double Fa, Fb, da, db;
  capped.force(0.02, 0, Fa, da);
  capped.force(0.03, 0, Fb, db);
  EXPECT_NEAR(da, 3e4, 1e-9);
  EXPECT_NEAR(Fb - Fa, 3e4 * 0.01, 1e-8);
  // tabular: zero below the first point, linear between, last slope beyond
  TabularLaw tab({0.0, 10.0, 30.0}, {0.0, 0.001, 0.002}, 1.0);
  tab.force(-0.001, 0, F, dF);
  EXPECT_EQ(F, 0.0);
  tab.force(0.0005, 0, F, dF);
  EXPECT_NEAR(F, 5.0, 1e-12);
  tab.force(0.003, 0, F, dF);
  EXPECT_NEAR(F, 30.0 + 20.0 / 0.001 * 0.001, 1e-9);
  // penalty: automatic stiffness = 10 x the connected elements' stiffness
  PenaltyLaw pen(0.0);
  pen.force(1e-3, 500.0, F, dF);
  EXPECT_NEAR(dF, 5000.0, 1e-12);
  EXPECT_NEAR(F, 5.0, 1e-12);
}

TEST(GapLaws, FrictionReturnMapping) {
  FrictionLaw law(coulomb(0.3, 0.01), 1.0);
  const Eigen::Vector2d zero = Eigen::Vector2d::Zero();
  // stick: force = (mu N / gamma) * elastic slip
  auto stick = law.penalty(Eigen::Vector2d(0.004, 0.0), Eigen::Vector2d(0.004, 0.0), zero, 100.0,
                           1.0, 0, 0.01);
  EXPECT_FALSE(stick.slipping);
  EXPECT_NEAR(stick.force[0], 30.0 / 0.01 * 0.004, 1e-12);
  // slip: force = mu N along the trial direction, plastic slip = slip - force / k
  auto slip = law.penalty(Eigen::Vector2d(0.03, 0.04), Eigen::Vector2d(0.03, 0.04), zero, 100.0,
                          1.0, 0, 0.01);
  EXPECT_TRUE(slip.slipping);
  EXPECT_NEAR(slip.force.norm(), 30.0, 1e-12);
  EXPECT_NEAR(slip.force[0] / slip.force[1], 0.75, 1e-12);
  EXPECT_NEAR((Eigen::Vector2d(0.03, 0.04) - slip.plastic_slip).norm(), 0.01, 1e-12);
  EXPECT_NEAR(slip.dissipation, 30.0 * 0.04, 1e-12); // |plastic slip| = 0.05 - 0.01
  // finite-difference derivatives in slip
  const double h = 1e-7;
  for (int j = 0; j < 2; ++j) {
    Eigen::Vector2d s(0.03, 0.04), d = s;
    s[j] += h;
    d[j] += h;
    auto p = law.penalty(s, d, zero, 100.0, 1.0, 0, 0.01);
    s[j] -= 2 * h;
    d[j] -= 2 * h;
    auto m = law.penalty(s, d, zero, 100.0, 1.0, 0, 0.01);
    for (int i = 0; i < 2; ++i)
      EXPECT_NEAR((p.force[i] - m.force[i]) / (2 * h), slip.dforce_dslip(i, j), 1e-5);
  }
  auto pN = law.penalty(Eigen::Vector2d(0.03, 0.04), Eigen::Vector2d(0.03, 0.04), zero, 100.0 + h,
                        1.0, 0, 0.01);
  EXPECT_NEAR((pN.force[0] - slip.force[0]) / h, slip.dforce_dnormal[0], 1e-6);
}

TEST(GapLaws, FrictionCoefficientTable) {
  // mu against slip rate (2 columns) and against slip rate at two pressures (3 columns)
  FrictionSpec f;
  f.given = true;
  f.n_columns = 2;
  f.rows = {{0.4, 0.0, 0, 0}, {0.2, 1.0, 0, 0}};
  FrictionLaw law(f, 1.0);
  EXPECT_NEAR(law.mu(0.5, 0, 0), 0.3, 1e-15);
  EXPECT_NEAR(law.mu(5.0, 0, 0), 0.2, 1e-15);
  f.n_columns = 3;
  f.rows = {{0.4, 0.0, 0.0, 0}, {0.2, 1.0, 0.0, 0}, {0.3, 0.0, 10.0, 0}, {0.1, 1.0, 10.0, 0}};
  FrictionLaw law3(f, 1.0);
  EXPECT_NEAR(law3.mu(0.5, 5.0, 0), 0.25, 1e-15); // (0.3 + 0.2) / 2
}

TEST(GapInteraction, PenaltyFrictionTangentStickAndSlip) {
  for (bool slipping : {false, true}) {
    for (ElementType type : {ElementType::GAPUNI, ElementType::GAPCYL, ElementType::GAPSPHER}) {
      SCOPED_TRACE(std::string(element_info(type).name) + (slipping ? " slip" : " stick"));
      GapSection s = gapuni(0.0);
      if (type == ElementType::GAPCYL) {
        s.d = 0.5;
        s.direction = {1, 0, 0};
      } else if (type == ElementType::GAPSPHER) {
        s.d = 0.5;
        s.direction_given = false;
        s.direction = {0, 0, 0};
      }
      s.friction = coulomb(0.3, 1e-3);
      s.behavior.given = true;
      s.behavior.law = PressureOverclosure::Linear;
      s.behavior.slope = 2e4;
      Model m =
          two_node_gap_model(type, {0, 0, 0}, {0, type == ElementType::GAPUNI ? -1.0 : 0.0, 0}, s);
      KernelProbe el = gap_probe(m);
      // overclosed by 0.01 along the closure direction, tangential increment 0.0005 or 0.005
      const double t = slipping ? 0.005 : 0.0002;
      el.u = type == ElementType::GAPUNI ? std::vector<double>{t, -0.01, 0.3 * t, 0, 0, 0}
                                         : std::vector<double>{t, 0.51, 0.3 * t, 0, 0, 0};
      el.state[GapStateLayout::direction] = type == ElementType::GAPUNI ? 0.0 : 0.0;
      el.state[GapStateLayout::direction + 1] = type == ElementType::GAPUNI ? -1.0 : 1.0;
      el.state0 = el.state;
      el.evaluate();
      ASSERT_EQ(gap_record(el).status, slipping ? ContactStatus::Slip : ContactStatus::Stick);
      expect_fd_tangent(el, {.length = 0.001});
    }
  }
}

TEST(GapInteraction, FrictionWithExactNormalContactHasTheNormalColumn) {
  // a closed GAPUNI with elastic-slip friction moved sideways by ux (small: stick; large: slip)
  auto closed_gap = [](double ux, auto check, KernelOptions options = {}) {
    GapSection s = gapuni(0.0);
    s.friction = coulomb(0.3, 1e-3);
    Model m = two_node_gap_model(ElementType::GAPUNI, {0, 0, 0}, {0, -1, 0}, s);
    KernelProbe el = gap_probe(m, options);
    commit_status(el, ContactStatus::Stick);
    el.mult[0] = 100.0;
    el.u = {ux, 0.0, 0.0001, 0, 0, 0};
    check(el, el.evaluate());
  };
  for (bool slipping : {false, true}) {
    SCOPED_TRACE(slipping ? "slip" : "stick");
    closed_gap(slipping ? 0.01 : 0.0002, [&](KernelProbe& el, const KernelResult& ev) {
      // the exact normal row, and the elastic-slip stiffness as compliant rows: both slip
      // directions in stick, the one across the slip direction in slip
      ASSERT_EQ(ev.n_constraints, slipping ? 2 : 3);
      int exact = 0;
      for (int r = 0; r < ev.n_constraints; ++r) {
        if (ev.compliance[r] == 0.0) {
          ++exact;
          EXPECT_EQ(ev.slot[r], 0);
        } else {
          EXPECT_GT(ev.slot[r], 0);
        }
      }
      EXPECT_EQ(exact, 1);
      EXPECT_EQ(ev.has_columns, true);
      EXPECT_FALSE(ev.unsymmetric); // the friction's coupling to the normal force is a column
      expect_fd_tangent(el, {.length = 0.001});
    });
  }
  // without friction rows (GAPFEM_FRICTION_ROWS=0) the same stiffness is in the tangent: one row
  closed_gap(
      0.0002,
      [](KernelProbe& el, const KernelResult& ev) {
        EXPECT_EQ(ev.n_constraints, 1);
        expect_fd_tangent(el, {.length = 0.001});
      },
      KernelOptions{.penalty_rows = true, .friction_rows = false});
}

TEST(GapInteraction, FrictionOnRotatingGapsWithExactNormalContact) {
  // GAPCYL and GAPSPHER closed by a multiplier, friction by elastic slip (stick and slip) or
  // LAGRANGE (slip): residual, rows and the normal column against central differences
  for (ElementType type : {ElementType::GAPCYL, ElementType::GAPSPHER})
    for (int kind = 0; kind < 6; ++kind) {
      SCOPED_TRACE(std::string(element_info(type).name) + " case " + std::to_string(kind));
      GapSection s;
      s.d = kind < 3 ? 0.5 : -0.5; // inside, or outside (external cylinders / spheres)
      if (type == ElementType::GAPCYL) {
        s.direction = {1, 0, 0};
        s.direction_given = true;
      }
      s.friction = coulomb(0.3, 1e-3);
      s.friction.lagrange = kind % 3 == 2;
      if (kind % 3 == 2) s.friction.elastic_slip.reset();
      Model m = two_node_gap_model(type, {0, 0, 0}, {0, 0, 0}, s);
      KernelProbe el = gap_probe(m);
      commit_status(el, kind % 3 == 0 ? ContactStatus::Stick : ContactStatus::Slip);
      el.state[GapStateLayout::direction + 1] = el.state0[GapStateLayout::direction + 1] = 1.0;
      el.state[GapStateLayout::slip_dir] = el.state0[GapStateLayout::slip_dir] = 1.0;
      el.mult[0] = 100.0;
      // on the surface, moved sideways (rotating the contact direction) by 0.0004 or 0.02
      const double t = kind % 3 == 0 ? 0.0002 : 0.02;
      el.u = {0.3 * t, std::sqrt(0.25 - t * t), t, 0, 0, 0};
      el.evaluate();
      ASSERT_EQ(gap_record(el).status, kind % 3 == 0 ? ContactStatus::Stick : ContactStatus::Slip);
      expect_fd_tangent(el, {.length = 0.001});
    }
}

TEST(GapInteraction, LagrangeFrictionStickRowsAndSlipForce) {
  GapSection s = gapuni(0.0);
  s.friction = coulomb(0.3);
  s.friction.lagrange = true;
  Model m = two_node_gap_model(ElementType::GAPUNI, {0, 0, 0}, {0, -1, 0}, s);
  KernelProbe el = gap_probe(m);
  commit_status(el, ContactStatus::Stick);
  el.mult = {100.0, 20.0, 0.0}; // friction 20 < 30: stick
  el.u = {0.001, 0, 0, 0, 0, 0};
  KernelResult ev = el.evaluate();
  EXPECT_EQ(ev.n_constraints, 3) << "normal + two stick rows";
  EXPECT_EQ(ev.status_changes, 0);
  el.mult = {100.0, 40.0, 0.0}; // friction above mu N: slip
  ev = el.evaluate();
  EXPECT_EQ(ev.status_changes, 1);
  EXPECT_EQ(ev.n_constraints, 1);
  EXPECT_NEAR(gap_record(el).friction_force[0], 30.0, 1e-12);
  expect_fd_tangent(el, {.length = 0.001});
}

TEST(GapInteraction, LagrangeFrictionUsesTheSlipRateOfTheIncrement) {
  // mu = 0.4 at rest falling to 0.2 at slip rate 1; N = 100, a slipping gap slides 0.5 along t1
  // in dt = 1: rate 0.5, mu = 0.3, friction force 30 (not mu(0) N = 40); tangent by differences.
  GapSection s = gapuni(0.0);
  s.friction = coulomb(0.4);
  s.friction.n_columns = 2;
  s.friction.rows = {{0.4, 0.0, 0, 0}, {0.2, 1.0, 0, 0}};
  s.friction.lagrange = true;
  Model m = two_node_gap_model(ElementType::GAPUNI, {0, 0, 0}, {0, -1, 0}, s);
  KernelProbe el = gap_probe(m);
  commit_status(el, ContactStatus::Slip);
  el.state[GapStateLayout::slip_dir] = el.state0[GapStateLayout::slip_dir] = 1.0;
  el.mult = {100.0, 0.0, 0.0};
  el.ctx.dt = 1.0;
  el.u = {0.5, 0, 0.1, 0, 0, 0};
  el.evaluate();
  ASSERT_EQ(gap_record(el).status, ContactStatus::Slip);
  const double rate = std::hypot(0.5, 0.1);
  EXPECT_NEAR(std::hypot(gap_record(el).friction_force[0], gap_record(el).friction_force[1]),
              100.0 * (0.4 - 0.2 * rate), 1e-12);
  expect_fd_tangent(el, {.length = 1e-4});
}

TEST(GapInteraction, AugmentedLagrangeAndDampingTangents) {
  {
    GapSection s = gapuni(0.0);
    s.behavior.given = true;
    s.behavior.method = ContactMethod::AugmentedLagrange;
    s.behavior.penalty_stiffness = 1e5;
    Model m = two_node_gap_model(ElementType::GAPUNI, {0, 0, 0}, {0, -1, 0}, s);
    KernelProbe el = gap_probe(m);
    el.u = {0, -0.01, 0, 0, 0, 0}; // overclosure 0.01 > tolerance 1e-3 x (node distance 1)
    el.evaluate();
    EXPECT_NEAR(gap_record(el).normal_force, 1000.0, 1e-9);
    expect_fd_tangent(el, {.length = 1e-4});
    // augmentation moves the multiplier estimate to the current force
    auto in = el.input();
    EXPECT_TRUE(el.kernel->augment(in));
    EXPECT_NEAR(el.state[GapStateLayout::lambda_aug], 1000.0, 1e-9);
  }
  {
    GapSection s = gapuni(0.5);
    s.damping.given = true;
    s.damping.coefficient = 50.0;
    s.damping.clearance = 1.0;
    s.damping.fraction = 0.2;
    s.damping.tangent_fraction = 0.5;
    s.behavior.given = true;
    s.behavior.law = PressureOverclosure::Linear;
    s.behavior.slope = 1e3;
    Model m = two_node_gap_model(ElementType::GAPSPHER, {0, 0.2, 0}, {0, 0, 0}, GapSection{s});
    m.gap_sections[0].direction_given = false;
    KernelProbe el = gap_probe(m);
    el.u0 = {0, 0, 0, 0, 0, 0};
    el.u = {0.05, 0.1, 0.02, 0, 0, 0}; // node 1 moves away from the centre: h = d - rho falls
    el.ctx.dt = 0.1;
    expect_fd_tangent(el, {.length = 0.01});
    EXPECT_GT(gap_record(el).damping_force, 0.0) << "closing: the damper pushes back";
    el.u = {0.0, -0.1, 0.0, 0, 0, 0}; // towards the centre: opening
    expect_fd_tangent(el, {.length = 0.01});
    EXPECT_LT(gap_record(el).damping_force, 0.0) << "opening: the damper pulls";
  }
}

TEST(GapInteraction, EveryNormalLawTangentOnARotatingGap) {
  // GAPSPHER (rotating direction: geometric stiffness) with each force law, overclosed by ~0.003.
  struct Case {
    std::string name;
    std::function<void(GapSection&)> set;
  };
  const std::vector<Case> cases = {
      {"linear",
       [](GapSection& s) {
         s.behavior.law = PressureOverclosure::Linear;
         s.behavior.slope = 1e4;
       }},
      {"exponential",
       [](GapSection& s) {
         s.behavior.law = PressureOverclosure::Exponential;
         s.behavior.c0 = 0.01;
         s.behavior.p0 = 20.0;
       }},
      {"exponential with K_max",
       [](GapSection& s) {
         s.behavior.law = PressureOverclosure::Exponential;
         s.behavior.c0 = 0.01;
         s.behavior.p0 = 20.0;
         s.behavior.max_stiffness = 5e3;
       }},
      {"tabular",
       [](GapSection& s) {
         s.behavior.law = PressureOverclosure::Tabular;
         s.behavior.table_p = {0.0, 5.0, 25.0};
         s.behavior.table_g = {0.0, 0.001, 0.002};
       }},
      {"penalty",
       [](GapSection& s) {
         s.behavior.method = ContactMethod::Penalty;
         s.behavior.penalty_stiffness = 3e4;
       }},
      {"ccx",
       [](GapSection& s) {
         s.behavior.given = false;
         s.ccx_penalty = true;
         s.ccx_stiffness = 1e5;
         s.ccx_tension = 1e-3;
       }},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    GapSection s;
    s.d = 0.2;
    s.behavior.given = true;
    c.set(s);
    Model m = two_node_gap_model(ElementType::GAPSPHER, {0, 0.1, 0}, {0, 0, 0}, s);
    KernelProbe el = gap_probe(m);
    el.u = {0.02, 0.103, 0.01, 0, 0, 0}; // rho = 0.2043: overclosure 0.0043
    expect_fd_tangent(el, {.length = 1e-4});
    EXPECT_GT(gap_record(el).normal_force, 0.0);
  }
}
