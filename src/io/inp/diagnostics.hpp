#pragma once
/// @file diagnostics.hpp
/// Collects the input errors and warnings of one deck so that the user sees all problems of a deck
/// at once (up to a cap) instead of fixing them one run at a time.
#include "common/error.hpp"

#include <string>
#include <vector>

namespace gapfem::inp {

/// Thrown by the collector when the error cap is reached; the reader turns it into the final
/// InputError. Never escapes read_deck().
struct TooManyErrors {};

/// `e` with every part made printable (deck_text.hpp): NUL and control bytes of the deck text it
/// quotes are shown as \xNN, never cutting or garbling the message.
InputError printable(const InputError& e);

/// Error and warning collector with a cap on the number of errors. Every error and warning is
/// stored printable.
class Diagnostics {
 public:
  /// `max_errors`: after this many errors, error() throws TooManyErrors.
  explicit Diagnostics(int max_errors = 50) : _max_errors(max_errors) {}

  /// Record an error; throws TooManyErrors once the cap is reached.
  void error(const InputError& e);
  /// Record an error built from its parts.
  void error(SourceLocation loc, std::string entity, std::string message) {
    error(InputError(std::move(loc), std::move(entity), std::move(message)));
  }
  /// Record a warning, formatted like an error message ("file:line: *KEYWORD: text").
  void warning(const SourceLocation& loc, const std::string& message);

  int n_errors() const { return static_cast<int>(_errors.size()); }
  /// While muted, errors are dropped (counted in n_suppressed()): used for checks whose failures
  /// would only be consequences of errors already reported.
  void set_muted(bool muted) { _muted = muted; }
  int n_suppressed() const { return _suppressed; }
  const std::vector<InputError>& errors() const { return _errors; }
  const std::vector<std::string>& warnings() const { return _warnings; }

  /// Throw the collected errors as one InputError (no-op without errors). A single error is
  /// rethrown as is; several are listed one per line, the location of the first in location().
  void throw_if_errors() const;

 private:
  int _max_errors;
  bool _muted = false;
  int _suppressed = 0;
  std::vector<InputError> _errors;
  std::vector<std::string> _warnings;
};

} // namespace gapfem::inp
