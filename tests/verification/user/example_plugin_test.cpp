// The example element plugin (examples/plugins/nonlinear_spring.cpp), built by the project as a
// shared library and compiled by gapfem from its source: the snubber deck meets the closed forms
// of examples/plugins/README.md.
#include "test_util.hpp"

using namespace gapfem;
using namespace gapfem::test;

TEST(ExamplePlugin, SnubberMeetsTheClosedForms) {
  const std::filesystem::path src =
      std::filesystem::path(GAPFEM_SOURCE_DIR) / "examples" / "plugins";
  const double kt = 1000.0 * 100.0 / 1100.0; // tangent after yield
  const double f_stop = 2000.0 + kt * 3.0;   // spring force when the stop closes at 5 mm
  const double dp = 5.0 - f_stop / 1000.0;   // plastic displacement left at release
  for (const std::filesystem::path code :
       {std::filesystem::path(GAPFEM_EXAMPLE_PLUGIN), src / "nonlinear_spring.cpp"}) {
    SCOPED_TRACE(code.string());
    JobOptions o;
    o.deck = src / "snubber.inp";
    o.output_dir = test_dir() / code.extension().string().substr(1);
    o.write_vtu = false;
    o.quiet = true;
    o.user_code = code;
    const JobResult r = run_job(o);
    ASSERT_EQ(r.exit_code, 0) << r.error;
    EXPECT_NEAR(U(r, last_frame(r, 1), 2)[0], 5.0, 1e-12);
    EXPECT_NEAR(gap(r, last_frame(r, 1), 2).normal_force, 3500.0 - f_stop, 1e-8);
    EXPECT_EQ(gap(r, last_frame(r, 2), 2).status, ContactStatus::Open);
    EXPECT_NEAR(U(r, last_frame(r, 2), 2)[0], dp, 1e-12);
    // reverse yield where F - b = -Fy (b = 100 dp), then the hardening branch down to -3500 N
    const double f_rev = 100.0 * dp - 2000.0;
    const double d_rev = dp + f_rev / 1000.0;
    EXPECT_NEAR(U(r, last_frame(r, 3), 2)[0], d_rev + (-3500.0 - f_rev) / kt, 1e-10);
  }
}
