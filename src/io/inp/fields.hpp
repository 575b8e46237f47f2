#pragma once
/// @file fields.hpp
/// Reading numbers from data-line fields: Fortran-style reals ("1.E6", "1.0D3", "-.5", "+2") and
/// integers, with errors that name the line, the field and what it should hold.
#include "common/error.hpp"
#include "io/inp/keyword.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace gapfem::inp {

/// Node and element numbers run from 1 to this, Abaqus's limit ("the maximum node number allowed
/// is 999999999", Abaqus Analysis User's Guide, Node definition). A Label (int64) holds it with
/// the instance index above it (model/mesh.hpp), and so do every label column of the result
/// files (10 characters in job.frd) and a user element's JELEM (a 32-bit integer).
inline constexpr long long kMaxLabel = 999'999'999;
/// The largest count, frequency or index the model keeps: what a 32-bit int holds (2^31 - 1).
inline constexpr long long kMaxInt = 2'147'483'647;

/// A real number in Fortran/Abaqus notation: optional sign, digits with an optional decimal point
/// (at least one digit), optional exponent introduced by E or D (either case). nullopt otherwise,
/// also for a number beyond the double range (real_out_of_range tells that case apart).
std::optional<double> parse_real(std::string_view text);
/// True when `text` is written as a real number but its magnitude exceeds the largest double
/// (1.8E308), e.g. 1e400.
bool real_out_of_range(std::string_view text);
/// The sentence for a field or parameter value that parse_real refused, starting with the value
/// quoted: "'x' is not a number; write it like ..." or "'1e400' is out of range (...)".
std::string real_problem(std::string_view text);
/// An integer: optional sign and decimal digits only. nullopt otherwise (also on overflow).
std::optional<long long> parse_integer(std::string_view text);

/// How a text reads as a whole number from a range.
enum class IntCheck : std::uint8_t {
  Ok,        ///< a whole number within the range
  NotWhole,  ///< not written as a whole number (letters, a decimal point, an exponent)
  OutOfRange ///< a whole number outside the range (also one beyond 64 bits)
};
/// Reads `text` as a whole number from `min` to `max` (into `value` when Ok).
IntCheck check_integer(std::string_view text, long long min, long long max, long long& value);
/// The sentence for an integer field that check_integer refused, starting with the value quoted:
/// "'2.5' is not a whole number; give ..." or "'4294967296' is out of range; give ...".
std::string integer_problem(std::string_view text, IntCheck why, long long min, long long max);

/// Typed access to the fields of one data line. Errors are thrown as InputError located at the
/// line, naming the 1-based field and its meaning ("field 3 (magnitude)").
class FieldReader {
 public:
  /// Reads `line`, which counts from now on as read by its keyword (DataLine::read).
  FieldReader(const DataLine& line, SourceLocation loc) : _line(line), _loc(std::move(loc)) {
    line.read = true;
  }

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
  /// Required whole number from `min` to `max` (an error naming the range otherwise: every
  /// integer field is read with the range its use can hold, so nothing narrows it later).
  /// `rule`, when given, is the sentence for a value out of range, with {} for the value as
  /// written ("DOF {} is not available; gapfem knows DOFs 1-6 ..."), for fields whose allowed
  /// values say more than a range.
  long long integer(std::size_t i, std::string_view what, long long min, long long max,
                    std::string_view rule = {}) const;
  /// As integer(), `def` when blank.
  long long integer_or(std::size_t i, long long def, std::string_view what, long long min,
                       long long max, std::string_view rule = {}) const;
  /// Throws when a field after the first `n` is non-empty (the keyword has no such field).
  void at_most(std::size_t n, std::string_view layout) const;

  /// Notes that field i is read as a whole number (DataLine::integer_fields).
  void mark_integer(std::size_t i) const {
    if (i < 64) _line.integer_fields |= std::uint64_t{1} << i;
  }
  const SourceLocation& loc() const { return _loc; }
  const DataLine& line() const { return _line; }
  /// Throws an InputError at this line.
  [[noreturn]] void fail(std::string entity, std::string message) const;

 private:
  const DataLine& _line;
  SourceLocation _loc;
};

} // namespace gapfem::inp
