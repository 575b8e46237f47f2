// DatWriter: Abaqus-style printed tables (*NODE PRINT / *EL PRINT), self-checks
// and summary, on the hand-built model of writer_fixture.hpp.
//
// Column layout (docs/results.md, after Abaqus .dat files): node rows are the
// label right-aligned in columns 1-11, a 4-column foot-note field, then
// 12-column value fields (first one columns 16-27); element rows are the label
// in columns 1-12, the point in 13-16, 7 blanks, then value fields from column
// 24 (24-35, 36-47, ...). Values are 1P E-format with 4 decimals.
#include "output/dat_writer.hpp"
#include "solver/thermal_step.hpp"
#include "writer_fixture.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace gapfem {
namespace {

using namespace testing_output;

std::vector<std::string> run_dat(const Model& m, const std::filesystem::path& dir) {
  DatWriter w(dir / "wt.dat");
  run_standard(w, m);
  return read_lines(dir / "wt.dat");
}

/// Index of the first line at or after `from` containing `text`, or -1.
int find_line(const std::vector<std::string>& lines, std::string_view text, int from = 0) {
  for (int i = std::max(from, 0); i < static_cast<int>(lines.size()); ++i)
    if (lines[i].find(text) != std::string::npos) return i;
  return -1;
}

int count_lines(const std::vector<std::string>& lines, std::string_view text) {
  return static_cast<int>(std::count_if(lines.begin(), lines.end(), [&](const std::string& l) {
    return l.find(text) != std::string::npos;
  }));
}

/// Field `k` (0-based) of a node row: 12 columns starting at column 16
/// (1-based).
std::string node_field(const std::string& row, int k) {
  return row.substr(15 + 12 * k, 12);
}
/// Field `k` of an element row: 12 columns starting at column 24.
std::string elem_field(const std::string& row, int k) {
  return row.substr(23 + 12 * k, 12);
}
std::string e12(double v) {
  return fmt::format(" {:>11.4E}", v);
}

TEST(OutputDat, StepAndIncrementHeadings) {
  const auto lines = run_dat(make_model(), fresh_dir());
  EXPECT_GE(find_line(lines, "Writer test: cube with a gap"), 0);
  EXPECT_GE(find_line(lines, "S T E P    1     S T A T I C   A N A L Y S I S"), 0);
  // Both frames had something due.
  EXPECT_EQ(count_lines(lines, "INCREMENT     1 SUMMARY"), 1);
  EXPECT_EQ(count_lines(lines, "INCREMENT     2 SUMMARY"), 1);
  const int i1 = find_line(lines, "INCREMENT     1 SUMMARY");
  // Increment 1: dt 0.5, fraction 0.5 of the period 1.0, step and total time
  // 0.5.
  EXPECT_EQ(lines[find_line(lines, "TIME INCREMENT COMPLETED", i1)],
            " TIME INCREMENT COMPLETED  5.0000E-01,  FRACTION OF STEP "
            "COMPLETED  5.0000E-01");
  EXPECT_EQ(lines[find_line(lines, "STEP TIME COMPLETED", i1)],
            " STEP TIME COMPLETED       5.0000E-01,  TOTAL TIME COMPLETED      "
            "  5.0000E-01");
  EXPECT_GE(find_line(lines, "E L E M E N T   O U T P U T"), 0);
  EXPECT_GE(find_line(lines, "N O D E   O U T P U T"), 0);
}

TEST(OutputDat, NodeTableColumnsAndSummaryRows) {
  const auto lines = run_dat(make_model(), fresh_dir());
  // Second frame (increment 2, load fraction 1): the TOP table with U.
  const int inc2 = find_line(lines, "INCREMENT     2 SUMMARY");
  const int t = find_line(lines, "FOR NODES BELONGING TO NODE SET TOP", inc2);
  ASSERT_GE(t, 0);
  const std::string& header = lines[t + 2];
  EXPECT_EQ(header.find("NODE FOOT-"), 7u);
  EXPECT_EQ(header.find("U1"), 20u); // column 21, as in Abaqus
  EXPECT_EQ(header.find("U2"), 32u);
  EXPECT_EQ(header.find("U3"), 44u);
  EXPECT_EQ(lines[t + 3], "            NOTE");
  // Rows for labels 50, 60, 70, 80 in ascending order; U = disp(label, 1).
  const std::vector<Label> top = {50, 60, 70, 80};
  for (std::size_t k = 0; k < top.size(); ++k) {
    const std::string& row = lines[t + 5 + k];
    EXPECT_EQ(row.substr(0, 11), fmt::format("{:>11}", top[k]));
    const Vec3 u = disp(top[k], 1.0);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(node_field(row, c), e12(u[c])) << row;
  }
  // U1 = 1e-3 * label: maximum 8.0000E-02 at node 80, minimum 5.0000E-02 at
  // node 50. U2 = -2e-3 * label: maximum at node 50, minimum at node 80.
  const int mx = find_line(lines, " MAXIMUM", t);
  ASSERT_EQ(mx, t + 10);
  EXPECT_EQ(node_field(lines[mx], 0), e12(0.08));
  EXPECT_EQ(node_field(lines[mx], 1), e12(-0.1));
  EXPECT_EQ(lines[mx + 1].substr(0, 8), " AT NODE");
  EXPECT_EQ(node_field(lines[mx + 1], 0), fmt::format("{:>12}", 80));
  EXPECT_EQ(node_field(lines[mx + 1], 1), fmt::format("{:>12}", 50));
  const int mn = find_line(lines, " MINIMUM", t);
  EXPECT_EQ(node_field(lines[mn], 0), e12(0.05));
  EXPECT_EQ(node_field(lines[mn + 1], 0), fmt::format("{:>12}", 50));
  // TOTALS=YES: U1 total = 1e-3 * (50 + 60 + 70 + 80) = 0.26.
  const int tot = find_line(lines, " TOTAL", t);
  ASSERT_GT(tot, mn);
  EXPECT_EQ(node_field(lines[tot], 0), e12(0.26));

  // The RF table of the same request follows: top nodes carry no reaction.
  const int rf = find_line(lines, "FOR NODES BELONGING TO NODE SET TOP", t + 1);
  ASSERT_GE(rf, 0);
  EXPECT_EQ(lines[rf + 2].find("RF1"), 20u);
}

TEST(OutputDat, TotalsOnlyPrintsTheTotalRowAlone) {
  Model m = make_model();
  m.steps[0].node_prints[0].totals_only = true; // TOTALS=ONLY (reader: summary off)
  m.steps[0].node_prints[0].summary = false;
  const auto lines = run_dat(m, fresh_dir());
  const int inc2 = find_line(lines, "INCREMENT     2 SUMMARY");
  const int t = find_line(lines, "FOR NODES BELONGING TO NODE SET TOP", inc2);
  ASSERT_GE(t, 0);
  // header, then straight to the total (1e-3 * (50 + 60 + 70 + 80) = 0.26): no rows, no summary
  const int tot = find_line(lines, " TOTAL", t);
  ASSERT_GT(tot, t);
  EXPECT_EQ(node_field(lines[tot], 0), e12(0.26));
  for (int i = t + 4; i < tot; ++i) EXPECT_TRUE(lines[i].empty()) << lines[i];
}

TEST(OutputDat, AllNodesTableOnlyWhenDueAndInLabelOrder) {
  const auto lines = run_dat(make_model(), fresh_dir());
  // Request 1 (all nodes, FREQUENCY=0) is due only at the last increment.
  EXPECT_EQ(count_lines(lines, "THE FOLLOWING TABLE IS PRINTED FOR ALL NODES"), 1);
  const int t = find_line(lines, "THE FOLLOWING TABLE IS PRINTED FOR ALL NODES");
  ASSERT_GT(t, find_line(lines, "INCREMENT     2 SUMMARY"));
  // Node 5 was defined last but has the smallest label: it comes first.
  EXPECT_EQ(lines[t + 5].substr(0, 11), fmt::format("{:>11}", 5));
  EXPECT_EQ(lines[t + 6].substr(0, 11), fmt::format("{:>11}", 10));
  EXPECT_EQ(lines[t + 13].substr(0, 11), fmt::format("{:>11}", 80));
  // Default SUMMARY=YES, TOTALS=NO.
  EXPECT_EQ(lines[t + 15].substr(0, 8), " MAXIMUM");
  const int next_table = find_line(lines, "THE FOLLOWING TABLE", t + 1);
  const int tot = find_line(lines, " TOTAL", t);
  EXPECT_TRUE(tot < 0 || (next_table >= 0 && tot > next_table));
}

TEST(OutputDat, ElementTablesByTypeAtIntegrationPoints) {
  const auto lines = run_dat(make_model(), fresh_dir());
  const int t = find_line(lines, "THE FOLLOWING TABLE IS PRINTED AT THE INTEGRATION POINTS FOR "
                                 "ELEMENT TYPE C3D8 AND ELEMENT SET ALL");
  ASSERT_GE(t, 0);
  const std::string& header = lines[t + 2];
  EXPECT_EQ(header.find("ELEMENT  PT FOOT-"), 4u);
  EXPECT_EQ(header.find("S11"), 28u); // column 29, as in Abaqus
  EXPECT_EQ(header.find("S23"), 28u + 5 * 12);
  // 8 rows: element 7, points 1..8; S_c at point p = 10*(p+1) + c (load
  // fraction 1).
  for (int p = 0; p < 8; ++p) {
    const std::string& row = lines[t + 5 + p];
    EXPECT_EQ(row.substr(0, 16), fmt::format("{:>12}{:>4}", 7, p + 1));
    for (int c = 0; c < 6; ++c) EXPECT_EQ(elem_field(row, c), e12(c3d8_stress(p, c))) << row;
  }
  // Maximum S11 = 80 (point 8), minimum 10 (point 1), both in element 7.
  const int mx = find_line(lines, " MAXIMUM", t);
  ASSERT_EQ(mx, t + 14);
  EXPECT_EQ(elem_field(lines[mx], 0), e12(80.0));
  EXPECT_EQ(lines[mx + 1].substr(0, 8), " ELEMENT");
  EXPECT_EQ(elem_field(lines[mx + 1], 0), fmt::format("{:>12}", 7));
  EXPECT_EQ(elem_field(lines[find_line(lines, " MINIMUM", t)], 0), e12(10.0));

  // Same request: the E table of C3D8 and then the GAPUNI tables (element types
  // in order).
  const int e_table = find_line(lines, "ELEMENT TYPE C3D8 AND ELEMENT SET ALL", t + 1);
  ASSERT_GT(e_table, t);
  EXPECT_EQ(lines[e_table + 2].find("E11"), 28u);
  const int gap = find_line(lines, "ELEMENT TYPE GAPUNI AND ELEMENT SET ALL", t);
  ASSERT_GT(gap, e_table);
  EXPECT_EQ(lines[gap + 2].find("S11"), 28u);
  EXPECT_EQ(lines[gap + 2].find("S12"), 40u);
  const std::string& grow = lines[gap + 5];
  EXPECT_EQ(grow.substr(0, 16), fmt::format("{:>12}{:>4}", 3, 1));
  EXPECT_EQ(elem_field(grow, 0),
            e12(50.0)); // contact pressure, positive in compression
  EXPECT_EQ(elem_field(grow, 1), e12(2.0));
}

TEST(OutputDat, CentroidalTableHasNoPointColumn) {
  const auto lines = run_dat(make_model(), fresh_dir());
  const std::string heading = "THE FOLLOWING TABLE IS PRINTED AT THE CENTROID OF THE ELEMENT FOR "
                              "ELEMENT TYPE GAPUNI AND ELEMENT SET GAPS";
  // Request 1 is due at both increments.
  EXPECT_EQ(count_lines(lines, heading), 2);
  const int t = find_line(lines, heading);
  EXPECT_EQ(lines[t + 2].find("ELEMENT     FOOT-"), 4u);
  const std::string& row = lines[t + 5];
  EXPECT_EQ(row.substr(0, 16), fmt::format("{:>12}{:>4}", 3, ""));
  EXPECT_EQ(elem_field(row, 0), e12(50.0));
  EXPECT_EQ(elem_field(row, 2), e12(0.0));
}

TEST(OutputDat, SelfChecksAndSummary) {
  const auto lines = run_dat(make_model(), fresh_dir());
  const int c = find_line(lines, "S T E P   1   S E L F - C H E C K S");
  ASSERT_GE(c, 0);
  EXPECT_GE(find_line(lines, "STEP 1 COMPLETED: 2 INCREMENTS (3 ATTEMPTS), 7 ITERATIONS", c), 0);
  const int gaps = find_line(lines, " GAP ELEMENTS", c);
  ASSERT_GE(gaps, 0);
  EXPECT_NE(lines[gaps].find(" 1"), std::string::npos);
  EXPECT_NE(lines[find_line(lines, "CLOSED, STICKING", c)].find(" 1"), std::string::npos);
  const std::string& pen = lines[find_line(lines, "MAXIMUM PENETRATION OF A CLOSED GAP", c)];
  EXPECT_NE(pen.find(e12(2.5e-7)), std::string::npos);
  EXPECT_NE(pen.find("AT ELEMENT 3"), std::string::npos);
  const std::string& rel = lines[find_line(lines, "RELATIVE ERROR", c)];
  EXPECT_NE(rel.find(e12(1e-11)), std::string::npos); // 1e-9 / force scale 100
  EXPECT_LT(find_line(lines, "HEAT BALANCE", c), 0) << "not a thermal step";
  EXPECT_LT(find_line(lines, "DAMPING", c), 0) << "no damping force";
  EXPECT_GE(find_line(lines, "A N A L Y S I S   S U M M A R Y", c), 0);
  EXPECT_NE(lines[find_line(lines, " ITERATIONS ", c + 5)].find("7"), std::string::npos);
  EXPECT_GE(find_line(lines, "*GAP: area not given; S11 is a force"), 0);
  EXPECT_EQ(lines.back(), "          THE ANALYSIS HAS BEEN COMPLETED");
}

TEST(OutputDat, FailedRunSaysSo) {
  const Model m = make_model();
  const auto dir = fresh_dir();
  DatWriter w(dir / "f.dat");
  w.begin(m);
  w.begin_step(m, 0);
  StepSummary s = make_summary();
  s.converged = false;
  s.failure = "time increment below the minimum";
  w.end_step(m, 0, s);
  RunSummary run = make_run();
  run.completed = false;
  run.failure = "step 1 did not converge";
  w.end(m, run);
  const auto lines = read_lines(dir / "f.dat");
  EXPECT_GE(find_line(lines, "STEP 1 WAS NOT COMPLETED: time increment below the minimum"), 0);
  EXPECT_GE(find_line(lines, "***ERROR: step 1 did not converge"), 0);
  EXPECT_EQ(lines.back(), "          THE ANALYSIS HAS NOT BEEN COMPLETED");
}

TEST(OutputDat, PlanarColumns) {
  const Model m = make_planar_model();
  const auto dir = fresh_dir();
  DatWriter w(dir / "p.dat");
  w.begin(m);
  w.begin_step(m, 0);
  w.frame(m, 0, make_planar_frame(m));
  w.end(m, RunSummary{});
  const auto lines = read_lines(dir / "p.dat");
  // U table: U1 U2 only, all five nodes; UR table: UR3 only, only node 9 (the one with a rotation).
  const int u = find_line(lines, "THE FOLLOWING TABLE IS PRINTED FOR ALL NODES");
  ASSERT_GE(u, 0);
  EXPECT_EQ(lines[u + 2], "       NODE FOOT-   U1          U2");
  EXPECT_EQ(lines[u + 5], fmt::format("{:>11}    {}{}", 1, e12(1.0), e12(2.0)));
  EXPECT_EQ(lines[u + 9].substr(0, 11), fmt::format("{:>11}", 9));
  const int ur = find_line(lines, "THE FOLLOWING TABLE IS PRINTED FOR ALL NODES", u + 1);
  ASSERT_GT(ur, u);
  EXPECT_EQ(lines[ur + 2], "       NODE FOOT-   UR3");
  EXPECT_EQ(lines[ur + 5], fmt::format("{:>11}    {}", 9, e12(0.01)));
  EXPECT_EQ(lines[ur + 6], "");
  EXPECT_EQ(lines[ur + 7].substr(0, 8), " MAXIMUM");
}

/// The planar model's frame with the rates of a dynamic step: V = 10 U, A = -100 U, and at node 9
/// VR3 = 0.5, AR3 = -2.
Frame planar_frame_with_rates(const Model& m) {
  Frame fr = make_planar_frame(m);
  auto& r = fr.nodes;
  r.V = r.A = r.U;
  for (std::size_t i = 0; i < r.U.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      r.V[i][c] = 10.0 * r.U[i][c];
      r.A[i][c] = -100.0 * r.U[i][c];
    }
  r.VR.assign(r.U.size(), Vec3{});
  r.AR = r.VR;
  r.VR[4] = {0.0, 0.0, 0.5};
  r.AR[4] = {0.0, 0.0, -2.0};
  return fr;
}

std::vector<std::string> run_planar_dat(const Model& m, const Frame& frame,
                                        const std::filesystem::path& dir) {
  DatWriter w(dir / "p.dat");
  w.begin(m);
  w.begin_step(m, 0);
  w.frame(m, 0, frame);
  w.end(m, RunSummary{});
  return read_lines(dir / "p.dat");
}

TEST(OutputDat, VelocityAndAccelerationTables) {
  Model m = make_planar_model();
  m.steps[0].procedure = Procedure::Dynamic;
  m.steps[0].node_prints[0].vars = {NodeVar::V, NodeVar::VR, NodeVar::A, NodeVar::AR};
  const auto lines = run_planar_dat(m, planar_frame_with_rates(m), fresh_dir());
  // V and A as U (V1 V2 in 2-D, every node), VR and AR as UR (VR3 only, node 9 only)
  const int v = find_line(lines, "NODE FOOT-   V1");
  ASSERT_GE(v, 0);
  EXPECT_EQ(lines[v], "       NODE FOOT-   V1          V2");
  EXPECT_EQ(lines[v + 3], fmt::format("{:>11}    {}{}", 1, e12(10.0), e12(20.0)));
  const int vr = find_line(lines, "NODE FOOT-   VR3", v);
  ASSERT_GT(vr, v);
  EXPECT_EQ(lines[vr], "       NODE FOOT-   VR3");
  EXPECT_EQ(lines[vr + 3], fmt::format("{:>11}    {}", 9, e12(0.5)));
  EXPECT_EQ(lines[vr + 4], "");
  const int a = find_line(lines, "NODE FOOT-   A1", vr);
  ASSERT_GT(a, vr);
  EXPECT_EQ(lines[a], "       NODE FOOT-   A1          A2");
  EXPECT_EQ(lines[a + 3], fmt::format("{:>11}    {}{}", 1, e12(-100.0), e12(-200.0)));
  const int ar = find_line(lines, "NODE FOOT-   AR3", a);
  ASSERT_GT(ar, a);
  EXPECT_EQ(lines[ar + 3], fmt::format("{:>11}    {}", 9, e12(-2.0)));
}

TEST(OutputDat, RatesOfAStepWithoutThemAreLeftOut) {
  // a static frame has no V or A: their tables are not printed (the input layer warned), and a
  // request of nothing else prints no node output at all
  Model m = make_planar_model();
  m.steps[0].node_prints[0].vars = {NodeVar::U, NodeVar::V, NodeVar::A};
  auto lines = run_planar_dat(m, make_planar_frame(m), fresh_dir());
  EXPECT_GE(find_line(lines, "NODE FOOT-   U1"), 0);
  EXPECT_EQ(find_line(lines, "V1"), -1);
  EXPECT_EQ(find_line(lines, "A1"), -1);
  EXPECT_EQ(find_line(lines, "NOTHING TO PRINT"), -1);
  EXPECT_EQ(count_lines(lines, "THE FOLLOWING TABLE IS PRINTED"), 1);
  m.steps[0].node_prints[0].vars = {NodeVar::V};
  lines = run_planar_dat(m, make_planar_frame(m), fresh_dir());
  EXPECT_EQ(find_line(lines, "N O D E   O U T P U T"), -1);
  EXPECT_EQ(find_line(lines, "INCREMENT     1 SUMMARY"), -1);
}

TEST(OutputDat, ThermalAndDampingChecks) {
  const Model m = make_model();
  const auto dir = fresh_dir();
  DatWriter w(dir / "t.dat");
  w.begin(m);
  w.begin_step(m, 0);
  StepSummary s = make_summary();
  s.checks.thermal = true;
  s.checks.reaction_flux_sum = -500.0;
  s.checks.applied_flux_sum = 500.0;
  s.checks.heat_balance_error = 1e-10;
  s.checks.heat_scale = 1000.0;
  s.checks.relative_heat_balance = 1e-13;
  s.checks.max_damping_force = 0.125;
  w.end_step(m, 0, s);
  w.end(m, make_run());
  const auto lines = read_lines(dir / "t.dat");
  const int h = find_line(lines, " HEAT BALANCE");
  ASSERT_GE(h, 0);
  EXPECT_NE(lines[find_line(lines, "SUM OF REACTION FLUXES RFL", h)].find(e12(-500.0)),
            std::string::npos);
  EXPECT_NE(lines[find_line(lines, "HEAT BALANCE ERROR", h)].find(e12(1e-10)), std::string::npos);
  // The heat scale follows the error, then the relative error 1e-10 / 1000 = 1e-13.
  const int scale = find_line(lines, "HEAT SCALE", h);
  ASSERT_EQ(scale, find_line(lines, "HEAT BALANCE ERROR", h) + 1);
  EXPECT_NE(lines[scale].find(e12(1000.0)), std::string::npos);
  ASSERT_EQ(find_line(lines, "RELATIVE ERROR", scale), scale + 1);
  EXPECT_NE(lines[scale + 1].find(e12(1e-13)), std::string::npos);
  EXPECT_NE(lines[find_line(lines, "MAXIMUM DAMPING FORCE IN A GAP")].find(e12(0.125)),
            std::string::npos);
}

TEST(OutputDat, HeatBalanceWithoutScaleHasNoRelativeError) {
  const Model m = make_model();
  const auto dir = fresh_dir();
  DatWriter w(dir / "t.dat");
  w.begin(m);
  w.begin_step(m, 0);
  StepSummary s = make_summary();
  s.checks.thermal = true; // nothing flows: heat scale 0
  w.end_step(m, 0, s);
  w.end(m, make_run());
  const auto lines = read_lines(dir / "t.dat");
  const int scale = find_line(lines, "HEAT SCALE", find_line(lines, " HEAT BALANCE"));
  ASSERT_GE(scale, 0);
  EXPECT_EQ(lines[scale + 1].substr(lines[scale + 1].size() - 3), "N/A");
}

/// The incrementation lines of the step header of a one-step run of `step`.
std::vector<std::string> step_header(Model m, const Step& step) {
  m.steps = {step};
  const auto dir = fresh_dir();
  DatWriter w(dir / "h.dat");
  w.begin(m);
  w.begin_step(m, 0);
  w.end(m, make_run());
  const auto lines = read_lines(dir / "h.dat");
  const int from = find_line(lines, "S T E P    1");
  const int to = find_line(lines, "TIME PERIOD IS", from);
  return {lines.begin() + from, lines.begin() + to + 1};
}

TEST(OutputDat, StepHeaderNamesFixedIncrements) {
  const Model m = make_model();
  Step base = m.steps[0];
  base.inc.initial = 0.25;
  auto has = [](const std::vector<std::string>& h, std::string_view text) {
    return find_line(h, text) >= 0;
  };
  struct Case {
    const char* what;
    Procedure procedure;
    bool steady_state, direct;
    double deltmx;
    bool fixed;
  };
  const Case cases[] = {
      {"static, automatic", Procedure::Static, true, false, 0.0, false},
      {"static, DIRECT", Procedure::Static, true, true, 0.0, true},
      {"steady heat transfer", Procedure::HeatTransfer, true, false, 0.0, false},
      {"transient heat transfer without DELTMX", Procedure::HeatTransfer, false, false, 0.0, true},
      {"transient heat transfer with DELTMX", Procedure::HeatTransfer, false, false, 5.0, false},
      {"transient coupled without DELTMX", Procedure::CoupledTempDisp, false, false, 0.0, true},
      {"transient coupled with DELTMX", Procedure::CoupledTempDisp, false, false, 5.0, false},
      {"steady coupled", Procedure::CoupledTempDisp, true, false, 0.0, false},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    Step st = base;
    st.procedure = c.procedure;
    st.inc.steady_state = c.steady_state;
    st.inc.direct = c.direct;
    st.inc.deltmx = c.deltmx;
    // The writer's rule is the analysis's (solver/thermal_step.hpp) plus DIRECT.
    EXPECT_EQ(DatWriter::fixed_increments(st), c.direct || fixed_transient_increments(st));
    EXPECT_EQ(DatWriter::fixed_increments(st), c.fixed);
    const auto h = step_header(m, st);
    EXPECT_EQ(has(h, "FIXED TIME INCREMENTS"), c.fixed);
    EXPECT_EQ(has(h, "AUTOMATIC TIME CONTROL"), !c.fixed);
    if (c.fixed) {
      // the size of every increment: the initial increment 0.25
      const int inc = find_line(h, "TIME INCREMENT IS");
      ASSERT_GE(inc, 0);
      EXPECT_NE(h[inc].find("2.5000E-01"), std::string::npos) << h[inc];
      EXPECT_FALSE(has(h, "MAXIMUM TIME INCREMENT"));
    } else {
      EXPECT_TRUE(has(h, "INITIAL TIME INCREMENT"));
    }
  }
}

// A step that stops early hands its last converged increment over again as the final frame
// (last_in_step, dt 0). Increment 1 of the fixture printed node request 0 (TOP: U and RF tables)
// and element request 1 (GAPS); the repeat prints only what was not printed yet: node request 1
// (all nodes) and element request 0 (ALL).
TEST(OutputDat, RepeatedFinalFramePrintsOnlyTheMissingTables) {
  const Model m = make_model();
  const auto dir = fresh_dir();
  DatWriter w(dir / "r.dat");
  w.begin(m);
  w.begin_step(m, 0);
  w.frame(m, 0, make_frame(m, 1, 0.5, false));
  Frame again = make_frame(m, 1, 0.5, true);
  again.dt = 0.0;
  w.frame(m, 0, again);
  StepSummary s = make_summary();
  s.converged = false;
  w.end_step(m, 0, s);
  w.end(m, make_run());
  const auto lines = read_lines(dir / "r.dat");
  ASSERT_EQ(count_lines(lines, "INCREMENT     1 SUMMARY"), 2);
  const int second =
      find_line(lines, "INCREMENT     1 SUMMARY", find_line(lines, "INCREMENT     1 SUMMARY") + 1);
  // The repeat's header keeps the increment's size and says why it is there.
  EXPECT_EQ(lines[find_line(lines, "TIME INCREMENT COMPLETED", second)],
            " TIME INCREMENT COMPLETED  5.0000E-01,  FRACTION OF STEP COMPLETED  5.0000E-01");
  EXPECT_GE(find_line(lines, "THE STEP STOPPED EARLY", second), 0);
  EXPECT_EQ(count_lines(lines, "FOR NODES BELONGING TO NODE SET TOP"), 2); // U, RF: once each
  EXPECT_LT(find_line(lines, "FOR NODES BELONGING TO NODE SET TOP", second), 0);
  EXPECT_EQ(count_lines(lines, "ELEMENT TYPE GAPUNI AND ELEMENT SET GAPS"), 1);
  EXPECT_LT(find_line(lines, "ELEMENT TYPE GAPUNI AND ELEMENT SET GAPS", second), 0);
  EXPECT_GT(find_line(lines, "PRINTED FOR ALL NODES"), second);
  EXPECT_GT(find_line(lines, "ELEMENT TYPE C3D8 AND ELEMENT SET ALL"), second);
}

TEST(OutputDat, RepeatedFinalFrameWithEverythingPrintedAddsNothing) {
  Model m = make_model();
  m.steps.push_back(m.steps[0]);
  m.steps[1].number = 2;
  const auto dir = fresh_dir();
  DatWriter w(dir / "r.dat");
  w.begin(m);
  w.begin_step(m, 0);
  Frame all_due = make_frame(m, 1, 0.5, false);
  all_due.node_print_due = {true, true};
  all_due.el_print_due = {true, true};
  w.frame(m, 0, all_due);
  Frame again = make_frame(m, 1, 0.5, true);
  again.dt = 0.0;
  w.frame(m, 0, again);
  w.end_step(m, 0, make_summary());
  // The next step starts afresh: its increment 1 is not a repeat.
  w.begin_step(m, 1);
  Frame next = make_frame(m, 1, 0.5, false);
  next.step = 2;
  w.frame(m, 1, next);
  w.end(m, make_run());
  const auto lines = read_lines(dir / "r.dat");
  EXPECT_EQ(count_lines(lines, "INCREMENT     1 SUMMARY"), 2); // step 1 once, step 2 once
  EXPECT_EQ(count_lines(lines, "PRINTED FOR ALL NODES"), 1);
  EXPECT_EQ(count_lines(lines, "THE STEP STOPPED EARLY"), 0);
  EXPECT_GE(find_line(lines, "STEP    2  INCREMENT    1"), 0);
}

} // namespace
} // namespace gapfem
