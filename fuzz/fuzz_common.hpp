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

} // namespace gapfem::fuzz
