// libFuzzer target: the deck reader (lexer and keyword parser into a Model, with the model-wide
// checks). Every input must either read or raise InputError; anything else (another exception,
// a crash, a sanitizer report, a hang) is a finding.
#include "common/error.hpp"
#include "fuzz_common.hpp"
#include "io/inp/reader.hpp"
#include "model/model.hpp"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  if (gapfem::fuzz::names_a_file(text)) return -1; // not added to the corpus
  try {
    const gapfem::Model model = gapfem::read_deck_string(text, "fuzz.inp", {}, "/nonexistent");
    (void)model;
  } catch (const gapfem::InputError&) {
  }
  return 0;
}
