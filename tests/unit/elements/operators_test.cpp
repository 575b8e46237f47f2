// The operators of the kernel contract (issue 44, item 3): each kernel's mass sums to rho x
// volume per direction (beams and shells: element_mass_test.cpp), the heat capacity block is the
// derivative of the capacity flux by the temperature rate, massless kernels say so, and the
// assembler's k K + c C + m M equals the sum of its separate assemblies, with M a + C v in the
// residual when the context defines rates.
#include "fem/assembler.hpp"
#include "io/inp/reader.hpp"
#include "model/model.hpp"
#include "solver/time_integrator.hpp"
#include "unit/dense_inserter.hpp"
#include "unit/elements/kernel_probe.hpp"

#include <gtest/gtest.h>
#include <numbers>
#include <string>

namespace gapfem {
namespace {

using test::KernelProbe;

constexpr double kRho = 7.8e-9, kCapacity = 4.6e8; // the decks' *DENSITY and *SPECIFIC HEAT

std::shared_ptr<const Model> model_of(const std::string& text) {
  return std::make_shared<const Model>(read_deck_string(text, "operators.inp"));
}

std::string material(bool heat = false) {
  std::string s = "*MATERIAL, NAME=M\n*ELASTIC\n2e5, 0.3\n*DENSITY\n7.8e-9\n";
  if (heat) s += "*CONDUCTIVITY\n45.\n*SPECIFIC HEAT\n4.6e8\n*EXPANSION\n1e-5\n";
  return s;
}

/// The kernel's blocks at the probe's state: mass and damping (each n x n) when it has them.
struct Operators {
  std::vector<double> mass, damping, residual, tangent;
};

Operators operators_of(KernelProbe& p, bool want_tangent = false) {
  const auto n = static_cast<std::size_t>(p.n());
  Operators o;
  o.residual.assign(n, 0.0);
  o.tangent.assign(want_tangent ? n * n : 0, 0.0);
  o.mass.assign(p.kernel->has_mass() ? n * n : 0, 0.0);
  o.damping.assign(p.kernel->has_damping() ? n * n : 0, 0.0);
  ElementOutput out;
  out.residual = o.residual;
  out.tangent = o.tangent;
  out.want_tangent = want_tangent;
  out.mass = o.mass;
  out.want_mass = p.kernel->has_mass();
  out.damping = o.damping;
  out.want_damping = p.kernel->has_damping();
  const ElementInput in = p.input();
  p.kernel->evaluate(in, out);
  return o;
}

/// Sum of M over the rows and columns of DOF type d; and the largest |M| entry joining two
/// different DOF types (must be 0: translations do not couple directions, rotations are massless).
double sum_of(const KernelProbe& p, const std::vector<double>& M, DofType d, double* cross) {
  std::vector<DofType> dof;
  for (int a = 0; a < p.kernel->n_nodes(); ++a)
    for (DofType t : p.kernel->node_dofs(a)) dof.push_back(t);
  const std::size_t n = dof.size();
  double s = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      if (dof[i] == d && dof[j] == d) s += M[i * n + j];
      if (dof[i] != dof[j] && cross) *cross = std::max(*cross, std::abs(M[i * n + j]));
    }
  return s;
}

void expect_mass(KernelProbe& p, double expected, int ndir, bool rotations) {
  ASSERT_TRUE(p.kernel->has_mass());
  const Operators o = operators_of(p);
  const DofType dirs[3] = {DofType::U1, DofType::U2, DofType::U3};
  double cross = 0.0;
  for (int d = 0; d < ndir; ++d)
    EXPECT_NEAR(sum_of(p, o.mass, dirs[d], &cross), expected, 1e-12 * expected)
        << "direction " << d + 1;
  EXPECT_EQ(cross, 0.0);
  if (rotations) {
    const DofType rot[3] = {DofType::UR1, DofType::UR2, DofType::UR3};
    for (DofType r : rot) EXPECT_EQ(sum_of(p, o.mass, r, nullptr), 0.0);
  }
  // symmetric and positive on the translations' diagonal
  const auto n = static_cast<std::size_t>(p.n());
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) EXPECT_EQ(o.mass[i * n + j], o.mass[j * n + i]);
}

std::string line_deck(const std::string& type, int nodes, const std::string& section) {
  std::string s = "*NODE\n1, 0., 0., 0.\n";
  s += nodes == 2 ? "2, 3., 4., 0.\n" : "2, 1.5, 2., 0.\n3, 3., 4., 0.\n";
  s += "*ELEMENT, TYPE=" + type + ", ELSET=E\n1, 1, 2" + (nodes == 3 ? ", 3" : "") + "\n";
  return s + section + material(type.back() == 'T');
}

TEST(KernelMass, TrussIsRhoALPerDirection) {
  auto p = KernelProbe::of(
      model_of(line_deck("T3D2", 2, "*SOLID SECTION, ELSET=E, MATERIAL=M\n0.25\n")));
  expect_mass(p, kRho * 0.25 * 5.0, 3, false);
  EXPECT_FALSE(p.kernel->has_damping());
}

TEST(KernelMass, CoupledTrussMassAndCapacity) {
  auto p = KernelProbe::of(
      model_of(line_deck("T3D2T", 2, "*SOLID SECTION, ELSET=E, MATERIAL=M\n0.25\n")));
  p.u[3] = p.u[7] = 20.0; // temperatures
  p.u0 = p.u;
  expect_mass(p, kRho * 0.25 * 5.0, 3, false);
  ASSERT_TRUE(p.kernel->has_damping());
  EXPECT_TRUE(p.kernel->damping_in_residual());
  const Operators o = operators_of(p);
  double cross = 0.0;
  EXPECT_NEAR(sum_of(p, o.damping, DofType::NT, &cross), kRho * kCapacity * 0.25 * 5.0, 1e-9);
  EXPECT_EQ(cross, 0.0);
}

// The beams' and shells' mass (with their rotary inertia since issue 46): element_mass_test.cpp.

TEST(KernelMass, MasslessKernelsSaySo) {
  const std::string spring = "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=SPRINGA, "
                             "ELSET=E\n1, 1, 2\n*SPRING, ELSET=E\n\n10.\n";
  auto s = KernelProbe::of(model_of(spring));
  EXPECT_FALSE(s.kernel->has_mass());
  EXPECT_FALSE(s.kernel->has_damping());
  const std::string gap = "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=GAPUNI, "
                          "ELSET=G\n1, 1, 2\n*GAP, ELSET=G\n0.1, 1., 0., 0.\n";
  auto g = KernelProbe::of(model_of(gap));
  EXPECT_FALSE(g.kernel->has_mass());
  EXPECT_FALSE(g.kernel->has_damping());
}

// The heat kernels: no mass; the capacity is a damping operator that the kernel integrates itself
// (E(T) is nonlinear), so with the integrator's v_du the transient tangent is the steady one plus
// v_du D, D = d(capacity flux) / d(temperature rate), and D sums to rho c V.
std::string heat_deck(const std::string& type) {
  std::string s = "*NODE\n1, 0., 0., 0.\n2, 2., 0., 0.\n3, 2., 3., 0.\n4, 0., 3., 0.\n"
                  "5, 0., 0., 1.\n6, 2., 0., 1.\n7, 2., 3., 1.\n8, 0., 3., 1.\n";
  s += "*ELEMENT, TYPE=" + type + ", ELSET=E\n1, 1, 2, 3, 4, 5, 6, 7, 8\n";
  s += "*SOLID SECTION, ELSET=E, MATERIAL=M\n";
  // a specific heat that depends on temperature: E(T) is nonlinear
  s += "*MATERIAL, NAME=M\n*CONDUCTIVITY\n45.\n*DENSITY\n7.8e-9\n*SPECIFIC HEAT\n4.0e8, 0.\n"
       "6.0e8, 200.\n";
  return s;
}

TEST(KernelDamping, HeatCapacityBlockIsTheDerivativeByTheRate) {
  auto p = KernelProbe::of(model_of(heat_deck("DC3D8")));
  EXPECT_FALSE(p.kernel->has_mass());
  ASSERT_TRUE(p.kernel->has_damping());
  EXPECT_TRUE(p.kernel->damping_in_residual());
  const auto n = static_cast<std::size_t>(p.n());
  for (std::size_t i = 0; i < n; ++i) {
    p.u0[i] = 20.0 + 3.0 * static_cast<double>(i);
    p.u[i] = p.u0[i] + 10.0 + static_cast<double>(i * i);
  }
  const Operators steady = operators_of(p, true);
  BackwardEuler be;
  be.begin_increment(0.25);
  p.ctx.rates = be.coefficients();
  const Operators transient = operators_of(p, true);
  double sum = 0.0, scale = 0.0;
  for (double d : transient.damping) scale = std::max(scale, std::abs(d));
  for (std::size_t k = 0; k < n * n; ++k) {
    const double dK = transient.tangent[k] - steady.tangent[k];
    EXPECT_NEAR(dK, p.ctx.rates.v_du * transient.damping[k], 1e-12 * scale * p.ctx.rates.v_du);
    sum += transient.damping[k];
  }
  // rho c(T) V between c(20) and c(200): the mean nodal temperature sets the scale
  EXPECT_GT(sum, 7.8e-9 * 4.0e8 * 6.0);
  EXPECT_LT(sum, 7.8e-9 * 6.0e8 * 6.0);
  // the capacity flux's derivative by the rate, by central differences of the rate (T moves,
  // T0 stays: dT = dTdot / v_du)
  const double h = 1e-3;
  for (std::size_t j = 0; j < n; ++j) {
    const double keep = p.u[j];
    p.u[j] = keep + h / p.ctx.rates.v_du;
    const auto rp = operators_of(p).residual;
    p.u[j] = keep - h / p.ctx.rates.v_du;
    const auto rm = operators_of(p).residual;
    p.u[j] = keep;
    // conduction is linear in T here (constant k): its part of the difference is K_cond dT
    for (std::size_t i = 0; i < n; ++i) {
      const double fd = (rp[i] - rm[i]) / (2.0 * h);
      const double expected =
          transient.damping[i * n + j] + steady.tangent[i * n + j] / p.ctx.rates.v_du;
      EXPECT_NEAR(fd, expected, 1e-6 * scale) << i << ", " << j;
    }
  }
}

// ------------------------------------------------------------------------------ the assembler

using test::DenseInserter;

/// Three coupled trusses in a row (mass on U, capacity on NT) and a spring (massless).
std::string assembly_deck() {
  std::string s = "*NODE\n1, 0., 0., 0.\n2, 1., 0.5, 0.\n3, 2.5, 0., 0.3\n4, 3., 1., 0.\n";
  s += "*ELEMENT, TYPE=T3D2T, ELSET=E\n1, 1, 2\n2, 2, 3\n3, 3, 4\n";
  s += "*SOLID SECTION, ELSET=E, MATERIAL=M\n0.25\n" + material(true);
  return s;
}

struct AssemblyFixture {
  std::shared_ptr<const Model> model = model_of(assembly_deck());
  Discretization disc{*model};
  Assembler assembler{disc};
  std::vector<double> u, u0, v0, a0;
  StepContext ctx;

  AssemblyFixture() {
    for (auto& b : disc.blocks()) b.eqs = b.slots;
    const auto n = static_cast<std::size_t>(disc.dofs().n_slots());
    u.resize(n);
    u0.resize(n);
    v0.resize(n);
    a0.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      const bool nt = disc.dofs().slot_field(static_cast<LocalIndex>(k)) == Field::Temperature;
      u0[k] = nt ? 20.0 + k : 1e-4 * static_cast<double>(k);
      u[k] = u0[k] + (nt ? 5.0 : 1e-4 * std::cos(static_cast<double>(k)));
      v0[k] = 0.1 * std::sin(static_cast<double>(k));
      a0[k] = 0.05 * static_cast<double>(k % 3);
    }
  }
  std::size_t n() const { return u.size(); }
  FieldView fields(bool rates) const {
    FieldView f;
    f.u = u;
    f.u_start = u0;
    if (rates) {
      f.v_start = v0;
      f.a_start = a0;
    }
    return f;
  }
  /// The matrix and f_int with these weights.
  std::pair<std::vector<double>, std::vector<double>> assemble(const OperatorWeights& w,
                                                               bool rates = false) {
    DenseInserter K(n());
    std::vector<double> f(n(), 0.0);
    assembler.assemble(fields(rates), ctx, f, &K, nullptr, w);
    disc.reset_trial();
    return {K.A, f};
  }
};

TEST(OperatorAssembly, WeightedSumEqualsTheSeparateAssemblies) {
  AssemblyFixture fx;
  const auto [K, f] = fx.assemble({1.0, 0.0, 0.0});
  const auto [C, fc] = fx.assemble({0.0, 1.0, 0.0});
  const auto [M, fm] = fx.assemble({0.0, 0.0, 1.0});
  const OperatorWeights w{2.0, 3.0, 5.0};
  const auto [A, fa] = fx.assemble(w);
  double mass = 0.0, damping = 0.0, scale = 0.0;
  for (std::size_t k = 0; k < A.size(); ++k) {
    scale = std::max(scale, std::abs(A[k]));
    mass += M[k];
    damping += C[k];
  }
  for (std::size_t k = 0; k < A.size(); ++k)
    EXPECT_NEAR(A[k], 2.0 * K[k] + 3.0 * C[k] + 5.0 * M[k], 1e-14 * scale) << k;
  // without rates the residual is the static one whatever the weights
  for (std::size_t k = 0; k < f.size(); ++k) EXPECT_EQ(fa[k], f[k]);
  // the blocks are what the kernels say: 3 directions x rho A L, rho c A L
  double length = 0.0;
  const auto& X = fx.model->mesh.coords;
  for (int e = 0; e < 3; ++e)
    length += std::hypot(X[e + 1][0] - X[e][0], X[e + 1][1] - X[e][1], X[e + 1][2] - X[e][2]);
  EXPECT_NEAR(mass, 3.0 * kRho * 0.25 * length, 1e-12 * mass);
  EXPECT_NEAR(damping, kRho * kCapacity * 0.25 * length, 1e-9 * damping);
}

TEST(OperatorAssembly, StaticWeightsGiveTheTangentBitForBit) {
  AssemblyFixture fx;
  DenseInserter K(fx.n());
  std::vector<double> f(fx.n(), 0.0);
  fx.assembler.assemble(fx.fields(false), fx.ctx, f, &K, nullptr);
  fx.disc.reset_trial();
  const auto [K1, f1] = fx.assemble({});
  EXPECT_EQ(K.A, K1);
  EXPECT_EQ(f, f1);
}

// With rates defined (a second-order integrator's coefficients), the residual gets M a, the
// matrix m M; the capacity (integrated by the kernel itself) is never added a second time.
TEST(OperatorAssembly, InertiaForcesAndWeightsFollowTheRates) {
  AssemblyFixture fx;
  const auto [K, f] = fx.assemble({1.0, 0.0, 0.0});
  const auto [M, fm] = fx.assemble({0.0, 0.0, 1.0});
  RateCoefficients c;
  c.first_order = c.second_order = true;
  c.v_du = 2.0; // (a heat kernel takes no velocity with history: E's committed rate is not kept)
  c.a_du = 4.0, c.a_v = -4.0, c.a_a = -1.0;
  fx.ctx.rates = c;
  const OperatorWeights w{1.0, c.v_du, c.a_du};
  const auto [A, fa] = fx.assemble(w, true);
  const auto [Kr, fr] = fx.assemble({1.0, 0.0, 0.0}, true); // the kernels' own rate terms
  const std::size_t n = fx.n();
  double scale = 0.0;
  for (double x : A) scale = std::max(scale, std::abs(x));
  for (std::size_t k = 0; k < n * n; ++k)
    EXPECT_NEAR(A[k], Kr[k] + c.a_du * M[k], 1e-14 * scale) << k;
  for (std::size_t i = 0; i < n; ++i) {
    double Ma = 0.0;
    for (std::size_t j = 0; j < n; ++j)
      Ma += M[i * n + j] * c.acceleration(fx.u[j] - fx.u0[j], fx.v0[j], fx.a0[j]);
    EXPECT_NEAR(fa[i], fr[i] + Ma, 1e-12 * (std::abs(fr[i]) + std::abs(Ma) + 1e-30)) << i;
  }
}

} // namespace
} // namespace gapfem
