#pragma once
/// @file keyword.hpp
/// One keyword block of an Abaqus input deck as the lexer delivers it: the keyword name, its
/// parameters (case- and blank-insensitive names) and its data lines, each with its file and line.
#include "common/error.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gapfem::inp {

/// Upper case with every blank removed: the form in which keyword and parameter names and
/// enumerated parameter values are compared ("*solid   section" and "*SOLIDSECTION" are equal).
std::string canonical(std::string_view text);
/// Upper case with runs of blanks collapsed to one and the ends trimmed ("SOLID SECTION").
std::string display_upper(std::string_view text);
/// `text` without leading and trailing blanks (spaces, tabs, CR).
std::string_view trim(std::string_view text);
/// Upper-case copy of `text` (ASCII).
std::string to_upper(std::string_view text);

/// One data line, split at commas. Fields are trimmed; empty fields ("1,,3") are kept as "".
struct DataLine {
  std::vector<std::string> fields; ///< a trailing comma does not add an empty last field
  std::string text;                ///< the line as written (CR and trailing blanks removed)
  std::int32_t file = 0;           ///< index into the deck's file list
  std::int32_t line = 0;           ///< 1-based line number in that file
  bool trailing_comma = false;     ///< the line ended with a comma (continuation of *ELEMENT data)
  /// A handler read the line (FieldReader, for_each_line, Keyword::mark_read). After a keyword's
  /// handler has run, the parser reports every line of it that is not blank and was not read:
  /// each data line belongs to a keyword that reads it (parser.cpp, report_unread_lines).
  mutable bool read = false;
  /// Bit i: field i was read as a whole number (FieldReader::integer, a node or element number).
  /// What a keyword reads is thereby known from its lines: the integer sweep test
  /// (tests/unit/io/reader_integers_test.cpp) finds every integer field this way.
  mutable std::uint64_t integer_fields = 0;

  /// True for a line without any non-empty field (blank line or only commas).
  bool empty() const;
  /// True for a line without any character but blanks (only commas is not blank).
  bool blank() const;
  /// True when field i exists and is not empty.
  bool has(std::size_t i) const { return i < fields.size() && !fields[i].empty(); }
};

/// A keyword parameter: NAME or NAME=value.
struct Parameter {
  std::string key;   ///< canonical name (upper case, no blanks), used for lookups
  std::string name;  ///< display name (upper case, single blanks), used in messages
  std::string value; ///< trimmed value with its case kept (quotes removed)
  bool has_value = false;
  /// The value was read as a whole number (int_param): see DataLine::integer_fields.
  mutable bool integer = false;
};

/// A keyword line with its parameters and the data lines that follow it.
struct Keyword {
  std::string key;  ///< canonical name, e.g. "SOLIDSECTION"
  std::string name; ///< display name with the star, e.g. "*SOLID SECTION"
  std::vector<Parameter> params;
  std::vector<DataLine> data;
  std::int32_t file = 0;
  std::int32_t line = 0;
  SourceLocation loc; ///< file, line and display name of the keyword line
  /// The keyword line itself is in error (reported by the lexer): the keyword is not run, only
  /// the names it would define are noted, so that their uses raise no follow-on errors.
  bool failed = false;
  /// Data lines the lexer reported and left out of `data` (too long, NUL bytes): the keyword runs
  /// without them, and the names they would define are noted as failed definitions.
  std::vector<DataLine> rejected;

  /// Marks every data line as read: for a handler that skips its data on purpose (its definition
  /// failed and was reported, or a warning says that the data is ignored).
  void mark_read() const {
    for (const DataLine& d : data) d.read = true;
  }

  /// The parameter with this name (compared canonically), or nullptr.
  const Parameter* find(std::string_view param) const;
  /// True when the parameter is present (with or without a value).
  bool has(std::string_view param) const { return find(param) != nullptr; }
  /// The raw value of the parameter, or nullopt when it is absent.
  std::optional<std::string> value(std::string_view param) const;
};

} // namespace gapfem::inp
