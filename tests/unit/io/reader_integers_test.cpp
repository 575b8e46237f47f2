// Every integer field and parameter the reader knows is read as an exact whole number with a
// range check (issue 43): 2^31, 2^32, 2^63, 1e20 and -1 in any of them are one clear message at
// its line, never a number wrapped to 32 bits or a silently dropped request.
//
// The sweep finds the integer fields itself, so that a keyword added later cannot be missed: it
// reads every deck of the repository (the verification decks, the examples and the bad-input
// corpus) and notes each field and parameter a keyword read as a whole number
// (DataLine::integer_fields, Parameter::integer). Each one is then rewritten with each bad value
// and the deck read again.
#include "io/inp/keyword.hpp"
#include "io/inp/lexer.hpp"
#include "io/inp/parser.hpp"
#include "unit/io/reader_test_util.hpp"

#include <fstream>
#include <map>
#include <regex>
#include <sstream>

namespace gapfem {
namespace {

namespace fs = std::filesystem;

/// One integer field (field >= 0) or parameter (field < 0) of a keyword in a deck.
struct Site {
  fs::path deck;
  int line = 0;                  ///< the line of the field, or of the keyword line
  int field = -1;                ///< 0-based field of the data line
  std::string param;             ///< the parameter's display name
  bool deck_reads_clean = false; ///< the deck as it is reads without an input error
};

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// A correct deck with the integer parameters and fields that the repository's .inp decks do not
/// all use (most of its decks live inside the C++ tests).
constexpr std::string_view kCatalogue = R"(*HEADING
integer fields and parameters
*NODE, NSET=ALL
1, 0., 0., 0.
2, 1., 0., 0.
3, 2., 0., 0.
*NSET, NSET=GEN, GENERATE
1, 3, 1
*ELEMENT, TYPE=B31, ELSET=BEAMS
1, 1, 2
2, 2, 3
*ELSET, ELSET=EGEN, GENERATE
1, 2, 1
*NODE
101, 2., 0., -0.01
11, 0., 0., 1.
12, 1., 0., 1.
13, 1., 1., 1.
14, 0., 1., 1.
15, 0., 0., 2.
16, 1., 0., 2.
17, 1., 1., 2.
18, 0., 1., 2.
*ELEMENT, TYPE=C3D8, ELSET=BRICK
11, 11, 12, 13, 14, 15, 16, 17, 18
*SOLID SECTION, ELSET=BRICK, MATERIAL=STEEL
*ELEMENT, TYPE=GAPUNI, ELSET=GAPS
201, 3, 101
*GAP, ELSET=GAPS
0.01, 0., 0., -1., 1.
*MATERIAL, NAME=STEEL
*ELASTIC, DEPENDENCIES=0
200000., 0.3
*DENSITY
7.85E-9
*BEAM SECTION, ELSET=BEAMS, MATERIAL=STEEL, SECTION=CIRC
0.05
0., 1., 0.
*EQUATION
2
3, 6, 1., 2, 6, -1.
*BOUNDARY
1, 1, 6
101, 1, 3
*RESTART, WRITE, FREQUENCY=5
*STEP, INC=50
*STATIC
0.5, 1.
*CONTROLS, PARAMETERS=TIME INCREMENTATION
4, , , 10, 12, 5, 8, 6
*CLOAD
3, 2, -10.
*DLOAD
1, GRAV, 9810., 0., 0., -1.
*CONTACT INTERFERENCE, TYPE=ELEMENT
201, 0.0001
*MONITOR, NODE=3, DOF=2, FREQUENCY=1
*NODE PRINT, NSET=ALL, FREQUENCY=2
U
*EL PRINT, ELSET=BEAMS, FREQUENCY=2
S
1
*NODE FILE, FREQUENCY=2
U
*EL FILE, FREQUENCY=2
S
*OUTPUT, FIELD, FREQUENCY=2
*NODE OUTPUT
U
*END STEP
)";

/// The same for heat transfer.
constexpr std::string_view kHeatCatalogue = R"(*HEADING
integer fields of heat transfer
*NODE, NSET=ALL
1, 0.
2, 1.
*ELEMENT, TYPE=DC1D2, ELSET=ROD
1, 1, 2
*MATERIAL, NAME=CU
*CONDUCTIVITY
400.
*SOLID SECTION, ELSET=ROD, MATERIAL=CU
1.
*INITIAL CONDITIONS, TYPE=TEMPERATURE
1, 20.
*STEP
*HEAT TRANSFER, STEADY STATE
1., 1.
*BOUNDARY
1, 11, 11, 20.
*CFLUX
2, 11, 5.
*FILM
1, F1, 15., 10.
*END STEP
)";

std::vector<fs::path> repository_decks() {
  std::vector<fs::path> out;
  const fs::path dir = test::fresh_dir();
  test::write_file(dir / "catalogue.inp", kCatalogue);
  test::write_file(dir / "heat_catalogue.inp", kHeatCatalogue);
  out.push_back(dir / "catalogue.inp");
  out.push_back(dir / "heat_catalogue.inp");
  for (const fs::path root : {fs::path(GAPFEM_TEST_DIR), fs::path(GAPFEM_SOURCE_DIR) / "examples"})
    for (const auto& e : fs::recursive_directory_iterator(root))
      if (e.path().extension() == ".inp" &&
          e.path().string().find("/bad_input/include/") == std::string::npos)
        out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

bool reads_clean(const fs::path& deck) {
  try {
    read_deck(deck);
  } catch (const InputError&) {
    return false;
  }
  return true;
}

/// Reads `deck` through the parser and adds the integer fields and parameters of its own lines
/// (not those of included files) to `sites`, keyed "*KEYWORD field n" / "*KEYWORD PARAM".
void discover(const fs::path& deck, std::map<std::string, std::vector<Site>>& sites) {
  inp::Diagnostics diag;
  const ReadOptions opts;
  inp::Deck lexed;
  try {
    lexed = inp::lex_file(deck, diag);
  } catch (const InputError&) {
    return;
  }
  inp::BuildState state(opts, diag);
  state.model.source_files = lexed.files;
  try {
    inp::parse_deck(lexed, state);
  } catch (const inp::TooManyErrors&) {
  } catch (const InputError&) {
  }
  const bool clean = diag.n_errors() == 0 && reads_clean(deck);
  auto add = [&](std::string key, Site site) {
    site.deck = deck;
    site.deck_reads_clean = clean;
    auto& list = sites[std::move(key)]; // a few occurrences, the clean ones first
    const auto n_clean =
        std::count_if(list.begin(), list.end(), [](const Site& s) { return s.deck_reads_clean; });
    if (clean && n_clean < 2)
      list.insert(list.begin() + n_clean, std::move(site));
    else if (!clean && list.size() - n_clean < 6)
      list.push_back(std::move(site));
  };
  for (const inp::Keyword& kw : lexed.keywords) {
    if (kw.file != 0) continue;
    for (const inp::Parameter& p : kw.params)
      if (p.integer) add(kw.name + " " + p.name, Site{{}, kw.line, -1, p.name});
    for (const inp::DataLine& line : kw.data)
      for (int i = 0; i < 64 && line.file == 0; ++i)
        if (line.integer_fields & (std::uint64_t{1} << i))
          add(fmt::format("{} field {}", kw.name, i + 1), Site{{}, line.line, i, {}});
  }
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

/// The deck text with the site's value replaced by `value` ("" when the site is not found).
std::string rewrite(const Site& site, const std::string& value) {
  std::vector<std::string> lines = lines_of(read_text(site.deck));
  if (site.field >= 0) {
    std::string& l = lines.at(static_cast<std::size_t>(site.line - 1));
    std::vector<std::string> fields(1);
    for (char c : l)
      if (c == ',')
        fields.emplace_back();
      else
        fields.back().push_back(c);
    fields.at(static_cast<std::size_t>(site.field)) = " " + value;
    l.clear();
    for (std::size_t i = 0; i < fields.size(); ++i) l += (i ? "," : "") + fields[i];
  } else {
    // NAME=value on the keyword line or a continuation of it (blanks in names are optional)
    std::string name;
    for (char c : site.param)
      if (c != ' ') name += std::string(name.empty() ? "" : "\\s*") + c;
    const std::regex re("(" + name + "\\s*=\\s*)(\"[^\"]*\"|[^,]*)", std::regex::icase);
    bool found = false;
    for (std::size_t k = site.line - 1; k < lines.size() && k < site.line + 4u && !found; ++k) {
      std::smatch m;
      if (!std::regex_search(lines[k], m, re)) continue;
      lines[k] = m.prefix().str() + m[1].str() + value + m.suffix().str();
      found = true;
    }
    if (!found) return {};
  }
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

/// The messages of reading `text` (as the deck of `site`) that name the site's line.
std::vector<std::string> messages_at(const Site& site, const std::string& text) {
  std::vector<std::string> out;
  try {
    read_deck_string(text, site.deck.filename().string(), {}, site.deck.parent_path());
  } catch (const InputError& e) {
    const std::string at = fmt::format("{}:{}:", site.deck.filename().string(), site.line);
    for (const std::string& l : lines_of(e.what()))
      if (l.find(at) != std::string::npos && l.find("the deck has ") == std::string::npos)
        out.push_back(l);
  }
  return out;
}

/// A message that says the value is not a whole number of the field's range, in its own words.
bool clear_range_message(const std::string& message, const std::string& value) {
  if (inp::to_upper(message).find(inp::to_upper(value)) == std::string::npos) return false;
  // (in a field for a number or a name, a number written as a real (1e20) is a name)
  for (const char* phrase :
       {"whole number", "out of range", "is not available", "DOF", "within 1-6", "Simpson",
        "node position", "is not defined", "is not a node number", "does not know"})
    if (message.find(phrase) != std::string::npos) return true;
  return false;
}

/// The message that `value` at the site gives in the first deck where it is clear; "" when it
/// is clear (a deck whose own mistake is on that line may show another message first).
std::string unclear_message(const std::vector<Site>& candidates, const std::string& value) {
  std::string first;
  for (const Site& site : candidates) {
    const std::string text = rewrite(site, value);
    if (text.empty()) continue;
    const std::vector<std::string> found = messages_at(site, text);
    for (const std::string& m : found)
      if (clear_range_message(m, value)) return {};
    if (first.empty())
      first = fmt::format("{}:{}: {}", site.deck.filename().string(), site.line,
                          found.empty() ? "read without an error at the line" : found.front());
  }
  return first.empty() ? "no deck to rewrite" : first;
}

TEST(ReaderIntegers, EveryIntegerFieldAndParameterIsRangeChecked) {
  std::map<std::string, std::vector<Site>> sites;
  for (const fs::path& deck : repository_decks()) discover(deck, sites);
  // the sweep must have found the integer fields the issue names (and it finds more)
  for (const char* key : {"*STEP INC", "*NODE field 1", "*ELEMENT field 1", "*ELEMENT field 2",
                          "*NODE PRINT FREQUENCY", "*EL PRINT FREQUENCY", "*NODE FILE FREQUENCY",
                          "*OUTPUT FREQUENCY", "*RESTART FREQUENCY", "*BOUNDARY field 2",
                          "*CLOAD field 2", "*NSET field 3", "*CONTROLS field 1"})
    EXPECT_TRUE(sites.count(key)) << "no deck of the repository has an integer " << key;
  EXPECT_GE(sites.size(), 60u);
  std::string all;
  for (const auto& [key, list] : sites) all += key + "; ";
  RecordProperty("integer_sites", all);

  for (const auto& [key, candidates] : sites) {
    SCOPED_TRACE(key);
    for (const char* value : {"-1", "2147483648", "4294967296", "9223372036854775808", "1e20"}) {
      const std::string unclear = unclear_message(candidates, value);
      EXPECT_TRUE(unclear.empty()) << value << ": " << unclear;
    }
    // 0: a value some fields take (FREQUENCY=0: no output); where refused, said as clearly
    const Site& site = candidates.front();
    const std::vector<std::string> zero = messages_at(site, rewrite(site, "0"));
    if (site.deck_reads_clean && !zero.empty())
      EXPECT_TRUE(clear_range_message(zero.front(), "0")) << zero.front();
  }
}

} // namespace
} // namespace gapfem
