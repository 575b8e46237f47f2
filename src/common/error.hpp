#pragma once
/// @file error.hpp
/// The error policy (docs/conventions.md): every user-facing problem is an exception carrying the
/// deck location and the entity, with a sentence the user can act on.
///   InputError        bad deck: exit status 1, raised before solving
///   AnalysisError     the analysis cannot continue (no convergence, singular system): exit status 2
///   ConvergenceFailure recoverable: the increment controller cuts back
///   InternalError     a bug in gapfem: exit status 3
#include <stdexcept>
#include <string>

namespace gapfem {

/// Where in the deck something was defined: file, 1-based line and the keyword (e.g. "*ELEMENT").
struct SourceLocation {
  std::string file;
  int line = 0;
  std::string keyword;

  bool empty() const { return file.empty() && line == 0; }
  /// "deck.inp:12 (*GAP)" or "" when unknown.
  std::string str() const;
};

class Error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// A problem in the input deck. The message reads "file:line: *KEYWORD: entity: what to do".
class InputError : public Error {
public:
  InputError(SourceLocation loc, std::string entity, std::string message);
  InputError(SourceLocation loc, std::string message) : InputError(std::move(loc), {}, std::move(message)) {}
  const SourceLocation& location() const { return _loc; }
  const std::string& entity() const { return _entity; }
  const std::string& message() const { return _message; }

private:
  SourceLocation _loc;
  std::string _entity;
  std::string _message;
};

/// The analysis stopped: no convergence at the minimum increment, a singular system, too many
/// increments. Results up to the last converged increment are still written.
class AnalysisError : public Error {
public:
  using Error::Error;
};

/// Recoverable: Newton did not converge, a NaN appeared, contact chattered. The increment
/// controller catches it and cuts the increment back.
class ConvergenceFailure : public Error {
public:
  using Error::Error;
};

/// A bug in gapfem (an invariant did not hold).
class InternalError : public Error {
public:
  using Error::Error;
};

[[noreturn]] void throw_internal(const char* file, int line, const char* cond, const std::string& msg);

} // namespace gapfem

/// Always-on check for internal invariants: throws InternalError with file and line.
#define FE_CHECK(cond, msg)                                                                        \
  do {                                                                                             \
    if (!(cond)) ::gapfem::throw_internal(__FILE__, __LINE__, #cond, (msg));                       \
  } while (0)

/// Debug-only assertion (compiled out with NDEBUG).
#ifdef NDEBUG
#define FE_ASSERT(cond) ((void)0)
#else
#define FE_ASSERT(cond) FE_CHECK(cond, "assertion failed")
#endif
