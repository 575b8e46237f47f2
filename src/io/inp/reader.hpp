#pragma once
/// @file reader.hpp
/// Reading an Abaqus input deck into the immutable gapfem::Model (docs/keywords.md lists every
/// supported keyword and parameter).
#include "model/model.hpp"

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace gapfem {

/// How the reader treats what it does not know.
struct ReadOptions {
  /// Unknown keywords and unknown parameters become warnings (appended to Model::warnings with
  /// file:line) instead of input errors.
  bool ignore_unknown = false;
  /// A restart deck (*RESTART, READ; docs/restart.md) continues an earlier job, whose deck holds
  /// the model data and the steps before the restart point. Called with the READ request, returns
  /// that deck and the number of its steps to keep; throws InputError when there is no such job.
  /// Empty: a deck with *RESTART, READ is an input error.
  struct RestartBase {
    std::filesystem::path deck;
    int steps = 0;
  };
  std::function<RestartBase(const RestartRead& request)> restart_base;
};

/// Reads `deck` (following *INCLUDE and INPUT= files relative to the file that names them) and
/// builds the model. All input problems found are thrown together as one InputError, one problem
/// per line, the location of the first in InputError::location(). Model::job_name is left empty.
Model read_deck(const std::filesystem::path& deck, const ReadOptions& opts = {});

/// As read_deck() for deck text held in memory (tests). `name` is the file name used in messages;
/// *INCLUDE / INPUT= paths are relative to `base_dir` (the current directory when empty).
Model read_deck_string(std::string_view text, const std::string& name, const ReadOptions& opts = {},
                       const std::filesystem::path& base_dir = {});

} // namespace gapfem
