// The damping block of a UEL (UelKernel, LFLAGS(3) = 3; docs/theory/dynamics.md §8) with a UEL
// written here in C++ with the Fortran calling convention: a spring k and a dashpot c between two
// nodes along x (DOF 1 each). What is checked, each against values by hand:
// - in a *DYNAMIC step the damping block is the AMATRX of the LFLAGS(3) = 3 call (symmetrized
//   unless UNSYMM), asked with LFLAGS(1) = 11 or 12 on copies of SVARS (the history is that of the
//   residual call alone); residual, tangent and mass are those without damping;
// - a zero damping matrix is asked for once per step (the element's history remembers it across
//   the attempt and the increments of the step) and again in the next step; a non-zero one at
//   every evaluation;
// - a UEL that returns its stiffness for LFLAGS(3) = 3 (it does not read LFLAGS(3)) is undamped;
// - no damping call outside *DYNAMIC steps, none in a model without a *DYNAMIC step;
// - a non-finite damping entry is one AnalysisError naming the element and LFLAGS(3) = 3.
#include "elements/user/uel_kernel.hpp"
#include "elements/user/user_code.hpp"
#include "unit/elements/kernel_probe.hpp"

#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace gapfem::test {
namespace {

/// What the UEL below saw: calls per LFLAGS(3), LFLAGS(1) of the last damping call. Calls are
/// serialised by UserCode's mutex; the tests run one kernel at a time.
struct Calls {
  std::array<int, 5> by_flag{};
  int damping_procedure = 0;
};
Calls g_calls;

enum class Mode { Damped, Undamped, StiffnessAlways, NonFinite };
Mode g_mode = Mode::Damped;

constexpr double kK = 500.0, kC = 3.0, kM = 0.5;

/// PROPS = k, c. SVARS(1) counts the residual calls (a damping call must not change it).
void uel(double* rhs, double* amatrx, double* svars, double* /*energy*/, int* ndofel, int* /*nrhs*/,
         int* /*nsvars*/, double* props, int* /*nprops*/, double* /*coords*/, int* /*mcrd*/,
         int* /*nnode*/, double* u, double* /*du*/, double* /*v*/, double* /*a*/, int* /*jtype*/,
         double* /*time*/, double* /*dtime*/, int* /*kstep*/, int* /*kinc*/, int* /*jelem*/,
         double* /*params*/, int* /*ndload*/, int* /*jdltyp*/, double* /*adlmag*/,
         double* /*predef*/, int* /*npredf*/, int* lflags, int* /*mlvarx*/, double* /*ddlmag*/,
         int* /*mdload*/, double* /*pnewdt*/, int* /*jprops*/, int* /*njprop*/,
         double* /*period*/) {
  const int what = g_mode == Mode::StiffnessAlways && lflags[2] != 4 ? 2 : lflags[2];
  ++g_calls.by_flag[static_cast<std::size_t>(lflags[2])];
  const int n = *ndofel;
  auto set = [&](double s) { // s [1 -1; -1 1], column-major
    amatrx[0] = amatrx[3] = s;
    amatrx[1] = amatrx[2] = -s;
  };
  if (what == 4) {
    amatrx[3] = kM;
    return;
  }
  if (what == 3) {
    g_calls.damping_procedure = lflags[0];
    if (g_mode == Mode::Damped) set(props[1]);
    if (g_mode == Mode::NonFinite) {
      set(props[1]);
      amatrx[1] = std::numeric_limits<double>::quiet_NaN();
    }
    return;
  }
  set(props[0]);
  for (int i = 0; i < n; ++i) rhs[i] = -(amatrx[i] * u[0] + amatrx[i + n] * u[1]);
  svars[0] += 1.0;
}

UserElementType type() {
  UserElementType t;
  t.name = "U7";
  t.number = 7;
  t.n_nodes = 2;
  t.n_coords = 1;
  t.n_properties = 2;
  t.n_variables = 1;
  t.node_dofs = {{1}, {1}};
  return t;
}

KernelProbe probe(Mode mode, bool dynamic_model = true) {
  g_mode = mode;
  g_calls = {};
  UelProperty props;
  props.properties = {kK, kC};
  auto code = std::make_shared<const UserCode>(&uel, nullptr, "uel (unit test)");
  KernelProbe p(std::make_shared<UelKernel>(type(), &props, code, false, dynamic_model),
                {Vec3{0.0, 0.0, 0.0}, Vec3{1.0, 0.0, 0.0}});
  p.ctx.procedure = Procedure::Dynamic;
  p.ctx.direct = true;
  p.ctx.dt = 0.01;
  p.ctx.step_number = 2;
  p.ctx.increment = 1;
  p.u = {0.001, 0.004};
  return p;
}

/// One evaluation asking for residual, tangent, mass and damping.
struct Blocks {
  std::vector<double> r, K, M, C;
};
Blocks evaluate(KernelProbe& p) {
  Blocks b{std::vector<double>(2), std::vector<double>(4), std::vector<double>(4),
           std::vector<double>(4)};
  std::vector<double> v{0.1, -0.2}, a{0.0, 0.0};
  ElementInput in = p.input();
  in.v = v;
  in.a = a;
  in.v_start = v;
  in.a_start = a;
  ElementOutput out;
  out.residual = b.r;
  out.tangent = b.K;
  out.mass = b.M;
  out.want_mass = true;
  out.damping = b.C;
  out.want_damping = p.kernel->has_damping();
  p.kernel->evaluate(in, out);
  return b;
}

void expect_block(const std::vector<double>& A, double s) {
  EXPECT_EQ(A, (std::vector<double>{s, -s, -s, s}));
}

TEST(UelDamping, DampingBlockIsTheLflags3Matrix) {
  KernelProbe p = probe(Mode::Damped);
  EXPECT_TRUE(p.kernel->has_damping());
  const Blocks b = evaluate(p);
  expect_block(b.C, kC);
  expect_block(b.K, kK);
  EXPECT_EQ(b.M, (std::vector<double>{0.0, 0.0, 0.0, kM}));
  EXPECT_DOUBLE_EQ(b.r[1], kK * (0.004 - 0.001)); // no C v in the kernel's residual
  EXPECT_EQ(g_calls.damping_procedure, 12);       // *DYNAMIC, DIRECT
  EXPECT_EQ(p.state[0], 1.0);                     // SVARS: the residual call only
  // damped: asked at every evaluation, the stiffness only at the first (the comparison)
  evaluate(p);
  EXPECT_EQ(g_calls.by_flag[3], 2);
  EXPECT_EQ(g_calls.by_flag[2], 1);
}

TEST(UelDamping, ZeroDampingIsAskedForOncePerStep) {
  KernelProbe p = probe(Mode::Undamped);
  for (int i = 0; i < 3; ++i) expect_block(evaluate(p).C, 0.0); // iterations of one attempt
  EXPECT_EQ(g_calls.by_flag[3], 1);
  p.commit();
  p.ctx.increment = 2;
  evaluate(p);
  p.revert(); // a cut-back: the committed history still knows
  evaluate(p);
  EXPECT_EQ(g_calls.by_flag[3], 1);
  EXPECT_EQ(g_calls.by_flag[2], 0);
  p.commit();
  p.ctx.step_number = 3; // a new step asks again
  p.ctx.increment = 1;
  evaluate(p);
  EXPECT_EQ(g_calls.by_flag[3], 2);
}

TEST(UelDamping, StiffnessReturnedAsDampingIsNoDamping) {
  KernelProbe p = probe(Mode::StiffnessAlways);
  expect_block(evaluate(p).C, 0.0);
  expect_block(evaluate(p).C, 0.0);
  EXPECT_EQ(g_calls.by_flag[3], 1);
  EXPECT_EQ(g_calls.by_flag[2], 1);
}

TEST(UelDamping, NoDampingOutsideDynamicSteps) {
  KernelProbe p = probe(Mode::Damped);
  p.ctx.procedure = Procedure::CoupledTempDisp;
  p.ctx.transient = true;
  expect_block(evaluate(p).C, 0.0);
  EXPECT_EQ(g_calls.by_flag[3], 0);
  KernelProbe q = probe(Mode::Damped, false);
  EXPECT_FALSE(q.kernel->has_damping());
  EXPECT_FALSE(q.kernel->has_mass());
}

TEST(UelDamping, NonFiniteDampingNamesTheElement) {
  KernelProbe p = probe(Mode::NonFinite);
  try {
    evaluate(p);
    ADD_FAILURE() << "no error";
  } catch (const AnalysisError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("U7"), std::string::npos) << what;
    EXPECT_NE(what.find("the damping matrix (LFLAGS(3) = 3)"), std::string::npos) << what;
    EXPECT_NE(what.find("AMATRX(2,1) = nan"), std::string::npos) << what;
  }
}

} // namespace
} // namespace gapfem::test
