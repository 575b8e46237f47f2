#pragma once
/// @file lexer.hpp
/// Splits an Abaqus input deck into keyword blocks: comment lines (**), keyword-line continuation
/// (trailing comma), *INCLUDE (spliced in place, nested, relative to the including file) and INPUT=
/// on data keywords (*NODE,
/// *ELEMENT, *NSET, *ELSET, *AMPLITUDE). Every keyword and data line keeps its
/// file and line number.
#include "io/inp/diagnostics.hpp"
#include "io/inp/keyword.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace gapfem::inp {

/// The longest line read (characters, without the line end); a longer one is an input error.
constexpr std::size_t kMaxLineLength = 65536;
/// The most deck text read for one job, the main deck and all its *INCLUDE and INPUT= files.
constexpr std::uintmax_t kMaxDeckBytes = std::uintmax_t{2} << 30;

/// The lexed deck: the files read (index = DataLine::file; [0] is the main deck) and the keywords
/// in deck order (*INCLUDE keywords are resolved and do not appear).
struct Deck {
  std::vector<std::string> files;
  std::vector<Keyword> keywords;
};

/// Lexes a deck file. Problems (missing include files, data before the first keyword, malformed
/// keyword lines) are reported to `diag`; a main deck that cannot be read throws InputError.
Deck lex_file(const std::filesystem::path& deck, Diagnostics& diag);

/// Lexes deck text held in memory. `name` is used as the file name in messages;
/// *INCLUDE and INPUT= paths are relative to `base_dir` (the current directory
/// when empty).
Deck lex_string(std::string_view text, const std::string& name,
                const std::filesystem::path& base_dir, Diagnostics& diag);

/// Splits a data line at commas into trimmed fields (see DataLine).
DataLine split_data_line(std::string_view text);

} // namespace gapfem::inp
