// *FREQUENCY of a rigid block on gap supports over springs (issue 47's closed form;
// docs/theory/frequency.md §2): the base state's contact status decides the supports.
// The block: two stiff B31 (E = 1e15: their bending adds ~1e-9 of the compliance) from x = 0 to
// x = L = 2, its mass m = 10 (MASS) and rotary inertia I = 5 about z (ROTARYI) at its centre,
// held out of the x-y plane. Supports at x = 0, 1, 2: a GAPUNI from the block down to a massless
// node on a SPRING1 of k = 1000 to ground. A general step pushes the block down by 100: the end
// gaps (clearance 0) close; the middle one (clearance 0.5) stays open. In the frequency step the
// closed gaps are bilateral, the open one is nothing:
//   bounce  omega^2 = 2 k / m = 200,   rocking  omega^2 = 2 k (L/2)^2 / I = 400.
// With the middle clearance 0 it closes too: bounce 3 k / m = 300, rocking still 400 (the middle
// support lies on the axis of rotation). Tolerance 1e-6.
#include "test_util.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace gapfem {
namespace {

std::string block(double middle_clearance) {
  return fmt::format(R"(*HEADING
Rigid block on gap supports over springs
*NODE
1, 0., 0., 0.
2, 1., 0., 0.
3, 2., 0., 0.
11, 0., -0.1, 0.
12, 1., -0.1, 0.
13, 2., -0.1, 0.
*ELEMENT, TYPE=B31, ELSET=BLOCK
1, 1, 2
2, 2, 3
*BEAM SECTION, ELSET=BLOCK, MATERIAL=STIFF, SECTION=RECT
0.1, 0.1
0., 0., -1.
*MATERIAL, NAME=STIFF
*ELASTIC
1e15, 0.3
*ELEMENT, TYPE=MASS, ELSET=M
20, 2
*MASS, ELSET=M
10.
*ELEMENT, TYPE=ROTARYI, ELSET=I
21, 2
*ROTARY INERTIA, ELSET=I
1., 1., 5.
*ELEMENT, TYPE=GAPUNI, ELSET=ENDS
31, 1, 11
33, 3, 13
*GAP, ELSET=ENDS
0., 0., -1., 0.
*ELEMENT, TYPE=GAPUNI, ELSET=MIDDLE
32, 2, 12
*GAP, ELSET=MIDDLE
{}, 0., -1., 0.
*ELEMENT, TYPE=SPRING1, ELSET=SPRINGS
41, 11
42, 12
43, 13
*SPRING, ELSET=SPRINGS
2
1000.
*BOUNDARY
1, 3, 5
2, 1, 1
2, 3, 5
3, 3, 5
11, 1, 1
11, 3, 3
12, 1, 1
12, 3, 3
13, 1, 1
13, 3, 3
*STEP
*STATIC
*CLOAD
2, 2, -100.
*END STEP
*STEP
*FREQUENCY
2
*END STEP
)",
                     middle_clearance);
}

const EigenSummary& modes_of(const JobResult& r) {
  for (const auto& [index, m] : r.modes)
    if (index == 1) return m;
  throw std::runtime_error("no modes for step 2");
}

TEST(VerificationRigidBlock, AnOpenSupportDoesNotStiffenTheModes) {
  const JobResult r = test::run_deck(block(0.5));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const EigenSummary& m = modes_of(r);
  ASSERT_EQ(m.modes.size(), 2u);
  EXPECT_NEAR(m.modes[0].eigenvalue, 200.0, 1e-6 * 200.0);
  EXPECT_NEAR(m.modes[1].eigenvalue, 400.0, 1e-6 * 400.0);
  // the base state: the ends closed, the middle open
  const Frame& base = test::last_frame(r, 1);
  EXPECT_EQ(test::gap(r, base, 31).status, ContactStatus::Closed);
  EXPECT_EQ(test::gap(r, base, 32).status, ContactStatus::Open);
}

TEST(VerificationRigidBlock, AClosedMiddleSupportStiffensTheBounceOnly) {
  const JobResult r = test::run_deck(block(0.0));
  ASSERT_EQ(r.exit_code, 0) << r.error;
  const EigenSummary& m = modes_of(r);
  ASSERT_EQ(m.modes.size(), 2u);
  EXPECT_NEAR(m.modes[0].eigenvalue, 300.0, 1e-6 * 300.0);
  EXPECT_NEAR(m.modes[1].eigenvalue, 400.0, 1e-6 * 400.0);
}

} // namespace
} // namespace gapfem
