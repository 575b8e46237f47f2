#pragma once
/// @file fields.hpp
/// Reading numbers from data-line fields: Fortran-style reals ("1.E6", "1.0D3", "-.5", "+2") and
/// integers, with errors that name the line, the field and what it should hold.
#include "common/error.hpp"
#include "io/inp/keyword.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace gapfem::inp {

/// A real number in Fortran/Abaqus notation: optional sign, digits with an optional decimal point
/// (at least one digit), optional exponent introduced by E or D (either case). nullopt otherwise.
std::optional<double> parse_real(std::string_view text);
/// An integer: optional sign and decimal digits only. nullopt otherwise (also on overflow).
std::optional<long long> parse_integer(std::string_view text);

/// Typed access to the fields of one data line. Errors are thrown as InputError located at the
/// line, naming the 1-based field and its meaning ("field 3 (magnitude)").
class FieldReader {
 public:
  FieldReader(const DataLine& line, SourceLocation loc) : _line(line), _loc(std::move(loc)) {}

  /// Number of fields (a trailing comma does not count).
  std::size_t size() const { return _line.fields.size(); }
  /// True when field i (0-based) is missing or empty.
  bool blank(std::size_t i) const { return !_line.has(i); }
  /// Field i as written, "" when missing.
  const std::string& text(std::size_t i) const;
  /// Required real number.
  double real(std::size_t i, std::string_view what) const;
  /// Real number, `def` when blank.
  double real_or(std::size_t i, double def, std::string_view what) const;
  /// Real number or nullopt when blank.
  std::optional<double> opt_real(std::size_t i, std::string_view what) const;
  /// Required integer.
  long long integer(std::size_t i, std::string_view what) const;
  /// Integer, `def` when blank.
  long long integer_or(std::size_t i, long long def, std::string_view what) const;
  /// Throws when a field after the first `n` is non-empty (the keyword has no such field).
  void at_most(std::size_t n, std::string_view layout) const;

  const SourceLocation& loc() const { return _loc; }
  const DataLine& line() const { return _line; }
  /// Throws an InputError at this line.
  [[noreturn]] void fail(std::string entity, std::string message) const;

 private:
  const DataLine& _line;
  SourceLocation _loc;
};

} // namespace gapfem::inp
