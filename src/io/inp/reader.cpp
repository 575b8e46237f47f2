#include "io/inp/reader.hpp"

#include "io/inp/diagnostics.hpp"
#include "io/inp/lexer.hpp"
#include "io/inp/parser.hpp"

namespace gapfem {
namespace {

Model build(inp::Deck deck, const ReadOptions& opts, inp::Diagnostics& diag) {
  inp::BuildState state(opts, diag);
  state.model.source_files = deck.files;
  try {
    inp::parse_deck(deck, state);
  } catch (const inp::TooManyErrors&) {
    // the collected errors are thrown below
  }
  diag.throw_if_errors();
  state.model.warnings = diag.warnings();
  return std::move(state.model);
}

} // namespace

Model read_deck(const std::filesystem::path& deck, const ReadOptions& opts) {
  inp::Diagnostics diag;
  try {
    inp::Deck lexed = inp::lex_file(deck, diag);
    return build(std::move(lexed), opts, diag);
  } catch (const inp::TooManyErrors&) {
    diag.throw_if_errors();
    throw;
  }
}

Model read_deck_string(std::string_view text, const std::string& name, const ReadOptions& opts,
                       const std::filesystem::path& base_dir) {
  inp::Diagnostics diag;
  try {
    inp::Deck lexed = inp::lex_string(text, name, base_dir, diag);
    return build(std::move(lexed), opts, diag);
  } catch (const inp::TooManyErrors&) {
    diag.throw_if_errors();
    throw;
  }
}

} // namespace gapfem
