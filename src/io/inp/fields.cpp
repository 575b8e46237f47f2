#include "io/inp/fields.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fmt/format.h>
#include <limits>

namespace gapfem::inp {
namespace {
bool digit(char c) {
  return c >= '0' && c <= '9';
}

std::string field_entity(std::size_t i, std::string_view what) {
  return what.empty() ? fmt::format("field {}", i + 1) : fmt::format("field {} ({})", i + 1, what);
}
} // namespace

namespace {
/// parse_real's work: the value, nullopt on a syntax error; `overflow` tells a number written
/// correctly whose magnitude is beyond the double range.
std::optional<double> read_real(std::string_view text, bool& overflow) {
  overflow = false;
  text = trim(text);
  std::string s;
  std::size_t i = 0;
  const std::size_t n = text.size();
  if (i < n && (text[i] == '+' || text[i] == '-')) s.push_back(text[i++]);
  int mantissa_digits = 0;
  while (i < n && digit(text[i])) {
    s.push_back(text[i++]);
    ++mantissa_digits;
  }
  if (i < n && text[i] == '.') {
    s.push_back(text[i++]);
    while (i < n && digit(text[i])) {
      s.push_back(text[i++]);
      ++mantissa_digits;
    }
  }
  if (mantissa_digits == 0) return std::nullopt;
  if (i < n && (text[i] == 'e' || text[i] == 'E' || text[i] == 'd' || text[i] == 'D')) {
    s.push_back('e');
    ++i;
    if (i < n && (text[i] == '+' || text[i] == '-')) s.push_back(text[i++]);
    int exp_digits = 0;
    while (i < n && digit(text[i])) {
      s.push_back(text[i++]);
      ++exp_digits;
    }
    if (exp_digits == 0) return std::nullopt;
  }
  if (i != n) return std::nullopt;
  errno = 0;
  const double v = std::strtod(s.c_str(), nullptr);
  if (errno == ERANGE && std::isinf(v)) {
    overflow = true;
    return std::nullopt;
  }
  return v;
}
} // namespace

std::optional<double> parse_real(std::string_view text) {
  bool overflow = false;
  return read_real(text, overflow);
}

bool real_out_of_range(std::string_view text) {
  bool overflow = false;
  read_real(text, overflow);
  return overflow;
}

std::string real_problem(std::string_view text) {
  if (real_out_of_range(text))
    return fmt::format("'{}' is out of range (larger than 1.8E308 in magnitude, the largest "
                       "number gapfem holds); check the exponent",
                       text);
  return fmt::format("'{}' is not a number; write it like 2, -0.5, 1.E6 or 1.0D3", text);
}

std::optional<long long> parse_integer(std::string_view text) {
  text = trim(text);
  std::size_t i = 0;
  bool negative = false;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) negative = text[i++] == '-';
  if (i == text.size()) return std::nullopt;
  long long v = 0;
  for (; i < text.size(); ++i) {
    if (!digit(text[i])) return std::nullopt;
    if (v > (std::numeric_limits<long long>::max() - 9) / 10) return std::nullopt;
    v = v * 10 + (text[i] - '0');
  }
  return negative ? -v : v;
}

IntCheck check_integer(std::string_view text, long long min, long long max, long long& value) {
  const std::string_view t = trim(text);
  std::size_t i = t.size() > 0 && (t[0] == '+' || t[0] == '-') ? 1 : 0;
  if (i == t.size()) return IntCheck::NotWhole;
  for (; i < t.size(); ++i)
    if (!digit(t[i])) return IntCheck::NotWhole;
  const auto v = parse_integer(t);
  if (!v || *v < min || *v > max) return IntCheck::OutOfRange; // (nullopt: beyond 64 bits)
  value = *v;
  return IntCheck::Ok;
}

std::string integer_problem(std::string_view text, IntCheck why, long long min, long long max) {
  if (why == IntCheck::OutOfRange)
    return fmt::format("'{}' is out of range; give a whole number from {} to {}", text, min, max);
  return fmt::format("'{}' is not a whole number; give a whole number from {} to {}, written "
                     "with digits only",
                     text, min, max);
}

const std::string& FieldReader::text(std::size_t i) const {
  static const std::string empty;
  return i < _line.fields.size() ? _line.fields[i] : empty;
}

double FieldReader::real(std::size_t i, std::string_view what) const {
  if (blank(i))
    fail(field_entity(i, what), "this value is required but the field is missing or blank");
  return *opt_real(i, what);
}

double FieldReader::real_or(std::size_t i, double def, std::string_view what) const {
  return opt_real(i, what).value_or(def);
}

std::optional<double> FieldReader::opt_real(std::size_t i, std::string_view what) const {
  if (blank(i)) return std::nullopt;
  const auto v = parse_real(_line.fields[i]);
  if (!v) fail(field_entity(i, what), real_problem(_line.fields[i]));
  return v;
}

long long FieldReader::integer(std::size_t i, std::string_view what, long long min, long long max,
                               std::string_view rule) const {
  if (blank(i))
    fail(field_entity(i, what), "this value is required but the field is missing or blank");
  long long v = 0;
  const std::string& t = _line.fields[i];
  mark_integer(i);
  const IntCheck c = check_integer(t, min, max, v);
  if (c == IntCheck::OutOfRange && !rule.empty())
    fail(field_entity(i, what), fmt::format(fmt::runtime(rule), t));
  if (c != IntCheck::Ok) fail(field_entity(i, what), integer_problem(t, c, min, max));
  return v;
}

long long FieldReader::integer_or(std::size_t i, long long def, std::string_view what,
                                  long long min, long long max, std::string_view rule) const {
  return blank(i) ? def : integer(i, what, min, max, rule);
}

void FieldReader::at_most(std::size_t n, std::string_view layout) const {
  for (std::size_t i = n; i < _line.fields.size(); ++i)
    if (!_line.fields[i].empty())
      fail(field_entity(i, ""),
           fmt::format("unexpected value '{}': this data line has at most {} fields ({})",
                       _line.fields[i], n, layout));
}

void FieldReader::fail(std::string entity, std::string message) const {
  // "field N (...)": the message echoes the value as written, unless it quotes it already
  unsigned n = 0;
  if (std::sscanf(entity.c_str(), "field %u", &n) == 1 && n >= 1 && n <= _line.fields.size() &&
      entity.rfind("fields", 0) != 0) {
    const std::string& text = _line.fields[n - 1];
    if (!text.empty() && message.find(text) == std::string::npos)
      message += fmt::format(" (given: {})", text);
  }
  throw InputError(_loc, std::move(entity), std::move(message));
}

} // namespace gapfem::inp
