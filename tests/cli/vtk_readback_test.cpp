// What users see: the ParaView frame read back by VTK's own reader (Debian python3-vtk9, through
// tests/cli/vtk_dump.py) holds, for every requested variable, the values of job.results.json, beams
// included (S at the extreme fibre, SF and SM). Skipped with a message where VTK's Python bindings
// are missing; CI installs them (scripts/install-deps.sh).
#include "test_util.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace gapfem {
namespace {

using gapfem::test::slurp;

using nlohmann::json;

/// VTK's view of a .vtu (vtk_dump.py), or nullopt with the reason when VTK is not available.
std::optional<json> vtk_view(const std::filesystem::path& vtu, std::string& why) {
  const std::filesystem::path out = vtu.parent_path() / "vtk_dump.json";
  const std::string cmd = "/usr/bin/python3 " + std::string(GAPFEM_TEST_DIR) +
                          "/cli/vtk_dump.py '" + vtu.string() + "' > '" + out.string() + "'";
  const int rc = std::system(cmd.c_str());
  if (rc == -1 || !WIFEXITED(rc) || WEXITSTATUS(rc) == 77 || WEXITSTATUS(rc) == 127) {
    why = "VTK's Python bindings are not installed (Debian python3-vtk9 for /usr/bin/python3)";
    return std::nullopt;
  }
  EXPECT_EQ(WEXITSTATUS(rc), 0) << cmd;
  return json::parse(slurp(out));
}

void expect_tuple(const json& vtk, const json& ref, double tol, const std::string& what) {
  ASSERT_TRUE(vtk.is_array()) << what;
  ASSERT_EQ(vtk.size(), ref.size()) << what << ": VTK " << vtk << " vs JSON " << ref;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    const double a = vtk[i].get<double>(), b = ref[i].get<double>();
    EXPECT_NEAR(a, b, tol * std::max(1.0, std::abs(b))) << what << " component " << i;
  }
}

TEST(VtkReadback, EveryRequestedVariableAsInTheJsonResults) {
  // a B31 cantilever (RECT 10 x 20) loaded down and twisted at the tip, closing a GAPUNI under it
  const std::string deck =
      "*NODE\n1, 0, 0, 0\n2, 50, 0, 0\n3, 100, 0, 0\n4, 100, -1, 0\n*NSET, NSET=TIP\n3\n"
      "*ELEMENT, TYPE=B31, ELSET=BEAM\n1, 1, 2\n2, 2, 3\n*ELEMENT, TYPE=GAPUNI, ELSET=G\n3, 3, 4\n"
      "*MATERIAL, NAME=M\n*ELASTIC\n200000., 0.3\n"
      "*BEAM SECTION, ELSET=BEAM, MATERIAL=M, SECTION=RECT\n10., 20.\n0., 0., -1.\n"
      "*GAP, ELSET=G\n0.01, 0., -1., 0., 1.\n*BOUNDARY\n1, ENCASTRE\n4, 1, 3\n"
      "*STEP\n*STATIC\n*CLOAD\n3, 2, -1.e5\n3, 4, 2.e4\n3, 5, 3.e4\n"
      "*OUTPUT, FIELD\n*NODE OUTPUT\nU, UR, RF, CF\n*ELEMENT OUTPUT\nS, SF\n"
      "*NODE PRINT\nU, UR, RF, CF\n*EL PRINT\nS, SF\n*END STEP\n";
  const JobResult r = test::run_deck(deck, true);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  std::string why;
  const auto vtk = vtk_view(test::test_dir() / "job_1_1.vtu", why);
  if (!vtk) GTEST_SKIP() << why;
  const json res = json::parse(slurp(test::test_dir() / "job.results.json"));
  const json& inc = res["steps"][0]["frames"].back();
  const json& nodes = inc["nodes"];
  const json& elements = inc["elements"];
  ASSERT_EQ((*vtk)["points"], 4);
  ASSERT_EQ((*vtk)["cells"], 3);
  const json& point = (*vtk)["point"];
  for (const char* v : {"U", "UR", "RF", "CF"}) {
    ASSERT_TRUE(point.contains(v)) << v;
    for (int n = 0; n < 4; ++n) { // points in deck order: labels 1 … 4
      const std::string label = std::to_string(n + 1);
      if (!nodes[label].contains(v)) continue; // the ground node has no rotations
      expect_tuple(point[v][n], nodes[label][v], 1e-12, std::string(v) + " at node " + label);
    }
  }
  EXPECT_FALSE(point.contains("NT"));
  const json& cell = (*vtk)["cell"];
  for (const char* v : {"S", "SF", "SM", "gap_status"}) EXPECT_TRUE(cell.contains(v)) << v;
  EXPECT_FALSE(cell.contains("E")); // not requested
  for (int e = 0; e < 2; ++e) {
    const json& el = elements[std::to_string(e + 1)];
    // SF1 SF2 SF3 SM1 SM2 SM3 of the beam: VTU SF (6 slots) and SM (3)
    const json& sf = el["SF"];
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(cell["SF"][e][k].get<double>(), sf[k].get<double>(),
                  1e-9 * std::max(1.0, std::abs(sf[k].get<double>())));
      EXPECT_NEAR(cell["SM"][e][k].get<double>(), sf[3 + k].get<double>(),
                  1e-9 * std::max(1.0, std::abs(sf[3 + k].get<double>())));
    }
    EXPECT_TRUE(cell["SF"][e][3].is_null()); // SF4 … SF6: not a beam's
    // S at the extreme fibre: the section point with the largest |S11| (Voigt 11 and 12)
    double peak = -1.0;
    json fibre;
    for (const json& p : el["S_POINTS"])
      if (std::abs(p[0].get<double>()) > peak) {
        peak = std::abs(p[0].get<double>());
        fibre = p;
      }
    EXPECT_NEAR(cell["S"][e][0].get<double>(), fibre[0].get<double>(), 1e-9 * peak);
    EXPECT_NEAR(cell["S"][e][3].get<double>(), fibre[1].get<double>(), 1e-9 * peak);
    EXPECT_GT(peak, 0.0);
  }
  // the gap: closed, its contact pressure in S11
  const json& gap = elements["3"];
  EXPECT_EQ(gap["gap"]["status"], "closed");
  EXPECT_EQ(cell["gap_status"][2][0].get<double>(), 1.0);
  EXPECT_NEAR(cell["S"][2][0].get<double>(), gap["S"][0].get<double>(),
              1e-9 * std::abs(gap["S"][0].get<double>()));
}

} // namespace
} // namespace gapfem
