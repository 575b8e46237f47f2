#pragma once
/// @file reader_test_util.hpp
/// Helpers for the deck-reader tests: decks in memory or in a per-test temporary directory,
/// and checks on the text of input errors.
#include "io/inp/reader.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <string_view>

namespace gapfem::test {

/// A small valid model: two nodes and one T3D2 truss with an elastic material. Tests append
/// keywords to it (more model data, or steps).
inline constexpr std::string_view kTrussModel = R"(*NODE, NSET=ALL
1, 0., 0., 0.
2, 1., 0., 0.
*ELEMENT, TYPE=T3D2, ELSET=TRUSS
1, 1, 2
*MATERIAL, NAME=STEEL
*ELASTIC
200000., 0.3
*SOLID SECTION, ELSET=TRUSS, MATERIAL=STEEL
1.
)";

/// Reads deck text (file name "deck.inp" in messages).
inline Model read(std::string_view text, ReadOptions opts = {}) {
  return read_deck_string(text, "deck.inp", opts);
}

/// The InputError a deck raises; records a test failure when it reads without error.
inline InputError read_error(std::string_view text, ReadOptions opts = {},
                             const std::string& name = "deck.inp") {
  try {
    read_deck_string(text, name, opts);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "the deck was read without an InputError:\n" << text;
  return InputError(SourceLocation{}, "", "");
}

/// The message (what()) of the error a deck raises.
inline std::string error_text(std::string_view text, ReadOptions opts = {}) {
  return read_error(text, opts).what();
}

/// A fresh, empty directory for the files of the current test (not test_util.hpp's test_dir(),
/// which keeps what an earlier run left: two inline functions of one name would break the ODR).
inline std::filesystem::path fresh_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "gapfem_reader" /
                                    (std::string(info->test_suite_name()) + "_" + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// Writes `text` to `path` (creating parent directories).
inline void write_file(const std::filesystem::path& path, std::string_view text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << text;
}

/// Number of warnings that contain `part`.
inline int count_warnings(const Model& m, std::string_view part) {
  int n = 0;
  for (const auto& w : m.warnings)
    if (w.find(part) != std::string::npos) ++n;
  return n;
}

} // namespace gapfem::test

/// Expects `text` (a std::string) to contain `part`, printing the text otherwise.
#define EXPECT_CONTAINS(text, part)                                                                \
  EXPECT_NE(std::string(text).find(part), std::string::npos)                                       \
      << "expected to find \"" << (part) << "\" in:\n"                                             \
      << (text)
