// libFuzzer target: the deck reader (lexer and keyword parser into a Model, with the model-wide
// checks). Every input must either read or raise InputError whose every part is printable (the
// deck bytes it quotes escaped, never cut at a NUL); anything else (another exception, a raw
// control byte in a message, a crash, a sanitizer report, a hang) is a finding.
#include "common/error.hpp"
#include "fuzz_common.hpp"
#include "io/inp/reader.hpp"
#include "model/model.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  if (gapfem::fuzz::names_a_file(text)) return -1; // not added to the corpus
  try {
    const gapfem::Model model = gapfem::read_deck_string(text, "fuzz.inp", {}, "/nonexistent");
    (void)model;
  } catch (const gapfem::InputError& e) {
    using gapfem::fuzz::printable;
    if (!printable(e.message()) || !printable(e.entity()) || !printable(e.location().file) ||
        !printable(e.location().keyword))
      std::abort();
  }
  return 0;
}
