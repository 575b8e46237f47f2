// General input-deck syntax: case and blank insensitivity, comments, commas, CRLF, Fortran
// numbers, continuation lines, *INCLUDE, INPUT=, GENERATE, sets in data lines.
#include "io/inp/fields.hpp"
#include "io/inp/lexer.hpp"
#include "io/inp/parser.hpp"
#include "io/inp/spelling.hpp"
#include "unit/io/reader_test_util.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <random>
#include <set>

namespace gapfem {
namespace {

using test::error_text;
using test::kTrussModel;
using test::read;

std::vector<Label> labels(const Model& m, const std::vector<NodeId>& nodes) {
  std::vector<Label> out;
  for (NodeId n : nodes) out.push_back(m.node_label(n).key);
  std::sort(out.begin(), out.end());
  return out;
}
std::vector<Label> elem_labels(const Model& m, const std::vector<ElemId>& elems) {
  std::vector<Label> out;
  for (ElemId e : elems) out.push_back(m.element_label(e).key);
  std::sort(out.begin(), out.end());
  return out;
}

TEST(ReaderSyntax, FortranNumbersAreAccepted) {
  using inp::parse_real;
  EXPECT_EQ(parse_real("1.E6"), 1e6);
  EXPECT_EQ(parse_real("1.0D3"), 1000.0);
  EXPECT_EQ(parse_real("2.5d-1"), 0.25);
  EXPECT_EQ(parse_real("-.5"), -0.5);
  EXPECT_EQ(parse_real("+2"), 2.0);
  EXPECT_EQ(parse_real("5."), 5.0);
  EXPECT_EQ(parse_real(" 3e+2 "), 300.0);
  for (const char* bad : {"", ".", "e5", "1.2.3", "1e", "1,5", "abc", "1.0x", "--1", "1e5.0"})
    EXPECT_FALSE(parse_real(bad).has_value()) << bad;
  EXPECT_EQ(inp::parse_integer("+12"), 12);
  EXPECT_EQ(inp::parse_integer("-3"), -3);
  for (const char* bad : {"", "1.", "1e3", "x1", "+"})
    EXPECT_FALSE(inp::parse_integer(bad).has_value()) << bad;
}

TEST(ReaderSyntax, FortranNumbersInDeck) {
  const Model m = read("*NODE\n1, 1.E2, 1.0D1, -.5\n2, +2, 0, 0\n");
  EXPECT_EQ(m.mesh.coords[0][0], 100.0);
  EXPECT_EQ(m.mesh.coords[0][1], 10.0);
  EXPECT_EQ(m.mesh.coords[0][2], -0.5);
  EXPECT_EQ(m.mesh.coords[1][0], 2.0);
}

TEST(ReaderSyntax, BadNumberNamesFieldLineAndKeyword) {
  const std::string e = error_text("*NODE\n1, 0, 0, 0\n2, 1, 1.2.3, 0\n");
  EXPECT_CONTAINS(e, "deck.inp:3");
  EXPECT_CONTAINS(e, "*NODE");
  EXPECT_CONTAINS(e, "field 3 (y)");
  EXPECT_CONTAINS(e, "'1.2.3' is not a number");
}

TEST(ReaderSyntax, KeywordsAndParametersIgnoreCaseAndBlanks) {
  const Model m = read(R"(*node, nset = all
1, 0, 0, 0
2, 1, 0, 0
*Element, Type = t3d2, ELSET = truss
1, 1, 2
*material, name=Steel
*elastic
200000., 0.3
*solid   section, elset=TRUSS, material=steel
)");
  ASSERT_EQ(m.mesh.n_elements(), 1);
  EXPECT_EQ(m.mesh.elem_types[0], ElementType::T3D2);
  EXPECT_EQ(m.nsets.count("ALL"), 1u);
  EXPECT_EQ(m.elsets.count("TRUSS"), 1u);
  EXPECT_EQ(m.materials[0].name, "STEEL");
  EXPECT_EQ(m.element_property[0].kind, PropertyRef::Kind::Solid);
  EXPECT_EQ(m.solid_sections[0].material, 0);
}

TEST(ReaderSyntax, CommentsAnywhereAndBlankLines) {
  const Model m = read(R"(** leading comment
*NODE
** between data lines
1, 0, 0, 0

   ** indented comment
2, 1, 0, 0
*ELEMENT, TYPE=T3D2,
** comment inside a continued keyword line
ELSET=TRUSS
1, 1, 2
*MATERIAL, NAME=STEEL
*ELASTIC
200000., 0.3
*SOLID SECTION, ELSET=TRUSS, MATERIAL=STEEL
)");
  EXPECT_EQ(m.mesh.n_nodes(), 2);
  EXPECT_EQ(m.elsets.at("TRUSS").size(), 1u);
}

TEST(ReaderSyntax, TrailingCommasAndEmptyFieldsMeanDefaults) {
  const Model m = read("*NODE\n1, 1.,, 3.,\n2,\n3, , 2.\n");
  EXPECT_EQ(m.mesh.coords[0], (Vec3{1.0, 0.0, 3.0}));
  EXPECT_EQ(m.mesh.coords[1], (Vec3{0.0, 0.0, 0.0}));
  EXPECT_EQ(m.mesh.coords[2], (Vec3{0.0, 2.0, 0.0}));
}

TEST(ReaderSyntax, WindowsLineEndsAndTrailingBlanks) {
  std::string deck(kTrussModel);
  std::string crlf;
  for (char c : deck) {
    if (c == '\n') crlf += "   \t\r";
    crlf += c;
  }
  crlf += "*STEP  \r\n*STATIC\r\n0.5, 1.\r\n*END STEP\r\n";
  const Model m = read(crlf);
  ASSERT_EQ(m.steps.size(), 1u);
  EXPECT_EQ(m.steps[0].inc.initial, 0.5);
  EXPECT_EQ(m.mesh.coords[1][0], 1.0);
}

TEST(ReaderSyntax, KeywordLineContinuedWithTrailingComma) {
  const Model m = read("*NODE,\n NSET=A\n1, 0, 0, 0\n*NSET, NSET=B,\nUNSORTED\n1\n");
  EXPECT_EQ(m.nsets.at("A").size(), 1u);
  EXPECT_EQ(m.nsets.at("B").size(), 1u);
}

TEST(ReaderSyntax, KeywordLineEndingWithCommaBeforeDataLine) {
  // a line starting with a number cannot hold parameters: it is the first data line
  const Model m = read("*NODE, NSET=A,\n1, 0, 0, 0\n*NSET, NSET=B,\n1\n");
  EXPECT_EQ(m.mesh.n_nodes(), 1);
  EXPECT_EQ(m.nsets.at("A").size(), 1u);
  EXPECT_EQ(m.nsets.at("B").size(), 1u);
}

TEST(ReaderSyntax, ElementDataContinuedAfterTrailingComma) {
  const Model m = read(R"(*NODE
1, 0, 0, 0
2, 1, 0, 0
3, 1, 1, 0
4, 0, 1, 0
5, 0, 0, 1
6, 1, 0, 1
7, 1, 1, 1
8, 0, 1, 1
*ELEMENT, TYPE=C3D8, ELSET=B
100, 1, 2, 3, 4,
5, 6,
7, 8
*MATERIAL, NAME=M
*ELASTIC
1000., 0.25
*SOLID SECTION, ELSET=B, MATERIAL=M
)");
  ASSERT_EQ(m.mesh.n_elements(), 1);
  const auto nodes = m.mesh.element_nodes(0);
  ASSERT_EQ(nodes.size(), 8u);
  EXPECT_EQ(m.node_label(nodes[7]).key, 8);
  EXPECT_EQ(m.mesh.elem_src[0].line, 11); // the element's first line
}

TEST(ReaderSyntax, NsetDataWithTrailingCommasOverSeveralLines) {
  const Model m = read("*NODE\n1\n2\n3\n4\n*NSET, NSET=S\n1, 2,\n3,\n");
  EXPECT_EQ(labels(m, m.nsets.at("S")), (std::vector<Label>{1, 2, 3}));
}

TEST(ReaderSyntax, NestedIncludesRelativeToIncludingFile) {
  const auto dir = test::fresh_dir();
  test::write_file(dir / "main.inp", "*HEADING\nmain\n*INCLUDE, INPUT=parts/mesh.inp\n"
                                     "*NSET, NSET=LAST\n3\n");
  // parts/mesh.inp includes nodes.inp from its own directory (parts/)
  test::write_file(dir / "parts" / "mesh.inp",
                   "*NODE\n1, 0, 0, 0\n*INCLUDE, INPUT=more/Nodes.inp\n");
  test::write_file(dir / "parts" / "more" / "Nodes.inp", "** data lines only: they continue *NODE\n"
                                                         "2, 1, 0, 0\n3, 2, 0, 0\n");
  const Model m = read_deck(dir / "main.inp");
  EXPECT_EQ(m.mesh.n_nodes(), 3);
  EXPECT_EQ(m.nsets.at("LAST").size(), 1u);
  ASSERT_EQ(m.source_files.size(), 3u);
  EXPECT_EQ(m.source_files[0], (dir / "main.inp").string());
  EXPECT_CONTAINS(m.source_files[2], "Nodes.inp"); // file names keep their case
}

TEST(ReaderSyntax, LocationsInIncludedFilesNameThatFile) {
  const auto dir = test::fresh_dir();
  test::write_file(dir / "main.inp", "*NODE\n1\n*INCLUDE, INPUT=elems.inp\n");
  test::write_file(dir / "elems.inp", "*ELEMENT, TYPE=T3D2\n\n7, 1, 99\n");
  try {
    read_deck(dir / "main.inp");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_CONTAINS(e.what(), "elems.inp:3: *ELEMENT: element 7: node 99 is not defined");
    EXPECT_EQ(e.location().line, 3);
  }
}

TEST(ReaderSyntax, MissingIncludeNamesTheIncludingLine) {
  const auto dir = test::fresh_dir();
  test::write_file(dir / "main.inp", "*HEADING\nx\n*INCLUDE, INPUT=nothere.inp\n");
  try {
    read_deck(dir / "main.inp");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_CONTAINS(e.what(), "main.inp:3");
    EXPECT_CONTAINS(e.what(), "*INCLUDE");
    EXPECT_CONTAINS(e.what(), "INPUT=nothere.inp");
    EXPECT_CONTAINS(e.what(), "cannot read file");
  }
}

TEST(ReaderSyntax, MissingMainDeckIsAnInputError) {
  EXPECT_THROW(read_deck(test::fresh_dir() / "absent.inp"), InputError);
}

TEST(ReaderSyntax, SelfIncludeStopsWithError) {
  const auto dir = test::fresh_dir();
  test::write_file(dir / "loop.inp", "*INCLUDE, INPUT=loop.inp\n");
  try {
    read_deck(dir / "loop.inp");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_CONTAINS(e.what(), "the include files form a cycle");
    EXPECT_CONTAINS(e.what(), "loop.inp:1");
  }
}

TEST(ReaderSyntax, InputParameterReadsDataLinesFromFile) {
  const auto dir = test::fresh_dir();
  test::write_file(dir / "nodes.txt", "1, 0, 0, 0\n2, 1, 0, 0\n** comment\n3, 2, 0, 0\n");
  test::write_file(dir / "sub" / "elems.txt", "1, 1, 2\n2, 2, 3\n");
  test::write_file(dir / "sub" / "set.txt", "1, 3\n");
  test::write_file(dir / "eset.txt", "2\n");
  test::write_file(dir / "main.inp", R"(*NODE, INPUT=nodes.txt
*ELEMENT, TYPE=T3D2, INPUT=sub/elems.txt, ELSET=ALL
*NSET, NSET=ENDS, INPUT=sub/set.txt
*ELSET, ELSET=SECOND, INPUT=eset.txt
*MATERIAL, NAME=M
*ELASTIC
1., 0.
*SOLID SECTION, ELSET=ALL, MATERIAL=M
)");
  const Model m = read_deck(dir / "main.inp");
  EXPECT_EQ(m.mesh.n_nodes(), 3);
  EXPECT_EQ(m.mesh.n_elements(), 2);
  EXPECT_EQ(labels(m, m.nsets.at("ENDS")), (std::vector<Label>{1, 3}));
  EXPECT_EQ(elem_labels(m, m.elsets.at("SECOND")), (std::vector<Label>{2}));
  // the element location points into the data file
  EXPECT_CONTAINS(m.element_location(1).str(), "elems.txt:2");
}

TEST(ReaderSyntax, InputFileMustHoldDataLinesOnly) {
  const auto dir = test::fresh_dir();
  test::write_file(dir / "nodes.txt", "1, 0, 0, 0\n*NODE\n2\n");
  test::write_file(dir / "main.inp", "*NODE, INPUT=nodes.txt\n");
  try {
    read_deck(dir / "main.inp");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_CONTAINS(e.what(), "nodes.txt:2");
    EXPECT_CONTAINS(e.what(), "data lines only");
  }
}

TEST(ReaderSyntax, GenerateWithAndWithoutIncrement) {
  const Model m = read(R"(*NODE
1
3
5
7
8
*NSET, NSET=ODD, GENERATE
1, 7, 2
*NSET, NSET=ONE, GENERATE
7, 8
*NSET, NSET=GAPPY, GENERATE
1, 8
)");
  EXPECT_EQ(labels(m, m.nsets.at("ODD")), (std::vector<Label>{1, 3, 5, 7}));
  EXPECT_EQ(labels(m, m.nsets.at("ONE")), (std::vector<Label>{7, 8}));
  // labels in the range that do not exist are left out with one warning
  EXPECT_EQ(labels(m, m.nsets.at("GAPPY")), (std::vector<Label>{1, 3, 5, 7, 8}));
  EXPECT_EQ(test::count_warnings(m, "left out"), 1);
}

TEST(ReaderSyntax, LongGenerateRangesAgainstTheirDefinition) {
  // A range longer than the model has nodes is resolved from the nodes (so a typo such as
  // 1, 15056603 costs the model's size, not the range's): random ranges, short and long, give the
  // members and the count of missing numbers the definition (every number of the range, in order)
  // gives.
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> label(1, 400), first(1, 60), step(1, 7);
  for (int trial = 0; trial < 40; ++trial) {
    std::set<Label> defined;
    while (defined.size() < 30) defined.insert(label(rng));
    std::string deck = "*NODE\n";
    for (Label l : defined) deck += std::to_string(l) + "\n";
    const long long f = first(rng), st = step(rng);
    const long long last = trial % 2 ? f + st * (rng() % 10) : f + st * 2000000 + rng() % 3;
    deck += "*NSET, NSET=R, GENERATE\n" + std::to_string(f) + ", " + std::to_string(last) + ", " +
            std::to_string(st) + "\n";
    std::vector<Label> expected;
    long long missing = 0, first_missing = 0;
    for (long long l = f; l <= last; l += st)
      if (defined.count(l))
        expected.push_back(l);
      else if (missing++ == 0)
        first_missing = l;
    const Model m = read(deck);
    SCOPED_TRACE(deck.substr(deck.rfind('*')));
    EXPECT_EQ(labels(m, m.nsets.at("R")), expected);
    if (missing)
      EXPECT_EQ(test::count_warnings(m, std::to_string(missing) +
                                            " node number(s) of the GENERATE "
                                            "ranges of set R are not defined (the first is " +
                                            std::to_string(first_missing) + ")"),
                1);
  }
}

TEST(ReaderSyntax, GenerateBadRangesAreErrors) {
  const std::string base = "*NODE\n1\n2\n";
  EXPECT_CONTAINS(error_text(base + "*NSET, NSET=A, GENERATE\n5, 1\n"),
                  "deck.inp:5: *NSET: range 5-1");
  EXPECT_CONTAINS(error_text(base + "*NSET, NSET=A, GENERATE\n1, 5, 0\n"),
                  "the increment must be a whole number from 1 to 999999999, not 0");
  EXPECT_CONTAINS(error_text(base + "*NSET, NSET=A, GENERATE\n1, 5, -1\n"), "field 3 (increment)");
  EXPECT_CONTAINS(error_text(base + "*NSET, NSET=A, GENERATE\n1, 2, 1, 4\n"), "at most 3 fields");
}

TEST(ReaderSyntax, ElsetGenerate) {
  const Model m =
      read(std::string(kTrussModel) + "*ELEMENT, TYPE=T3D2, ELSET=TRUSS\n"
                                      "5, 1, 2\n9, 2, 1\n*ELSET, ELSET=G, GENERATE\n1, 9, 4\n");
  EXPECT_EQ(elem_labels(m, m.elsets.at("G")), (std::vector<Label>{1, 5, 9}));
}

TEST(ReaderSyntax, SetNamesMixedWithLabelsAndRepeatedSetsExtend) {
  const Model m = read(R"(*NODE, NSET=FIRST
10
20
*NODE
30
40
*NSET, NSET=mixed
first, 30
*NSET, NSET=MIXED
40, 30
)");
  EXPECT_EQ(labels(m, m.nsets.at("MIXED")), (std::vector<Label>{10, 20, 30, 40}));
  // stored sorted and unique by internal index
  const auto& s = m.nsets.at("MIXED");
  EXPECT_TRUE(std::is_sorted(s.begin(), s.end()));
  EXPECT_EQ(std::adjacent_find(s.begin(), s.end()), s.end());
}

TEST(ReaderSyntax, LabelsNeedNotBeContiguous) {
  const Model m = read("*NODE\n1000, 1\n7, 2\n123456789, 3\n");
  EXPECT_EQ(m.mesh.find_node(7), 1);
  EXPECT_EQ(m.mesh.coords[m.mesh.find_node(123456789)][0], 3.0);
}

TEST(ReaderSyntax, SetNamesUsableInLoadsAndBoundaries) {
  const Model m = read(std::string(kTrussModel) + R"(*NSET, NSET=Left
1
*STEP
*STATIC
*BOUNDARY
left, 1, 3
*CLOAD
ALL, 1, 5.
*END STEP
)");
  ASSERT_EQ(m.steps.size(), 1u);
  EXPECT_EQ(m.steps[0].boundary.size(), 3u);
  EXPECT_EQ(m.steps[0].cloads.size(), 2u); // both nodes of ALL
}

TEST(ReaderSyntax, UnknownSetNameIsError) {
  const std::string e =
      error_text(std::string(kTrussModel) + "*STEP\n*STATIC\n*CLOAD\nNOSUCH, 1, 1.\n*END STEP\n");
  EXPECT_CONTAINS(e, "deck.inp:14: *CLOAD: node set NOSUCH: this node set is not defined");
}

TEST(ReaderSyntax, UnknownKeywordIsErrorOrWarning) {
  const std::string deck =
      std::string(kTrussModel) + "*INTEGRATED OUTPUT SECTION, NAME=IOS1, SURFACE=S1\n";
  // an output keyword gapfem lacks is a warning with or without --ignore-unknown
  for (const bool ignore : {false, true}) {
    const Model m = read(deck, ReadOptions{ignore});
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_CONTAINS(m.warnings[0], "deck.inp:11: *INTEGRATED OUTPUT SECTION: the keyword "
                                   "*INTEGRATED OUTPUT SECTION is not supported by gapfem and was "
                                   "ignored (it controls output only");
  }
  // print controls are read with a note, with or without the option
  const Model p = read(std::string(kTrussModel) + "*FILE FORMAT, ASCII\n*ENERGY PRINT\n");
  EXPECT_EQ(p.warnings.size(), 2u);
}

TEST(ReaderSyntax, UnknownKeywordInsideMaterialKeepsTheMaterialOpen) {
  // *PLASTIC changes the material: an error even with --ignore-unknown, and the only one (the
  // *DENSITY after it still belongs to the material)
  const std::string e = error_text(R"(*MATERIAL, NAME=M
*PLASTIC
100., 0.
*DENSITY
7.8E-9
)",
                                   ReadOptions{true});
  EXPECT_CONTAINS(e, "deck.inp:2: *PLASTIC: the keyword *PLASTIC is not supported");
  EXPECT_EQ(e.find("DENSITY"), std::string::npos) << e;
}

TEST(ReaderSyntax, UnknownParameterIsErrorOrWarning) {
  const std::string deck = "*NODE, NSET=A, COLOR=RED\n1\n";
  const std::string e = error_text(deck);
  EXPECT_CONTAINS(e, "deck.inp:1: *NODE: the parameter COLOR of *NODE is not supported");
  EXPECT_CONTAINS(error_text(deck, ReadOptions{true}), "--ignore-unknown does not skip it");
  // an output request's unknown parameter is skipped with a warning, with or without the option
  const std::string out = std::string(kTrussModel) + "*STEP\n*STATIC\n*NODE PRINT, COLOR=RED\n"
                                                     "U\n*END STEP\n";
  for (const bool ignore : {false, true}) {
    const Model m = read(out, ReadOptions{ignore});
    EXPECT_EQ(test::count_warnings(m, "the parameter COLOR of *NODE PRINT is not supported"), 1);
  }
}

TEST(ReaderSyntax, DataBeforeFirstKeywordIsError) {
  EXPECT_CONTAINS(error_text("1, 2, 3\n*NODE\n1\n"),
                  "deck.inp:1: data line before the first keyword");
}

TEST(ReaderSyntax, QuotedParameterValues) {
  const Model m = read("*NODE, NSET=\"My Set\"\n1\n");
  EXPECT_EQ(m.nsets.count("MY SET"), 1u);
}

TEST(ReaderSyntax, LexerKeepsFieldsAndTrailingComma) {
  const inp::DataLine d = inp::split_data_line(" 1 , ,3,  ");
  ASSERT_EQ(d.fields.size(), 3u);
  EXPECT_EQ(d.fields[0], "1");
  EXPECT_EQ(d.fields[1], "");
  EXPECT_EQ(d.fields[2], "3");
  EXPECT_TRUE(d.trailing_comma);
  EXPECT_TRUE(inp::split_data_line("   ").empty());
  EXPECT_TRUE(inp::split_data_line(",,").empty());
}

} // namespace
} // namespace gapfem

namespace gapfem {
namespace {

TEST(ReaderSyntax, KeywordTableIsConsistentAndDocumented) {
  std::ifstream in(std::filesystem::path(GAPFEM_SOURCE_DIR) / "docs" / "keywords.md");
  ASSERT_TRUE(in) << "docs/keywords.md is missing";
  const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::set<std::string> keys;
  for (const auto& spec : inp::keyword_table()) {
    EXPECT_NE(spec.handler, nullptr) << spec.name;
    EXPECT_TRUE(keys.insert(inp::canonical(spec.name)).second) << "duplicate " << spec.name;
    EXPECT_CONTAINS(doc, "`" + std::string(spec.name)) << "add the keyword to docs/keywords.md";
  }
}

TEST(ReaderSyntax, UnsupportedProcedureIsOneError) {
  // not followed by a false "the step has no procedure"
  const std::string e =
      error_text(std::string(kTrussModel) + "*STEP\n*VISCO\n0.1, 1.\n*END STEP\n");
  EXPECT_CONTAINS(e, "*VISCO: the procedure *VISCO is not supported by gapfem");
  EXPECT_EQ(e.find("no procedure"), std::string::npos) << e;
}

TEST(ReaderSyntax, AnUnsupportedProcedureRaisesNoFollowOnErrorOfItsStep) {
  // *MODAL DAMPING belongs to the mode-based procedure the step names, which gapfem lacks: the
  // procedure is the one error (not also "*MODAL DAMPING belongs to a mode-based step")
  const std::string e = error_text(std::string(kTrussModel) +
                                   "*STEP\n*RANDOM RESPONSE\n0.1, 1.\n*MODAL DAMPING\n,,0.02\n"
                                   "*END STEP\n");
  EXPECT_CONTAINS(e, "*RANDOM RESPONSE: the procedure *RANDOM RESPONSE is not supported by gapfem");
  EXPECT_EQ(e.find("mode-based"), std::string::npos) << e;
}

TEST(ReaderSyntax, AMisspeltKeywordOrParameterIsNamedWithWhatWasMeant) {
  // a misspelling of a keyword gapfem knows; its block's sub-options raise nothing more
  const std::string e = error_text(std::string(kTrussModel) + "*MATERAL, NAME=M2\n*ELASTIC\n1., "
                                                              "0.3\n*SURFACE BEHAVIOUR\n");
  EXPECT_CONTAINS(e, "*MATERAL: unknown keyword; did you mean *MATERIAL?");
  EXPECT_CONTAINS(e, "*SURFACE BEHAVIOUR: unknown keyword; did you mean *SURFACE BEHAVIOR?");
  EXPECT_EQ(e.find("*ELASTIC"), std::string::npos) << e;
  // a misspelling of an Abaqus keyword gapfem lacks says so
  EXPECT_CONTAINS(error_text(std::string(kTrussModel) + "*PLASTC\n100., 0.\n"),
                  "*PLASTC: unknown keyword; did you mean *PLASTIC? (*PLASTIC is an Abaqus "
                  "keyword gapfem does not support)");
  // a real Abaqus keyword is never taken for a misspelling (*PLASTIC is one letter from *ELASTIC)
  EXPECT_CONTAINS(error_text(std::string(kTrussModel) + "*PLASTIC\n100., 0.\n"),
                  "*PLASTIC: the keyword *PLASTIC is not supported by gapfem");
  // a misspelt procedure is the step's procedure: no "the step has no procedure" after it
  const std::string p = error_text(std::string(kTrussModel) + "*STEP\n*STATC\n*END STEP\n");
  EXPECT_CONTAINS(p, "*STATC: unknown keyword; did you mean *STATIC?");
  EXPECT_EQ(p.find("procedure"), std::string::npos) << p;
  // parameters: a misspelling or synonym of the keyword's own, or one of the block keyword above
  const std::string steps = std::string(kTrussModel) + "*STEP\n*STATIC\n";
  EXPECT_CONTAINS(error_text(steps + "*NODE PRINT, NODESET=ALL\nU\n*END STEP\n"),
                  "*NODE PRINT: unknown parameter NODESET; did you mean NSET?");
  EXPECT_CONTAINS(error_text(steps + "*EL PRINT, ELSTE=TRUSS\nS\n*END STEP\n"),
                  "*EL PRINT: unknown parameter ELSTE; did you mean ELSET?");
  EXPECT_CONTAINS(error_text(steps + "*OUTPUT, FIELD\n*NODE OUTPUT, FREQUENCY=2\nU\n*END STEP\n"),
                  "*NODE OUTPUT: FREQUENCY is a parameter of *OUTPUT, not of *NODE OUTPUT; give "
                  "it on the *OUTPUT line above");
  EXPECT_CONTAINS(error_text(std::string(kTrussModel) + "*MATERIAL, NAME=M2\n*DENSITY, NAME=X\n1."
                                                        "\n"),
                  "NAME is a parameter of *MATERIAL, not of *DENSITY");
  // with --ignore-unknown an output request's misspelt parameter is skipped with the same words
  const Model m = read(steps + "*NODE PRINT, NODESET=ALL\nU\n*END STEP\n", ReadOptions{true});
  EXPECT_EQ(
      test::count_warnings(m, "unknown parameter NODESET; did you mean NSET?; it was ignored"), 1);
}

TEST(ReaderSyntax, TextAfterASingleStarIsSaidToBeOne) {
  EXPECT_CONTAINS(error_text("*HEADING\n*Block on gap supports\n" + std::string(kTrussModel)),
                  "deck.inp:2: *BLOCK ON GAP SUPPORTS: unknown keyword; the *HEADING above has no "
                  "title line");
  EXPECT_CONTAINS(error_text(std::string(kTrussModel) + "* the supports of the block\n"),
                  "*THE SUPPORTS OF THE BLOCK: unknown keyword; if this line is a title or a "
                  "comment: a line starting with a single * is a keyword line");
}

TEST(ReaderSyntax, QuotedNamesInDataLines) {
  // a name in double quotes is the name inside them; an unclosed quote is named
  const std::string steps = std::string(kTrussModel) + "*STEP\n*STATIC\n";
  EXPECT_NO_THROW(read(steps + "*BOUNDARY\n\"ALL\", 1, 3\n*END STEP\n"));
  EXPECT_CONTAINS(error_text(steps + "*BOUNDARY\n\"ALL, 1, 3\n*END STEP\n"),
                  "deck.inp:14: *BOUNDARY: field 1 (\"ALL): a double quote (\") in this name is "
                  "not closed; a quoted name is enclosed in two, as in \"ALL\"");
}

TEST(ReaderSyntax, SpellingDistanceCountsSwapsAsOneMistake) {
  EXPECT_EQ(inp::spelling_distance("SOLIDSECTON", "SOLIDSECTION"), 1);
  EXPECT_EQ(inp::spelling_distance("SOLIDSECITON", "SOLIDSECTION"), 1); // two letters swapped
  EXPECT_EQ(inp::spelling_distance("PLASTIC", "ELASTIC"), 1);
  EXPECT_EQ(inp::spelling_distance("", "NSET"), 4);
  EXPECT_EQ(inp::spelling_distance("NSET", "NSET"), 0);
  EXPECT_TRUE(inp::foreign_keyword("PLASTIC"));
  EXPECT_FALSE(inp::foreign_keyword("SOLIDSECTON"));
  // a keyword --ignore-unknown skips stays skipped (it is no misspelling)
  const Model m = read(std::string(kTrussModel) + "*EQUATION PRINT\n", ReadOptions{true});
  EXPECT_EQ(test::count_warnings(m, "*EQUATION PRINT"), 1);
}

} // namespace
} // namespace gapfem
