#include "io/inp/reader.hpp"

#include "io/inp/diagnostics.hpp"
#include "io/inp/lexer.hpp"
#include "io/inp/parameters.hpp"
#include "io/inp/parser.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace gapfem {
namespace {

/// The *RESTART, READ of a deck (nullptr: none).
const inp::Keyword* restart_read(const inp::Deck& deck) {
  for (const inp::Keyword& kw : deck.keywords)
    if (kw.key == "RESTART" && kw.has("READ")) return &kw;
  return nullptr;
}

/// A restart deck after the old job's deck cut after its first `steps` steps: one deck whose files
/// are the old deck's, then the restart deck's (*HEADING of the restart deck dropped).
inp::Deck splice_restart(inp::Deck old_deck, int steps, inp::Deck deck) {
  int ended = 0;
  std::size_t keep = old_deck.keywords.size();
  for (std::size_t k = 0; k < old_deck.keywords.size(); ++k)
    if (old_deck.keywords[k].key == "ENDSTEP" && ++ended == steps) {
      keep = k + 1;
      break;
    }
  old_deck.keywords.resize(keep);
  const auto shift = static_cast<std::int32_t>(old_deck.files.size());
  for (auto& f : deck.files) old_deck.files.push_back(std::move(f));
  for (inp::Keyword& kw : deck.keywords) {
    if (kw.key == "HEADING") continue;
    kw.file += shift;
    for (auto& line : kw.data) line.file += shift;
    old_deck.keywords.push_back(std::move(kw));
  }
  return old_deck;
}

/// Follows a restart deck's *RESTART, READ to the deck of the job it continues.
inp::Deck with_restart_base(inp::Deck deck, const ReadOptions& opts, inp::Diagnostics& diag) {
  const inp::Keyword* kw = restart_read(deck);
  if (!kw) return deck;
  if (!opts.restart_base)
    throw InputError(kw->loc, "READ",
                     "this deck continues an earlier job: run it as gapfem deck.inp --oldjob "
                     "OLDJOB (Abaqus's oldjob=), OLDJOB being the job whose *RESTART, WRITE "
                     "wrote OLDJOB.res");
  RestartRead request;
  request.step = static_cast<int>(
      inp::int_param(*kw, "STEP", "the step to continue from", 0, inp::kMaxInt).value_or(0));
  request.increment = static_cast<int>(
      inp::int_param(*kw, "INC", "the increment to continue from", 0, inp::kMaxInt).value_or(0));
  request.end_step = kw->has("END STEP");
  request.loc = kw->loc;
  const ReadOptions::RestartBase base = opts.restart_base(request);
  inp::Deck old_deck = inp::lex_file(base.deck, diag);
  if (restart_read(old_deck))
    throw InputError(
        kw->loc, "READ",
        fmt::format("the old job's deck '{}' is itself a restart deck; gapfem continues "
                    "a job only from one that ran from the beginning",
                    base.deck.string()));
  return splice_restart(std::move(old_deck), base.steps, std::move(deck));
}

Model build(inp::Deck deck, const ReadOptions& opts, inp::Diagnostics& diag) {
  inp::BuildState state(opts, diag);
  state.model.source_files = deck.files;
  try {
    inp::substitute_parameters(deck, diag); // *PARAMETER and <name>, before anything reads
    inp::parse_deck(deck, state);
  } catch (const inp::TooManyErrors&) {
    // the collected errors are thrown below
  }
  diag.throw_if_errors();
  state.model.warnings = diag.warnings();
  return std::move(state.model);
}

/// Reads the deck `lex` lexes. Every input error leaves printable (deck_text.hpp): those the
/// diagnostics collected are so already, and one thrown directly is made so here.
template <typename Lex>
Model read(Lex&& lex, const ReadOptions& opts) {
  inp::Diagnostics diag;
  try {
    inp::Deck lexed = lex(diag);
    // a deck whose text could not be read at all (its encoding, binary data) ends with that
    if (lexed.keywords.empty()) diag.throw_if_errors();
    lexed = with_restart_base(std::move(lexed), opts, diag);
    return build(std::move(lexed), opts, diag);
  } catch (const inp::TooManyErrors&) {
    diag.throw_if_errors();
    throw;
  } catch (const InputError& e) {
    throw inp::printable(e);
  }
}

} // namespace

Model read_deck(const std::filesystem::path& deck, const ReadOptions& opts) {
  return read([&](inp::Diagnostics& diag) { return inp::lex_file(deck, diag); }, opts);
}

Model read_deck_string(std::string_view text, const std::string& name, const ReadOptions& opts,
                       const std::filesystem::path& base_dir) {
  return read([&](inp::Diagnostics& diag) { return inp::lex_string(text, name, base_dir, diag); },
              opts);
}

} // namespace gapfem
