#pragma once
/// @file fuzz_common.hpp
/// Shared by the libFuzzer targets: which inputs a target skips. A deck that names another file
/// (*INCLUDE, INPUT=) would let the fuzzer read arbitrary files of the machine; the include and
/// INPUT= paths are covered by the unit tests instead.
#include <cctype>
#include <string>
#include <string_view>

namespace gapfem::fuzz {

/// True when `text` mentions INPUT (in any case, with blanks inside, as parameter names may be).
inline bool names_a_file(std::string_view text) {
  std::string squeezed;
  squeezed.reserve(text.size());
  for (const char c : text)
    if (c != ' ' && c != '\t')
      squeezed.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  return squeezed.find("INPUT") != std::string::npos;
}

/// True when `text` has no NUL or other control byte but tab and newline: what every input error
/// must be, since the reader shows the deck bytes it quotes as \xNN (io/inp/deck_text.hpp).
inline bool printable(std::string_view text) {
  for (const char c : text) {
    const auto b = static_cast<unsigned char>(c);
    if ((b < 0x20 && b != '\n' && b != '\t') || b == 0x7F) return false;
  }
  return true;
}

} // namespace gapfem::fuzz
