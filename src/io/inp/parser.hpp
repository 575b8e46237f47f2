#pragma once
/// @file parser.hpp
/// Dispatches the lexed keywords to their handlers through one table (keyword → handler, where it
/// may appear, its parameters, the block it belongs to) and applies the reader's policies: unknown
/// keywords and parameters, sub-option attachment, model vs history data.
#include "io/inp/lexer.hpp"
#include "io/inp/model_builder.hpp"

#include <span>
#include <string_view>

namespace gapfem::inp {

/// Where a keyword may appear.
enum class Where : std::uint8_t { Model, History, Both };

/// One row of the keyword table.
struct KeywordSpec {
  std::string_view name; ///< display name with the star, e.g. "*SOLID SECTION"
  void (*handler)(BuildState&, const Keyword&);
  Where where;
  std::string_view params; ///< accepted parameters, display names separated by
                           ///< '|'; "*" = any
  unsigned parents = 0;    ///< sub-option: bit mask of the Parent blocks it may follow (0: none)
  Parent opens = Parent::None; ///< block this keyword starts (its sub-options follow it)
};

/// The keyword table (for docs and tests).
std::span<const KeywordSpec> keyword_table();

/// Runs all keywords of `deck` through their handlers into `s` (errors go to s.diag).
void parse_deck(Deck& deck, BuildState& s);

} // namespace gapfem::inp
