#include "io/inp/lexer.hpp"

#include "io/inp/deck_text.hpp"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>

namespace gapfem::inp {
namespace fs = std::filesystem;

namespace {

/// Keywords whose data lines may come from another file via INPUT=.
bool takes_input_file(std::string_view key) {
  return key == "NODE" || key == "ELEMENT" || key == "NSET" || key == "ELSET" ||
         key == "AMPLITUDE" || key == "EQUATION" || key == "MATRIX" || key == "MATRIXINPUT";
}

constexpr int kMaxIncludeDepth = 16;

bool is_comment(std::string_view line) {
  const std::string_view t = trim(line);
  return t.size() >= 2 && t[0] == '*' && t[1] == '*';
}
bool is_keyword_line(std::string_view line) {
  const std::string_view t = trim(line);
  return !t.empty() && t[0] == '*' && !(t.size() >= 2 && t[1] == '*');
}

/// A line that can continue a keyword line: it starts with a parameter name (a letter or a quote).
/// A line starting with a digit, sign or point after a keyword line that ends with a comma is taken
/// as the first data line instead.
bool is_parameter_line(std::string_view line) {
  const std::string_view t = trim(line);
  if (t.empty() || t[0] == '*') return false;
  return std::isalpha(static_cast<unsigned char>(t[0])) || t[0] == '"';
}

/// Splits at commas outside double quotes.
std::vector<std::string> split_quoted(std::string_view text) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (char c : text) {
    if (c == '"') quoted = !quoted;
    if (c == ',' && !quoted) {
      out.emplace_back();
      continue;
    }
    out.back().push_back(c);
  }
  return out;
}

std::string unquote(std::string_view v) {
  v = trim(v);
  if (v.size() >= 2 && v.front() == '"' && v.back() == '"') v = v.substr(1, v.size() - 2);
  return std::string(v);
}

/// A line as a message quotes it: at most 80 characters.
std::string excerpt(std::string_view line) {
  line = trim(line);
  return line.size() <= 80 ? std::string(line) : std::string(line.substr(0, 77)) + "...";
}

/// A data line the lexer rejected, split for the names it would define (its NUL bytes dropped).
DataLine rejected_line(std::string_view line) {
  std::string text(line);
  std::erase(text, '\0');
  return split_data_line(text);
}

/// A file with NUL bytes on this many lines or more is binary, not a deck with a few damaged lines.
constexpr std::size_t kBinaryLines = 4;

class Lexer {
 public:
  explicit Lexer(Diagnostics& diag) : _diag(diag) {}

  Deck run(std::string_view text, const std::string& name, const fs::path& dir) {
    _deck.files.push_back(name);
    _stack.push_back(identity(name));
    _shown.push_back(name);
    _bytes = text.size();
    const std::string problem = text_problem(text, name, "the deck");
    if (!problem.empty()) { // the one message: nothing of the file is read
      _diag.error(SourceLocation{name, 0, {}}, "", problem);
      return std::move(_deck);
    }
    lex_text(skip_utf8_bom(text), 0, dir, 0);
    if (_deck.keywords.empty() && _diag.n_errors() == 0)
      _diag.error(SourceLocation{name, 0, {}}, "",
                  "the deck has no keyword lines (it is empty or holds only ** comments); a deck "
                  "defines the model (*NODE, *ELEMENT, sections, materials) and at least one "
                  "*STEP");
    return std::move(_deck);
  }

 private:
  Diagnostics& _diag;
  Deck _deck;
  int _current = -1;               ///< index of the keyword receiving data lines (spans
                                   ///< *INCLUDE boundaries)
  bool _drop_data = false;         ///< after a keyword line in error: its data lines are dropped
  std::vector<std::string> _stack; ///< the files being lexed, outermost first (cycle check)
  std::vector<std::string> _shown; ///< the same files as the messages name them
  std::uintmax_t _bytes = 0;       ///< deck text read so far, all files

  /// A file's identity for the include-cycle check: its canonical path where it exists.
  static std::string identity(const fs::path& path) {
    std::error_code ec;
    const fs::path c = fs::weakly_canonical(path, ec);
    return (ec ? path.lexically_normal() : c).string();
  }

  /// Why the text of a file is not deck text at all ("" when it is): UTF-16 or UTF-32, or binary
  /// data (NUL bytes on many lines). `what` names the file in the sentence ("the deck").
  static std::string text_problem(std::string_view text, const std::string& name,
                                  std::string_view what) {
    if (const std::string enc = foreign_encoding(text); !enc.empty())
      return fmt::format("{} is {} text; gapfem reads ASCII or UTF-8 (as Abaqus does): save it "
                         "as ASCII or UTF-8 (in Notepad: Save as, Encoding UTF-8)",
                         what, enc);
    std::size_t nul_lines = 0, first = 0, line = 1;
    bool counted = false;
    for (char c : text) {
      if (c == '\n') {
        ++line;
        counted = false;
      } else if (c == '\0' && !counted) {
        counted = true;
        if (nul_lines++ == 0) first = line;
      }
    }
    if (nul_lines < kBinaryLines) return {};
    return fmt::format("{} ('{}') holds binary data, not text: {} of its lines hold NUL bytes, "
                       "the first line {}; check that this is the right file",
                       what, name, nul_lines, first);
  }

  /// Reports a line the lexer cannot take (longer than kMaxLineLength, or holding a NUL byte);
  /// true when the line is to be left out.
  bool reject(std::string_view line, int file, int lineno) {
    if (line.size() > kMaxLineLength) {
      _diag.error(loc(file, lineno), "",
                  fmt::format("the line is {} characters long; gapfem reads lines of up to {} "
                              "characters (Abaqus reads 256): break the data over several lines",
                              line.size(), kMaxLineLength));
      return true;
    }
    if (line.find('\0') != std::string_view::npos) {
      _diag.error(loc(file, lineno), "",
                  fmt::format("the line holds a NUL byte (shown as \\x00), which is not text: "
                              "'{}'; delete it (the file was damaged there, or a program wrote "
                              "binary data into it)",
                              excerpt(line)));
      return true;
    }
    return false;
  }

  SourceLocation loc(int file, int line, std::string keyword = {}) const {
    return SourceLocation{_deck.files[file], line, std::move(keyword)};
  }

  int add_file(const fs::path& path) {
    _deck.files.push_back(path.lexically_normal().string());
    return static_cast<int>(_deck.files.size()) - 1;
  }

  /// A keyword line that was rejected (reported): read for the names it would define, without
  /// further messages, and not run (Keyword::failed); its data lines stay with it.
  void add_rejected_keyword(std::string_view line, int file, int lineno) {
    std::string text(trim(line));
    std::erase(text, '\0'); // (the best guess of the names it would define)
    _diag.set_muted(true);
    Keyword kw = parse_keyword_line(text, file, lineno);
    _diag.set_muted(false);
    _drop_data = kw.key.empty() || kw.key == "INCLUDE";
    if (_drop_data) return;
    kw.failed = true;
    _deck.keywords.push_back(std::move(kw));
    _current = static_cast<int>(_deck.keywords.size()) - 1;
  }

  void lex_text(std::string_view text, int file, const fs::path& dir, int depth) {
    const auto lines = split_lines(text);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      const std::string_view line = lines[i];
      const int lineno = static_cast<int>(i) + 1;
      if (reject(line, file, lineno)) {
        if (is_keyword_line(line))
          add_rejected_keyword(line, file, lineno);
        else
          add_data_line(line, file, lineno, true);
        continue;
      }
      if (is_comment(line)) continue;
      if (!is_keyword_line(line)) {
        add_data_line(line, file, lineno, false);
        continue;
      }
      // keyword line, possibly continued on following lines (trailing comma)
      std::string full(trim(line));
      bool continuation_rejected = false;
      while (!full.empty() && full.back() == ',' && i + 1 < lines.size()) {
        std::size_t j = i + 1;
        while (j < lines.size() && is_comment(lines[j])) ++j;
        if (j >= lines.size() || !is_parameter_line(lines[j])) break;
        i = j;
        if (reject(lines[j], file, static_cast<int>(j) + 1)) {
          continuation_rejected = true;
          break;
        }
        full += ' ';
        full += trim(lines[j]);
      }
      if (continuation_rejected) {
        add_rejected_keyword(full, file, lineno);
        continue;
      }
      Keyword kw = parse_keyword_line(full, file, lineno);
      _drop_data = kw.key.empty(); // reported; its data lines would only add false errors
      if (_drop_data) continue;
      if (kw.key == "INCLUDE") {
        include(kw, dir, depth);
        continue;
      }
      _deck.keywords.push_back(std::move(kw));
      _current = static_cast<int>(_deck.keywords.size()) - 1;
      const Keyword& added = _deck.keywords.back();
      if (takes_input_file(added.key)) {
        if (const Parameter* p = added.find("INPUT")) read_data_file(*p, dir);
      }
    }
  }

  /// A data line for the current keyword; a `rejected` one (reported) is kept aside, for the
  /// names it would define.
  void add_data_line(std::string_view line, int file, int lineno, bool rejected) {
    if (_drop_data) return;
    if (_current < 0) {
      if (trim(line).empty() || rejected) return;
      _diag.error(loc(file, lineno), "",
                  "data line before the first keyword; start the deck with a keyword line such as "
                  "*HEADING");
      return;
    }
    DataLine d = rejected ? rejected_line(line) : split_data_line(line);
    d.file = file;
    d.line = lineno;
    Keyword& kw = _deck.keywords[_current];
    (rejected ? kw.rejected : kw.data).push_back(std::move(d));
  }

  Keyword parse_keyword_line(const std::string& text, int file, int lineno) {
    Keyword kw;
    kw.file = file;
    kw.line = lineno;
    auto tokens = split_quoted(std::string_view(text).substr(1));
    kw.key = canonical(tokens[0]);
    kw.name = std::string(1, '*');
    kw.name += display_upper(tokens[0]);
    kw.loc = loc(file, lineno, kw.name);
    if (kw.key.empty()) {
      _diag.error(
          loc(file, lineno), "",
          "keyword line without a keyword name; write e.g. *NODE, or start comments with **");
      return kw;
    }
    if (std::count(text.begin(), text.end(), '"') % 2 != 0) {
      _diag.error(kw.loc, "",
                  "a double quote (\") on this keyword line is not closed; a quoted name ends with "
                  "another \", as in NAME=\"Part 1\"");
      kw.failed = true; // its parameters are read without the quotes, for their names only
      std::string unquoted = text.substr(1);
      std::erase(unquoted, '"');
      tokens = split_quoted(unquoted);
    }
    for (std::size_t t = 1; t < tokens.size(); ++t) {
      const std::string_view tok = trim(tokens[t]);
      if (tok.empty()) continue;
      Parameter p;
      const auto eq = tok.find('=');
      const std::string_view pname = eq == std::string_view::npos ? tok : tok.substr(0, eq);
      p.key = canonical(pname);
      p.name = display_upper(pname);
      if (eq != std::string_view::npos) {
        p.has_value = true;
        p.value = unquote(tok.substr(eq + 1));
      }
      if (p.key.empty()) {
        _diag.error(kw.loc, "", fmt::format("parameter '{}' has no name; write NAME=value", tok));
        continue;
      }
      if (kw.find(p.key)) {
        _diag.error(kw.loc, p.name,
                    "this parameter is given twice on the keyword line; keep one of them");
        kw.failed = true; // reported: the keyword is not run (its first value names what it
        continue;         // would define)
      }
      kw.params.push_back(std::move(p));
    }
    return kw;
  }

  /// Resolves a file named by INPUT= relative to `dir`; reports a missing file at `at`.
  bool open_relative(const Parameter* p, const fs::path& dir, const SourceLocation& at,
                     fs::path& path, std::string& text) {
    if (!p || !p->has_value || p->value.empty()) {
      _diag.error(at, "", "INPUT= needs a file name; write INPUT=file.inp");
      return false;
    }
    path = dir / p->value;
    const std::string why = read_file(path, text, kMaxDeckBytes - std::min(_bytes, kMaxDeckBytes));
    if (!why.empty()) {
      _diag.error(
          at, fmt::format("INPUT={}", p->value),
          fmt::format("cannot read file '{}': {} (paths are relative to the directory of the file "
                      "that contains this line)",
                      path.lexically_normal().string(), why));
      return false;
    }
    _bytes += text.size();
    const std::string problem =
        text_problem(text, path.lexically_normal().string(), fmt::format("file '{}'", p->value));
    if (!problem.empty()) { // the one message: nothing of the file is read
      _diag.error(at, fmt::format("INPUT={}", p->value), problem);
      return false;
    }
    return true;
  }

  void include(const Keyword& kw, const fs::path& dir, int depth) {
    for (const auto& p : kw.params)
      if (p.key != "INPUT" && p.key != "PASSWORD")
        _diag.error(kw.loc, p.name, "unknown parameter of *INCLUDE; only INPUT= is supported");
    if (depth >= kMaxIncludeDepth) {
      _diag.error(kw.loc, "",
                  fmt::format("*INCLUDE nested deeper than {} levels; does a file include itself?",
                              kMaxIncludeDepth));
      return;
    }
    const Parameter* input = kw.find("INPUT");
    if (input && input->has_value && !input->value.empty()) {
      const std::string id = identity(dir / input->value);
      if (const auto it = std::find(_stack.begin(), _stack.end(), id); it != _stack.end()) {
        const auto first = static_cast<std::size_t>(it - _stack.begin());
        std::string cycle;
        for (std::size_t f = first; f < _shown.size(); ++f)
          cycle += fmt::format("{} includes ", _shown[f]);
        _diag.error(kw.loc, fmt::format("INPUT={}", input->value),
                    fmt::format("the include files form a cycle: {}{} again; remove this "
                                "*INCLUDE",
                                cycle, _shown[first]));
        return;
      }
    }
    fs::path path;
    std::string text;
    if (!open_relative(input, dir, kw.loc, path, text)) return;
    const int file = add_file(path);
    _stack.push_back(identity(path));
    _shown.push_back(path.lexically_normal().string());
    lex_text(skip_utf8_bom(text), file, path.parent_path(), depth + 1);
    _stack.pop_back();
    _shown.pop_back();
  }

  void read_data_file(const Parameter& p, const fs::path& dir) {
    Keyword& kw = _deck.keywords[_current];
    fs::path path;
    std::string text;
    if (!open_relative(&p, dir, kw.loc, path, text)) return;
    const int file = add_file(path);
    const auto lines = split_lines(skip_utf8_bom(text));
    for (std::size_t i = 0; i < lines.size(); ++i) {
      const int lineno = static_cast<int>(i) + 1;
      if (reject(lines[i], file, lineno)) {
        DataLine d = rejected_line(lines[i]);
        d.file = file;
        d.line = lineno;
        kw.rejected.push_back(std::move(d));
        continue;
      }
      if (is_comment(lines[i])) continue;
      if (is_keyword_line(lines[i])) {
        _diag.error(loc(file, lineno), "",
                    fmt::format("keyword line in a data file read by {}, INPUT=; such a file holds "
                                "data lines only (use *INCLUDE for files with keywords)",
                                kw.name));
        return;
      }
      DataLine d = split_data_line(lines[i]);
      d.file = file;
      d.line = lineno;
      kw.data.push_back(std::move(d));
    }
  }
};

} // namespace

DataLine split_data_line(std::string_view text) {
  DataLine d;
  d.text = std::string(text);
  const std::string_view t = trim(text);
  if (t.empty()) return d;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = t.find(',', start);
    if (comma == std::string_view::npos) {
      d.fields.emplace_back(trim(t.substr(start)));
      break;
    }
    d.fields.emplace_back(trim(t.substr(start, comma - start)));
    start = comma + 1;
  }
  if (t.back() == ',') {
    d.trailing_comma = true;
    d.fields.pop_back();
  }
  return d;
}

Deck lex_file(const fs::path& deck, Diagnostics& diag) {
  std::string text;
  const std::string why = read_file(deck, text, kMaxDeckBytes);
  if (!why.empty())
    throw InputError(SourceLocation{deck.string(), 0, {}}, "",
                     fmt::format("cannot read the input deck: {}", why));
  Lexer lexer(diag);
  return lexer.run(text, deck.string(), deck.parent_path());
}

Deck lex_string(std::string_view text, const std::string& name, const fs::path& base_dir,
                Diagnostics& diag) {
  Lexer lexer(diag);
  return lexer.run(text, name, base_dir);
}

} // namespace gapfem::inp
