// JsonWriter: schema "gapfem.results/1" (docs/results.md) on the hand-built
// model of writer_fixture.hpp.
#include "output/json_writer.hpp"
#include "output/writers.hpp"
#include "writer_fixture.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>

namespace gapfem {
namespace {

using namespace testing_output;
using nlohmann::json;

json run_and_parse(const Model& m, const std::filesystem::path& dir) {
  JsonWriter w(dir / "wt.results.json", "wt");
  run_standard(w, m);
  return json::parse(read_file(dir / "wt.results.json")); // throws if not valid JSON
}

TEST(OutputJson, TopLevelSchemaAndModel) {
  const Model m = make_model();
  const json j = run_and_parse(m, fresh_dir());
  EXPECT_EQ(j["schema"], "gapfem.results/1");
  EXPECT_EQ(j["job"], "wt");
  EXPECT_EQ(j["heading"], m.heading);
  EXPECT_EQ(j["model"]["space"], "3D");
  EXPECT_EQ(j["model"]["nodes"], 9);
  EXPECT_EQ(j["model"]["elements"], 2);
  ASSERT_EQ(j["steps"].size(), 1u);
  const json& s = j["steps"][0];
  EXPECT_EQ(s["step"], 1);
  EXPECT_EQ(s["name"], "Load");
  EXPECT_EQ(s["procedure"], "STATIC");
  EXPECT_EQ(s["converged"], true);
  EXPECT_TRUE(s["failure"].is_null());
  EXPECT_EQ(s["increments"], 2);
  EXPECT_EQ(s["iterations"], 7);
  EXPECT_EQ(j["summary"]["completed"], true);
  EXPECT_EQ(j["summary"]["iterations"], 7);
  EXPECT_EQ(j["summary"]["factorizations"], 7);
  EXPECT_DOUBLE_EQ(j["summary"]["wall_seconds"].get<double>(), 1.25);
  ASSERT_EQ(j["summary"]["warnings"].size(), 1u);
  EXPECT_EQ(j["summary"]["warnings"][0], "*GAP: area not given; S11 is a force");
}

TEST(OutputJson, IntermediateFrameHoldsOnlyDueRequests) {
  const Model m = make_model();
  const json j = run_and_parse(m, fresh_dir());
  const json& frames = j["steps"][0]["frames"];
  ASSERT_EQ(frames.size(), 2u);
  const json& f1 = frames[0];
  EXPECT_EQ(f1["increment"], 1);
  EXPECT_DOUBLE_EQ(f1["step_time"].get<double>(), 0.5);
  EXPECT_EQ(f1["last_in_step"], false);
  // Frame 1: *NODE PRINT on NSET TOP (labels 50..80) and *EL PRINT on ELSET
  // GAPS (label 3).
  std::vector<std::string> node_keys;
  for (const auto& [k, v] : f1["nodes"].items()) node_keys.push_back(k);
  std::sort(node_keys.begin(), node_keys.end());
  EXPECT_EQ(node_keys, (std::vector<std::string>{"50", "60", "70", "80"}));
  ASSERT_EQ(f1["elements"].size(), 1u);
  EXPECT_TRUE(f1["elements"].contains("3"));
}

TEST(OutputJson, LastFrameIsCompleteWithExactValues) {
  const Model m = make_model();
  const json j = run_and_parse(m, fresh_dir());
  const json& f2 = j["steps"][0]["frames"][1];
  EXPECT_EQ(f2["last_in_step"], true);
  ASSERT_EQ(f2["nodes"].size(), 9u);
  ASSERT_EQ(f2["elements"].size(), 2u);
  // Round-trip precision: the doubles read back are bit-identical to the ones
  // handed over.
  for (Label label : kNodeLabels) {
    const json& n = f2["nodes"][std::to_string(label)];
    const Vec3 u = disp(label, 1.0);
    ASSERT_EQ(n["U"].size(), 3u) << label;
    for (int c = 0; c < 3; ++c) EXPECT_EQ(n["U"][c].get<double>(), u[c]) << label;
    EXPECT_EQ(n["RF"].size(), 3u);
    EXPECT_FALSE(n.contains("UR")) << "node without rotational DOFs";
    EXPECT_FALSE(n.contains("NT")) << "node without temperature";
  }
  EXPECT_EQ(f2["nodes"]["10"]["RF"][2].get<double>(), 25.0);
  // CF is written only where a load acts: node index 6 (label 70).
  EXPECT_EQ(f2["nodes"]["70"]["CF"][2].get<double>(), -100.0);
  EXPECT_FALSE(f2["nodes"]["10"].contains("CF"));

  const json& brick = f2["elements"]["7"];
  EXPECT_EQ(brick["type"], "C3D8");
  // S averaged over the 8 points: mean of 10*(p+1) + c over p = 10*4.5 + c.
  ASSERT_EQ(brick["S"].size(), 6u);
  for (int c = 0; c < 6; ++c) EXPECT_DOUBLE_EQ(brick["S"][c].get<double>(), 45.0 + c);
  // E: mean of 1e-4*(p+1)*(c+1) = 4.5e-4*(c+1).
  for (int c = 0; c < 6; ++c) EXPECT_NEAR(brick["E"][c].get<double>(), 4.5e-4 * (c + 1), 1e-18);
  EXPECT_FALSE(brick.contains("gap"));

  const json& el_types = j["element_types"];
  EXPECT_EQ(el_types["C3D8"]["S"],
            (std::vector<std::string>{"S11", "S22", "S33", "S12", "S13", "S23"}));
  EXPECT_EQ(el_types["GAPUNI"]["S"], (std::vector<std::string>{"S11", "S12", "S13"}));
  EXPECT_EQ(el_types["GAPUNI"]["E"], (std::vector<std::string>{"E11", "E12", "E13"}));
}

TEST(OutputJson, GapRecordFields) {
  const Model m = make_model();
  const json j = run_and_parse(m, fresh_dir());
  const json& gap_el = j["steps"][0]["frames"][1]["elements"]["3"];
  EXPECT_EQ(gap_el["type"], "GAPUNI");
  EXPECT_EQ(gap_el["S"], (std::vector<double>{50.0, 2.0, 0.0}));
  const json& g = gap_el["gap"];
  EXPECT_EQ(g["status"], "stick");
  EXPECT_EQ(g["clearance"].get<double>(), 0.0);
  EXPECT_EQ(g["normal_force"].get<double>(), 50.0);
  EXPECT_EQ(g["pressure"].get<double>(), 50.0);
  EXPECT_EQ(g["direction"], (std::vector<double>{0, 0, -1}));
  EXPECT_EQ(g["t1"], (std::vector<double>{1, 0, 0}));
  EXPECT_EQ(g["t2"], (std::vector<double>{0, 1, 0}));
  EXPECT_EQ(g["slip"], (std::vector<double>{1e-3, 0.0}));
  EXPECT_EQ(g["shear"], (std::vector<double>{2.0, 0.0}));
  EXPECT_EQ(g["friction_force"], (std::vector<double>{2.0, 0.0}));
  EXPECT_EQ(g["damping_force"].get<double>(), 0.0);
  EXPECT_FALSE(g.contains("heat_flux")) << "mechanical gap: no thermal fields";
}

TEST(OutputJson, ThermalGapHasHeatFields) {
  const Model m = make_model();
  const auto dir = fresh_dir();
  JsonWriter w(dir / "t.results.json", "t");
  w.begin(m);
  w.begin_step(m, 0);
  Frame fr = make_frame(m, 1, 1.0, true);
  fr.elements[1] = gap_result(/*thermal=*/true);
  w.frame(m, 0, fr);
  w.end_step(m, 0, make_summary());
  w.end(m, make_run());
  const json j = json::parse(read_file(dir / "t.results.json"));
  const json& g = j["steps"][0]["frames"][0]["elements"]["3"]["gap"];
  EXPECT_EQ(g["heat_flux"].get<double>(), 12.5);
  EXPECT_EQ(g["heat_flow"].get<double>(), 12.5);
  EXPECT_EQ(g["conductance"].get<double>(), 4.0);
}

TEST(OutputJson, StepChecks) {
  const Model m = make_model();
  const json j = run_and_parse(m, fresh_dir());
  const json& c = j["steps"][0]["checks"];
  EXPECT_EQ(c["gaps"]["total"], 1);
  EXPECT_EQ(c["gaps"]["stick"], 1);
  EXPECT_EQ(c["gaps"]["open"], 0);
  EXPECT_EQ(c["max_penetration"]["value"].get<double>(), 2.5e-7);
  EXPECT_EQ(c["max_penetration"]["element"], 3);
  EXPECT_TRUE(c["max_tensile_force"]["element"].is_null()) << "label 0 means no element";
  EXPECT_EQ(c["equilibrium"]["reaction_sum"], (std::vector<double>{0, 0, 100}));
  // relative error = 1e-9 / 100
  EXPECT_DOUBLE_EQ(c["equilibrium"]["relative_error"].get<double>(), 1e-11);
  EXPECT_TRUE(c["heat_balance"].is_null());
}

TEST(OutputJson, HeatBalanceWithScaleAndRelativeError) {
  const Model m = make_model();
  const auto dir = fresh_dir();
  JsonWriter w(dir / "h.results.json", "h");
  w.begin(m);
  w.begin_step(m, 0);
  StepSummary s = make_summary();
  s.checks.thermal = true;
  s.checks.reaction_flux_sum = -500.0;
  s.checks.applied_flux_sum = 500.0;
  s.checks.heat_balance_error = 1e-10;
  s.checks.heat_scale = 1000.0;
  s.checks.relative_heat_balance = 1e-13;
  w.end_step(m, 0, s);
  w.begin_step(m, 0); // a second step in which no heat flows: scale 0
  s.checks.heat_balance_error = 0.0;
  s.checks.heat_scale = 0.0;
  w.end_step(m, 0, s);
  w.end(m, make_run());
  const json j = json::parse(read_file(dir / "h.results.json"));
  const json& h = j["steps"][0]["checks"]["heat_balance"];
  EXPECT_EQ(h["error"].get<double>(), 1e-10);
  EXPECT_EQ(h["heat_scale"].get<double>(), 1000.0);
  // relative error = 1e-10 / 1000
  EXPECT_DOUBLE_EQ(h["relative_error"].get<double>(), 1e-13);
  EXPECT_TRUE(j["steps"][1]["checks"]["heat_balance"]["relative_error"].is_null());
}

// A step that stops early hands its last converged increment over again as the final frame; the
// stream cannot take back the earlier frame, so the repeat is marked and readers take the last
// frame with a given increment.
TEST(OutputJson, RepeatedFinalFrameIsMarked) {
  Model m = make_model();
  m.steps.push_back(m.steps[0]);
  m.steps[1].number = 2;
  const auto dir = fresh_dir();
  JsonWriter w(dir / "r.results.json", "r");
  w.begin(m);
  w.begin_step(m, 0);
  w.frame(m, 0, make_frame(m, 1, 0.5, false));
  Frame again = make_frame(m, 1, 0.5, true);
  again.dt = 0.0;
  w.frame(m, 0, again);
  StepSummary s = make_summary();
  s.converged = false;
  s.failure = "time increment below the minimum";
  w.end_step(m, 0, s);
  w.begin_step(m, 1);
  Frame next = make_frame(m, 1, 0.5, true);
  next.step = 2;
  w.frame(m, 1, next);
  w.end_step(m, 1, make_summary());
  w.end(m, make_run());
  const json j = json::parse(read_file(dir / "r.results.json"));
  const json& frames = j["steps"][0]["frames"];
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0]["increment"], 1);
  EXPECT_EQ(frames[0]["repeated"], false);
  EXPECT_EQ(frames[1]["increment"], 1);
  EXPECT_EQ(frames[1]["repeated"], true);
  EXPECT_EQ(frames[1]["last_in_step"], true);
  EXPECT_EQ(frames[1]["nodes"].size(), 9u) << "the repeat is complete";
  // The reader's rule: the last frame with a given increment wins.
  std::map<int, const json*> by_increment;
  for (const json& f : frames) by_increment[f["increment"].get<int>()] = &f;
  ASSERT_EQ(by_increment.size(), 1u);
  EXPECT_EQ((*by_increment[1])["last_in_step"], true);
  // Increment 1 of the next step is not a repeat.
  EXPECT_EQ(j["steps"][1]["frames"][0]["repeated"], false);
}

TEST(OutputJson, FramesWithoutDuePrintsAreSkipped) {
  const Model m = make_model();
  const auto dir = fresh_dir();
  JsonWriter w(dir / "s.results.json", "s");
  w.begin(m);
  w.begin_step(m, 0);
  Frame fr = make_frame(m, 1, 0.5, false);
  fr.node_print_due = {false, false};
  fr.el_print_due = {false, false}; // only a ParaView frame
  w.frame(m, 0, fr);
  w.frame(m, 0, make_frame(m, 2, 1.0, true));
  w.end_step(m, 0, make_summary());
  w.end(m, make_run());
  const json j = json::parse(read_file(dir / "s.results.json"));
  ASSERT_EQ(j["steps"][0]["frames"].size(), 1u);
  EXPECT_EQ(j["steps"][0]["frames"][0]["increment"], 2);
}

TEST(OutputJson, ValidWhenTheRunStopsInsideAStep) {
  const Model m = make_model();
  const auto dir = fresh_dir();
  JsonWriter w(dir / "f.results.json", "f");
  w.begin(m);
  w.begin_step(m, 0);
  Frame fr = make_frame(m, 1, 0.5, false);
  fr.nodes.U[4][0] = std::numeric_limits<double>::quiet_NaN(); // non-finite -> null
  fr.nodes.U[4][1] = std::numeric_limits<double>::infinity();
  w.frame(m, 0, fr);
  RunSummary run = make_run();
  run.completed = false;
  run.failure = "no convergence at the minimum increment";
  w.end(m, run); // no end_step: the writer closes the step itself
  const json j = json::parse(read_file(dir / "f.results.json"));
  EXPECT_EQ(j["steps"][0]["converged"], false);
  EXPECT_TRUE(j["steps"][0]["frames"][0]["nodes"]["50"]["U"][0].is_null());
  EXPECT_TRUE(j["steps"][0]["frames"][0]["nodes"]["50"]["U"][1].is_null());
  EXPECT_EQ(j["summary"]["completed"], false);
  EXPECT_EQ(j["summary"]["failure"], "no convergence at the minimum increment");
}

TEST(OutputJson, PlanarModelHasTwoDisplacementComponents) {
  const Model m = make_planar_model();
  const auto dir = fresh_dir();
  JsonWriter w(dir / "p.results.json", "p");
  w.begin(m);
  w.begin_step(m, 0);
  w.frame(m, 0, make_planar_frame(m));
  w.end_step(m, 0, StepSummary{});
  w.end(m, RunSummary{});
  const json j = json::parse(read_file(dir / "p.results.json"));
  EXPECT_EQ(j["model"]["space"], "planar");
  const json& nodes = j["steps"][0]["frames"][0]["nodes"];
  EXPECT_EQ(nodes["3"]["U"], (std::vector<double>{3.0, 6.0}));
  EXPECT_EQ(nodes["3"]["RF"].size(), 2u);
  EXPECT_FALSE(nodes["3"].contains("UR"));
  // In 2-D the only rotation is UR3.
  EXPECT_EQ(nodes["9"]["UR"], (std::vector<double>{0.01}));
  EXPECT_EQ(nodes["9"]["RM"], (std::vector<double>{0.0}));
}

TEST(OutputJson, VelocityAndAccelerationOfDynamicFrames) {
  const Model m = make_planar_model();
  auto write = [&](const Frame& frame, const std::filesystem::path& dir) {
    JsonWriter w(dir / "p.results.json", "p");
    w.begin(m);
    w.begin_step(m, 0);
    w.frame(m, 0, frame);
    w.end_step(m, 0, StepSummary{});
    w.end(m, RunSummary{});
    return json::parse(read_file(dir / "p.results.json"))["steps"][0]["frames"][0]["nodes"];
  };
  Frame fr = make_planar_frame(m);
  const auto dir = fresh_dir();
  std::filesystem::create_directories(dir / "rates");
  // without rates (a static step): no V, VR, A, AR keys
  json nodes = write(fr, dir);
  for (const char* k : {"V", "VR", "A", "AR"}) {
    EXPECT_FALSE(nodes["3"].contains(k)) << k;
    EXPECT_FALSE(nodes["9"].contains(k)) << k;
  }
  // with them: V and A like U (2 components in 2-D), VR and AR like UR ([VR3]) where UR is
  auto& r = fr.nodes;
  r.V.assign(r.U.size(), Vec3{});
  r.A = r.VR = r.AR = r.V;
  r.V[2] = {1.5, -2.5, 0.0};
  r.A[2] = {-30.0, 40.0, 0.0};
  r.VR[4] = {0.0, 0.0, 0.25};
  r.AR[4] = {0.0, 0.0, -4.0};
  nodes = write(fr, dir / "rates");
  EXPECT_EQ(nodes["3"]["V"], (std::vector<double>{1.5, -2.5}));
  EXPECT_EQ(nodes["3"]["A"], (std::vector<double>{-30.0, 40.0}));
  EXPECT_FALSE(nodes["3"].contains("VR"));
  EXPECT_EQ(nodes["9"]["VR"], (std::vector<double>{0.25}));
  EXPECT_EQ(nodes["9"]["AR"], (std::vector<double>{-4.0}));
}

TEST(OutputJson, FactoryWritesAllFiles) {
  const Model m = make_model();
  const auto dir = fresh_dir() / "sub" / "dir"; // created by the factory
  WriterOptions opt;
  opt.directory = dir;
  opt.job = "wt";
  auto writers = make_result_writers(opt);
  ASSERT_EQ(writers.size(),
            7u); // dat, json, vtu, frd (nothing without *NODE FILE), report, sta, msg
  for (auto& w : writers) w->begin(m);
  for (auto& w : writers) w->begin_step(m, 0);
  const Frame fr = make_frame(m, 1, 1.0, true);
  for (auto& w : writers) w->frame(m, 0, fr);
  for (auto& w : writers) w->end_step(m, 0, make_summary());
  for (auto& w : writers) w->end(m, make_run());
  for (const char* name : {"wt.dat", "wt.sta", "wt.msg", "wt.results.json", "wt.pvd", "wt_1_1.vtu"})
    EXPECT_TRUE(std::filesystem::exists(dir / name)) << name;
  json parsed;
  EXPECT_NO_THROW(parsed = json::parse(read_file(dir / "wt.results.json")));
  EXPECT_TRUE(parsed.contains("summary"));
}

} // namespace
} // namespace gapfem
