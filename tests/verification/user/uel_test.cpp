// Nonlinear user elements through `--user`: a Fortran UEL written for the tests
// (uel/uel_elements.f: a nonlinear spring and an elastic-plastic truss with state variables and
// PNEWDT) and the same elements as a C++ plugin (uel/plugin_elements.cc) give the same answers as
// each other and as closed forms, with a gap closing and opening on the truss; PNEWDT drives
// cut-backs; bad user code gives clear errors.
#include "elements/user/user_code.hpp"
#include "test_util.hpp"

#include <cmath>
#include <fmt/format.h>
#include <sys/wait.h>

using namespace gapfem;
using namespace gapfem::test;

namespace {

namespace fs = std::filesystem;

const fs::path kUelDir = fs::path(GAPFEM_TEST_DIR) / "verification" / "user" / "uel";

JobResult run_user(const std::string& deck, const fs::path& code, const std::string& name = "job") {
  JobOptions o;
  o.deck = write_deck(deck, name);
  o.write_files = true;
  o.write_vtu = false;
  o.quiet = true;
  o.factor_reuse = FactorReuse::Never;
  o.user_code = code;
  return run_job(o);
}

/// The truss of U2 (L = 100, A = 10, E = 2e5, sigma_y = 250, H = 2e4; PNEWDT asked when the plastic
/// strain grows by more than 5e-4 in an increment) pushed by P = 4000 into a gap of clearance 0.5,
/// then unloaded to 0.
std::string truss_deck(const std::string& first_increment = "0.5") {
  return fmt::format(R"(*HEADING
elastic-plastic UEL truss pushed into a gap, then unloaded
*NODE
1, 0., 0., 0.
2, 100., 0., 0.
3, 101., 0., 0.
*USER ELEMENT, TYPE=U2, NODES=2, COORDINATES=3, PROPERTIES=5, VARIABLES=3
1, 2, 3
*UEL PROPERTY, ELSET=BAR
10., 200000., 250., 20000., 0.0005
*ELEMENT, TYPE=U2, ELSET=BAR
1, 1, 2
*ELEMENT, TYPE=GAPUNI, ELSET=GAP
2, 2, 3
*GAP, ELSET=GAP
0.5, 1., 0., 0., 1.
*BOUNDARY
1, 1, 3
3, 1, 3
2, 2, 3
*STEP, INC=100
*STATIC
{}, 1.
*CLOAD
2, 1, 4000.
*EL PRINT, ELSET=BAR
NFORC
*END STEP
*STEP, INC=100
*STATIC
0.5, 1.
*CLOAD
2, 1, 0.
*EL PRINT, ELSET=BAR
NFORC
*END STEP
)",
                     first_increment);
}

/// The nonlinear spring U1 (F = k d + k3 d^3, k = 100, k3 = 2) from a fixed node 1 to node 2 under
/// P = 500 (and a GAPUNI at node 2 that never closes).
const char* kSpringDeck = R"(*HEADING
nonlinear UEL spring
*NODE
1, 0., 0., 0.
2, 1., 0., 0.
3, 1., 0., 0.
*USER ELEMENT, TYPE=U1, NODES=2, PROPERTIES=2
1
*UEL PROPERTY, ELSET=S
100., 2.
*ELEMENT, TYPE=U1, ELSET=S
1, 1, 2
*ELEMENT, TYPE=GAPUNI, ELSET=G
2, 2, 3
*GAP, ELSET=G
50., 1., 0., 0.
*BOUNDARY
1, 1, 1
2, 2, 3
3, 1, 3
*STEP, INC=100
*STATIC
0.1, 1.
*CLOAD
2, 1, 500.
*END STEP
)";

} // namespace

TEST(UserSubroutine, FortranUelAndPluginMatchTheClosedForms) {
  // closed form of the truss: the gap closes at u = 0.5 (strain 0.005 > 0.00125, plastic); there
  // 0.005 = s/E + (s - 250)/H gives s = 3500/11 and a truss force 35000/11, the gap takes the rest;
  // unloaded, the bar keeps its plastic strain (s - 250)/H: u = 100 (s - 250)/H
  const double s = 3500.0 / 11.0;
  const double gap_force = 4000.0 - 10.0 * s, u_end = 100.0 * (s - 250.0) / 2e4;
  JobResult runs[2];
  int k = 0;
  for (const char* code : {"uel_elements.f", "plugin_elements.cc"}) {
    SCOPED_TRACE(code);
    JobResult& r = runs[k++];
    r = run_user(truss_deck(), kUelDir / code, k == 1 ? "fortran" : "plugin");
    ASSERT_EQ(r.exit_code, 0) << r.error;
    const Frame& f1 = last_frame(r, 1);
    EXPECT_NEAR(U(r, f1, 2)[0], 0.5, 1e-12);
    EXPECT_NEAR(gap(r, f1, 2).normal_force, gap_force, 1e-8);
    EXPECT_NEAR(RF(r, f1, 1)[0], -10.0 * s, 1e-8);
    // NFORC of the truss: -F at node 1, +F at node 2 (the force it exerts on its nodes)
    const OutputBlock* nf = f1.element(r.model->mesh.find_element(1))->data.find(ElemVar::NFORC);
    ASSERT_TRUE(nf);
    EXPECT_NEAR(nf->values[0], -10.0 * s, 1e-8);
    EXPECT_NEAR(nf->values[3], 10.0 * s, 1e-8);
    const Frame& f2 = last_frame(r, 2);
    EXPECT_EQ(gap(r, f2, 2).status, ContactStatus::Open);
    EXPECT_NEAR(U(r, f2, 2)[0], u_end, 1e-12);
  }
  // the two codes take the same path: the same increments and results
  ASSERT_EQ(runs[0].increments.size(), runs[1].increments.size());
  ASSERT_EQ(runs[0].frames.size(), runs[1].frames.size());
  for (std::size_t i = 0; i < runs[0].frames.size(); ++i)
    EXPECT_NEAR(runs[0].frames[i].nodes.U[1][0], runs[1].frames[i].nodes.U[1][0], 1e-12);

  // the spring: 2 d^3 + 100 d = 500 (Newton on the closed form)
  double d = 5.0;
  for (int i = 0; i < 50; ++i) d -= (2 * d * d * d + 100 * d - 500) / (6 * d * d + 100);
  for (const char* code : {"uel_elements.f", "plugin_elements.cc"}) {
    SCOPED_TRACE(code);
    const JobResult r = run_user(kSpringDeck, kUelDir / code, "spring");
    ASSERT_EQ(r.exit_code, 0) << r.error;
    // the last increment stops by Abaqus's criteria, started from the extrapolated guess: its
    // answer is accurate to the last correction (~1e-9), not to round-off
    EXPECT_NEAR(U(r, last_frame(r), 2)[0], d, 1e-8 * d);
    EXPECT_NEAR(RF(r, last_frame(r), 1)[0], -500.0, 1e-8 * 500.0);
  }
}

// PNEWDT = 0.5 when the plastic strain grows by more than 5e-4: with a first increment of the
// whole step the UEL rejects it and each retry is half the one before, until the plastic strain
// increment is small enough; the answer is unchanged.
TEST(UserSubroutine, PnewdtDrivesCutBacks) {
  const JobResult r = run_user(truss_deck("1."), kUelDir / "uel_elements.f");
  ASSERT_EQ(r.exit_code, 0) << r.error;
  int rejected = 0;
  double tried = 0.0;
  for (const IncrementInfo& i : r.increments) {
    if (i.step != 1) continue;
    if (tried > 0.0) EXPECT_NEAR(i.dt, 0.5 * tried, 1e-12) << "increment " << i.increment;
    tried = i.converged ? 0.0 : i.dt;
    rejected += !i.converged;
  }
  EXPECT_GE(rejected, 2);
  EXPECT_NEAR(U(r, last_frame(r, 2), 2)[0], 100.0 * (3500.0 / 11.0 - 250.0) / 2e4, 1e-12);
  // DIRECT incrementation allows no cut-back: PNEWDT < 1 stops the step
  std::string direct = truss_deck("1.");
  direct.replace(direct.find("*STATIC\n1., 1."), 14, "*STATIC, DIRECT\n1., 1.");
  const JobResult d = run_user(direct, kUelDir / "uel_elements.f", "direct");
  EXPECT_EQ(d.exit_code, kExitNoConvergence);
  EXPECT_NE(d.error.find("PNEWDT"), std::string::npos) << d.error;
}

// Bad user code: each an input error (exit 1) or, for a UEL that returns NaN, an analysis error
// (exit 2) naming the element; never a crash.
TEST(UserSubroutine, BadUserCodeGivesClearErrors) {
  const fs::path dir = test_dir();
  auto source = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return dir / name;
  };
  // a source that does not compile: the compiler's own message
  JobResult r = run_user(
      kSpringDeck, source("broken.f", "      SUBROUTINE UEL(RHS)\n      X = = 1\n      END\n"),
      "broken");
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("gfortran could not compile this file"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("broken.f:2"), std::string::npos) << r.error;
  // a library without UEL (the subroutine has another name)
  r = run_user(kSpringDeck, source("umat.f", "      SUBROUTINE UMAT(X)\n      X = 1.\n      END\n"),
               "nouel");
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("defines neither a UEL subroutine"), std::string::npos) << r.error;
  // a UEL that returns NaN
  r = run_user(kSpringDeck, source("nan.f90", R"(subroutine uel(rhs, amatrx, svars, energy, ndofel)
  include 'ABA_PARAM.INC'
  dimension rhs(ndofel), amatrx(ndofel, ndofel)
  zero = 0.d0
  rhs = zero / zero
  amatrx = 1.d0
end subroutine
)"),
               "nan");
  EXPECT_EQ(r.exit_code, kExitNoConvergence);
  EXPECT_NE(r.error.find("element 1 (U1): the user subroutine UEL (nan.f90) returned RHS(1) = nan "
                         "in step 1, increment 1"),
            std::string::npos)
      << r.error;
  // no --user for a user element that needs code
  JobOptions o;
  o.deck = write_deck(kSpringDeck, "nocode");
  o.write_files = false;
  o.quiet = true;
  r = run_job(o);
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("run gapfem --user uel.f deck.inp"), std::string::npos) << r.error;
  // a plugin of another ABI version
  r = run_user(kSpringDeck,
               source("old.cpp", R"(extern "C" int gapfem_plugin_abi_version() { return 0; }
struct gapfem_element_call;
extern "C" int gapfem_element(gapfem_element_call*) { return 0; }
)"),
               "abi");
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("built for plugin ABI version 0"), std::string::npos) << r.error;
  // a file that is not code
  r = run_user(kSpringDeck, source("notes.txt", "hello\n"), "txt");
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("give a Fortran"), std::string::npos) << r.error;
}

// The CLI: `gapfem --user uel.f deck.inp` as Abaqus's `abaqus job=deck user=uel.f`.
TEST(UserSubroutine, CommandLine) {
  const fs::path deck = write_deck(kSpringDeck, "cli");
  const std::string cmd =
      fmt::format("cd '{}' && '{}' -q --user '{}' cli.inp > cli.log 2>&1",
                  deck.parent_path().string(), GAPFEM_EXE, (kUelDir / "uel_elements.f").string());
  const int rc = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(rc));
  EXPECT_EQ(WEXITSTATUS(rc), 0) << slurp(deck.parent_path() / "cli.log");
  EXPECT_FALSE(fs::exists(deck.parent_path() / "cli.scratch")); // removed once loaded
}
