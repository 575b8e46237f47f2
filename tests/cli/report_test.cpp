// job.report.html: its data are those of the run (parsed back from the page), and headless
// Chromium draws every plot (the page's script records on <body> how many charts it drew and how
// many canvases hold paint). Skipped with a message where Chromium is missing; CI installs it.
#include "test_util.hpp"

#include <cstdlib>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

namespace gapfem {
namespace {

using gapfem::test::slurp;

using nlohmann::json;

json page_data(const std::string& html) {
  const std::string mark = "const DATA = ";
  const auto at = html.rfind(mark);
  EXPECT_NE(at, std::string::npos);
  const auto end = html.find(";\n", at);
  std::string d = html.substr(at + mark.size(), end - at - mark.size());
  return json::parse(std::regex_replace(d, std::regex("<\\\\/"), "</"));
}

// A B31 cantilever (L = 100, RECT 10 x 10, E = 2e5: tip stiffness 3EI/L^3 = 500) pushed down at
// its tip by 100, 200, ... 500 in five increments onto two GAPUNI: gap 11 (clearance 0.15) to a
// node on a spring of 500, gap 12 (clearance 0.35) to a fixed node, and gap 13 (clearance 5)
// at the clamped end, which never closes. Without contact the tip would move F/500 (0.2 at the
// first increment): gap 11 closes in increment 1; then u = 0.15 + (F - 75)/1000, so gap 12
// closes in increment 3 (0.375 > 0.35) and ends carrying 500 - 500 x 0.35 - 500 x 0.2 = 225,
// more than gap 11's 100.
const char* const kDeck =
    "*NODE\n1, 0, 0, 0\n2, 100, 0, 0\n3, 100, -1, 0\n4, 100, -2, 0\n5, 0, -1, 0\n"
    "*ELEMENT, TYPE=B31, ELSET=BEAM\n1, 1, 2\n*ELEMENT, TYPE=GAPUNI, ELSET=G11\n11, 2, 3\n"
    "*ELEMENT, TYPE=GAPUNI, ELSET=G12\n12, 2, 4\n*ELEMENT, TYPE=GAPUNI, ELSET=FAR\n13, 1, 5\n"
    "*ELSET, ELSET=GAPS\nG11, G12, FAR\n*ELEMENT, TYPE=SPRING1, ELSET=SP\n21, 3\n"
    "*SPRING, ELSET=SP\n2\n500.\n*MATERIAL, NAME=M\n*ELASTIC\n200000., 0.3\n"
    "*BEAM SECTION, ELSET=BEAM, MATERIAL=M, SECTION=RECT\n10., 10.\n0., 0., -1.\n"
    "*GAP, ELSET=G11\n0.15, 0., -1., 0.\n*GAP, ELSET=G12\n0.35, 0., -1., 0.\n"
    "*GAP, ELSET=FAR\n5., 0., -1., 0.\n"
    "*BOUNDARY\n1, ENCASTRE\n3, 1, 1\n3, 3, 6\n4, 1, 6\n5, 1, 6\n"
    "*STEP\n*STATIC, DIRECT\n0.2, 1.\n*CLOAD\n2, 2, -500.\n*EL PRINT, ELSET=GAPS\nE\n*END STEP\n";

TEST(RunReport, DataOfTheRun) {
  const JobResult r = test::run_deck(kDeck, true);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  const std::string html = slurp(test::test_dir() / "job.report.html");
  EXPECT_NE(html.find("Chart.js v"), std::string::npos); // the library is inlined
  const json d = page_data(html);
  ASSERT_EQ(d["gaps"].size(), 3u); // fewer gaps than kMostLoaded: all of them
  ASSERT_EQ(d["contact_set"].size(), 5u);
  const int closed[5] = {1, 1, 2, 2, 2};
  for (int k = 0; k < 5; ++k) {
    EXPECT_NEAR(d["contact_set"][k][0].get<double>(), 0.2 * (k + 1), 1e-12);
    EXPECT_EQ(d["contact_set"][k][1].get<int>(), closed[k]) << "increment " << k + 1;
  }
  EXPECT_EQ(d["attempts"].size(), static_cast<std::size_t>(r.run.stats.attempts));
  // most loaded first
  EXPECT_EQ(d["gaps"][0]["label"], "12 (GAPUNI)");
  EXPECT_EQ(d["gaps"][1]["label"], "11 (GAPUNI)");
  EXPECT_EQ(d["gaps"][2]["label"], "13 (GAPUNI)");
  // every sample as the run's own gap records (floats on the page)
  ASSERT_EQ(r.frames.size(), 5u);
  const Label labels[3] = {12, 11, 13};
  for (int g = 0; g < 3; ++g) {
    const json& h = d["gaps"][g];
    ASSERT_EQ(h["time"].size(), 5u);
    for (int k = 0; k < 5; ++k) {
      const GapRecord& rec = test::gap(r, r.frames[k], labels[g]);
      EXPECT_NEAR(h["force"][k].get<double>(), rec.normal_force, 1e-6 * 500);
      EXPECT_NEAR(h["clearance"][k].get<double>(), rec.clearance, 1e-7);
      EXPECT_EQ(h["status"][k].get<int>(), static_cast<int>(rec.status));
    }
  }
  EXPECT_EQ(d["gaps"][0]["status"][1], 0); // gap 12 open in increment 2, closed in 3
  EXPECT_EQ(d["gaps"][0]["status"][2], 1);
  EXPECT_NEAR(d["gaps"][0]["force"][4].get<double>(), 225.0, 5.0); // shear flexibility of B31
  for (const json& p : d["time_split"]) EXPECT_GE(p[1].get<double>(), 0.0);
}

TEST(RunReport, NamedGapsAndBadNames) {
  const auto deck = test::write_deck(kDeck);
  JobOptions o;
  o.deck = deck;
  o.quiet = true;
  o.report_gaps = {"13", "g11", "G12"};
  JobResult r = run_job(o);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  const json d = page_data(slurp(test::test_dir() / "job.report.html"));
  ASSERT_EQ(d["gaps"].size(), 3u);
  EXPECT_EQ(d["gaps"][0]["label"], "13 (GAPUNI)"); // in the order named
  EXPECT_TRUE(d["named"].get<bool>());
  o.report_gaps = {"1"};
  r = run_job(o);
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("--report-gaps 1: element 1 is a B31, not a gap element"),
            std::string::npos)
      << r.error;
  o.report_gaps = {"NOSUCH"};
  r = run_job(o);
  EXPECT_EQ(r.exit_code, kExitInputError);
  EXPECT_NE(r.error.find("neither an element label nor an element set"), std::string::npos)
      << r.error;
}

TEST(RunReport, ChromiumDrawsEveryPlot) {
  if (std::system("command -v chromium > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "Chromium (Debian chromium) is not installed";
  const JobResult r = test::run_deck(kDeck, true);
  ASSERT_EQ(r.exit_code, kExitOk) << r.error;
  const auto dir = test::test_dir();
  const std::string chromium = "timeout 120 chromium --headless --no-sandbox --disable-gpu "
                               "--window-size=1200,2600 ";
  const std::string page = "file://" + (dir / "job.report.html").string();
  const std::string cmd = "cd '" + dir.string() + "' && " + chromium + "--dump-dom " + page +
                          " > dom.html 2> chromium.log && " + chromium +
                          "--screenshot=report.png " + page + " 2>> chromium.log";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(dir / "chromium.log");
  const std::string dom = slurp(dir / "dom.html");
  // gap force, clearance, status, contact set, residuals, time split
  EXPECT_NE(dom.find("data-charts=\"6\""), std::string::npos) << dom.substr(0, 2000);
  EXPECT_NE(dom.find("data-painted=\"6\""), std::string::npos) << dom.substr(0, 2000);
  EXPECT_TRUE(std::filesystem::exists(dir / "report.png"));
}

} // namespace
} // namespace gapfem
