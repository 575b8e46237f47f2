// CalculiX's dialect: stress elements (C3D8, C3D20R, CPS4, CAX8, …) whose material has
// *CONDUCTIVITY and no *ELASTIC are read as their heat-transfer twins (DC3D8, DC3D20, DC2D4,
// DCAX8, …) with one warning per type; the temperatures are those of the deck written with the
// twins. A material with neither stays an error.
#include "test_util.hpp"

#include <fmt/format.h>

using namespace gapfem;
using namespace gapfem::test;

namespace {

/// A 2 x 1 x 1 block of two cells, T = 100 at x = 0, a film (h = 5, sink 20) at x = 2.
std::string block(const std::string& type, bool conductivity = true) {
  std::string d = "*HEADING\nstress elements in heat transfer\n*NODE\n";
  for (int i = 0; i <= 2; ++i)
    for (int k = 0; k < 4; ++k)
      d += fmt::format("{}, {}, {}, {}\n", 1 + 4 * i + k, i, k == 1 || k == 2 ? 1 : 0,
                       k >= 2 ? 1 : 0);
  d += fmt::format("*ELEMENT, TYPE={}, ELSET=B\n", type);
  for (int i = 0; i < 2; ++i) {
    const int a = 1 + 4 * i, b = a + 4;
    d += fmt::format("{}, {}, {}, {}, {}, {}, {}, {}, {}\n", i + 1, a, a + 1, a + 2, a + 3, b,
                     b + 1, b + 2, b + 3);
  }
  d += "*SOLID SECTION, ELSET=B, MATERIAL=M\n*MATERIAL, NAME=M\n";
  d += conductivity ? "*CONDUCTIVITY\n3.\n" : "*DENSITY\n1.\n";
  d += "*BOUNDARY\n1, 11, 11, 100.\n2, 11, 11, 100.\n3, 11, 11, 100.\n4, 11, 11, 100.\n";
  d += "*STEP\n*HEAT TRANSFER, STEADY STATE\n1., 1.\n*FILM\n2, F2, 20., 5.\n*NODE PRINT\nNT\n"
       "*END STEP\n";
  return d;
}

} // namespace

TEST(StressElementsInHeatTransfer, AreReadAsTheirHeatTransferTwins) {
  for (const auto& [stress, heat] :
       {std::pair{"C3D8", "DC3D8"}, std::pair{"C3D8R", "DC3D8"}, std::pair{"C3D8I", "DC3D8"}}) {
    SCOPED_TRACE(stress);
    const JobResult s = run_deck(block(stress), false, "stress");
    ASSERT_EQ(s.exit_code, 0) << s.error;
    const JobResult h = run_deck(block(heat), false, "heat");
    ASSERT_EQ(h.exit_code, 0) << h.error;
    const std::string warning = fmt::format(
        "{} element(s) have a material with *CONDUCTIVITY and no *ELASTIC: they are read as DC3D8",
        stress);
    int warned = 0;
    for (const std::string& w : s.model->warnings) warned += w.find(warning) != std::string::npos;
    EXPECT_EQ(warned, 1);
    // the closed form of the 1-D bar: q = (100 - 20) / (L/k + 1/h), T(2) = 20 + q / h
    const double q = 80.0 / (2.0 / 3.0 + 1.0 / 5.0);
    for (int n = 1; n <= 12; ++n) {
      const double Ts = last_frame(s).nodes.NT.at(s.model->mesh.find_node(n));
      EXPECT_NEAR(Ts, last_frame(h).nodes.NT.at(h.model->mesh.find_node(n)), 1e-10) << n;
      if (n > 8) EXPECT_NEAR(Ts, 20.0 + q / 5.0, 1e-8) << n;
    }
  }
  const JobResult bad = run_deck(block("C3D8", false), false, "bad");
  EXPECT_EQ(bad.exit_code, kExitInputError);
  EXPECT_NE(bad.error.find("needs *ELASTIC"), std::string::npos) << bad.error;
}
