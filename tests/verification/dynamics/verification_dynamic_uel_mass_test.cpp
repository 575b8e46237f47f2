// A UEL's mass in a dynamic step (elements/user/uel_kernel.cpp): the user element of
// uel/uel_mass_truss.f, a linear truss returning K for LFLAGS(3) = 1, 2 and the lumped mass
// rho A L / 2 per node and translation for LFLAGS(3) = 4, against the built-in T3D2 (the same
// stiffness EA/L and the same lumped mass, docs/theory/dynamics.md) in the same *DYNAMIC steps:
// HHT (TRANSIENT FIDELITY, initial accelerations from M) and the trapezoidal rule. The two
// models are the same equations assembled from the same numbers, so their histories agree to
// round-off: 1e-10 of the largest displacement (the algebra of two 4-DOF systems differs by
// summation order only, ~1e-15 relative). The response must also be dynamic: at the first
// increment the free end has moved less than a fifth of its static displacement (a massless
// UEL would reach it at once), and it overshoots the static value later (no damping).
#include "test_util.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>

namespace gapfem {
namespace {

namespace fs = std::filesystem;

const fs::path kUelDir = fs::path(GAPFEM_TEST_DIR) / "verification" / "user" / "uel";

/// Two trusses in a row along x (L = 100, A = 10, E = 2e5, rho = 7.8e-9), node 1 fixed, U2 and U3
/// held, a force F = 1000 suddenly applied at node 3: built-in T3D2 or the UEL U3.
std::string deck(bool user, const std::string& dynamic) {
  const std::string elements =
      user ? "*USER ELEMENT, TYPE=U3, NODES=2, COORDINATES=3, PROPERTIES=3, VARIABLES=1\n"
             "1, 2, 3\n"
             "*ELEMENT, TYPE=U3, ELSET=BAR\n1, 1, 2\n2, 2, 3\n"
             "*UEL PROPERTY, ELSET=BAR\n10., 200000., 7.8e-9\n"
           : "*ELEMENT, TYPE=T3D2, ELSET=BAR\n1, 1, 2\n2, 2, 3\n"
             "*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL\n10.\n"
             "*MATERIAL, NAME=STEEL\n*ELASTIC\n200000., 0.3\n*DENSITY\n7.8e-9\n";
  return fmt::format(R"(*HEADING
two-truss bar under a suddenly applied force
*NODE
1, 0., 0., 0.
2, 100., 0., 0.
3, 200., 0., 0.
{}*BOUNDARY
1, 1, 3
2, 2, 3
3, 2, 3
*AMPLITUDE, NAME=CONST
0., 1., 1., 1.
*STEP, INC=1000
*DYNAMIC, DIRECT{}
5e-6, 2e-4
*CLOAD, AMPLITUDE=CONST
3, 1, 1000.
*NODE PRINT, FREQUENCY=1
U
*END STEP
)",
                     elements, dynamic);
}

JobResult run(bool user, const std::string& dynamic, const std::string& name) {
  JobOptions o;
  o.deck = test::write_deck(deck(user, dynamic), name);
  o.write_files = false;
  o.quiet = true;
  o.factor_reuse = FactorReuse::Never;
  if (user) o.user_code = kUelDir / "uel_mass_truss.f";
  return run_job(o);
}

/// U1 of nodes 2 and 3 at the end of every increment.
std::vector<double> history(const JobResult& r) {
  std::vector<double> h;
  for (const Frame& f : r.frames) {
    if (f.increment <= 0) continue;
    for (Label n : {2, 3}) h.push_back(test::U(r, f, n)[0]);
  }
  return h;
}

TEST(DynamicUelMass, UelTrussMatchesT3D2) {
  // static end displacement: two springs EA/L = 2e4 in series under 1000
  const double u_static = 1000.0 / 2e4 * 2.0;
  for (const char* dynamic : {"", ", ALPHA=0."}) {
    SCOPED_TRACE(dynamic);
    const JobResult builtin = run(false, dynamic, "t3d2");
    const JobResult user = run(true, dynamic, "uel");
    ASSERT_EQ(builtin.exit_code, 0) << builtin.error;
    ASSERT_EQ(user.exit_code, 0) << user.error;
    const auto a = history(builtin), b = history(user);
    ASSERT_EQ(a.size(), 80u);
    ASSERT_EQ(b.size(), a.size());
    double peak = 0.0;
    for (double v : a) peak = std::max(peak, std::abs(v));
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(b[i], a[i], 1e-10 * peak) << i;
    EXPECT_LT(std::abs(b[1]), 0.2 * u_static);
    EXPECT_GT(peak, 1.3 * u_static);
  }
}

} // namespace
} // namespace gapfem
