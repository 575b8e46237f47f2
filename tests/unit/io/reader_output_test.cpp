// Output requests: *NODE PRINT, *EL PRINT, *OUTPUT with *NODE OUTPUT / *ELEMENT OUTPUT, and their
// carry-over from step to step.
#include "unit/io/reader_test_util.hpp"

namespace gapfem {
namespace {

using test::error_text;
using test::kTrussModel;
using test::read;

std::string step(std::string_view body, std::string_view procedure = "*STATIC") {
  return std::string(kTrussModel) + "*STEP\n" + std::string(procedure) + "\n" + std::string(body) +
         "*END STEP\n";
}
// the first line of `body` is line 13

TEST(ReaderOutput, NodePrint) {
  const Model m = read(step("*NODE PRINT\nU1, U2\nRF, NT11\n*NODE PRINT, NSET=ALL, FREQUENCY=5, "
                            "TOTALS=YES, SUMMARY=NO, GLOBAL=YES\nCF\n"));
  const auto& np = m.steps[0].node_prints;
  ASSERT_EQ(np.size(), 2u);
  EXPECT_EQ(np[0].nset, "");
  EXPECT_EQ(np[0].nodes.size(), 2u); // all nodes
  EXPECT_EQ(np[0].frequency, 1);
  EXPECT_FALSE(np[0].totals);
  EXPECT_TRUE(np[0].summary);
  EXPECT_EQ(np[0].vars, (std::vector<NodeVar>{NodeVar::U, NodeVar::RF, NodeVar::NT}));
  EXPECT_EQ(np[0].loc.line, 13);
  EXPECT_EQ(np[1].nset, "ALL");
  EXPECT_EQ(np[1].frequency, 5);
  EXPECT_TRUE(np[1].totals);
  EXPECT_FALSE(np[1].summary);
  EXPECT_EQ(np[1].vars, (std::vector<NodeVar>{NodeVar::CF}));
  const Model only = read(step("*NODE PRINT, TOTALS=ONLY\nRF\n"));
  EXPECT_TRUE(only.steps[0].node_prints[0].totals);
  EXPECT_TRUE(only.steps[0].node_prints[0].totals_only);
  EXPECT_FALSE(only.steps[0].node_prints[0].summary);
}

TEST(ReaderOutput, NodePrintErrors) {
  EXPECT_CONTAINS(error_text(step("*NODE PRINT, NSET=NONE\nU\n")),
                  "deck.inp:13: *NODE PRINT: NSET=NONE: this node set is not defined");
  EXPECT_CONTAINS(
      error_text(step("*NODE PRINT, FREQUENCY=-1\nU\n")),
      "FREQUENCY=-1: the output frequency (every n-th increment; 0: none) must be a whole "
      "number from 0 to 2147483647");
}

TEST(ReaderOutput, ElPrint) {
  const Model m =
      read(step("*EL PRINT, ELSET=TRUSS, POSITION=CENTROIDAL, FREQUENCY=0\n\nS11, E\nSF1\n"
                "*EL PRINT\nHFL\n"));
  const auto& ep = m.steps[0].el_prints;
  ASSERT_EQ(ep.size(), 2u);
  EXPECT_EQ(ep[0].elset, "TRUSS");
  EXPECT_EQ(ep[0].elements.size(), 1u);
  EXPECT_EQ(ep[0].position, ElPosition::Centroidal);
  EXPECT_EQ(ep[0].frequency, 0);
  EXPECT_EQ(ep[0].vars, (std::vector<ElemVar>{ElemVar::S, ElemVar::E, ElemVar::SF}));
  EXPECT_EQ(ep[1].position, ElPosition::IntegrationPoints);
  EXPECT_EQ(ep[1].elements.size(), 1u);

  EXPECT_EQ(read(step("*EL PRINT, POSITION=AVERAGED AT NODES\nS\n")).steps[0].el_prints[0].position,
            ElPosition::Averaged);
  EXPECT_EQ(test::count_warnings(read(step("*EL PRINT\nS, PEEQ\n")),
                                 "deck.inp:14: *EL PRINT: gapfem does not know the output "
                                 "variable PEEQ"),
            1);
  EXPECT_CONTAINS(error_text(step("*EL PRINT, ELSET=X\nS\n")),
                  "ELSET=X: this element set is not defined");
}

TEST(ReaderOutput, FieldOutputPreselectDependsOnProcedure) {
  const Model st = read(step("*OUTPUT, FIELD, VARIABLE=PRESELECT, FREQUENCY=2\n"));
  ASSERT_EQ(st.steps[0].field_outputs.size(), 1u);
  const FieldOutputRequest& f = st.steps[0].field_outputs[0];
  EXPECT_EQ(f.frequency, 2);
  EXPECT_EQ(f.node_vars, (std::vector<NodeVar>{NodeVar::U, NodeVar::RF}));
  EXPECT_EQ(f.elem_vars, (std::vector<ElemVar>{ElemVar::S, ElemVar::E}));
  // the procedure may follow *OUTPUT: PRESELECT is resolved at *END STEP
  const Model co =
      read(std::string(kTrussModel) + "*STEP\n*OUTPUT, FIELD, VARIABLE=PRESELECT\n"
                                      "*COUPLED TEMPERATURE-DISPLACEMENT\n*END STEP\n");
  EXPECT_EQ(co.steps[0].field_outputs[0].node_vars,
            (std::vector<NodeVar>{NodeVar::U, NodeVar::RF, NodeVar::NT}));
  EXPECT_EQ(co.steps[0].field_outputs[0].elem_vars,
            (std::vector<ElemVar>{ElemVar::S, ElemVar::E, ElemVar::HFL}));
  const Model all = read(step("*OUTPUT, FIELD, VARIABLE=ALL\n"));
  EXPECT_EQ(all.steps[0].field_outputs[0].node_vars.size(), 6u); // U UR RF RM CF CM
  EXPECT_EQ(all.steps[0].field_outputs[0].elem_vars.size(), 3u); // S E SF
}

TEST(ReaderOutput, NodeAndElementOutput) {
  const Model m =
      read(step("*OUTPUT, FIELD\n*NODE OUTPUT, NSET=ALL\nU, RF3, COORD\n*ELEMENT OUTPUT, "
                "DIRECTIONS=YES\nS, LE\n"));
  const FieldOutputRequest& f = m.steps[0].field_outputs.at(0);
  EXPECT_EQ(f.node_vars, (std::vector<NodeVar>{NodeVar::U, NodeVar::RF}));
  EXPECT_EQ(f.elem_vars, (std::vector<ElemVar>{ElemVar::S}));
  // unknown variables in field output only drive ParaView files: warnings with their location
  EXPECT_EQ(test::count_warnings(m, "output variable COORD"), 1);
  EXPECT_EQ(test::count_warnings(m, "deck.inp:17: *ELEMENT OUTPUT"), 1);
}

TEST(ReaderOutput, HistoryOutputRequestsAreRead) {
  // PRESELECT: the whole-model energies (Abaqus's preselected history output); *NODE OUTPUT on a
  // set: its variables at the set's nodes; *ELEMENT OUTPUT without ELSET (the whole model, which
  // Abaqus refuses for history output) is one warning and left out
  const Model m = read(step("*OUTPUT, HISTORY, VARIABLE=PRESELECT\n*NODE OUTPUT, NSET=ALL\nU\n"
                            "*OUTPUT, HISTORY, FREQUENCY=2\n*ELEMENT OUTPUT\nS\n*ENERGY OUTPUT\n"));
  ASSERT_EQ(m.steps[0].history_outputs.size(), 2u);
  EXPECT_TRUE(m.steps[0].field_outputs.empty());
  const HistoryOutputRequest& a = m.steps[0].history_outputs[0];
  EXPECT_TRUE(a.energies);
  ASSERT_EQ(a.node_vars.size(), 1u);
  EXPECT_EQ(a.node_vars[0].first, NodeVar::U);
  EXPECT_FALSE(a.node_vars[0].second.empty());
  const HistoryOutputRequest& b = m.steps[0].history_outputs[1];
  EXPECT_EQ(b.frequency, 2);
  EXPECT_TRUE(b.energies); // *ENERGY OUTPUT
  EXPECT_TRUE(b.elem_vars.empty());
  EXPECT_EQ(test::count_warnings(m, "history output needs ELSET="), 1);
}

TEST(ReaderOutput, ResultsFileRequestsForTheFrdFile) {
  const Model m =
      read(step("*NODE FILE, FREQUENCY=2, NSET=ALL\nU, RF\n*EL FILE, POSITION=CENTROIDAL\n"
                "S, E11\n"));
  ASSERT_EQ(m.steps[0].file_outputs.size(), 2u);
  const FileOutputRequest& n = m.steps[0].file_outputs[0];
  EXPECT_FALSE(n.element);
  EXPECT_EQ(n.frequency, 2);
  EXPECT_EQ(n.set, "ALL");
  EXPECT_EQ(n.node_vars, (std::vector<NodeVar>{NodeVar::U, NodeVar::RF}));
  const FileOutputRequest& e = m.steps[0].file_outputs[1];
  EXPECT_TRUE(e.element);
  EXPECT_TRUE(e.set.empty());
  EXPECT_EQ(e.elem_vars, (std::vector<ElemVar>{ElemVar::S, ElemVar::E}));
  // the frd holds nodal values only: CENTROIDAL is told it is written averaged at the nodes
  EXPECT_EQ(test::count_warnings(m, "deck.inp:15: *EL FILE: POSITION=CENTROIDAL"), 1);
  EXPECT_TRUE(m.steps[0].node_prints.empty());
}

// docs/keywords.md, "Output requests never stop a run": what gapfem cannot write is a warning and
// the rest of the request is honoured
TEST(ReaderOutput, UnknownVariablesAreLeftOutWithAWarning) {
  const Model m = read(step("*NODE PRINT\nU, COORD\n*EL PRINT\nS, PEEQ, CENT\n*NODE FILE\nU, "
                            "SXX\n*EL FILE\nS, SF, NFORC\n*EL PRINT\nXYZ\n"));
  const Step& st = m.steps[0];
  ASSERT_EQ(st.node_prints.size(), 1u);
  EXPECT_EQ(st.node_prints[0].vars, (std::vector<NodeVar>{NodeVar::U}));
  ASSERT_EQ(st.el_prints.size(), 1u); // the request of XYZ alone writes nothing: dropped
  EXPECT_EQ(st.el_prints[0].vars, (std::vector<ElemVar>{ElemVar::S}));
  ASSERT_EQ(st.file_outputs.size(), 2u);
  EXPECT_EQ(st.file_outputs[0].node_vars, (std::vector<NodeVar>{NodeVar::U}));
  EXPECT_EQ(st.file_outputs[1].elem_vars, (std::vector<ElemVar>{ElemVar::S}));
  EXPECT_EQ(test::count_warnings(m, "deck.inp:14: *NODE PRINT: gapfem does not know the output "
                                    "variable COORD"),
            1);
  EXPECT_EQ(test::count_warnings(m, "output variable PEEQ"), 1);
  EXPECT_EQ(test::count_warnings(m, "output variable CENT"), 1);
  EXPECT_EQ(test::count_warnings(m, "output variable SXX"), 1);
  EXPECT_EQ(test::count_warnings(m, "section forces (SF) are not written to job.frd"), 1);
  EXPECT_EQ(test::count_warnings(m, "element nodal forces (NFORC) are not written to job.frd"), 1);
  EXPECT_EQ(test::count_warnings(m, "*EL PRINT lists no output variable gapfem writes"), 1);
}

TEST(ReaderOutput, RequestsWithoutDataLinesWriteTheDefaults) {
  // CalculiX's defaults: U at the nodes, S in the elements
  const Model m = read(step("*NODE PRINT, NSET=ALL\n*EL PRINT\n*NODE FILE\n*EL FILE\n"));
  const Step& st = m.steps[0];
  ASSERT_EQ(st.node_prints.size(), 1u);
  EXPECT_EQ(st.node_prints[0].vars, (std::vector<NodeVar>{NodeVar::U}));
  ASSERT_EQ(st.el_prints.size(), 1u);
  EXPECT_EQ(st.el_prints[0].vars, (std::vector<ElemVar>{ElemVar::S}));
  ASSERT_EQ(st.file_outputs.size(), 2u);
  EXPECT_EQ(st.file_outputs[0].node_vars, (std::vector<NodeVar>{NodeVar::U}));
  EXPECT_EQ(st.file_outputs[1].elem_vars, (std::vector<ElemVar>{ElemVar::S}));
  EXPECT_TRUE(m.warnings.empty());
}

TEST(ReaderOutput, AbaqusAndCalculixSpellingsOfOutputParameters) {
  const Model m = read(step("*EL PRINT, POSITION=INTEGRATION POINT\nS\n*EL FILE, NSET=ALL\nS\n"
                            "*EL PRINT, POSITION=NODES\nE\n"));
  const Step& st = m.steps[0];
  ASSERT_EQ(st.el_prints.size(), 2u);
  EXPECT_EQ(st.el_prints[0].position, ElPosition::IntegrationPoints);
  EXPECT_EQ(st.el_prints[1].position, ElPosition::Averaged);
  EXPECT_EQ(test::count_warnings(m, "POSITION=NODES"), 1);
  ASSERT_EQ(st.file_outputs.size(), 1u);
  EXPECT_EQ(st.file_outputs[0].set, "ALL");
  EXPECT_EQ(st.file_outputs[0].members.size(), 1u); // the truss: both its nodes are in ALL
  EXPECT_EQ(test::count_warnings(m, "NSET=ALL on *EL FILE (CalculiX)"), 1);
  EXPECT_CONTAINS(error_text(step("*EL FILE, NSET=ALL, ELSET=TRUSS\nS\n")),
                  "give ELSET= or NSET= on *EL FILE, not both");
}

TEST(ReaderOutput, OutputParametersGapfemLacksAreWarnings) {
  const Model m = read(step("*OUTPUT, FIELD, NUMBER INTERVAL=10, TIME MARKS=YES\n*NODE OUTPUT\nU\n"
                            "*OUTPUT, VARIABLE=PRESELECT\n*OUTPUT, FIELD, HISTORY\n*NODE OUTPUT\n"
                            "RF\n*NODE PRINT, NOSUCH=1\nU\n"));
  const Step& st = m.steps[0];
  EXPECT_EQ(st.field_outputs.size(), 3u);
  EXPECT_EQ(test::count_warnings(m, "deck.inp:13: *OUTPUT: NUMBER INTERVAL on *OUTPUT is not "
                                    "supported by gapfem"),
            1);
  EXPECT_EQ(test::count_warnings(m, "TIME MARKS on *OUTPUT"), 1);
  EXPECT_EQ(test::count_warnings(m, "neither is given: it was read as a field output request"), 1);
  EXPECT_EQ(test::count_warnings(m, "both are given: it was read as a field output request"), 1);
  EXPECT_EQ(test::count_warnings(m, "NOSUCH"), 1);
  ASSERT_EQ(st.node_prints.size(), 1u);
}

TEST(ReaderOutput, OutputErrors) {
  EXPECT_CONTAINS(error_text(step("*NODE OUTPUT\nU\n")),
                  "deck.inp:13: *NODE OUTPUT: *NODE OUTPUT must follow *OUTPUT");
}

TEST(ReaderOutput, EmptyFieldRequestIsDroppedWithWarning) {
  const Model m = read(step("*OUTPUT, FIELD\n"));
  EXPECT_TRUE(m.steps[0].field_outputs.empty());
  EXPECT_EQ(test::count_warnings(m, "has no variables"), 1);
}

TEST(ReaderOutput, RequestsCarryOverUntilAStepGivesItsOwn) {
  const Model m = read(std::string(kTrussModel) + R"(*STEP
*STATIC
*NODE PRINT
U
*EL PRINT
S
*OUTPUT, FIELD, VARIABLE=PRESELECT
*END STEP
*STEP
*STATIC
*END STEP
*STEP
*STATIC
*NODE PRINT, FREQUENCY=3
RF
*END STEP
)");
  ASSERT_EQ(m.steps.size(), 3u);
  // step 2 has no requests: all three kinds carry over
  EXPECT_EQ(m.steps[1].node_prints.size(), 1u);
  EXPECT_EQ(m.steps[1].node_prints[0].vars, (std::vector<NodeVar>{NodeVar::U}));
  EXPECT_EQ(m.steps[1].el_prints.size(), 1u);
  EXPECT_EQ(m.steps[1].field_outputs.size(), 1u);
  // step 3 gives a *NODE PRINT: it replaces the previous node prints only
  ASSERT_EQ(m.steps[2].node_prints.size(), 1u);
  EXPECT_EQ(m.steps[2].node_prints[0].vars, (std::vector<NodeVar>{NodeVar::RF}));
  EXPECT_EQ(m.steps[2].node_prints[0].frequency, 3);
  EXPECT_EQ(m.steps[2].el_prints.size(), 1u);
  EXPECT_EQ(m.steps[2].field_outputs.size(), 1u);
}

} // namespace
} // namespace gapfem
